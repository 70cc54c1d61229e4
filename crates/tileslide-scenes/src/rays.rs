//! The "rays" scene: seeded rays starting in empty cells of a map.

use glam::Vec2;

use crate::{SolidGrid, SplitMix64};

/// Seed of the rays scene.
const RAYS_SEED: u64 = 0xA11C_E5ED_0000_0002;
/// Longest ray, in cells.
const MAX_LENGTH: f32 = 64.0;

/// One benchmark ray: origin, unit direction, length (in cells).
///
/// ```
/// use glam::Vec2;
/// use tileslide_scenes::SceneRay;
/// let ray = SceneRay { origin: Vec2::new(1.0, 2.0), dir: Vec2::X, length: 3.0 };
/// assert_eq!(ray.end(), Vec2::new(4.0, 2.0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SceneRay {
    /// Start point, inside an empty cell.
    pub origin: Vec2,
    /// Unit direction `(cos θ, sin θ)`.
    pub dir: Vec2,
    /// Length in cells, in `(0, 64]`.
    pub length: f32,
}

impl SceneRay {
    /// The end point, `origin + dir * length`.
    #[must_use]
    pub fn end(&self) -> Vec2 {
        self.origin + self.dir * self.length
    }
}

/// The first `n` rays of the "rays" scene of BENCHMARKS.md on `grid` (seed
/// `0xA11CE5ED00000002`). Returns no rays if the grid has no empty cell.
///
/// Per ray, in draw order: an empty cell `empties[below(len)]` (empty cells in
/// row-major order); origin `(x + f32(), y + f32())`; angle `f32() * TAU` in
/// f32; direction `(cos, sin)` with Rust's f32 `cos`/`sin`; length
/// `64 * (1 - f32())`.
///
/// ```
/// let grid = tileslide_scenes::dungeon256();
/// let rays = tileslide_scenes::scene_rays(&grid, 10);
/// assert_eq!(rays.len(), 10);
/// for ray in &rays {
///     let cell = ray.origin.floor();
///     assert!(!grid.is_solid(cell.x as i64, cell.y as i64));
/// }
/// ```
#[must_use]
pub fn scene_rays(grid: &SolidGrid, n: usize) -> Vec<SceneRay> {
    let empties: Vec<Vec2> = (0..grid.height)
        .flat_map(|y| (0..grid.width).map(move |x| (x, y)))
        .filter(|&(x, y)| !grid.solid.get(y * grid.width + x).copied().unwrap_or(false))
        // Grid coordinates are small enough for f32 to hold them exactly.
        .map(|(x, y)| Vec2::new(x as f32, y as f32))
        .collect();
    if empties.is_empty() {
        return Vec::new();
    }
    let count = empties.len() as u64;
    let mut rng = SplitMix64::new(RAYS_SEED);
    (0..n)
        .map(|_| {
            let pick = usize::try_from(rng.below(count)).unwrap_or(0);
            let cell = empties.get(pick).copied().unwrap_or(Vec2::ZERO);
            let fx = rng.f32();
            let fy = rng.f32();
            let origin = Vec2::new(cell.x + fx, cell.y + fy);
            let angle = rng.f32() * std::f32::consts::TAU;
            let dir = Vec2::new(angle.cos(), angle.sin());
            let length = MAX_LENGTH * (1.0 - rng.f32());
            SceneRay {
                origin,
                dir,
                length,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dungeon256;

    #[test]
    fn rays_start_in_empty_cells_with_unit_directions_and_bounded_lengths() {
        let grid = dungeon256();
        for ray in scene_rays(&grid, 10_000) {
            let cell = ray.origin.floor();
            assert!(!grid.is_solid(cell.x as i64, cell.y as i64));
            assert!((ray.dir.length() - 1.0).abs() < 1e-6);
            assert!(ray.length > 0.0 && ray.length <= 64.0);
        }
    }

    #[test]
    fn a_shorter_scene_is_a_prefix_of_a_longer_one() {
        let grid = dungeon256();
        let long = scene_rays(&grid, 100);
        assert_eq!(scene_rays(&grid, 10)[..], long[..10]);
    }

    #[test]
    fn grid_without_empty_cells_gives_no_rays() {
        let full = SolidGrid {
            width: 2,
            height: 2,
            solid: vec![true; 4],
        };
        assert!(scene_rays(&full, 5).is_empty());
    }
}
