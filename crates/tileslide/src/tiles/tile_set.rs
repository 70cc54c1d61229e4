use std::collections::BTreeMap;

use glam::Vec2;
use thiserror::Error;

use super::{ShapeError, TileId, TileShape};

/// Why a tile set refused a tile or a size.
#[derive(Clone, Debug, PartialEq, Error)]
#[non_exhaustive]
pub enum TileSetError {
    /// The tile size must be positive and finite on both axes.
    #[error("tile size {w}×{h} is not positive and finite")]
    InvalidTileSize {
        /// Width given.
        w: f32,
        /// Height given.
        h: f32,
    },
    /// Tile id `u32::MAX` is reserved (the map uses it for empty cells).
    #[error("tile id {} is reserved", u32::MAX)]
    ReservedId,
    /// The shape of tile `id` is invalid.
    #[error("tile {id}: {source}")]
    InvalidTile {
        /// The tile's id.
        id: TileId,
        /// What is wrong with its shape.
        source: ShapeError,
    },
}

/// Maps tile ids to tile shapes, all of one tile size.
///
/// ```
/// # use tileslide::{TileId, TileSet, TileShape, Vec2};
/// let mut set = TileSet::new(Vec2::splat(1.0))?;
/// let square = [Vec2::ZERO, Vec2::X, Vec2::ONE, Vec2::Y];
/// set.insert(TileId(1), TileShape::polygon(&square).unwrap())?;
/// assert_eq!(set.shape(TileId(1)).unwrap().segments().len(), 4);
/// assert!(set.shape(TileId(2)).is_none());
/// # Ok::<(), tileslide::TileSetError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct TileSet {
    tile_size: Vec2,
    shapes: BTreeMap<TileId, TileShape>,
}

impl TileSet {
    /// An empty tile set whose tiles are `tile_size` wide and high.
    pub fn new(tile_size: Vec2) -> Result<Self, TileSetError> {
        if !(tile_size.is_finite() && tile_size.cmpgt(Vec2::ZERO).all()) {
            return Err(TileSetError::InvalidTileSize {
                w: tile_size.x,
                h: tile_size.y,
            });
        }
        Ok(Self {
            tile_size,
            shapes: BTreeMap::new(),
        })
    }

    /// Width and height of every tile.
    #[must_use]
    pub fn tile_size(&self) -> Vec2 {
        self.tile_size
    }

    /// Adds (or replaces) tile `id`. Refused if a segment leaves the tile's rectangle, or for
    /// the reserved id `u32::MAX`.
    pub fn insert(&mut self, id: TileId, shape: TileShape) -> Result<(), TileSetError> {
        if id.0 == u32::MAX {
            return Err(TileSetError::ReservedId);
        }
        shape
            .check_inside_tile(self.tile_size)
            .map_err(|source| TileSetError::InvalidTile { id, source })?;
        self.shapes.insert(id, shape);
        Ok(())
    }

    /// The shape of tile `id`, if the set has it.
    #[must_use]
    pub fn shape(&self, id: TileId) -> Option<&TileShape> {
        self.shapes.get(&id)
    }

    /// Every tile, by increasing id.
    pub fn iter(&self) -> impl Iterator<Item = (TileId, &TileShape)> {
        self.shapes.iter().map(|(id, s)| (*id, s))
    }

    /// Number of tiles.
    #[must_use]
    pub fn len(&self) -> usize {
        self.shapes.len()
    }

    /// True when the set has no tile.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.shapes.is_empty()
    }
}
