//! The circles each circle may meet during a step, kept for several steps.
//!
//! Two circles can meet only if their reach discs overlap: a circle's reach disc is
//! centred where it starts, with its radius grown by its move and the gap, so it holds
//! everywhere the circle can be during the step. Finding those pairs with a broadphase over
//! every circle, every step, was about a tenth of a crowd step. Instead the candidate pairs
//! are found for the discs' boxes (the reach boxes) grown by a margin and kept while every
//! reach box stays inside its grown box: then every pair whose reach discs overlap is among
//! them, and each step only tests the candidates' discs. These are Verlet neighbour lists
//! (L. Verlet, "Computer experiments on classical fluids", Phys. Rev. 159, 1967) with the
//! skin test done on boxes; a crowd moving 0.05 cells a step finds its candidates again
//! about every fifth step.
//!
//! The rows are discs, not boxes, because every pass of a sweep tests every neighbour in
//! the row: in a packed crowd a circle's four diagonal neighbours are in its reach box but
//! never within reach, and testing them cost a third of the neighbour tests and many
//! mispredicted branches (see docs/resolver.md). A pair whose discs are apart is one the
//! resolver's reach test skips anyway, with a gap to spare for rounding: that test asks
//! whether the centres are within both radii, one gap and what is left of the mover's move,
//! and neither centre strays from its disc's centre by more than its own move has taken it
//! (what the mover has taken and what is left add up to at most its move), so apart discs
//! leave the centres farther than that by at least one more gap. The same holds for the
//! settled bodies' disturbed flags, which follow the rows.
//!
//! The rows are exactly the pairs whose reach discs overlap, in another order than an
//! all-pairs search would give; the nearest contact is chosen by time and then by index,
//! so the order changes no result.

use std::ops::Range;

use crate::broadphase::{PairFinder, PairMethod};
use crate::geometry::{Aabb, Circle};
use crate::prefetch::prefetch;

/// How far the boxes the candidates are found for reach past the reach boxes, in cells.
/// Measured on the crowd scene (10k): 0.1 barely gains (candidates found every other
/// step), 0.25 and 0.3 gain about 7 %; a wider margin tests more candidates every step.
const MARGIN: f32 = 0.25;

/// How many circles ahead [`Candidates::fill`] asks for the candidates' discs.
const FILL_AHEAD: usize = 4;

/// Circles whose rows one task fills at least (the `parallel` feature): a row costs a few
/// disc tests.
#[cfg(feature = "parallel")]
const CIRCLES_PER_TASK: usize = 4096;

/// Per circle, the circles it may meet (compressed rows), and what they were found for.
#[derive(Clone, Debug, Default)]
pub(super) struct Neighbours {
    finder: PairFinder,
    /// The pairs of grown boxes, as found (a buffer).
    pairs: Vec<(u32, u32)>,
    /// The candidates of circle `c` are `candidates[first[c]..first[c + 1]]`: the circles
    /// whose grown boxes overlap its own, each pair in both rows.
    first: Vec<u32>,
    candidates: Vec<u32>,
    /// Row `c` is `list[first[c]..first[c] + len[c]]`: the candidates whose reach discs
    /// overlap now, in the candidates' order, each written where the candidates of its row
    /// start, so rows are filled independently of each other.
    list: Vec<u32>,
    len: Vec<u32>,
    /// The grown boxes the rows were found for, and with which broadphase; `None` once
    /// forgotten.
    grown: Vec<Aabb>,
    found_with: Option<PairMethod>,
    /// How many times the candidates were found (so that what is built from them can tell
    /// when to build again).
    searches: u64,
}

impl Neighbours {
    /// Per circle, the grown box its candidates were found for, or `None` once forgotten
    /// (the circles changed since).
    pub fn grown(&self) -> Option<&[Aabb]> {
        self.found_with.map(|_| self.grown.as_slice())
    }

    /// Drops the candidates: the circles changed (added, removed, filters).
    pub fn forget(&mut self) {
        self.found_with = None;
    }

    /// Makes the rows hold every pair of circles whose `reach` discs overlap and whose
    /// bodies (`body_of`) differ and collide by `collides`. `boxes` are the discs' boxes:
    /// the candidates are found again with `kind` for them grown by a margin, unless every
    /// box is still inside the grown box the candidates were found for. `cell` is the map's
    /// smaller cell side, the unit of the margin. `beside` runs with the candidates (found
    /// again or kept) while the rows are filled.
    ///
    /// With the `parallel` feature, the rows are filled on the threads of the current
    /// rayon pool, each from its own candidates (the same rows on any number of threads),
    /// and `beside` runs beside them.
    #[allow(clippy::too_many_arguments)]
    pub fn update(
        &mut self,
        kind: PairMethod,
        reach: &[Circle],
        boxes: &[Aabb],
        cell: f32,
        body_of: impl Fn(u32) -> usize + Sync,
        collides: impl Fn(usize, usize) -> bool + Sync,
        beside: impl FnOnce(CandidateRows<'_>) + Send,
    ) {
        self.find_candidates(kind, boxes, cell, body_of, collides);
        let rows = CandidateRows {
            first: &self.first,
            candidates: &self.candidates,
            searches: self.searches,
        };
        let fill = || {
            fill_rows(
                &self.first,
                &self.candidates,
                reach,
                &mut self.list,
                &mut self.len,
            );
        };
        #[cfg(feature = "parallel")]
        rayon::join(fill, || beside(rows));
        #[cfg(not(feature = "parallel"))]
        {
            let mut fill = fill;
            fill();
            beside(rows);
        }
    }

    /// Finds the candidates again with `kind` for `boxes` grown by the margin, unless every
    /// box is still inside the grown box the candidates were found for (see
    /// [`update`](Self::update)).
    fn find_candidates(
        &mut self,
        kind: PairMethod,
        boxes: &[Aabb],
        cell: f32,
        body_of: impl Fn(u32) -> usize + Sync,
        collides: impl Fn(usize, usize) -> bool + Sync,
    ) {
        let kept = self.found_with == Some(kind)
            && self.grown.len() == boxes.len()
            && self.grown.iter().zip(boxes).all(|(g, b)| g.contains(b));
        if !kept {
            let margin = MARGIN * cell;
            self.grown.clear();
            self.grown.extend(boxes.iter().map(|b| b.expand(margin)));
            self.found_with = Some(kind);
            self.pairs.clear();
            self.finder.find(kind, &self.grown, &mut self.pairs);
            self.pairs.retain(|&(i, j)| {
                let (a, b) = (body_of(i), body_of(j));
                a != b && collides(a, b)
            });
            self.candidate_rows(boxes.len());
            self.searches += 1;
        }
    }

    /// The candidates' rows from the pairs, by counting sort: count each circle's pairs,
    /// running sums give each row's end, and filling every row backwards leaves `first[c]`
    /// at its start.
    fn candidate_rows(&mut self, n: usize) {
        self.first.clear();
        self.first.resize(n + 1, 0);
        for &(i, j) in &self.pairs {
            self.first[i as usize] += 1;
            self.first[j as usize] += 1;
        }
        for k in 1..n {
            self.first[k] += self.first[k - 1];
        }
        let total = if n == 0 { 0 } else { self.first[n - 1] };
        self.first[n] = total;
        self.candidates.clear();
        self.candidates.resize(total as usize, 0);
        for &(i, j) in &self.pairs {
            for (a, b) in [(i, j), (j, i)] {
                let slot = &mut self.first[a as usize];
                *slot -= 1;
                self.candidates[*slot as usize] = b;
            }
        }
        // A row keeps the broadphase's order: `first_contact` breaks ties between neighbours
        // by index, so the result does not depend on it (and sorting every row cost a
        // mispredicted branch or two per circle in a dense crowd).
    }

    /// Asks the processor to bring circle `c`'s row's place and length into its caches
    /// (see [`prefetch`](crate::prefetch)).
    #[cfg(feature = "parallel")]
    pub fn prefetch_row_place(&self, c: usize) {
        crate::prefetch::prefetch(&self.first, c);
        crate::prefetch::prefetch(&self.len, c);
    }

    /// Asks the processor to bring circle `c`'s row into its caches (its first entries: a
    /// row is a few entries long).
    #[cfg(feature = "parallel")]
    pub fn prefetch_row(&self, c: usize) {
        if let Some(&start) = self.first.get(c) {
            crate::prefetch::prefetch(&self.list, start as usize);
        }
    }

    /// The circles circle `c` may meet.
    #[inline]
    pub fn row(&self, c: usize) -> &[u32] {
        let start = self.first[c] as usize;
        &self.list[start..start + self.len[c] as usize]
    }
}

/// The candidates' rows, read while the rows are filled (see [`Neighbours::update`]).
#[derive(Clone, Copy)]
pub(super) struct CandidateRows<'a> {
    first: &'a [u32],
    candidates: &'a [u32],
    searches: u64,
}

#[cfg_attr(not(feature = "parallel"), allow(dead_code))]
impl CandidateRows<'_> {
    /// The candidates of circle `c`: a superset of its row, unchanged until the candidates
    /// are found again (see [`searches`](Self::searches)).
    #[inline]
    pub fn candidates(&self, c: usize) -> &[u32] {
        &self.candidates[self.first[c] as usize..self.first[c + 1] as usize]
    }

    /// How many times the candidates were found so far: the candidates are the same as
    /// long as this is.
    pub fn searches(&self) -> u64 {
        self.searches
    }
}

/// Fills the rows (`list`, `len`) from the candidates' rows (`first`, `candidates`): each
/// circle's candidates whose `reach` discs overlap its own; on the threads of the current
/// rayon pool for many circles (the `parallel` feature).
fn fill_rows(
    first: &[u32],
    candidates: &[u32],
    reach: &[Circle],
    list: &mut Vec<u32>,
    len: &mut Vec<u32>,
) {
    let n = reach.len();
    list.resize(candidates.len(), 0);
    len.resize(n, 0);
    let from = Candidates {
        first,
        candidates,
        reach,
    };
    #[cfg(feature = "parallel")]
    if n >= 2 * CIRCLES_PER_TASK && rayon::current_num_threads() > 1 {
        from.fill_split(0..n, list, len);
        return;
    }
    from.fill(0..n, list, len);
}

/// What the rows are filled from: the candidates' rows and the reach discs.
struct Candidates<'a> {
    first: &'a [u32],
    candidates: &'a [u32],
    reach: &'a [Circle],
}

impl Candidates<'_> {
    /// Fills the rows of `circles`: `list` holds the candidates' places from
    /// `first[circles.start]` on, and `len` the rows' lengths from `circles.start` on.
    fn fill(&self, circles: Range<usize>, list: &mut [u32], len: &mut [u32]) {
        let base = self.first[circles.start] as usize;
        for (c, len) in circles.zip(len) {
            // The candidates' discs are anywhere in `reach` (slot order is not spatial
            // order): asked for a few circles ahead, they arrive while the rows between are
            // filled.
            if let (Some(&start), Some(&end)) = (
                self.first.get(c + FILL_AHEAD),
                self.first.get(c + FILL_AHEAD + 1),
            ) {
                for &other in &self.candidates[start as usize..end as usize] {
                    prefetch(self.reach, other as usize);
                }
            }
            let (start, end) = (self.first[c] as usize, self.first[c + 1] as usize);
            let disc = &self.reach[c];
            let row = &mut list[start - base..end - base];
            // Written branch-free: whether a candidate is kept is a coin toss for the branch
            // predictor.
            let mut kept = 0;
            for &other in &self.candidates[start..end] {
                row[kept] = other;
                kept += usize::from(disc.overlaps(&self.reach[other as usize]));
            }
            *len = kept as u32;
        }
    }

    /// [`fill`](Self::fill) on the threads of the current rayon pool, in halves down to
    /// [`CIRCLES_PER_TASK`] circles.
    #[cfg(feature = "parallel")]
    fn fill_split(&self, circles: Range<usize>, list: &mut [u32], len: &mut [u32]) {
        if circles.len() < 2 * CIRCLES_PER_TASK {
            self.fill(circles, list, len);
            return;
        }
        let mid = circles.start + circles.len() / 2;
        let low = (self.first[mid] - self.first[circles.start]) as usize;
        let (list_low, list_high) = list.split_at_mut(low);
        let (len_low, len_high) = len.split_at_mut(mid - circles.start);
        rayon::join(
            || self.fill_split(circles.start..mid, list_low, len_low),
            || self.fill_split(mid..circles.end, list_high, len_high),
        );
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use glam::Vec2;

    /// Numbers in [0, 1) from a linear congruential generator seeded with `seed`.
    pub(in crate::bodies) fn uniform(seed: u64) -> impl FnMut() -> f32 {
        let mut state = seed;
        move || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (state >> 40) as f32 / (1u64 << 24) as f32
        }
    }

    /// Discs drifting a little each call, some jumping: the rows always hold exactly the
    /// overlapping pairs of different bodies (circles 2k and 2k + 1 share a body), each in
    /// both rows, whichever broadphase found the candidates.
    #[test]
    fn rows_are_exactly_the_overlapping_pairs_call_after_call() {
        for kind in [PairMethod::UniformGrid, PairMethod::SweepAndPrune] {
            let mut rand = uniform(0x1234_5678_9abc_def0);
            let n = 400;
            let mut centres: Vec<Vec2> = (0..n)
                .map(|_| Vec2::new(rand() * 20.0, rand() * 20.0))
                .collect();
            let mut neighbours = Neighbours::default();
            let mut rebuilt = 0;
            for call in 0..30 {
                for (k, c) in centres.iter_mut().enumerate() {
                    let jump = call % 10 == 9 && k % 97 == 0;
                    *c += Vec2::new(rand() - 0.5, rand() - 0.5) * if jump { 4.0 } else { 0.08 };
                }
                let discs: Vec<Circle> = centres.iter().map(|&c| Circle::new(c, 0.4)).collect();
                let boxes: Vec<Aabb> = discs.iter().map(Circle::aabb).collect();
                let grown_before = neighbours.grown.clone();
                neighbours.update(
                    kind,
                    &discs,
                    &boxes,
                    1.0,
                    |i| i as usize / 2,
                    |_, _| true,
                    |_| {},
                );
                rebuilt += usize::from(neighbours.grown != grown_before);
                for i in 0..n {
                    let mut row: Vec<u32> = neighbours.row(i).to_vec();
                    row.sort_unstable();
                    let expected: Vec<u32> = (0..n as u32)
                        .filter(|&j| {
                            j as usize / 2 != i / 2 && discs[i].overlaps(&discs[j as usize])
                        })
                        .collect();
                    assert_eq!(row, expected, "{kind:?}, call {call}, circle {i}");
                }
            }
            // Both paths ran: candidates found again, and kept.
            assert!(
                rebuilt > 1 && rebuilt < 30,
                "{kind:?}: found {rebuilt} times in 30"
            );
        }
    }

    /// Rows filled on many threads (the `parallel` feature, from 8,192 circles) are the rows
    /// one thread fills, entry for entry, on pools of 2, 3 and 8 threads; and some of them
    /// checked against every disc.
    #[cfg(feature = "parallel")]
    #[test]
    fn rows_filled_on_many_threads_are_the_rows_of_one() {
        let mut rand = uniform(0x0bad_5eed);
        let n = 20_011;
        let discs: Vec<Circle> = (0..n)
            .map(|_| {
                Circle::new(
                    Vec2::new(rand() * 120.0, rand() * 120.0),
                    0.3 + rand() * 0.2,
                )
            })
            .collect();
        let boxes: Vec<Aabb> = discs.iter().map(Circle::aabb).collect();
        let rows_on = |threads: usize| {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            let mut neighbours = Neighbours::default();
            pool.install(|| {
                neighbours.update(
                    PairMethod::UniformGrid,
                    &discs,
                    &boxes,
                    1.0,
                    |i| i as usize,
                    |_, _| true,
                    |_| {},
                );
            });
            (0..n)
                .map(|c| neighbours.row(c).to_vec())
                .collect::<Vec<_>>()
        };
        let one = rows_on(1);
        for threads in [2, 3, 8] {
            assert_eq!(rows_on(threads), one, "{threads} threads");
        }
        for c in (0..n).step_by(97) {
            let mut row = one[c].clone();
            row.sort_unstable();
            let expected: Vec<u32> = (0..n as u32)
                .filter(|&j| j as usize != c && discs[c].overlaps(&discs[j as usize]))
                .collect();
            assert_eq!(row, expected, "circle {c}");
        }
        assert!(
            one.iter().map(Vec::len).sum::<usize>() > n,
            "a crowd that meets"
        );
    }

    #[test]
    fn forgetting_finds_the_candidates_again() {
        let discs = [
            Circle::new(Vec2::ZERO, 0.5),
            Circle::new(Vec2::new(0.8, 0.0), 0.5),
        ];
        let boxes = discs.map(|d| d.aabb());
        let mut neighbours = Neighbours::default();
        neighbours.update(
            PairMethod::UniformGrid,
            &discs,
            &boxes,
            1.0,
            |i| i as usize,
            |_, _| true,
            |_| {},
        );
        assert_eq!(neighbours.row(0), [1]);
        // The same boxes, but the bodies no longer collide: only a forgotten list knows.
        neighbours.forget();
        neighbours.update(
            PairMethod::UniformGrid,
            &discs,
            &boxes,
            1.0,
            |i| i as usize,
            |_, _| false,
            |_| {},
        );
        assert!(neighbours.row(0).is_empty());
    }
}
