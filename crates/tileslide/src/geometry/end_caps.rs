//! Which end points of a segment a sweep can catch.

/// Which end points of a segment a sweep can catch, at its end `a` and its end `b`
/// (the [`Segment`](crate::Segment)'s fields): a capped end rounds a swept circle's capsule
/// and catches a swept box's side. An end is left uncapped where the surface continues
/// into a collinear or concave neighbour, whose flat side covers it: a cap there would snag
/// a shape sliding over the seam. A lone segment has [`BOTH`](Self::BOTH).
///
/// ```
/// use tileslide::geometry::{EndCaps, sweep_circle_segment};
/// use tileslide::{Segment, Vec2};
/// // A floor from x = 0 to 4 facing up, continued by another floor past x = 4.
/// let floor = Segment::new(Vec2::new(0.0, 0.0), Vec2::new(4.0, 0.0));
/// let seam = EndCaps { a: true, b: false };
/// // A circle of radius 0.5 sliding right along it, dipping a little past its end: the
/// // end at the seam does not catch it; the same end capped does.
/// let (center, motion) = (Vec2::new(3.5, 0.6), Vec2::new(1.0, -0.2));
/// assert!(sweep_circle_segment(center, 0.5, motion, &floor, Vec2::Y, seam).is_none());
/// assert!(sweep_circle_segment(center, 0.5, motion, &floor, Vec2::Y, EndCaps::BOTH).is_some());
/// ```
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct EndCaps {
    /// The end `a` is capped.
    pub a: bool,
    /// The end `b` is capped.
    pub b: bool,
}

impl EndCaps {
    /// Both ends capped: a lone segment, or one whose neighbours meet it at convex corners.
    pub const BOTH: Self = Self { a: true, b: true };
    /// Neither end capped: a segment inside a straight run.
    pub const NONE: Self = Self { a: false, b: false };

    /// The caps of the same segment reversed (its `b` first): the two swapped.
    #[must_use]
    pub const fn reversed(self) -> Self {
        Self {
            a: self.b,
            b: self.a,
        }
    }

    /// As an array `[a, b]`, for code that walks both ends by index.
    #[must_use]
    pub(crate) const fn to_array(self) -> [bool; 2] {
        [self.a, self.b]
    }

    /// From an array `[a, b]`.
    #[must_use]
    pub(crate) const fn from_array([a, b]: [bool; 2]) -> Self {
        Self { a, b }
    }
}
