//! The ray benchmark: the "rays" scene of BENCHMARKS.md cast on "dungeon256" or "open256"
//! by tileslide and, in the same process on the same rays, by parry2d's `Voxels` and
//! `Polyline` shapes and by Box2D v3's world ray cast against chain loops or boxes.
//!
//! tileslide casts the rays as a game with many rays would, with `TileMap::cast_rays`, in
//! blocks of [`RAYS_PER_CALL`]; two more entries cast the same rays other ways, with the same
//! answers bit for bit: `tileslide-single`, one `cast_ray` call at a time, and
//! `tileslide-portable`, `cast_rays`'s batch walk built for x86-64's baseline instruction set
//! (SSE2) rather than the AVX2 it takes where the processor has it, so that one run shows
//! what each instruction set gives on its processor. parry2d and Box2D have no call for many
//! rays: they cast one at a time.
//!
//! Each engine casts every ray once untimed to record its answers (hits, mean hit fraction,
//! disagreements with tileslide), then `passes` timed passes are run, interleaving the
//! engines so that machine noise falls on all of them alike; throughput is the median pass.
//!
//! Every peer has a `NAME`, a `new` that builds its acceleration structure from the scene (not
//! timed; fallible for the Box2D peers, whose world can be refused), and a `cast` that answers
//! one [`SceneRay`] with the distance, in cells, to the first solid-cell boundary the ray meets
//! within its length.

mod box2d_boxes;
mod box2d_chains;
mod parry_polyline;
mod parry_voxels;
#[cfg(test)]
pub(crate) mod test_grids;

use std::hint::black_box;
use std::time::Instant;

use parry2d::query::Ray as ParryRay;
use tileslide::{QueryFilter, Ray, RayHit, TileMap};
use tileslide_scenes::{Scene, SceneRay, TileMapError, scene_rays};

use crate::parry_vectors::to_parry;
pub use box2d_boxes::Box2dBoxes;
pub use box2d_chains::Box2dChains;
pub use parry_polyline::ParryPolyline;
pub use parry_voxels::ParryVoxels;

/// The parry2d ray of a scene ray: same origin, same (unit) direction, so parry's time of impact
/// is a distance in cells and `ray.length` can be passed as the maximum time of impact unchanged.
#[inline]
pub fn parry_ray(ray: &SceneRay) -> ParryRay {
    ParryRay::new(to_parry(ray.origin), to_parry(ray.dir))
}

/// Two answers disagree when their hit distances differ by more than this many cells (or
/// one hits and the other does not).
pub const DISAGREEMENT_TOLERANCE: f32 = 1e-3;

/// Rays per `cast_rays` call in tileslide's timed passes: a frame's worth, so that the
/// answers stay in cache as a game's would.
pub const RAYS_PER_CALL: usize = 1024;

/// One engine's cast: ray index → hit distance in cells.
type CastFn<'a> = dyn Fn(usize) -> Option<f32> + 'a;

/// What to run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RaysConfig {
    /// The map.
    pub scene: Scene,
    /// How many rays of the scene (the first `n`).
    pub rays: usize,
    /// How many timed passes per engine (the median is reported).
    pub passes: usize,
}

impl Default for RaysConfig {
    fn default() -> Self {
        Self {
            scene: Scene::Dungeon256,
            rays: 1_000_000,
            passes: 7,
        }
    }
}

/// One engine's figures.
#[derive(Clone, Debug, PartialEq)]
pub struct EngineResult {
    /// Engine name (`tileslide`, `parry2d-voxels`, `parry2d-polyline`, `box2d-chains`,
    /// `box2d-boxes`, `tileslide-single`, `tileslide-portable`).
    pub name: &'static str,
    /// Median throughput over the timed passes, in millions of rays per second.
    pub mrays_per_s: f64,
    /// Slowest and fastest pass, in millions of rays per second.
    pub spread: (f64, f64),
    /// Rays that hit.
    pub hits: usize,
    /// Mean hit fraction `t` in `[0, 1]` over the rays that hit.
    pub mean_t: f64,
    /// Mean hit distance in cells over the rays that hit.
    pub mean_distance: f64,
    /// Rays whose answer differs from tileslide's (see [`DISAGREEMENT_TOLERANCE`]).
    pub disagreements: usize,
}

/// The whole benchmark's result.
#[derive(Clone, Debug, PartialEq)]
pub struct RaysReport {
    /// Scene name.
    pub scene: &'static str,
    /// FNV-1a fingerprint of the map, as 16 hex digits.
    pub fingerprint: String,
    /// Number of rays.
    pub rays: usize,
    /// Timed passes per engine.
    pub passes: usize,
    /// One entry per engine: tileslide, the two parry2d shapes, the two Box2D worlds, then
    /// tileslide one ray a call and tileslide's portable batch walk.
    pub results: Vec<EngineResult>,
}

/// Why the benchmark could not run.
#[derive(Debug, thiserror::Error)]
pub enum RaysError {
    /// The generated map does not match the fingerprint BENCHMARKS.md publishes.
    #[error("scene {scene}: map fingerprint {found} differs from the published {expected}")]
    FingerprintMismatch {
        /// Scene name.
        scene: &'static str,
        /// Published fingerprint.
        expected: &'static str,
        /// Generated fingerprint.
        found: String,
    },
    /// The map could not be built.
    #[error("cannot build the map: {0}")]
    Map(TileMapError),
    /// Box2D refused a peer's world.
    #[error("cannot build the Box2D peers: {0}")]
    Box2d(boxdd::Error),
    /// Zero rays or zero passes.
    #[error("the benchmark needs at least one ray and one pass")]
    Empty,
}

/// Runs the benchmark; `progress(done, total)` is called after each timed pass.
pub fn run_rays(
    config: RaysConfig,
    mut progress: impl FnMut(usize, usize),
) -> Result<RaysReport, RaysError> {
    if config.rays == 0 || config.passes == 0 {
        return Err(RaysError::Empty);
    }
    let grid = config.scene.grid();
    let fingerprint = grid.fingerprint_hex();
    if let Some(expected) = config.scene.expected_fingerprint()
        && expected != fingerprint
    {
        return Err(RaysError::FingerprintMismatch {
            scene: config.scene.name(),
            expected,
            found: fingerprint,
        });
    }
    let rays = scene_rays(&grid, config.rays);
    let map = grid.to_tile_map().map_err(RaysError::Map)?;
    let voxels = ParryVoxels::new(&grid);
    let polyline = ParryPolyline::new(&grid);
    let chains = Box2dChains::new(&grid).map_err(RaysError::Box2d)?;
    let boxes = Box2dBoxes::new(&grid).map_err(RaysError::Box2d)?;
    let ours: Vec<Ray> = rays
        .iter()
        .map(|r| Ray {
            origin: r.origin,
            delta: r.dir * r.length,
        })
        .collect();

    let batch: Vec<Option<f32>> = map
        .cast_rays(&ours, &QueryFilter::default())
        .iter()
        .zip(&rays)
        .map(|(hit, ray)| hit.map(|h| h.t * ray.length))
        .collect();
    let portable = map.cast_rays_portable(&ours, &QueryFilter::default());
    let engines: [(&'static str, &CastFn); 7] = [
        ("tileslide", &|i| batch[i]),
        (ParryVoxels::NAME, &|i| voxels.cast(&rays[i])),
        (ParryPolyline::NAME, &|i| polyline.cast(&rays[i])),
        (Box2dChains::NAME, &|i| chains.cast(&rays[i])),
        (Box2dBoxes::NAME, &|i| boxes.cast(&rays[i])),
        ("tileslide-single", &|i| {
            cast_tileslide(&map, ours[i]).map(|t| t * rays[i].length)
        }),
        ("tileslide-portable", &|i| {
            portable[i].map(|h| h.t * rays[i].length)
        }),
    ];
    let answers: Vec<Vec<Option<f32>>> = engines
        .iter()
        .map(|(_, cast)| (0..rays.len()).map(cast).collect())
        .collect();

    // Timed passes: each engine runs over all rays in a tight loop of its own, so that the
    // closure indirection above is not part of what is measured.
    let total = config.passes * engines.len();
    let mut times = vec![Vec::with_capacity(config.passes); engines.len()];
    let mut hits = Vec::with_capacity(RAYS_PER_CALL);
    let filter = QueryFilter::default();
    for pass in 0..config.passes {
        for (engine, slot) in times.iter_mut().enumerate() {
            let start = Instant::now();
            let checksum = match engine {
                0 => pass_tileslide(&ours, &mut hits, |b, h| map.cast_rays_into(b, &filter, h)),
                1 => pass_peer(&rays, |r| voxels.cast(r)),
                2 => pass_peer(&rays, |r| polyline.cast(r)),
                3 => pass_peer(&rays, |r| chains.cast(r)),
                4 => pass_peer(&rays, |r| boxes.cast(r)),
                5 => pass_tileslide_single(&map, &ours),
                _ => pass_tileslide(&ours, &mut hits, |b, h| {
                    map.cast_rays_portable_into(b, &filter, h);
                }),
            };
            slot.push(start.elapsed().as_secs_f64());
            black_box(checksum);
            progress(pass * engines.len() + engine + 1, total);
        }
    }

    let results = engines
        .iter()
        .zip(&answers)
        .zip(&times)
        .map(|(((name, _), answer), time)| summarize(name, answer, &answers[0], &rays, time))
        .collect();
    Ok(RaysReport {
        scene: config.scene.name(),
        fingerprint,
        rays: rays.len(),
        passes: config.passes,
        results,
    })
}

#[inline(never)]
fn cast_tileslide(map: &TileMap, ray: Ray) -> Option<f32> {
    map.cast_ray(ray, &QueryFilter::default()).map(|h| h.t)
}

/// A pass of a tileslide batch call (`cast_rays_into` or the portable walk's), one block of
/// [`RAYS_PER_CALL`] rays a call.
#[inline(never)]
fn pass_tileslide(
    rays: &[Ray],
    hits: &mut Vec<Option<RayHit>>,
    cast: impl Fn(&[Ray], &mut Vec<Option<RayHit>>),
) -> f32 {
    let mut sum = 0.0;
    for block in rays.chunks(RAYS_PER_CALL) {
        cast(block, hits);
        sum += hits.iter().flatten().map(|h| h.t).sum::<f32>();
    }
    sum
}

#[inline(never)]
fn pass_tileslide_single(map: &TileMap, rays: &[Ray]) -> f32 {
    let filter = QueryFilter::default();
    let mut sum = 0.0;
    for ray in rays {
        if let Some(hit) = map.cast_ray(*ray, &filter) {
            sum += hit.t;
        }
    }
    sum
}

#[inline(never)]
fn pass_peer(rays: &[SceneRay], cast: impl Fn(&SceneRay) -> Option<f32>) -> f32 {
    let mut sum = 0.0;
    for ray in rays {
        if let Some(d) = cast(ray) {
            sum += d;
        }
    }
    sum
}

fn summarize(
    name: &'static str,
    answer: &[Option<f32>],
    reference: &[Option<f32>],
    rays: &[SceneRay],
    times: &[f64],
) -> EngineResult {
    let mut hits = 0;
    let (mut sum_t, mut sum_d) = (0.0f64, 0.0f64);
    for (a, ray) in answer.iter().zip(rays) {
        if let Some(d) = a {
            hits += 1;
            sum_d += f64::from(*d);
            sum_t += f64::from(*d) / f64::from(ray.length);
        }
    }
    let disagreements = answer
        .iter()
        .zip(reference)
        .filter(|(a, b)| match (a, b) {
            (Some(a), Some(b)) => (a - b).abs() > DISAGREEMENT_TOLERANCE,
            (None, None) => false,
            _ => true,
        })
        .count();
    let mut rates: Vec<f64> = times.iter().map(|t| rays.len() as f64 / t / 1e6).collect();
    rates.sort_by(f64::total_cmp);
    let median = rates[rates.len() / 2];
    let per_hit = |s: f64| if hits > 0 { s / hits as f64 } else { 0.0 };
    EngineResult {
        name,
        mrays_per_s: median,
        spread: (rates[0], rates[rates.len() - 1]),
        hits,
        mean_t: per_hit(sum_t),
        mean_distance: per_hit(sum_d),
        disagreements,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_run_reports_every_engine_and_they_agree() {
        let report = run_rays(
            RaysConfig {
                scene: Scene::Dungeon256,
                rays: 5_000,
                passes: 1,
            },
            |_, _| {},
        )
        .unwrap();
        assert_eq!(report.fingerprint, "a36c9fd56f2ba422");
        let names: Vec<_> = report.results.iter().map(|r| r.name).collect();
        assert_eq!(
            names,
            [
                "tileslide",
                "parry2d-voxels",
                "parry2d-polyline",
                "box2d-chains",
                "box2d-boxes",
                "tileslide-single",
                "tileslide-portable"
            ]
        );
        let ours = &report.results[0];
        assert_eq!(ours.disagreements, 0);
        // One ray a call and the portable batch walk give the same answers.
        for other in [5, 6] {
            assert_eq!(report.results[other].disagreements, 0, "{}", names[other]);
            assert_eq!(report.results[other].hits, ours.hits, "{}", names[other]);
        }
        assert!(ours.hits > 4_000 && ours.mean_t > 0.0 && ours.mean_t <= 1.0);
        // The peers agree too: parry's voxels and both Box2D worlds.
        for peer in [1, 3, 4] {
            assert_eq!(report.results[peer].disagreements, 0, "{}", names[peer]);
            assert_eq!(report.results[peer].hits, ours.hits, "{}", names[peer]);
        }
    }

    #[test]
    fn zero_rays_is_an_error() {
        let config = RaysConfig {
            rays: 0,
            ..RaysConfig::default()
        };
        assert!(matches!(run_rays(config, |_, _| {}), Err(RaysError::Empty)));
    }
}
