use std::fmt;
use std::path::PathBuf;

use thiserror::Error;

use super::baked::BakedFault;
#[cfg(feature = "ldtk")]
use super::ldtk_faults::LdtkFault;
use super::tiled_faults::{NotTiled, TilePlacement, Unsupported};
use crate::tiles::{Cell, MapError, TileSetError};

/// Where in a file a load error is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Location {
    /// The whole file (it could not be read, or a fact about all of it).
    File,
    /// A byte offset from the start of a binary file.
    Byte(u64),
    /// A 1-based line and column (in characters) of a text file.
    LineColumn {
        /// Line, from 1.
        line: u32,
        /// Column, from 1.
        column: u32,
    },
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Location::File => Ok(()),
            Location::Byte(offset) => write!(f, ": byte {offset}"),
            Location::LineColumn { line, column } => write!(f, ":{line}:{column}"),
        }
    }
}

/// A parser crate's error, kept as the [`source`](std::error::Error::source) of a
/// [`LoadErrorKind::Syntax`].
pub type ParserError = Box<dyn std::error::Error + Send + Sync + 'static>;

/// What went wrong while loading.
///
/// Each variant carries what a program would branch on (the character, the layer, the
/// field, the offsets); its `Display` names the cause for a person. New causes may be added,
/// so matches need a `_` arm.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum LoadErrorKind {
    /// A file could not be read: the file the error names, or (`referenced` is `Some`) a file
    /// it refers to, such as a Tiled map's external tile set. The I/O error is the
    /// [`source`](std::error::Error::source): its [`kind`](std::io::Error::kind) tells a
    /// missing file from a refused one.
    #[error("cannot read {}: {source}", file_name(.referenced.as_deref()))]
    Io {
        /// The file referred to that could not be read, or `None` for the file itself.
        referenced: Option<PathBuf>,
        /// The error the operating system gave.
        #[source]
        source: std::io::Error,
    },
    /// The file ended inside a field.
    #[error("file ends inside `{field}` ({needed} more bytes needed)")]
    Truncated {
        /// The field being read.
        field: &'static str,
        /// How many bytes were missing.
        needed: u64,
    },
    /// A signature (magic number) field is wrong: not this kind of file.
    #[error("`{field}` is {found}, expected {expected}: not a {format} file")]
    BadSignature {
        /// The field.
        field: &'static str,
        /// What it should be.
        expected: i64,
        /// What the file holds.
        found: i64,
        /// The format expected.
        format: &'static str,
    },
    /// The magic bytes that start a file are wrong: not this kind of file.
    #[error(
        "`magic` is b\"{}\", expected b\"{}\": not a {format} file",
        .found.escape_ascii(),
        .expected.escape_ascii()
    )]
    BadMagic {
        /// What they should be.
        expected: &'static [u8],
        /// What the file holds.
        found: Vec<u8>,
        /// The format expected.
        format: &'static str,
    },
    /// The checksum stored in the file is not the one of its data: the file is corrupt.
    #[error(
        "`checksum` is {stored:#010x}, but the payload's CRC-32 is {computed:#010x}: the file \
         is corrupt"
    )]
    ChecksumMismatch {
        /// The checksum the file holds.
        stored: u64,
        /// The checksum of the data the file holds.
        computed: u64,
    },
    /// A size or count field is out of range.
    #[error("`{field}` = {value} is out of range: {reason}")]
    BadSize {
        /// The field.
        field: &'static str,
        /// Its value.
        value: i64,
        /// Why it is refused.
        reason: String,
    },
    /// A tile id appears twice in a tile set.
    #[error("tile {0} is defined twice")]
    DuplicateTile(u32),
    /// A text file that is not valid UTF-8 (the location is the first bad byte).
    #[error("the file is not valid UTF-8 text")]
    NotText,
    /// A character that is not a tile (the location is its line and column).
    #[error("unknown tile character {0:?} (expected one of `.`, space, `#`, `/`, `\\`, `=`)")]
    UnknownCharacter(char),
    /// The file has no cells.
    #[error("the map has no rows")]
    NoRows,
    /// A level without a collision layer.
    #[error("the level has no collision layer (type 1)")]
    NoCollisionLayer,
    /// Bytes after the end of the data.
    #[error("{0} unexpected bytes after the end of the data")]
    TrailingBytes(u64),
    /// A tile shape is invalid.
    #[error(transparent)]
    TileSet(#[from] TileSetError),
    /// The map could not be built.
    #[error(transparent)]
    Map(#[from] MapError),
    /// A parameter given with the file is invalid.
    #[error("{0}")]
    Parameter(String),
    /// A baked map's culled segments are not what its tiles make (the file was changed, or
    /// written by a faulty tool, with a right checksum): bake the map again from its source.
    #[error("{}{fault}", segment_in_cell(*.segment, *.cell))]
    BakedSegments {
        /// The cell at fault.
        cell: Cell,
        /// The active segment at fault, by its rank in the file, when one is.
        segment: Option<u64>,
        /// What is wrong.
        fault: BakedFault,
    },
    /// A tile sheet whose size is not a whole number of tiles.
    #[error("a {width} × {height} image does not divide into {tile_width} × {tile_height} tiles")]
    SheetSize {
        /// The image's width, in pixels.
        width: u32,
        /// The image's height, in pixels.
        height: u32,
        /// The tile width asked for.
        tile_width: u32,
        /// The tile height asked for.
        tile_height: u32,
    },
    /// Text or data that the parser of its format refuses (malformed or truncated XML or
    /// JSON, a damaged PNG image, bad base64): the parser's own words, its error (when it
    /// gave one) kept as the [`source`](std::error::Error::source).
    #[error("{message}")]
    Syntax {
        /// The format: `"XML"`, `"JSON"`, `"PNG"`, `"Tiled"` (an error of the `tiled` crate),
        /// `"base64"`, `"zlib"`, `"gzip"`, `"zstd"`.
        format: &'static str,
        /// The data ends early (a file cut short, or still being written).
        truncated: bool,
        /// What the parser says, with where it is when that is not the error's location.
        message: String,
        /// The parser's error.
        #[source]
        source: Option<ParserError>,
    },
    /// The file is not a Tiled map, and what it is instead.
    #[error(transparent)]
    NotATiledMap(#[from] NotTiled),
    /// The file uses something tileslide does not load.
    #[error(transparent)]
    Unsupported(#[from] Unsupported),
    /// A required field or attribute is absent.
    #[error("{owner} has no `{field}`")]
    Missing {
        /// What should hold it: `<map>`, `layers[2] ("walls")`, `tile set "kit"`.
        owner: String,
        /// The field or attribute.
        field: String,
    },
    /// A field, attribute or property has a value it cannot have.
    #[error("{owner}: `{field}` is {found}, expected {expected}")]
    BadValue {
        /// What holds it: `<layer>`, `layer "walls"`, `tile set "kit", tile 3`.
        owner: String,
        /// The field, attribute or property.
        field: &'static str,
        /// What it is (its value, or its type).
        found: String,
        /// What it may be.
        expected: &'static str,
    },
    /// A custom property that a loader reads (`collision`, `one_way`, `hit_types`, …) or that
    /// it converts has a value it cannot have.
    #[error("{owner}: property `{property}`: {reason}")]
    BadProperty {
        /// What it is a property of: `layer "walls"`, `object layer "spawns", object 3`.
        owner: String,
        /// The property's name.
        property: String,
        /// What is wrong with its value.
        reason: String,
    },
    /// A tile layer's data does not hold one gid per cell.
    #[error(
        "{owner}: the tile data holds {found}{} gids, expected {expected} (one per cell)",
        if *.or_more { " or more" } else { "" }
    )]
    GidCount {
        /// The layer (or chunk) whose data it is.
        owner: String,
        /// How many gids it holds (`or_more`: at least this many).
        found: u64,
        /// Whether it holds more than `found` (decoding stopped there).
        or_more: bool,
        /// How many cells the layer has.
        expected: u64,
    },
    /// The collision layer named by [`TiledOptions::layer`](crate::io::tiled::TiledOptions)
    /// is not in the map.
    #[error("{}", unknown_layer(.requested, .layers))]
    UnknownLayer {
        /// The layer asked for (a name, `NAME#N` or `#N`).
        requested: String,
        /// The map's tile layers, in file order.
        layers: Vec<String>,
    },
    /// The map has no tile layer to collide with.
    #[error("the map has no tile layer")]
    NoTileLayer,
    /// A gid placed in the collision layer below every tile set's first gid.
    #[error("{at}: no tile set holds this gid (it is below every first gid)")]
    GidBelowTileSets {
        /// Where it is placed.
        at: Box<TilePlacement>,
    },
    /// A gid placed in the collision layer past the last tile of the tile set it falls in.
    #[error("{at}: tile set {tile_set:?} has {tile_count} tiles, so it has no tile {tile}")]
    TileNotInSet {
        /// Where it is placed.
        at: Box<TilePlacement>,
        /// The tile set its number falls in.
        tile_set: String,
        /// How many tiles that tile set has.
        tile_count: u32,
        /// The tile asked for, within the tile set.
        tile: u32,
    },
    /// A tile that cannot be used: its collision objects or properties are wrong, or it
    /// cannot go where it is placed.
    #[error("{}tile set {tile_set:?}, tile {tile}: {reason}", placed_prefix(.placed.as_deref()))]
    BadTile {
        /// Where it is placed, when the fault is its placement there (it reaches out of its
        /// cell, or cannot be flipped so); `None` when its own definition is wrong.
        placed: Option<Box<TilePlacement>>,
        /// The name of its tile set.
        tile_set: String,
        /// Its id within the tile set.
        tile: u32,
        /// What is wrong, naming the collision object or property.
        reason: String,
    },
    /// A fault in an LDtk project or level file, at a JSON path of it.
    #[cfg(feature = "ldtk")]
    #[error("{}{fault}", json_path_prefix(.json_path))]
    Ldtk {
        /// Where in the file's JSON: `levels[2].layerInstances[0].intGridCsv` (empty for the
        /// whole file).
        json_path: String,
        /// What is wrong (boxed: it is large, and load errors are returned by value).
        fault: Box<LdtkFault>,
    },
}

/// `levels[2].pxWid: ` or nothing for the whole file.
#[cfg(feature = "ldtk")]
fn json_path_prefix(json_path: &str) -> String {
    if json_path.is_empty() {
        String::new()
    } else {
        format!("{json_path}: ")
    }
}

/// `the file`, or the file referred to.
fn file_name(referenced: Option<&std::path::Path>) -> String {
    referenced.map_or_else(
        || "the file".to_string(),
        |p| format!("the external file {}", p.display()),
    )
}

/// `active segment 3: in cell (4, 1), ` or `cell (4, 1): `.
fn segment_in_cell(segment: Option<u64>, cell: Cell) -> String {
    match segment {
        Some(k) => format!("active segment {k}: in cell ({}, {}), ", cell.col, cell.row),
        None => format!("cell ({}, {}): ", cell.col, cell.row),
    }
}

/// `layer "l": cell (0, 0), gid 0x2: ` or nothing.
fn placed_prefix(placed: Option<&TilePlacement>) -> String {
    placed.map_or_else(String::new, |p| format!("{p}: "))
}

/// Why no tile layer is `requested`: the layer names and the choices that pick each.
fn unknown_layer(requested: &str, layers: &[String]) -> String {
    // Every layer as a choice that picks it: "walls", then "walls#2" for a second "walls".
    let mut seen = std::collections::BTreeMap::<&str, usize>::new();
    let choices: Vec<String> = layers
        .iter()
        .map(|name| {
            let n = seen.entry(name).or_default();
            *n += 1;
            if *n == 1 {
                format!("{name:?}")
            } else {
                format!("{:?}", format!("{name}#{n}"))
            }
        })
        .collect();
    let choices = choices.join(", ");
    let numbered = requested
        .rsplit_once('#')
        .and_then(|(name, n)| Some((name, n.parse::<usize>().ok().filter(|&n| n >= 1)?)));
    let Some((name, _)) = numbered else {
        return format!(
            "the map has no tile layer named {requested:?} (its tile layers: {choices})"
        );
    };
    let count = layers
        .iter()
        .filter(|l| name.is_empty() || *l == name)
        .count();
    if name.is_empty() {
        format!("the map has {count} tile layers, so no {requested:?}")
    } else if count == 0 {
        format!("the map has no tile layer named {name:?} (its tile layers: {choices})")
    } else {
        format!(
            "the map has {count} tile layers named {name:?}, so no {requested:?} (its tile \
             layers: {choices})"
        )
    }
}

/// A load error: the file, where in it, and what is wrong.
///
/// Displays as `path:line:column: cause` for text and `path: byte N: cause` for binary files.
/// Its [`source`](std::error::Error::source) is the cause's own source: the I/O error of a
/// file that could not be read, a parser crate's error.
#[derive(Debug)]
pub struct LoadError {
    /// The file (as given, or a name for in-memory data).
    pub path: PathBuf,
    /// Where in the file.
    pub location: Location,
    /// What is wrong.
    pub kind: LoadErrorKind,
}

impl fmt::Display for LoadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}{}: {}", self.path.display(), self.location, self.kind)
    }
}

impl std::error::Error for LoadError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        // The kind is this error's own message: its source is the next cause down.
        self.kind.source()
    }
}

impl LoadError {
    /// An error in `path` at `location`.
    #[must_use]
    pub fn new(path: impl Into<PathBuf>, location: Location, kind: LoadErrorKind) -> Self {
        Self {
            path: path.into(),
            location,
            kind,
        }
    }

    /// The error for a file at `path` that could not be read.
    #[must_use]
    pub fn unreadable(path: impl Into<PathBuf>, source: std::io::Error) -> Self {
        Self::new(
            path,
            Location::File,
            LoadErrorKind::Io {
                referenced: None,
                source,
            },
        )
    }

    /// The I/O error, when a file could not be read.
    #[must_use]
    pub fn io_error(&self) -> Option<&std::io::Error> {
        match &self.kind {
            LoadErrorKind::Io { source, .. } => Some(source),
            _ => None,
        }
    }

    /// The kind of I/O error ([`NotFound`](std::io::ErrorKind::NotFound),
    /// [`PermissionDenied`](std::io::ErrorKind::PermissionDenied), …), when a file could not
    /// be read.
    #[must_use]
    pub fn io_error_kind(&self) -> Option<std::io::ErrorKind> {
        self.io_error().map(std::io::Error::kind)
    }
}

/// Reads a whole file, naming it in the error; refused past [`MAX_FILE_BYTES`].
pub(crate) fn read_file(path: &std::path::Path) -> Result<Vec<u8>, LoadError> {
    read_limited(path).map_err(|e| LoadError::unreadable(path, e))
}

/// Most bytes a file read whole may hold (1 GiB): more than the largest map tileslide loads
/// (a Tiled map of [`MAX_CELLS`](crate::limits::MAX_CELLS) cells written as CSV), and a bound on
/// what a file that never ends (a device, a pipe) may take.
pub const MAX_FILE_BYTES: u64 = 1 << 30;

/// The bytes of the file at `path`, read whole: what every loader reading from disk uses.
///
/// # Errors
/// The operating system's error, or one of kind
/// [`FileTooLarge`](std::io::ErrorKind::FileTooLarge) for a file of more than
/// [`MAX_FILE_BYTES`] bytes, found from its size before reading when it has one, else by
/// reading no more than one byte past the limit.
pub fn read_limited(path: &std::path::Path) -> std::io::Result<Vec<u8>> {
    read_at_most(path, MAX_FILE_BYTES)
}

/// [`read_limited`] with a limit of `max` bytes.
fn read_at_most(path: &std::path::Path, max: u64) -> std::io::Result<Vec<u8>> {
    use std::io::Read;
    let file = std::fs::File::open(path)?;
    let too_large = || {
        std::io::Error::new(
            std::io::ErrorKind::FileTooLarge,
            format!("it holds more than {max} bytes (MAX_FILE_BYTES)"),
        )
    };
    // A regular file says its size; a device or a pipe says 0 and is read up to the limit.
    let size = file.metadata().map_or(0, |m| m.len());
    if size > max {
        return Err(too_large());
    }
    let mut bytes = Vec::with_capacity(usize::try_from(size).unwrap_or(0));
    file.take(max + 1).read_to_end(&mut bytes)?;
    if bytes.len() as u64 > max {
        return Err(too_large());
    }
    Ok(bytes)
}

/// `bytes` as UTF-8 text, or an error naming `path` and the first byte that is not.
pub(crate) fn as_text<'a>(bytes: &'a [u8], path: &std::path::Path) -> Result<&'a str, LoadError> {
    std::str::from_utf8(bytes).map_err(|e| {
        LoadError::new(
            path,
            Location::Byte(e.valid_up_to() as u64),
            LoadErrorKind::NotText,
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_file_that_never_ends_is_read_no_further_than_the_limit() {
        let zero = std::path::Path::new("/dev/zero");
        if !zero.exists() {
            return;
        }
        let e = read_at_most(zero, 4096).unwrap_err();
        assert_eq!(e.kind(), std::io::ErrorKind::FileTooLarge);
        assert!(e.to_string().contains("more than 4096 bytes"), "{e}");
    }

    #[test]
    fn a_file_at_the_limit_is_read_whole_and_one_past_it_is_refused() {
        let path = std::env::temp_dir().join(format!("tileslide-limit-{}", std::process::id()));
        std::fs::write(&path, [7u8; 100]).unwrap();
        assert_eq!(read_at_most(&path, 100).unwrap(), [7u8; 100]);
        let e = read_at_most(&path, 99).unwrap_err();
        assert_eq!(e.kind(), std::io::ErrorKind::FileTooLarge);
        std::fs::remove_file(&path).unwrap();
    }
}
