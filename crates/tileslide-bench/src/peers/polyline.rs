//! The parry2d `Polyline` peer: the grid's merged exposed edges as one parry2d [`Polyline`].

use parry2d::query::RayCast;
use parry2d::shape::Polyline;

use super::{parry_ray, to_parry};
use tileslide_scenes::{SceneRay, SolidGrid};

/// The grid's merged exposed edges (maximal collinear runs of solid/empty boundary) as one
/// parry2d [`Polyline`], each edge its own two-vertex segment; parry builds a BVH over the
/// segments and ray casts walk it.
///
/// parry's 2D segments are two-sided (a ray hits a segment from either side), which is harmless
/// here: a ray that starts in an empty cell meets the empty side of a wall edge first.
///
/// Two small differences from [`ParryVoxels`](super::ParryVoxels), neither of which changes a
/// single hit on the standard scenes: parry's composite-shape cast keeps a hit only if its time of
/// impact is strictly below `ray.length` (a wall exactly at the end of the ray is missed), and its
/// segment cast is less precise (on dungeon256's million rays, up to ~4e-4 cells across the face
/// hit, against ~8e-6 for the voxels, because merged edges are long and the line–line solve
/// runs in f32).
#[derive(Clone, Debug)]
pub struct ParryPolyline {
    shape: Polyline,
}

impl ParryPolyline {
    /// The name this peer is reported under.
    pub const NAME: &'static str = "parry2d-polyline";

    /// Builds the polyline from `grid.merged_exposed_edges()`.
    pub fn new(grid: &SolidGrid) -> Self {
        let edges = grid.merged_exposed_edges();
        let mut vertices = Vec::with_capacity(edges.len() * 2);
        let mut indices = Vec::with_capacity(edges.len());
        for edge in &edges {
            let first = vertices.len() as u32;
            vertices.push(to_parry(edge.a));
            vertices.push(to_parry(edge.b));
            indices.push([first, first + 1]);
        }
        Self {
            shape: Polyline::new(vertices, Some(indices)),
        }
    }

    /// The parry2d shape, for callers that want to run other parry queries on it.
    pub fn shape(&self) -> &Polyline {
        &self.shape
    }

    /// Distance in cells along `ray` (whose `dir` must be unit length) to the first exposed edge
    /// it meets within `ray.length`, or `None` if there is none.
    ///
    /// Uses `RayCast::cast_local_ray` (identity pose; parry's time-of-impact-only path for
    /// composite shapes, which skips computing the normal). `solid` is irrelevant: a 2D segment
    /// has no interior.
    #[inline]
    pub fn cast(&self, ray: &SceneRay) -> Option<f32> {
        self.shape.cast_local_ray(&parry_ray(ray), ray.length, true)
    }
}

#[cfg(test)]
mod tests {
    use super::ParryPolyline;
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
        let peer = ParryPolyline::new(&boxed_8x8());
        // Cell (4, 4) covers [4, 5] × [4, 5].
        assert_hit(peer.cast(&ray((1.5, 4.5), (1.0, 0.0), 10.0)), 2.5);
        assert_hit(peer.cast(&ray((6.5, 4.5), (-1.0, 0.0), 10.0)), 1.5);
        assert_hit(peer.cast(&ray((4.5, 1.5), (0.0, 1.0), 10.0)), 2.5);
        assert_hit(peer.cast(&ray((4.5, 6.5), (0.0, -1.0), 10.0)), 1.5);
    }

    #[test]
    fn rays_hit_the_inner_faces_of_the_border() {
        let peer = ParryPolyline::new(&boxed_8x8());
        // The border ring leaves [1, 7] × [1, 7] open.
        assert_hit(peer.cast(&ray((1.5, 1.5), (-1.0, 0.0), 10.0)), 0.5);
        assert_hit(peer.cast(&ray((1.5, 2.25), (0.0, -1.0), 10.0)), 1.25);
        assert_hit(peer.cast(&ray((2.5, 5.5), (1.0, 0.0), 10.0)), 4.5);
        assert_hit(peer.cast(&ray((5.5, 5.75), (0.0, 1.0), 10.0)), 1.25);
    }

    #[test]
    fn a_diagonal_ray_hits_the_side_face_it_reaches_first() {
        let peer = ParryPolyline::new(&boxed_8x8());
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
        let peer = ParryPolyline::new(&boxed_8x8());
        assert_eq!(peer.cast(&ray((1.5, 4.5), (1.0, 0.0), 2.0)), None);
        assert_eq!(peer.cast(&ray((1.5, 1.5), (0.0, 1.0), 5.0)), None);
        // Just long enough.
        assert_hit(peer.cast(&ray((1.5, 4.5), (1.0, 0.0), 2.5001)), 2.5);
    }

    #[test]
    fn a_ray_that_leaves_the_map_misses() {
        let peer = ParryPolyline::new(&lone_cell_8x8());
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
            let peer = ParryPolyline::new(grid);
            rays.iter().map(|r| peer.cast(r)).collect()
        });
        assert!(hits > 1_000, "only {hits} hits: the check is too weak");
    }

    #[test]
    fn agrees_with_the_reference_walk_on_the_dungeon_rays() {
        let grid = tileslide_scenes::dungeon256();
        let peer = ParryPolyline::new(&grid);
        let hits = check_against_scene(&grid, 20_000, |r| peer.cast(r));
        // BENCHMARKS.md: 943,906 of 1,000,000 rays hit on dungeon256.
        assert!((18_500..19_300).contains(&hits), "{hits} hits");
    }
}
