//! tileslide's resolver on the BENCHMARKS.md crowd: a clean audit after every run, and
//! bit-identical positions from run to run and between debug and release builds (a golden
//! hash: `.ci/run` runs this test in both profiles). A change to the resolver that moves any
//! body by a single bit changes the hash: update `GOLDEN` only for a deliberate change, and
//! say so in the commit.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use tileslide_bench::crowd::{CrowdContender, TileslideCrowd, run_crowd};
use tileslide_scenes::{CROWD_RADIUS, dungeon256, positions_hash, scene_crowd};

/// [`positions_hash`] of the final positions: FNV-1a 64 of their bits, x then y, body by
/// body.
const GOLDEN: u64 = 0x8584_2b31_c9d3_e773;

#[test]
fn the_crowd_is_clean_and_bit_identical_to_the_golden_run() {
    let grid = dungeon256();
    let bodies = scene_crowd(&grid, 2_000);
    let mut crowd = TileslideCrowd::new(&grid, &bodies, CROWD_RADIUS).unwrap();
    let result = run_crowd(&mut crowd, &grid, 40, CROWD_RADIUS);
    assert_eq!(result.audit.overlapping_pairs, 0, "{:?}", result.audit);
    assert_eq!(result.audit.wall_penetrations, 0, "{:?}", result.audit);
    // The skin: nothing closer than the radii by more than 1e-4 cell.
    assert!(result.audit.max_overlap <= 1e-4, "{:?}", result.audit);
    assert!(result.audit.max_penetration <= 1e-4, "{:?}", result.audit);
    assert!(
        result.mean_travel > 1.0,
        "the crowd hardly moved: {}",
        result.mean_travel
    );
    let hash = positions_hash(&crowd.positions());
    // A second run from scratch gives the same bits.
    let mut again = TileslideCrowd::new(&grid, &bodies, CROWD_RADIUS).unwrap();
    for _ in 0..40 {
        again.step();
    }
    assert_eq!(positions_hash(&again.positions()), hash);
    assert_eq!(
        hash, GOLDEN,
        "positions changed: golden hash is now {hash:#018x}"
    );
}
