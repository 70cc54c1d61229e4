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
super::test_grids::ray_peer_tests!(ParryVoxels);
