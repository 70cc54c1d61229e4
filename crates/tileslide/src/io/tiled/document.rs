//! A Tiled map as both readers (`.tmx` through the `tiled` crate, `.tmj` through serde) hand
//! it to the builder: only what collision and object layers need, the same for both formats.

use std::collections::BTreeMap;
use std::path::PathBuf;

use glam::Vec2;

use super::objects::{MapObject, ObjectLayer};
use super::properties::Properties;
use crate::io::Location;

/// An orthogonal Tiled map, checked for size and orientation.
#[derive(Debug)]
pub(super) struct Document {
    /// The map's grid cell size in pixels (both positive).
    pub tile_size: (u32, u32),
    /// The tile sets, by increasing first gid as the file lists them.
    pub tile_sets: Vec<TileSetDoc>,
    /// The tile layers, in file order (group members included, depth first).
    pub tile_layers: Vec<TileLayerDoc>,
    /// The object layers, in file order.
    pub object_layers: Vec<ObjectLayer>,
    /// The map's custom properties.
    pub properties: Properties,
}

/// A tile set and the first gid the map gave it.
#[derive(Debug)]
pub(super) struct TileSetDoc {
    /// The gid of its tile 0.
    pub first_gid: u32,
    /// Its name.
    pub name: String,
    /// The file that defines it (the map for an embedded set): errors name it.
    pub file: PathBuf,
    /// Width and height of its tiles in pixels.
    pub tile_size: (u32, u32),
    /// Its number of tiles.
    pub tile_count: u32,
    /// The tiles that have a class, properties or collision objects, by local id.
    pub tiles: BTreeMap<u32, TileDoc>,
}

/// What a tile set says about one tile.
#[derive(Debug, Default)]
pub(super) struct TileDoc {
    /// The tile's class; empty if none.
    pub class: String,
    /// The tile's custom properties.
    pub properties: Properties,
    /// The objects of its collision editor, in tile pixels.
    pub collision: Vec<MapObject>,
}

/// A tile layer with its raw gids (flip bits included).
#[derive(Debug)]
pub(super) struct TileLayerDoc {
    /// The layer's name.
    pub name: String,
    /// The layer's custom properties.
    pub properties: Properties,
    /// The sum of the layer's and its groups' offsets, in pixels.
    pub offset: Vec2,
    /// Its cells.
    pub cells: LayerCells,
    /// Where the layer is in the map file (line:column for `.tmx`).
    pub location: Location,
    /// How errors name the layer (`layer "ground"`, `layers[2] ("ground")`).
    pub label: String,
}

/// The cells of a tile layer.
#[derive(Debug)]
pub(super) enum LayerCells {
    /// A finite layer: `width × height` gids, row by row (already checked).
    Finite {
        /// Columns.
        width: u32,
        /// Rows.
        height: u32,
        /// One gid per cell.
        gids: Vec<u32>,
    },
    /// An infinite layer's chunks.
    Chunks(Vec<Chunk>),
}

/// A rectangle of cells of an infinite layer.
#[derive(Debug)]
pub(super) struct Chunk {
    /// Column of its top-left cell (may be negative).
    pub x: i32,
    /// Row of its top-left cell (may be negative).
    pub y: i32,
    /// Columns.
    pub width: u32,
    /// Rows.
    pub height: u32,
    /// One gid per cell, row by row (already checked).
    pub gids: Vec<u32>,
}
