//! The causes of LDtk load errors that a program may branch on, each found at a JSON path
//! of the project (`levels[2].layerInstances[0].intGridCsv`) or of a level file.

use thiserror::Error;

/// What is wrong in an LDtk project or level file, at the JSON path the error names.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum LdtkFault {
    /// Valid JSON whose value at the path is not what the LDtk format has there (a string
    /// for a number, a missing required field): serde's words.
    #[error("{0}")]
    Schema(String),
    /// A size or count that is out of range, refused before anything is allocated from it.
    #[error("`{field}` = {value} is out of range: {reason}")]
    Size {
        /// The field (`__cWid × __cHei`, `__gridSize`).
        field: &'static str,
        /// Its value.
        value: i64,
        /// Why it is refused.
        reason: String,
    },
    /// The project has no level.
    #[error("the project has no level")]
    NoLevels,
    /// The level asked for is not in the project (the levels it has, in file order).
    #[error("the project has no level {requested:?} (its levels: {})", quoted(.levels))]
    UnknownLevel {
        /// The level asked for.
        requested: String,
        /// The identifiers of the project's levels.
        levels: Vec<String>,
    },
    /// The layer asked for is not a layer of the level that can collide (the IntGrid,
    /// auto-layer and tile layers it has, in file order).
    #[error(
        "level {level:?} has no IntGrid, auto-layer or tile layer {requested:?} (its layers: {})",
        quoted(.layers)
    )]
    UnknownLayer {
        /// The level.
        level: String,
        /// The layer asked for.
        requested: String,
        /// The identifiers of its IntGrid, auto-layer and tile layers.
        layers: Vec<String>,
    },
    /// No layer was asked for, and the level has no IntGrid layer, nor an auto-layer or tile
    /// layer whose tile set names a collision shape.
    #[error(
        "level {level:?} has no IntGrid layer, nor an auto-layer or tile layer whose tiles name a \
         collision shape (its layers: {}); choose one",
        quoted(.layers)
    )]
    NoCollisionLayer {
        /// The level.
        level: String,
        /// The identifiers of all its layers.
        layers: Vec<String>,
    },
    /// A level with neither layers in the project nor a level file.
    #[error("the level has neither `layerInstances` nor an `externalRelPath`")]
    NoLayerInstances,
    /// A level file that holds another level than the project says.
    #[error("the level file holds level {found:?}, not {expected:?}")]
    WrongLevelFile {
        /// The level the project names.
        expected: String,
        /// The level the file holds.
        found: String,
    },
    /// A file path in the project that leads outside the project's folder: an absolute path,
    /// a `..` that climbs above the folder, or a symbolic link out of it. Such a file is
    /// never opened.
    #[error("{path:?} leads outside the project's folder ({why}): it is not opened")]
    OutsideProject {
        /// The path as the project writes it.
        path: String,
        /// How: `an absolute path`, `".." climbs above the folder`, `a symbolic link leads out`.
        why: &'static str,
    },
    /// A layer's IntGrid values are not one per cell.
    #[error("holds {found} values, expected {expected} (`__cWid` × `__cHei`, one per cell)")]
    CellCount {
        /// How many it holds.
        found: u64,
        /// How many cells the layer has.
        expected: u64,
    },
    /// A negative IntGrid value.
    #[error("IntGrid value {0} is negative")]
    NegativeValue(i64),
    /// A layer names a definition (layer, tile set, enum) the project does not have.
    #[error("no {what} has uid {uid}")]
    UnknownUid {
        /// `tile set`, `layer definition`, `enum`.
        what: &'static str,
        /// The uid named.
        uid: i64,
    },
    /// A tile of a tile or auto-layer placed off the layer's grid or outside it.
    #[error(
        "tile {tile} at pixel ({x}, {y}) is not on a cell of the layer's {columns} × {rows} grid of {grid_size} pixels"
    )]
    TileOffGrid {
        /// The tile's id in its tile set.
        tile: i64,
        /// Its pixel position in the layer, x.
        x: i64,
        /// Its pixel position in the layer, y.
        y: i64,
        /// The layer's columns.
        columns: u32,
        /// The layer's rows.
        rows: u32,
        /// The layer's cell size, in pixels.
        grid_size: u32,
    },
    /// A collision layer whose tile set's tiles are not the size of the layer's cells.
    #[error(
        "the tile set {tile_set:?} has tiles of {tile_size} pixels, the layer cells of {grid_size}: the tiles of a collision layer must fill one cell each"
    )]
    TileSize {
        /// The tile set.
        tile_set: String,
        /// Its tiles' size, in pixels.
        tile_size: i64,
        /// The layer's cell size.
        grid_size: u32,
    },
    /// A tile whose enum tags or custom data name two different collision shapes.
    #[error(
        "tile {tile} of tile set {tile_set:?} names two collision shapes, {first:?} and {second:?}"
    )]
    TwoShapes {
        /// The tile set.
        tile_set: String,
        /// The tile's id.
        tile: i64,
        /// The first shape named.
        first: String,
        /// The second.
        second: String,
    },
    /// A tile's custom data says `collision: NAME` with a name that is no collision shape.
    #[error("tile {tile} of tile set {tile_set:?}: custom data `collision` is {name:?}, which names no collision shape (expected one of {})", crate::io::ldtk::Collision::NAMES.join(", "))]
    UnknownShape {
        /// The tile set.
        tile_set: String,
        /// The tile's id.
        tile: i64,
        /// The name given.
        name: String,
    },
    /// A field value that does not match its `__type`.
    #[error("field {field:?} of type {kind:?}: {reason}")]
    BadField {
        /// The field's identifier.
        field: String,
        /// Its `__type`.
        kind: String,
        /// What is wrong.
        reason: String,
    },
}

/// `"a", "b"`, or `none` for no names.
fn quoted(names: &[String]) -> String {
    if names.is_empty() {
        return "none".to_owned();
    }
    names
        .iter()
        .map(|n| format!("{n:?}"))
        .collect::<Vec<_>>()
        .join(", ")
}
