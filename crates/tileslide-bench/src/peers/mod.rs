//! The peers tileslide is measured against, each wrapped behind the same small API so that a
//! benchmark can run them on exactly the same scene in the same process.
//!
//! Every peer has a `NAME`, a `new` that builds its acceleration structure from the scene (not
//! timed by the ray benchmark), and a `cast` that answers one [`SceneRay`] with the distance, in
//! cells, to the first solid-cell boundary the ray meets within its length.
//!
//! parry2d 0.31 is built on `glamx` 0.3, which re-exports **glam 0.33**, while this workspace uses
//! glam 0.34; the two `Vec2` types are distinct, so vectors cross the boundary field by field
//! (see [`to_parry`]).

mod polyline;
mod voxels;

#[cfg(test)]
mod test_grids;

pub use polyline::ParryPolyline;
pub use voxels::ParryVoxels;

use parry2d::math::Vector;
use parry2d::query::Ray;
use tileslide_scenes::SceneRay;

/// Converts a workspace (glam 0.34) vector into parry2d's vector type (glam 0.33 through glamx).
#[inline]
pub fn to_parry(v: glam::Vec2) -> Vector {
    Vector::new(v.x, v.y)
}

/// The parry2d ray of a scene ray: same origin, same (unit) direction, so parry's time of impact
/// is a distance in cells and `ray.length` can be passed as the maximum time of impact unchanged.
#[inline]
pub fn parry_ray(ray: &SceneRay) -> Ray {
    Ray::new(to_parry(ray.origin), to_parry(ray.dir))
}
