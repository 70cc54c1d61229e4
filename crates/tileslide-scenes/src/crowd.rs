//! The "crowd" scene: circles on a lattice of free spots, each with a constant velocity.

use glam::Vec2;

use crate::{SolidGrid, SplitMix64};

/// Seed of the crowd scene.
const CROWD_SEED: u64 = 0xC0DE_C0DE_0000_0003;
/// Spacing of the candidate lattice, in cells.
const LATTICE_STEP: f32 = 0.65;
/// Clearance a candidate needs from every solid cell: a little more than
/// [`CROWD_RADIUS`], so that no circle starts touching a wall.
const CLEARANCE: f32 = 0.31;
/// Length of every velocity, in cells per step.
const SPEED: f32 = 0.05;

/// Radius of every circle of the crowd scene, in cells.
///
/// The lattice spacing (0.65) leaves a gap of 0.05 between neighbouring circles
/// at the start, and the candidate clearance (0.31) a gap of at least 0.01
/// between a circle and the walls.
pub const CROWD_RADIUS: f32 = 0.3;

/// One circle of the crowd scene: where it starts and the move it proposes every step.
///
/// ```
/// use glam::Vec2;
/// use tileslide_scenes::CrowdBody;
/// let body = CrowdBody { position: Vec2::new(1.5, 1.5), velocity: Vec2::new(0.05, 0.0) };
/// assert_eq!(body.position + body.velocity, Vec2::new(1.55, 1.5));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CrowdBody {
    /// Centre at the start, a candidate of [`crowd_candidates`].
    pub position: Vec2,
    /// Constant proposed move per step, `0.05 · (cos θ, sin θ)` cells.
    pub velocity: Vec2,
}

/// The free spots of the crowd scene on `grid`, in lattice order: the points
/// `((i + 0.5) · 0.65, (j + 0.5) · 0.65)` for `i, j` in `0..floor(256 / 0.65)`
/// (`j` outer, `i` inner) whose disk of radius 0.31 touches no solid cell.
/// dungeon256 has 74,276.
///
/// The lattice is always 393 × 393 points, whatever the grid's size
/// (BENCHMARKS.md defines it for the 256-cell maps); points over cells outside
/// the grid are kept, as those cells are empty.
///
/// "Touches" means that the closest point of the solid cell's closed square
/// `[x, x+1] × [y, y+1]` is at distance `<= 0.31` from the lattice point.
/// The boundary convention does not matter on dungeon256: the strict reading
/// (`< 0.31`), and the same tests done in f64 instead of f32, all give the
/// published 74,276.
///
/// ```
/// let grid = tileslide_scenes::dungeon256();
/// assert_eq!(tileslide_scenes::crowd_candidates(&grid).len(), 74_276);
/// ```
#[must_use]
pub fn crowd_candidates(grid: &SolidGrid) -> Vec<Vec2> {
    // floor(256 / 0.65) = 393, computed once in f64 to avoid any doubt about
    // the rounding of 0.65.
    let count = (256.0_f64 / f64::from(LATTICE_STEP)).floor() as u32;
    let mut candidates = Vec::new();
    for j in 0..count {
        for i in 0..count {
            // Lattice indices are below 2²⁴, so the casts are exact.
            let point = Vec2::new(
                (i as f32 + 0.5) * LATTICE_STEP,
                (j as f32 + 0.5) * LATTICE_STEP,
            );
            if !touches_solid(grid, point, CLEARANCE) {
                candidates.push(point);
            }
        }
    }
    candidates
}

/// Whether the closed disk of `radius` around `point` touches the closed square
/// of any solid cell (distance to the square's closest point `<= radius`).
fn touches_solid(grid: &SolidGrid, point: Vec2, radius: f32) -> bool {
    // Every cell whose square comes within `radius` of the point lies in the
    // cell range of the disk's bounding box; one cell more on each side makes
    // that hold even when a box side falls exactly on a grid line.
    let x0 = (point.x - radius).floor() as i64 - 1;
    let x1 = (point.x + radius).floor() as i64 + 1;
    let y0 = (point.y - radius).floor() as i64 - 1;
    let y1 = (point.y + radius).floor() as i64 + 1;
    (y0..=y1).any(|y| {
        (x0..=x1).any(|x| {
            if !grid.is_solid(x, y) {
                return false;
            }
            // Cell coordinates here are small, so the casts are exact.
            let (cx, cy) = (x as f32, y as f32);
            let closest = Vec2::new(point.x.clamp(cx, cx + 1.0), point.y.clamp(cy, cy + 1.0));
            point.distance_squared(closest) <= radius * radius
        })
    })
}

/// The first `n` circles of the "crowd" scene of BENCHMARKS.md on `grid` (seed
/// `0xC0DEC0DE00000003`); all of the candidates when `n` is larger.
///
/// In draw order: the [`crowd_candidates`] are shuffled with Fisher–Yates
/// (`for i in (1..len).rev() { j = below(i + 1); swap(i, j) }`) and the first
/// `n` kept; then, from the same generator, one velocity per kept circle in
/// order: angle `f32() · 2π` in f32 arithmetic, velocity `0.05 · (cos, sin)`
/// with Rust's f32 `cos`/`sin`. Every circle has radius [`CROWD_RADIUS`].
///
/// ```
/// let grid = tileslide_scenes::dungeon256();
/// let crowd = tileslide_scenes::scene_crowd(&grid, 1_000);
/// assert_eq!(crowd.len(), 1_000);
/// assert!(crowd.iter().all(|b| (b.velocity.length() - 0.05).abs() < 1e-6));
/// ```
#[must_use]
pub fn scene_crowd(grid: &SolidGrid, n: usize) -> Vec<CrowdBody> {
    let mut candidates = crowd_candidates(grid);
    let mut rng = SplitMix64::new(CROWD_SEED);
    for i in (1..candidates.len()).rev() {
        // below(i + 1) <= i, so the index is in range.
        let j = usize::try_from(rng.below(i as u64 + 1)).unwrap_or(0);
        candidates.swap(i, j);
    }
    candidates.truncate(n);
    candidates
        .into_iter()
        .map(|position| {
            let angle = rng.f32() * std::f32::consts::TAU;
            CrowdBody {
                position,
                velocity: Vec2::new(angle.cos(), angle.sin()) * SPEED,
            }
        })
        .collect()
}

/// `crowd` run on `map` with the core's [`Bodies`](tileslide::Bodies) as the golden test
/// runs it: one circle of [`CROWD_RADIUS`] per body, each proposing its velocity every step,
/// `steps` steps. The set, and the handles in crowd order.
///
/// # Errors
/// A body the set refuses (a position out of range): never for the scene's own bodies.
pub fn run_crowd(
    map: &tileslide::TileMap,
    crowd: &[CrowdBody],
    steps: usize,
) -> Result<(tileslide::Bodies, Vec<tileslide::BodyHandle>), tileslide::BodyError> {
    let mut bodies = tileslide::Bodies::new();
    let mut handles = Vec::with_capacity(crowd.len());
    for b in crowd {
        let shape = tileslide::BodyShape::circle(CROWD_RADIUS)?;
        handles.push(bodies.add(tileslide::BodyDesc::new(b.position, shape))?);
    }
    for _ in 0..steps {
        for (h, b) in handles.iter().zip(crowd) {
            bodies.propose(*h, b.velocity)?;
        }
        bodies.step(map);
    }
    Ok((bodies, handles))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dungeon256;

    fn grid(rows: &[&str]) -> SolidGrid {
        SolidGrid::from_rows(rows)
    }

    #[test]
    fn dungeon256_has_the_published_74276_candidates() {
        assert_eq!(crowd_candidates(&dungeon256()).len(), 74_276);
    }

    #[test]
    fn candidates_keep_their_clearance_from_every_solid_cell() {
        let g = dungeon256();
        for p in crowd_candidates(&g) {
            // Brute force over the 3×3 cells around the point (0.31 < 1).
            let (px, py) = (p.x.floor() as i64, p.y.floor() as i64);
            for y in py - 1..=py + 1 {
                for x in px - 1..=px + 1 {
                    if g.is_solid(x, y) {
                        let q = Vec2::new(
                            p.x.clamp(x as f32, x as f32 + 1.0),
                            p.y.clamp(y as f32, y as f32 + 1.0),
                        );
                        assert!(p.distance(q) > 0.31 - 1e-6, "{p} touches cell ({x}, {y})");
                    }
                }
            }
        }
    }

    #[test]
    fn a_disk_that_just_reaches_a_cell_touches_it() {
        // Cell (1, 1) covers [1, 2] × [1, 2].
        let g = grid(&["....", ".#..", "...."]);
        assert!(!touches_solid(&g, Vec2::new(0.5, 1.5), 0.31));
        assert!(touches_solid(&g, Vec2::new(0.75, 1.5), 0.25));
        assert!(touches_solid(&g, Vec2::new(1.5, 2.25), 0.25));
        // Diagonal from the corner (2, 2): at distance 0.3 (a 3-4-5 triangle).
        assert!(touches_solid(&g, Vec2::new(2.18, 2.24), 0.301));
        assert!(!touches_solid(&g, Vec2::new(2.18, 2.24), 0.299));
    }

    #[test]
    fn crowd_is_deterministic_and_a_prefix_of_the_shuffle() {
        let g = dungeon256();
        let a = scene_crowd(&g, 1_000);
        assert_eq!(a, scene_crowd(&g, 1_000));
        // The positions of a smaller crowd are a prefix (same shuffle); the
        // velocities are drawn after the shuffle, so they are too.
        let small = scene_crowd(&g, 10);
        assert_eq!(small[..], a[..10]);
        let candidates = crowd_candidates(&g);
        for body in &a {
            assert!(candidates.contains(&body.position));
            assert!((body.velocity.length() - SPEED).abs() < 1e-6);
        }
    }

    #[test]
    fn crowd_positions_are_distinct() {
        let g = dungeon256();
        let mut keys: Vec<(u32, u32)> = scene_crowd(&g, 50_000)
            .iter()
            .map(|b| (b.position.x.to_bits(), b.position.y.to_bits()))
            .collect();
        keys.sort_unstable();
        keys.dedup();
        assert_eq!(keys.len(), 50_000);
    }

    #[test]
    fn asking_for_more_than_the_candidates_takes_them_all() {
        let g = dungeon256();
        assert_eq!(scene_crowd(&g, 1_000_000).len(), 74_276);
        assert!(scene_crowd(&g, 0).is_empty());
    }

    #[test]
    fn shuffle_follows_the_published_fisher_yates() {
        // Replays the specification step by step on the candidate list.
        let g = dungeon256();
        let mut want = crowd_candidates(&g);
        let mut rng = SplitMix64::new(0xC0DE_C0DE_0000_0003);
        let mut i = want.len() - 1;
        while i >= 1 {
            let j = rng.below(i as u64 + 1) as usize;
            want.swap(i, j);
            i -= 1;
        }
        let got = scene_crowd(&g, 5);
        for (k, body) in got.iter().enumerate() {
            assert_eq!(body.position, want[k]);
            let angle = rng.f32() * std::f32::consts::TAU;
            assert_eq!(body.velocity, Vec2::new(angle.cos(), angle.sin()) * 0.05);
        }
    }
}
