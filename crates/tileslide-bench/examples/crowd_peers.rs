//! Runs the "crowd" scene of BENCHMARKS.md with the peers alone (parry2d shape casts with the
//! walls as voxels or as segments, rapier2d's kinematic character controller) and prints their
//! figures side by side:
//! `cargo run --release -p tileslide-bench --example crowd_peers -- [steps at 10,000]`.
//! Until `tileslide bench crowd` exists, this is how the peer figures are measured.

use tileslide_bench::crowd::{
    CrowdContender, CrowdResult, ParrySegmentsCrowd, ParryVoxelsCrowd, RapierCrowd, TileslideCrowd,
    run_crowd,
};
use tileslide_scenes::{CROWD_RADIUS, CrowdBody, SolidGrid, dungeon256, scene_crowd};

/// Builds a contender from the map, the bodies and the radius.
type Make = fn(&SolidGrid, &[CrowdBody], f32) -> Box<dyn CrowdContender>;

fn main() {
    let steps_10k: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(100);
    let only = std::env::args().nth(2);
    let grid = dungeon256();
    let peers: [Make; 4] = [
        |g, b, r| match TileslideCrowd::new(g, b, r) {
            Ok(crowd) => Box::new(crowd),
            Err(e) => {
                eprintln!("cannot build the tileslide crowd: {e}");
                std::process::exit(1)
            }
        },
        |g, b, r| Box::new(ParryVoxelsCrowd::new(g, b, r)),
        |g, b, r| Box::new(ParrySegmentsCrowd::new(g, b, r)),
        |g, b, r| Box::new(RapierCrowd::new(g, b, r)),
    ];
    for (n, steps) in [(1_000, 100), (10_000, steps_10k)] {
        let bodies = scene_crowd(&grid, n);
        println!("crowd on dungeon256: N = {n}, {steps} steps, radius {CROWD_RADIUS}");
        println!(
            "  {:<18} {:>9} {:>19} {:>8} {:>10} {:>7} {:>10} {:>7}",
            "peer", "ms/step", "spread", "µs/body", "overlaps", "max", "walls", "max"
        );
        for make in peers {
            let mut peer = make(&grid, &bodies, CROWD_RADIUS);
            if only.as_deref().is_some_and(|o| o != peer.name()) {
                continue;
            }
            print_row(
                &run_crowd(peer.as_mut(), &grid, steps, CROWD_RADIUS),
                n,
                steps,
            );
        }
    }
}

/// One line of the table: timing, audit, and travel against the unobstructed `0.05 × steps`.
fn print_row(r: &CrowdResult, n: usize, steps: usize) {
    println!(
        "  {:<18} {:>9.3} {:>8.3} – {:>8.3} {:>8.3} {:>10} {:>7.4} {:>10} {:>7.4}   travel {:.3} of {:.3}",
        r.name,
        r.ms_per_step,
        r.spread_ms.0,
        r.spread_ms.1,
        r.ms_per_step * 1e3 / n as f64,
        r.audit.overlapping_pairs,
        r.audit.max_overlap,
        r.audit.wall_penetrations,
        r.audit.max_penetration,
        r.mean_travel,
        0.05 * steps as f64,
    );
}
