//! Broadphase: the pairs of boxes that overlap (closed boxes: touching counts), each once,
//! found with a uniform grid or by sweep and prune. Both are checked against the all-pairs
//! reference by a model test.
//!
//! [`Bodies`](crate::Bodies) feeds it the regions its circles can reach during a step, and
//! the hit volumes their objects' swept bounding circles, so a pair that can meet is never
//! missed.
//!
//! ```
//! use tileslide::{Aabb, Broadphase, PairFinder, Vec2};
//! let boxes = [
//!     Aabb::from_corners(Vec2::new(0.0, 0.0), Vec2::new(1.0, 1.0)),
//!     Aabb::from_corners(Vec2::new(1.0, 0.5), Vec2::new(2.0, 1.5)), // touches the first
//!     Aabb::from_corners(Vec2::new(5.0, 5.0), Vec2::new(6.0, 6.0)),
//! ];
//! let mut finder = PairFinder::default();
//! let mut pairs = Vec::new();
//! finder.find(Broadphase::SweepAndPrune, &boxes, &mut pairs);
//! assert_eq!(pairs, [(0, 1)]);
//! ```

use glam::Vec2;

use crate::geometry::Aabb;

/// Which broadphase finds the pairs of boxes: bodies that may meet during a step, objects
/// whose hit volumes may touch.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Broadphase {
    /// A uniform grid sized to the largest body's reach: the right choice when bodies are
    /// of similar size. The default.
    #[default]
    UniformGrid,
    /// Sweep and prune along x: no size assumption, better when sizes vary widely.
    SweepAndPrune,
}

/// Most grid cells the uniform grid allocates; beyond it, its cells grow.
const MAX_GRID_CELLS: usize = 1 << 22;

/// Finds the overlapping pairs of a list of boxes; keeps its buffers (and the sweep order)
/// between calls, so finding the pairs of boxes that moved a little is cheap and allocates
/// nothing once warm.
#[derive(Clone, Debug, Default)]
pub struct PairFinder {
    /// Uniform grid: per cell, the start of its run in `entries` (prefix sums).
    starts: Vec<u32>,
    entries: Vec<u32>,
    /// Per box, its cell; and the fill cursors of the counting sort.
    cells: Vec<u32>,
    fill: Vec<u32>,
    /// Sweep and prune: box indices by `min.x`, kept between calls (nearly sorted when the
    /// boxes move little, so insertion sort is close to linear).
    order: Vec<u32>,
}

impl PairFinder {
    /// Appends to `pairs` every `(i, j)`, `i < j`, whose closed boxes share a point, each
    /// once. The order is deterministic for given boxes.
    pub fn find(&mut self, kind: Broadphase, boxes: &[Aabb], pairs: &mut Vec<(u32, u32)>) {
        match kind {
            Broadphase::UniformGrid => self.grid(boxes, pairs),
            Broadphase::SweepAndPrune => self.sweep_and_prune(boxes, pairs),
        }
    }

    fn grid(&mut self, boxes: &[Aabb], pairs: &mut Vec<(u32, u32)>) {
        let Some((lo, hi, largest)) = extent(boxes) else {
            return;
        };
        // Cells at least as large as the largest box, and about ten cells per box: bodies
        // gather in rooms and crowds, so with fewer cells a box meets many it does not
        // touch (measured on the crowd scene: about one cell per box is 10% slower at
        // 10,000 bodies), and with many more, clearing and summing the cells dominates.
        let span = hi - lo;
        let per_box = (span.x.max(largest) * span.y.max(largest) / boxes.len() as f32).sqrt();
        let mut size = largest
            .max(0.3 * per_box)
            .max(span.max_element() / 4096.0)
            .max(f32::MIN_POSITIVE);
        let dims = |size: f32| ((span.x / size) as usize + 1, (span.y / size) as usize + 1);
        while dims(size).0.saturating_mul(dims(size).1) > MAX_GRID_CELLS {
            size *= 2.0;
        }
        let (w, h) = dims(size);
        let inv = 1.0 / size;
        // Each box goes into the one cell that holds its `min` corner. Since no box is
        // larger than a cell, a box that overlaps it has its `min` corner in the same cell
        // or one of the eight around.
        let cell_of = |p: Vec2| {
            let c = ((p - lo) * inv).min(Vec2::new((w - 1) as f32, (h - 1) as f32));
            (c.x as usize, c.y as usize)
        };
        // Counting sort by cell: count into `starts[cell + 1]`, running sums, then place
        // (boxes in index order, so each cell's run is sorted by index).
        self.starts.clear();
        self.starts.resize(w * h + 1, 0);
        self.cells.clear();
        for b in boxes {
            let (c, r) = cell_of(b.min);
            let cell = r * w + c;
            self.cells.push(cell as u32);
            self.starts[cell + 1] += 1;
        }
        for i in 1..self.starts.len() {
            self.starts[i] += self.starts[i - 1];
        }
        self.entries.clear();
        self.entries.resize(boxes.len(), 0);
        let mut fill = std::mem::take(&mut self.fill);
        fill.clear();
        fill.extend_from_slice(&self.starts[..w * h]);
        for (i, &cell) in self.cells.iter().enumerate() {
            let slot = &mut fill[cell as usize];
            self.entries[*slot as usize] = i as u32;
            *slot += 1;
        }
        self.fill = fill;
        // Each pair once: within a cell the later box of the pair, and across cells only
        // the four "forward" neighbours (right, and the three below) of a box's cell.
        // Candidates are written unconditionally and kept by advancing the cursor: whether
        // two boxes of a crowd overlap is a coin toss the branch predictor loses (measured:
        // a third of the grid's time went to it).
        let mut n = pairs.len();
        for (i, a) in boxes.iter().enumerate() {
            let cell = self.cells[i] as usize;
            let (c, r) = (cell % w, cell / w);
            let forward = [
                Some(cell),
                (c + 1 < w).then(|| cell + 1),
                (r + 1 < h && c > 0).then(|| cell + w - 1),
                (r + 1 < h).then(|| cell + w),
                (r + 1 < h && c + 1 < w).then(|| cell + w + 1),
            ];
            for other in forward.into_iter().flatten() {
                let run =
                    &self.entries[self.starts[other] as usize..self.starts[other + 1] as usize];
                if pairs.len() < n + run.len() {
                    pairs.resize(2 * (n + run.len()), (0, 0));
                }
                // In its own cell, a box pairs only with the later ones (and not itself).
                let own = other == cell;
                for &j in run {
                    let b = &boxes[j as usize];
                    let overlap = (a.min.cmple(b.max) & b.min.cmple(a.max)).bitmask() == 3;
                    let keep = overlap & (!own | (j as usize > i));
                    pairs[n] = (i.min(j as usize) as u32, i.max(j as usize) as u32);
                    n += usize::from(keep);
                }
            }
        }
        pairs.truncate(n);
    }

    fn sweep_and_prune(&mut self, boxes: &[Aabb], pairs: &mut Vec<(u32, u32)>) {
        if self.order.len() != boxes.len() {
            // Fewer or more boxes than last time (objects come and go between frames): keep
            // the order of the ones still there, the new ones at the end, so the insertion
            // sort still starts from a nearly sorted list.
            let n = boxes.len() as u32;
            let old = self.order.len() as u32;
            self.order.retain(|&i| i < n);
            self.order.extend(old..n);
        }
        // By (min.x, index): deterministic, and nearly sorted from the last call.
        let key = |i: u32| (boxes[i as usize].min.x, i);
        insertion_sort_by(&mut self.order, |a, b| lt(key(a), key(b)));
        for (k, &i) in self.order.iter().enumerate() {
            let a = &boxes[i as usize];
            for &j in &self.order[k + 1..] {
                let b = &boxes[j as usize];
                if b.min.x > a.max.x {
                    break;
                }
                if a.overlaps(b) {
                    pairs.push((i.min(j), i.max(j)));
                }
            }
        }
    }
}

/// Sorts in place with insertion sort: close to linear on nearly sorted lists (the sweep
/// order between calls) and on short ones (a circle's few neighbours).
pub(crate) fn insertion_sort_by<T: Copy>(list: &mut [T], less: impl Fn(T, T) -> bool) {
    for k in 1..list.len() {
        let item = list[k];
        let mut j = k;
        while j > 0 && less(item, list[j - 1]) {
            list[j] = list[j - 1];
            j -= 1;
        }
        list[j] = item;
    }
}

/// `(x, i) < (y, j)` with `total_cmp` on the floats (no NaN reaches here, but a sort must
/// not depend on that).
fn lt(a: (f32, u32), b: (f32, u32)) -> bool {
    a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)).is_lt()
}

/// The boxes' common bounds and the largest side of any box, or `None` without boxes.
fn extent(boxes: &[Aabb]) -> Option<(Vec2, Vec2, f32)> {
    let first = boxes.first()?;
    let mut lo = first.min;
    let mut hi = first.max;
    let mut largest = 0.0f32;
    for b in boxes {
        lo = lo.min(b.min);
        hi = hi.max(b.max);
        largest = largest.max(b.size().max_element());
    }
    Some((lo, hi, largest))
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn brute(boxes: &[Aabb]) -> Vec<(u32, u32)> {
        let mut out = Vec::new();
        for i in 0..boxes.len() {
            for j in i + 1..boxes.len() {
                if boxes[i].overlaps(&boxes[j]) {
                    out.push((i as u32, j as u32));
                }
            }
        }
        out
    }

    fn sorted(mut v: Vec<(u32, u32)>) -> Vec<(u32, u32)> {
        v.sort_unstable();
        v
    }

    fn boxes_strategy() -> impl Strategy<Value = Vec<Aabb>> {
        // Mostly small boxes, some large ones, some touching exactly (integer corners).
        prop::collection::vec(
            (
                0u32..40,
                0u32..40,
                0u32..4,
                0u32..4,
                any::<bool>(),
                0u32..20,
            )
                .prop_map(|(x, y, w, h, big, k)| {
                    let scale = if big && k == 0 { 8.0 } else { 1.0 };
                    let min = Vec2::new(x as f32 * 0.5, y as f32 * 0.5);
                    Aabb::from_corners(min, min + Vec2::new(w as f32, h as f32) * 0.5 * scale)
                }),
            0..120,
        )
    }

    proptest! {
        #[test]
        fn grid_and_sweep_and_prune_match_all_pairs(boxes in boxes_strategy()) {
            let expected = brute(&boxes);
            for kind in [Broadphase::UniformGrid, Broadphase::SweepAndPrune] {
                let mut finder = PairFinder::default();
                let mut pairs = Vec::new();
                finder.find(kind, &boxes, &mut pairs);
                prop_assert_eq!(pairs.len(), expected.len(), "{:?} reported a pair twice or missed one", kind);
                prop_assert_eq!(sorted(pairs), expected.clone());
            }
        }
    }

    #[test]
    fn sweep_and_prune_reuses_its_order_when_boxes_move() {
        let mut finder = PairFinder::default();
        let mut boxes: Vec<Aabb> = (0..50)
            .map(|i| Aabb::from_center(Vec2::new(i as f32 * 0.7, 0.0), Vec2::splat(0.4)))
            .collect();
        let mut pairs = Vec::new();
        finder.find(Broadphase::SweepAndPrune, &boxes, &mut pairs);
        assert_eq!(sorted(pairs.clone()), brute(&boxes));
        // Reverse the row: the kept order is now fully wrong, and must still give the truth.
        for (i, b) in boxes.iter_mut().enumerate() {
            *b = Aabb::from_center(Vec2::new(50.0 - i as f32 * 0.7, 0.0), Vec2::splat(0.4));
        }
        pairs.clear();
        finder.find(Broadphase::SweepAndPrune, &boxes, &mut pairs);
        assert_eq!(sorted(pairs), brute(&boxes));
    }
}
