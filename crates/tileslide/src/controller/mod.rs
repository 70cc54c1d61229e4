//! A platformer character controller: a box or circle moved against the tile world and its
//! temporary segments, with ground, ceiling and wall contacts, slopes, ground snapping and
//! one-way platforms.
//!
//! Replica Island keeps its characters out of the world with ray sweeps of the box's leading
//! edges, then snaps the box flush and casts short alignment rays; tileslide sweeps the
//! whole shape exactly instead (see `docs/controller.md` for how the two differ and why).

pub(crate) mod character;
mod contact;
mod debug_lines;
pub(crate) mod platform;
mod shape;
mod trace;
mod velocity;

pub use character::{Character, ControllerConfig, MoveOptions};
pub use contact::{Contact, Contacts, Surface};
pub use shape::CharacterShape;
pub use trace::{
    MoveEvent, MoveHit, MoveTrace, OneWayPass, SlideResponse, SweepPurpose, SweepTrace,
};

use glam::Vec2;

/// A character or its move was given a value it cannot use.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ControllerError {
    /// A position, direction or displacement was not finite (or `up` was zero).
    #[error("character {what} must be finite (and `up` non-zero), got {value}")]
    NonFinite {
        /// Which value: `"position"`, `"up"`, `"displacement"`, `"displacement length"`
        /// (finite components whose length overflows), `"velocity"` or `"velocity × dt"`
        /// (a finite velocity and time step whose product overflows).
        what: &'static str,
        /// The value given.
        value: Vec2,
    },
    /// A position, or the end point of a move, lies beyond [`MAX_COORD`](crate::limits::MAX_COORD).
    #[error(
        "character {what} {value} is beyond the coordinate range (±{})",
        crate::geometry::MAX_COORD
    )]
    OutOfRange {
        /// Which value: `"position"`, or `"displacement"` or `"velocity × dt"` (the move's
        /// end point is out of range).
        what: &'static str,
        /// The value given.
        value: Vec2,
    },
    /// A shape's size was not positive and finite, or was beyond
    /// [`MAX_COORD`](crate::limits::MAX_COORD).
    #[error(
        "character shape {what} must be positive and at most {}, got {value}",
        crate::geometry::MAX_COORD
    )]
    BadShape {
        /// `"radius"` or `"half extents"`.
        what: &'static str,
        /// The value given (a radius in both lanes).
        value: Vec2,
    },
    /// The time step of [`Character::move_and_slide`] was negative or not finite.
    #[error("time step dt must be finite and not negative, got {dt}")]
    BadTimeStep {
        /// The value given.
        dt: f32,
    },
    /// A [`ControllerConfig`] field was out of range.
    #[error(
        "controller config field `{field}` is out of range: {value} (max_slope_degrees in [0, 90), distances in [0, {}], max_slides at least 1)",
        crate::geometry::MAX_COORD
    )]
    BadConfig {
        /// The field's name.
        field: &'static str,
        /// The value given.
        value: f32,
    },
}
