use std::fmt;

use tileslide::io::ascii;
use tileslide::{MapError, TileMap, TileSetError, Vec2};

use crate::SolidGrid;

/// Why a grid could not become a tile map.
#[derive(Clone, Debug, PartialEq)]
pub enum TileMapError {
    /// The built-in tile set was refused.
    TileSet(TileSetError),
    /// The map was refused (an empty or oversized grid).
    Map(MapError),
}

impl fmt::Display for TileMapError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TileMapError::TileSet(e) => write!(f, "{e}"),
            TileMapError::Map(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for TileMapError {}

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
            return Err(TileMapError::Map(MapError::TooLarge {
                width: u32::MAX,
                height: u32::MAX,
            }));
        };
        TileMap::from_tiles(std::sync::Arc::new(set), w, h, Vec2::ZERO, &tiles)
            .map_err(TileMapError::Map)
    }
}
