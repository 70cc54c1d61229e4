//! The "crowd" scene at a fixed density and growing size: dungeon256 laid `k × k` times
//! side by side, each copy holding the scene's first `N` circles, all in one resolver in a
//! shuffled slot order. So the bodies number `k² · N` while each one sees what it sees in
//! the scene with `N`: the cost per circle against the number of bodies, density aside.
//! (In the scene itself, more bodies means denser: 1k circles fill 1.3 % of the lattice
//! sites, 10k 13 %, 50k 67 %.)
//!
//! `cargo run --release -p tileslide-bench --example crowd_tiled -- [N] [k] [steps]`.

use std::time::Instant;

use glam::Vec2;
use tileslide::{Bodies, BodyDesc, BodyShape};
use tileslide_scenes::{CROWD_RADIUS, SolidGrid, SplitMix64, dungeon256, scene_crowd};

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
    let side = tile.width * k;
    let grid = SolidGrid {
        width: side,
        height: tile.height * k,
        solid: (0..tile.height * k)
            .flat_map(|y| (0..side).map(move |x| (x, y)))
            .map(|(x, y)| tile.solid[(y % tile.height) * tile.width + x % tile.width])
            .collect(),
    };
    let map = grid.to_tile_map()?;
    let scene = scene_crowd(&tile, n);
    let mut crowd: Vec<(Vec2, Vec2)> = Vec::with_capacity(k * k * n);
    for copy in 0..k * k {
        let offset = Vec2::new(
            ((copy % k) * tile.width) as f32,
            ((copy / k) * tile.height) as f32,
        );
        crowd.extend(scene.iter().map(|b| (b.position + offset, b.velocity)));
    }
    let mut rng = SplitMix64::new(0x7115_0000_0000_0005);
    for i in (1..crowd.len()).rev() {
        let j = usize::try_from(rng.below(i as u64 + 1))?;
        crowd.swap(i, j);
    }
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
