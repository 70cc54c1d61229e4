//! Tiled maps: `.tmx` (XML) and `.tmj` (JSON) from the [Tiled](https://www.mapeditor.org)
//! editor, with embedded or external tile sets (`.tsx`, `.tsj`), as a [`TileMap`] plus the
//! map's object layers. Needs the `tiled` cargo feature (on by default).
//!
//! - **Coordinates** are the map's pixels, y down, as Tiled shows them: the map's cells are
//!   the map's `tilewidth × tileheight`, cell (0, 0) of a finite map is at the origin (plus
//!   the layer's offset), and an infinite map covers the bounding box of its chunks, its
//!   origin at the top-left chunk's corner (so negative chunks keep their pixels).
//! - **The collision layer** is one tile layer: the one [`TiledOptions::layer`] names, else
//!   the first with the bool property `collision = true`, else the first tile layer.
//! - **Tile shapes** come from each tile's collision objects (Tiled's collision editor):
//!   rectangles, polygons, ellipses ([`ELLIPSE_SEGMENTS`] segments) and capsules are solid
//!   outlines; polylines are two-sided thin walls, or one-way with `one_way = true`. A tile
//!   without collision objects blocks nothing, whatever its size; a tile of another size
//!   than the grid is placed from its cell's bottom-left corner, as Tiled draws it, and its
//!   collision must lie in that cell. A vertex up to one pixel (or 1/64 of a cell over 64
//!   pixels) outside the cell is moved onto its edge; further out is an error naming the
//!   layer, cell and tile. Properties: `one_way`, `one_way_side`
//!   (`up`, `down`, `left`, `right`), `flag0`…`flag23` (user bits), `hit_types`.
//! - **Tile ids**: a cell's [`TileId`] is its gid with its flip bits (the hexagonal bit,
//!   which Tiled ignores on orthogonal maps, cleared), so each (tile, flips) pair placed is
//!   its own tile shape, flipped as Tiled draws it ([`Flip`]).
//!   [`TiledMap::tile_info`] tells which tile of which tile set an id is.
//! - **Errors** name the file and the line:column (XML, and JSON syntax) or the field
//!   (`layers[2].data`); sizes are checked against [`MAX_CELLS`](crate::limits::MAX_CELLS) before
//!   anything is allocated; nothing panics.
//!
//! The `tiled` crate reads `.tmx` maps, `.tsx` tile sets and `.tx` templates; serde reads
//! `.tmj` and `.tsj`. See `docs/tiled.md` for the conventions, with pictures.
//!
//! ```
//! use tileslide::io::tiled::{self, TiledOptions};
//! use tileslide::{Ray, QueryFilter, Vec2};
//!
//! let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/maps/cave.tmx");
//! let cave = tiled::load(path, &TiledOptions::default())?;
//! assert_eq!(cave.collision_layer, "walls");
//! // Straight down from the top of the cave: the floor's top is at y = 224 pixels.
//! let down = Ray::between(Vec2::new(40.0, 20.0), Vec2::new(40.0, 300.0));
//! let hit = cave.map.cast_ray(down, &QueryFilter::default()).unwrap();
//! assert_eq!((hit.point.y, hit.normal), (224.0, Vec2::new(0.0, -1.0)));
//! // The object layers come along: the player's spawn point.
//! let spawn = cave.object_layer("spawns").and_then(|l| l.object("player")).unwrap();
//! assert_eq!(spawn.position, Vec2::new(40.0, 200.0));
//! # Ok::<(), tileslide::io::LoadError>(())
//! ```

mod build;
mod document;
mod files;
mod flip;
mod objects;
mod placement;
mod properties;
mod shapes;
mod tile_data;
mod tmj;
mod tmj_schema;
mod tmx;
mod tmx_scan;
mod xml_walker;

use std::collections::BTreeMap;
use std::path::Path;

pub use files::TiledFiles;
pub use flip::Flip;
pub use objects::{MapObject, ObjectLayer, ObjectShape};
pub use properties::{Properties, PropertyValue};
pub use shapes::ELLIPSE_SEGMENTS;

use super::error::{as_text, read_file};
use super::json_text::line_column;
use super::{LoadError, Location, NotTiled};
use crate::HitTypes;
use crate::tiles::{TileId, TileMap};

/// Most tiles a tile set may declare (its `tilecount`): the `tiled` crate reserves room for
/// that many before reading them.
pub const MAX_TILE_COUNT: u32 = 1 << 18;

/// How to load a Tiled map, and the bounds a game loading its players' levels can set on
/// what one file may cost.
///
/// ```
/// # use tileslide::io::tiled::TiledOptions;
/// let options = TiledOptions::default().with_layer("ground").with_max_cells(1 << 20);
/// assert_eq!(options.layer.as_deref(), Some("ground"));
/// assert_eq!((options.max_cells, options.max_chunk_spread), (1 << 20, 64));
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TiledOptions {
    /// The tile layer that collides: the first named so; else, as `NAME#N`, the N-th (from 1)
    /// tile layer named `NAME` (Tiled lets layers share a name), or as `#N` the N-th tile layer
    /// of the file. `None` (the default): the first tile layer with the bool property
    /// `collision = true`, else the first tile layer.
    pub layer: Option<String>,
    /// Most cells a tile layer may hold (`width × height`; for an infinite layer, its
    /// chunks together, and the collision layer's bounding box), checked before anything is
    /// allocated from them. A map costs about 16 bytes a cell. Default, and most:
    /// [`MAX_CELLS`](crate::limits::MAX_CELLS) (2²⁶); a larger value is taken as that.
    pub max_cells: u64,
    /// Most cells an infinite collision layer's bounding box may span for each cell its
    /// chunks hold, once it spans more than [`SPREAD_FREE_CELLS`]. The map is built over the
    /// whole bounding box, so a few chunks far apart (a 500-byte file with two chunks 8000
    /// cells apart) cost memory for every empty cell between them; the default, 64,
    /// refuses such a map and loads any whose chunks cover a 64th of their extent.
    pub max_chunk_spread: u64,
    /// The map's external files (tile sets, templates) given in memory, by the name the map
    /// writes them with (relative to it): a game in the browser has no disk to read them
    /// from. Empty (the default): they are read from disk beside the map.
    pub files: TiledFiles,
}

/// Cells an infinite layer's bounding box may span whatever its chunks hold (about 16 MB of
/// map): [`TiledOptions::max_chunk_spread`] bounds only maps larger than this.
pub const SPREAD_FREE_CELLS: u64 = 1 << 20;

impl Default for TiledOptions {
    fn default() -> Self {
        Self {
            layer: None,
            max_cells: crate::tiles::MAX_CELLS,
            max_chunk_spread: 64,
            files: TiledFiles::new(),
        }
    }
}

impl TiledOptions {
    /// These options with the collision layer `name` (a name, `NAME#N` or `#N`: see
    /// [`layer`](Self::layer)).
    #[must_use]
    pub fn with_layer(mut self, name: impl Into<String>) -> Self {
        self.layer = Some(name.into());
        self
    }

    /// These options with at most `cells` cells a layer (see [`max_cells`](Self::max_cells)).
    #[must_use]
    pub fn with_max_cells(mut self, cells: u64) -> Self {
        self.max_cells = cells;
        self
    }

    /// These options with an infinite layer's bounding box at most `spread` times its chunks'
    /// cells (see [`max_chunk_spread`](Self::max_chunk_spread)).
    #[must_use]
    pub fn with_max_chunk_spread(mut self, spread: u64) -> Self {
        self.max_chunk_spread = spread;
        self
    }

    /// These options with the external file `name` (as the map writes it, relative to the
    /// map) given as `bytes`, read instead of the disk; once one file is given, every
    /// external file must be.
    #[must_use]
    pub fn with_file(mut self, name: impl Into<String>, bytes: impl Into<Vec<u8>>) -> Self {
        self.files.insert(name.into(), bytes.into());
        self
    }

    /// The cell bound in force: [`max_cells`](Self::max_cells), at most `MAX_CELLS`.
    fn cell_bound(&self) -> u64 {
        self.max_cells.min(crate::tiles::MAX_CELLS)
    }
}

/// How errors name the cell bound `limit`, and how to raise it.
fn cell_limit(limit: u64) -> String {
    if limit >= crate::tiles::MAX_CELLS {
        format!("{limit} cells")
    } else {
        format!("{limit} cells (`TiledOptions::max_cells`; raise it to load this map)")
    }
}

/// A loaded Tiled map: the collision layer as a [`TileMap`], and the rest of what a game
/// needs from the file.
#[derive(Clone, Debug)]
pub struct TiledMap {
    /// The collision layer's tiles and their shapes.
    pub map: TileMap,
    /// The name of the tile layer [`map`](Self::map) was built from.
    pub collision_layer: String,
    /// Its index in [`tile_layers`](Self::tile_layers) (which may hold its name twice).
    pub collision_layer_index: usize,
    /// The names of every tile layer, in file order (group members included).
    pub tile_layers: Vec<String>,
    /// The object layers, in file order (group members included).
    pub object_layers: Vec<ObjectLayer>,
    /// The map's custom properties.
    pub properties: Properties,
    tiles: BTreeMap<TileId, TileInfo>,
}

impl TiledMap {
    /// What a tile id of [`map`](Self::map) is: its tile, tile set, flips and properties.
    #[must_use]
    pub fn tile_info(&self, id: TileId) -> Option<&TileInfo> {
        self.tiles.get(&id)
    }

    /// The first object layer named `name`.
    #[must_use]
    pub fn object_layer(&self, name: &str) -> Option<&ObjectLayer> {
        self.object_layers.iter().find(|l| l.name == name)
    }
}

/// A tile placed in the collision layer, as Tiled knows it.
#[derive(Clone, Debug, PartialEq)]
pub struct TileInfo {
    /// The gid with its flip bits: the same number as the tile id.
    pub gid: u32,
    /// The name of its tile set.
    pub tile_set: String,
    /// Its id within the tile set.
    pub local_id: u32,
    /// How it is flipped.
    pub flip: Flip,
    /// The tile's class; empty if none.
    pub class: String,
    /// The tile's custom properties.
    pub properties: Properties,
    /// The tile's `hit_types` property, parsed ([`HitTypes::NONE`] when unset).
    pub hit_types: HitTypes,
}

/// Loads a `.tmx` or `.tmj` map (by its extension; `.json` is read as `.tmj`, and JSON that
/// is not a Tiled map — a tile set, a scene — is an error saying what it is). External tile
/// sets are found relative to the map's folder.
pub fn load(path: impl AsRef<Path>, options: &TiledOptions) -> Result<TiledMap, LoadError> {
    let path = path.as_ref();
    let extension = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let parse = match extension.as_deref() {
        Some("tmx") => parse_tmx,
        Some("tmj" | "json") => parse_tmj,
        _ => {
            return Err(LoadError::new(
                path,
                Location::File,
                NotTiled::Extension(extension).into(),
            ));
        }
    };
    let bytes = read_file(path)?;
    let text = as_text(&bytes, path)?;
    parse(text, path, options)
}

/// Parses `.tmx` text. `path` names it in errors; its external tile sets and templates are
/// read from disk relative to `path`'s folder.
pub fn parse_tmx(
    text: &str,
    path: impl AsRef<Path>,
    options: &TiledOptions,
) -> Result<TiledMap, LoadError> {
    let path = path.as_ref();
    let doc = tmx::parse(strip_bom(text), path, options.cell_bound(), &options.files)?;
    build::build(doc, options, path)
}

/// Parses `.tmj` text. `path` names it in errors; its external tile sets are read from disk
/// relative to `path`'s folder.
///
/// ```
/// use tileslide::io::tiled::{self, TiledOptions};
/// use tileslide::{Cell, Vec2};
///
/// let tmj = r#"{
///   "orientation": "orthogonal", "width": 2, "height": 1,
///   "tilewidth": 8, "tileheight": 8,
///   "tilesets": [{ "firstgid": 1, "name": "t", "tilewidth": 8, "tileheight": 8,
///     "tilecount": 1, "tiles": [{ "id": 0, "objectgroup": { "objects": [
///       { "id": 1, "x": 0, "y": 0, "width": 8, "height": 8 } ] } }] }],
///   "layers": [{ "type": "tilelayer", "name": "walls", "width": 2, "height": 1,
///     "data": [0, 1] }]
/// }"#;
/// let level = tiled::parse_tmj(tmj, "level.tmj", &TiledOptions::default())?;
/// assert_eq!(level.map.cell_size(), Vec2::splat(8.0));
/// assert!(level.map.is_point_solid(Vec2::new(12.0, 4.0)));
/// assert!(level.map.tile(Cell::new(0, 0)).is_none());
///
/// // A truncated file: the error names where the JSON ends, line 3 column 3.
/// let cut = &tmj[..tmj.find("\"tilewidth").unwrap()];
/// let e = tiled::parse_tmj(cut, "level.tmj", &TiledOptions::default()).unwrap_err();
/// assert_eq!(e.to_string(), "level.tmj:3:3: truncated JSON: EOF while parsing a value");
/// # Ok::<(), tileslide::io::LoadError>(())
/// ```
pub fn parse_tmj(
    text: &str,
    path: impl AsRef<Path>,
    options: &TiledOptions,
) -> Result<TiledMap, LoadError> {
    let path = path.as_ref();
    let doc = tmj::parse(strip_bom(text), path, options.cell_bound(), &options.files)?;
    build::build(doc, options, path)
}

/// The text without a leading byte-order mark.
fn strip_bom(text: &str) -> &str {
    text.strip_prefix('\u{feff}').unwrap_or(text)
}
