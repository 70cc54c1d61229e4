//! Vectors across to parry2d and rapier2d, which every scene's peers use.
//!
//! parry2d 0.31 is built on `glamx` 0.3, which re-exports **glam 0.33**, while this workspace uses
//! glam 0.34; the two `Vec2` types are distinct, so vectors cross the boundary field by field.

use parry2d::math::Vector;

/// Converts a workspace (glam 0.34) vector into parry2d's vector type (glam 0.33 through glamx).
#[inline]
pub fn to_parry(v: glam::Vec2) -> Vector {
    Vector::new(v.x, v.y)
}
