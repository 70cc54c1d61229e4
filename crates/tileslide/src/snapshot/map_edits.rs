//! A map's state as the edits of the map it was built as: what a save or a rollback keeps
//! of a map whose level the game loads from a file.

use std::iter::Peekable;

use super::SnapshotError;
use crate::tiles::{Cell, TemporarySegment, TileId, TileMap};

/// The state of a [`TileMap`] relative to the map as it was built (its *base*, the level
/// as loaded from its file): the cells whose tile differs from the base, with their tile,
/// and the temporary segments. What a save file or rollback netcode keeps of a map: the
/// game loads the level once, and [`TileMap::restore_edits`] brings the map back to any
/// saved state.
///
/// Its size grows with the cells that differ from the base, not with the map: saving
/// costs O(cells ever edited), restoring O(cells that differ between now and then), each
/// restored cell an ordinary tile edit, so everything that remembers map data (the
/// resolver's memories, navigation grids, flow fields) catches up locally from the map's
/// journal, as after any edit. Edits name their base by a checksum: restoring the edits
/// of another level is refused.
///
/// ```
/// # use tileslide::{io::ascii, Cell};
/// let level = "######\n#....#\n######";
/// let mut map = ascii::parse(level, "level.txt", 1.0)?;
/// map.clear_tile(Cell::new(2, 0))?; // dug
/// let saved = map.edits();
/// assert_eq!(saved.tiles(), [(Cell::new(2, 0), None)]);
/// map.clear_tile(Cell::new(3, 0))?;
/// map.set_tile(Cell::new(2, 0), Some(ascii::SOLID))?; // built back
/// map.restore_edits(&saved)?;
/// assert_eq!(map.tile(Cell::new(2, 0)), None);
/// assert_eq!(map.tile(Cell::new(3, 0)), Some(ascii::SOLID));
/// // Another level of the same size is another base.
/// let mut other = ascii::parse("######\n#.#..#\n######", "other.txt", 1.0)?;
/// assert!(other.restore_edits(&saved).is_err());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// With the `serde` feature it is `Serialize` and `Deserialize`; what is read is checked
/// (cells inside the map, in order and each once, temporary segments as
/// [`TileMap::add_temporary`] checks them), and [`TileMap::restore_edits`] checks the rest
/// against the map.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(try_from = "read::MapEditsData")
)]
pub struct MapEdits {
    width: u32,
    height: u32,
    /// The CRC-32 of the base.
    base: u32,
    /// Cells off the base, in row-major order, each once.
    tiles: Vec<(Cell, Option<TileId>)>,
    temporaries: Vec<TemporarySegment>,
}

impl MapEdits {
    /// The cells whose tile differs from the map as built, with their tile (`None`:
    /// empty), in row-major order.
    #[must_use]
    pub fn tiles(&self) -> &[(Cell, Option<TileId>)] {
        &self.tiles
    }

    /// The temporary segments, in the order they were added.
    #[must_use]
    pub fn temporaries(&self) -> &[TemporarySegment] {
        &self.temporaries
    }
}

impl TileMap {
    /// The map's state as edits of the map as it was built: the cells whose tile differs
    /// and the temporary segments (see [`MapEdits`]). O(cells ever edited), plus, the first
    /// time it or [`restore_edits`](Self::restore_edits) is called on a map, one pass over
    /// every cell to checksum the base.
    #[must_use]
    pub fn edits(&self) -> MapEdits {
        MapEdits {
            width: self.width(),
            height: self.height(),
            base: self.base_checksum(),
            tiles: self.cells_off_base().collect(),
            temporaries: self.temporaries().to_vec(),
        }
    }

    /// Brings the map to the state `edits` saved: every cell as it was then (the cells
    /// edited since put back, each an ordinary tile edit), and its temporary segments.
    /// Everything that remembers map data catches up from the map's journal, locally, as
    /// after any edit.
    ///
    /// # Errors
    /// [`SnapshotError::OtherMapSize`] or [`SnapshotError::OtherBase`] for edits of another
    /// map, [`SnapshotError::UnknownTile`] for a tile the tile set lacks,
    /// [`SnapshotError::NoChange`] for an edit that puts the tile the map was built with:
    /// the map is then unchanged. [`SnapshotError::Map`] with [`MapError::TooManySegments`](crate::MapError::TooManySegments) if the map
    /// cannot hold the segments (about 2³² of them): the edits made are then undone.
    pub fn restore_edits(&mut self, edits: &MapEdits) -> Result<(), SnapshotError> {
        let (map_width, map_height) = (self.width(), self.height());
        if (edits.width, edits.height) != (map_width, map_height) {
            return Err(SnapshotError::OtherMapSize {
                width: edits.width,
                height: edits.height,
                map_width,
                map_height,
            });
        }
        let map = self.base_checksum();
        if edits.base != map {
            return Err(SnapshotError::OtherBase {
                edits: edits.base,
                map,
            });
        }
        for &(cell, id) in &edits.tiles {
            if let Some(id) = id
                && self.tile_set().shape(id).is_none()
            {
                return Err(SnapshotError::UnknownTile { cell, id });
            }
            if id == self.base_tile(cell) {
                return Err(SnapshotError::NoChange { cell });
            }
        }
        // Every cell that differs from the base now or in the edits: the union of two
        // row-major lists.
        let wanted = Union {
            now: self.cells_ever_edited().peekable(),
            then: edits.tiles.iter().peekable(),
        }
        .filter_map(|(cell, then)| {
            let target = then.unwrap_or_else(|| self.base_tile(cell));
            (self.tile(cell) != target).then_some((cell, target))
        })
        .collect::<Vec<_>>();
        let mut done = Vec::with_capacity(wanted.len());
        for (cell, target) in wanted {
            let before = self.tile(cell);
            if let Err(e) = self.set_tile(cell, target) {
                // Back as it was: each of these cells held its tile before, and the map
                // had room for it.
                for &(cell, before) in done.iter().rev() {
                    let _ = self.set_tile(cell, before);
                }
                return Err(e.into());
            }
            done.push((cell, before));
        }
        self.restore_temporaries(&edits.temporaries);
        Ok(())
    }
}

/// The cells of two row-major lists, each once, with the tile the second gives it: the
/// cells edited now and the cells off the base then.
struct Union<'a, A: Iterator<Item = Cell>> {
    now: Peekable<A>,
    then: Peekable<std::slice::Iter<'a, (Cell, Option<TileId>)>>,
}

impl<A: Iterator<Item = Cell>> Iterator for Union<'_, A> {
    /// A cell, and `Some(tile)` when the second list has it.
    type Item = (Cell, Option<Option<TileId>>);

    fn next(&mut self) -> Option<Self::Item> {
        let key = |c: &Cell| (c.row, c.col);
        match (self.now.peek(), self.then.peek()) {
            (None, None) => None,
            (Some(_), None) => self.now.next().map(|c| (c, None)),
            (Some(a), Some((b, _))) if key(a) < key(b) => self.now.next().map(|c| (c, None)),
            (Some(a), Some((b, _))) if key(a) == key(b) => {
                self.now.next();
                self.then.next().map(|&(c, t)| (c, Some(t)))
            }
            _ => self.then.next().map(|&(c, t)| (c, Some(t))),
        }
    }
}

/// Reading [`MapEdits`]: what is read, and its checks.
#[cfg(feature = "serde")]
mod read {
    use glam::Vec2;

    use super::{MapEdits, SnapshotError};
    use crate::tiles::{
        Cell, MAX_CELLS, MAX_TEMPORARIES, MapError, TemporaryError, TemporarySegment, TileId,
    };

    /// How far a saved normal's squared length may be from 1: a few rounding steps of the
    /// normalisation the map applies, far less than any normal that was not normalised.
    const UNIT_SLACK: f32 = 1e-5;

    /// What a [`MapEdits`] is read as, before it is checked.
    #[derive(serde::Deserialize)]
    pub(super) struct MapEditsData {
        width: u32,
        height: u32,
        base: u32,
        tiles: Vec<(Cell, Option<TileId>)>,
        temporaries: Vec<TemporarySegment>,
    }

    impl TryFrom<MapEditsData> for MapEdits {
        type Error = SnapshotError;

        fn try_from(data: MapEditsData) -> Result<Self, SnapshotError> {
            let (width, height) = (data.width, data.height);
            if width == 0 || height == 0 {
                return Err(MapError::EmptySize { width, height }.into());
            }
            if u64::from(width) * u64::from(height) > MAX_CELLS {
                return Err(MapError::TooLarge { width, height }.into());
            }
            let mut last = None;
            for (index, &(cell, _)) in data.tiles.iter().enumerate() {
                if cell.col >= width || cell.row >= height {
                    return Err(SnapshotError::EditOutsideMap {
                        index,
                        cell,
                        width,
                        height,
                    });
                }
                let at = u64::from(cell.row) * u64::from(width) + u64::from(cell.col);
                if last.is_some_and(|last| at <= last) {
                    return Err(SnapshotError::Unsorted {
                        what: "tile edits",
                        index,
                    });
                }
                last = Some(at);
            }
            if let Some(t) = data.temporaries.get(MAX_TEMPORARIES) {
                return Err(SnapshotError::Temporary {
                    index: MAX_TEMPORARIES,
                    error: TemporaryError::TooMany(t.owner),
                });
            }
            for (index, t) in data.temporaries.iter().enumerate() {
                check_temporary(index, t)?;
            }
            Ok(Self {
                width,
                height,
                base: data.base,
                tiles: data.tiles,
                temporaries: data.temporaries,
            })
        }
    }

    /// A saved temporary segment: checked as [`TileMap::add_temporary`](crate::TileMap::add_temporary) checks one, with the
    /// normal it was saved with (normalising it again could move its last bit).
    fn check_temporary(index: usize, t: &TemporarySegment) -> Result<(), SnapshotError> {
        t.validated()
            .map_err(|error| SnapshotError::Temporary { index, error })?;
        if (t.normal.length_squared() - 1.0).abs() > UNIT_SLACK {
            let Vec2 { x, y } = t.normal;
            return Err(SnapshotError::NotUnitNormal { index, x, y });
        }
        Ok(())
    }
}
