use std::fmt;
use std::path::PathBuf;

use thiserror::Error;

use crate::tiles::{MapError, TileSetError};

/// Where in a file a load error is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
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

/// What went wrong while loading.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum LoadErrorKind {
    /// The file could not be read.
    #[error("cannot read the file: {0}")]
    Io(String),
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
    /// A character that is not a tile.
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
    /// The file's content is malformed or uses something not supported (a syntax error,
    /// an unknown encoding, a hexagonal map): the message says what.
    #[error("{0}")]
    Invalid(String),
}

/// A load error: the file, where in it, and what is wrong.
///
/// Displays as `path:line:column: cause` for text and `path: byte N: cause` for binary files.
#[derive(Clone, Debug, PartialEq, Error)]
#[error("{}{location}: {kind}", path.display())]
pub struct LoadError {
    /// The file (as given, or a name for in-memory data).
    pub path: PathBuf,
    /// Where in the file.
    pub location: Location,
    /// What is wrong.
    pub kind: LoadErrorKind,
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
}

/// Reads a whole file, naming it in the error.
pub(crate) fn read_file(path: &std::path::Path) -> Result<Vec<u8>, LoadError> {
    std::fs::read(path)
        .map_err(|e| LoadError::new(path, Location::File, LoadErrorKind::Io(e.to_string())))
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
