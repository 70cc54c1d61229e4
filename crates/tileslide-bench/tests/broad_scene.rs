//! Every broad-phase contender (tileslide's two and the peers) finds exactly the reference pairs of the BENCHMARKS.md broad scene
//! (5,000 circles, 3 updates): same pairs, touching boxes included, nothing more.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use tileslide::broadphase::PairMethod;
use tileslide_bench::broad::{
    Box2dTreeBroad, BroadContender, ParryBvhBroad, RapierBroad, TileslideBroad, run_broad,
};
use tileslide_scenes::{broad_pairs_reference, scene_broad, update_broad};

const N: usize = 5_000;
const UPDATES: usize = 3;

/// The reference pairs after `UPDATES` updates.
fn reference() -> Vec<(u32, u32)> {
    let mut circles = scene_broad(N);
    for _ in 0..UPDATES {
        update_broad(&mut circles);
    }
    broad_pairs_reference(&circles)
}

fn check(peer: &mut dyn BroadContender) {
    let result = run_broad(peer, N, UPDATES);
    let want = reference();
    assert!(want.len() > 200, "{} reference pairs", want.len());
    assert_eq!(peer.pairs(), want, "{}", result.name);
    assert!(result.exact, "{result:?}");
    assert_eq!(result.pairs, want.len(), "{result:?}");
}

#[test]
fn parry_bvh_finds_exactly_the_reference_pairs() {
    check(&mut ParryBvhBroad::new());
}

#[test]
fn rapier_broad_phase_finds_exactly_the_reference_pairs() {
    let mut peer = RapierBroad::new();
    check(&mut peer);
    // Its own pair set is a superset, filtered down by the peer.
    assert!(peer.kept_pairs() >= peer.pair_count());
}

#[test]
fn box2d_dynamic_tree_finds_exactly_the_reference_pairs() {
    let mut peer = Box2dTreeBroad::new();
    check(&mut peer);
    assert_eq!(peer.error(), None);
}

#[test]
fn tileslide_grid_finds_exactly_the_reference_pairs() {
    check(&mut TileslideBroad::new(PairMethod::UniformGrid));
}

#[test]
fn tileslide_sweep_and_prune_finds_exactly_the_reference_pairs() {
    check(&mut TileslideBroad::new(PairMethod::SweepAndPrune));
}
