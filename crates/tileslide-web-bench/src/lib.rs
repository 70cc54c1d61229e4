//! The native side of the web package's benchmark (`npm run bench` in `web/`) and of its
//! bit-identity tests: the standard scenes of BENCHMARKS.md written as files Node reads,
//! and the same work timed natively through the code the package runs
//! (`tileslide_wasm::rays::cast_flat`, `tileslide_wasm::body_set::BodySet`).
//!
//! The scenes are generated here, natively, and handed to Node as bytes, because their
//! generators use `f32::cos` and `f32::sin`, which are not bit-identical between the
//! platform's maths library and wasm's: the package must give native answers for the
//! same input, and the input is the same only if it comes from one place. Nothing of this
//! crate is in the package.
//!
//! Files written by [`Scenes::write`] (little-endian):
//!
//! - `dungeon256.tsm`: the dungeon256 map, baked;
//! - `rays.f32`: the rays scene, 4 floats a ray (`x0, y0, x1, y1`), [`RAYS`] rays;
//! - `crowd.f32`: the crowd scene, 4 floats a circle (`x, y, vx, vy`), [`CROWD`] circles
//!   (the first 2,000 are the golden run's crowd).
#![forbid(unsafe_code)]

use std::fmt;
use std::path::Path;
use std::time::Instant;

use tileslide::io::baked;
use tileslide::{BodyDesc, BodyShape, QueryFilter, TileMap, Vec2};
use tileslide_scenes::{CROWD_RADIUS, Fnv1a, dungeon256, scene_crowd, scene_rays};
use tileslide_wasm::body_set::BodySet;
use tileslide_wasm::rays::{cast_flat, cast_flat_with};

/// Rays in the rays scene.
pub const RAYS: usize = 1_000_000;

/// Circles in the crowd scene as the benchmark runs it.
pub const CROWD: usize = 10_000;

/// FNV-1a over the bits of the 5 floats a ray (`t, x, y, nx, ny`) that `castRays` answers
/// for the rays scene on dungeon256: the package must give it too.
pub const RAYS_CHECKSUM: u64 = 0x2d21_87ac_d274_2f7e;

/// Why the scenes could not be written or run.
#[derive(Debug)]
pub struct BenchError(String);

impl fmt::Display for BenchError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for BenchError {}

impl BenchError {
    /// An error saying `message`.
    #[must_use]
    pub fn from_message(message: &str) -> Self {
        Self(message.to_string())
    }
}

fn fail(what: impl fmt::Display) -> BenchError {
    BenchError(what.to_string())
}

/// The scenes, in memory: the map, the rays and the crowd, as the files hold them.
pub struct Scenes {
    /// dungeon256 as a map.
    pub map: TileMap,
    /// 4 floats a ray.
    pub rays: Vec<f32>,
    /// 4 floats a circle: position, then the move it proposes every step.
    pub crowd: Vec<f32>,
}

impl Scenes {
    /// Generates the scenes.
    ///
    /// # Errors
    /// The dungeon could not become a map.
    pub fn generate() -> Result<Self, BenchError> {
        let grid = dungeon256();
        let map = grid.to_tile_map().map_err(fail)?;
        let rays = scene_rays(&grid, RAYS)
            .iter()
            .flat_map(|r| {
                let end = r.end();
                [r.origin.x, r.origin.y, end.x, end.y]
            })
            .collect();
        let crowd = scene_crowd(&grid, CROWD)
            .iter()
            .flat_map(|b| [b.position.x, b.position.y, b.velocity.x, b.velocity.y])
            .collect();
        Ok(Self { map, rays, crowd })
    }

    /// Writes the files the module's documentation lists into `dir` (made if missing).
    ///
    /// # Errors
    /// A file could not be written.
    pub fn write(&self, dir: &Path) -> Result<(), BenchError> {
        let write = |name: &str, bytes: &[u8]| {
            std::fs::write(dir.join(name), bytes)
                .map_err(|e| fail(format!("{}: {e}", dir.join(name).display())))
        };
        std::fs::create_dir_all(dir).map_err(|e| fail(format!("{}: {e}", dir.display())))?;
        write("dungeon256.tsm", &baked::to_bytes(&self.map))?;
        write("rays.f32", &floats_le(&self.rays))?;
        write("crowd.f32", &floats_le(&self.crowd))
    }
}

/// The floats' little-endian bytes.
fn floats_le(floats: &[f32]) -> Vec<u8> {
    floats.iter().flat_map(|f| f.to_le_bytes()).collect()
}

/// FNV-1a over the floats' bits, in order (the crowd's `positions_hash` for positions).
#[must_use]
pub fn floats_hash(floats: &[f32]) -> u64 {
    let mut hash = Fnv1a::new();
    for &f in floats {
        hash.write_f32(f);
    }
    hash.finish()
}

/// The answers to the rays scene, as `castRays` gives them (5 floats a ray).
///
/// # Errors
/// A ray `cast_flat` refuses.
pub fn cast_scene_rays(scenes: &Scenes) -> Result<Vec<f32>, BenchError> {
    cast_flat(&scenes.map, &scenes.rays, &QueryFilter::default()).map_err(fail)
}

/// [`cast_scene_rays`] through the portable batch walk ([`TileMap::cast_rays_portable`]),
/// which on x86-64 is SSE2 code whose eight lanes are two 128-bit halves, as in the wasm
/// build, where `cast_rays` runs 256-bit AVX2 when the processor has it: the native figure
/// at the package's SIMD width. The answers are the same.
///
/// # Errors
/// A ray `cast_flat` refuses.
pub fn cast_scene_rays_portable(scenes: &Scenes) -> Result<Vec<f32>, BenchError> {
    let filter = QueryFilter::default();
    cast_flat_with(&scenes.rays, |chunk, hits| {
        *hits = scenes.map.cast_rays_portable(chunk, &filter);
    })
    .map_err(fail)
}

/// The first `n` circles of the crowd in a [`BodySet`], and their handles and moves, as a
/// JavaScript game holds them.
pub struct Crowd {
    /// The bodies.
    pub set: BodySet,
    /// Their handle numbers, in order.
    pub handles: Vec<f64>,
    /// Their moves, 2 floats a body.
    pub moves: Vec<f32>,
}

impl Crowd {
    /// The first `n` circles of `scenes`' crowd.
    ///
    /// # Errors
    /// A body the set refuses.
    pub fn new(scenes: &Scenes, n: usize) -> Result<Self, BenchError> {
        let mut set = BodySet::default();
        let shape = BodyShape::circle(CROWD_RADIUS).map_err(fail)?;
        let mut handles = Vec::with_capacity(n);
        let mut moves = Vec::with_capacity(2 * n);
        for c in scenes.crowd.chunks_exact(4).take(n) {
            let desc = BodyDesc::new(Vec2::new(c[0], c[1]), shape.clone());
            handles.push(set.add(desc).map_err(fail)?);
            moves.extend_from_slice(&c[2..4]);
        }
        Ok(Self {
            set,
            handles,
            moves,
        })
    }

    /// One step: every body proposes its move (`proposeMany`), then `step`.
    ///
    /// # Errors
    /// A move the set refuses.
    pub fn step(&mut self, map: &TileMap) -> Result<(), BenchError> {
        self.set
            .propose_many(&self.handles, &self.moves)
            .map_err(fail)?;
        self.set.bodies.step(map);
        Ok(())
    }

    /// FNV-1a over the positions, x then y, body by body: the golden hash's.
    pub fn hash(&mut self) -> u64 {
        floats_hash(self.set.positions())
    }
}

/// The median of `runs` timings of `work`, in seconds.
///
/// # Errors
/// The first error of `work`.
pub fn median_seconds(
    runs: usize,
    mut work: impl FnMut() -> Result<(), BenchError>,
) -> Result<f64, BenchError> {
    let mut times = Vec::with_capacity(runs);
    for _ in 0..runs {
        let start = Instant::now();
        work()?;
        times.push(start.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    times
        .get(times.len() / 2)
        .copied()
        .ok_or_else(|| fail("no runs"))
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;

    /// The golden hash of `tileslide/tests/resolver_golden.rs`: 2,000 circles, 40 steps.
    const GOLDEN: u64 = 0x527e_da96_98ab_4a5d;

    #[test]
    fn the_crowd_through_the_package_code_gives_the_golden_hash() {
        let scenes = Scenes::generate().unwrap();
        let mut crowd = Crowd::new(&scenes, 2_000).unwrap();
        for _ in 0..40 {
            crowd.step(&scenes.map).unwrap();
        }
        assert_eq!(crowd.hash(), GOLDEN, "{:#018x}", crowd.hash());
    }

    #[test]
    fn the_rays_scene_gives_the_checksum_the_package_test_expects() {
        let scenes = Scenes::generate().unwrap();
        let out = cast_scene_rays(&scenes).unwrap();
        let hits = out.chunks(5).filter(|h| !h[0].is_nan()).count();
        assert_eq!(hits, 943_906, "BENCHMARKS.md's hits");
        assert_eq!(
            floats_hash(&out),
            RAYS_CHECKSUM,
            "{:#018x}",
            floats_hash(&out)
        );
    }
}
