//! Attack and vulnerability volumes with hit types: Replica Island's "moving objects vs
//! each other", with its flaws fixed.
//!
//! Each frame, game objects register their current animation frame's volumes (circles and
//! boxes in object-local coordinates, mirrored when the object faces the other way), each
//! with the [`HitTypes`] it deals or accepts. [`HitWorld::detect`] pairs the objects with a
//! broadphase (sweep and prune on x, keeping its order between frames, or a uniform grid),
//! tests attack volumes against vulnerability volumes exactly, along the frame's move for
//! moving objects, and reports [`HitEvent`]s in a fixed order after asking a [`HitRule`]
//! whether each victim takes its hit.
//!
//! What changed from the original (see `docs/volumes.md`):
//!
//! - the pair test uses the exact box of all volumes, not a bounding circle of radius
//!   `max(w, h) / 2` that misses volumes reaching into the corners;
//! - touching volumes hit (closed sets), where the original's strict tests did not;
//! - volumes with a move are swept, so a projectile cannot pass through a target;
//! - "hit once per swing" and teams are built in.

mod debug_lines;
mod hit_types;
mod volume;
mod world;

pub use hit_types::HitTypes;
pub use volume::{Facing, Volume, VolumeError, VolumeShape};
pub use world::{HitEvent, HitObject, HitRule, HitWorld, ObjectId, TeamRule};
