//! What navigation calls refuse, and the check every point goes through.

use glam::Vec2;
use thiserror::Error;

use super::MAX_NAV_NODES;
#[cfg(doc)]
use super::{FlowField, NavGrid};

/// What a navigation call refuses.
#[derive(Clone, Debug, PartialEq, Error)]
#[non_exhaustive]
pub enum NavError {
    /// `max_radius` is not positive and finite, or too large for the cell size.
    #[error("max_radius {max_radius} must be positive, finite and at most {limit} (31 cells)")]
    BadMaxRadius {
        /// The value given.
        max_radius: f32,
        /// The largest allowed for this map.
        limit: f32,
    },
    /// The map has more lattice nodes than [`MAX_NAV_NODES`].
    #[error("a {width} × {height} map has {nodes} navigation nodes, more than {MAX_NAV_NODES}")]
    TooLarge {
        /// Map width in cells.
        width: u32,
        /// Map height in cells.
        height: u32,
        /// Its lattice nodes.
        nodes: u64,
    },
    /// The map reaches so far from (0, 0) that `f32` coordinates there are farther apart
    /// than the grid's margin (1/1000 of a cell), so clearances cannot keep it.
    #[error(
        "the map reaches {corner}, where coordinates are {spacing} apart, more than the navigation grid's margin {margin} (1/1000 of a cell): move its origin nearer (0, 0)"
    )]
    TooFar {
        /// The map's corner farthest from (0, 0).
        corner: Vec2,
        /// The spacing of `f32` values there (map units).
        spacing: f32,
        /// The grid's margin (map units).
        margin: f32,
    },
    /// A radius that is not positive and finite, or above the grid's `max_radius`.
    #[error(
        "radius {radius} must be positive, finite and at most the grid's max_radius {max_radius}"
    )]
    BadRadius {
        /// The radius asked for.
        radius: f32,
        /// The grid's `max_radius`.
        max_radius: f32,
    },
    /// A point with a NaN or infinite coordinate.
    #[error("the {what} point {point} is not finite")]
    NonFinite {
        /// Which point (`from`, `to`, `goal`, …).
        what: &'static str,
        /// Its value.
        point: Vec2,
    },
    /// A point with a coordinate beyond [`MAX_COORD`](crate::limits::MAX_COORD) in magnitude.
    #[error("the {what} point {point} is beyond the ±{max} coordinate range (MAX_COORD)", max = crate::geometry::MAX_COORD)]
    OutOfRange {
        /// Which point (`from`, `to`, `goal`, …).
        what: &'static str,
        /// Its value.
        point: Vec2,
    },
    /// The map's tiles changed since the grid (or the flow field) last caught up with
    /// them: call [`NavGrid::sync`] (then [`FlowField::sync`]) after editing the map.
    #[error(
        "the navigation data is behind the map: its tiles changed since the last sync (call NavGrid::sync, then FlowField::sync, after editing the map)"
    )]
    Stale,
    /// The map is not the one the grid (or the flow field) was built for: another map, or
    /// a clone of it edited apart from the map the grid has caught up with (see
    /// [`MapRevision`](crate::MapRevision)).
    #[error(
        "the navigation data was built for another map (or for a clone of this one edited apart from it)"
    )]
    OtherMap,
}

/// Refuses a point that is not finite or lies beyond [`MAX_COORD`](crate::limits::MAX_COORD):
/// lattice coordinates of such a point overflow the integers nodes are counted in.
pub(crate) fn check_point(what: &'static str, point: Vec2) -> Result<(), NavError> {
    if !point.is_finite() {
        Err(NavError::NonFinite { what, point })
    } else if !crate::geometry::in_range(point) {
        Err(NavError::OutOfRange { what, point })
    } else {
        Ok(())
    }
}
