use glam::Vec2;

use crate::tiles::{Cell, Owner, SegmentFlags, SegmentRef, TileId, TileMap, WallSource};

/// Where a segment found by a query comes from.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum SegmentSource {
    /// An active segment of a tile.
    Tile {
        /// The active segment (its cell and index in the cell).
        segment: SegmentRef,
        /// The tile in that cell. (The segment's index in the tile's shape is
        /// [`TileMap::active_segment`](crate::TileMap::active_segment)`(segment).source`.)
        tile: TileId,
    },
    /// A temporary segment.
    Temporary {
        /// Who submitted it.
        owner: Owner,
        /// Its index in [`TileMap::temporaries`](crate::TileMap::temporaries).
        index: usize,
        /// How fast it moves.
        velocity: Vec2,
    },
}

impl SegmentSource {
    /// The same source as a trace names it (a tile's segment by its tile segment too), or
    /// `None` for an active segment `map` does not have.
    pub(crate) fn wall_source(self, map: &TileMap) -> Option<WallSource> {
        match self {
            SegmentSource::Tile { segment, .. } => WallSource::tile(map, segment),
            SegmentSource::Temporary { owner, index, .. } => {
                Some(WallSource::Temporary { owner, index })
            }
        }
    }
}

/// A ray's hit on a segment.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RayHit {
    /// Fraction along the ray, in `[0, 1]`.
    pub t: f32,
    /// The point hit, in world coordinates.
    pub point: Vec2,
    /// The outward unit normal of the segment hit.
    pub normal: Vec2,
    /// The flags of the segment hit.
    pub flags: SegmentFlags,
    /// What was hit.
    pub source: SegmentSource,
}

impl RayHit {
    /// The cell of the tile hit, or `None` for a temporary segment.
    #[must_use]
    pub fn cell(&self) -> Option<Cell> {
        match self.source {
            SegmentSource::Tile { segment, .. } => Some(segment.cell),
            SegmentSource::Temporary { .. } => None,
        }
    }

    /// The tile hit, or `None` for a temporary segment.
    #[must_use]
    pub fn tile(&self) -> Option<TileId> {
        match self.source {
            SegmentSource::Tile { tile, .. } => Some(tile),
            SegmentSource::Temporary { .. } => None,
        }
    }
}
