//! The crowd audit: overlapping circle pairs and circles sunk into walls, after a run.

use glam::Vec2;

use crate::SolidGrid;

/// How much overlap or penetration, in cells, the audit forgives: BENCHMARKS.md
/// asks for no pair closer than `2r − 1e-3` and no wall penetration deeper than
/// `1e-3`.
pub const AUDIT_TOLERANCE: f32 = 1e-3;

/// What [`audit_crowd`] found: how many pairs overlap and how many circles sink
/// into walls beyond [`AUDIT_TOLERANCE`], and the worst of each.
///
/// A clean crowd has both counts at zero (BENCHMARKS.md's requirement); the
/// maxima then stay at or below the tolerance.
///
/// ```
/// use tileslide_scenes::CrowdAudit;
/// let audit = CrowdAudit::default();
/// assert!(audit.is_clean());
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CrowdAudit {
    /// Pairs of circles whose centres are closer than `2r − 1e-3`.
    pub overlapping_pairs: usize,
    /// Largest `2r − distance` over all pairs, or 0 if no pair overlaps at all
    /// (it includes the pairs within the tolerance).
    pub max_overlap: f32,
    /// Circles that penetrate a solid cell deeper than `1e-3`.
    pub wall_penetrations: usize,
    /// Largest penetration over all circles, or 0 if none touches a solid cell
    /// (it includes the penetrations within the tolerance).
    pub max_penetration: f32,
}

impl CrowdAudit {
    /// Whether nothing overlaps or penetrates beyond the tolerance.
    #[must_use]
    pub fn is_clean(&self) -> bool {
        self.overlapping_pairs == 0 && self.wall_penetrations == 0
    }
}

/// Audits circles of `radius` centred at `positions` on `grid`: the crowd
/// scene's end-of-run check of BENCHMARKS.md.
///
/// - A pair overlaps when its centres are closer than `2r − 1e-3`.
/// - A circle penetrates a solid cell by `r − d`, `d` being the distance from
///   its centre to the closest point of the cell's square; a centre inside (or
///   on the boundary of) a solid cell penetrates by `r + depth`, `depth` being
///   the distance to the nearest face of that cell, so it is always counted.
///   A circle's penetration is the largest over the solid cells; it is counted
///   when deeper than `1e-3`. Cells outside the grid are empty.
///
/// A non-finite centre is a broken run, not a position: it counts as one wall
/// penetration of infinite depth and takes part in no pair. A negative or
/// non-finite `radius` is audited as radius 0.
///
/// Pairs are found with a uniform grid of buckets at least `2r` wide (each
/// circle is compared with the circles of its own and the 8 neighbouring
/// buckets), so the audit stays linear in practice: 50,000 circles take
/// milliseconds. Distances are computed in f64 from the f32 positions.
///
/// ```
/// use glam::Vec2;
/// use tileslide_scenes::{SolidGrid, audit_crowd};
/// // One solid cell (1, 0), covering [1, 2] × [0, 1].
/// let grid = SolidGrid { width: 3, height: 1, solid: vec![false, true, false] };
/// let positions = [Vec2::new(0.5, 0.5), Vec2::new(2.2, 0.5), Vec2::new(2.75, 0.5)];
/// let audit = audit_crowd(&grid, &positions, 0.3);
/// assert_eq!(audit.overlapping_pairs, 1); // 0.55 apart, less than 0.6
/// assert!((audit.max_overlap - 0.05).abs() < 1e-6);
/// assert_eq!(audit.wall_penetrations, 1); // 0.2 from the wall
/// assert!((audit.max_penetration - 0.1).abs() < 1e-6);
/// ```
#[must_use]
pub fn audit_crowd(grid: &SolidGrid, positions: &[Vec2], radius: f32) -> CrowdAudit {
    let radius = if radius.is_finite() {
        f64::from(radius.max(0.0))
    } else {
        0.0
    };
    let (overlapping_pairs, max_overlap) = audit_pairs(positions, radius);
    let (wall_penetrations, max_penetration) = audit_walls(grid, positions, radius);
    CrowdAudit {
        overlapping_pairs,
        max_overlap: max_overlap as f32,
        wall_penetrations,
        max_penetration: max_penetration as f32,
    }
}

/// Penetrations deeper than the tolerance, and the deepest (0 if none).
fn audit_walls(grid: &SolidGrid, positions: &[Vec2], radius: f64) -> (usize, f64) {
    let tolerance = f64::from(AUDIT_TOLERANCE);
    let mut count = 0;
    let mut deepest = 0.0_f64;
    for &p in positions {
        let depth = if p.is_finite() {
            penetration(grid, p, radius)
        } else {
            f64::INFINITY
        };
        if depth > tolerance {
            count += 1;
        }
        deepest = deepest.max(depth);
    }
    (count, deepest)
}

/// How deep the circle of `radius` at `p` sinks into the solid cells of `grid`
/// (the largest over the cells; 0 or less when it touches none).
fn penetration(grid: &SolidGrid, p: Vec2, radius: f64) -> f64 {
    let (px, py) = (f64::from(p.x), f64::from(p.y));
    // Only cells meeting the circle's bounding box can be penetrated, and cells
    // outside the grid are empty, so the range is clamped to the grid (which
    // also keeps it small for centres far outside).
    let last_x = grid.width.saturating_sub(1) as f64;
    let last_y = grid.height.saturating_sub(1) as f64;
    let x0 = (px - radius).floor().max(0.0) as i64;
    let x1 = (px + radius).floor().min(last_x) as i64;
    let y0 = (py - radius).floor().max(0.0) as i64;
    let y1 = (py + radius).floor().min(last_y) as i64;
    let mut deepest = f64::NEG_INFINITY;
    for y in y0..=y1 {
        for x in x0..=x1 {
            if grid.is_solid(x, y) {
                let depth = radius - signed_distance_to_cell(px, py, x as f64, y as f64);
                deepest = deepest.max(depth);
            }
        }
    }
    deepest
}

/// Signed distance from `(px, py)` to the square `[x, x+1] × [y, y+1]`:
/// the distance to its closest point outside, minus the distance to its
/// nearest face inside (0 on the boundary).
fn signed_distance_to_cell(px: f64, py: f64, x: f64, y: f64) -> f64 {
    let dx = (x - px).max(px - (x + 1.0));
    let dy = (y - py).max(py - (y + 1.0));
    if dx <= 0.0 && dy <= 0.0 {
        // Inside: both are minus the distances to the nearer face on each axis.
        dx.max(dy)
    } else {
        dx.max(0.0).hypot(dy.max(0.0))
    }
}

/// Overlapping pairs beyond the tolerance, and the largest overlap (0 if none).
fn audit_pairs(positions: &[Vec2], radius: f64) -> (usize, f64) {
    let reach = 2.0 * radius;
    let finite: Vec<(f64, f64)> = positions
        .iter()
        .filter(|p| p.is_finite())
        .map(|p| (f64::from(p.x), f64::from(p.y)))
        .collect();
    if reach <= 0.0 || finite.len() < 2 {
        return (0, 0.0);
    }
    let buckets = Buckets::new(&finite, reach);
    let limit = reach - f64::from(AUDIT_TOLERANCE);
    let mut count = 0;
    let mut largest = 0.0_f64;
    for (i, &(px, py)) in finite.iter().enumerate() {
        let (bx, by) = buckets.bucket_of(px, py);
        for ny in by.saturating_sub(1)..=(by + 1).min(buckets.rows - 1) {
            for nx in bx.saturating_sub(1)..=(bx + 1).min(buckets.cols - 1) {
                for &j in buckets.members(nx, ny) {
                    // Each unordered pair once.
                    if j <= i {
                        continue;
                    }
                    let (qx, qy) = finite[j];
                    let d = (px - qx).hypot(py - qy);
                    if d < limit {
                        count += 1;
                    }
                    largest = largest.max(reach - d);
                }
            }
        }
    }
    (count, largest)
}

/// A uniform grid of square buckets over the bounding box of some points,
/// filled by counting sort: the members of bucket `b` are
/// `order[start[b]..start[b + 1]]`.
struct Buckets {
    /// Lower corner of the bounding box.
    origin: (f64, f64),
    /// Bucket side, at least the largest distance that matters.
    size: f64,
    /// Buckets along x.
    cols: usize,
    /// Buckets along y.
    rows: usize,
    /// Prefix sums of the bucket counts (`cols * rows + 1` entries).
    start: Vec<usize>,
    /// Point indices, grouped by bucket.
    order: Vec<usize>,
}

impl Buckets {
    /// Buckets at least `reach` wide (`reach > 0`) over `points` (finite,
    /// at least one).
    fn new(points: &[(f64, f64)], reach: f64) -> Self {
        let (mut lo, mut hi) = ((f64::MAX, f64::MAX), (f64::MIN, f64::MIN));
        for &(x, y) in points {
            lo = (lo.0.min(x), lo.1.min(y));
            hi = (hi.0.max(x), hi.1.max(y));
        }
        // Sparse points would make a huge, mostly empty grid: widen the buckets
        // until there are at most about four per point. Wider buckets only cost
        // more distance checks, never a missed pair.
        let max_buckets = (4 * points.len()).max(64) as f64;
        let mut size = reach;
        let dims = |size: f64| {
            (
                ((hi.0 - lo.0) / size).floor() + 1.0,
                ((hi.1 - lo.1) / size).floor() + 1.0,
            )
        };
        while {
            let (c, r) = dims(size);
            c * r > max_buckets
        } {
            size *= 2.0;
        }
        let (c, r) = dims(size);
        let (cols, rows) = (c as usize, r as usize);
        let mut buckets = Self {
            origin: lo,
            size,
            cols,
            rows,
            start: vec![0; cols * rows + 1],
            order: vec![0; points.len()],
        };
        let keys: Vec<usize> = points
            .iter()
            .map(|&(x, y)| {
                let (bx, by) = buckets.bucket_of(x, y);
                by * cols + bx
            })
            .collect();
        for &k in &keys {
            buckets.start[k + 1] += 1;
        }
        for k in 0..cols * rows {
            buckets.start[k + 1] += buckets.start[k];
        }
        let mut next = buckets.start.clone();
        for (i, &k) in keys.iter().enumerate() {
            buckets.order[next[k]] = i;
            next[k] += 1;
        }
        buckets
    }

    /// The bucket holding `(x, y)` (clamped into the grid against rounding).
    fn bucket_of(&self, x: f64, y: f64) -> (usize, usize) {
        let bx = ((x - self.origin.0) / self.size).floor() as usize;
        let by = ((y - self.origin.1) / self.size).floor() as usize;
        (bx.min(self.cols - 1), by.min(self.rows - 1))
    }

    /// The indices of the points in bucket `(bx, by)`.
    fn members(&self, bx: usize, by: usize) -> &[usize] {
        let k = by * self.cols + bx;
        &self.order[self.start[k]..self.start[k + 1]]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{SplitMix64, dungeon256, scene_crowd};

    fn grid(rows: &[&str]) -> SolidGrid {
        SolidGrid::from_rows(rows)
    }

    /// O(n²) pairs and every solid cell for every circle, written from the
    /// definition independently of the bucketed audit.
    fn brute_force(g: &SolidGrid, positions: &[Vec2], radius: f32) -> CrowdAudit {
        let r = f64::from(radius);
        let tol = f64::from(AUDIT_TOLERANCE);
        let mut audit = CrowdAudit::default();
        let (mut max_overlap, mut max_penetration) = (0.0_f64, 0.0_f64);
        for (i, p) in positions.iter().enumerate() {
            for q in &positions[i + 1..] {
                let d = (f64::from(p.x) - f64::from(q.x)).hypot(f64::from(p.y) - f64::from(q.y));
                if d < 2.0 * r - tol {
                    audit.overlapping_pairs += 1;
                }
                max_overlap = max_overlap.max(2.0 * r - d);
            }
            let mut depth = f64::NEG_INFINITY;
            for y in 0..g.height {
                for x in 0..g.width {
                    if !g.solid[y * g.width + x] {
                        continue;
                    }
                    let (x0, y0) = (x as f64, y as f64);
                    let (px, py) = (f64::from(p.x), f64::from(p.y));
                    let inside = (x0..=x0 + 1.0).contains(&px) && (y0..=y0 + 1.0).contains(&py);
                    let d = if inside {
                        let to_face = (px - x0).min(x0 + 1.0 - px).min(py - y0).min(y0 + 1.0 - py);
                        r + to_face
                    } else {
                        let cx = px.clamp(x0, x0 + 1.0);
                        let cy = py.clamp(y0, y0 + 1.0);
                        r - (px - cx).hypot(py - cy)
                    };
                    depth = depth.max(d);
                }
            }
            if depth > tol {
                audit.wall_penetrations += 1;
            }
            max_penetration = max_penetration.max(depth);
        }
        audit.max_overlap = max_overlap as f32;
        audit.max_penetration = max_penetration as f32;
        audit
    }

    #[test]
    fn matches_brute_force_on_random_small_crowds() {
        let mut rng = SplitMix64::new(0xA0D1_7000_0000_0001);
        let mut seen = CrowdAudit::default();
        for round in 0..40 {
            let size = 4 + rng.below(12) as usize;
            let solid = (0..size * size).map(|_| rng.f32() < 0.3).collect();
            let g = SolidGrid {
                width: size,
                height: size,
                solid,
            };
            let n = rng.below(120) as usize;
            let radius = 0.05 + 0.5 * rng.f32();
            // Some centres a little outside the grid, where cells are empty.
            let span = size as f32 + 2.0;
            let positions: Vec<Vec2> = (0..n)
                .map(|_| Vec2::new(span * rng.f32() - 1.0, span * rng.f32() - 1.0))
                .collect();
            let got = audit_crowd(&g, &positions, radius);
            let want = brute_force(&g, &positions, radius);
            assert_eq!(got, want, "round {round}: {n} circles of radius {radius}");
            seen.overlapping_pairs += got.overlapping_pairs;
            seen.wall_penetrations += got.wall_penetrations;
        }
        // The check is only worth something if it saw both kinds of fault.
        assert!(seen.overlapping_pairs > 100 && seen.wall_penetrations > 100);
    }

    #[test]
    fn the_scene_starts_clean() {
        // The lattice leaves 0.05 between circles and 0.01 to the walls.
        let g = dungeon256();
        let positions: Vec<Vec2> = scene_crowd(&g, 50_000).iter().map(|b| b.position).collect();
        let audit = audit_crowd(&g, &positions, crate::CROWD_RADIUS);
        assert!(audit.is_clean(), "{audit:?}");
        assert_eq!(audit.max_overlap, 0.0);
        assert_eq!(audit.max_penetration, 0.0);
    }

    #[test]
    fn pairs_within_the_tolerance_are_forgiven_but_reported() {
        let g = grid(&["....."]);
        // 0.6 − 0.0005 apart: overlapping by 0.0005, within the tolerance.
        let close = [Vec2::new(1.0, 0.5), Vec2::new(1.5995, 0.5)];
        let audit = audit_crowd(&g, &close, 0.3);
        assert_eq!(audit.overlapping_pairs, 0);
        assert!((audit.max_overlap - 0.0005).abs() < 1e-6);
        // 0.002 too close: counted.
        let closer = [Vec2::new(1.0, 0.5), Vec2::new(1.598, 0.5)];
        assert_eq!(audit_crowd(&g, &closer, 0.3).overlapping_pairs, 1);
    }

    #[test]
    fn a_centre_inside_a_wall_penetrates_by_radius_plus_depth() {
        // Cell (1, 0) covers [1, 2] × [0, 1]; the centre 0.2 inside its left face.
        let g = grid(&[".#."]);
        let audit = audit_crowd(&g, &[Vec2::new(1.2, 0.5)], 0.3);
        assert_eq!(audit.wall_penetrations, 1);
        assert!((audit.max_penetration - 0.5).abs() < 1e-6);
        // Even a circle of radius 0 whose centre is inside counts.
        let audit = audit_crowd(&g, &[Vec2::new(1.2, 0.5)], 0.0);
        assert_eq!(audit.wall_penetrations, 1);
        // Just touching the face is not a penetration.
        let audit = audit_crowd(&g, &[Vec2::new(0.7, 0.5)], 0.3);
        assert_eq!(audit.wall_penetrations, 0);
    }

    #[test]
    fn a_corner_is_penetrated_along_the_diagonal() {
        // Cell (1, 1) covers [1, 2] × [1, 2]; centre 0.2 from its corner (1, 1).
        let g = grid(&["...", ".#.", "..."]);
        let audit = audit_crowd(&g, &[Vec2::new(0.88, 0.84)], 0.3);
        assert_eq!(audit.wall_penetrations, 1);
        assert!((audit.max_penetration - 0.1).abs() < 1e-6);
    }

    #[test]
    fn non_finite_centres_are_counted_as_broken() {
        let g = grid(&["..."]);
        let positions = [Vec2::new(f32::NAN, 0.5), Vec2::new(0.5, 0.5)];
        let audit = audit_crowd(&g, &positions, 0.3);
        assert_eq!(audit.wall_penetrations, 1);
        assert_eq!(audit.max_penetration, f32::INFINITY);
        assert_eq!(audit.overlapping_pairs, 0);
    }

    #[test]
    fn sparse_far_apart_circles_do_not_make_a_huge_bucket_grid() {
        let g = grid(&["."]);
        let positions = [
            Vec2::new(-1.0e6, -1.0e6),
            Vec2::new(1.0e6, 1.0e6),
            Vec2::new(1.0e6 + 0.1, 1.0e6),
        ];
        let audit = audit_crowd(&g, &positions, 0.3);
        assert_eq!(audit.overlapping_pairs, 1);
    }
}
