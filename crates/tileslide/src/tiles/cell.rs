use std::fmt;

/// A cell of a [`TileMap`](crate::TileMap): column and row. Cell `(col, row)` covers
/// `[col·w, (col+1)·w) × [row·h, (row+1)·h)` relative to the map's origin.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Cell {
    /// Column, counted from the map's origin along x.
    pub col: u32,
    /// Row, counted from the map's origin along y.
    pub row: u32,
}

impl Cell {
    /// The cell at `col`, `row`.
    #[must_use]
    pub const fn new(col: u32, row: u32) -> Self {
        Self { col, row }
    }
}

impl fmt::Display for Cell {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "({}, {})", self.col, self.row)
    }
}

/// A tile id: the key of a tile shape in a [`TileSet`](crate::TileSet).
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[cfg_attr(feature = "serde", serde(transparent))]
pub struct TileId(pub u32);

impl fmt::Display for TileId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.0)
    }
}
