use glam::Vec2;

use super::Segment;

/// An axis-aligned box `[min, max]`, closed on every side.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    /// The corner with the smallest coordinates.
    pub min: Vec2,
    /// The corner with the largest coordinates.
    pub max: Vec2,
}

impl Aabb {
    /// A box from two corners, in any order. A corner with a NaN coordinate gives a box that
    /// is not [valid](Self::is_valid), which every query treats as overlapping nothing.
    ///
    /// ```
    /// # use tileslide::{Aabb, Vec2};
    /// let b = Aabb::from_corners(Vec2::new(2.0, 0.0), Vec2::new(0.0, 1.0));
    /// assert_eq!(b.min, Vec2::new(0.0, 0.0));
    /// assert_eq!(b.max, Vec2::new(2.0, 1.0));
    /// assert!(!Aabb::from_corners(Vec2::new(f32::NAN, 0.0), Vec2::ONE).is_valid());
    /// ```
    #[must_use]
    pub fn from_corners(a: Vec2, b: Vec2) -> Self {
        // glam's `min`/`max`, like `f32::min`, return the other operand when one is NaN: a
        // NaN corner would silently become a valid box at the other corner. Keep the NaN so
        // that `is_valid` is false and the queries see nothing.
        if a.is_nan() || b.is_nan() {
            return Self {
                min: Vec2::NAN,
                max: Vec2::NAN,
            };
        }
        Self {
            min: a.min(b),
            max: a.max(b),
        }
    }

    /// The box centred on `center` with half extents `half`.
    #[must_use]
    pub fn from_center(center: Vec2, half: Vec2) -> Self {
        let (min, max) = (center - half, center + half);
        // The common case in one comparison (false with a NaN); the resolver builds a box
        // per circle per step.
        if min.cmple(max).all() {
            Self { min, max }
        } else {
            Self::from_corners(min, max)
        }
    }

    /// The box grown by `margin` on every side.
    ///
    /// ```
    /// # use tileslide::{Aabb, Vec2};
    /// let b = Aabb::from_corners(Vec2::ZERO, Vec2::ONE).expand(0.5);
    /// assert_eq!((b.min, b.max), (Vec2::splat(-0.5), Vec2::splat(1.5)));
    /// ```
    #[must_use]
    pub fn expand(&self, margin: f32) -> Self {
        Self {
            min: self.min - Vec2::splat(margin),
            max: self.max + Vec2::splat(margin),
        }
    }

    /// The smallest box that contains both.
    ///
    /// ```
    /// # use tileslide::{Aabb, Vec2};
    /// let a = Aabb::from_corners(Vec2::ZERO, Vec2::ONE);
    /// let b = Aabb::from_corners(Vec2::new(2.0, -1.0), Vec2::new(3.0, 0.5));
    /// let u = a.union(&b);
    /// assert_eq!((u.min, u.max), (Vec2::new(0.0, -1.0), Vec2::new(3.0, 1.0)));
    /// ```
    #[must_use]
    pub fn union(&self, other: &Aabb) -> Self {
        Self {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    /// Width and height.
    #[must_use]
    pub fn size(&self) -> Vec2 {
        self.max - self.min
    }

    /// True when all four coordinates are finite and `min <= max`.
    #[must_use]
    pub fn is_valid(&self) -> bool {
        self.min.is_finite() && self.max.is_finite() && self.min.cmple(self.max).all()
    }

    /// True when `p` lies in the box or on its boundary.
    #[must_use]
    pub fn contains_point(&self, p: Vec2) -> bool {
        p.cmpge(self.min).all() && p.cmple(self.max).all()
    }

    /// True when `other` lies in the box, boundary included (false with a NaN).
    ///
    /// ```
    /// # use tileslide::{Aabb, Vec2};
    /// let outer = Aabb::from_corners(Vec2::ZERO, Vec2::splat(2.0));
    /// assert!(outer.contains(&Aabb::from_corners(Vec2::splat(0.5), Vec2::splat(2.0))));
    /// assert!(!outer.contains(&Aabb::from_corners(Vec2::splat(0.5), Vec2::splat(2.5))));
    /// ```
    #[must_use]
    pub fn contains(&self, other: &Aabb) -> bool {
        other.min.cmpge(self.min).all() && other.max.cmple(self.max).all()
    }

    /// True when the two closed boxes share at least one point (touching counts).
    #[must_use]
    pub fn overlaps(&self, other: &Aabb) -> bool {
        self.min.cmple(other.max).all() && other.min.cmple(self.max).all()
    }

    /// True when the closed segment shares at least one point with the closed box.
    ///
    /// Separating-axis test on the box's two axes and the segment's normal (Ericson,
    /// *Real-Time Collision Detection*, 5.2.1 adapted to 2D).
    #[must_use]
    pub fn overlaps_segment(&self, segment: &Segment) -> bool {
        let seg_box = Aabb::from_corners(segment.a, segment.b);
        if !self.overlaps(&seg_box) {
            return false;
        }
        // Axis perpendicular to the segment: the box's projection must straddle the line.
        let d = segment.b - segment.a;
        let n = d.perp();
        let center = (self.min + self.max) * 0.5;
        let half = (self.max - self.min) * 0.5;
        let dist = n.dot(center - segment.a);
        let radius = half.x * n.x.abs() + half.y * n.y.abs();
        dist.abs() <= radius
    }
}
