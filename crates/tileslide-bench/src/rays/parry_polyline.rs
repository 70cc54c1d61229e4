//! The parry2d `Polyline` peer: the grid's merged exposed edges as one parry2d [`Polyline`].

use parry2d::query::RayCast;
use parry2d::shape::Polyline;

use super::parry_ray;
use crate::parry_vectors::to_parry;
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
super::test_grids::ray_peer_tests!(ParryPolyline);
