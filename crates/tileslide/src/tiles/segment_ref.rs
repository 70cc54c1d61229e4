use super::Cell;

/// An active segment of the map, named by its cell and its index among the cell's active
/// segments. Only meaningful until that cell or a neighbour is edited: an edit renumbers
/// the cell's segments, and the same reference may then name another one.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct SegmentRef {
    /// The cell that holds the segment.
    pub cell: Cell,
    /// Index among the cell's active segments.
    pub index: u32,
}
