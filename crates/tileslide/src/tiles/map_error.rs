//! Why a map could not be built or edited.

use thiserror::Error;

use super::map::MAX_CELLS;
use super::{Cell, TemporaryError, TileId};

/// Why a map could not be built or edited.
#[derive(Clone, Debug, PartialEq, Error)]
#[non_exhaustive]
pub enum MapError {
    /// Width and height must both be at least 1.
    #[error("map size {width}×{height} is empty")]
    EmptySize {
        /// Width given.
        width: u32,
        /// Height given.
        height: u32,
    },
    /// More cells than [`MAX_CELLS`], or more segments than the map can index.
    #[error("map size {width}×{height} is too large (at most {MAX_CELLS} cells)")]
    TooLarge {
        /// Width given.
        width: u32,
        /// Height given.
        height: u32,
    },
    /// The origin has a NaN or infinite coordinate.
    #[error("map origin ({x}, {y}) is not finite")]
    NonFiniteOrigin {
        /// x given.
        x: f32,
        /// y given.
        y: f32,
    },
    /// The map would reach past [`MAX_COORD`](crate::limits::MAX_COORD) from the origin: its
    /// corners are where every query and body would compute.
    #[error(
        "map of {width}×{height} cells at ({x}, {y}) reaches ({far_x}, {far_y}), past the \
         ±{max} coordinate range (MAX_COORD)",
        max = crate::geometry::MAX_COORD
    )]
    OutOfRange {
        /// Width given.
        width: u32,
        /// Height given.
        height: u32,
        /// Origin x.
        x: f32,
        /// Origin y.
        y: f32,
        /// The far corner's x (origin + width × tile width).
        far_x: f32,
        /// The far corner's y.
        far_y: f32,
    },
    /// A cell outside the map.
    #[error("cell {cell} is outside the {width}×{height} map")]
    CellOutOfBounds {
        /// The cell asked for.
        cell: Cell,
        /// Map width.
        width: u32,
        /// Map height.
        height: u32,
    },
    /// A tile id the tile set does not have.
    #[error("tile {id} is not in the tile set")]
    UnknownTile {
        /// The id asked for.
        id: TileId,
    },
    /// The list of tiles does not have one entry per cell.
    #[error("expected {expected} tiles (one per cell), got {got}")]
    WrongTileCount {
        /// width × height.
        expected: usize,
        /// Length of the list given.
        got: usize,
    },
    /// The map would hold more active segments than it can index (about 2³²).
    #[error("the map would hold more active segments than it can index")]
    TooManySegments,
    /// A temporary segment was refused.
    #[error(transparent)]
    Temporary(#[from] TemporaryError),
}
