//! Casts the "rays" scene with tileslide alone, for profilers (perf, callgrind):
//! `cargo run --release -p tileslide-bench --example ray_profile -- [dungeon256|open256] [passes]`.
//! Figures that compare with peers come from `tileslide bench rays`.

use std::time::Instant;

use tileslide::{Ray, RayFilter};
use tileslide_scenes::{Scene, scene_rays};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let scene = args
        .next()
        .and_then(|s| Scene::from_name(&s))
        .unwrap_or(Scene::Dungeon256);
    let passes: usize = args.next().and_then(|s| s.parse().ok()).unwrap_or(10);
    let grid = scene.grid();
    let map = grid.to_tile_map()?;
    let rays: Vec<Ray> = scene_rays(&grid, 1_000_000)
        .iter()
        .map(|r| Ray {
            origin: r.origin,
            delta: r.dir * r.length,
        })
        .collect();
    let filter = RayFilter::default();
    let mut best = f64::MAX;
    for _ in 0..passes {
        let start = Instant::now();
        let mut sum = 0.0;
        for ray in &rays {
            if let Some(hit) = map.cast_ray(*ray, &filter) {
                sum += hit.t;
            }
        }
        best = best.min(start.elapsed().as_secs_f64());
        std::hint::black_box(sum);
    }
    println!(
        "{}: best of {passes} passes {:.2} Mrays/s",
        scene.name(),
        rays.len() as f64 / best / 1e6
    );
    Ok(())
}
