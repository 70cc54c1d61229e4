//! Per-cell storage of active segments: a pool of fixed-size blocks with one free list per
//! power-of-two size, so a tile edit reallocates only the cells it changes, in O(1), and the
//! ray walk reads one `Slot` per visited cell.

use glam::Vec2;

use super::{Cell, SegmentFlags};

/// Where a cell's active segments live in the pool.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Slot {
    pub start: u32,
    pub len: u32,
}

/// An active segment in world coordinates, laid out for the ray walk: `e = b − a` is
/// precomputed so the intersection needs no subtraction of end points.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct HotSegment {
    pub a: Vec2,
    pub e: Vec2,
    pub normal: Vec2,
    pub flags: SegmentFlags,
    /// Index of the segment in its tile's shape.
    pub source: u32,
}

impl HotSegment {
    pub fn b(&self) -> Vec2 {
        self.a + self.e
    }
}

/// An active segment of the map, named by its cell and its index among the cell's active
/// segments. Valid until that cell or a neighbour is edited.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct SegmentRef {
    /// The cell that holds the segment.
    pub cell: Cell,
    /// Index among the cell's active segments.
    pub index: u32,
}

/// For each end (`a`, `b`) of an active segment, the active segment it continues into.
pub(crate) type Links = [Option<SegmentRef>; 2];

#[derive(Clone, Debug, Default)]
pub(crate) struct SegmentStore {
    slots: Vec<Slot>,
    hot: Vec<HotSegment>,
    links: Vec<Links>,
    /// `free[k]`: starts of unused blocks of `1 << k` entries.
    free: Vec<Vec<u32>>,
    active: usize,
}

fn class_of(len: usize) -> usize {
    len.next_power_of_two().trailing_zeros() as usize
}

impl SegmentStore {
    pub fn new(cells: usize) -> Self {
        Self {
            slots: vec![Slot::default(); cells],
            ..Self::default()
        }
    }

    #[inline(always)]
    pub fn slots(&self) -> &[Slot] {
        &self.slots
    }

    #[inline(always)]
    pub fn hot(&self) -> &[HotSegment] {
        &self.hot
    }

    pub fn cell(&self, index: usize) -> &[HotSegment] {
        let s = self.slots[index];
        &self.hot[s.start as usize..(s.start + s.len) as usize]
    }

    pub fn links(&self, index: usize) -> &[Links] {
        let s = self.slots[index];
        &self.links[s.start as usize..(s.start + s.len) as usize]
    }

    pub fn links_mut(&mut self, index: usize) -> &mut [Links] {
        let s = self.slots[index];
        &mut self.links[s.start as usize..(s.start + s.len) as usize]
    }

    /// Total number of active segments.
    pub fn active_count(&self) -> usize {
        self.active
    }

    /// Replaces the active segments of cell `index`; their links are cleared.
    pub fn set_cell(&mut self, index: usize, segments: &[HotSegment]) {
        let old = self.slots[index];
        if old.len > 0 {
            let class = class_of(old.len as usize);
            self.free[class].push(old.start);
        }
        self.active = self.active - old.len as usize + segments.len();
        if segments.is_empty() {
            self.slots[index] = Slot::default();
            return;
        }
        let class = class_of(segments.len());
        if self.free.len() <= class {
            self.free.resize_with(class + 1, Vec::new);
        }
        let start = match self.free[class].pop() {
            Some(start) => start as usize,
            None => {
                let start = self.hot.len();
                let cap = 1usize << class;
                let filler = segments[0];
                self.hot.resize(start + cap, filler);
                self.links.resize(start + cap, [None; 2]);
                start
            }
        };
        self.hot[start..start + segments.len()].copy_from_slice(segments);
        self.links[start..start + segments.len()].fill([None; 2]);
        self.slots[index] = Slot {
            start: start as u32,
            len: segments.len() as u32,
        };
    }
}
