//! The tiles a map was built with: what its edits are measured against.
//!
//! A game loads its level from a file and edits it while it runs (digging, building). To
//! save or roll back the map it needs only the cells that differ from the level as loaded
//! (see [`MapEdits`](crate::MapEdits)), so the map keeps, for every cell an edit has
//! touched, the tile the cell held when the map was built: the cells that differ are then
//! found among those, in O(edited cells), whatever the map's size.

use std::collections::BTreeMap;
use std::sync::OnceLock;

use super::map::EMPTY;
use super::{Cell, TileId, TileMap};

/// The tiles a map was built with, where edits changed them.
#[derive(Clone, Debug, Default)]
pub(crate) struct BaseTiles {
    /// Per cell an edit has touched (row-major index), the raw tile id it held when the map
    /// was built. Ordered, so edits are listed in row-major order.
    originals: BTreeMap<u32, u32>,
    /// The CRC-32 of the base, computed when first asked for: the base never changes.
    checksum: OnceLock<u32>,
}

impl BaseTiles {
    /// Cell `index` is edited; it held `old` before (kept only for the first edit).
    pub fn record(&mut self, index: u32, old: u32) {
        self.originals.entry(index).or_insert(old);
    }
}

/// A raw tile id as a tile.
fn tile_of(raw: u32) -> Option<TileId> {
    (raw != EMPTY).then_some(TileId(raw))
}

impl TileMap {
    /// The tile `cell` held when the map was built; `None` for an empty cell or a cell
    /// outside the map.
    #[must_use]
    pub fn base_tile(&self, cell: Cell) -> Option<TileId> {
        if cell.col >= self.width() || cell.row >= self.height() {
            return None;
        }
        let index = cell.row * self.width() + cell.col;
        match self.base.originals.get(&index) {
            Some(&raw) => tile_of(raw),
            None => tile_of(self.tiles[index as usize]),
        }
    }

    /// The cells whose tile differs from the one they held when the map was built, with
    /// their tile now, in row-major order. O(cells ever edited).
    pub(crate) fn cells_off_base(&self) -> impl Iterator<Item = (Cell, Option<TileId>)> + '_ {
        let width = self.width();
        self.base
            .originals
            .iter()
            .filter_map(move |(&index, &old)| {
                let now = self.tiles[index as usize];
                (now != old).then(|| (Cell::new(index % width, index / width), tile_of(now)))
            })
    }

    /// The cells an edit has touched since the map was built (whatever they hold now), in
    /// row-major order.
    pub(crate) fn cells_ever_edited(&self) -> impl Iterator<Item = Cell> + '_ {
        let width = self.width();
        self.base
            .originals
            .keys()
            .map(move |&index| Cell::new(index % width, index / width))
    }

    /// A CRC-32 of the map as it was built: its size, origin, cell size and tiles. Computed
    /// once, in O(cells), when first asked for.
    pub(crate) fn base_checksum(&self) -> u32 {
        *self.base.checksum.get_or_init(|| {
            let mut crc = crc32fast::Hasher::new();
            crc.update(b"tileslide map base");
            for value in [self.width(), self.height()]
                .into_iter()
                .chain(self.origin().to_array().map(f32::to_bits))
                .chain(self.cell_size().to_array().map(f32::to_bits))
            {
                crc.update(&value.to_le_bytes());
            }
            // The tiles as they are, with the edited cells' originals put back, a chunk at
            // a time.
            let mut originals = self.base.originals.iter().peekable();
            let mut chunk = Vec::with_capacity(4096);
            for (index, &now) in self.tiles.iter().enumerate() {
                let raw = match originals.peek() {
                    Some(&(&at, &old)) if at as usize == index => {
                        originals.next();
                        old
                    }
                    _ => now,
                };
                chunk.extend_from_slice(&raw.to_le_bytes());
                if chunk.len() == chunk.capacity() {
                    crc.update(&chunk);
                    chunk.clear();
                }
            }
            crc.update(&chunk);
            crc.finalize()
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::ascii::{self, TEST_ROOM};

    fn room() -> TileMap {
        ascii::parse(TEST_ROOM, "room.txt", 1.0).unwrap_or_else(|e| panic!("{e}"))
    }

    #[test]
    fn the_cells_off_base_are_the_edited_cells_that_differ_now() {
        let mut map = room();
        let before = map.base_checksum();
        let solid = Some(ascii::SOLID);
        let (a, b, c) = (Cell::new(3, 2), Cell::new(1, 1), Cell::new(5, 3));
        assert_eq!(map.base_tile(a), None);
        map.set_tile(a, solid).unwrap_or_else(|e| panic!("{e}"));
        map.set_tile(b, solid).unwrap_or_else(|e| panic!("{e}"));
        map.set_tile(c, solid).unwrap_or_else(|e| panic!("{e}"));
        // Cell c put back: edited, but as it was.
        map.clear_tile(c).unwrap_or_else(|e| panic!("{e}"));
        let off: Vec<_> = map.cells_off_base().collect();
        assert_eq!(off, [(b, solid), (a, solid)], "row-major order");
        assert_eq!(map.cells_ever_edited().collect::<Vec<_>>(), [b, a, c]);
        assert_eq!((map.base_tile(a), map.tile(a)), (None, solid));
        assert_eq!(map.base_tile(Cell::new(99, 0)), None);
        // The base is the map as built, however it is edited since.
        assert_eq!(map.base_checksum(), before);
        assert_eq!(room().base_checksum(), before);
        let mut other = room();
        other.set_tile(a, solid).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(other.base_checksum(), before, "edited before asked");
        let moved = ascii::parse(&TEST_ROOM.replace("#.", ".#"), "other.txt", 1.0)
            .unwrap_or_else(|e| panic!("{e}"));
        assert_ne!(moved.base_checksum(), before);
    }
}
