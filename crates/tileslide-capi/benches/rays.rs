//! `ts_map_cast_rays` against the Rust batch it wraps: the standard rays scene
//! (BENCHMARKS.md's "rays", 1,000,000 rays on dungeon256), cast by `TileMap::cast_rays_into`
//! and through the C ABI (flat floats in, `ts_ray_hit`s out, called as C calls it), in the
//! same run. `cargo bench -p tileslide-capi --bench rays`.
//!
//! Before criterion's groups, an interleaved run takes the two in turn, 11 rounds, and
//! prints their medians and the ratio: on a shared machine the load drifts between
//! criterion's groups.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic,
    missing_docs,
    unsafe_code
)]

use std::ffi::CString;
use std::ptr;
use std::time::{Duration, Instant};

use criterion::Criterion;
use tileslide::{QueryFilter, Ray, RayHit, TileMap};
use tileslide_capi::{
    ts_map, ts_map_cast_rays, ts_map_free, ts_map_from_ascii, ts_ray_hit, ts_status,
};
use tileslide_scenes::{dungeon256, scene_rays};

const N: usize = 1_000_000;

struct Scene {
    rust_map: TileMap,
    c_map: *mut ts_map,
    rays: Vec<Ray>,
    flat: Vec<f32>,
    rust_out: Vec<Option<RayHit>>,
    c_out: Vec<ts_ray_hit>,
}

impl Scene {
    fn new() -> Self {
        let grid = dungeon256();
        let text = grid.to_ascii();
        let text = CString::new(text).unwrap();
        let mut c_map = ptr::null_mut();
        // SAFETY: a valid string and out pointer.
        let status = unsafe { ts_map_from_ascii(text.as_ptr(), 1.0, &mut c_map) };
        assert_eq!(status, ts_status::TS_OK);
        let rays: Vec<Ray> = scene_rays(&grid, N)
            .iter()
            .map(|r| Ray::between(r.origin, r.end()))
            .collect();
        let flat = rays
            .iter()
            .flat_map(|r| {
                let end = r.end();
                [r.origin.x, r.origin.y, end.x, end.y]
            })
            .collect();
        // SAFETY: ts_ray_hit is plain old data; every slot is written before it is read.
        let blank = unsafe { std::mem::zeroed::<ts_ray_hit>() };
        Self {
            rust_map: grid.to_tile_map().unwrap(),
            c_map,
            rays,
            flat,
            rust_out: Vec::with_capacity(N),
            c_out: vec![blank; N],
        }
    }

    fn rust(&mut self) {
        self.rust_map
            .cast_rays_into(&self.rays, &QueryFilter::default(), &mut self.rust_out);
    }

    fn c(&mut self) {
        // SAFETY: 4 N floats in, N hits out, a live map.
        let status = unsafe {
            ts_map_cast_rays(
                self.c_map,
                self.flat.as_ptr(),
                N,
                0,
                self.c_out.as_mut_ptr(),
            )
        };
        assert_eq!(status, ts_status::TS_OK);
    }
}

impl Drop for Scene {
    fn drop(&mut self) {
        // SAFETY: the scene's own map, freed once.
        unsafe { ts_map_free(self.c_map) };
    }
}

fn median(mut v: Vec<Duration>) -> Duration {
    v.sort();
    v[v.len() / 2]
}

fn main() {
    let mut scene = Scene::new();
    scene.rust();
    scene.c();
    let hits = scene.rust_out.iter().filter(|h| h.is_some()).count();
    let c_hits = scene.c_out.iter().filter(|h| !h.t.is_nan()).count();
    assert_eq!(c_hits, hits, "the C batch and the Rust batch disagree");
    let (mut rust, mut c) = (Vec::new(), Vec::new());
    for _ in 0..11 {
        let t = Instant::now();
        scene.rust();
        rust.push(t.elapsed());
        let t = Instant::now();
        scene.c();
        c.push(t.elapsed());
    }
    let (rust, c) = (median(rust), median(c));
    println!(
        "interleaved, 11 rounds of {N} rays ({hits} hit): Rust batch {:.1} ms, C batch {:.1} ms, C / Rust {:.3}",
        rust.as_secs_f64() * 1e3,
        c.as_secs_f64() * 1e3,
        c.as_secs_f64() / rust.as_secs_f64()
    );
    let mut criterion = Criterion::default().sample_size(10).configure_from_args();
    criterion.bench_function("rays/rust_batch", |b| b.iter(|| scene.rust()));
    criterion.bench_function("rays/c_batch", |b| b.iter(|| scene.c()));
    criterion.final_summary();
}
