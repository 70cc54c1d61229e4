//! Shared by the platformer's tests: where the Replica Island data is, and an independent
//! check that a box is not inside solid.
#![allow(clippy::unwrap_used, dead_code)]

use std::path::{Path, PathBuf};

use tileslide::{Aabb, SegmentFlags, TileMap, Vec2};

/// The Replica Island data beside the checkout, or `None` (with a note) when it is missing
/// outside CI; in CI its absence fails the test.
pub fn replica_dir() -> Option<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/data/replica-island");
    if dir.is_dir() {
        return Some(dir);
    }
    assert!(
        std::env::var_os("CI").is_none(),
        "CI is set but the Replica Island data is missing at {}",
        dir.display()
    );
    eprintln!("skipped: no Replica Island data at {}", dir.display());
    None
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
