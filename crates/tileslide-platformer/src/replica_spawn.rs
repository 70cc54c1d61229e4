//! The player spawn of a Replica Island level: the first cell of its object layer (type 2)
//! holding object 0, read from the level file (see the data's FORMAT.md). The core loader
//! reads only the collision layer.

use tileslide::Cell;

/// Layer header: type, texture index, scroll speed; then the tile map's signature, width
/// and height.
const LAYER_HEADER: usize = 1 + 1 + 4 + 1 + 4 + 4;

/// The spawn cell (world row: row 0 at the bottom), or `None` when the level has no object
/// layer, no player spawn, or is cut short.
#[must_use]
pub fn player_spawn(bytes: &[u8]) -> Option<Cell> {
    let layers = usize::try_from(*bytes.get(1)? as i8).ok()?;
    let mut at = 3;
    for _ in 0..layers {
        let header = bytes.get(at..at + LAYER_HEADER)?;
        let kind = header[0] as i8;
        let width = usize::try_from(le_i32(&header[7..11])?).ok()?;
        let height = usize::try_from(le_i32(&header[11..15])?).ok()?;
        let cells = width.checked_mul(height)?;
        let start = at + LAYER_HEADER;
        let data = bytes.get(start..start.checked_add(cells)?)?;
        if kind == 2 {
            let index = data.iter().position(|&b| b == 0)?;
            let (col, file_row) = (index % width, index / width);
            return Some(Cell::new(
                u32::try_from(col).ok()?,
                u32::try_from(height - 1 - file_row).ok()?,
            ));
        }
        at = start + cells;
    }
    None
}

fn le_i32(b: &[u8]) -> Option<i32> {
    Some(i32::from_le_bytes(b.try_into().ok()?))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A level of one `kind` layer of `w × h` cells.
    fn level(kind: u8, w: i32, h: i32, cells: &[u8]) -> Vec<u8> {
        let mut b = vec![96, 1, 0, kind, 0, 0, 0, 0, 0, 42];
        b.extend_from_slice(&w.to_le_bytes());
        b.extend_from_slice(&h.to_le_bytes());
        b.extend_from_slice(cells);
        b
    }

    #[test]
    fn spawn_row_counts_from_the_bottom() {
        // Top row first in the file: object 0 in the top row of 2 is world row 1.
        let bytes = level(2, 3, 2, &[0xff, 0, 0xff, 0xff, 0xff, 0xff]);
        assert_eq!(player_spawn(&bytes), Some(Cell::new(1, 1)));
    }

    #[test]
    fn cut_short_or_without_objects_is_none() {
        let bytes = level(2, 3, 2, &[0xff, 0, 0xff]);
        assert_eq!(player_spawn(&bytes), None);
        assert_eq!(player_spawn(&level(1, 1, 1, &[0])), None);
        assert_eq!(player_spawn(&level(2, -1, 1, &[0])), None);
        assert_eq!(player_spawn(&[]), None);
    }
}
