//! Times the core's ray batch on the rays scene, for benchmarks in other languages to set
//! their own figure beside (crates/tileslide-py/bench/rays.py runs it in the same run).
//!
//! `cargo run --release -p tileslide-scenes --example time_rays -- [RAYS] [PASSES]` casts
//! the first RAYS (default 1,000,000) rays of the rays scene on dungeon256 as one batch
//! (`TileMap::cast_rays_into`), PASSES times (default 11) after one warm-up, and prints one
//! JSON object: `{"rays", "passes", "hits", "median_ms", "min_ms", "max_ms", "times_ms"}`
//! (every pass's time, in the order run).

use std::process::ExitCode;
use std::time::Instant;

use tileslide::io::ascii;
use tileslide::{QueryFilter, Ray};
use tileslide_scenes::{dungeon256, scene_rays};

fn arg(
    args: &mut impl Iterator<Item = String>,
    name: &str,
    default: usize,
) -> Result<usize, String> {
    match args.next() {
        Some(v) => match v.parse() {
            Ok(n) if n > 0 => Ok(n),
            _ => Err(format!("{name} {v:?} is not a positive whole number")),
        },
        None => Ok(default),
    }
}

fn run() -> Result<(), String> {
    let mut args = std::env::args().skip(1);
    let rays = arg(&mut args, "RAYS", 1_000_000)?;
    let passes = arg(&mut args, "PASSES", 11)?;
    let grid = dungeon256();
    let map = ascii::parse(&grid.to_ascii(), "dungeon256", 1.0).map_err(|e| e.to_string())?;
    let batch: Vec<Ray> = scene_rays(&grid, rays)
        .iter()
        .map(|r| Ray::between(r.origin, r.end()))
        .collect();
    let filter = QueryFilter::default();
    let mut hits = Vec::with_capacity(batch.len());
    map.cast_rays_into(&batch, &filter, &mut hits);
    let mut times = Vec::with_capacity(passes);
    for _ in 0..passes {
        let start = Instant::now();
        map.cast_rays_into(&batch, &filter, &mut hits);
        times.push(start.elapsed().as_secs_f64() * 1e3);
    }
    let in_order: Vec<String> = times.iter().map(|t| format!("{t:.3}")).collect();
    times.sort_by(f64::total_cmp);
    println!(
        "{{\"rays\": {rays}, \"passes\": {passes}, \"hits\": {}, \"median_ms\": {:.3}, \"min_ms\": {:.3}, \"max_ms\": {:.3}, \"times_ms\": [{}]}}",
        hits.iter().flatten().count(),
        times[passes / 2],
        times[0],
        times[passes - 1],
        in_order.join(", ")
    );
    Ok(())
}

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("time_rays: {e}");
            ExitCode::FAILURE
        }
    }
}
