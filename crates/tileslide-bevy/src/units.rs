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
/// let units = MapUnits::new(16.0);
/// let world = Vec2::new(40.0, -24.0);
/// assert_eq!(units.to_map(world), tileslide::Vec2::new(2.5, 1.5));
/// assert_eq!(units.to_world(units.to_map(world)), world);
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

impl MapUnits {
    /// World units per map unit (for a Tiled map in pixels drawn at one world unit a pixel,
    /// 1; for an ASCII map of unit cells drawn 32 units a cell, 32). A scale that is not
    /// finite and positive is taken as 1.
    #[must_use]
    pub fn new(scale: f32) -> Self {
        let scale = if scale.is_finite() && scale > 0.0 {
            scale
        } else {
            1.0
        };
        Self { scale }
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
mod tests {
    use super::*;

    #[test]
    fn a_power_of_two_scale_converts_exactly_both_ways() {
        let units = MapUnits::new(32.0);
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
    fn a_scale_that_is_not_positive_and_finite_is_one() {
        for bad in [0.0, -2.0, f32::NAN, f32::INFINITY] {
            assert_eq!(MapUnits::new(bad).scale(), 1.0);
        }
    }
}
