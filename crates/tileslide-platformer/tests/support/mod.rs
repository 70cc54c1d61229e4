//! Shared by the platformer's tests: where the Replica Island data is (the core crate's
//! test support, read in place), and an independent check that a box is not inside solid.
#![allow(clippy::unwrap_used, dead_code)]

#[path = "../../../tileslide/tests/replica_support/mod.rs"]
mod replica_support;

use std::path::PathBuf;

use tileslide::{Aabb, SegmentFlags, TileMap, Vec2};

/// The Replica Island data beside the checkout, or `None` (with a note) when it is missing
/// outside CI; in CI its absence fails the test.
pub fn replica_dir() -> Option<PathBuf> {
    replica_support::data_dir()
}

/// Whether a box at `center` overlaps a solid segment by more than a five-hundredth of a
/// cell (`scale` wide), or its centre is in a solid tile.
pub fn inside_solid(map: &TileMap, center: Vec2, half: Vec2, scale: f32) -> bool {
    let probe = Aabb::from_center(center, half - Vec2::splat(0.002 * scale));
    map.is_point_solid(center)
        || map
            .segments_overlapping_aabb(&probe)
            .iter()
            .any(|s| s.flags.contains(SegmentFlags::SOLID))
}
