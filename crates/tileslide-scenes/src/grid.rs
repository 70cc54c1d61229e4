//! The solid/empty cell grid that every standard scene is built on.

use crate::Fnv1a;

/// A `width`×`height` grid of solid/empty cells, row-major (index `y*width + x`);
/// cell `(x, y)` covers `[x, x+1] × [y, y+1]`.
///
/// The fields are public so that other crates can convert the grid into their
/// own map types; `solid` is expected to hold `width * height` entries. The
/// queries never panic when it does not: a missing entry reads as empty.
///
/// ```
/// use tileslide_scenes::SolidGrid;
/// let grid = SolidGrid { width: 2, height: 1, solid: vec![true, false] };
/// assert!(grid.is_solid(0, 0));
/// assert!(!grid.is_solid(1, 0));
/// assert!(!grid.is_solid(-1, 0)); // outside the grid is empty
/// assert_eq!(grid.solid_count(), 1);
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SolidGrid {
    /// Number of columns.
    pub width: usize,
    /// Number of rows.
    pub height: usize,
    /// `solid[y * width + x]` is `true` when cell `(x, y)` is solid.
    pub solid: Vec<bool>,
}

impl SolidGrid {
    /// A grid drawn as text, one string per row, row 0 first: `#` is solid, anything else
    /// empty. The width is the first row's length; shorter rows are padded with empty
    /// cells, longer ones cut.
    ///
    /// ```
    /// # use tileslide_scenes::SolidGrid;
    /// let grid = SolidGrid::from_rows(&["###", "#.#", "###"]);
    /// assert_eq!((grid.width, grid.height, grid.solid_count()), (3, 3, 8));
    /// ```
    #[must_use]
    pub fn from_rows(rows: &[&str]) -> Self {
        let width = rows.first().map_or(0, |r| r.len());
        let solid = rows
            .iter()
            .flat_map(|r| {
                let bytes = r.as_bytes();
                (0..width).map(move |x| bytes.get(x) == Some(&b'#'))
            })
            .collect();
        Self {
            width,
            height: rows.len(),
            solid,
        }
    }

    /// The grid as an ASCII map (`#` solid, `.` empty, a line a row, row 0 first), the text
    /// [`from_rows`](Self::from_rows) and tileslide's ASCII loader read: how a binding that
    /// takes maps as text gets the standard scenes.
    ///
    /// ```
    /// # use tileslide_scenes::SolidGrid;
    /// let grid = SolidGrid::from_rows(&["###", "#.#"]);
    /// assert_eq!(grid.to_ascii(), "###\n#.#\n");
    /// ```
    #[must_use]
    pub fn to_ascii(&self) -> String {
        let mut text = String::with_capacity((self.width + 1) * self.height);
        for row in self.solid.chunks(self.width.max(1)).take(self.height) {
            text.extend(row.iter().map(|&s| if s { '#' } else { '.' }));
            text.push('\n');
        }
        text
    }

    /// Whether cell `(x, y)` is solid; cells outside the grid are empty (`false`).
    #[must_use]
    pub fn is_solid(&self, x: i64, y: i64) -> bool {
        match (usize::try_from(x), usize::try_from(y)) {
            (Ok(x), Ok(y)) if x < self.width && y < self.height => {
                self.solid.get(y * self.width + x).copied().unwrap_or(false)
            }
            _ => false,
        }
    }

    /// Number of solid cells.
    #[must_use]
    pub fn solid_count(&self) -> usize {
        self.solid.iter().filter(|&&s| s).count()
    }

    /// FNV-1a 64-bit hash of the row-major cell bytes (1 = solid, 0 = empty),
    /// the golden value BENCHMARKS.md publishes for each map.
    #[must_use]
    pub fn fingerprint(&self) -> u64 {
        let mut hash = Fnv1a::new();
        for &s in &self.solid {
            hash.write_u8(u8::from(s));
        }
        hash.finish()
    }

    /// [`fingerprint`](Self::fingerprint) as 16 lowercase hex digits, the form
    /// BENCHMARKS.md prints (e.g. `"a36c9fd56f2ba422"` for dungeon256).
    #[must_use]
    pub fn fingerprint_hex(&self) -> String {
        format!("{:016x}", self.fingerprint())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fnv1a_of_known_bytes() {
        // FNV-1a 64 of the empty input is the offset basis; of the single byte 0x00
        // it is 0xaf63bd4c8601b7df (from the FNV reference test vectors).
        let empty = SolidGrid {
            width: 0,
            height: 0,
            solid: vec![],
        };
        assert_eq!(empty.fingerprint(), Fnv1a::OFFSET_BASIS);
        let one = SolidGrid {
            width: 1,
            height: 1,
            solid: vec![false],
        };
        assert_eq!(one.fingerprint_hex(), "af63bd4c8601b7df");
        let solid = SolidGrid {
            width: 1,
            height: 1,
            solid: vec![true],
        };
        assert_eq!(solid.fingerprint_hex(), "af63bc4c8601b62c");
    }

    #[test]
    fn is_solid_reads_row_major_and_treats_outside_as_empty() {
        // Row 0: "#.", row 1: ".."
        let grid = SolidGrid {
            width: 2,
            height: 2,
            solid: vec![true, false, false, false],
        };
        assert!(grid.is_solid(0, 0));
        assert!(!grid.is_solid(1, 0));
        assert!(!grid.is_solid(0, 1));
        for (x, y) in [(-1, 0), (0, -1), (2, 0), (0, 2), (i64::MIN, i64::MAX)] {
            assert!(!grid.is_solid(x, y));
        }
    }

    #[test]
    fn short_cell_vector_reads_as_empty_instead_of_panicking() {
        let grid = SolidGrid {
            width: 4,
            height: 4,
            solid: vec![true],
        };
        assert!(grid.is_solid(0, 0));
        assert!(!grid.is_solid(3, 3));
    }
}
