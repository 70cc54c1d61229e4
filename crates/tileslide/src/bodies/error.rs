//! What [`Bodies`](crate::Bodies) calls, body shapes and resolve settings refuse.

use glam::Vec2;
use thiserror::Error;

use super::handle::BodyHandle;
use crate::geometry::MAX_COORD;

/// Errors from [`Bodies`](crate::Bodies) calls, body shapes and resolve settings.
#[derive(Clone, Debug, PartialEq, Error)]
#[non_exhaustive]
pub enum BodyError {
    /// The handle's body was removed.
    #[error("stale body handle (slot {}, generation {}): the body was removed", .0.index, .0.generation)]
    StaleHandle(BodyHandle),
    /// A shape without circles.
    #[error("a body shape needs at least one circle")]
    EmptyShape,
    /// A circle's radius is not positive, or beyond [`MAX_COORD`] (NaN and infinity
    /// included).
    #[error(
        "circle {index} of the body shape has radius {radius}: it must be positive and at most {max}",
        max = MAX_COORD
    )]
    InvalidRadius {
        /// The circle's index in the shape.
        index: usize,
        /// Its radius.
        radius: f32,
    },
    /// A circle's offset has a coordinate beyond [`MAX_COORD`] (NaN and infinity included).
    #[error(
        "circle {index} of the body shape has offset {offset}: each coordinate must be at most {max} in magnitude",
        max = MAX_COORD
    )]
    InvalidOffset {
        /// The circle's index in the shape.
        index: usize,
        /// Its offset.
        offset: Vec2,
    },
    /// A position or move with a NaN or infinite coordinate.
    #[error("the {what} {value} is not finite")]
    NonFinite {
        /// `"position"` or `"move"`.
        what: &'static str,
        /// The value given.
        value: Vec2,
    },
    /// A position, or the end point of a move (where the body would be after it), with a
    /// finite coordinate beyond [`MAX_COORD`].
    #[error("the {what} {value} is out of range: each coordinate must be at most {max} in magnitude", max = MAX_COORD)]
    OutOfRange {
        /// `"position"` or `"move's end point"`.
        what: &'static str,
        /// The value given (for a move, where it ends).
        value: Vec2,
    },
    /// A [`ResolveConfig`](crate::ResolveConfig) field out of its range (see the field's
    /// documentation).
    #[error("resolve setting {field} = {value} is out of range")]
    BadConfig {
        /// The field's name.
        field: &'static str,
        /// The value given.
        value: f32,
    },
    /// A compound shape with more than [`MAX_COMPOUND_CIRCLES`](crate::limits::MAX_COMPOUND_CIRCLES)
    /// circles.
    #[error("a body shape has more than {max} circles")]
    TooManyCircles {
        /// The limit.
        max: usize,
    },
    /// All `u32::MAX` slots are in use.
    #[error("too many bodies (at most {max})")]
    TooMany {
        /// The limit.
        max: u32,
    },
}
