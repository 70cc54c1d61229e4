//! The uniform grid: every box filed under the cell of its `min` corner, cells at least as
//! large as the largest box, so a box can only overlap boxes filed in its own cell or the
//! eight around it.

use glam::{Vec2, Vec4};

use super::{Candidates, extent, lower, upper};
use crate::geometry::Aabb;

/// Most grid cells the uniform grid allocates; beyond it, its cells grow.
const MAX_GRID_CELLS: usize = 1 << 22;

/// The uniform grid's buffers, kept between calls.
#[derive(Clone, Debug, Default)]
pub(super) struct GridPairs {
    /// Per cell, the start of its run in `candidates` (prefix sums); then the fill cursors
    /// of the counting sort.
    starts: Vec<u32>,
    fill: Vec<u32>,
    /// The boxes in cell order, and the cell of each.
    candidates: Candidates,
    cells_sorted: Vec<u32>,
    /// The order to visit the boxes in (the last call's cell order), and for each box in
    /// that order, its cell and its [`upper`] form.
    visit: Vec<u32>,
    cells: Vec<u32>,
    staged: Vec<Vec4>,
    /// The scan on many threads.
    #[cfg(feature = "parallel")]
    parts: super::Parts,
}

impl GridPairs {
    /// Appends every overlapping pair of `boxes` to `pairs` (see
    /// [`PairFinder::find`](super::PairFinder::find)).
    pub(super) fn find(&mut self, boxes: &[Aabb], pairs: &mut Vec<(u32, u32)>) {
        let Some((lo, hi, largest)) = extent(boxes) else {
            return;
        };
        // Cells at least as large as the largest box, and about ten cells per box: bodies
        // gather in rooms and crowds, so with fewer cells a box meets many it does not
        // touch (measured on the crowd scene: about one cell per box is 10% slower at
        // 10,000 bodies), and with many more, clearing and summing the cells dominates.
        let span = hi - lo;
        let per_box = (span.x.max(largest) * span.y.max(largest) / boxes.len() as f32).sqrt();
        // Larger than the largest box by more than a box's corners can round to: a corner's
        // cell coordinate `(p − lo) · inv` is off by a few units in its last place (up to
        // 2⁻¹⁰ of a cell for the 4,097 cells a side can have), and a box exactly one cell
        // tall could then span three rows and miss a box two rows from its own.
        let mut size = (largest * (1.0 + 1.0 / 256.0))
            .max(0.3 * per_box)
            .max(span.max_element() / 4096.0)
            .max(f32::MIN_POSITIVE);
        let dims = |size: f32| ((span.x / size) as usize + 1, (span.y / size) as usize + 1);
        while dims(size).0.saturating_mul(dims(size).1) > MAX_GRID_CELLS {
            size *= 2.0;
        }
        let (w, h) = dims(size);
        let inv = 1.0 / size;
        // One always-empty column right of the grid and one row below it: then the cell
        // right of a box's cell, and the three below it, are each a single run of cell
        // numbers that never wraps into boxes of another row.
        let stride = w + 1;
        let last = Vec2::new((w - 1) as f32, (h - 1) as f32);
        let cell_of = |p: Vec2| {
            let c = ((p - lo) * inv).min(last);
            // Through `u32`: a saturating f32 → u64 cast costs a branch on x86-64.
            c.y as u32 as usize * stride + c.x as u32 as usize
        };
        // Counting sort by cell: count into `starts[cell + 1]`, running sums, then place.
        // Boxes are visited in the cell order of the last call (they move little between
        // calls), so counting and placing walk the cells nearly in order instead of
        // jumping around them (measured on 100,000 scattered boxes: the whole search 1.25×
        // faster than visiting them by index).
        self.starts.clear();
        self.starts.resize((h + 1) * stride + 1, 0);
        if self.visit.len() != boxes.len() {
            self.visit.clear();
            self.visit.extend(0..boxes.len() as u32);
        }
        self.cells.resize(boxes.len(), 0);
        self.staged.resize(boxes.len(), Vec4::ZERO);
        for ((&i, cell), staged) in self.visit.iter().zip(&mut self.cells).zip(&mut self.staged) {
            let b = &boxes[i as usize];
            let c = cell_of(b.min);
            *cell = c as u32;
            *staged = upper(b);
            self.starts[c + 1] += 1;
        }
        // A running total, not `starts[i] += starts[i - 1]`: that reloads what it just
        // stored, a chain of store-to-load latencies (measured: 7× slower).
        let mut total = 0;
        for start in &mut self.starts {
            total += *start;
            *start = total;
        }
        // The boxes themselves, copied in cell order: the scan below then reads two
        // contiguous runs per box instead of jumping around the caller's list (measured
        // on 100,000 scattered boxes: the whole search 1.8× faster).
        self.candidates.reset(boxes.len());
        self.cells_sorted.resize(boxes.len(), 0);
        self.fill.clear();
        self.fill
            .extend_from_slice(&self.starts[..self.starts.len() - 1]);
        for ((&cell, &staged), &i) in self.cells.iter().zip(&self.staged).zip(&self.visit) {
            let slot = &mut self.fill[cell as usize];
            self.candidates.set(*slot as usize, staged, i);
            self.cells_sorted[*slot as usize] = cell;
            *slot += 1;
        }
        // Each pair once: a box meets the later boxes of its own cell and all boxes of the
        // "forward" neighbours: the cell to the right (together with the rest of its own
        // cell, one run) and the three cells below (another run).
        let (starts, candidates) = (&self.starts, &self.candidates);
        let cells_sorted = &self.cells_sorted;
        let scan = |run: std::ops::Range<usize>, pairs: &mut Vec<(u32, u32)>| {
            let mut n = pairs.len();
            for (p, &cell) in run.clone().zip(&cells_sorted[run]) {
                let cell = cell as usize;
                let (lower, id) = (lower(candidates.uppers[p]), candidates.ids[p]);
                let beside = p + 1..starts[cell + 2] as usize;
                let below = starts[cell + stride - 1] as usize..starts[cell + stride + 2] as usize;
                candidates.emit(lower, id, beside, pairs, &mut n);
                candidates.emit(lower, id, below, pairs, &mut n);
            }
            pairs.truncate(n);
        };
        let whole = 0..boxes.len();
        #[cfg(feature = "parallel")]
        if super::Parts::worth(boxes.len()) {
            // Any box may start a run.
            self.parts.cut(boxes.len(), whole.clone());
            self.parts.scan(pairs, scan);
        } else {
            scan(whole, pairs);
        }
        #[cfg(not(feature = "parallel"))]
        scan(whole, pairs);
        self.visit.clear();
        self.visit
            .extend_from_slice(&self.candidates.ids[..boxes.len()]);
    }
}
