//! What changed in the map since the last resolve, for the memories the resolver keeps from
//! one step to the next: the walls kept near each circle and the settled bodies.
//!
//! Both memories are statements about the walls within some disc, and an edit changes walls
//! only near where it happens. So a memory whose disc is far from every change still holds:
//! digging one square of a dungeon, or moving one platform, wakes the bodies near it and
//! renews their wall lists, not everyone's.
//!
//! - **A tile edit** recomputes its cell and the four next to it (seam culling) and relinks
//!   the segment ends within two cells (caps; see `TileMap::set_tile`), so walls change only
//!   inside the cell's box grown by two cells. The map's edit journal
//!   (`TileMap::changes_since`) names the cells.
//! - **A temporary segment** changes walls where it was and where it is. Temporaries are
//!   compared entry by entry in list order, the order every query lists them in (equal
//!   contacts go to the first listed), so an entry that moved, appeared, vanished or holds
//!   another segment than before changes the boxes of both its old and its new segment.
//!   A game that clears and re-submits the same temporaries every frame changes nothing.
//!
//! Anything the journal cannot account for (another map, a clone edited apart, more edits
//! than it keeps, more changes than [`MAX_REGIONS`]) changes everything: the resolver
//! forgets its memories and carries on with the map it is given.
//!
//! The changed boxes are marked on a bitmap of the map's cells, so asking whether a disc's
//! box touches any of them reads the few cells the box covers, however many changed: every
//! kept list and every body asks once a step.

use glam::Vec2;

use crate::geometry::{Aabb, Segment};
use crate::tiles::{MapRevision, SegmentFlags, TileMap};

/// Most changed boxes tracked one by one; past this, every memory is dropped.
const MAX_REGIONS: usize = 1024;

/// How far past its cell a tile edit changes walls, in cells: two (the relinked ends),
/// plus a quarter for rounding in the segments' corners.
const EDIT_REACH: f32 = 2.25;

/// How the map changed since the last resolve.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum MapChange {
    /// Not at all: every memory holds.
    Unchanged,
    /// Only inside some boxes ([`MapWatch::touches`]): memories of discs that touch none of
    /// them hold.
    Local,
    /// In a way the watch cannot place: no memory holds.
    Everything,
}

/// A temporary segment as a wall: what the resolver sweeps against.
type TemporaryWall = (Segment, Vec2, SegmentFlags);

/// The map as the last resolve saw it.
#[derive(Clone, Debug, Default)]
pub(super) struct MapWatch {
    /// The map's revision; `None` before the first resolve.
    seen: Option<MapRevision>,
    temporaries: Vec<TemporaryWall>,
    /// The boxes outside which nothing changed, when the change is local.
    regions: Vec<Aabb>,
    /// The cells those boxes touch.
    marks: CellMarks,
}

impl MapWatch {
    /// How `map` changed since the last call, which it then remembers.
    pub fn update(&mut self, map: &TileMap) -> MapChange {
        self.regions.clear();
        let Some(seen) = self.seen.replace(map.revision()) else {
            self.remember_temporaries(map);
            return MapChange::Everything;
        };
        let mut everything = false;
        if !map.tiles_at(&seen) {
            match map.changes_since(&seen) {
                Ok(cells) => {
                    let reach = map.cell_size() * EDIT_REACH;
                    for cell in cells {
                        let rect = map.cell_rect(cell);
                        self.regions
                            .push(Aabb::from_corners(rect.min - reach, rect.max + reach));
                        if self.regions.len() > MAX_REGIONS {
                            everything = true;
                            break;
                        }
                    }
                }
                Err(_) => everything = true,
            }
        }
        if !map.temporaries_at(&seen) {
            let old = std::mem::take(&mut self.temporaries);
            self.remember_temporaries(map);
            let longest = old.len().max(self.temporaries.len());
            for i in 0..longest {
                let (was, is) = (old.get(i), self.temporaries.get(i));
                if was == is {
                    continue;
                }
                let boxes = [was, is].into_iter().flatten().map(|(s, ..)| s.aabb());
                self.regions.extend(boxes);
                if self.regions.len() > MAX_REGIONS {
                    everything = true;
                    break;
                }
            }
        }
        self.marks.clear();
        if everything {
            self.regions.clear();
            MapChange::Everything
        } else if self.regions.is_empty() {
            MapChange::Unchanged
        } else {
            self.marks.fit(map);
            for region in &self.regions {
                self.marks.mark(region);
            }
            MapChange::Local
        }
    }

    /// The boxes a [`MapChange::Local`] change happened in.
    #[cfg(test)]
    pub fn regions(&self) -> &[Aabb] {
        &self.regions
    }

    /// Whether `area` may touch a box the last [`MapChange::Local`] change happened in:
    /// true whenever it does (and sometimes when it only shares a cell with one).
    pub fn touches(&self, area: &Aabb) -> bool {
        self.marks.any(area)
    }

    fn remember_temporaries(&mut self, map: &TileMap) {
        self.temporaries.clear();
        self.temporaries.extend(
            map.temporaries()
                .iter()
                .map(|t| (t.segment, t.normal, t.flags)),
        );
    }
}

/// A bitmap of a map's cells: which cells a set of boxes touch.
///
/// A box is taken to touch the cells from the one holding its min corner to the one
/// holding its max corner, clamped to the map: points outside the map count as in the
/// nearest cell of its border. The cell of a point is a monotone function of the point
/// (rounded subtraction, multiplication by a positive number, clamp and truncation all keep
/// order), so two boxes that share a point both touch that point's cell: [`Self::any`]
/// never misses a box that [`Aabb::overlaps`] would find.
#[derive(Clone, Debug, Default)]
struct CellMarks {
    origin: Vec2,
    inv_cell: Vec2,
    /// The last column and row, as floats (rounded up past 2²⁴ cells a side, so the
    /// indices are clamped again as integers).
    last: Vec2,
    width: usize,
    height: usize,
    bits: Vec<u64>,
    /// The words of `bits` with a bit set, to clear them.
    set: Vec<usize>,
    /// A box holding every marked box: most asks are far from every change.
    bounds: Option<Aabb>,
}

impl CellMarks {
    /// Fits the bitmap to `map`'s cells (all clear).
    fn fit(&mut self, map: &TileMap) {
        let (width, height) = (map.width() as usize, map.height() as usize);
        self.origin = map.origin();
        self.inv_cell = map.cell_size().recip();
        self.last = Vec2::new(width as f32 - 1.0, height as f32 - 1.0);
        if (width, height) != (self.width, self.height) {
            (self.width, self.height) = (width, height);
            self.bits.clear();
            self.bits.resize((width * height).div_ceil(64), 0);
        }
    }

    /// The columns and rows of the cells `b` touches.
    fn cells(&self, b: &Aabb) -> (usize, usize, usize, usize) {
        let cell = |p: Vec2| {
            // Clamped to the map first, so truncation is the floor: no call to libm's
            // `floorf` (x86-64 has no rounding instruction before SSE4.1). (`clamp` takes
            // NaN to 0.)
            let at = ((p - self.origin) * self.inv_cell).clamp(Vec2::ZERO, self.last);
            let col = (at.x as u32 as usize).min(self.width - 1);
            (col, (at.y as u32 as usize).min(self.height - 1))
        };
        let ((c0, r0), (c1, r1)) = (cell(b.min), cell(b.max));
        (c0, r0, c1, r1)
    }

    fn mark(&mut self, b: &Aabb) {
        self.bounds = Some(self.bounds.map_or(*b, |bounds| bounds.union(b)));
        let (c0, r0, c1, r1) = self.cells(b);
        for row in r0..=r1 {
            for col in c0..=c1 {
                let i = row * self.width + col;
                if self.bits[i / 64] == 0 {
                    self.set.push(i / 64);
                }
                self.bits[i / 64] |= 1 << (i % 64);
            }
        }
    }

    fn any(&self, b: &Aabb) -> bool {
        if !self.bounds.is_some_and(|bounds| bounds.overlaps(b)) {
            return false;
        }
        let (c0, r0, c1, r1) = self.cells(b);
        (r0..=r1).any(|row| {
            // The row's cells `c0..=c1` are consecutive bits: a mask on each word they
            // span (most often one).
            let (first, last) = (row * self.width + c0, row * self.width + c1);
            (first / 64..=last / 64).any(|w| {
                let from = if w == first / 64 { first % 64 } else { 0 };
                let to = if w == last / 64 { last % 64 } else { 63 };
                let mask = (u64::MAX >> (63 - to)) & (u64::MAX << from);
                self.bits[w] & mask != 0
            })
        })
    }

    fn clear(&mut self) {
        for &w in &self.set {
            self.bits[w] = 0;
        }
        self.set.clear();
        self.bounds = None;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::ascii::{self, TEST_ROOM};
    use crate::{Cell, Owner, TemporarySegment};
    use proptest::prelude::*;

    proptest! {
        /// The cell bitmap finds every box that overlaps a marked one, inside the map or
        /// outside it, whatever the map's origin and cell size: a map of 100 × 20 cells
        /// (rows that cross the bitmap's words) of up to three units a side; marked boxes of
        /// up to 40 units, asked ones of up to three (points too).
        #[test]
        fn cell_marks_never_miss_an_overlap(
            origin in (-50.0f32..50.0, -50.0f32..50.0),
            cell in (0.25f32..3.0, 0.25f32..3.0),
            marked in prop::collection::vec(boxes(40.0), 1..6),
            asked in prop::collection::vec(boxes(3.0), 1..200),
        ) {
            let row = ".".repeat(100);
            let text = [row.as_str(); 20].join("\n");
            let map = ascii::parse(&text, "marks.txt", 1.0).unwrap_or_else(|e| panic!("{e}"));
            let origin = Vec2::new(origin.0, origin.1);
            let at = |b: &Aabb| Aabb::from_corners(b.min + origin, b.max + origin);
            let mut marks = CellMarks::default();
            marks.fit(&map);
            marks.origin = origin;
            marks.inv_cell = Vec2::new(cell.0, cell.1).recip();
            for b in &marked {
                marks.mark(&at(b));
            }
            for b in &asked {
                if marked.iter().any(|m| at(m).overlaps(&at(b))) {
                    prop_assert!(marks.any(&at(b)), "{:?} overlaps a marked box", at(b));
                }
            }
            marks.clear();
            prop_assert!(marks.bits.iter().all(|&w| w == 0) && !marks.any(&at(&marked[0])));
        }
    }

    /// A marked cell is found by every box whose row span covers it, and by no other:
    /// spans that start, end or pass at every bit of the bitmap's words. (A second mark in
    /// another row, at the other end, makes the bounding box wide, so the bitmap decides.)
    #[test]
    fn a_marked_cell_is_found_by_exactly_the_spans_that_cover_it() {
        let row = ".".repeat(100);
        let text = [row.as_str(); 3].join("\n");
        let map = ascii::parse(&text, "marks.txt", 1.0).unwrap_or_else(|e| panic!("{e}"));
        let mut marks = CellMarks::default();
        marks.fit(&map);
        let centre = |col: usize, row: usize| Vec2::new(col as f32 + 0.5, row as f32 + 0.5);
        for (col, row) in (0..100).flat_map(|c| (0..3).map(move |r| (c, r))) {
            for (c, r) in [(col, row), (99 - col, (row + 2) % 3)] {
                marks.mark(&Aabb::from_corners(centre(c, r), centre(c, r)));
            }
            for (from, to) in (0..100).flat_map(|a| (a..100.min(a + 70)).map(move |b| (a, b))) {
                let span = Aabb::from_corners(centre(from, row), centre(to, row));
                assert_eq!(
                    marks.any(&span),
                    (from..=to).contains(&col),
                    "cell ({col}, {row}), span {from}..={to}"
                );
            }
            let above = Aabb::from_corners(centre(0, (row + 1) % 3), centre(99, (row + 1) % 3));
            assert!(!marks.any(&above), "cell ({col}, {row}): another row");
            marks.clear();
        }
    }

    /// Boxes (offsets from the map's origin) from 10 units before the map to 10 past its
    /// largest extent, of up to `side` units a side, a fifth of them points.
    fn boxes(side: f32) -> impl Strategy<Value = Aabb> {
        (
            -10.0f32..310.0,
            -10.0f32..70.0,
            0.0..side,
            0.0..side,
            0u8..5,
        )
            .prop_map(|(x, y, w, h, point)| {
                let size = if point == 0 {
                    Vec2::ZERO
                } else {
                    Vec2::new(w, h)
                };
                Aabb::from_corners(Vec2::new(x, y), Vec2::new(x, y) + size)
            })
    }

    fn room() -> TileMap {
        ascii::parse(TEST_ROOM, "room.txt", 1.0).unwrap_or_else(|e| panic!("{e}"))
    }

    fn platform(x: f32) -> TemporarySegment {
        TemporarySegment {
            segment: Segment::new(Vec2::new(x, 2.0), Vec2::new(x + 1.0, 2.0)),
            normal: Vec2::Y,
            flags: SegmentFlags::SOLID,
            owner: Owner(7),
            velocity: Vec2::ZERO,
        }
    }

    fn dig(map: &mut TileMap, cell: Cell) {
        // (An edit that changes nothing is no edit: the cell must be a wall.)
        let floor = ascii::tile_for_char('.').unwrap_or_else(|e| panic!("{e}: no tile for '.'"));
        map.set_tile(cell, floor).unwrap_or_else(|e| panic!("{e}"));
    }

    #[test]
    fn edits_are_placed_within_two_cells_of_their_cell() {
        let mut map = room();
        let mut watch = MapWatch::default();
        assert_eq!(watch.update(&map), MapChange::Everything, "first look");
        assert_eq!(watch.update(&map), MapChange::Unchanged);
        dig(&mut map, Cell::new(0, 3));
        assert_eq!(watch.update(&map), MapChange::Local);
        let [region] = watch.regions() else {
            panic!("one edit, one region: {:?}", watch.regions());
        };
        // Cell (0, 3) spans x 0..1, y 3..4; two and a quarter cells around it.
        assert_eq!(region.min, Vec2::new(-2.25, 0.75));
        assert_eq!(region.max, Vec2::new(3.25, 6.25));
        // (Asked by cell: a box that only shares a cell with the region may count as
        // touching it too.)
        let near = Aabb::from_corners(Vec2::new(3.0, 5.0), Vec2::new(3.5, 5.5));
        let far = Aabb::from_corners(Vec2::new(4.0, 5.0), Vec2::new(4.5, 5.5));
        assert!(watch.touches(&near) && !watch.touches(&far));
        assert_eq!(watch.update(&map), MapChange::Unchanged, "seen already");
    }

    #[test]
    fn resubmitted_temporaries_change_nothing_and_moved_ones_change_both_places() {
        let mut map = room();
        let mut watch = MapWatch::default();
        map.add_temporary(platform(2.0))
            .unwrap_or_else(|e| panic!("{e}"));
        watch.update(&map);
        // Cleared and submitted again, the same: nothing changed.
        map.clear_temporaries();
        map.add_temporary(platform(2.0))
            .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(watch.update(&map), MapChange::Unchanged);
        // Moved: where it was and where it is.
        map.clear_temporaries();
        map.add_temporary(platform(4.0))
            .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(watch.update(&map), MapChange::Local);
        let boxes: Vec<_> = watch.regions().iter().map(|r| (r.min, r.max)).collect();
        assert_eq!(
            boxes,
            [
                (Vec2::new(2.0, 2.0), Vec2::new(3.0, 2.0)),
                (Vec2::new(4.0, 2.0), Vec2::new(5.0, 2.0))
            ]
        );
        // Gone: where it was.
        map.clear_temporaries();
        assert_eq!(watch.update(&map), MapChange::Local);
        assert_eq!(watch.regions().len(), 1);
    }

    #[test]
    fn another_map_or_too_many_edits_change_everything() {
        let mut map = room();
        let mut watch = MapWatch::default();
        watch.update(&map);
        assert_eq!(watch.update(&room()), MapChange::Everything, "another map");
        watch.update(&map);
        // One more edit than the watch places one by one: a cell filled and dug in turn.
        for k in 0..=MAX_REGIONS {
            let tile = ascii::tile_for_char(if k % 2 == 0 { '#' } else { '.' });
            let tile = tile.unwrap_or_else(|e| panic!("{e}"));
            map.set_tile(Cell::new(3, 2), tile)
                .unwrap_or_else(|e| panic!("{e}"));
        }
        assert_eq!(watch.update(&map), MapChange::Everything);
        assert!(watch.regions().is_empty());
    }
}
