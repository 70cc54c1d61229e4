//! ASCII maps: one character per cell, the first line is row 0 (y grows downward).
//!
//! | char | cell shape (cell-local, y down, unit cell) |
//! |---|---|
//! | `.` or space | empty |
//! | `#` | solid square |
//! | `/` | solid triangle (0,1)-(1,1)-(1,0): a ramp rising to the right, surface facing up-left |
//! | `\` | solid triangle (0,0)-(0,1)-(1,1): a ramp falling to the right, surface facing up-right |
//! | `=` | one-way platform: one segment along the top edge, normal pointing up (0,−1) |
//!
//! Lines starting with `;` are comments and are not rows. A leading UTF-8 byte-order mark
//! is ignored. Lines may differ in length: the
//! map is as wide as the longest, shorter lines are padded with empty cells. Blank lines
//! after the last row are ignored; a blank line between rows is a row of empty cells. The
//! map's origin is (0, 0).
//!
//! ```
//! # use tileslide::{io::ascii, Cell};
//! let map = ascii::parse("; a ledge\n#..=\n####\n", "ledge.txt", 1.0)?;
//! assert_eq!((map.width(), map.height()), (4, 2));
//! assert_eq!(map.tile(Cell::new(3, 0)), Some(ascii::ONE_WAY));
//! # Ok::<(), tileslide::io::LoadError>(())
//! ```

use std::path::Path;
use std::sync::Arc;

use glam::Vec2;
use thiserror::Error;

use super::error::{as_text, read_file};
use super::{LoadError, LoadErrorKind, Location};
use crate::tiles::{
    MAX_CELLS, MapError, SegmentFlags, TileId, TileMap, TileSegment, TileSet, TileSetError,
    TileShape,
};

/// `#`: a solid square.
pub const SOLID: TileId = TileId(1);
/// `/`: a ramp rising to the right (y down).
pub const RAMP_UP_RIGHT: TileId = TileId(2);
/// `\`: a ramp falling to the right (y down).
pub const RAMP_DOWN_RIGHT: TileId = TileId(3);
/// `=`: a one-way platform along the top edge.
pub const ONE_WAY: TileId = TileId(4);

/// A room of 6 × 3 empty cells walled in, for the crate's tests.
#[cfg(test)]
pub(crate) const TEST_ROOM: &str = "\
########
#......#
#......#
#......#
########";

/// A character that stands for no tile, as [`tile_for_char`] reports it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Error)]
#[error("unknown tile character {0:?} (expected one of `.`, space, `#`, `/`, `\\`, `=`)")]
pub struct UnknownTileChar(pub char);

/// The tile id for an ASCII character: `Ok(None)` for empty, an error naming the character
/// for one that stands for no tile.
///
/// ```
/// # use tileslide::io::ascii::{self, UnknownTileChar};
/// assert_eq!(ascii::tile_for_char('#'), Ok(Some(ascii::SOLID)));
/// assert_eq!(ascii::tile_for_char('.'), Ok(None));
/// assert_eq!(ascii::tile_for_char('@'), Err(UnknownTileChar('@')));
/// ```
pub fn tile_for_char(c: char) -> Result<Option<TileId>, UnknownTileChar> {
    match c {
        '.' | ' ' => Ok(None),
        '#' => Ok(Some(SOLID)),
        '/' => Ok(Some(RAMP_UP_RIGHT)),
        '\\' => Ok(Some(RAMP_DOWN_RIGHT)),
        '=' => Ok(Some(ONE_WAY)),
        _ => Err(UnknownTileChar(c)),
    }
}

/// The built-in tile set of ASCII maps, for square cells of side `cell`.
pub fn tile_set(cell: f32) -> Result<TileSet, TileSetError> {
    let size = Vec2::splat(cell);
    let mut set = TileSet::new(size)?;
    let p = |x: f32, y: f32| Vec2::new(x, y) * size;
    let shapes = [
        (
            SOLID,
            TileShape::polygon(&[p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)]),
        ),
        (
            RAMP_UP_RIGHT,
            TileShape::polygon(&[p(0.0, 1.0), p(1.0, 1.0), p(1.0, 0.0)]),
        ),
        (
            RAMP_DOWN_RIGHT,
            TileShape::polygon(&[p(0.0, 0.0), p(0.0, 1.0), p(1.0, 1.0)]),
        ),
        (
            ONE_WAY,
            TileShape::from_segments([TileSegment::new(
                p(0.0, 0.0),
                p(1.0, 0.0),
                Vec2::new(0.0, -1.0),
                SegmentFlags::ONE_WAY,
            )]),
        ),
    ];
    for (id, shape) in shapes {
        let shape = shape.map_err(|source| TileSetError::InvalidTile { id, source })?;
        set.insert(id, shape)?;
    }
    Ok(set)
}

/// Loads an ASCII map file with square cells of side `cell`.
pub fn load(path: impl AsRef<Path>, cell: f32) -> Result<TileMap, LoadError> {
    let path = path.as_ref();
    let bytes = read_file(path)?;
    let text = as_text(&bytes, path)?;
    parse(text, path, cell)
}

/// Parses ASCII map text; `path` names it in errors.
pub fn parse(text: &str, path: impl AsRef<Path>, cell: f32) -> Result<TileMap, LoadError> {
    let path = path.as_ref();
    let err = |location, kind| LoadError::new(path, location, kind);
    if !(cell.is_finite() && cell > 0.0) {
        return Err(err(
            Location::File,
            LoadErrorKind::Parameter(format!("cell size {cell} is not positive and finite")),
        ));
    }
    // A byte-order mark (as Windows editors write) is not part of the map.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut rows: Vec<Vec<Option<TileId>>> = Vec::new();
    for (line_index, line) in text.split('\n').enumerate() {
        let line = line.strip_suffix('\r').unwrap_or(line);
        if line.starts_with(';') {
            continue;
        }
        let mut row = Vec::with_capacity(line.len());
        for (col, c) in line.chars().enumerate() {
            let tile = tile_for_char(c).map_err(|UnknownTileChar(c)| {
                err(
                    Location::LineColumn {
                        line: line_index as u32 + 1,
                        column: col as u32 + 1,
                    },
                    LoadErrorKind::UnknownCharacter(c),
                )
            })?;
            row.push(tile);
        }
        rows.push(row);
    }
    while rows.last().is_some_and(|r| r.is_empty()) {
        rows.pop();
    }
    let height = rows.len();
    let width = rows.iter().map(Vec::len).max().unwrap_or(0);
    if height == 0 || width == 0 {
        return Err(err(Location::File, LoadErrorKind::NoRows));
    }
    let cells = width as u64 * height as u64;
    if cells > MAX_CELLS {
        return Err(err(
            Location::File,
            LoadErrorKind::BadSize {
                field: "width × height",
                value: cells as i64,
                reason: format!("more than {MAX_CELLS} cells"),
            },
        ));
    }
    let mut tiles = vec![None; width * height];
    for (r, row) in rows.iter().enumerate() {
        tiles[r * width..r * width + row.len()].copy_from_slice(row);
    }
    // The built-in shapes can only fail to build when `cell` is so large or small that their
    // areas overflow or underflow f32 (e.g. 1e20 or 1e-30): the cause is the cell size the
    // caller gave, not a tile they never defined, so say so.
    let set = tile_set(cell).map_err(|e| {
        err(
            Location::File,
            LoadErrorKind::Parameter(format!(
                "cell size {cell} is outside the range the built-in tiles support ({e})"
            )),
        )
    })?;
    TileMap::from_tiles(
        Arc::new(set),
        width as u32,
        height as u32,
        Vec2::ZERO,
        &tiles,
    )
    .map_err(|e| match e {
        // Only the cell size the caller chose can carry a map this small that far.
        MapError::OutOfRange { .. } => err(
            Location::File,
            LoadErrorKind::Parameter(format!("cell size {cell} is too large: {e}")),
        ),
        e => err(Location::File, e.into()),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Cell;

    #[test]
    fn unknown_character_is_named_with_line_and_column() {
        let e = parse("; comment\n#..#\n#.x#\n", "m.txt", 1.0).unwrap_err();
        assert_eq!(e.location, Location::LineColumn { line: 3, column: 3 });
        assert!(
            matches!(e.kind, LoadErrorKind::UnknownCharacter('x')),
            "{e}"
        );
        assert_eq!(
            e.to_string(),
            "m.txt:3:3: unknown tile character 'x' (expected one of `.`, space, `#`, `/`, `\\`, `=`)"
        );
    }

    #[test]
    fn empty_map_is_an_error() {
        let e = parse("; only a comment\n\n", "e.txt", 1.0).unwrap_err();
        assert!(matches!(e.kind, LoadErrorKind::NoRows), "{e}");
    }

    #[test]
    fn bad_cell_size_is_an_error() {
        assert!(matches!(
            parse("#", "c.txt", f32::NAN).unwrap_err().kind,
            LoadErrorKind::Parameter(_)
        ));
        assert!(matches!(
            parse("#", "c.txt", 0.0).unwrap_err().kind,
            LoadErrorKind::Parameter(_)
        ));
    }

    #[test]
    fn short_lines_are_padded_and_crlf_is_accepted() {
        let map = parse("#\r\n###\r\n", "p.txt", 2.0).unwrap();
        assert_eq!((map.width(), map.height()), (3, 2));
        assert_eq!(map.tile(Cell::new(1, 0)), None);
        assert_eq!(map.cell_size(), Vec2::splat(2.0));
    }
}
