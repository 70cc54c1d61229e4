use thiserror::Error;
use tileslide::io::ascii;
use tileslide::{MapError, TileMap, TileSetError, Vec2};

use crate::SolidGrid;

/// Why a grid could not become a tile map.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum TileMapError {
    /// The built-in tile set was refused.
    #[error(transparent)]
    TileSet(TileSetError),
    /// The map was refused (an empty or oversized grid).
    #[error(transparent)]
    Map(MapError),
    /// A side longer than a map can be.
    #[error("a {width}×{height} grid is larger than a map can be")]
    TooLarge {
        /// Grid width.
        width: usize,
        /// Grid height.
        height: usize,
    },
}

impl SolidGrid {
    /// The grid as a tileslide map: each solid cell holds the ASCII tile set's solid square
    /// (`#`), cell size 1, origin (0, 0), row `y` of the grid is the map's row `y`.
    pub fn to_tile_map(&self) -> Result<TileMap, TileMapError> {
        let set = ascii::tile_set(1.0).map_err(TileMapError::TileSet)?;
        let tiles: Vec<_> = self
            .solid
            .iter()
            .map(|&s| s.then_some(ascii::SOLID))
            .collect();
        let (w, h) = (u32::try_from(self.width), u32::try_from(self.height));
        let (Ok(w), Ok(h)) = (w, h) else {
            return Err(TileMapError::TooLarge {
                width: self.width,
                height: self.height,
            });
        };
        TileMap::from_tiles(std::sync::Arc::new(set), w, h, Vec2::ZERO, &tiles)
            .map_err(TileMapError::Map)
    }
}
