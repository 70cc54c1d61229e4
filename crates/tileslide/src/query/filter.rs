use glam::Vec2;

use crate::tiles::{Owner, SegmentFlags};

/// Which faces of a segment a ray or a cast can hit.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq, Default)]
#[non_exhaustive]
pub enum Faces {
    /// Only faces the ray meets head-on: `dot(normal, p1 − p0) < 0` (the default).
    #[default]
    Front,
    /// Both faces.
    Both,
    /// Replica Island's direction filter: a face counts only if `dot(normal, dir) < 0`, for a
    /// direction chosen by the caller (for example only the vertical part of a move).
    Against(Vec2),
}

/// What a query may hit.
///
/// ```
/// # use tileslide::{Faces, Owner, QueryFilter, SegmentFlags, Vec2};
/// let f = QueryFilter::default();
/// assert_eq!(f.faces, Faces::Front);
/// let floor_only = QueryFilter::against(Vec2::new(0.0, 1.0))
///     .with_mask(SegmentFlags::SOLID)
///     .excluding(Owner(7));
/// assert_eq!(floor_only.exclude_owner, Some(Owner(7)));
/// ```
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QueryFilter {
    /// Which faces count.
    pub faces: Faces,
    /// A segment counts only if it has at least one of these flags.
    pub mask: SegmentFlags,
    /// Temporary segments of this owner are ignored (a platform casting its own rays).
    pub exclude_owner: Option<Owner>,
}

impl Default for QueryFilter {
    fn default() -> Self {
        Self {
            faces: Faces::Front,
            mask: SegmentFlags::ALL,
            exclude_owner: None,
        }
    }
}

impl QueryFilter {
    /// Front faces only, every flag, no owner excluded (same as `default()`).
    #[must_use]
    pub fn front_faces() -> Self {
        Self::default()
    }

    /// Both faces count.
    #[must_use]
    pub fn both_sides() -> Self {
        Self {
            faces: Faces::Both,
            ..Self::default()
        }
    }

    /// Faces opposing `dir` count (Replica Island's direction filter).
    #[must_use]
    pub fn against(dir: Vec2) -> Self {
        Self {
            faces: Faces::Against(dir),
            ..Self::default()
        }
    }

    /// The same filter, counting only segments with one of `mask`'s flags.
    #[must_use]
    pub fn with_mask(self, mask: SegmentFlags) -> Self {
        Self { mask, ..self }
    }

    /// The same filter, ignoring `owner`'s temporary segments.
    #[must_use]
    pub fn excluding(self, owner: Owner) -> Self {
        Self {
            exclude_owner: Some(owner),
            ..self
        }
    }

    /// Whether a ray moving by `delta` may hit a segment with this `normal` and `flags`,
    /// owned by `owner` if it is a temporary segment (`None` for a tile's): the segment has
    /// one of the [`mask`](Self::mask)'s flags, is not a temporary segment of the
    /// [excluded owner](Self::exclude_owner), and its face counts under
    /// [`faces`](Self::faces).
    ///
    /// This is the rule every ray query applies; the walks apply it without branches, and
    /// their tests hold them to this definition.
    ///
    /// ```
    /// # use tileslide::{Owner, QueryFilter, SegmentFlags, Vec2};
    /// let right = Vec2::new(1.0, 0.0);
    /// let wall = Vec2::new(-1.0, 0.0); // a wall's face, seen from its left
    /// let f = QueryFilter::default();
    /// assert!(f.accepts(right, wall, SegmentFlags::SOLID, None));
    /// assert!(!f.accepts(-right, wall, SegmentFlags::SOLID, None)); // its back
    /// assert!(QueryFilter::both_sides().accepts(-right, wall, SegmentFlags::SOLID, None));
    /// let door = Some(Owner(7));
    /// assert!(!f.excluding(Owner(7)).accepts(right, wall, SegmentFlags::SOLID, door));
    /// assert!(!f.with_mask(SegmentFlags::ONE_WAY).accepts(right, wall, SegmentFlags::SOLID, None));
    /// ```
    #[must_use]
    #[inline]
    pub fn accepts(
        &self,
        delta: Vec2,
        normal: Vec2,
        flags: SegmentFlags,
        owner: Option<Owner>,
    ) -> bool {
        let face = match self.faces {
            Faces::Front => normal.dot(delta) < 0.0,
            Faces::Both => true,
            Faces::Against(dir) => normal.dot(dir) < 0.0,
        };
        let excluded = owner.is_some() && owner == self.exclude_owner;
        face && flags.intersects(self.mask) && !excluded
    }

    /// The direction a face must oppose, for a ray moving by `delta`, or `None` for
    /// [`Faces::Both`].
    #[inline(always)]
    pub(crate) fn face_direction(&self, delta: Vec2) -> Option<Vec2> {
        match self.faces {
            Faces::Front => Some(delta),
            Faces::Both => None,
            Faces::Against(dir) => Some(dir),
        }
    }
}
