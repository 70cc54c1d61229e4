//! The causes of Tiled load errors that a program may branch on: a file that is not a Tiled
//! map, a feature tileslide does not load, where a tile is placed. Defined whether or not
//! the `tiled` feature is on, as [`LoadErrorKind`](super::LoadErrorKind) is.

use std::fmt;

use thiserror::Error;

/// Why a file is not a Tiled map, saying what it is instead.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum NotTiled {
    /// The file's extension is not `.tmx`, `.tmj` or `.json` (the extension, if any).
    #[error("not a Tiled map: expected a .tmx, .tmj or .json file")]
    Extension(Option<String>),
    /// XML whose root element is not `<map>` (the element's name, e.g. `tileset`).
    #[error("not a Tiled map: the root element is <{0}>, not <map>")]
    RootElement(String),
    /// XML without any element.
    #[error("not a Tiled map: no <map> element")]
    NoMapElement,
    /// A Tiled JSON tile set (`"type": "tileset"`).
    #[error("a Tiled tile set (\"type\": \"tileset\"), not a map")]
    TileSet,
    /// A JSON object whose `type` is not `map` (the type, e.g. `world`).
    #[error("not a Tiled JSON map: its `type` is {0:?}, not \"map\"")]
    JsonType(String),
    /// A JSON object with neither a `type` nor an `orientation`.
    #[error("not a Tiled JSON map: it has neither `\"type\": \"map\"` nor an `orientation`")]
    UntypedJson,
    /// JSON that is not an object.
    #[error("not a Tiled JSON map: the file is JSON but not an object")]
    NotAnObject,
}

/// Something a Tiled file uses that tileslide does not load.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum Unsupported {
    /// A map that is not orthogonal (the orientation: `isometric`, `staggered`, `hexagonal`).
    #[error("orientation {0:?} is not supported: tileslide loads orthogonal maps only")]
    Orientation(String),
    /// A tile layer's data encoding (`None`: XML `<tile>` elements) and compression.
    #[error(
        "{layer}: unknown tile data encoding: encoding {:?}, compression {:?} (supported: csv; \
         base64 without compression or with zlib, gzip or zstd)",
        .encoding.as_deref().unwrap_or("none (XML <tile> elements)"),
        .compression.as_deref().unwrap_or("none")
    )]
    Encoding {
        /// The layer: `layer "walls"`, `layers[2] ("walls")`.
        layer: String,
        /// The `encoding`.
        encoding: Option<String>,
        /// The `compression`.
        compression: Option<String>,
    },
    /// Something this build can read only with a cargo feature it was built without.
    #[error("{what} needs tileslide's `{feature}` cargo feature")]
    Feature {
        /// What needs it, e.g. `zstd-compressed tile data`.
        what: &'static str,
        /// The feature, e.g. `tiled-zstd`.
        feature: &'static str,
    },
    /// A `.tmx` map's external tile set saved as JSON (the file, as the map names it).
    #[error(
        "external tile set {0:?} is JSON: a .tmx map's tile sets must be .tsx files (save the \
         tile set as .tsx, or the map as .tmj)"
    )]
    JsonTileSetInTmx(String),
    /// An object of a `.tmj` map made from a template (the object's id and the template).
    #[error(
        "object {object} uses the template {template:?}: templates are supported in .tmx maps \
         only (detach it in Tiled, or save the map as .tmx)"
    )]
    TemplateInTmj {
        /// The object's id.
        object: u32,
        /// The template file, as the map names it.
        template: String,
    },
}

/// Where a tile is placed in a Tiled map's collision layer.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TilePlacement {
    /// The layer's name.
    pub layer: String,
    /// The cell's column, in Tiled's cell coordinates (negative in an infinite map's chunks
    /// left of the origin).
    pub x: i64,
    /// The cell's row, in Tiled's cell coordinates.
    pub y: i64,
    /// The gid placed there, with its flip bits.
    pub gid: u32,
}

impl fmt::Display for TilePlacement {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "layer {:?}: cell ({}, {}), gid {:#x}",
            self.layer, self.x, self.y, self.gid
        )
    }
}
