//! The "crowd" scene at a fixed density and growing size: dungeon256 laid `k × k` times
//! side by side, each copy holding the scene's first `N` circles, all in one resolver in a
//! shuffled slot order. So the bodies number `k² · N` while each one sees what it sees in
//! the scene with `N`: the cost per circle against the number of bodies, density aside.
//! (In the scene itself, more bodies means denser: 1k circles fill 1.3 % of the lattice
//! sites, 10k 13 %, 50k 67 %.)
//!
//! `cargo run --release -p tileslide-bench --example crowd_tiled -- [N] [k] [steps]`.

use std::time::Instant;

use tileslide::{Bodies, BodyDesc, BodyShape};
use tileslide_bench::threads::{copies, laid};
use tileslide_scenes::{CROWD_RADIUS, dungeon256, scene_crowd};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let mut arg = |default: usize| -> Result<usize, Box<dyn std::error::Error>> {
        match args.next() {
            Some(s) => Ok(s.parse().map_err(|e| format!("{s:?}: {e}"))?),
            None => Ok(default),
        }
    };
    let n = arg(10_000)?;
    let k = arg(2)?;
    let steps = arg(if n >= 50_000 { 30 } else { 100 })?;
    if k == 0 || k > 8 {
        return Err(format!("k must be 1 to 8, not {k}").into());
    }
    let tile = dungeon256();
    let grid = laid(&tile, k);
    let map = grid.to_tile_map()?;
    let crowd = copies(&tile, &scene_crowd(&tile, n), k);
    let mut bodies = Bodies::new();
    let shape = BodyShape::circle(CROWD_RADIUS)?;
    let mut handles = Vec::with_capacity(crowd.len());
    for &(position, velocity) in &crowd {
        handles.push((
            bodies.add(BodyDesc::new(position, shape.clone()))?,
            velocity,
        ));
    }
    let mut times = Vec::with_capacity(steps);
    for _ in 0..steps {
        let start = Instant::now();
        for &(h, v) in &handles {
            bodies.propose(h, v)?;
        }
        bodies.step(&map);
        times.push(start.elapsed().as_secs_f64() * 1e3);
    }
    times.sort_by(f64::total_cmp);
    let median = times.get(steps / 2).copied().unwrap_or(0.0);
    println!(
        "{k}×{k} copies of the {n}-circle scene ({} circles), {steps} steps: median {median:.3} ms/step, {:.3} µs per circle",
        crowd.len(),
        median * 1e3 / crowd.len() as f64
    );
    Ok(())
}
