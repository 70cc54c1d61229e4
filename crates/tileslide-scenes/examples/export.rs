//! Writes the standard scenes, and the core's answers on them, to files other languages
//! read: the Python package's tests and benchmark check their answers against these, bit for
//! bit.
//!
//! `cargo run --release -p tileslide-scenes --example export -- DIR [RAYS]` writes, in DIR:
//! - `dungeon256.txt`: the 256 × 256 dungeon as an ASCII map (unit cells);
//! - `rays.f32`: the first RAYS (default 1,000,000) rays of the rays scene, rows
//!   `x0, y0, x1, y1`, little-endian `float32`;
//! - `rays_hits.f32`: the core's batch answer for each, rows `t, x, y, nx, ny`, NaN for a
//!   miss;
//! - `crowd.f32`: the 2,000 bodies of the crowd scene, rows `x, y, dx, dy` (start and
//!   constant proposed move);
//! - `crowd_end.f32`: their positions after 40 steps, rows `x, y`;
//! - `expected.json`: the counts, and the crowd's positions hash (FNV-1a 64 over the
//!   little-endian bytes of `crowd_end.f32`) as a hex string.

use std::path::PathBuf;
use std::process::ExitCode;

use tileslide::io::ascii;
use tileslide::{QueryFilter, Ray};
use tileslide_scenes::{
    CROWD_RADIUS, dungeon256, positions_hash, run_crowd, scene_crowd, scene_rays,
};

/// The crowd as the golden test runs it (crates/tileslide/tests/resolver_golden.rs).
const CROWD_BODIES: usize = 2_000;
const CROWD_STEPS: usize = 40;

fn floats_bytes(values: impl IntoIterator<Item = f32>) -> Vec<u8> {
    values.into_iter().flat_map(f32::to_le_bytes).collect()
}

fn run() -> Result<(), String> {
    let mut args = std::env::args().skip(1);
    let dir = PathBuf::from(args.next().ok_or("usage: export DIR [RAYS]")?);
    let rays: usize = match args.next() {
        Some(n) => n.parse().map_err(|e| format!("RAYS {n:?}: {e}"))?,
        None => 1_000_000,
    };
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let write = |name: &str, bytes: &[u8]| {
        let path = dir.join(name);
        std::fs::write(&path, bytes).map_err(|e| format!("{}: {e}", path.display()))
    };

    let grid = dungeon256();
    let text = grid.to_ascii();
    write("dungeon256.txt", text.as_bytes())?;
    let map = ascii::parse(&text, "dungeon256.txt", 1.0).map_err(|e| e.to_string())?;

    let scene = scene_rays(&grid, rays);
    let batch: Vec<Ray> = scene
        .iter()
        .map(|r| Ray::between(r.origin, r.end()))
        .collect();
    write(
        "rays.f32",
        &floats_bytes(scene.iter().flat_map(|r| {
            let end = r.end();
            [r.origin.x, r.origin.y, end.x, end.y]
        })),
    )?;
    let mut hits = Vec::new();
    map.cast_rays_into(&batch, &QueryFilter::default(), &mut hits);
    let hit_count = hits.iter().flatten().count();
    write(
        "rays_hits.f32",
        &floats_bytes(hits.iter().flat_map(|h| match h {
            Some(h) => [h.t, h.point.x, h.point.y, h.normal.x, h.normal.y],
            None => [f32::NAN; 5],
        })),
    )?;

    let crowd = scene_crowd(&grid, CROWD_BODIES);
    write(
        "crowd.f32",
        &floats_bytes(
            crowd
                .iter()
                .flat_map(|b| [b.position.x, b.position.y, b.velocity.x, b.velocity.y]),
        ),
    )?;
    let (bodies, handles) = run_crowd(&map, &crowd, CROWD_STEPS).map_err(|e| e.to_string())?;
    let end = handles
        .iter()
        .map(|h| bodies.get(*h).map(|b| b.position()))
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| e.to_string())?;
    write(
        "crowd_end.f32",
        &floats_bytes(end.iter().flat_map(|p| [p.x, p.y])),
    )?;
    write(
        "expected.json",
        format!(
            "{{\"rays\": {rays}, \"ray_hits\": {hit_count}, \"crowd_bodies\": {CROWD_BODIES}, \
             \"crowd_radius\": {CROWD_RADIUS}, \"crowd_steps\": {CROWD_STEPS}, \
             \"crowd_hash\": \"{:#018x}\"}}\n",
            positions_hash(&end)
        )
        .as_bytes(),
    )?;
    Ok(())
}

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("export: {e}");
            ExitCode::FAILURE
        }
    }
}
