use glam::Vec2;
use thiserror::Error;

use super::{MapError, SegmentFlags, TileMap};
use crate::geometry::{Segment, in_range, unit_normal};
use crate::owner::Owner;

/// A segment that is part of the world only until it is cleared: a moving platform's top, a
/// door. Queries treat it like a tile segment, except that it knows who owns it (so the
/// owner's own casts can skip it) and how fast it moves (so a rider can be carried).
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TemporarySegment {
    /// The segment, in world coordinates.
    pub segment: Segment,
    /// Outward unit normal (normalised when added).
    pub normal: Vec2,
    /// What the segment is.
    pub flags: SegmentFlags,
    /// Who submitted it.
    pub owner: Owner,
    /// How far it moves per second (or per step: the game's unit), for riders.
    pub velocity: Vec2,
}

/// Most temporary segments a map holds at once: every query looks at each of them, so a
/// game with more (a whole level of moving platforms) makes them tiles instead.
pub const MAX_TEMPORARIES: usize = 1 << 16;

/// Why a temporary segment was refused.
#[derive(Clone, Copy, Debug, PartialEq, Error)]
#[non_exhaustive]
pub enum TemporaryError {
    /// An end point, the normal or the velocity has a NaN or infinite component.
    #[error("temporary segment of owner {} has a non-finite {what} ({x}, {y})", owner.0)]
    NonFinite {
        /// Who submitted it.
        owner: Owner,
        /// Which value: `"end point a"`, `"end point b"`, `"normal"` or `"velocity"`.
        what: &'static str,
        /// The value's x.
        x: f32,
        /// The value's y.
        y: f32,
    },
    /// Start and end point are the same.
    #[error("temporary segment of owner {} has zero length", .0.0)]
    ZeroLength(Owner),
    /// The normal is the zero vector.
    #[error("temporary segment of owner {} has a zero normal", .0.0)]
    ZeroNormal(Owner),
    /// An end point lies beyond [`MAX_COORD`](crate::limits::MAX_COORD): every query computes with
    /// the segment, and promises its answers within that range only.
    #[error(
        "temporary segment of owner {} has end point ({x}, {y}), past the ±{max} coordinate \
         range (MAX_COORD)",
        owner.0,
        max = crate::geometry::MAX_COORD
    )]
    OutOfRange {
        /// Who submitted it.
        owner: Owner,
        /// The end point's x.
        x: f32,
        /// The end point's y.
        y: f32,
    },
    /// The map already holds [`MAX_TEMPORARIES`] temporary segments.
    #[error(
        "temporary segment of owner {} refused: the map already holds {MAX_TEMPORARIES}, the \
         most it holds (MAX_TEMPORARIES)",
        .0.0
    )]
    TooMany(Owner),
}

impl TemporarySegment {
    /// Checks the segment (finite, within [`MAX_COORD`](crate::limits::MAX_COORD), not a point, a
    /// non-zero normal) and normalises its normal.
    pub(crate) fn validated(mut self) -> Result<Self, TemporaryError> {
        let id = self.owner;
        for (what, v) in [
            ("end point a", self.segment.a),
            ("end point b", self.segment.b),
            ("normal", self.normal),
            ("velocity", self.velocity),
        ] {
            if !v.is_finite() {
                return Err(TemporaryError::NonFinite {
                    owner: id,
                    what,
                    x: v.x,
                    y: v.y,
                });
            }
        }
        if let Some(p) = [self.segment.a, self.segment.b]
            .into_iter()
            .find(|&p| !in_range(p))
        {
            return Err(TemporaryError::OutOfRange {
                owner: id,
                x: p.x,
                y: p.y,
            });
        }
        if self.segment.a == self.segment.b {
            return Err(TemporaryError::ZeroLength(id));
        }
        // (Finite here, so `None` means the zero vector.)
        self.normal = unit_normal(self.normal).ok_or(TemporaryError::ZeroNormal(id))?;
        Ok(self)
    }
}

impl TileMap {
    /// Adds a temporary segment (a moving platform, a door) that every query sees until
    /// [`clear_temporaries`](Self::clear_temporaries). Refused if non-finite or degenerate,
    /// or when the map already holds [`MAX_TEMPORARIES`].
    pub fn add_temporary(&mut self, segment: TemporarySegment) -> Result<(), MapError> {
        let segment = segment.validated()?;
        if self.temporaries.len() >= MAX_TEMPORARIES {
            return Err(TemporaryError::TooMany(segment.owner).into());
        }
        self.temporaries.push(segment);
        self.journal.record_temporaries();
        Ok(())
    }

    /// Removes every temporary segment (call once per frame before submitting new ones).
    pub fn clear_temporaries(&mut self) {
        if !self.temporaries.is_empty() {
            self.temporaries.clear();
            self.journal.record_temporaries();
        }
    }

    /// Removes the temporary segments of one owner.
    pub fn clear_temporaries_of(&mut self, owner: Owner) {
        let before = self.temporaries.len();
        self.temporaries.retain(|t| t.owner != owner);
        if self.temporaries.len() != before {
            self.journal.record_temporaries();
        }
    }

    /// The temporary segments, in the order they were added.
    #[must_use]
    pub fn temporaries(&self) -> &[TemporarySegment] {
        &self.temporaries
    }

    /// Puts `segments` (checked, normals kept bit for bit) in place of the temporary
    /// segments; a change only if some bit differs.
    pub(crate) fn restore_temporaries(&mut self, segments: &[TemporarySegment]) {
        let bits = |t: &TemporarySegment| {
            let v = [t.segment.a, t.segment.b, t.normal, t.velocity];
            (v.map(|v| v.to_array().map(f32::to_bits)), t.flags, t.owner)
        };
        let same = self.temporaries.len() == segments.len()
            && self
                .temporaries
                .iter()
                .zip(segments)
                .all(|(a, b)| bits(a) == bits(b));
        if !same {
            self.temporaries.clear();
            self.temporaries.extend_from_slice(segments);
            self.journal.record_temporaries();
        }
    }
}
