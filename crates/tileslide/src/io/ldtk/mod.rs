//! LDtk projects: `.ldtk` files from the [LDtk](https://ldtk.io) editor, with their levels
//! inline or in `.ldtkl` files, as a [`TileMap`] for one layer of one level plus the level's
//! entity layers and the project's levels. Needs the `ldtk` cargo feature (on by default).
//!
//! - **Coordinates** are world pixels, y down, as LDtk shows them: a level sits at its world
//!   position (`worldX`, `worldY` in the free and GridVania layouts; one level after the
//!   other, 48 pixels apart, in the linear layouts, as LDtk places them), and a layer's
//!   cells are its `__gridSize` pixels, from the level's corner plus the layer's offset.
//! - **The level** is the one [`LdtkOptions::level`] names, else the first. **The layer** is
//!   the IntGrid, auto-layer or tile layer [`LdtkOptions::layer`] names, else the first
//!   IntGrid layer, else the first auto-layer or tile layer whose tiles name a collision
//!   shape. Unknown names are errors listing the names there are.
//! - **IntGrid values** become tiles by the game's mapping (by value, then by the value's
//!   identifier), else by the value's identifier when it names a [`Collision`] (`solid`,
//!   `one_way`, `ramp_up_right`, …), else value 1 is solid and the others empty.
//! - **Tiles of auto-layers and tile layers** collide by their tile set: a tile's enum tags
//!   and its custom data (`collision: one_way`, or the whole text a shape's name) name its
//!   [`Collision`], through the game's mapping first; tiles flipped in LDtk are mirrored
//!   (their ids carry [`FLIP_X_BIT`] and [`FLIP_Y_BIT`]). Where tiles stack, the top one
//!   that names a shape counts.
//! - **Entities** come as [`EntityLayer`]s: identifier, position, size, pivot, tags and
//!   fields, the way [`io::tiled`](crate::io::tiled) gives object layers.
//! - **Errors** name the file, the JSON path (`levels[2].layerInstances[0].intGridCsv`) and
//!   the cause ([`LdtkFault`]); sizes are checked against
//!   [`MAX_CELLS`](crate::limits::MAX_CELLS) and [`MAX_GRID_SIZE`] before anything is
//!   allocated; a path the project writes (`externalRelPath`) never opens a file outside
//!   the project's folder; nothing panics.
//!
//! See `docs/ldtk.md` for the conventions.
//!
//! ```
//! use tileslide::io::ldtk::{self, Collision, LdtkOptions};
//! use tileslide::{QueryFilter, Ray, Vec2};
//!
//! let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/maps/ldtk/platformer.ldtk");
//! let level = ldtk::load(path, &LdtkOptions::default())?;
//! assert_eq!((level.level.as_str(), level.collision_layer.as_str()), ("Meadow", "Collisions"));
//! // Straight down from the sky at x = 40: the ground's top is at y = 272 pixels.
//! let down = Ray::between(Vec2::new(40.0, 8.0), Vec2::new(40.0, 400.0));
//! let hit = level.map.cast_ray(down, &QueryFilter::default()).unwrap();
//! assert_eq!((hit.point.y, hit.normal), (272.0, Vec2::new(0.0, -1.0)));
//! // The entities come along: where the player starts.
//! let start = level.entity_layer("Entities").and_then(|l| l.entity("PlayerStart")).unwrap();
//! assert_eq!(start.position, Vec2::new(40.0, 272.0));
//! # Ok::<(), tileslide::io::LoadError>(())
//! ```

mod build;
mod collision;
mod entities;
mod files;
mod layers;
mod schema;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use glam::Vec2;
use serde::de::DeserializeOwned;

pub use collision::{Collision, FLIP_X_BIT, FLIP_Y_BIT};
pub use entities::{EntityLayer, FieldPoint, FieldValue, Fields, LdtkEntity, TileRect};
pub use files::LdtkFiles;

use super::error::{as_text, read_file};
use super::json_text::{json_error, json_location, json_message};
use super::{LdtkFault, LoadError, LoadErrorKind, Location};
use crate::tiles::{TileId, TileMap, TileShape};

/// Largest layer cell (`__gridSize`) the loader accepts, in pixels.
pub const MAX_GRID_SIZE: i64 = 1 << 16;

/// How to load an LDtk level: which level and layer, what cells become, and the bound a
/// game loading its players' levels can set on what one file may cost.
///
/// ```
/// use tileslide::io::ldtk::{Collision, LdtkOptions};
/// let options = LdtkOptions::default()
///     .with_level("Cave")
///     .with_layer("Walls")
///     .with_value(3, Collision::OneWay)
///     .with_name("slope", Collision::RampUpRight);
/// assert_eq!(options.level.as_deref(), Some("Cave"));
/// assert_eq!(options.values[&3], Collision::OneWay);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct LdtkOptions {
    /// The level (its identifier). `None` (the default): the first level.
    pub level: Option<String>,
    /// The layer that collides (its identifier): an IntGrid, auto-layer or tile layer.
    /// `None` (the default): the level's first IntGrid layer, else its first auto-layer or
    /// tile layer whose tiles name a collision shape.
    pub layer: Option<String>,
    /// IntGrid values the game maps, by value: these come first.
    pub values: BTreeMap<i64, Collision>,
    /// Names the game maps: IntGrid value identifiers, tile enum tags, and the names custom
    /// data gives, before the built-in names of [`Collision::from_name`].
    pub names: BTreeMap<String, Collision>,
    /// The shapes of the game's own tiles ([`Collision::Tile`]), in a unit cell (`[0, 1]²`,
    /// y down): the loader scales them to the layer's cells (and mirrors them for flipped
    /// tiles).
    pub tile_shapes: BTreeMap<TileId, TileShape>,
    /// Most cells the collision layer may hold (`__cWid × __cHei`), checked before anything
    /// is allocated from them. Default, and most: [`MAX_CELLS`](crate::limits::MAX_CELLS).
    pub max_cells: u64,
    /// The project's level files given in memory, by the path the project writes
    /// (`externalRelPath`): a game in the browser has no disk to read them from. Empty (the
    /// default): they are read from disk, inside the project's folder.
    pub files: LdtkFiles,
}

impl Default for LdtkOptions {
    fn default() -> Self {
        Self {
            level: None,
            layer: None,
            values: BTreeMap::new(),
            names: BTreeMap::new(),
            tile_shapes: BTreeMap::new(),
            max_cells: crate::tiles::MAX_CELLS,
            files: LdtkFiles::new(),
        }
    }
}

impl LdtkOptions {
    /// These options with the level `identifier`.
    #[must_use]
    pub fn with_level(mut self, identifier: impl Into<String>) -> Self {
        self.level = Some(identifier.into());
        self
    }

    /// These options with the collision layer `identifier`.
    #[must_use]
    pub fn with_layer(mut self, identifier: impl Into<String>) -> Self {
        self.layer = Some(identifier.into());
        self
    }

    /// These options with IntGrid value `value` made `collision`.
    #[must_use]
    pub fn with_value(mut self, value: i64, collision: Collision) -> Self {
        self.values.insert(value, collision);
        self
    }

    /// These options with the name `name` (an IntGrid value identifier, an enum tag, a
    /// custom data name) made `collision`.
    #[must_use]
    pub fn with_name(mut self, name: impl Into<String>, collision: Collision) -> Self {
        self.names.insert(name.into(), collision);
        self
    }

    /// These options with the game's tile `id` of `shape` (in a unit cell), for
    /// [`Collision::Tile`].
    #[must_use]
    pub fn with_tile_shape(mut self, id: TileId, shape: TileShape) -> Self {
        self.tile_shapes.insert(id, shape);
        self
    }

    /// These options with at most `cells` cells in the collision layer.
    #[must_use]
    pub fn with_max_cells(mut self, cells: u64) -> Self {
        self.max_cells = cells;
        self
    }

    /// These options with the level file `name` (as the project writes it) given as
    /// `bytes`, read instead of the disk; once one file is given, every level file must be.
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

/// How a project's levels are placed in its world.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum WorldLayout {
    /// Anywhere: each level's `worldX`, `worldY`.
    Free,
    /// On a grid of world cells: each level's `worldX`, `worldY`.
    GridVania,
    /// One after the other, left to right, 48 pixels apart.
    LinearHorizontal,
    /// One after the other, top to bottom, 48 pixels apart.
    LinearVertical,
}

/// The gap LDtk leaves between levels in the linear layouts, in pixels.
pub const LINEAR_LEVEL_SPACING: i64 = 48;

/// A level of the project, as the project file describes it.
#[derive(Clone, Debug, PartialEq)]
pub struct LdtkLevel {
    /// The level's identifier.
    pub identifier: String,
    /// The level's iid.
    pub iid: String,
    /// The identifier of its world: empty unless the project has several worlds.
    pub world: String,
    /// How its world places levels.
    pub layout: WorldLayout,
    /// Its top-left corner, in world pixels.
    pub world_position: Vec2,
    /// Its width and height, in pixels.
    pub size: Vec2,
    /// Its depth in the world (greater is above).
    pub world_depth: i64,
    /// The file holding its layers, as the project writes it (`externalRelPath`); `None`
    /// when they are in the project.
    pub external_file: Option<String>,
    /// Its custom fields.
    pub fields: Fields,
}

/// A parsed `.ldtk` project: its levels, ready to build any one of them. Levels saved in
/// their own `.ldtkl` files are read when built.
///
/// ```
/// use tileslide::io::ldtk::{LdtkOptions, LdtkProject};
/// let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/maps/ldtk/dungeon.ldtk");
/// let project = LdtkProject::load(path)?;
/// let names: Vec<&str> = project.levels().iter().map(|l| l.identifier.as_str()).collect();
/// assert_eq!(names, ["Entrance", "Crypt"]);
/// let crypt = project.build(&LdtkOptions::default().with_level("Crypt"))?;
/// assert_eq!(crypt.map.origin().x, 256.0 + 48.0); // after the entrance, 48 pixels apart
/// # Ok::<(), tileslide::io::LoadError>(())
/// ```
#[derive(Clone, Debug)]
pub struct LdtkProject {
    path: PathBuf,
    json: schema::ProjectJson,
    levels: Vec<LdtkLevel>,
    /// Where each level is in the project's JSON.
    level_paths: Vec<build::LevelSource>,
}

impl LdtkProject {
    /// Reads the project at `path` (not its level files).
    pub fn load(path: impl AsRef<Path>) -> Result<Self, LoadError> {
        let path = path.as_ref();
        let bytes = read_file(path)?;
        let text = as_text(&bytes, path)?;
        Self::parse(text, path)
    }

    /// Parses project text; `path` names it in errors and locates its level files.
    pub fn parse(text: &str, path: impl AsRef<Path>) -> Result<Self, LoadError> {
        let path = path.as_ref();
        let json: schema::ProjectJson = from_json(text, path)?;
        let (levels, level_paths) =
            build::levels(&json).map_err(|(at, fault)| ldtk_error(path, at, fault))?;
        Ok(Self {
            path: path.to_path_buf(),
            json,
            levels,
            level_paths,
        })
    }

    /// The project's file, as given.
    #[must_use]
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The format version the file says it is (`jsonVersion`).
    #[must_use]
    pub fn json_version(&self) -> &str {
        &self.json.json_version
    }

    /// The levels, in file order (world after world in a multi-world project).
    #[must_use]
    pub fn levels(&self) -> &[LdtkLevel] {
        &self.levels
    }

    /// The first level whose identifier is `identifier`.
    #[must_use]
    pub fn level(&self, identifier: &str) -> Option<&LdtkLevel> {
        self.levels.iter().find(|l| l.identifier == identifier)
    }

    /// Where the file at `rel`, a path the project writes (a tile set's `relPath`, a
    /// `FilePath` field), is on disk: refused if it leads outside the project's folder
    /// (absolute, a `..` above the folder, or a symbolic link out of it).
    ///
    /// # Errors
    /// [`LdtkFault::OutsideProject`], or the I/O error of a file that does not exist.
    pub fn resolve(&self, rel: &str) -> Result<PathBuf, LoadError> {
        let inside = files::inside(rel).map_err(|f| ldtk_error(&self.path, String::new(), f))?;
        files::disk_path(&self.path, &inside).map_err(|e| disk_error(&self.path, e))
    }

    /// Builds the level and layer `options` choose.
    pub fn build(&self, options: &LdtkOptions) -> Result<LdtkMap, LoadError> {
        build::build(self, options)
    }
}

/// A loaded LDtk level: its collision layer as a [`TileMap`], its entity layers, and the
/// project's levels.
#[derive(Clone, Debug)]
pub struct LdtkMap {
    /// The collision layer's tiles and their shapes, in world pixels.
    pub map: TileMap,
    /// The identifier of the level built.
    pub level: String,
    /// Its index in [`levels`](Self::levels).
    pub level_index: usize,
    /// The identifier of the layer [`map`](Self::map) was built from.
    pub collision_layer: String,
    /// The identifiers of every layer of the level, in LDtk's order (top-most first).
    pub layers: Vec<String>,
    /// The level's entity layers, in LDtk's order.
    pub entity_layers: Vec<EntityLayer>,
    /// Every level of the project (with its world position and fields).
    pub levels: Vec<LdtkLevel>,
    /// The IntGrid values of the collision layer, one per cell row by row (empty when it is
    /// an auto-layer or tile layer).
    int_grid: Vec<i64>,
}

impl LdtkMap {
    /// The entity layer whose identifier is `identifier`.
    #[must_use]
    pub fn entity_layer(&self, identifier: &str) -> Option<&EntityLayer> {
        self.entity_layers
            .iter()
            .find(|l| l.identifier == identifier)
    }

    /// Every entity of the level, layer after layer.
    pub fn entities(&self) -> impl Iterator<Item = &LdtkEntity> {
        self.entity_layers.iter().flat_map(|l| &l.entities)
    }

    /// The level built, as the project describes it.
    #[must_use]
    pub fn level_info(&self) -> Option<&LdtkLevel> {
        self.levels.get(self.level_index)
    }

    /// The IntGrid value of `cell` in the collision layer (0 for an empty cell); `None`
    /// outside the map, or when the layer is not an IntGrid layer.
    #[must_use]
    pub fn int_grid_value(&self, cell: crate::Cell) -> Option<i64> {
        if cell.col >= self.map.width() || cell.row >= self.map.height() {
            return None;
        }
        let i = cell.row as usize * self.map.width() as usize + cell.col as usize;
        self.int_grid.get(i).copied()
    }
}

/// Loads the level `options` choose from the project at `path`, reading its level file if
/// it has one.
pub fn load(path: impl AsRef<Path>, options: &LdtkOptions) -> Result<LdtkMap, LoadError> {
    LdtkProject::load(path)?.build(options)
}

/// Parses project text and builds the level `options` choose; `path` names the project in
/// errors and locates its level files.
///
/// ```
/// use tileslide::io::ldtk::{self, LdtkOptions};
/// let project = r#"{ "jsonVersion": "1.5.3", "worldLayout": "Free",
///   "levels": [{ "identifier": "One", "worldX": 0, "worldY": 0, "pxWid": 32, "pxHei": 16,
///     "layerInstances": [{ "__identifier": "Walls", "__type": "IntGrid",
///       "__cWid": 2, "__cHei": 1, "__gridSize": 16, "intGridCsv": [0, 1] }] }] }"#;
/// let level = ldtk::parse(project, "one.ldtk", &LdtkOptions::default())?;
/// assert!(level.map.is_point_solid(tileslide::Vec2::new(24.0, 8.0)));
///
/// // A value that is not one: the error names the file, the line and column and the path.
/// let bad = project.replace("[0, 1]", "[0, \"1\"]");
/// let e = ldtk::parse(&bad, "one.ldtk", &LdtkOptions::default()).unwrap_err();
/// assert_eq!(
///     e.to_string(),
///     "one.ldtk:4:71: levels[0].layerInstances[0].intGridCsv[1]: invalid type: string \"1\", expected i64"
/// );
/// # Ok::<(), tileslide::io::LoadError>(())
/// ```
pub fn parse(
    text: &str,
    path: impl AsRef<Path>,
    options: &LdtkOptions,
) -> Result<LdtkMap, LoadError> {
    LdtkProject::parse(text, path)?.build(options)
}

/// `text` read as JSON of type `T`; a value serde refuses is named by its JSON path.
fn from_json<T: DeserializeOwned>(text: &str, path: &Path) -> Result<T, LoadError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut de = serde_json::Deserializer::from_str(text);
    let value: T = serde_path_to_error::deserialize(&mut de).map_err(|e| {
        let json_path = e.path().to_string();
        let inner = e.into_inner();
        if !inner.is_data() {
            return json_error(text, path, inner);
        }
        let location = json_location(text, &inner);
        let kind = LoadErrorKind::Ldtk {
            json_path: if json_path == "." {
                String::new()
            } else {
                json_path
            },
            fault: Box::new(LdtkFault::Schema(json_message(&inner))),
        };
        LoadError::new(path, location, kind)
    })?;
    // Text after the value: malformed.
    de.end().map_err(|e| json_error(text, path, e))?;
    Ok(value)
}

/// The error `fault` at `json_path` of the file `path`.
fn ldtk_error(path: &Path, json_path: String, fault: LdtkFault) -> LoadError {
    LoadError::new(
        path,
        Location::File,
        LoadErrorKind::Ldtk {
            json_path,
            fault: Box::new(fault),
        },
    )
}

/// The error for a file the project at `path` names that could not be read from disk.
fn disk_error(path: &Path, e: files::DiskFault) -> LoadError {
    match e {
        files::DiskFault::Io(file, source) => LoadError::new(
            path,
            Location::File,
            LoadErrorKind::Io {
                referenced: Some(file),
                source,
            },
        ),
        files::DiskFault::Outside(fault) => ldtk_error(path, String::new(), fault),
    }
}
