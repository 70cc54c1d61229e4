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

use super::{Cell, SegmentFlags};

/// `starts` entry of a cell with no active segments.
pub(crate) const NO_SEGMENTS: u32 = u32::MAX;

/// A cell's shape summary (`kinds`), read by the ray walk at every step: 0 for no active
/// segments, [`KIND_GENERAL`] for segments that must be tested one by one, or otherwise a
/// set of `FACE_*` bits: the cell's active segments are exactly those whole cell edges, each
/// facing straight out of the cell and flagged exactly [`SegmentFlags::SOLID`] (the
/// boundary of solid squares, by far the most common tile). A front-face ray entering such
/// a cell hits it exactly when it enters through one of those faces, so the walk decides
/// from this byte alone, without reading the segments.
pub(crate) const KIND_GENERAL: u8 = 0x80;
/// The edge `x = x0` (normal −x).
pub(crate) const FACE_MIN_X: u8 = 1;
/// The edge `x = x0 + w` (normal +x).
pub(crate) const FACE_MAX_X: u8 = 2;
/// The edge `y = y0` (normal −y).
pub(crate) const FACE_MIN_Y: u8 = 4;
/// The edge `y = y0 + h` (normal +y).
pub(crate) const FACE_MAX_Y: u8 = 8;

/// The outward normal of a whole-edge face (a `FACE_*` bit).
pub(crate) fn face_normal(face: u8) -> Vec2 {
    match face {
        FACE_MIN_X => Vec2::NEG_X,
        FACE_MAX_X => Vec2::X,
        FACE_MIN_Y => Vec2::NEG_Y,
        _ => Vec2::Y,
    }
}

/// The stored form of a whole-edge face of the cell with corner `base` and size `size`:
/// start point and `e = b − a`, running with the normal on the right like every active
/// segment. The store keeps face cells' segments exactly so (see `canonical_faces`) and the
/// ray walk recomputes them from the cell alone, with the same operations, so both agree
/// bit for bit.
#[inline(always)]
pub(crate) fn face_segment(base: Vec2, size: Vec2, face: u8) -> (Vec2, Vec2) {
    let (la, lb) = match face {
        FACE_MIN_X => (Vec2::new(0.0, size.y), Vec2::ZERO),
        FACE_MAX_X => (Vec2::new(size.x, 0.0), size),
        FACE_MIN_Y => (Vec2::ZERO, Vec2::new(size.x, 0.0)),
        _ => (size, Vec2::new(0.0, size.y)),
    };
    let (a, b) = (base + la, base + lb);
    (a, b - a)
}

/// Index of `face` among a face cell's segments, which are stored in `FACE_*` bit order.
#[inline(always)]
pub(crate) fn face_index(kind: u8, face: u8) -> u32 {
    // A table: x86-64's baseline has no popcount instruction.
    const BITS: [u8; 16] = [0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4];
    BITS[usize::from(kind & (face - 1) & 0x0f)].into()
}

/// Puts a face cell's segments (`kind` from [`kind_of`]) in the stored form: `FACE_*` bit
/// order, each as [`face_segment`] gives it.
pub(crate) fn canonical_faces(segments: &mut [HotSegment], kind: u8, base: Vec2, size: Vec2) {
    if kind == 0 || kind == KIND_GENERAL {
        return;
    }
    segments.sort_by_key(|s| face_bit(s.normal));
    for s in segments.iter_mut() {
        let (a, e) = face_segment(base, size, face_bit(s.normal));
        s.a = a;
        s.e = e;
    }
}

fn face_bit(normal: Vec2) -> u8 {
    if normal == Vec2::NEG_X {
        FACE_MIN_X
    } else if normal == Vec2::X {
        FACE_MAX_X
    } else if normal == Vec2::NEG_Y {
        FACE_MIN_Y
    } else {
        FACE_MAX_Y
    }
}

/// The `kinds` byte for a cell with corner `base` and size `size` holding `segments`.
pub(crate) fn kind_of(segments: &[HotSegment], base: Vec2, size: Vec2) -> u8 {
    if segments.is_empty() {
        return 0;
    }
    let (x0, y0) = (base.x, base.y);
    let (x1, y1) = (base.x + size.x, base.y + size.y);
    let faces = [
        (
            FACE_MIN_X,
            Vec2::new(x0, y0),
            Vec2::new(x0, y1),
            Vec2::NEG_X,
        ),
        (FACE_MAX_X, Vec2::new(x1, y0), Vec2::new(x1, y1), Vec2::X),
        (
            FACE_MIN_Y,
            Vec2::new(x0, y0),
            Vec2::new(x1, y0),
            Vec2::NEG_Y,
        ),
        (FACE_MAX_Y, Vec2::new(x0, y1), Vec2::new(x1, y1), Vec2::Y),
    ];
    let mut kind = 0;
    for s in segments {
        let (a, b) = (s.a, s.b());
        let face = faces.iter().find(|(_, p, q, n)| {
            s.normal == *n
                && s.flags == SegmentFlags::SOLID
                && ((a == *p && b == *q) || (a == *q && b == *p))
        });
        match face {
            Some((bit, ..)) if kind & bit == 0 => kind |= bit,
            _ => return KIND_GENERAL,
        }
    }
    kind
}

/// Most active segments one cell can hold (a segment's `count` is a `u16`).
const MAX_CELL_SEGMENTS: usize = u16::MAX as usize;

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

/// An active segment of the map, named by its cell and its index among the cell's active
/// segments. Only meaningful until that cell or a neighbour is edited: an edit renumbers
/// the cell's segments, and the same reference may then name another one.
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
    /// Per cell, the pool index of its first active segment, or [`NO_SEGMENTS`].
    starts: Vec<u32>,
    /// Per cell, its shape summary (see [`KIND_GENERAL`]): one byte, so the walk's per-step
    /// read stays in cache.
    kinds: Vec<u8>,
    hot: Vec<HotSegment>,
    links: Vec<Links>,
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

    /// Replaces the active segments of cell `index` (their `count` is set here) and its
    /// summary `kind` (see [`kind_of`]); their links are cleared. The caller has checked
    /// [`has_room_for`](Self::has_room_for).
    pub fn set_cell(&mut self, index: usize, segments: &[HotSegment], kind: u8) {
        self.kinds[index] = kind;
        let old = self.range(index);
        if !old.is_empty() {
            self.free[class_of(capacity_of(old.len()))].push(old.start as u32);
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
                self.links.resize(start + capacity, [None; 2]);
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
        self.links[start..start + segments.len()].fill([None; 2]);
        self.starts[index] = start as u32;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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

    #[test]
    fn whole_solid_cell_edges_are_summarised_as_faces() {
        let base = Vec2::new(3.0, 5.0);
        let edge = |a: Vec2, b: Vec2, normal: Vec2| HotSegment {
            a: base + a,
            e: b - a,
            normal,
            flags: SegmentFlags::SOLID,
            source: 0,
            count: 0,
        };
        let left = edge(Vec2::new(0.0, 1.0), Vec2::new(0.0, 0.0), Vec2::NEG_X);
        let top = edge(Vec2::new(1.0, 1.0), Vec2::new(0.0, 1.0), Vec2::Y);
        assert_eq!(
            kind_of(&[left, top], base, Vec2::ONE),
            FACE_MIN_X | FACE_MAX_Y
        );
        assert_eq!(kind_of(&[], base, Vec2::ONE), 0);
        // A one-way edge, a half edge or a slanted normal needs the general test.
        let one_way = HotSegment {
            flags: SegmentFlags::ONE_WAY,
            ..top
        };
        assert_eq!(kind_of(&[left, one_way], base, Vec2::ONE), KIND_GENERAL);
        let half = HotSegment {
            e: Vec2::new(0.0, -0.5),
            ..left
        };
        assert_eq!(kind_of(&[half], base, Vec2::ONE), KIND_GENERAL);
        let slanted = HotSegment {
            normal: Vec2::new(-0.6, 0.8),
            ..left
        };
        assert_eq!(kind_of(&[slanted], base, Vec2::ONE), KIND_GENERAL);
        assert_eq!(kind_of(&[left, left], base, Vec2::ONE), KIND_GENERAL);
    }
}
