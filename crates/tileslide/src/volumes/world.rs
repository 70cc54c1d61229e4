//! The frame's objects and their hits: registration, broadphase, the attack-against-
//! vulnerability test, acceptance and "hit once per swing".

use std::collections::HashSet;

use glam::Vec2;

use super::HitTypes;
use super::volume::{Facing, Placed, Volume, VolumeError, check_range};
use crate::broadphase::{PairFinder, PairMethod};
use crate::geometry::{Aabb, Circle};
use crate::owner::Owner;

/// An object registered for one frame: where it is, how it faces, and who it is.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HitObject {
    /// The caller's entity (stable across frames: "hit once per swing" remembers it).
    pub owner: Owner,
    /// Its position at the end of the frame (its volumes' local origin).
    pub position: Vec2,
    /// How far it moved during the frame: its volumes are tested along the whole move, so
    /// a fast projectile cannot pass through a target between frames. Zero: a still test.
    pub motion: Vec2,
    /// Its size, about which volumes are mirrored.
    pub size: Vec2,
    /// Which way it faces.
    pub facing: Facing,
    /// Its team (see [`TeamRule`]).
    pub team: u32,
    /// Refuses every hit under [`TeamRule`] (a hero blinking after a hit).
    pub invulnerable: bool,
    /// The attack it is making, if it should hit each victim at most once until the attack
    /// ends: the swing ends at the first frame in which no object registers it.
    pub swing: Option<u64>,
}

impl HitObject {
    /// An object of `owner` at `position` of `size`: still, facing right and up, team 0, no
    /// swing.
    #[must_use]
    pub fn new(owner: Owner, position: Vec2, size: Vec2) -> Self {
        Self {
            owner,
            position,
            motion: Vec2::ZERO,
            size,
            facing: Facing::default(),
            team: 0,
            invulnerable: false,
            swing: None,
        }
    }

    /// Whether the object can be registered with its volumes: its position, where it
    /// starts the frame (`position − motion`) and its size finite and within
    /// [`MAX_COORD`](crate::limits::MAX_COORD), so that placing and sweeping its volumes cannot
    /// overflow. [`HitWorld::register`] refuses an object this refuses.
    ///
    /// # Errors
    /// [`VolumeError::NonFinite`] or [`VolumeError::OutOfRange`] naming the value.
    pub fn check(&self) -> Result<(), VolumeError> {
        check_range("position", self.position)?;
        if !self.motion.is_finite() {
            let (x, y) = (self.motion.x, self.motion.y);
            return Err(VolumeError::NonFinite {
                what: "motion",
                x,
                y,
            });
        }
        check_range("start", self.position - self.motion)?;
        check_range("size", self.size)
    }
}

/// An object's index in the frame's registrations.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[cfg_attr(feature = "serde", serde(transparent))]
pub struct ObjectId(pub u32);

/// One hit: an attack volume of `attacker` met a vulnerability volume of `victim` that
/// accepts its type.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HitEvent {
    /// Who hit.
    pub attacker: ObjectId,
    /// Who was hit.
    pub victim: ObjectId,
    /// The types dealt: the attack volume's types that the vulnerability volume accepts.
    pub hit_type: HitTypes,
    /// Whether the victim (the [`HitRule`]) took the hit.
    pub accepted: bool,
}

/// Decides whether a victim takes a hit. The victim is asked first; the attacker learns
/// the answer from [`HitEvent::accepted`].
pub trait HitRule {
    /// True when `victim` takes a hit of `hit_type` from `attacker`.
    fn accept(&mut self, attacker: &HitObject, victim: &HitObject, hit_type: HitTypes) -> bool;
}

/// The built-in rule: a victim takes hits from other teams while it is not invulnerable.
#[derive(Clone, Copy, Debug, Default)]
pub struct TeamRule;

impl HitRule for TeamRule {
    fn accept(&mut self, attacker: &HitObject, victim: &HitObject, _: HitTypes) -> bool {
        attacker.team != victim.team && !victim.invulnerable
    }
}

impl<F: FnMut(&HitObject, &HitObject, HitTypes) -> bool> HitRule for F {
    fn accept(&mut self, attacker: &HitObject, victim: &HitObject, hit_type: HitTypes) -> bool {
        self(attacker, victim, hit_type)
    }
}

/// A registered object and where its volumes are.
#[derive(Clone, Copy, Debug)]
pub(super) struct Entry {
    pub(super) object: HitObject,
    /// Ranges in `attack` and `vulnerable`.
    pub(super) attack: (u32, u32),
    pub(super) vulnerable: (u32, u32),
    /// Every point any of its volumes takes during the frame.
    pub(super) reach: Aabb,
}

/// Attack and vulnerability volumes of the objects of one frame, and the hits between them
/// (Replica Island's "moving objects vs each other", with its flaws fixed).
///
/// Each frame: [`begin_frame`](Self::begin_frame), [`register`](Self::register) every
/// object with the volumes of its current animation frame, then
/// [`detect`](Self::detect). A pair of objects is tested when the boxes of all their
/// volumes (over the frame's move) overlap, which never misses an overlap, unlike a
/// bounding circle of `max(w, h) / 2`. In each direction, the **first attack volume** (in
/// list order) that meets a vulnerability volume accepting one of its types gives one
/// hit.
///
/// Events come in a fixed order, whatever the broadphase: by pair `(i, j)`, `i < j` in
/// registration order, then `i` hitting `j` before `j` hitting `i`.
///
/// ```
/// use tileslide::{HitObject, HitTypes, HitWorld, Owner, TeamRule, Vec2, Volume};
/// let mut world = HitWorld::new();
/// world.begin_frame();
/// let hero = HitObject { team: 1, ..HitObject::new(Owner(1), Vec2::ZERO, Vec2::new(1.0, 2.0)) };
/// let fist = [Volume::circle(Vec2::new(1.3, 1.0), 0.3, HitTypes::HIT)?];
/// let body = [Volume::rect(Vec2::new(0.5, 1.0), Vec2::new(0.5, 1.0), HitTypes::ANY)?];
/// let hero = world.register(hero, &fist, &body)?;
/// let slime = HitObject::new(Owner(2), Vec2::new(1.5, 0.0), Vec2::ONE);
/// let slime = world.register(slime, &[], &body[..1])?;
/// let hits = world.detect(&mut TeamRule);
/// assert_eq!(hits.len(), 1);
/// assert_eq!((hits[0].attacker, hits[0].victim), (hero, slime));
/// assert_eq!(hits[0].hit_type, HitTypes::HIT);
/// assert!(hits[0].accepted);
/// # Ok::<(), tileslide::VolumeError>(())
/// ```
#[derive(Clone, Debug, Default)]
pub struct HitWorld {
    pub(crate) broadphase: PairMethod,
    pub(super) entries: Vec<Entry>,
    pub(super) attack: Vec<Volume>,
    pub(super) vulnerable: Vec<Volume>,
    finder: PairFinder,
    boxes: Vec<Aabb>,
    pairs: Vec<(u32, u32)>,
    pub(super) events: Vec<HitEvent>,
    /// Accepted hits per swing: `(swing, victim owner)`.
    pub(crate) swung: HashSet<(u64, Owner)>,
    /// Swings registered this frame and the last.
    pub(crate) swings_now: HashSet<u64>,
    swings_before: HashSet<u64>,
}

impl HitWorld {
    /// An empty world using sweep and prune on x, as Replica Island does.
    #[must_use]
    pub fn new() -> Self {
        Self::with_broadphase(PairMethod::SweepAndPrune)
    }

    /// An empty world using `broadphase` (the results are the same either way).
    #[must_use]
    pub fn with_broadphase(broadphase: PairMethod) -> Self {
        Self {
            broadphase,
            ..Self::default()
        }
    }

    /// Starts a frame: forgets the last frame's objects, and ends the swings nobody
    /// registered in it.
    pub fn begin_frame(&mut self) {
        self.entries.clear();
        self.attack.clear();
        self.vulnerable.clear();
        self.events.clear();
        std::mem::swap(&mut self.swings_before, &mut self.swings_now);
        self.swings_now.clear();
        let live = &self.swings_before;
        self.swung.retain(|(swing, _)| live.contains(swing));
    }

    /// Registers an object for this frame with its attack and vulnerability volumes
    /// (copied).
    ///
    /// # Errors
    ///
    /// What [`HitObject::check`] or [`Volume::check`] says of the object or of its first
    /// bad volume (a NaN, infinite or out-of-range position, start, size, centre or
    /// corner); the world is unchanged. So every pair test computes within a few times
    /// [`MAX_COORD`](crate::limits::MAX_COORD), where nothing overflows (a box at 3·10³⁸ once
    /// missed a box it lay in, its centre overflowing to infinity).
    pub fn register(
        &mut self,
        object: HitObject,
        attack: &[Volume],
        vulnerable: &[Volume],
    ) -> Result<ObjectId, VolumeError> {
        object.check()?;
        for v in attack.iter().chain(vulnerable) {
            v.check()?;
        }
        let id = ObjectId(self.entries.len() as u32);
        let a0 = self.attack.len() as u32;
        self.attack.extend_from_slice(attack);
        let v0 = self.vulnerable.len() as u32;
        self.vulnerable.extend_from_slice(vulnerable);
        let mut reach: Option<Aabb> = None;
        for v in attack.iter().chain(vulnerable) {
            let end = place(&object, v).aabb();
            let start = Aabb {
                min: end.min - object.motion,
                max: end.max - object.motion,
            };
            let both = Aabb {
                min: start.min.min(end.min),
                max: start.max.max(end.max),
            };
            reach = Some(reach.map_or(both, |r| Aabb {
                min: r.min.min(both.min),
                max: r.max.max(both.max),
            }));
        }
        if let Some(swing) = object.swing {
            self.swings_now.insert(swing);
        }
        self.entries.push(Entry {
            object,
            attack: (a0, self.attack.len() as u32),
            vulnerable: (v0, self.vulnerable.len() as u32),
            // An object without volumes gets a box that overlaps nothing (NaN compares
            // false), so it never reaches the exact test.
            reach: reach.unwrap_or(Aabb {
                min: Vec2::NAN,
                max: Vec2::NAN,
            }),
        });
        Ok(id)
    }

    /// The object registered as `id` this frame.
    #[must_use]
    pub fn object(&self, id: ObjectId) -> Option<&HitObject> {
        self.entries.get(id.0 as usize).map(|e| &e.object)
    }

    /// A circle holding every volume of `id` at the end of the frame: centred on the box of
    /// its volumes, as large as the farthest point of any of them. `None` without volumes.
    #[must_use]
    pub fn bounding_circle(&self, id: ObjectId) -> Option<Circle> {
        let e = self.entries.get(id.0 as usize)?;
        let volumes = self.volumes_of(e);
        let placed = volumes.clone().map(|v| place(&e.object, v));
        let mut bounds: Option<Aabb> = None;
        for p in placed.clone() {
            let b = p.aabb();
            bounds = Some(bounds.map_or(b, |r| Aabb {
                min: r.min.min(b.min),
                max: r.max.max(b.max),
            }));
        }
        let center = (bounds?.min + bounds?.max) * 0.5;
        let radius = placed.map(|p| p.reach_from(center)).fold(0.0f32, f32::max);
        // One part in a million more, so rounding in the distances never leaves a volume's
        // edge outside.
        Some(Circle::new(center, radius * (1.0 + 1e-6) + f32::EPSILON))
    }

    fn volumes_of<'a>(&'a self, e: &Entry) -> impl Iterator<Item = &'a Volume> + Clone + 'a {
        let (a0, a1) = e.attack;
        let (v0, v1) = e.vulnerable;
        self.attack[a0 as usize..a1 as usize]
            .iter()
            .chain(&self.vulnerable[v0 as usize..v1 as usize])
    }

    /// Finds this frame's hits, asks `rule` whether each victim takes its hit, and returns
    /// the events (see the type's documentation for the order). An attack with a swing that
    /// already landed on a victim (accepted) does not hit it again until the swing ends.
    pub fn detect(&mut self, rule: &mut impl HitRule) -> &[HitEvent] {
        self.events.clear();
        self.boxes.clear();
        self.boxes.extend(self.entries.iter().map(|e| e.reach));
        self.pairs.clear();
        self.finder
            .find(self.broadphase, &self.boxes, &mut self.pairs);
        self.pairs.sort_unstable();
        for k in 0..self.pairs.len() {
            let (i, j) = self.pairs[k];
            self.hit(i, j, rule);
            self.hit(j, i, rule);
        }
        &self.events
    }

    /// `a` attacking `v`: the first attack volume of `a` that meets a vulnerability volume
    /// of `v` accepting one of its types.
    fn hit(&mut self, a: u32, v: u32, rule: &mut impl HitRule) {
        let (ea, ev) = (&self.entries[a as usize], &self.entries[v as usize]);
        if let Some(swing) = ea.object.swing
            && self.swung.contains(&(swing, ev.object.owner))
        {
            return;
        }
        // Relative motion: in the victim's frame the attacker moves by the difference.
        let motion = ea.object.motion - ev.object.motion;
        let attacks = &self.attack[ea.attack.0 as usize..ea.attack.1 as usize];
        let vulnerable = &self.vulnerable[ev.vulnerable.0 as usize..ev.vulnerable.1 as usize];
        let found = attacks.iter().find_map(|attack| {
            let from = start_of(&ea.object, attack);
            vulnerable.iter().find_map(|target| {
                let dealt = attack.hit & target.hit;
                (!dealt.is_empty() && from.meets(motion, &start_of(&ev.object, target)))
                    .then_some(dealt)
            })
        });
        let Some(hit_type) = found else {
            return;
        };
        let accepted = rule.accept(&ea.object, &ev.object, hit_type);
        if accepted && let Some(swing) = ea.object.swing {
            self.swung.insert((swing, ev.object.owner));
        }
        self.events.push(HitEvent {
            attacker: ObjectId(a),
            victim: ObjectId(v),
            hit_type,
            accepted,
        });
    }
}

/// Volume `v` of `object` where the frame ends.
pub(super) fn place(object: &HitObject, v: &Volume) -> Placed {
    Placed::new(&v.shape, object.position, object.size, object.facing)
}

/// Volume `v` of `object` where the frame starts.
fn start_of(object: &HitObject, v: &Volume) -> Placed {
    Placed::new(
        &v.shape,
        object.position - object.motion,
        object.size,
        object.facing,
    )
}
