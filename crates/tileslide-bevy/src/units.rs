//! Bevy's world and tileslide's map: one scale and a flipped y axis, converted here and
//! nowhere else.

use bevy::prelude::*;

/// How positions in Bevy's world relate to positions on the map.
///
/// tileslide's loaders read maps y down, the way editors draw them (row 0 on top), while
/// Bevy's y points up. So a map point `(x, y)` is the world point `(x · scale, −y · scale)`:
/// the map's top-left corner is at the world's origin and the map extends to +x and −y.
/// Every component of this crate is in world units (Bevy's), y up; the plugin converts at
/// the boundary, so a game never sees the map's axes. With a power of two for `scale` (the
/// default, 1, included) the conversion is exact both ways.
///
/// Points and vectors (moves, velocities, normals, offsets) convert alike: the map's origin
/// is the world's, so no offset is added.
///
/// Bevy's `Vec2` and tileslide's `Vec2` are different types (Bevy 0.19 uses glam 0.32,
/// tileslide glam 0.34); these methods are the bridge.
///
/// ```
/// # use bevy::prelude::*;
/// # use tileslide_bevy::MapUnits;
/// let units = MapUnits::new(16.0)?;
/// let world = Vec2::new(40.0, -24.0);
/// assert_eq!(units.to_map(world), tileslide::Vec2::new(2.5, 1.5));
/// assert_eq!(units.to_world(units.to_map(world)), world);
/// assert!(MapUnits::new(0.0).is_err());
/// # Ok::<(), tileslide_bevy::InvalidScale>(())
/// ```
#[derive(Resource, Clone, Copy, Debug, PartialEq)]
pub struct MapUnits {
    scale: f32,
}

impl Default for MapUnits {
    fn default() -> Self {
        Self { scale: 1.0 }
    }
}

/// A scale [`MapUnits::new`] refuses: not between [`MapUnits::MIN_SCALE`] and
/// [`MapUnits::MAX_SCALE`] (NaN and infinities included).
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
#[error(
    "the scale {0} is not a number of world units per map unit from {min} to {max}",
    min = MapUnits::MIN_SCALE,
    max = MapUnits::MAX_SCALE
)]
pub struct InvalidScale(pub f32);

impl MapUnits {
    /// The smallest scale: 2⁻²⁰ world units per map unit.
    pub const MIN_SCALE: f32 = 1.0 / 1_048_576.0;
    /// The largest scale: 2²⁰ world units per map unit.
    pub const MAX_SCALE: f32 = 1_048_576.0;

    /// World units per map unit (for a Tiled map in pixels drawn at one world unit a pixel,
    /// 1; for an ASCII map of unit cells drawn 32 units a cell, 32).
    ///
    /// # Errors
    /// [`InvalidScale`] for a scale outside [`MIN_SCALE`](Self::MIN_SCALE) to
    /// [`MAX_SCALE`](Self::MAX_SCALE): past them a world position converts to a map
    /// position the core refuses, or to one that rounds away what the game meant.
    pub fn new(scale: f32) -> Result<Self, InvalidScale> {
        if (Self::MIN_SCALE..=Self::MAX_SCALE).contains(&scale) {
            Ok(Self { scale })
        } else {
            Err(InvalidScale(scale))
        }
    }

    /// World units per map unit.
    #[must_use]
    pub fn scale(&self) -> f32 {
        self.scale
    }

    /// The map point (or vector) at world point (or vector) `p`.
    #[must_use]
    pub fn to_map(&self, p: Vec2) -> tileslide::Vec2 {
        tileslide::Vec2::new(p.x / self.scale, -p.y / self.scale)
    }

    /// The world point (or vector) at map point (or vector) `p`.
    #[must_use]
    pub fn to_world(&self, p: tileslide::Vec2) -> Vec2 {
        Vec2::new(p.x * self.scale, -p.y * self.scale)
    }

    /// A world direction (a normal, an up) on the map: y flipped, not scaled.
    #[must_use]
    pub fn direction_to_map(&self, d: Vec2) -> tileslide::Vec2 {
        tileslide::Vec2::new(d.x, -d.y)
    }

    /// A map direction in the world: y flipped, not scaled.
    #[must_use]
    pub fn direction_to_world(&self, d: tileslide::Vec2) -> Vec2 {
        Vec2::new(d.x, -d.y)
    }

    /// A world distance (a radius, a half width) in map units.
    #[must_use]
    pub fn length_to_map(&self, d: f32) -> f32 {
        d / self.scale
    }

    /// A map distance in world units.
    #[must_use]
    pub fn length_to_world(&self, d: f32) -> f32 {
        d * self.scale
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    #[test]
    fn a_power_of_two_scale_converts_exactly_both_ways() {
        let units = MapUnits::new(32.0).unwrap();
        for p in [
            Vec2::new(0.1, -7.3),
            Vec2::new(-1e6, 3.25),
            Vec2::new(0.0, 0.0),
        ] {
            assert_eq!(units.to_world(units.to_map(p)), p);
        }
        assert_eq!(
            units.to_map(Vec2::new(32.0, 64.0)),
            tileslide::Vec2::new(1.0, -2.0)
        );
    }

    #[test]
    fn a_scale_outside_its_range_is_refused_by_value() {
        for bad in [0.0, -2.0, f32::NAN, f32::INFINITY, 1e-40, 1e-7, 2e6] {
            let refused = MapUnits::new(bad);
            // (Compared by bits: NaN is not equal to itself.)
            assert_eq!(
                refused.map_err(|e| e.0.to_bits()),
                Err(bad.to_bits()),
                "{bad}"
            );
            assert!(
                refused
                    .unwrap_err()
                    .to_string()
                    .starts_with(&format!("the scale {bad} is not"))
            );
        }
        for good in [
            MapUnits::MIN_SCALE,
            1.0 / 16.0,
            1.0,
            32.0,
            MapUnits::MAX_SCALE,
        ] {
            assert_eq!(MapUnits::new(good).map(|u| u.scale()), Ok(good));
        }
    }
}
