//! Per-cell storage of active segments, laid out for the ray walk.
//!
//! The walk reads one byte per visited cell, its *kind* (64 KiB for a 256 × 256 map, so it
//! stays in cache), and touches a cell's segments only when the kind says they must be
//! tested. Those live in a pool of 32-byte records found through `starts` (a `u32` per
//! cell); every record of a cell's block carries the block's length, so no other per-cell
//! record is needed. Blocks come from free lists (exact sizes up to 8, powers of two above),
//! so a tile edit reallocates only the cells it changes, in O(1), and the pool never needs
//! compacting.

use glam::Vec2;

use super::SegmentFlags;
use super::link::Link;

/// Cap bit of a segment's `a` end: the surface does not continue from there into a collinear
/// or concave neighbour, so a swept circle must round it (see `continuity`).
pub(crate) const CAP_A: u8 = 1;
/// Cap bit of a segment's `b` end.
pub(crate) const CAP_B: u8 = 2;

/// `starts` entry of a cell with no active segments.
pub(crate) const NO_SEGMENTS: u32 = u32::MAX;

/// Most active segments one cell can hold (a segment's `count` is a `u16`).
pub(crate) const MAX_CELL_SEGMENTS: usize = u16::MAX as usize;

/// An active segment in world coordinates, laid out for the ray walk: `e = b − a` is
/// precomputed so the intersection needs no subtraction of end points. 32 bytes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct HotSegment {
    pub a: Vec2,
    pub e: Vec2,
    pub normal: Vec2,
    pub flags: SegmentFlags,
    /// Index of the segment in its tile's shape.
    pub source: u16,
    /// Number of active segments in this segment's cell.
    pub count: u16,
}

impl HotSegment {
    pub fn b(&self) -> Vec2 {
        self.a + self.e
    }
}

/// For each end (`a`, `b`) of an active segment, the active segment it continues into.
pub(crate) type Links = [Link; 2];

#[derive(Clone, Debug, Default)]
pub(crate) struct SegmentStore {
    /// Per cell, the pool index of its first active segment, or [`NO_SEGMENTS`].
    starts: Vec<u32>,
    /// Per cell, its shape summary (see [`KIND_GENERAL`](super::face_kind::KIND_GENERAL)): one byte, so the walk's per-step
    /// read stays in cache.
    kinds: Vec<u8>,
    hot: Vec<HotSegment>,
    links: Vec<Links>,
    /// Per active segment, which ends need a rounded cap for a swept circle (see
    /// [`CAP_A`]): set with the links.
    caps: Vec<u8>,
    /// Starts of unused blocks, by size class (see `class_of`).
    free: Vec<Vec<u32>>,
    active: usize,
}

/// Block capacity for `len` segments: exact up to 8, then the next power of two.
fn capacity_of(len: usize) -> usize {
    if len <= 8 {
        len
    } else {
        len.next_power_of_two()
    }
}

/// The block capacity a cell of `len` active segments gets (for laying out a store, see
/// [`SegmentStore::from_layout`]).
pub(crate) fn block_capacity(len: usize) -> usize {
    capacity_of(len)
}

/// Free-list index of a block capacity.
fn class_of(capacity: usize) -> usize {
    if capacity <= 8 {
        capacity
    } else {
        // 16 → 9, 32 → 10, …
        8 + capacity.trailing_zeros() as usize - 3
    }
}

impl SegmentStore {
    pub fn new(cells: usize) -> Self {
        Self {
            starts: vec![NO_SEGMENTS; cells],
            kinds: vec![0; cells],
            ..Self::default()
        }
    }

    #[inline(always)]
    pub fn starts(&self) -> &[u32] {
        &self.starts
    }

    #[inline(always)]
    pub fn kinds(&self) -> &[u8] {
        &self.kinds
    }

    #[inline(always)]
    pub fn hot(&self) -> &[HotSegment] {
        &self.hot
    }

    #[inline]
    fn range(&self, index: usize) -> std::ops::Range<usize> {
        let start = self.starts[index];
        if start == NO_SEGMENTS {
            return 0..0;
        }
        let start = start as usize;
        start..start + self.hot[start].count as usize
    }

    pub fn cell(&self, index: usize) -> &[HotSegment] {
        &self.hot[self.range(index)]
    }

    pub fn links(&self, index: usize) -> &[Links] {
        &self.links[self.range(index)]
    }

    pub fn links_mut(&mut self, index: usize) -> &mut [Links] {
        let range = self.range(index);
        &mut self.links[range]
    }

    /// The cap bits of the cell's active segments, in order.
    pub fn caps(&self, index: usize) -> &[u8] {
        &self.caps[self.range(index)]
    }

    pub fn caps_mut(&mut self, index: usize) -> &mut [u8] {
        let range = self.range(index);
        &mut self.caps[range]
    }

    /// True when cells with these segments fit: none has more than `MAX_CELL_SEGMENTS`,
    /// and new blocks for all of them keep pool indices below [`NO_SEGMENTS`] (checked
    /// before anything changes, so a refused edit leaves the map as it was).
    pub fn has_room_for(&self, cells: &[&Vec<HotSegment>]) -> bool {
        let room = (NO_SEGMENTS as usize).saturating_sub(self.hot.len());
        let needed: usize = cells.iter().map(|s| capacity_of(s.len())).sum();
        cells.iter().all(|s| s.len() <= MAX_CELL_SEGMENTS) && needed <= room
    }

    /// Total number of active segments.
    pub fn active_count(&self) -> usize {
        self.active
    }

    /// A store from its arrays, laid out as [`block_capacity`] says (cell `i`'s block at
    /// `starts[i]`, its segments' `count` set, padding up to the block's capacity), with
    /// nothing free: what a baked map loads into. The caller has checked the layout.
    pub fn from_layout(
        starts: Vec<u32>,
        kinds: Vec<u8>,
        hot: Vec<HotSegment>,
        links: Vec<Links>,
        caps: Vec<u8>,
        active: usize,
    ) -> Self {
        Self {
            starts,
            kinds,
            hot,
            links,
            caps,
            free: Vec::new(),
            active,
        }
    }

    /// Replaces the active segments of cell `index` (their `count` is set here) and its
    /// summary `kind` (see [`kind_of`](super::face_kind::kind_of)); their links are cleared and both ends capped. The caller has checked
    /// [`has_room_for`](Self::has_room_for).
    pub fn set_cell(&mut self, index: usize, segments: &[HotSegment], kind: u8) {
        self.kinds[index] = kind;
        let old = self.range(index);
        if !old.is_empty() {
            // (A store laid out by `from_cells` has no free lists yet.)
            let class = class_of(capacity_of(old.len()));
            if self.free.len() <= class {
                self.free.resize_with(class + 1, Vec::new);
            }
            self.free[class].push(old.start as u32);
        }
        self.active = self.active - old.len() + segments.len();
        if segments.is_empty() {
            self.starts[index] = NO_SEGMENTS;
            return;
        }
        let capacity = capacity_of(segments.len());
        let class = class_of(capacity);
        if self.free.len() <= class {
            self.free.resize_with(class + 1, Vec::new);
        }
        let start = match self.free[class].pop() {
            Some(start) => start as usize,
            None => {
                let start = self.hot.len();
                self.hot.resize(start + capacity, segments[0]);
                self.links.resize(start + capacity, [Link::NONE; 2]);
                self.caps.resize(start + capacity, CAP_A | CAP_B);
                start
            }
        };
        let count = segments.len() as u16;
        for (slot, s) in self.hot[start..start + segments.len()]
            .iter_mut()
            .zip(segments)
        {
            *slot = HotSegment { count, ..*s };
        }
        self.links[start..start + segments.len()].fill([Link::NONE; 2]);
        self.caps[start..start + segments.len()].fill(CAP_A | CAP_B);
        self.starts[index] = start as u32;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tiles::face_kind::KIND_GENERAL;

    fn seg(x: f32) -> HotSegment {
        HotSegment {
            a: Vec2::new(x, 0.0),
            e: Vec2::X,
            normal: Vec2::Y,
            flags: SegmentFlags::SOLID,
            source: 0,
            count: 0,
        }
    }

    #[test]
    fn freed_blocks_are_reused_and_counts_kept() {
        let mut store = SegmentStore::new(4);
        store.set_cell(0, &[seg(0.0), seg(1.0), seg(2.0)], KIND_GENERAL);
        store.set_cell(1, &[seg(3.0)], KIND_GENERAL);
        assert_eq!(store.cell(0).len(), 3);
        assert!(store.cell(0).iter().all(|s| s.count == 3));
        let pool = store.hot().len();
        store.set_cell(0, &[], 0);
        assert!(store.cell(0).is_empty());
        store.set_cell(2, &[seg(4.0), seg(5.0), seg(6.0)], KIND_GENERAL);
        assert_eq!(
            store.hot().len(),
            pool,
            "the freed block of three is reused"
        );
        assert_eq!(store.cell(2)[2].a.x, 6.0);
        assert_eq!(store.active_count(), 4);
    }
}
