//! Tile sets, tile maps, seam culling and end-point continuity.
//!
//! A [`TileSet`] maps a [`TileId`] to a [`TileShape`]: segments with outward normals and
//! [`SegmentFlags`] in tile-local coordinates. A [`TileMap`] places tiles on a grid and keeps,
//! per cell, the *active* segments left after seam culling, each knowing which segment its
//! ends continue into; [`TileMap::explain_cell`] says why.

mod base;
mod cell;
mod continuity;
mod culling;
mod debug_lines;
mod explain;
pub(crate) mod face_kind;
mod flags;
mod journal;
pub(crate) mod link;
pub(crate) mod map;
mod map_error;
mod segment_ref;
pub(crate) mod shape;
pub(crate) mod store;
mod temporary;
mod tile_set;
mod trace;

pub use crate::owner::Owner;
pub use cell::{Cell, TileId};
pub use continuity::EndJoin;
pub use culling::CellSide;
pub use explain::{
    ActivePiece, CellExplanation, HiddenPart, PieceEnd, PlacedSegment, SegmentExplanation,
    WallSource,
};
pub use flags::SegmentFlags;
pub use journal::{JOURNAL_EDITS, JournalError, MapRevision};
pub use map::{ActiveSegment, MAX_CELLS, TileMap};
pub use map_error::MapError;
pub use segment_ref::SegmentRef;
pub use shape::{MAX_SHAPE_SEGMENTS, ShapeError, TileSegment, TileShape};
pub use temporary::{MAX_TEMPORARIES, TemporaryError, TemporarySegment};
pub use tile_set::{TileSet, TileSetError};
