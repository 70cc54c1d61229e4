//! The collision audit: after every step, no character may be inside solid, and no
//! character's centre may have crossed a solid face during the step. Checked with the
//! map's own queries, independently of the controller that moved them.

use tileslide::{Aabb, QueryFilter, Ray, SegmentFlags, TileMap, Vec2};

/// Overlaps shallower than this fraction of a cell are contact, not penetration (the
/// controller keeps a skin of a thousandth of a cell).
pub const TOLERANCE: f32 = 0.002;

/// What the audit found over a run.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Audit {
    /// Character-steps that ended overlapping a solid segment by more than the tolerance,
    /// or with the centre inside a solid tile.
    pub inside_solid: u64,
    /// Character-steps whose centre crossed a solid face.
    pub tunnels: u64,
    /// The deepest overlap found, in cells (0 when none).
    pub max_penetration: f32,
}

impl Audit {
    /// Checks a character of half size `half` that moved from `from` to `to` this step, on
    /// a map with cells `scale` wide.
    pub fn check(&mut self, map: &TileMap, from: Vec2, to: Vec2, half: Vec2, scale: f32) {
        let tolerance = TOLERANCE * scale;
        if overlaps_solid(map, to, half, tolerance) || map.is_point_solid(to) {
            self.inside_solid += 1;
            let depth = penetration(map, to, half, tolerance) / scale;
            self.max_penetration = self.max_penetration.max(depth);
        }
        let solid = QueryFilter::default().with_mask(SegmentFlags::SOLID);
        if from != to && map.cast_ray(Ray::between(from, to), &solid).is_some() {
            self.tunnels += 1;
        }
    }

    /// True when nothing was found.
    #[must_use]
    pub fn is_clean(&self) -> bool {
        self.inside_solid == 0 && self.tunnels == 0
    }
}

/// Whether the box at `center`, shrunk by `shrink` on every side, overlaps a solid segment.
#[must_use]
pub fn overlaps_solid(map: &TileMap, center: Vec2, half: Vec2, shrink: f32) -> bool {
    let inner = half - Vec2::splat(shrink);
    if inner.min_element() <= 0.0 {
        return false;
    }
    map.segments_overlapping_aabb(&Aabb::from_center(center, inner))
        .iter()
        .any(|s| s.flags.contains(SegmentFlags::SOLID))
}

/// How deep the box is in solid: the least shrink at which it overlaps nothing (bisection
/// to a ten-thousandth of the half size).
fn penetration(map: &TileMap, center: Vec2, half: Vec2, tolerance: f32) -> f32 {
    let (mut lo, mut hi) = (tolerance, half.min_element());
    for _ in 0..14 {
        let mid = 0.5 * (lo + hi);
        if overlaps_solid(map, center, half, mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    hi
}
