//! tileslide on one thread and on several (its `parallel` feature), in the same run: the
//! "rays" scene cast in one batch, the "crowd" scene stepped, the "broad" scene's pairs found
//! ([`run_threads`]); and the crowd at a fixed density as it grows, dungeon256 laid `k × k`
//! ([`run_growth`]).
//!
//! Every piece of work runs in a rayon pool of each size in turn, pass after pass, so that
//! machine noise falls on every size alike, and every run's answers are hashed (FNV-1a 64
//! over their bits): the hashes must be equal across thread counts, and a report says
//! whether they are.

use std::time::Instant;

use glam::Vec2;
use rayon::ThreadPool;
use tileslide::broadphase::{PairFinder, PairMethod};
use tileslide::{Aabb, Bodies, BodyDesc, BodyHandle, BodyShape, QueryFilter, Ray, RayHit, TileMap};
use tileslide_scenes::{
    CROWD_RADIUS, Fnv1a, SolidGrid, SplitMix64, TileMapError, audit_crowd, broad_boxes, dungeon256,
    positions_hash, scene_broad, scene_crowd, scene_rays, update_broad,
};

/// What [`run_threads`] runs.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ThreadsConfig {
    /// The pool sizes to compare (the first is the baseline of the speed-ups).
    pub threads: Vec<usize>,
    /// Rays of the "rays" scene on dungeon256, cast in one batch.
    pub rays: usize,
    /// Circles of the "crowd" scene, and the steps each run takes.
    pub crowd: usize,
    /// Steps of each crowd run.
    pub crowd_steps: usize,
    /// Circles of the "broad" scene, and the updates each run takes.
    pub broad: usize,
    /// Updates of each broad run.
    pub broad_updates: usize,
    /// Runs of each piece of work per pool size.
    pub passes: usize,
}

impl Default for ThreadsConfig {
    fn default() -> Self {
        Self {
            threads: vec![1, 2],
            rays: 1_000_000,
            crowd: 50_000,
            crowd_steps: 30,
            broad: 100_000,
            broad_updates: 10,
            passes: 5,
        }
    }
}

/// One piece of work on one pool size.
#[derive(Clone, Debug, PartialEq)]
pub struct ThreadsRow {
    /// `rays`, `crowd` or `broad`.
    pub work: &'static str,
    /// Threads of the pool.
    pub threads: usize,
    /// Median time of one unit (a whole batch of rays, a step, an update), in milliseconds.
    pub ms: f64,
    /// Fastest and slowest unit, in milliseconds.
    pub spread_ms: (f64, f64),
    /// The baseline's median over this one's (the first pool size's row: 1.0).
    pub speedup: f64,
    /// FNV-1a 64 of every answer of the first run (hits, final positions, pairs in order).
    pub checksum: u64,
}

/// [`run_threads`]'s result.
#[derive(Clone, Debug, PartialEq)]
pub struct ThreadsReport {
    /// The configuration run.
    pub config: ThreadsConfig,
    /// Per piece of work, one row per pool size, in the configuration's order.
    pub rows: Vec<ThreadsRow>,
    /// Whether every piece of work gave the same checksum on every pool size.
    pub identical: bool,
    /// Whether the crowd ended clean (no overlap, no circle in a wall) on every pool size.
    pub crowd_clean: bool,
    /// The share of the machine's CPU time that its host took while the runs ran (see
    /// [`CpuTicks::steal_percent`]), in percent; `None` where `/proc/stat` cannot be read.
    pub host_steal_percent: Option<f64>,
}

/// The machine's CPU time so far, in clock ticks, from the first line of `/proc/stat`
/// (Linux): what its processors spent busy (user, nice, system, irq and softirq time) and
/// what a virtual machine's host took from them (steal time).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CpuTicks {
    /// Busy time.
    pub busy: u64,
    /// Steal time.
    pub steal: u64,
}

impl CpuTicks {
    /// The ticks so far, or `None` where `/proc/stat` cannot be read.
    #[must_use]
    pub fn now() -> Option<Self> {
        Self::parse(&std::fs::read_to_string("/proc/stat").ok()?)
    }

    /// The ticks of the `cpu` line of a `/proc/stat` text, or `None` if it has none.
    #[must_use]
    pub fn parse(stat: &str) -> Option<Self> {
        let line = stat.lines().find(|l| l.starts_with("cpu "))?;
        let v: Vec<u64> = line
            .split_whitespace()
            .skip(1)
            .map(|x| x.parse().ok())
            .collect::<Option<_>>()?;
        let field = |k: usize| v.get(k).copied();
        Some(Self {
            busy: field(0)? + field(1)? + field(2)? + field(5)? + field(6)?,
            steal: field(7)?,
        })
    }

    /// [`steal_percent`](Self::steal_percent) from `start` (as [`now`](Self::now) read it
    /// then) to now; `None` when either reading is missing.
    #[must_use]
    pub fn steal_percent_since(start: Option<Self>) -> Option<f64> {
        start
            .zip(Self::now())
            .and_then(|(before, after)| before.steal_percent(after))
    }

    /// Of the CPU time the machine's threads ran or were kept from running by the host
    /// between `self` and `later`, the share the host kept, in percent (`None` when no time
    /// passed). On a shared virtual machine, a run with much steal time is slower by about
    /// that much, and more so with more threads: its figures say less.
    #[must_use]
    pub fn steal_percent(self, later: Self) -> Option<f64> {
        let busy = later.busy.checked_sub(self.busy)?;
        let steal = later.steal.checked_sub(self.steal)?;
        let total = busy + steal;
        (total > 0).then(|| 100.0 * steal as f64 / total as f64)
    }
}

/// Why a benchmark could not run.
#[derive(Debug, thiserror::Error)]
pub enum ThreadsError {
    /// No pool sizes, a pool of zero threads, zero passes, or zero work.
    #[error("{0}")]
    Config(String),
    /// A rayon pool could not be made.
    #[error("cannot make a pool of {threads} threads: {message}")]
    Pool {
        /// The pool's size.
        threads: usize,
        /// rayon's error.
        message: String,
    },
    /// The map could not be built.
    #[error("cannot build the map: {0}")]
    Map(TileMapError),
    /// tileslide refused a body.
    #[error("cannot add a body: {0}")]
    Body(tileslide::BodyError),
}

/// Runs `work` on a rayon pool of one thread, so that tileslide's `parallel` feature (on in
/// the benchmark build) splits nothing: how the peers, which run on one thread, are met.
///
/// # Errors
/// The pool cannot be made (the system refuses a thread).
pub fn on_one_thread<R: Send>(work: impl FnOnce() -> R + Send) -> Result<R, ThreadsError> {
    let pool = pools(&[1])?.pop();
    pool.map(|p| p.install(work))
        .ok_or_else(|| ThreadsError::Config("no pool".into()))
}

/// Most threads a pool may have here: more is a typing error, not a machine.
pub const MAX_THREADS: usize = 256;

fn pools(threads: &[usize]) -> Result<Vec<ThreadPool>, ThreadsError> {
    if threads.is_empty() {
        return Err(ThreadsError::Config("no thread counts given".into()));
    }
    threads
        .iter()
        .map(|&t| {
            if t == 0 || t > MAX_THREADS {
                return Err(ThreadsError::Config(format!(
                    "a pool needs 1 to {MAX_THREADS} threads, not {t}"
                )));
            }
            rayon::ThreadPoolBuilder::new()
                .num_threads(t)
                .build()
                .map_err(|e| ThreadsError::Pool {
                    threads: t,
                    message: e.to_string(),
                })
        })
        .collect()
}

/// The median, fastest and slowest of `times` (not empty).
fn summary(times: &mut [f64]) -> (f64, (f64, f64)) {
    times.sort_by(f64::total_cmp);
    (times[times.len() / 2], (times[0], times[times.len() - 1]))
}

/// Runs the three pieces of work on every pool size; `progress(done, total)` after each run.
///
/// # Errors
/// A bad configuration, a pool that cannot be made, or a scene that cannot be built.
pub fn run_threads(
    config: &ThreadsConfig,
    mut progress: impl FnMut(usize, usize),
) -> Result<ThreadsReport, ThreadsError> {
    if config.passes == 0 || config.rays == 0 || config.crowd == 0 || config.broad == 0 {
        return Err(ThreadsError::Config(
            "every piece of work needs at least one ray, circle and pass".into(),
        ));
    }
    if config.crowd_steps == 0 || config.broad_updates == 0 {
        return Err(ThreadsError::Config(
            "the crowd and the broad scene need at least one step".into(),
        ));
    }
    let pools = pools(&config.threads)?;
    let grid = dungeon256();
    let map = grid.to_tile_map().map_err(ThreadsError::Map)?;
    let rays: Vec<Ray> = scene_rays(&grid, config.rays)
        .iter()
        .map(|r| Ray {
            origin: r.origin,
            delta: r.dir * r.length,
        })
        .collect();
    let crowd = scene_crowd(&grid, config.crowd);
    let total = 3 * config.passes * pools.len();
    let mut done = 0;
    let n = pools.len();
    // Per pool: the times, and the first run's checksum.
    let mut rays_times = vec![Vec::new(); n];
    let mut crowd_times = vec![Vec::new(); n];
    let mut broad_times = vec![Vec::new(); n];
    let mut sums = [vec![None; n], vec![None; n], vec![None; n]];
    let mut crowd_clean = true;
    // The answers' buffer, reused from pass to pass as a game reuses its own (a fresh one
    // is 40 MB of page faults).
    let mut hits = Vec::new();
    let ticks = CpuTicks::now();
    for _ in 0..config.passes {
        for (p, pool) in pools.iter().enumerate() {
            let (ms, sum) = pool.install(|| cast(&map, &rays, &mut hits));
            rays_times[p].push(ms);
            sums[0][p].get_or_insert(sum);
            done += 1;
            progress(done, total);
            let (times, positions) =
                pool.install(|| step_crowd(&map, &crowd, config.crowd_steps))?;
            crowd_times[p].extend(times);
            crowd_clean &= audit_crowd(&grid, &positions, CROWD_RADIUS).is_clean();
            sums[1][p].get_or_insert(positions_hash(&positions));
            done += 1;
            progress(done, total);
            let (times, sum) = pool.install(|| find_broad(config.broad, config.broad_updates));
            broad_times[p].extend(times);
            sums[2][p].get_or_insert(sum);
            done += 1;
            progress(done, total);
        }
    }
    let mut rows = Vec::new();
    for (work, times, sums) in [
        ("rays", &mut rays_times, &sums[0]),
        ("crowd", &mut crowd_times, &sums[1]),
        ("broad", &mut broad_times, &sums[2]),
    ] {
        let medians: Vec<(f64, (f64, f64))> = times.iter_mut().map(|t| summary(t)).collect();
        for (p, &threads) in config.threads.iter().enumerate() {
            rows.push(ThreadsRow {
                work,
                threads,
                ms: medians[p].0,
                spread_ms: medians[p].1,
                speedup: medians[0].0 / medians[p].0,
                checksum: sums[p].unwrap_or_default(),
            });
        }
    }
    let identical = sums.iter().all(|s| s.iter().all(|x| *x == s[0]));
    let host_steal_percent = CpuTicks::steal_percent_since(ticks);
    Ok(ThreadsReport {
        config: config.clone(),
        rows,
        identical,
        crowd_clean,
        host_steal_percent,
    })
}

/// Casts every ray in one batch into `hits`: the time in milliseconds and the answers'
/// checksum.
fn cast(map: &TileMap, rays: &[Ray], hits: &mut Vec<Option<RayHit>>) -> (f64, u64) {
    let start = Instant::now();
    map.cast_rays_into(rays, &QueryFilter::default(), hits);
    let ms = start.elapsed().as_secs_f64() * 1e3;
    let mut hash = Fnv1a::new();
    for hit in hits.iter() {
        match hit {
            Some(h) => {
                hash.write_f32(h.t);
                hash.write_f32(h.point.x);
                hash.write_f32(h.point.y);
            }
            None => hash.write_u8(0),
        }
    }
    (ms, hash.finish())
}

/// Steps the crowd: each step's time in milliseconds, and the final positions.
fn step_crowd(
    map: &TileMap,
    crowd: &[tileslide_scenes::CrowdBody],
    steps: usize,
) -> Result<(Vec<f64>, Vec<Vec2>), ThreadsError> {
    let moves: Vec<(Vec2, Vec2)> = crowd.iter().map(|b| (b.position, b.velocity)).collect();
    let (mut bodies, handles) = place(&moves)?;
    let mut times = Vec::with_capacity(steps);
    for _ in 0..steps {
        times.push(step(&mut bodies, &handles, map)?);
    }
    let positions = positions(&bodies, &handles);
    Ok((times, positions))
}

/// A set of circles of the crowd's radius at the given positions; the handles with their
/// velocities.
fn place(crowd: &[(Vec2, Vec2)]) -> Result<(Bodies, Vec<(BodyHandle, Vec2)>), ThreadsError> {
    let mut bodies = Bodies::new();
    let shape = BodyShape::circle(CROWD_RADIUS).map_err(ThreadsError::Body)?;
    let mut handles = Vec::with_capacity(crowd.len());
    for &(position, velocity) in crowd {
        let handle = bodies
            .add(BodyDesc::new(position, shape.clone()))
            .map_err(ThreadsError::Body)?;
        handles.push((handle, velocity));
    }
    Ok((bodies, handles))
}

/// One step, every body proposing its velocity: its time in milliseconds.
fn step(
    bodies: &mut Bodies,
    handles: &[(BodyHandle, Vec2)],
    map: &TileMap,
) -> Result<f64, ThreadsError> {
    let start = Instant::now();
    for &(h, v) in handles {
        bodies.propose(h, v).map_err(ThreadsError::Body)?;
    }
    bodies.step(map);
    Ok(start.elapsed().as_secs_f64() * 1e3)
}

fn positions(bodies: &Bodies, handles: &[(BodyHandle, Vec2)]) -> Vec<Vec2> {
    handles
        .iter()
        .filter_map(|&(h, _)| bodies.get(h).ok().map(|b| b.position()))
        .collect()
}

/// The broad scene's updates with tileslide's uniform grid: each update's time (moving the
/// circles, their boxes, the pairs) in milliseconds, and the checksum of every update's pairs
/// in the finder's order.
fn find_broad(n: usize, updates: usize) -> (Vec<f64>, u64) {
    let mut circles = scene_broad(n);
    let mut finder = PairFinder::default();
    let mut boxes: Vec<Aabb> = Vec::new();
    let mut pairs = Vec::new();
    let mut hash = Fnv1a::new();
    let mut times = Vec::with_capacity(updates);
    for _ in 0..updates {
        let start = Instant::now();
        update_broad(&mut circles);
        broad_boxes(&circles, &mut boxes);
        pairs.clear();
        finder.find(PairMethod::UniformGrid, &boxes, &mut pairs);
        times.push(start.elapsed().as_secs_f64() * 1e3);
        for &(i, j) in &pairs {
            hash.write_u32(i);
            hash.write_u32(j);
        }
    }
    (times, hash.finish())
}

/// What [`run_growth`] runs.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GrowthConfig {
    /// Circles per copy of dungeon256 (the first `n` of the crowd scene).
    pub n: usize,
    /// The layouts: `k × k` copies each.
    pub ks: Vec<usize>,
    /// The pool sizes.
    pub threads: Vec<usize>,
    /// Steps per run.
    pub steps: usize,
    /// Runs of each layout on each pool, interleaved (every layout and pool once, then
    /// again): the median step is over every step of every pass, so a burst of noise on a
    /// shared machine falls on all the layouts alike rather than on one.
    pub passes: usize,
}

impl Default for GrowthConfig {
    fn default() -> Self {
        Self {
            n: 10_000,
            ks: vec![1, 2, 3, 4],
            threads: vec![1, 2],
            steps: 20,
            passes: 3,
        }
    }
}

/// What [`run_growth`] measured.
#[derive(Clone, Debug, PartialEq)]
pub struct GrowthReport {
    /// One row per layout and pool size, layouts in the order given.
    pub rows: Vec<GrowthRow>,
    /// The share of the machine's CPU time that its host took while the runs ran (see
    /// [`CpuTicks::steal_percent`]), in percent; `None` where `/proc/stat` cannot be read.
    pub host_steal_percent: Option<f64>,
}

/// One layout on one pool size.
#[derive(Clone, Debug, PartialEq)]
pub struct GrowthRow {
    /// Copies per side.
    pub k: usize,
    /// Bodies in all.
    pub bodies: usize,
    /// Threads of the pool.
    pub threads: usize,
    /// Median step over every pass, in milliseconds.
    pub ms_per_step: f64,
    /// The fastest and the slowest pass's median step, in milliseconds.
    pub ms_range: (f64, f64),
    /// The median step per body, in microseconds.
    pub us_per_body: f64,
    /// This row's cost per body over the first layout's on the same pool size.
    pub growth: f64,
    /// What the process's resident memory grew by while the bodies were added and stepped in
    /// the first pass, per body, in bytes (`None` where `/proc/self/statm` cannot be read).
    pub bytes_per_body: Option<f64>,
    /// FNV-1a 64 of the final positions.
    pub checksum: u64,
}

/// Largest `k` [`run_growth`] lays out (8 × 8 copies: 2048 × 2048 cells).
pub const MAX_K: usize = 8;

/// Runs the crowd at the density of the scene with `n` circles on `k × k` copies of
/// dungeon256, for each `k` and pool size, `passes` times over; `progress(done, total)`
/// after each run.
///
/// # Errors
/// A bad configuration, a pool that cannot be made, a scene that cannot be built, or a run
/// whose final positions differ from the first pass's (which would be a bug).
pub fn run_growth(
    config: &GrowthConfig,
    mut progress: impl FnMut(usize, usize),
) -> Result<GrowthReport, ThreadsError> {
    if config.n == 0 || config.steps == 0 || config.passes == 0 || config.ks.is_empty() {
        return Err(ThreadsError::Config(
            "growth needs circles, steps, passes and at least one k".into(),
        ));
    }
    if let Some(&k) = config.ks.iter().find(|&&k| k == 0 || k > MAX_K) {
        return Err(ThreadsError::Config(format!(
            "k must be 1 to {MAX_K}, not {k}"
        )));
    }
    let pools = pools(&config.threads)?;
    let tile = dungeon256();
    let scene = scene_crowd(&tile, config.n);
    let layouts = config
        .ks
        .iter()
        .map(|&k| {
            let map = laid(&tile, k).to_tile_map().map_err(ThreadsError::Map)?;
            Ok((map, copies(&tile, &scene, k)))
        })
        .collect::<Result<Vec<_>, ThreadsError>>()?;
    let runs = layouts.len() * pools.len();
    // Per run (layout, then pool): every step's time, each pass's median, the memory per
    // body and the checksum of the first pass.
    let mut times: Vec<Vec<f64>> = vec![Vec::new(); runs];
    let mut medians: Vec<Vec<f64>> = vec![Vec::new(); runs];
    let mut first: Vec<(Option<f64>, u64)> = Vec::with_capacity(runs);
    let ticks = CpuTicks::now();
    for pass in 0..config.passes {
        for (l, (map, crowd)) in layouts.iter().enumerate() {
            for (p, pool) in pools.iter().enumerate() {
                let run = l * pools.len() + p;
                let before = resident_bytes();
                let (mut steps, checksum, after) = pool.install(|| {
                    let (mut bodies, handles) = place(crowd)?;
                    let steps = (0..config.steps)
                        .map(|_| step(&mut bodies, &handles, map))
                        .collect::<Result<Vec<f64>, _>>()?;
                    let after = resident_bytes();
                    let checksum = positions_hash(&positions(&bodies, &handles));
                    Ok::<_, ThreadsError>((steps, checksum, after))
                })?;
                let bytes = before
                    .zip(after)
                    .map(|(b, a)| a.saturating_sub(b) as f64 / crowd.len() as f64);
                if pass == 0 {
                    first.push((bytes, checksum));
                } else if first[run].1 != checksum {
                    return Err(ThreadsError::Config(format!(
                        "k = {} on {} threads ended elsewhere in pass {} than in the first",
                        config.ks[l],
                        config.threads[p],
                        pass + 1
                    )));
                }
                times[run].extend_from_slice(&steps);
                medians[run].push(summary(&mut steps).0);
                progress(pass * runs + run + 1, config.passes * runs);
            }
        }
    }
    let host_steal_percent = CpuTicks::steal_percent_since(ticks);
    let mut rows: Vec<GrowthRow> = Vec::with_capacity(runs);
    let each = times.iter_mut().zip(&mut medians).zip(first);
    for (run, ((times, medians), (bytes_per_body, checksum))) in each.enumerate() {
        let (l, p) = (run / pools.len(), run % pools.len());
        let bodies = layouts[l].1.len();
        let (median, _) = summary(times);
        let (_, ms_range) = summary(medians);
        let us_per_body = median * 1e3 / bodies as f64;
        let base = rows
            .iter()
            .find(|r| r.threads == config.threads[p])
            .map_or(us_per_body, |r| r.us_per_body);
        rows.push(GrowthRow {
            k: config.ks[l],
            bodies,
            threads: config.threads[p],
            ms_per_step: median,
            ms_range,
            us_per_body,
            growth: us_per_body / base,
            bytes_per_body,
            checksum,
        });
    }
    Ok(GrowthReport {
        rows,
        host_steal_percent,
    })
}

/// `tile` laid `k × k` times side by side.
#[must_use]
pub fn laid(tile: &SolidGrid, k: usize) -> SolidGrid {
    let side = tile.width * k;
    SolidGrid {
        width: side,
        height: tile.height * k,
        solid: (0..tile.height * k)
            .flat_map(|y| (0..side).map(move |x| (x, y)))
            .map(|(x, y)| tile.solid[(y % tile.height) * tile.width + x % tile.width])
            .collect(),
    }
}

/// The scene's circles copied into each of the `k × k` tiles, in a shuffled slot order (a
/// game adds bodies in no spatial order): positions and velocities.
#[must_use]
pub fn copies(
    tile: &SolidGrid,
    scene: &[tileslide_scenes::CrowdBody],
    k: usize,
) -> Vec<(Vec2, Vec2)> {
    let mut crowd = Vec::with_capacity(k * k * scene.len());
    for copy in 0..k * k {
        let offset = Vec2::new(
            ((copy % k) * tile.width) as f32,
            ((copy / k) * tile.height) as f32,
        );
        crowd.extend(scene.iter().map(|b| (b.position + offset, b.velocity)));
    }
    let mut rng = SplitMix64::new(0x7115_0000_0000_0005);
    for i in (1..crowd.len()).rev() {
        let j = rng.below(i as u64 + 1) as usize;
        crowd.swap(i, j);
    }
    crowd
}

/// The process's resident memory in bytes, from `/proc/self/statm` (Linux), or `None`.
fn resident_bytes() -> Option<u64> {
    let statm = std::fs::read_to_string("/proc/self/statm").ok()?;
    let pages: u64 = statm.split_whitespace().nth(1)?.parse().ok()?;
    Some(pages * 4096)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The `cpu` line's busy fields (user, nice, system, irq, softirq) and steal, whatever
    /// the lines around it; the steal share of busy plus steal between two readings.
    #[test]
    fn cpu_ticks_read_busy_and_steal_time_from_proc_stat() {
        let stat = "cpu  100 5 20 900 7 3 2 30 0 0\ncpu0 50 2 10 450 3 1 1 15 0 0\nintr 1 2\n";
        let before = CpuTicks::parse(stat).unwrap();
        assert_eq!(
            before,
            CpuTicks {
                busy: 130,
                steal: 30
            }
        );
        let after = CpuTicks::parse("cpu  190 5 30 950 7 3 2 70 0 0\n").unwrap();
        assert_eq!(
            after,
            CpuTicks {
                busy: 230,
                steal: 70
            }
        );
        let share = before.steal_percent(after).unwrap();
        assert!((share - 100.0 * 40.0 / 140.0).abs() < 1e-9, "{share}");
        assert_eq!(before.steal_percent(before), None);
        assert_eq!(CpuTicks::parse("intr 1 2\n"), None);
        assert_eq!(CpuTicks::parse("cpu  1 2 3\n"), None);
    }

    #[test]
    fn a_small_run_is_identical_on_every_pool_size() {
        let config = ThreadsConfig {
            threads: vec![1, 2, 3],
            rays: 20_000,
            crowd: 3_000,
            crowd_steps: 3,
            broad: 9_000,
            broad_updates: 2,
            passes: 1,
        };
        let report = run_threads(&config, |_, _| {}).unwrap();
        assert_eq!(report.rows.len(), 9);
        assert!(report.identical, "{:?}", report.rows);
        assert!(report.crowd_clean);
        assert_eq!(report.rows[0].speedup, 1.0);
    }

    #[test]
    fn growth_lays_copies_and_counts_every_body() {
        let config = GrowthConfig {
            n: 500,
            ks: vec![1, 2],
            threads: vec![1, 2],
            steps: 2,
            passes: 2,
        };
        let rows = run_growth(&config, |_, _| {}).unwrap().rows;
        let bodies: Vec<_> = rows.iter().map(|r| (r.k, r.bodies, r.threads)).collect();
        assert_eq!(
            bodies,
            [(1, 500, 1), (1, 500, 2), (2, 2_000, 1), (2, 2_000, 2)]
        );
        assert_eq!(rows[0].checksum, rows[1].checksum);
        assert_eq!(rows[2].checksum, rows[3].checksum);
        assert_eq!(rows[0].growth, 1.0);
    }

    #[test]
    fn bad_configurations_are_refused_with_what_is_wrong() {
        let zero = ThreadsConfig {
            threads: vec![1, 0],
            ..ThreadsConfig::default()
        };
        let err = run_threads(&zero, |_, _| {}).unwrap_err().to_string();
        assert!(err.contains("not 0"), "{err}");
        let big = GrowthConfig {
            ks: vec![9],
            ..GrowthConfig::default()
        };
        let err = run_growth(&big, |_, _| {}).unwrap_err().to_string();
        assert!(err.contains("k must be 1 to 8, not 9"), "{err}");
    }
}
