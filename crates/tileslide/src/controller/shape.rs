//! The shape a character collides with: a circle or an axis-aligned box.

use glam::Vec2;

use super::ControllerError;
use crate::geometry::{Aabb, EndCaps, SweepHit, in_range, sweep_box_segment};
use crate::query::Capsule;

/// A character's collision shape, centred on its position.
///
/// ```
/// use tileslide::{CharacterShape, Vec2};
/// let hero = CharacterShape::rect(Vec2::new(0.4, 0.9))?; // 0.8 wide, 1.8 tall
/// let ball = CharacterShape::circle(0.45)?;
/// assert!(CharacterShape::circle(f32::NAN).is_err());
/// # Ok::<(), tileslide::ControllerError>(())
/// ```
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum CharacterShape {
    /// A circle of this radius: rolls over corners, and stands on a slope at one point.
    Circle {
        /// Radius, positive and finite.
        radius: f32,
    },
    /// An axis-aligned box with these half extents: stands flat at a ledge's edge, the
    /// usual platformer hero.
    Rect {
        /// Half the width and half the height, positive and finite.
        half: Vec2,
    },
}

impl CharacterShape {
    /// A circle of `radius`; an error unless it is positive and at most
    /// [`MAX_COORD`](crate::limits::MAX_COORD).
    pub fn circle(radius: f32) -> Result<Self, ControllerError> {
        Self::Circle { radius }.validated()
    }

    /// A box with half extents `half`; an error unless both are positive and at most
    /// [`MAX_COORD`](crate::limits::MAX_COORD).
    pub fn rect(half: Vec2) -> Result<Self, ControllerError> {
        Self::Rect { half }.validated()
    }

    /// The shape, or an error naming its size when that is not positive or is beyond
    /// `MAX_COORD` (the variants' fields are public, so `Character::new` checks again).
    pub(crate) fn validated(self) -> Result<Self, ControllerError> {
        let (what, value) = match self {
            Self::Circle { radius } => ("radius", Vec2::splat(radius)),
            Self::Rect { half } => ("half extents", half),
        };
        if value.cmpgt(Vec2::ZERO).all() && in_range(value) {
            Ok(self)
        } else {
            Err(ControllerError::BadShape { what, value })
        }
    }

    /// The shape's bounding box around `center`.
    #[must_use]
    pub fn bounds(&self, center: Vec2) -> Aabb {
        match *self {
            Self::Circle { radius } => Aabb::from_center(center, Vec2::splat(radius)),
            Self::Rect { half } => Aabb::from_center(center, half),
        }
    }

    /// How far the shape reaches from its centre in direction `-normal` (unit): the
    /// distance from the centre to a line with that normal that the shape touches.
    #[must_use]
    pub(crate) fn support(&self, normal: Vec2) -> f32 {
        match *self {
            Self::Circle { radius } => radius,
            Self::Rect { half } => half.x * normal.x.abs() + half.y * normal.y.abs(),
        }
    }

    /// How to push the shape at `center` out of `capsule`'s segment when its centre is in
    /// front of the segment's line, it reaches past that line and it touches the segment:
    /// the unit direction and the distance. Along the capsule's normal by how far the shape
    /// reaches past the line, unless it reaches less far past one of the segment's ends
    /// (a box whose side overlaps the end of a platform, or only touches it): then along
    /// the segment, off that end, by that much. `None` when it does not overlap the
    /// segment from the front.
    pub(crate) fn penetration(&self, capsule: &Capsule, center: Vec2) -> Option<(Vec2, f32)> {
        let (segment, normal) = (&capsule.segment, capsule.normal);
        let height = (center - segment.a).dot(normal);
        let support = self.support(normal);
        let length = segment.length();
        if !(height >= 0.0 && height < support && length > 0.0) {
            return None;
        }
        let along = segment.delta() / length;
        let s = (center - segment.a).dot(along);
        let touches = match *self {
            // The centre over the segment's extent (the flat side; the rounded ends are
            // left to the sweeps).
            Self::Circle { .. } => (0.0..=length).contains(&s),
            Self::Rect { half } => Aabb::from_center(center, half).overlaps_segment(segment),
        };
        if !touches {
            return None;
        }
        let depth = support - height;
        // How far past each end the shape reaches along the segment: moved back by that
        // much it is off the segment. (A circle over the segment's extent reaches past
        // neither end less far than its radius, so it is pushed along the normal.)
        let reach = self.support(along);
        let (past_a, past_b) = (s + reach, length - s + reach);
        let side = past_a.min(past_b);
        Some(if side < depth {
            (if past_a <= past_b { -along } else { along }, side)
        } else {
            (normal, depth)
        })
    }

    /// The time of impact of the shape at `center` moving by `motion` against `capsule`'s
    /// front face (see `sweep_circle_segment` and `sweep_box_segment`).
    pub(crate) fn sweep(&self, capsule: &Capsule, center: Vec2, motion: Vec2) -> Option<SweepHit> {
        match *self {
            Self::Circle { radius } => capsule.sweep(center, radius, motion),
            Self::Rect { half } => sweep_box_segment(
                center,
                half,
                motion,
                &capsule.segment,
                capsule.normal,
                EndCaps::from_array(capsule.caps),
            ),
        }
    }
}
