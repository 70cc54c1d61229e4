//! The parry2d `Voxels` peer: the grid's solid cells as a parry2d [`Voxels`] shape.

use parry2d::math::{IVector, Vector};
use parry2d::query::RayCast;
use parry2d::shape::Voxels;

use super::parry_ray;
use tileslide_scenes::{SceneRay, SolidGrid};

/// The grid's solid cells as one parry2d [`Voxels`] shape (voxel size 1, identity pose), queried
/// with parry's own voxel traversal.
///
/// parry places voxel `(i, j)` of a `Voxels` built with `voxel_size = (1, 1)` at
/// `[i, i+1] × [j, j+1]` (minimum corner `(i, j) * voxel_size`, center `(i + 0.5, j + 0.5)`), which
/// is exactly the tileslide cell convention, so solid cell `(x, y)` becomes voxel `(x, y)` and the
/// shape is used with the identity pose: no offset anywhere.
#[derive(Clone, Debug)]
pub struct ParryVoxels {
    shape: Voxels,
}

impl ParryVoxels {
    /// The name this peer is reported under.
    pub const NAME: &'static str = "parry2d-voxels";

    /// Builds the voxel shape from the grid's solid cells.
    ///
    /// Grid coordinates must fit parry's `i32` voxel keys (any grid that fits in memory does).
    /// Entries of `grid.solid` beyond `width * height` are ignored, missing ones read as empty.
    pub fn new(grid: &SolidGrid) -> Self {
        let cells = grid.width * grid.height;
        let keys: Vec<IVector> = grid
            .solid
            .iter()
            .take(cells)
            .enumerate()
            .filter(|&(_, &solid)| solid)
            .map(|(i, _)| IVector::new((i % grid.width) as i32, (i / grid.width) as i32))
            .collect();
        Self {
            shape: Voxels::new(Vector::new(1.0, 1.0), &keys),
        }
    }

    /// The parry2d shape, for callers that want to run other parry queries on it.
    pub fn shape(&self) -> &Voxels {
        &self.shape
    }

    /// Distance in cells along `ray` (whose `dir` must be unit length) to the first solid voxel
    /// boundary it meets within `ray.length`, or `None` if there is none.
    ///
    /// Uses `RayCast::cast_local_ray` (identity pose, so the ray is not transformed; for `Voxels`
    /// it goes through `cast_local_ray_and_get_normal`, parry has no cheaper time-only path) with
    /// `solid = true`. Scene rays start in empty cells, where solid and hollow casts give the same
    /// answer; from inside a voxel, `solid = false` would report that voxel's far side.
    #[inline]
    pub fn cast(&self, ray: &SceneRay) -> Option<f32> {
        self.shape.cast_local_ray(&parry_ray(ray), ray.length, true)
    }
}

#[cfg(test)]
mod tests {
    use super::ParryVoxels;
    use crate::peers::test_grids::{
        boxed_8x8, check_against_reference, check_against_scene, lone_cell_8x8, ray,
    };

    fn assert_hit(got: Option<f32>, want: f32) {
        let got = got.unwrap_or_else(|| panic!("expected a hit at {want}, got a miss"));
        assert!(
            (got - want).abs() < 1e-5,
            "expected a hit at {want}, got {got}"
        );
    }

    #[test]
    fn axis_rays_hit_the_faces_of_the_lone_cell() {
        let peer = ParryVoxels::new(&boxed_8x8());
        // Cell (4, 4) covers [4, 5] × [4, 5].
        assert_hit(peer.cast(&ray((1.5, 4.5), (1.0, 0.0), 10.0)), 2.5);
        assert_hit(peer.cast(&ray((6.5, 4.5), (-1.0, 0.0), 10.0)), 1.5);
        assert_hit(peer.cast(&ray((4.5, 1.5), (0.0, 1.0), 10.0)), 2.5);
        assert_hit(peer.cast(&ray((4.5, 6.5), (0.0, -1.0), 10.0)), 1.5);
    }

    #[test]
    fn rays_hit_the_inner_faces_of_the_border() {
        let peer = ParryVoxels::new(&boxed_8x8());
        // The border ring leaves [1, 7] × [1, 7] open.
        assert_hit(peer.cast(&ray((1.5, 1.5), (-1.0, 0.0), 10.0)), 0.5);
        assert_hit(peer.cast(&ray((1.5, 2.25), (0.0, -1.0), 10.0)), 1.25);
        assert_hit(peer.cast(&ray((2.5, 5.5), (1.0, 0.0), 10.0)), 4.5);
        assert_hit(peer.cast(&ray((5.5, 5.75), (0.0, 1.0), 10.0)), 1.25);
    }

    #[test]
    fn a_diagonal_ray_hits_the_side_face_it_reaches_first() {
        let peer = ParryVoxels::new(&boxed_8x8());
        // Along (0.6, 0.8) from (1.5, 1.5): reaches x = 4 at t = 2.5 / 0.6 = 25/6, where
        // y = 1.5 + 0.8 · 25/6 = 4.833.., inside the left face of cell (4, 4).
        assert_hit(peer.cast(&ray((1.5, 1.5), (0.6, 0.8), 10.0)), 25.0 / 6.0);
        // Along (0.8, 0.6) from (1.5, 2.0): passes x = 4 below the cell (y = 3.875), then
        // reaches y = 4 at t = 2 / 0.6 = 10/3, where x = 4.166.., inside its bottom face.
        assert_hit(peer.cast(&ray((1.5, 2.0), (0.8, 0.6), 20.0)), 10.0 / 3.0);
        // Along (0.8, 0.6) from (5.5, 1.5): reaches the border column x = 7 at
        // t = 1.5 / 0.8 = 1.875 (y = 2.625); from (1.5, 5.5), the border row y = 7 at
        // t = 1.5 / 0.6 = 2.5 (x = 3.5).
        assert_hit(peer.cast(&ray((5.5, 1.5), (0.8, 0.6), 20.0)), 1.875);
        assert_hit(peer.cast(&ray((1.5, 5.5), (0.8, 0.6), 20.0)), 2.5);
    }

    #[test]
    fn a_ray_that_stops_short_misses() {
        let peer = ParryVoxels::new(&boxed_8x8());
        assert_eq!(peer.cast(&ray((1.5, 4.5), (1.0, 0.0), 2.0)), None);
        assert_eq!(peer.cast(&ray((1.5, 1.5), (0.0, 1.0), 5.0)), None);
        // Just long enough.
        assert_hit(peer.cast(&ray((1.5, 4.5), (1.0, 0.0), 2.5001)), 2.5);
    }

    #[test]
    fn a_ray_that_leaves_the_map_misses() {
        let peer = ParryVoxels::new(&lone_cell_8x8());
        assert_eq!(peer.cast(&ray((1.5, 1.5), (1.0, 0.0), 100.0)), None);
        assert_eq!(peer.cast(&ray((1.5, 4.5), (-1.0, 0.0), 100.0)), None);
        // Passes above the cell (y = 7.375 at x = 4) and leaves the map.
        assert_eq!(peer.cast(&ray((1.5, 5.5), (0.8, 0.6), 100.0)), None);
        // The same map still has its lone cell where it should be.
        assert_hit(peer.cast(&ray((1.5, 4.5), (1.0, 0.0), 100.0)), 2.5);
        assert_hit(peer.cast(&ray((4.5, 7.5), (0.0, -1.0), 100.0)), 2.5);
    }

    #[test]
    fn agrees_with_a_brute_force_reference_on_random_grids() {
        let hits = check_against_reference(|grid, rays| {
            let peer = ParryVoxels::new(grid);
            rays.iter().map(|r| peer.cast(r)).collect()
        });
        assert!(hits > 1_000, "only {hits} hits: the check is too weak");
    }

    #[test]
    fn agrees_with_the_reference_walk_on_the_dungeon_rays() {
        let grid = tileslide_scenes::dungeon256();
        let peer = ParryVoxels::new(&grid);
        let hits = check_against_scene(&grid, 20_000, |r| peer.cast(r));
        // BENCHMARKS.md: 943,906 of 1,000,000 rays hit on dungeon256.
        assert!((18_500..19_300).contains(&hits), "{hits} hits");
    }
}
