use glam::Vec2;

use super::{Aabb, Segment};

/// A circle (a disc: the inside counts as part of it).
///
/// A plain geometric value, like [`Aabb`], [`Segment`] and [`Ray`](super::Ray): [`new`]
/// checks nothing and the pair functions answer any values, so hot code builds them freely.
/// A radius is checked where it enters a system or a query: a body's
/// [`BodyShape::circle`](crate::BodyShape::circle), a character's
/// [`CharacterShape::circle`](crate::CharacterShape::circle), a hit
/// [`Volume::circle`](crate::Volume::circle) and
/// [`TileMap::cast_circle`](crate::TileMap::cast_circle) refuse one that describes no
/// circle.
///
/// [`new`]: Self::new
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Circle {
    /// Centre.
    pub center: Vec2,
    /// Radius, `>= 0`.
    pub radius: f32,
}

impl Circle {
    /// A circle at `center` with `radius`.
    #[must_use]
    pub fn new(center: Vec2, radius: f32) -> Self {
        Self { center, radius }
    }

    /// The smallest box that contains the circle.
    #[must_use]
    pub fn aabb(&self) -> Aabb {
        Aabb::from_center(self.center, Vec2::splat(self.radius))
    }

    /// True when the disc and the closed segment share a point (touching counts).
    ///
    /// ```
    /// # use tileslide::{Circle, Segment, Vec2};
    /// let c = Circle::new(Vec2::ZERO, 1.0);
    /// assert!(c.overlaps_segment(&Segment::new(Vec2::new(-2.0, 1.0), Vec2::new(2.0, 1.0))));
    /// assert!(!c.overlaps_segment(&Segment::new(Vec2::new(-2.0, 1.5), Vec2::new(2.0, 1.5))));
    /// ```
    #[must_use]
    pub fn overlaps_segment(&self, segment: &Segment) -> bool {
        segment.distance_squared_to(self.center) <= self.radius * self.radius
    }

    /// True when the two discs share a point (touching counts).
    ///
    /// ```
    /// # use tileslide::{Circle, Vec2};
    /// let c = Circle::new(Vec2::ZERO, 1.0);
    /// assert!(c.overlaps(&Circle::new(Vec2::new(1.5, 0.0), 0.5)));
    /// assert!(!c.overlaps(&Circle::new(Vec2::new(1.5, 1.5), 0.5)));
    /// ```
    #[must_use]
    pub fn overlaps(&self, other: &Circle) -> bool {
        let reach = self.radius + other.radius;
        self.center.distance_squared(other.center) <= reach * reach
    }

    /// True when the disc and the closed box share a point (touching counts).
    #[must_use]
    pub fn overlaps_aabb(&self, aabb: &Aabb) -> bool {
        let nearest = self.center.clamp(aabb.min, aabb.max);
        nearest.distance_squared(self.center) <= self.radius * self.radius
    }
}
