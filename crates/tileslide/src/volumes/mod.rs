//! Attack and vulnerability volumes with hit types: Replica Island's "moving objects vs
//! each other", with its flaws fixed.
//!
//! Each frame, game objects register their current animation frame's volumes (circles,
//! rectangles and capsules in object-local coordinates, mirrored when the object faces the
//! other way, attack volumes turned where it aims), each with the [`HitTypes`] it deals or
//! accepts. [`HitWorld::detect`] pairs the objects with a broadphase (sweep and prune on
//! x, keeping its order between frames, or a uniform grid), tests attack volumes against
//! vulnerability volumes exactly, along the frame's move for moving objects, and reports
//! [`HitEvent`]s in a fixed order after asking a [`HitRule`] whether each victim takes its
//! hit. Each event names both objects by their owners and says when (the time of impact
//! along the frame's move) and where the hit happened; the events stay readable until the
//! next `detect`.
//!
//! What changed from the original (see `docs/volumes.md`):
//!
//! - the pair test uses the exact box of all volumes, not a bounding circle of radius
//!   `max(w, h) / 2` that misses volumes reaching into the corners;
//! - touching volumes hit (closed sets), where the original's strict tests did not;
//! - volumes with a move are swept, so a projectile cannot pass through a target, and the
//!   hit says when along the move it happened, so a game can tell which victim came first;
//! - "hit once per swing" and teams are built in;
//! - attack volumes can be turned to aim in any direction, not only mirrored.
//!
//! Modules, in import order: `hit_types.rs`; `volume.rs` (shapes, `Facing`, errors);
//! `object.rs` (`HitObject`, `ObjectId`); `event.rs` (`HitEvent`, the rules);
//! `rounded.rs` (turned rectangles and capsules as rounded convex cores); `placed.rs`
//! (volumes in the world, the pair test); `contact.rs` (time of impact and contact point);
//! `trace.rs` (`DetectTrace`: what a traced `detect` tested and decided); `world.rs`
//! (`HitWorld`); `debug_lines.rs`.

mod contact;
mod debug_lines;
mod event;
mod hit_types;
mod object;
mod placed;
#[cfg(feature = "aim")]
mod rounded;
mod trace;
mod volume;
mod world;

pub use event::{HitEvent, HitRule, TeamRule};
pub use hit_types::HitTypes;
pub use object::{HitObject, ObjectId};
pub use trace::{DetectTrace, PairOutcome, PairTrace, Refusal, VolumeTest};
pub use volume::{Facing, Volume, VolumeError, VolumeShape};
pub use world::{HitWorld, MAX_FRAME_VOLUMES, MAX_HIT_OBJECTS, MAX_OBJECT_VOLUMES};
