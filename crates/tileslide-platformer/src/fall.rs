//! Falling: the gravity that pulls the player and the enemies, and the fastest fall.

/// Gravity, in cells per second per second.
pub const GRAVITY: f32 = 40.0;
/// The fastest fall, in cells per second.
const MAX_FALL: f32 = 20.0;

/// Gravity in world units per second per second, on a map whose cells are `scale` wide.
#[must_use]
pub(crate) fn gravity(scale: f32) -> f32 {
    GRAVITY * scale
}

/// The speed along up (world units per second) after falling for `dt` seconds from
/// `rise`, no faster than the fastest fall.
#[must_use]
pub(crate) fn fall(rise: f32, dt: f32, scale: f32) -> f32 {
    (rise - gravity(scale) * dt).max(-MAX_FALL * scale)
}
