use std::collections::BTreeMap;
use std::sync::Arc;

use glam::Vec2;

use super::SegmentRef;
use super::base::BaseTiles;
use super::continuity::link_cell;
use super::culling::{CellSide, active_segments};
use super::face_kind::{canonical_faces, kind_of};
use super::journal::Journal;
use super::store::{HotSegment, Links, SegmentStore};
use super::{Cell, MapError, SegmentFlags, TemporarySegment, TileId, TileSet, TileShape};
use crate::geometry::{Aabb, Segment, in_range};

/// The most cells a map may have (2²⁶, e.g. 8192 × 8192).
pub const MAX_CELLS: u64 = 1 << 26;

/// An active segment of a map: what queries test, after seam culling, in world coordinates.
///
/// Every active segment runs with its normal on the right of `a → b`
/// (`(b − a).perp_dot(normal) <= 0`), whatever direction its tile shape gave it: with y up,
/// solids are walked counter-clockwise. A resolver telling convex from concave corners can
/// rely on that.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ActiveSegment {
    /// The segment in world coordinates. A piece of a partly hidden tile segment is shorter
    /// than the tile segment it comes from.
    pub segment: Segment,
    /// Outward unit normal.
    pub normal: Vec2,
    /// What the segment is.
    pub flags: SegmentFlags,
    /// The tile it comes from.
    pub tile: TileId,
    /// Index of the segment in the tile's shape.
    pub source: u32,
    /// For each end (`segment.a`, `segment.b`), the active segment the surface continues into
    /// there, if any: the one sharing that end point whose normal is closest to this one's.
    pub continues: [Option<SegmentRef>; 2],
}

/// A grid of tiles with the active segments of every cell.
///
/// Cell `(col, row)` covers `origin + [col·w, (col+1)·w) × [row·h, (row+1)·h)` where `w × h`
/// is the tile set's tile size. The map does not know which way is up: loaders decide
/// whether row 0 is the top (ASCII, Tiled) or the bottom (Replica Island).
///
/// ```
/// # use std::sync::Arc;
/// # use tileslide::{Cell, TileId, TileMap, TileSet, TileShape, Vec2};
/// let mut set = TileSet::new(Vec2::ONE)?;
/// set.insert(TileId(1), TileShape::polygon(&[Vec2::ZERO, Vec2::X, Vec2::ONE, Vec2::Y])?)?;
/// let mut map = TileMap::new(Arc::new(set), 4, 3, Vec2::ZERO)?;
/// map.set_tile(Cell::new(1, 2), Some(TileId(1)))?;
/// map.set_tile(Cell::new(2, 2), Some(TileId(1)))?;
/// // Two squares side by side: the shared seam is hidden, 6 of 8 edges stay active.
/// assert_eq!(map.placed_segment_count(), 8);
/// assert_eq!(map.active_segment_count(), 6);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug)]
pub struct TileMap {
    tile_set: Arc<TileSet>,
    width: u32,
    height: u32,
    origin: Vec2,
    cell_size: Vec2,
    inv_cell_size: Vec2,
    /// Tile id per cell, row-major; `EMPTY` for none.
    pub(super) tiles: Vec<u32>,
    placed: usize,
    pub(crate) store: SegmentStore,
    pub(crate) temporaries: Vec<TemporarySegment>,
    /// Its revisions and latest tile edits, for everything that remembers map data (see
    /// [`TileMap::changes_since`]).
    pub(super) journal: Journal,
    /// The tiles the map was built with where edits changed them (see
    /// [`MapEdits`](crate::MapEdits)).
    pub(super) base: BaseTiles,
    /// Reused buffers for the active segments of the cells an edit recomputes (the cell
    /// and its four neighbours), so an edit does not allocate once warmed up.
    scratch: [Vec<HotSegment>; 5],
}

pub(super) const EMPTY: u32 = u32::MAX;

/// The number of cells of a `width × height` map at `origin`, or why it cannot be.
fn checked_size(width: u32, height: u32, origin: Vec2, cell_size: Vec2) -> Result<u64, MapError> {
    if width == 0 || height == 0 {
        return Err(MapError::EmptySize { width, height });
    }
    let cells = u64::from(width) * u64::from(height);
    if cells > MAX_CELLS {
        return Err(MapError::TooLarge { width, height });
    }
    if !origin.is_finite() {
        return Err(MapError::NonFiniteOrigin {
            x: origin.x,
            y: origin.y,
        });
    }
    let far = origin + Vec2::new(width as f32, height as f32) * cell_size;
    if !in_range(origin) || !in_range(far) {
        return Err(MapError::OutOfRange {
            width,
            height,
            x: origin.x,
            y: origin.y,
            far_x: far.x,
            far_y: far.y,
        });
    }
    Ok(cells)
}

/// The number of tile-shape segments `tiles` (raw ids, `u32::MAX` for empty) place, or the
/// index of the first tile `tile_set` lacks. A tile is looked up only where it differs from
/// the cell before (maps are mostly runs of one tile), so a million cells cost a few
/// thousand lookups, not a million.
pub(crate) fn placed_segments(tile_set: &TileSet, tiles: &[u32]) -> Result<usize, usize> {
    let mut placed = 0;
    let (mut last, mut last_count) = (EMPTY, 0);
    for (k, &raw) in tiles.iter().enumerate() {
        if raw != last {
            last_count = if raw == EMPTY {
                0
            } else {
                tile_set.shape(TileId(raw)).ok_or(k)?.segments().len()
            };
            last = raw;
        }
        placed += last_count;
    }
    Ok(placed)
}

impl TileMap {
    /// An empty map of `width × height` cells of the tile set's tile size, cell (0, 0)'s
    /// corner at `origin`.
    pub fn new(
        tile_set: Arc<TileSet>,
        width: u32,
        height: u32,
        origin: Vec2,
    ) -> Result<Self, MapError> {
        let cells = checked_size(width, height, origin, tile_set.tile_size())? as usize;
        Ok(Self::from_parts(
            tile_set,
            width,
            height,
            origin,
            vec![EMPTY; cells],
            SegmentStore::new(cells),
            0,
        ))
    }

    /// The map of these parts, with nothing checked or computed.
    fn from_parts(
        tile_set: Arc<TileSet>,
        width: u32,
        height: u32,
        origin: Vec2,
        tiles: Vec<u32>,
        store: SegmentStore,
        placed: usize,
    ) -> Self {
        let cell_size = tile_set.tile_size();
        Self {
            tile_set,
            width,
            height,
            origin,
            cell_size,
            inv_cell_size: cell_size.recip(),
            tiles,
            placed,
            store,
            temporaries: Vec::new(),
            journal: Journal::default(),
            base: BaseTiles::default(),
            scratch: Default::default(),
        }
    }

    /// A map filled from `tiles`, one entry per cell in row-major order (`row · width + col`).
    pub fn from_tiles(
        tile_set: Arc<TileSet>,
        width: u32,
        height: u32,
        origin: Vec2,
        tiles: &[Option<TileId>],
    ) -> Result<Self, MapError> {
        let mut map = Self::new(tile_set, width, height, origin)?;
        if tiles.len() != map.tiles.len() {
            return Err(MapError::WrongTileCount {
                expected: map.tiles.len(),
                got: tiles.len(),
            });
        }
        for (slot, id) in map.tiles.iter_mut().zip(tiles) {
            if let Some(id) = id {
                if map.tile_set.shape(*id).is_none() {
                    return Err(MapError::UnknownTile { id: *id });
                }
                *slot = id.0;
            }
        }
        map.rebuild()?;
        Ok(map)
    }

    /// A map of `tiles` (raw ids, row-major, `u32::MAX` for empty) whose culled segments
    /// and links are already known (`store`, as a baked map holds them): nothing is
    /// recomputed. The size is checked here; the caller has checked the tiles against the
    /// set (`placed` is what [`placed_segments`] returned for them) and that `store`
    /// matches them.
    pub(crate) fn from_store(
        tile_set: Arc<TileSet>,
        width: u32,
        height: u32,
        origin: Vec2,
        tiles: Vec<u32>,
        store: SegmentStore,
        placed: usize,
    ) -> Result<Self, MapError> {
        let cells = checked_size(width, height, origin, tile_set.tile_size())? as usize;
        if tiles.len() != cells {
            return Err(MapError::WrongTileCount {
                expected: cells,
                got: tiles.len(),
            });
        }
        Ok(Self::from_parts(
            tile_set, width, height, origin, tiles, store, placed,
        ))
    }

    /// Recomputes every cell's active segments and links from the tiles.
    fn rebuild(&mut self) -> Result<(), MapError> {
        let mut out = std::mem::take(&mut self.scratch[0]);
        for row in 0..self.height {
            for col in 0..self.width {
                let kind = self.compute_cell(col, row, &mut out);
                if !self.store.has_room_for(&[&out]) {
                    return Err(MapError::TooManySegments);
                }
                self.store
                    .set_cell((row * self.width + col) as usize, &out, kind);
            }
        }
        self.scratch[0] = out;
        for row in 0..self.height {
            for col in 0..self.width {
                link_cell(
                    &mut self.store,
                    self.width,
                    self.height,
                    self.cell_size,
                    col,
                    row,
                );
            }
        }
        // The tiles were checked against the set as they were placed.
        self.placed = placed_segments(&self.tile_set, &self.tiles).unwrap_or(0);
        Ok(())
    }

    /// Puts tile `id` (or nothing) in `cell`, updating seam culling for the cell and its four
    /// neighbours and end-point links around them: O(1), whatever the map's size.
    pub fn set_tile(&mut self, cell: Cell, id: Option<TileId>) -> Result<(), MapError> {
        let index = self.index_of(cell)?;
        let raw = match id {
            Some(id) if self.tile_set.shape(id).is_none() => {
                return Err(MapError::UnknownTile { id });
            }
            Some(id) => id.0,
            None => EMPTY,
        };
        let old = self.tiles[index];
        if old == raw {
            return Ok(());
        }
        self.tiles[index] = raw;
        // Recompute the cell and its four neighbours into the scratch buffers first, and
        // apply them only if the store can take them all: a refused edit changes nothing.
        let (col, row) = (cell.col as i64, cell.row as i64);
        let mut scratch = std::mem::take(&mut self.scratch);
        let mut changed = [None; 5];
        for (k, (dc, dr)) in [(0, 0), (-1, 0), (1, 0), (0, -1), (0, 1)]
            .into_iter()
            .enumerate()
        {
            if let Some((c, r)) = self.in_bounds(col + dc, row + dr) {
                let kind = self.compute_cell(c, r, &mut scratch[k]);
                changed[k] = Some(((r * self.width + c) as usize, kind));
            }
        }
        let outs: Vec<&Vec<HotSegment>> = (0..5)
            .filter(|&k| changed[k].is_some())
            .map(|k| &scratch[k])
            .collect();
        if !self.store.has_room_for(&outs) {
            self.tiles[index] = old;
            self.scratch = scratch;
            return Err(MapError::TooManySegments);
        }
        for (k, update) in changed.into_iter().enumerate() {
            if let Some((i, kind)) = update {
                self.store.set_cell(i, &scratch[k], kind);
            }
        }
        self.scratch = scratch;
        self.journal.record_edit(cell);
        self.base.record(index as u32, old);
        let count = |map: &Self, t: u32| map.shape_of_raw(t).map_or(0, |s| s.segments().len());
        self.placed = self.placed - count(self, old) + count(self, raw);
        // Links read the active segments of the 3×3 block around a cell, and active segments
        // changed in the plus-shaped block above: relink everything within two cells.
        for dr in -2..=2 {
            for dc in -2..=2 {
                if let Some((c, r)) = self.in_bounds(col + dc, row + dr) {
                    link_cell(
                        &mut self.store,
                        self.width,
                        self.height,
                        self.cell_size,
                        c,
                        r,
                    );
                }
            }
        }
        Ok(())
    }

    /// Removes the tile from `cell` (digging).
    pub fn clear_tile(&mut self, cell: Cell) -> Result<(), MapError> {
        self.set_tile(cell, None)
    }

    /// The active segments of cell (`col`, `row`) from its tile and its neighbours', into
    /// `out`, in the store's form; returns the cell's kind.
    fn compute_cell(&self, col: u32, row: u32, out: &mut Vec<HotSegment>) -> u8 {
        out.clear();
        let index = (row * self.width + col) as usize;
        let base = self.cell_corner(Cell::new(col, row));
        if let Some(shape) = self.shape_of_raw(self.tiles[index]) {
            let neighbour = |side: CellSide| -> Option<&TileShape> {
                let (dc, dr) = side.neighbour_offset();
                let (c, r) = self.in_bounds(col as i64 + dc, row as i64 + dr)?;
                self.shape_of_raw(self.tiles[(r * self.width + c) as usize])
            };
            active_segments(shape, self.cell_size, base, neighbour, out);
        }
        let kind = kind_of(out, base, self.cell_size);
        canonical_faces(out, kind, base, self.cell_size);
        kind
    }

    fn shape_of_raw(&self, raw: u32) -> Option<&TileShape> {
        if raw == EMPTY {
            None
        } else {
            self.tile_set.shape(TileId(raw))
        }
    }

    fn in_bounds(&self, col: i64, row: i64) -> Option<(u32, u32)> {
        (col >= 0 && row >= 0 && col < self.width as i64 && row < self.height as i64)
            .then_some((col as u32, row as u32))
    }

    fn index_of(&self, cell: Cell) -> Result<usize, MapError> {
        if cell.col < self.width && cell.row < self.height {
            Ok((cell.row * self.width + cell.col) as usize)
        } else {
            Err(MapError::CellOutOfBounds {
                cell,
                width: self.width,
                height: self.height,
            })
        }
    }

    /// The tile in the cell at row-major `index` (which must be in the map).
    #[inline(always)]
    pub(crate) fn tile_at_index(&self, index: usize) -> Option<TileId> {
        let raw = self.tiles[index];
        (raw != EMPTY).then_some(TileId(raw))
    }

    /// The tile in `cell`, or `None` for an empty cell or a cell outside the map.
    #[must_use]
    pub fn tile(&self, cell: Cell) -> Option<TileId> {
        let index = self.index_of(cell).ok()?;
        let raw = self.tiles[index];
        (raw != EMPTY).then_some(TileId(raw))
    }

    /// The tile set the map draws its shapes from.
    #[must_use]
    pub fn tile_set(&self) -> &Arc<TileSet> {
        &self.tile_set
    }

    /// Number of columns.
    #[must_use]
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Number of rows.
    #[must_use]
    pub fn height(&self) -> u32 {
        self.height
    }

    /// Width and height of a cell (the tile set's tile size).
    #[must_use]
    pub fn cell_size(&self) -> Vec2 {
        self.cell_size
    }

    /// World position of cell (0, 0)'s corner.
    #[must_use]
    pub fn origin(&self) -> Vec2 {
        self.origin
    }

    pub(crate) fn inv_cell_size(&self) -> Vec2 {
        self.inv_cell_size
    }

    /// The world rectangle the whole map covers.
    #[must_use]
    pub fn bounds(&self) -> Aabb {
        let size = Vec2::new(self.width as f32, self.height as f32) * self.cell_size;
        Aabb::from_corners(self.origin, self.origin + size)
    }

    /// World position of a cell's corner with the smallest coordinates.
    #[must_use]
    pub fn cell_corner(&self, cell: Cell) -> Vec2 {
        self.origin + Vec2::new(cell.col as f32, cell.row as f32) * self.cell_size
    }

    /// The closed world rectangle of a cell.
    #[must_use]
    pub fn cell_rect(&self, cell: Cell) -> Aabb {
        let corner = self.cell_corner(cell);
        Aabb::from_corners(corner, corner + self.cell_size)
    }

    /// The cell that contains world point `p` (cells are half-open), or `None` outside the
    /// map or for a non-finite point. Consistent with [`cell_corner`](Self::cell_corner):
    /// a point exactly on a cell's corner is in that cell, whatever the rounding of the
    /// cell size.
    #[must_use]
    pub fn cell_at(&self, p: Vec2) -> Option<Cell> {
        let g = ((p - self.origin) * self.inv_cell_size).floor();
        if !g.is_finite() {
            return None;
        }
        // `floor` of the scaled point can land one cell off next to a boundary: correct it
        // against the corners `cell_corner` computes, which is what the cells are.
        let corner = |c: f32, r: f32| self.origin + Vec2::new(c, r) * self.cell_size;
        let fix = |g: f32, at: &dyn Fn(f32) -> f32, p: f32| {
            if p < at(g) {
                g - 1.0
            } else if p >= at(g + 1.0) {
                g + 1.0
            } else {
                g
            }
        };
        let col = fix(g.x, &|c| corner(c, 0.0).x, p.x);
        let row = fix(g.y, &|r| corner(0.0, r).y, p.y);
        if col < 0.0 || row < 0.0 || col >= self.width as f32 || row >= self.height as f32 {
            return None;
        }
        Some(Cell::new(col as u32, row as u32))
    }

    /// Sum of the tile segments of every placed tile, before seam culling.
    #[must_use]
    pub fn placed_segment_count(&self) -> usize {
        self.placed
    }

    /// Number of active segments after seam culling (pieces of partly hidden segments count
    /// one each).
    #[must_use]
    pub fn active_segment_count(&self) -> usize {
        self.store.active_count()
    }

    /// How many cells hold each tile id, by increasing id.
    #[must_use]
    pub fn tile_counts(&self) -> BTreeMap<TileId, usize> {
        let mut counts = BTreeMap::new();
        for &raw in &self.tiles {
            if raw != EMPTY {
                *counts.entry(TileId(raw)).or_insert(0) += 1;
            }
        }
        counts
    }

    /// The active segments of `cell` (none outside the map).
    pub fn active_segments(&self, cell: Cell) -> impl ExactSizeIterator<Item = ActiveSegment> + '_ {
        let index = self.index_of(cell).ok();
        let (hot, links): (&[HotSegment], &[Links]) = match index {
            Some(i) => (self.store.cell(i), self.store.links(i)),
            None => (&[], &[]),
        };
        let tile = index.map_or(TileId(EMPTY), |i| TileId(self.tiles[i]));
        hot.iter().zip(links).map(move |(h, l)| ActiveSegment {
            segment: Segment::new(h.a, h.b()),
            normal: h.normal,
            flags: h.flags,
            tile,
            source: h.source.into(),
            continues: [l[0].resolve(cell), l[1].resolve(cell)],
        })
    }

    /// The active segment `r` names, or `None` if its cell is outside the map or has fewer
    /// segments. A reference is only meaningful until its cell or a neighbour is edited:
    /// after an edit the same index may name another segment of the cell.
    #[must_use]
    pub fn active_segment(&self, r: SegmentRef) -> Option<ActiveSegment> {
        self.active_segments(r.cell).nth(r.index as usize)
    }
}
