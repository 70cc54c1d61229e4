//! What a character touched: ground, ceiling, walls.

use glam::Vec2;

use crate::query::SegmentSource;
use crate::tiles::SegmentFlags;

/// One surface a character touched, and what it is.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Contact {
    /// The surface's unit normal at the contact, pointing towards the character (for a
    /// rounded corner, from the corner to the circle's centre).
    pub normal: Vec2,
    /// The segment's flags (`ONE_WAY` for a platform).
    pub flags: SegmentFlags,
    /// Where the segment comes from: a tile's active segment, or a temporary segment (a
    /// moving platform) with its owner and velocity.
    pub source: SegmentSource,
}

/// The surfaces a character touched during one move, by kind. Each holds the last contact
/// of its kind in the move, except `ground`, which is the ground under the character at
/// the end of the move (or `None` when it is in the air).
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Contacts {
    /// Walkable ground under the character after the move: a surface whose slope is within
    /// the configured maximum.
    pub ground: Option<Contact>,
    /// A surface above that stopped the character.
    pub ceiling: Option<Contact>,
    /// A wall on the character's left (lower x): its normal points to the right.
    pub left: Option<Contact>,
    /// A wall on the character's right (higher x): its normal points to the left.
    pub right: Option<Contact>,
    /// A moving platform that pushed into the character when the world left it no room (a
    /// platform pressing it into a ceiling or a wall): the character is crushed. It stays
    /// on the world's side, overlapping the platform.
    pub crush: Option<Contact>,
}

impl Contacts {
    /// True when the character stands on walkable ground.
    #[must_use]
    pub fn is_grounded(&self) -> bool {
        self.ground.is_some()
    }
}

/// Which kind of surface a contact makes for a character: what its normal says given the
/// character's up, its sideways axis (towards higher x) and its slope limit.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Surface {
    /// Walkable ground: the normal is within the slope limit of up.
    Ground,
    /// A ceiling: the normal is within the slope limit of down.
    Ceiling,
    /// A wall or steep slope on the character's left (lower x): its normal points right.
    Left,
    /// A wall or steep slope on the character's right: its normal points left.
    Right,
}

impl Surface {
    pub(crate) fn of(normal: Vec2, up: Vec2, side: Vec2, walkable: f32) -> Self {
        let rise = normal.dot(up);
        if rise >= walkable {
            Self::Ground
        } else if rise <= -walkable {
            Self::Ceiling
        } else if normal.dot(side) > 0.0 {
            Self::Left
        } else {
            Self::Right
        }
    }
}
