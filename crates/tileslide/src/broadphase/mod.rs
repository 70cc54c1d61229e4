//! The broadphase: every pair of boxes that overlap (closed boxes: touching counts), each
//! once. A [`PairFinder`] keeps its buffers between calls; a [`PairMethod`] chooses how it
//! looks: a uniform grid or sweep and prune. Both are checked against the all-pairs
//! reference by model tests, call after call on moving boxes.
//!
//! The crate uses it for its own pairs: [`Bodies`](crate::Bodies) feeds it the regions its
//! circles can reach during a step (choosing the method with
//! [`ResolveConfig::broadphase`](crate::ResolveConfig::broadphase)), and
//! [`HitWorld`](crate::HitWorld) its objects' swept bounding circles, so a pair that can meet
//! is never missed. A game calls it directly only for pairs of its own: its entities'
//! boxes, say, to find which may interact.
//!
//! ```
//! use tileslide::broadphase::{PairFinder, PairMethod};
//! use tileslide::{Aabb, Vec2};
//! let boxes = [
//!     Aabb::from_corners(Vec2::new(0.0, 0.0), Vec2::new(1.0, 1.0)),
//!     Aabb::from_corners(Vec2::new(1.0, 0.5), Vec2::new(2.0, 1.5)), // touches the first
//!     Aabb::from_corners(Vec2::new(5.0, 5.0), Vec2::new(6.0, 6.0)),
//! ];
//! let mut finder = PairFinder::default();
//! let mut pairs = Vec::new();
//! finder.find(PairMethod::SweepAndPrune, &boxes, &mut pairs);
//! assert_eq!(pairs, [(0, 1)]);
//! ```

mod grid;
mod sweep;

use std::ops::Range;

use glam::{Vec2, Vec4, Vec4Swizzles};

use crate::geometry::Aabb;

use grid::GridPairs;
use sweep::SweepPairs;

/// How a [`PairFinder`] finds the pairs of boxes: bodies that may meet during a step,
/// objects whose hit volumes may touch.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum PairMethod {
    /// A uniform grid sized to the largest box: the right choice when boxes are of similar
    /// size. The default.
    #[default]
    UniformGrid,
    /// Sweep and prune along x, in horizontal bands as tall as the largest box, keeping its
    /// order from one call to the next: no grid to size, and cheap when few boxes move.
    SweepAndPrune,
}

/// Finds the overlapping pairs of a list of boxes; keeps its buffers (and the sweep order)
/// between calls, so finding the pairs of boxes that moved a little is cheap and allocates
/// nothing once warm.
#[derive(Clone, Debug, Default)]
pub struct PairFinder {
    grid: GridPairs,
    sweep: SweepPairs,
}

impl PairFinder {
    /// Appends to `pairs` every `(i, j)`, `i < j`, whose closed boxes share a point, each
    /// once.
    ///
    /// The order of the pairs is unspecified but deterministic: the same calls with the
    /// same boxes give the same pairs in the same order. A box with a NaN coordinate
    /// overlaps nothing. Every finite box is paired exactly, however large or far (up to
    /// `±f32::MAX`: the boxes are only compared, and the grid's and bands' sizes are
    /// computed so that no overflow can lose a pair), and a few boxes far from the others
    /// cost no more than near ones.
    pub fn find(&mut self, method: PairMethod, boxes: &[Aabb], pairs: &mut Vec<(u32, u32)>) {
        match method {
            PairMethod::UniformGrid => self.grid.find(boxes, pairs),
            PairMethod::SweepAndPrune => self.sweep.find(boxes, pairs),
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

/// A box as `(max.x, max.y, −min.x, −min.y)`. Two closed boxes `a`, `b` overlap exactly when
/// every lane of [`lower`]`(a)` is `<=` the same lane of `upper(b)`: one four-lane compare
/// instead of four branches. Negation is exact, so this is the same test as
/// [`Aabb::overlaps`], touching included, and false whenever a coordinate is NaN.
#[inline]
fn upper(b: &Aabb) -> Vec4 {
    Vec4::new(b.max.x, b.max.y, -b.min.x, -b.min.y)
}

/// `(min.x, min.y, −max.x, −max.y)` of the box whose [`upper`] form is `u`.
#[inline]
fn lower(u: Vec4) -> Vec4 {
    -u.zwxy()
}

/// How many candidates [`Candidates::emit`] tests at once.
const BLOCK: usize = 2;

/// Boxes laid out in the order a broadphase scans them: their [`upper`] forms and their
/// indices, followed by [`BLOCK`] boxes that overlap nothing (NaN), so that a block of
/// candidates never reads past the end.
#[derive(Clone, Debug, Default)]
struct Candidates {
    uppers: Vec<Vec4>,
    ids: Vec<u32>,
}

impl Candidates {
    /// Makes room for `n` boxes (plus the padding), to be written with [`Self::set`].
    fn reset(&mut self, n: usize) {
        self.uppers.clear();
        self.uppers.resize(n + BLOCK, Vec4::NAN);
        self.ids.clear();
        self.ids.resize(n + BLOCK, 0);
    }

    /// Puts box `id`, in [`upper`] form, at `slot`.
    #[inline]
    fn set(&mut self, slot: usize, upper: Vec4, id: u32) {
        self.uppers[slot] = upper;
        self.ids[slot] = id;
    }

    /// Writes at `pairs[*n..]` the pairs of box `id` (whose [`lower`] form is `lower`) with
    /// the boxes at `run` that it overlaps, advancing `*n` past them; `pairs` grows as
    /// needed (the caller truncates it to `*n` at the end).
    ///
    /// Candidates are tested in whole blocks, the ones past the run masked off, and every
    /// candidate is written and kept by advancing the cursor: runs hold a few boxes, and
    /// both a loop that stops after a varying few steps and a branch on "overlaps" are
    /// mispredicted about every other time (measured on 100,000 scattered boxes: the grid's
    /// scan 1.4× slower with a loop per candidate).
    #[inline]
    fn emit(
        &self,
        lower: Vec4,
        id: u32,
        run: Range<usize>,
        pairs: &mut Vec<(u32, u32)>,
        n: &mut usize,
    ) {
        let mut q = run.start;
        loop {
            self.emit_block(lower, id, q, run.end, pairs, n);
            q += BLOCK;
            if q >= run.end {
                return;
            }
        }
    }

    /// One block of [`Self::emit`]: the boxes at `q..q + BLOCK` that are before `end`.
    #[inline]
    fn emit_block(
        &self,
        lower: Vec4,
        id: u32,
        q: usize,
        end: usize,
        pairs: &mut Vec<(u32, u32)>,
        n: &mut usize,
    ) {
        if pairs.len() < *n + BLOCK {
            pairs.resize(2 * (*n + BLOCK), (0, 0));
        }
        for k in q..q + BLOCK {
            let keep = lower.cmple(self.uppers[k]).all() & (k < end);
            let other = self.ids[k];
            pairs[*n] = (id.min(other), id.max(other));
            *n += usize::from(keep);
        }
    }
}

/// Boxes a task of a scan split across threads takes at least (the `parallel` feature).
#[cfg(feature = "parallel")]
const BOXES_PER_TASK: usize = 2048;

/// A scan split across threads (the `parallel` feature): the boxes in scan order are cut
/// into runs of at least [`BOXES_PER_TASK`], each run's pairs are found on any thread into
/// a buffer of its own, and the buffers are appended in run order. A run's pairs depend
/// only on its boxes, so the pairs come out exactly as one scan of every box gives them, in
/// the same order, whatever the number of threads.
#[cfg(feature = "parallel")]
#[derive(Clone, Debug, Default)]
struct Parts {
    /// Where each run starts in scan order, and one more entry at the end.
    cuts: Vec<usize>,
    parts: Vec<Vec<(u32, u32)>>,
}

#[cfg(feature = "parallel")]
impl Parts {
    /// Whether a scan of `boxes` boxes is worth splitting on the current rayon pool.
    fn worth(boxes: usize) -> bool {
        boxes >= 2 * BOXES_PER_TASK && rayon::current_num_threads() > 1
    }

    /// Cuts the scan of `boxes` boxes into runs at the first of `allowed` (increasing
    /// places where a run may start) at least [`BOXES_PER_TASK`] past the last cut.
    fn cut(&mut self, boxes: usize, allowed: impl IntoIterator<Item = usize>) {
        self.cuts.clear();
        self.cuts.push(0);
        for at in allowed {
            if at >= self.cuts[self.cuts.len() - 1] + BOXES_PER_TASK && at < boxes {
                self.cuts.push(at);
            }
        }
        self.cuts.push(boxes);
    }

    /// Runs `scan(run, pairs)` on every run of the last [`cut`](Self::cut), on the threads
    /// of the current rayon pool, and appends the pairs to `pairs` in run order.
    fn scan(
        &mut self,
        pairs: &mut Vec<(u32, u32)>,
        scan: impl Fn(Range<usize>, &mut Vec<(u32, u32)>) + Sync,
    ) {
        use rayon::prelude::*;
        let runs = self.cuts.len() - 1;
        self.parts.resize_with(runs, Vec::new);
        let cuts = &self.cuts;
        self.parts[..runs]
            .par_iter_mut()
            .enumerate()
            .for_each(|(k, part)| {
                part.clear();
                scan(cuts[k]..cuts[k + 1], part);
            });
        let found: usize = self.parts[..runs].iter().map(Vec::len).sum();
        pairs.reserve(found);
        for part in &self.parts[..runs] {
            pairs.extend_from_slice(part);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    const KINDS: [PairMethod; 2] = [PairMethod::UniformGrid, PairMethod::SweepAndPrune];

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

    /// The pairs `finder` finds, checked to be `(i, j)` with `i < j`, sorted.
    fn found(finder: &mut PairFinder, kind: PairMethod, boxes: &[Aabb]) -> Vec<(u32, u32)> {
        let mut pairs = vec![(7, 7)]; // `find` appends: what is there stays.
        finder.find(kind, boxes, &mut pairs);
        assert_eq!(pairs.remove(0), (7, 7));
        assert!(pairs.iter().all(|&(i, j)| i < j), "{kind:?}: {pairs:?}");
        pairs.sort_unstable();
        pairs
    }

    fn boxes_strategy() -> impl Strategy<Value = Vec<Aabb>> {
        // Mostly small boxes, some large ones, some touching exactly (corners on a lattice
        // of halves), some flat or points.
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

    /// A box moved by `(dx, dy)` halves, with its size unchanged or changed.
    fn moved(b: &Aabb, dx: i32, dy: i32, grow: u32) -> Aabb {
        let shift = Vec2::new(dx as f32, dy as f32) * 0.5;
        let max = b.max + shift + Vec2::splat(grow as f32 * 0.5);
        Aabb::from_corners(b.min + shift, max)
    }

    proptest! {
        #[test]
        fn grid_and_sweep_and_prune_match_all_pairs(boxes in boxes_strategy()) {
            let expected = brute(&boxes);
            for kind in KINDS {
                prop_assert_eq!(found(&mut PairFinder::default(), kind, &boxes), expected.clone());
            }
        }

        /// One finder per kind kept over several calls, as a game uses it: boxes move,
        /// grow, and come and go between calls, and every call must still give the truth.
        #[test]
        fn a_finder_kept_between_calls_matches_all_pairs(
            start in boxes_strategy(),
            calls in prop::collection::vec(
                (prop::collection::vec((-3i32..=3, -3i32..=3, 0u32..3), 120), 0usize..130),
                1..6,
            ),
        ) {
            let mut finders = [PairFinder::default(), PairFinder::default()];
            let mut boxes = start;
            for (moves, keep) in calls {
                boxes = boxes
                    .iter()
                    .zip(&moves)
                    .map(|(b, &(dx, dy, grow))| moved(b, dx, dy, grow))
                    .collect();
                // Drop boxes from the end, or add copies of the first ones back.
                let extra: Vec<Aabb> = boxes.iter().take(keep.saturating_sub(boxes.len())).copied().collect();
                boxes.truncate(keep);
                boxes.extend(extra);
                let expected = brute(&boxes);
                for (finder, kind) in finders.iter_mut().zip(KINDS) {
                    prop_assert_eq!(found(finder, kind, &boxes), expected.clone(), "{:?}", kind);
                }
            }
        }
    }

    proptest! {
        /// Boxes anywhere in `f32`'s finite range, most of them near each other and some far
        /// (where sums of coordinates overflow): the pairs are still exactly the all-pairs
        /// ones, and the sweep's sort keeps its buckets in proportion to the boxes.
        #[test]
        fn boxes_of_any_finite_coordinates_match_all_pairs(
            boxes in prop::collection::vec(
                (
                    prop_oneof![4 => Just(1.0f32), 1 => Just(crate::geometry::MAX_COORD), 1 => Just(1e30f32), 1 => Just(f32::MAX)],
                    -1.0f32..1.0,
                    -1.0f32..1.0,
                    0.0f32..0.5,
                    0.0f32..0.5,
                ),
                0..40,
            ),
        ) {
            let boxes: Vec<Aabb> = boxes
                .into_iter()
                .map(|(scale, x, y, w, h)| {
                    let min = Vec2::new(x, y) * scale;
                    Aabb::from_corners(min, min + Vec2::new(w, h) * scale)
                })
                .collect();
            let expected = brute(&boxes);
            for kind in KINDS {
                let mut finder = PairFinder::default();
                prop_assert_eq!(found(&mut finder, kind, &boxes), expected.clone(), "{:?}", kind);
                prop_assert!(finder.sweep.buckets() <= 3 * (4 * boxes.len() + 257) + 1);
            }
        }
    }

    #[test]
    fn sweep_and_prune_reuses_its_order_when_boxes_move() {
        let mut finder = PairFinder::default();
        let mut boxes: Vec<Aabb> = (0..50)
            .map(|i| Aabb::from_center(Vec2::new(i as f32 * 0.7, 0.0), Vec2::splat(0.4)))
            .collect();
        assert_eq!(
            found(&mut finder, PairMethod::SweepAndPrune, &boxes),
            brute(&boxes)
        );
        // Reverse the row: the kept order is now fully wrong, and must still give the truth.
        for (i, b) in boxes.iter_mut().enumerate() {
            *b = Aabb::from_center(Vec2::new(50.0 - i as f32 * 0.7, 0.0), Vec2::splat(0.4));
        }
        assert_eq!(
            found(&mut finder, PairMethod::SweepAndPrune, &boxes),
            brute(&boxes)
        );
    }

    #[test]
    fn boxes_touching_at_zero_and_minus_zero_are_a_pair() {
        // −0.0 and 0.0 are the same coordinate: the boxes touch. A sort on the raw bits
        // would put them apart.
        let boxes = [
            Aabb {
                min: Vec2::new(-1.0, -1.0),
                max: Vec2::new(-0.0, -0.0),
            },
            Aabb {
                min: Vec2::new(0.0, 0.0),
                max: Vec2::new(1.0, 1.0),
            },
        ];
        for kind in KINDS {
            assert_eq!(found(&mut PairFinder::default(), kind, &boxes), [(0, 1)]);
        }
    }

    #[test]
    fn boxes_with_nan_overlap_nothing_and_hide_no_other_pair() {
        let nan = f32::NAN;
        let unit = |x: f32, y: f32| Aabb {
            min: Vec2::new(x, y),
            max: Vec2::new(x + 1.0, y + 1.0),
        };
        let boxes = [
            unit(0.0, 0.0),
            Aabb {
                min: Vec2::new(nan, 0.0),
                max: Vec2::new(1.0, 1.0),
            },
            unit(0.5, 0.5),
            Aabb {
                min: Vec2::new(0.0, 0.0),
                max: Vec2::new(-nan, nan),
            },
            Aabb {
                min: Vec2::splat(-nan),
                max: Vec2::splat(nan),
            },
            unit(1.0, 1.0),
        ];
        for kind in KINDS {
            assert_eq!(
                found(&mut PairFinder::default(), kind, &boxes),
                [(0, 2), (0, 5), (2, 5)],
                "{kind:?}"
            );
        }
    }

    #[test]
    fn far_apart_huge_and_point_boxes_match_all_pairs() {
        // Coordinates near f32's limits, boxes of zero size, a box covering everything.
        let big = 3.0e38;
        let boxes = [
            Aabb::from_corners(Vec2::splat(-big), Vec2::splat(big)),
            Aabb::from_corners(Vec2::new(big, big), Vec2::new(big, big)),
            Aabb::from_corners(Vec2::new(-big, 5.0), Vec2::new(-big, 5.0)),
            Aabb::from_corners(Vec2::new(1.0, 1.0), Vec2::new(1.0, 1.0)),
            Aabb::from_corners(Vec2::new(1.0, 1.0), Vec2::new(2.0, 1.0)),
            Aabb::from_corners(Vec2::new(1e-40, 0.0), Vec2::new(1e-40, 0.0)),
            Aabb::from_corners(Vec2::new(0.0, -1e-40), Vec2::new(2e-40, 0.0)),
            // Turned inside out: `overlaps` is still defined for them, and must agree.
            Aabb {
                min: Vec2::new(3.0, 9.0),
                max: Vec2::new(-3.0, -9.0),
            },
            Aabb {
                min: Vec2::new(0.5, 0.5),
                max: Vec2::new(0.4, 0.4),
            },
        ];
        for kind in KINDS {
            assert_eq!(
                found(&mut PairFinder::default(), kind, &boxes),
                brute(&boxes),
                "{kind:?}"
            );
        }
    }

    #[test]
    fn a_box_exactly_one_grid_cell_tall_meets_what_its_far_end_touches() {
        // Found by the `volumes` fuzz target: the grid's cells were exactly as tall as the
        // tallest box (239/255, from 0 to 239/255 above the lowest box at −4780/255), so
        // that box's corners fell in cells 18.99999 and 20.00001 after rounding, and the
        // box it touches at the top, filed in row 20, was two rows away.
        let tall = 0.9372549f32;
        let boxes = [
            Aabb::from_corners(Vec2::new(0.0, -18.745098), Vec2::new(3e-30, -18.325489)),
            Aabb::from_corners(Vec2::new(0.0, -tall), Vec2::new(3e-30, 3e-30)),
            Aabb::from_corners(Vec2::ZERO, Vec2::splat(3e-30)),
            Aabb::from_corners(Vec2::ZERO, Vec2::splat(3e-30)),
        ];
        for kind in KINDS {
            assert_eq!(
                found(&mut PairFinder::default(), kind, &boxes),
                brute(&boxes),
                "{kind:?}"
            );
        }
    }

    #[test]
    fn many_points_on_a_lattice_match_all_pairs() {
        // Zero-size boxes, many sharing a coordinate: the sweep's bands cannot take their
        // height from the boxes.
        let boxes: Vec<Aabb> = (0..400)
            .map(|i| {
                let p = Vec2::new((i % 7) as f32, (i / 7 % 9) as f32 * 0.25);
                Aabb::from_corners(p, p)
            })
            .collect();
        for kind in KINDS {
            let pairs = found(&mut PairFinder::default(), kind, &boxes);
            assert!(pairs.len() > 1000, "{}", pairs.len());
            assert_eq!(pairs, brute(&boxes), "{kind:?}");
        }
    }

    /// With the `parallel` feature, enough boxes that the scan is split across threads: on
    /// 1, 2, 3 and 8 threads the pairs are the same, in the same order, call after call as
    /// the boxes move, and they are all the pairs.
    #[cfg(feature = "parallel")]
    #[test]
    fn pairs_found_on_any_number_of_threads_are_the_same_in_the_same_order() {
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        let mut rand = || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (state >> 40) as f32 / (1u64 << 24) as f32
        };
        // Scattered boxes, and clumps on a lattice of halves (touching pairs).
        let mut boxes: Vec<Aabb> = (0..9_000)
            .map(|k| {
                let min = if k % 3 == 0 {
                    Vec2::new((k % 61) as f32 * 0.5, (k / 61 % 47) as f32 * 0.5)
                } else {
                    Vec2::new(rand() * 150.0, rand() * 150.0)
                };
                Aabb::from_corners(min, min + Vec2::new(0.5 + rand(), 0.5 + rand()))
            })
            .collect();
        for call in 0..3 {
            let expected = brute(&boxes);
            for kind in KINDS {
                let mut orders = Vec::new();
                for threads in [1, 2, 3, 8] {
                    let pool = rayon::ThreadPoolBuilder::new()
                        .num_threads(threads)
                        .build()
                        .unwrap();
                    let mut finder = PairFinder::default();
                    let mut pairs = vec![(7, 7)];
                    pool.install(|| {
                        // Twice: the second call starts from the first one's order.
                        finder.find(kind, &boxes, &mut pairs);
                        pairs.truncate(1);
                        finder.find(kind, &boxes, &mut pairs);
                    });
                    assert_eq!(pairs[0], (7, 7), "{kind:?}: the pairs already there stay");
                    orders.push(pairs[1..].to_vec());
                }
                assert!(
                    orders.iter().all(|o| *o == orders[0]),
                    "{kind:?}, call {call}"
                );
                let mut sorted = orders[0].clone();
                sorted.sort_unstable();
                assert_eq!(sorted, expected, "{kind:?}, call {call}");
            }
            for b in &mut boxes {
                let shift = Vec2::new(rand() - 0.5, rand() - 0.5) * 3.0;
                *b = Aabb::from_corners(b.min + shift, b.max + shift);
            }
        }
    }

    #[test]
    fn insertion_sort_sorts() {
        let mut list = [5, 3, 9, 1, 1, 8, 0];
        insertion_sort_by(&mut list, |a, b| a < b);
        assert_eq!(list, [0, 1, 1, 3, 5, 8, 9]);
    }
}
