use glam::Vec2;

use super::Aabb;

/// A closed line segment from `a` to `b`.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Segment {
    /// Start point.
    pub a: Vec2,
    /// End point.
    pub b: Vec2,
}

impl Segment {
    /// The segment from `a` to `b`.
    #[must_use]
    pub fn new(a: Vec2, b: Vec2) -> Self {
        Self { a, b }
    }

    /// `b − a`.
    #[must_use]
    pub fn delta(&self) -> Vec2 {
        self.b - self.a
    }

    /// Length of the segment.
    #[must_use]
    pub fn length(&self) -> f32 {
        self.delta().length()
    }

    /// True when both end points are finite.
    #[must_use]
    pub fn is_finite(&self) -> bool {
        self.a.is_finite() && self.b.is_finite()
    }

    /// The point at fraction `s` from `a` (0) to `b` (1).
    #[must_use]
    #[inline]
    pub fn point_at(&self, s: f32) -> Vec2 {
        self.a + self.delta() * s
    }

    /// The point of the segment nearest to `p`. A zero-length segment returns `a`.
    ///
    /// ```
    /// # use tileslide::{Segment, Vec2};
    /// let s = Segment::new(Vec2::ZERO, Vec2::new(2.0, 0.0));
    /// assert_eq!(s.closest_point(Vec2::new(1.0, 5.0)), Vec2::new(1.0, 0.0));
    /// assert_eq!(s.closest_point(Vec2::new(-3.0, 1.0)), Vec2::ZERO);
    /// ```
    #[must_use]
    #[inline]
    pub fn closest_point(&self, p: Vec2) -> Vec2 {
        let d = self.delta();
        let len2 = d.length_squared();
        if len2 == 0.0 {
            return self.a;
        }
        let s = ((p - self.a).dot(d) / len2).clamp(0.0, 1.0);
        self.point_at(s)
    }

    /// Squared distance from `p` to the segment.
    #[must_use]
    pub fn distance_squared_to(&self, p: Vec2) -> f32 {
        self.closest_point(p).distance_squared(p)
    }

    /// Squared distance between two segments: 0 when they cross or touch, else the least of
    /// the four end-point-to-segment distances (the closest pair of points of two
    /// non-crossing segments always includes an end point).
    ///
    /// ```
    /// # use tileslide::{Segment, Vec2};
    /// let floor = Segment::new(Vec2::ZERO, Vec2::new(4.0, 0.0));
    /// let above = Segment::new(Vec2::new(1.0, 2.0), Vec2::new(3.0, 1.0));
    /// assert_eq!(floor.distance_squared_to_segment(&above), 1.0);
    /// let across = Segment::new(Vec2::new(2.0, -1.0), Vec2::new(2.0, 1.0));
    /// assert_eq!(floor.distance_squared_to_segment(&across), 0.0);
    /// ```
    #[must_use]
    pub fn distance_squared_to_segment(&self, other: &Segment) -> f32 {
        if self.crosses(other) {
            return 0.0;
        }
        self.distance_squared_to(other.a)
            .min(self.distance_squared_to(other.b))
            .min(other.distance_squared_to(self.a))
            .min(other.distance_squared_to(self.b))
    }

    /// True when the segments properly cross (each one's ends strictly on opposite sides of
    /// the other's line). Touching and collinear overlaps are left to the end-point
    /// distances, which are 0 for them.
    fn crosses(&self, other: &Segment) -> bool {
        let side = |s: &Segment, p: Vec2| s.delta().perp_dot(p - s.a);
        let (d1, d2) = (side(self, other.a), side(self, other.b));
        let (d3, d4) = (side(other, self.a), side(other, self.b));
        d1 * d2 < 0.0 && d3 * d4 < 0.0
    }

    /// The smallest box that contains the segment.
    #[must_use]
    pub fn aabb(&self) -> Aabb {
        Aabb::from_corners(self.a, self.b)
    }

    /// The same segment, translated by `offset`.
    #[must_use]
    pub fn translated(&self, offset: Vec2) -> Segment {
        Segment::new(self.a + offset, self.b + offset)
    }
}
