//! What `detect` reports: one event per hit, saying who hit whom, with what, when and
//! where, and the rules that decide whether a victim takes its hit.

use glam::Vec2;

use super::HitTypes;
use super::object::{HitObject, ObjectId};
use super::trace::Refusal;
use crate::owner::Owner;

/// One hit: an attack volume of `attacker` met a vulnerability volume of `victim` that
/// accepts its type, at time `t` of the frame's move, at `point`.
///
/// [`HitWorld`](super::HitWorld) keeps the events of its last
/// [`detect`](super::HitWorld::detect) until the next one (read them with
/// [`events`](super::HitWorld::events), or take them with
/// [`drain_events`](super::HitWorld::drain_events)). `attacker` and `victim` number the
/// objects of the frame `detect` ran in, so once the next frame has begun only the owners
/// still say who they were.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HitEvent {
    /// Who hit, as registered this frame.
    pub attacker: ObjectId,
    /// Who was hit, as registered this frame.
    pub victim: ObjectId,
    /// The attacker's [`HitObject::owner`]: the caller's key for it.
    pub attacker_owner: Owner,
    /// The victim's [`HitObject::owner`].
    pub victim_owner: Owner,
    /// The types dealt: the attack volume's types that the vulnerability volume accepts.
    pub hit_type: HitTypes,
    /// Whether the victim (the [`HitRule`]) took the hit.
    pub accepted: bool,
    /// When the volumes first touched, as a fraction of the frame's move in `[0, 1]`: 0
    /// when they overlap where the frame starts (and always, for objects that did not
    /// move), 1 at the end of the move. Of several victims of one fireball, the one with
    /// the least `t` is the first it reached.
    pub t: f32,
    /// Where the volumes touched at `t`, in world coordinates: a point both hold then. For
    /// volumes that overlap from the start, see
    /// [`HitWorld::detect`](super::HitWorld::detect) for which point of the overlap.
    pub point: Vec2,
}

/// Decides whether a victim takes a hit. The victim is asked first; the attacker learns
/// the answer from [`HitEvent::accepted`].
pub trait HitRule {
    /// True when `victim` takes a hit of `hit_type` from `attacker`.
    fn accept(&mut self, attacker: &HitObject, victim: &HitObject, hit_type: HitTypes) -> bool;

    /// Why the victim refused a hit that [`accept`](Self::accept) just refused: asked only
    /// by [`HitWorld::detect_traced`](super::HitWorld::detect_traced). By default
    /// [`Refusal::Rule`] (the game's own rule said no).
    fn refusal(&mut self, attacker: &HitObject, victim: &HitObject, hit_type: HitTypes) -> Refusal {
        let _ = (attacker, victim, hit_type);
        Refusal::Rule
    }
}

/// The built-in rule: a victim takes hits from other teams while it is not invulnerable.
#[derive(Clone, Copy, Debug, Default)]
pub struct TeamRule;

impl HitRule for TeamRule {
    fn accept(&mut self, attacker: &HitObject, victim: &HitObject, _: HitTypes) -> bool {
        attacker.team != victim.team && !victim.invulnerable
    }

    fn refusal(&mut self, attacker: &HitObject, victim: &HitObject, _: HitTypes) -> Refusal {
        if attacker.team == victim.team {
            Refusal::SameTeam
        } else {
            Refusal::Invulnerable
        }
    }
}

impl<F: FnMut(&HitObject, &HitObject, HitTypes) -> bool> HitRule for F {
    fn accept(&mut self, attacker: &HitObject, victim: &HitObject, hit_type: HitTypes) -> bool {
        self(attacker, victim, hit_type)
    }
}
