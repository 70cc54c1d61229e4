//! [`HitWorld::detect_traced`](super::HitWorld::detect_traced)'s record: for each pair of
//! objects and each direction, what `detect` tested and decided, and why.

use super::HitTypes;
use super::object::ObjectId;
use crate::owner::Owner;

/// What a traced [`detect`](super::HitWorld::detect_traced) did with each pair of objects,
/// in each direction: the bounding test, the volumes tested, and the hit accepted or
/// refused and by which rule.
///
/// [`new`](Self::new) records every pair the broadphase found (the pairs whose boxes
/// overlap); [`of`](Self::of) records only the pairs with an object of one owner, and also
/// the objects whose boxes did not reach it, so "why did my sword not hit that slime?" has
/// an answer even when the boxes were apart.
///
/// ```
/// use tileslide::{
///     DetectTrace, HitObject, HitTypes, HitWorld, Owner, PairOutcome, Refusal, TeamRule, Vec2,
///     Volume,
/// };
/// let mut world = HitWorld::new();
/// world.begin_frame();
/// let body = [Volume::rect(Vec2::splat(0.5), Vec2::splat(0.5), HitTypes::ANY)?];
/// let fist = [Volume::circle(Vec2::new(1.2, 0.5), 0.3, HitTypes::HIT)?];
/// let hero = HitObject::new(Owner(1), Vec2::ZERO, Vec2::ONE);
/// world.register(hero, &fist, &body)?;
/// // A slime of the hero's own team, in reach.
/// world.register(HitObject::new(Owner(2), Vec2::new(1.3, 0.0), Vec2::ONE), &[], &body)?;
/// let mut trace = DetectTrace::of(Owner(1));
/// assert!(world.detect_traced(&mut TeamRule, &mut trace).iter().all(|h| !h.accepted));
/// let punch = &trace.pairs()[0];
/// assert_eq!((punch.attacker_owner, punch.victim_owner), (Owner(1), Owner(2)));
/// assert_eq!(punch.outcome, PairOutcome::Refused { event: 0, by: Refusal::SameTeam });
/// # Ok::<(), tileslide::VolumeError>(())
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub struct DetectTrace {
    /// Only pairs with an object of this owner (`None`: every pair).
    only: Option<Owner>,
    pub(super) pairs: Vec<PairTrace>,
}

impl DetectTrace {
    /// A trace of every pair the broadphase finds.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// A trace of the pairs with an object registered with `owner`, including the objects
    /// whose boxes were apart from it ([`PairOutcome::BoxesApart`]).
    #[must_use]
    pub fn of(owner: Owner) -> Self {
        Self {
            only: Some(owner),
            pairs: Vec::new(),
        }
    }

    /// The pairs, in the events' order: by pair `(i, j)`, `i < j` in registration order,
    /// then `i` attacking `j` before `j` attacking `i`.
    #[must_use]
    pub fn pairs(&self) -> &[PairTrace] {
        &self.pairs
    }

    /// The owner it is limited to, if any.
    #[must_use]
    pub fn owner(&self) -> Option<Owner> {
        self.only
    }

    /// Whether it records a pair of objects with these owners.
    pub(super) fn wants(&self, a: Owner, b: Owner) -> bool {
        self.only.is_none_or(|o| o == a || o == b)
    }
}

/// One object attacking another in a traced `detect`.
#[derive(Clone, Debug, PartialEq)]
pub struct PairTrace {
    /// The attacking object, as registered this frame.
    pub attacker: ObjectId,
    /// The object attacked.
    pub victim: ObjectId,
    /// The attacker's owner.
    pub attacker_owner: Owner,
    /// The victim's owner.
    pub victim_owner: Owner,
    /// The volume pairs tested, in order: each attack volume of the attacker (in list
    /// order) against each vulnerability volume of the victim, until the first that meets.
    /// Empty when the boxes were apart, or the swing had already hit the victim.
    pub tests: Vec<VolumeTest>,
    /// What came of it.
    pub outcome: PairOutcome,
}

/// An attack volume tested against a vulnerability volume.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct VolumeTest {
    /// The attack volume's index in the attacker's list.
    pub attack: usize,
    /// The vulnerability volume's index in the victim's list.
    pub vulnerable: usize,
    /// The types the attack deals that the vulnerability accepts; empty, and the shapes not
    /// tested, when they have none in common.
    pub dealt: HitTypes,
    /// Whether the volumes meet during the frame (the exact test along the move).
    pub met: bool,
}

/// What a traced `detect` decided for one attacker and one victim.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PairOutcome {
    /// The boxes of their volumes over the frame's move do not overlap, so nothing was
    /// tested (recorded only by [`DetectTrace::of`]).
    BoxesApart,
    /// The attacker's swing had already hit the victim; nothing was tested.
    SwingAlreadyHit {
        /// The swing.
        swing: u64,
    },
    /// The attacker has no attack volumes, or the victim no vulnerability volumes.
    NoVolumes,
    /// No attack volume deals a type that a vulnerability volume accepts.
    NoTypeInCommon,
    /// Volumes with types in common were tested and none met.
    Missed,
    /// A hit the victim took: the event at this index of the events `detect` returned.
    Accepted {
        /// The event's index.
        event: usize,
    },
    /// A hit the victim refused: the event at this index, and the rule that refused it.
    Refused {
        /// The event's index.
        event: usize,
        /// Why.
        by: Refusal,
    },
}

/// Why a victim refused a hit, as its [`HitRule`](super::HitRule) says
/// ([`HitRule::refusal`](super::HitRule::refusal)).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Refusal {
    /// Attacker and victim are of the same team ([`TeamRule`](super::TeamRule)).
    SameTeam,
    /// The victim is invulnerable ([`TeamRule`](super::TeamRule)).
    Invulnerable,
    /// The game's own rule (a closure or a `HitRule` of its own) said no.
    Rule,
}

/// Where a `detect` writes what it does: nowhere for plain `detect` (every call compiles
/// away), into a [`DetectTrace`] for `detect_traced`.
pub(super) trait HitSink {
    /// Whether anything is recorded at all (a traced `detect` stays on one thread).
    #[cfg(feature = "parallel")]
    fn records(&self) -> bool;
    /// Whether the pair of these owners is recorded; the other calls come only for pairs
    /// it wants.
    fn wants(&self, attacker: Owner, victim: Owner) -> bool;
    /// A volume pair tested.
    fn test(&mut self, test: VolumeTest);
    /// The pair's outcome, with its objects.
    fn outcome(&mut self, pair: (ObjectId, ObjectId), owners: (Owner, Owner), outcome: PairOutcome);
}

/// The sink of an untraced `detect`.
pub(super) struct NoTrace;

impl HitSink for NoTrace {
    #[cfg(feature = "parallel")]
    #[inline(always)]
    fn records(&self) -> bool {
        false
    }
    #[inline(always)]
    fn wants(&self, _: Owner, _: Owner) -> bool {
        false
    }
    #[inline(always)]
    fn test(&mut self, _: VolumeTest) {}
    #[inline(always)]
    fn outcome(&mut self, _: (ObjectId, ObjectId), _: (Owner, Owner), _: PairOutcome) {}
}

/// A [`DetectTrace`] being written: the volume tests of the pair under way.
pub(super) struct Recorder<'a> {
    pub(super) trace: &'a mut DetectTrace,
    pub(super) tests: Vec<VolumeTest>,
}

impl HitSink for Recorder<'_> {
    #[cfg(feature = "parallel")]
    fn records(&self) -> bool {
        true
    }
    fn wants(&self, attacker: Owner, victim: Owner) -> bool {
        self.trace.wants(attacker, victim)
    }
    fn test(&mut self, test: VolumeTest) {
        self.tests.push(test);
    }
    fn outcome(
        &mut self,
        pair: (ObjectId, ObjectId),
        owners: (Owner, Owner),
        outcome: PairOutcome,
    ) {
        self.trace.pairs.push(PairTrace {
            attacker: pair.0,
            victim: pair.1,
            attacker_owner: owners.0,
            victim_owner: owners.1,
            tests: std::mem::take(&mut self.tests),
            outcome,
        });
    }
}
