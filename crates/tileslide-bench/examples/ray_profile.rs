//! Casts the "rays" scene with tileslide alone, for profilers (perf, callgrind):
//! `cargo run --release -p tileslide-bench --example ray_profile -- [dungeon256|open256] [passes]
//! [single|batch]` (`single`: one `cast_ray` call a ray; `batch`, the default: `cast_rays`).
//! Figures that compare with peers come from `tileslide bench rays`.
//!
//! Also prints a checksum of every hit, bit for bit (t, point, normal, flags, cell, segment
//! index, tile), so that two builds can be shown to return exactly the same results.

use std::time::Instant;

use tileslide::{QueryFilter, Ray, RayHit, SegmentSource};
use tileslide_scenes::{Fnv1a, Scene, scene_rays};

/// FNV-1a (64-bit) over the bits of every hit, and over a marker for every miss.
fn checksum(hits: impl Iterator<Item = Option<RayHit>>) -> u64 {
    let mut h = Fnv1a::new();
    for hit in hits {
        let Some(hit) = hit else {
            h.write_u32(u32::MAX);
            continue;
        };
        for f in [hit.t, hit.point.x, hit.point.y, hit.normal.x, hit.normal.y] {
            h.write_f32(f);
        }
        h.write_u32(hit.flags.0);
        match hit.source {
            SegmentSource::Tile { segment, tile } => {
                for word in [segment.cell.col, segment.cell.row, segment.index, tile.0] {
                    h.write_u32(word);
                }
            }
            SegmentSource::Temporary { index, .. } => h.write_u32(index as u32),
            // A source added to tileslide later: hashed as a marker of its own.
            _ => h.write_u32(u32::MAX - 1),
        }
    }
    h.finish()
}

/// Rays per `cast_rays` call: a frame's worth, so that the answers stay in cache.
const BLOCK: usize = 1024;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let scene = args
        .next()
        .and_then(|s| Scene::from_name(&s))
        .unwrap_or(Scene::Dungeon256);
    let passes: usize = args.next().and_then(|s| s.parse().ok()).unwrap_or(10);
    let batch = args.next().is_none_or(|s| s != "single");
    let grid = scene.grid();
    let map = grid.to_tile_map()?;
    let rays: Vec<Ray> = scene_rays(&grid, 1_000_000)
        .iter()
        .map(|r| Ray {
            origin: r.origin,
            delta: r.dir * r.length,
        })
        .collect();
    let filter = QueryFilter::default();
    let mut best = f64::MAX;
    let mut hits = Vec::with_capacity(rays.len());
    for _ in 0..passes {
        let start = Instant::now();
        let mut sum = 0.0;
        if batch {
            for block in rays.chunks(BLOCK) {
                map.cast_rays_into(block, &filter, &mut hits);
                sum += hits.iter().flatten().map(|h| h.t).sum::<f32>();
            }
        } else {
            for ray in &rays {
                if let Some(hit) = map.cast_ray(*ray, &filter) {
                    sum += hit.t;
                }
            }
        }
        best = best.min(start.elapsed().as_secs_f64());
        std::hint::black_box(sum);
    }
    let sum = if batch {
        checksum(map.cast_rays(&rays, &filter).into_iter())
    } else {
        checksum(rays.iter().map(|r| map.cast_ray(*r, &filter)))
    };
    println!(
        "{} ({}): best of {passes} passes {:.2} Mrays/s, checksum {sum:016x}",
        scene.name(),
        if batch { "batch" } else { "single" },
        rays.len() as f64 / best / 1e6,
    );
    Ok(())
}
