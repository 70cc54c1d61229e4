//! The broad-phase benchmark: the "broad" scene of BENCHMARKS.md (100,000 circles bouncing
//! around the map's square, map ignored) run by each contender, timed update by update, then
//! checked against the exact pair set.
//!
//! A contender implements [`BroadContender`]; [`run_broad`] builds the scene, moves the circles
//! with [`update_broad`], times every [`update`](BroadContender::update) alone and, after the
//! last one, compares the contender's pairs with [`broad_pairs_reference`]. The peers:
//!
//! - [`ParryBvhBroad`]: parry2d's `Bvh`, refitted to the new boxes and traversed against itself
//!   every update;
//! - [`RapierBroad`]: rapier2d's broad phase (`BroadPhaseBvh`), fed the moved colliders every
//!   update, its pair events kept as a pair set and filtered down to the exact pairs;
//! - [`Box2dTreeBroad`]: Box2D v3's dynamic tree, its fat proxies enlarged and the tree
//!   partly rebuilt as Box2D's broad phase does, then queried once per circle.
//!
//! A pair is two circles whose boxes ([`broad_box`](tileslide_scenes::broad_box): centre ∓
//! radius, in f32) overlap, touching included. Speed alone means nothing: read `ms_per_update`
//! together with `exact`.
//!
//! ```no_run
//! use tileslide_bench::broad::{ParryBvhBroad, run_broad};
//!
//! let result = run_broad(&mut ParryBvhBroad::new(), 100_000, 10);
//! println!("{}: {:.2} ms/update, {} pairs, exact {}", result.name, result.ms_per_update,
//!     result.pairs, result.exact);
//! ```

mod box2d_tree;
mod parry_bvh;
mod rapier_broad;
mod tileslide_broad;

pub use box2d_tree::Box2dTreeBroad;
pub use parry_bvh::ParryBvhBroad;
pub use rapier_broad::RapierBroad;
pub use tileslide_broad::TileslideBroad;

use std::time::Instant;

use tileslide::broadphase::PairMethod;
use tileslide_scenes::{BroadCircle, broad_pairs_reference, scene_broad, update_broad};

/// Every contender of `tileslide bench broad`, empty, in report order: tileslide's grid and
/// sweep and prune, then the peers.
#[must_use]
pub fn contenders() -> Vec<Box<dyn BroadContender>> {
    vec![
        Box::new(TileslideBroad::new(PairMethod::UniformGrid)),
        Box::new(TileslideBroad::new(PairMethod::SweepAndPrune)),
        Box::new(ParryBvhBroad::new()),
        Box::new(RapierBroad::new()),
        Box::new(Box2dTreeBroad::new()),
    ]
}

/// Something that finds every overlapping pair of a set of moving circles: tileslide or one of
/// its peers.
///
/// A contender is created empty (by a constructor of its own), then [built](Self::build) once
/// from the circles' start positions (not timed), then [updated](Self::update) once per frame
/// with the moved circles (timed). Every update must find the complete pair set of the circles
/// it is given; it may keep whatever it likes from the previous updates (a tree to refit, a
/// persistent pair set), as long as the answer is the same as from scratch.
///
/// The circles are always the same ones in the same order, and all have radius
/// [`BROAD_RADIUS`](tileslide_scenes::BROAD_RADIUS). A contender that works on a list of boxes
/// (such as tileslide's, on a `&[Aabb]`) fills that list with
/// [`broad_boxes`](tileslide_scenes::broad_boxes) at the start of its `update`, into a buffer
/// it keeps: converting the circles to the contender's own types is part of the timed work for
/// every contender.
pub trait BroadContender {
    /// The name the contender is reported under (e.g. `"parry2d-bvh"`).
    fn name(&self) -> &str;

    /// Sets the contender up for `circles` (their start positions): builds its structures,
    /// and finds the start pairs if it keeps pairs from one update to the next. Not timed.
    fn build(&mut self, circles: &[BroadCircle]);

    /// Finds the pairs of the moved `circles` (same circles, same order as given to
    /// [`build`](Self::build)). The timed part.
    fn update(&mut self, circles: &[BroadCircle]);

    /// The pairs found by the last update (or by [`build`](Self::build) before the first
    /// update), as circle indices `(i, j)` with `i < j`, sorted, without duplicates. Not
    /// timed: a contender may sort here rather than in `update`.
    fn pairs(&self) -> Vec<(u32, u32)>;

    /// The number of pairs found by the last update: `pairs().len()`, without the sort.
    fn pair_count(&self) -> usize;
}

/// One contender's figures on one broad scene.
#[derive(Clone, Debug, PartialEq)]
pub struct BroadResult {
    /// The contender's [`name`](BroadContender::name).
    pub name: String,
    /// Median wall time of one update, in milliseconds (0 for a run of no updates).
    pub ms_per_update: f64,
    /// Fastest and slowest update, in milliseconds.
    pub spread_ms: (f64, f64),
    /// The number of pairs found by the last update.
    pub pairs: usize,
    /// Whether the pairs of the last update are exactly [`broad_pairs_reference`]'s.
    pub exact: bool,
}

/// Runs the broad scene of `n` circles ([`scene_broad`]) for `updates` updates on `contender`.
///
/// [`build`](BroadContender::build)s it from the start positions, then for each update moves
/// the circles with [`update_broad`] and times [`update`](BroadContender::update) alone
/// ([`Instant`], wall time). After the last update, compares
/// [`pairs`](BroadContender::pairs) with [`broad_pairs_reference`] (neither timed).
pub fn run_broad(contender: &mut dyn BroadContender, n: usize, updates: usize) -> BroadResult {
    let mut circles = scene_broad(n);
    contender.build(&circles);
    let mut times_ms = Vec::with_capacity(updates);
    for _ in 0..updates {
        update_broad(&mut circles);
        let start = Instant::now();
        contender.update(&circles);
        times_ms.push(start.elapsed().as_secs_f64() * 1e3);
    }
    times_ms.sort_by(f64::total_cmp);
    let ms_per_update = times_ms.get(updates / 2).copied().unwrap_or(0.0);
    let spread_ms = (
        times_ms.first().copied().unwrap_or(0.0),
        times_ms.last().copied().unwrap_or(0.0),
    );
    BroadResult {
        name: contender.name().to_owned(),
        ms_per_update,
        spread_ms,
        pairs: contender.pair_count(),
        exact: contender.pairs() == broad_pairs_reference(&circles),
    }
}

/// `pairs` as [`BroadContender::pairs`] wants them: each pair `(min, max)`, sorted,
/// duplicates removed. For contenders that find pairs in any order or orientation.
///
/// ```
/// use tileslide_bench::broad::normalized_pairs;
/// assert_eq!(normalized_pairs([(5, 2), (0, 1), (2, 5)]), vec![(0, 1), (2, 5)]);
/// ```
#[must_use]
pub fn normalized_pairs(pairs: impl IntoIterator<Item = (u32, u32)>) -> Vec<(u32, u32)> {
    let mut pairs: Vec<(u32, u32)> = pairs
        .into_iter()
        .map(|(a, b)| (a.min(b), a.max(b)))
        .collect();
    pairs.sort_unstable();
    pairs.dedup();
    pairs
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec2;

    /// The reference sweep as a contender, optionally dropping its last pair: the harness's
    /// own check.
    struct Sweep {
        drop_one: bool,
        pairs: Vec<(u32, u32)>,
        builds: usize,
    }

    impl BroadContender for Sweep {
        fn name(&self) -> &str {
            "sweep"
        }
        fn build(&mut self, circles: &[BroadCircle]) {
            self.builds += 1;
            self.update(circles);
        }
        fn update(&mut self, circles: &[BroadCircle]) {
            self.pairs = broad_pairs_reference(circles);
            if self.drop_one {
                self.pairs.pop();
            }
        }
        fn pairs(&self) -> Vec<(u32, u32)> {
            self.pairs.clone()
        }
        fn pair_count(&self) -> usize {
            self.pairs.len()
        }
    }

    fn sweep(drop_one: bool) -> Sweep {
        Sweep {
            drop_one,
            pairs: Vec::new(),
            builds: 0,
        }
    }

    #[test]
    fn the_harness_checks_the_pairs_of_the_last_update() {
        let mut right = sweep(false);
        let result = run_broad(&mut right, 5_000, 4);
        assert_eq!(right.builds, 1);
        assert_eq!(result.name, "sweep");
        assert!(result.exact);
        let mut circles = scene_broad(5_000);
        for _ in 0..4 {
            update_broad(&mut circles);
        }
        assert_eq!(result.pairs, broad_pairs_reference(&circles).len());
        assert!(result.pairs > 100, "{result:?}");
        assert!(
            result.spread_ms.0 <= result.ms_per_update
                && result.ms_per_update <= result.spread_ms.1
        );

        let wrong = run_broad(&mut sweep(true), 5_000, 4);
        assert!(!wrong.exact);
        assert_eq!(wrong.pairs, result.pairs - 1);
    }

    #[test]
    fn no_updates_means_no_time_and_the_start_pairs() {
        let result = run_broad(&mut sweep(false), 2_000, 0);
        assert_eq!(result.ms_per_update, 0.0);
        assert!(result.exact);
    }

    /// Two circles whose boxes touch exactly (right side of the first = left side of the
    /// second, in f32), a third far away: the peers' unit tests' scene.
    pub(crate) fn touching_trio() -> Vec<BroadCircle> {
        let r = tileslide_scenes::BROAD_RADIUS;
        let x = 40.7_f32;
        let right = x + r;
        let mut b = x + 2.0 * r;
        for _ in 0..64 {
            if b - r == right {
                break;
            }
            b = if b - r < right {
                b.next_up()
            } else {
                b.next_down()
            };
        }
        assert_eq!(b - r, right, "no exact touching partner for {x}");
        [(x, 10.0), (b, 10.3), (200.0, 200.0)]
            .into_iter()
            .map(|(x, y)| BroadCircle {
                position: Vec2::new(x, y),
                velocity: Vec2::ZERO,
            })
            .collect()
    }

    #[test]
    fn the_touching_trio_has_one_pair() {
        assert_eq!(broad_pairs_reference(&touching_trio()), vec![(0, 1)]);
    }

    #[test]
    fn every_contender_pairs_touching_boxes_and_not_boxes_one_ulp_apart() {
        for mut contender in contenders() {
            let name = contender.name().to_owned();
            let mut circles = touching_trio();
            contender.build(&circles);
            assert_eq!(contender.pairs(), vec![(0, 1)], "{name}");
            // Two ulps right: the boxes no longer touch (the reference says so too).
            let x = circles[1].position.x;
            circles[1].position.x = x.next_up().next_up();
            contender.update(&circles);
            assert!(broad_pairs_reference(&circles).is_empty());
            assert!(contender.pairs().is_empty(), "{name}");
            assert_eq!(contender.pair_count(), 0, "{name}");
            // Back in contact.
            circles[1].position.x = x;
            contender.update(&circles);
            assert_eq!(contender.pairs(), vec![(0, 1)], "{name}");
        }
    }

    #[test]
    fn every_contender_follows_the_circles_update_after_update() {
        for mut contender in contenders() {
            let name = contender.name().to_owned();
            let mut circles = scene_broad(3_000);
            contender.build(&circles);
            assert_eq!(contender.pairs(), broad_pairs_reference(&circles), "{name}");
            for _ in 0..5 {
                update_broad(&mut circles);
                contender.update(&circles);
                assert_eq!(contender.pairs(), broad_pairs_reference(&circles), "{name}");
                // Each pair reported once.
                assert_eq!(contender.pair_count(), contender.pairs().len(), "{name}");
            }
            // A circle teleported onto another one, one sent far away: a tree refitted
            // in its old shape, a kept sweep order, a fat-box pair set must all follow.
            circles[7].position = circles[1_234].position + Vec2::new(0.1, -0.2);
            circles[1_234 + 1].position = Vec2::new(254.5, 1.5);
            contender.update(&circles);
            assert!(contender.pairs().contains(&(7, 1_234)), "{name}");
            assert_eq!(contender.pairs(), broad_pairs_reference(&circles), "{name}");
        }
    }
}
