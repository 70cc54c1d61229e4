//! A continuity link packed into four bytes: which of the 3 × 3 cells around a segment's own
//! cell holds the segment its end continues into, and that segment's index there.
//!
//! Links always point at a neighbour (an end point lies in or on the boundary of its own
//! cell, so the segment touching it does too), so the relative form needs 4 bits for the
//! cell and 16 for the index (a cell holds at most `MAX_CELL_SEGMENTS`). Four bytes instead
//! of a 16-byte `Option<SegmentRef>` keep the store small, and a baked map stores the very
//! same number, so loading a link is reading it and checking it is in range.

use super::{Cell, SegmentRef};

/// A packed link, or [`Link::NONE`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Link(u32);

impl Link {
    /// No continuation.
    pub const NONE: Link = Link(u32::MAX);

    /// The link to segment `index` of the cell at offset (`dc`, `dr`), each in −1..=1.
    pub fn new(dc: i64, dr: i64, index: usize) -> Self {
        debug_assert!((-1..=1).contains(&dc) && (-1..=1).contains(&dr));
        debug_assert!(index <= usize::from(u16::MAX));
        let neighbour = ((dr + 1) * 3 + (dc + 1)) as u32;
        Link(neighbour << 16 | index as u32)
    }

    /// The link stored as `raw` (see [`raw`](Self::raw)), or `None` if `raw` is neither a
    /// link nor [`Link::NONE`].
    pub fn from_raw(raw: u32) -> Option<Self> {
        (raw == u32::MAX || raw >> 16 < 9).then_some(Link(raw))
    }

    /// The number a baked map stores.
    pub fn raw(self) -> u32 {
        self.0
    }

    /// The linked cell's offset from the segment's own cell and the segment's index there,
    /// or `None` for [`Link::NONE`].
    pub fn target(self) -> Option<(i64, i64, u32)> {
        if self == Self::NONE {
            return None;
        }
        let neighbour = i64::from(self.0 >> 16);
        Some((neighbour % 3 - 1, neighbour / 3 - 1, self.0 & 0xFFFF))
    }

    /// The segment this link names, for a segment in `cell` (`None` for [`Link::NONE`]).
    pub fn resolve(self, cell: Cell) -> Option<SegmentRef> {
        let (dc, dr, index) = self.target()?;
        Some(SegmentRef {
            cell: Cell::new(
                (i64::from(cell.col) + dc) as u32,
                (i64::from(cell.row) + dr) as u32,
            ),
            index,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_link_names_its_neighbour_and_index() {
        for dr in -1..=1 {
            for dc in -1..=1 {
                for index in [0usize, 1, 7, 65_534] {
                    let link = Link::new(dc, dr, index);
                    assert_eq!(Link::from_raw(link.raw()), Some(link));
                    let r = link.resolve(Cell::new(10, 20)).unwrap();
                    assert_eq!(r.cell, Cell::new((10 + dc) as u32, (20 + dr) as u32));
                    assert_eq!(r.index as usize, index);
                }
            }
        }
        assert_eq!(Link::NONE.resolve(Cell::new(0, 0)), None);
        assert_eq!(Link::from_raw(u32::MAX), Some(Link::NONE));
        assert_eq!(Link::from_raw(9 << 16), None, "there are only nine cells");
    }
}
