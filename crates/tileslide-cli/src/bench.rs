//! `tileslide bench`.

use anyhow::{Result, anyhow};
use clap::Subcommand;
use indicatif::{ProgressBar, ProgressStyle};
use serde_json::json;
use tileslide_bench::broad::{BroadResult, contenders, run_broad};
use tileslide_bench::crowd::{
    Box2dMoverCrowd, CrowdContender, CrowdResult, ParrySegmentsCrowd, ParryVoxelsCrowd,
    RapierCrowd, TileslideCrowd, run_crowd,
};
use tileslide_bench::paths::{
    PATHS_QUERIES, PATHS_RADII, PathScene, PathsResult, contenders as path_contenders,
    count_mismatches, run_paths,
};
use tileslide_bench::rays::{RaysConfig, RaysReport, run_rays};
use tileslide_bench::threads::{
    GrowthConfig, GrowthRow, ThreadsConfig, ThreadsReport, on_one_thread, run_growth, run_threads,
};
use tileslide_scenes::{
    BROAD_RADIUS, CROWD_RADIUS, CrowdBody, Scene, SolidGrid, dungeon256, scene_crowd,
};

use crate::json::number;

#[derive(Subcommand, Debug)]
pub enum BenchCommand {
    /// The "rays" scene: 1,000,000 rays on dungeon256 or open256, tileslide vs parry2d and
    /// Box2D.
    Rays {
        /// The map: dungeon256 or open256.
        #[arg(long, default_value = "dungeon256", value_parser = parse_scene)]
        scene: Scene,
        /// How many rays (the first N of the scene).
        #[arg(long, default_value_t = 1_000_000, value_parser = clap::value_parser!(u64).range(1..=100_000_000))]
        n: u64,
        /// Timed passes per engine; the median is reported.
        #[arg(long, default_value_t = 7, value_parser = clap::value_parser!(u64).range(1..=1000))]
        passes: u64,
        /// Print one JSON object.
        #[arg(long)]
        json: bool,
    },
    /// The "crowd" scene: N circles sliding through dungeon256, tileslide vs parry2d shape
    /// casts (walls as voxels and as segments), rapier2d's character controller and Box2D's
    /// character mover.
    Crowd {
        /// Number of circles (BENCHMARKS.md: 1000, 10000, 50000).
        #[arg(long, default_value_t = 10_000, value_parser = clap::value_parser!(u64).range(1..=74_276))]
        n: u64,
        /// Steps (default: 100, or 30 from 50,000 circles as in BENCHMARKS.md).
        #[arg(long, value_parser = clap::value_parser!(u64).range(1..=100_000))]
        steps: Option<u64>,
        /// Print one JSON object.
        #[arg(long)]
        json: bool,
    },
    /// The "broad" scene: N circles bouncing in a square, every pair of overlapping boxes
    /// each update; tileslide's sweep and prune and grid vs parry2d's Bvh, rapier2d's broad
    /// phase and Box2D's dynamic tree.
    Broad {
        /// Number of circles (BENCHMARKS.md: 100000).
        #[arg(long, default_value_t = 100_000, value_parser = clap::value_parser!(u64).range(1..=10_000_000))]
        n: u64,
        /// Timed updates per contender; the median is reported.
        #[arg(long, default_value_t = 10, value_parser = clap::value_parser!(u64).range(1..=10_000))]
        updates: u64,
        /// Print one JSON object.
        #[arg(long)]
        json: bool,
    },
    /// tileslide alone on one thread and on several (its `parallel` feature), in one run:
    /// the rays scene cast in one batch, the crowd stepped, the broad scene's pairs; with
    /// the speed-ups and whether every answer is the same bit for bit.
    Threads {
        /// The pool sizes to compare, the first the baseline (comma-separated).
        #[arg(long, default_value = "1,2", value_delimiter = ',', value_parser = clap::value_parser!(u64).range(1..=256))]
        threads: Vec<u64>,
        /// Rays of the rays scene on dungeon256, cast in one batch.
        #[arg(long, default_value_t = 1_000_000, value_parser = clap::value_parser!(u64).range(1..=100_000_000))]
        rays: u64,
        /// Circles of the crowd scene.
        #[arg(long, default_value_t = 50_000, value_parser = clap::value_parser!(u64).range(1..=74_276))]
        crowd: u64,
        /// Steps of each crowd run.
        #[arg(long, default_value_t = 30, value_parser = clap::value_parser!(u64).range(1..=100_000))]
        steps: u64,
        /// Circles of the broad scene.
        #[arg(long, default_value_t = 100_000, value_parser = clap::value_parser!(u64).range(1..=10_000_000))]
        broad: u64,
        /// Runs of each piece of work per pool size, interleaved; the median is reported.
        #[arg(long, default_value_t = 5, value_parser = clap::value_parser!(u64).range(1..=1000))]
        passes: u64,
        /// Print one JSON object.
        #[arg(long)]
        json: bool,
    },
    /// The crowd at a fixed density as it grows: dungeon256 laid k × k, each copy holding
    /// the crowd scene's first N circles, on one thread and on several; the cost per body
    /// and the memory per body.
    Growth {
        /// Circles per copy of dungeon256.
        #[arg(long, default_value_t = 10_000, value_parser = clap::value_parser!(u64).range(1..=74_276))]
        n: u64,
        /// The layouts, k × k copies each (comma-separated, 1 to 8).
        #[arg(long, default_value = "1,2,3,4", value_delimiter = ',', value_parser = clap::value_parser!(u64).range(1..=8))]
        k: Vec<u64>,
        /// The pool sizes (comma-separated).
        #[arg(long, default_value = "1,2", value_delimiter = ',', value_parser = clap::value_parser!(u64).range(1..=256))]
        threads: Vec<u64>,
        /// Steps per run.
        #[arg(long, default_value_t = 20, value_parser = clap::value_parser!(u64).range(1..=100_000))]
        steps: u64,
        /// Runs of each layout on each pool size, interleaved; the median step over all of
        /// them is reported.
        #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u64).range(1..=1000))]
        passes: u64,
        /// Print one JSON object.
        #[arg(long)]
        json: bool,
    },
    /// The "paths" scene: paths for circles of radius 0.3 and 0.8 between random free
    /// nodes of dungeon256's navigation lattice; tileslide's find_path (A* and smoothing)
    /// vs the pathfinding crate's A* on the same graph.
    Paths {
        /// Queries per radius.
        #[arg(long, default_value_t = PATHS_QUERIES as u64, value_parser = clap::value_parser!(u64).range(1..=10_000_000))]
        queries: u64,
        /// Print one JSON object.
        #[arg(long)]
        json: bool,
    },
}

fn parse_scene(name: &str) -> Result<Scene, String> {
    Scene::from_name(name)
        .ok_or_else(|| format!("unknown scene {name:?}: expected dungeon256 or open256"))
}

pub fn run(which: BenchCommand) -> Result<()> {
    if cfg!(debug_assertions) {
        eprintln!(
            "warning: this is a debug build; benchmark figures are only meaningful with --release"
        );
    }
    // The peers run on one thread, so tileslide does too (its `parallel` feature is on in
    // this build, for `bench threads` and `bench growth`).
    let which = match which {
        BenchCommand::Threads {
            threads,
            rays,
            crowd,
            steps,
            broad,
            passes,
            json,
        } => {
            let config = ThreadsConfig {
                threads: threads.iter().map(|&t| t as usize).collect(),
                rays: rays as usize,
                crowd: crowd as usize,
                crowd_steps: steps as usize,
                broad: broad as usize,
                passes: passes as usize,
                ..ThreadsConfig::default()
            };
            return threads_bench(&config, json);
        }
        BenchCommand::Growth {
            n,
            k,
            threads,
            steps,
            passes,
            json,
        } => {
            let config = GrowthConfig {
                n: n as usize,
                ks: k.iter().map(|&k| k as usize).collect(),
                threads: threads.iter().map(|&t| t as usize).collect(),
                steps: steps as usize,
                passes: passes as usize,
            };
            return growth(&config, json);
        }
        other => other,
    };
    on_one_thread(|| single_threaded(which))?
}

/// The benchmarks against the peers, on the calling thread.
fn single_threaded(which: BenchCommand) -> Result<()> {
    match which {
        BenchCommand::Threads { .. } | BenchCommand::Growth { .. } => Ok(()),
        BenchCommand::Crowd { n, steps, json } => crowd(n as usize, steps, json),
        BenchCommand::Broad { n, updates, json } => broad(n as usize, updates as usize, json),
        BenchCommand::Paths { queries, json } => paths(queries as usize, json),
        BenchCommand::Rays {
            scene,
            n,
            passes,
            json,
        } => {
            let config = RaysConfig {
                scene,
                rays: n as usize,
                passes: passes as usize,
            };
            // Hidden automatically when stderr is not a terminal.
            let bar = ProgressBar::new(0);
            if let Ok(style) = ProgressStyle::with_template("{msg} [{bar:30}] {pos}/{len} passes") {
                bar.set_style(style.progress_chars("=> "));
            }
            bar.set_message(format!("bench rays {}", scene.name()));
            let report = run_rays(config, |done, total| {
                bar.set_length(total as u64);
                bar.set_position(done as u64);
            })
            .map_err(|e| anyhow!("{e}"))?;
            bar.finish_and_clear();
            if json {
                println!("{}", rays_json(&report));
            } else {
                print_rays_table(&report);
            }
            Ok(())
        }
    }
}

/// Builds one crowd contender.
type MakeContender = fn(&SolidGrid, &[CrowdBody], f32) -> Result<Box<dyn CrowdContender>>;

fn crowd(n: usize, steps: Option<u64>, json: bool) -> Result<()> {
    let steps = steps.map_or(if n >= 50_000 { 30 } else { 100 }, |s| s as usize);
    let grid = dungeon256();
    let bodies = scene_crowd(&grid, n);
    let contenders: [MakeContender; 5] = [
        |g, b, r| Ok(Box::new(TileslideCrowd::new(g, b, r)?)),
        |g, b, r| Ok(Box::new(ParryVoxelsCrowd::new(g, b, r))),
        |g, b, r| Ok(Box::new(ParrySegmentsCrowd::new(g, b, r))),
        |g, b, r| Ok(Box::new(RapierCrowd::new(g, b, r))),
        |g, b, r| Ok(Box::new(Box2dMoverCrowd::new(g, b, r)?)),
    ];
    let results: Vec<CrowdResult> = with_progress(contenders.to_vec(), |make, bar| {
        let mut contender = make(&grid, &bodies, CROWD_RADIUS)?;
        bar.set_message(format!("bench crowd N = {n}: {}", contender.name()));
        Ok(run_crowd(contender.as_mut(), &grid, steps, CROWD_RADIUS))
    })?;
    if json {
        let list: Vec<_> = results
            .iter()
            .map(|r| {
                json!({
                    "name": r.name,
                    "ms_per_step": r.ms_per_step,
                    "audit": {
                        "overlapping_pairs": r.audit.overlapping_pairs,
                        "wall_penetrations": r.audit.wall_penetrations,
                        "max_overlap": r.audit.max_overlap,
                        "max_penetration": r.audit.max_penetration,
                    },
                    "mean_travel": r.mean_travel,
                })
            })
            .collect();
        println!(
            "{}",
            json!({"scene": "crowd", "map": "dungeon256", "n": bodies.len(), "steps": steps, "results": list})
        );
        return Ok(());
    }
    println!(
        "crowd on dungeon256: {} circles of radius {CROWD_RADIUS}, {steps} steps, median step time",
        bodies.len()
    );
    println!(
        "{:<18} {:>9} {:>21} {:>9} {:>9} {:>12}",
        "engine", "ms/step", "(fastest–slowest)", "overlaps", "in walls", "mean travel"
    );
    for r in &results {
        println!(
            "{:<18} {:>9.3} {:>21} {:>9} {:>9} {:>12.3}",
            r.name,
            r.ms_per_step,
            format!("({:.3}–{:.3})", r.spread_ms.0, r.spread_ms.1),
            r.audit.overlapping_pairs,
            r.audit.wall_penetrations,
            r.mean_travel
        );
    }
    print_ratio(&results, |r| 1.0 / r.ms_per_step, |r| r.name);
    Ok(())
}

fn broad(n: usize, updates: usize, json: bool) -> Result<()> {
    let results: Vec<BroadResult> = with_progress(contenders(), |mut contender, bar| {
        bar.set_message(format!("bench broad N = {n}: {}", contender.name()));
        Ok(run_broad(contender.as_mut(), n, updates))
    })?;
    if json {
        let list: Vec<_> = results
            .iter()
            .map(|r| {
                json!({
                    "name": r.name,
                    "ms_per_update": r.ms_per_update,
                    "fastest_ms": r.spread_ms.0,
                    "slowest_ms": r.spread_ms.1,
                    "pairs": r.pairs,
                    "exact": r.exact,
                })
            })
            .collect();
        println!(
            "{}",
            json!({"scene": "broad", "n": n, "updates": updates, "radius": BROAD_RADIUS, "results": list})
        );
        return Ok(());
    }
    println!("broad: {n} circles of radius {BROAD_RADIUS}, {updates} updates, median update time");
    println!(
        "{:<18} {:>10} {:>21} {:>9} {:>6}",
        "engine", "ms/update", "(fastest–slowest)", "pairs", "exact"
    );
    for r in &results {
        println!(
            "{:<18} {:>10.3} {:>21} {:>9} {:>6}",
            r.name,
            r.ms_per_update,
            format!("({:.3}–{:.3})", r.spread_ms.0, r.spread_ms.1),
            r.pairs,
            if r.exact { "yes" } else { "NO" }
        );
    }
    if results.iter().any(|r| !r.exact) {
        println!(
            "NO marks a contender whose pairs differ from brute force: its time means nothing"
        );
    }
    print_ratio(&results, |r| 1.0 / r.ms_per_update, |r| r.name.as_str());
    Ok(())
}

fn paths(n: usize, json: bool) -> Result<()> {
    let scene = PathScene::dungeon256().map_err(|e| anyhow!("dungeon256: {e}"))?;
    let mut runs = Vec::new();
    for radius in PATHS_RADII {
        let queries = scene.queries(radius, n).map_err(|e| anyhow!("{e}"))?;
        for contender in path_contenders(&scene) {
            runs.push((radius, contender, queries.clone()));
        }
    }
    let mut results: Vec<PathsResult> =
        with_progress(runs, |(radius, mut contender, queries), bar| {
            bar.set_message(format!("bench paths r = {radius}: {}", contender.name()));
            run_paths(contender.as_mut(), &scene, radius, &queries).map_err(|e| anyhow!("{e}"))
        })?;
    count_mismatches(&mut results);
    if json {
        let list: Vec<_> = results
            .iter()
            .map(|r| {
                json!({
                    "radius": number(r.radius),
                    "name": r.name,
                    "ms_total": r.ms_total,
                    "us_per_query": r.us_per_query,
                    "found": r.found,
                    "mean_length": r.mean_length,
                    "mismatches": r.mismatches,
                })
            })
            .collect();
        println!(
            "{}",
            json!({"scene": "paths", "queries": n, "results": list})
        );
        return Ok(());
    }
    println!(
        "paths on dungeon256: {n} queries per radius between random free lattice nodes, single thread"
    );
    println!(
        "{:<6} {:<18} {:>10} {:>9} {:>7} {:>12} {:>10}",
        "radius", "engine", "ms total", "µs/query", "found", "mean length", "mismatches"
    );
    for r in &results {
        println!(
            "{:<6} {:<18} {:>10.3} {:>9.2} {:>7} {:>12.3} {:>10}",
            r.radius, r.name, r.ms_total, r.us_per_query, r.found, r.mean_length, r.mismatches
        );
    }
    println!(
        "mean length: tileslide's paths smoothed into straight runs, the peer's as found on the lattice"
    );
    if results.iter().any(|r| r.mismatches > 0) {
        println!(
            "mismatches: queries on which a contender and tileslide disagree about whether a path exists; they must be 0"
        );
    }
    for radius in PATHS_RADII {
        let group: Vec<&PathsResult> = results.iter().filter(|r| r.radius == radius).collect();
        print!("radius {radius}: ");
        print_ratio(&group, |r| 1.0 / r.ms_total, |r| r.name);
    }
    Ok(())
}

fn rays_json(report: &RaysReport) -> serde_json::Value {
    let results: Vec<_> = report
        .results
        .iter()
        .map(|r| {
            json!({
                "name": r.name,
                "mrays_per_s": r.mrays_per_s,
                "min_mrays_per_s": r.spread.0,
                "max_mrays_per_s": r.spread.1,
                "hits": r.hits,
                "mean_t": r.mean_t,
                "mean_distance": r.mean_distance,
                "disagreements": r.disagreements,
            })
        })
        .collect();
    json!({
        "scene": report.scene,
        "fingerprint": report.fingerprint,
        "rays": report.rays,
        "passes": report.passes,
        "results": results,
    })
}

fn print_rays_table(report: &RaysReport) {
    println!(
        "scene {} (fingerprint {}), {} rays, median of {} passes, single thread",
        report.scene, report.fingerprint, report.rays, report.passes
    );
    println!(
        "{:<18} {:>9} {:>17} {:>9} {:>8} {:>10} {:>13}",
        "engine", "Mrays/s", "(slowest–fastest)", "hits", "mean t", "mean dist", "disagreements"
    );
    for r in &report.results {
        println!(
            "{:<18} {:>9.2} {:>17} {:>9} {:>8.4} {:>10.4} {:>13}",
            r.name,
            r.mrays_per_s,
            format!("({:.2}–{:.2})", r.spread.0, r.spread.1),
            r.hits,
            r.mean_t,
            r.mean_distance,
            r.disagreements
        );
    }
    print_ratio(&report.results, |r| r.mrays_per_s, |r| r.name);
}

/// Runs `run` on each contender in turn under a progress bar (hidden when stderr is not a
/// terminal; `run` sets its message), and collects the results.
fn with_progress<C, R>(
    contenders: Vec<C>,
    mut run: impl FnMut(C, &ProgressBar) -> Result<R>,
) -> Result<Vec<R>> {
    let bar = ProgressBar::new(contenders.len() as u64);
    if let Ok(style) = ProgressStyle::with_template("{msg} [{bar:30}] {pos}/{len} contenders") {
        bar.set_style(style.progress_chars("=> "));
    }
    let mut results = Vec::with_capacity(contenders.len());
    for contender in contenders {
        results.push(run(contender, &bar)?);
        bar.inc(1);
    }
    bar.finish_and_clear();
    Ok(results)
}

/// Prints how many times faster tileslide's fastest entry (names starting with
/// "tileslide") is than the fastest peer (the others), by `speed` (larger is faster).
fn print_ratio<T>(results: &[T], speed: impl Fn(&T) -> f64, name: impl Fn(&T) -> &str) {
    let fastest = |ours: bool| {
        results
            .iter()
            .filter(|r| name(r).starts_with("tileslide") == ours)
            .max_by(|a, b| speed(a).total_cmp(&speed(b)))
    };
    if let (Some(ours), Some(best)) = (fastest(true), fastest(false)) {
        println!(
            "{}: {:.1}× the fastest peer ({}) in this run",
            name(ours),
            speed(ours) / speed(best),
            name(best)
        );
    }
}

/// A progress bar counting runs (hidden when stderr is not a terminal).
fn runs_bar(message: &'static str) -> ProgressBar {
    let bar = ProgressBar::new(0);
    if let Ok(style) = ProgressStyle::with_template("{msg} [{bar:30}] {pos}/{len} runs") {
        bar.set_style(style.progress_chars("=> "));
    }
    bar.set_message(message);
    bar
}

fn threads_bench(config: &ThreadsConfig, json: bool) -> Result<()> {
    let bar = runs_bar("bench threads");
    let report = run_threads(config, |done, total| {
        bar.set_length(total as u64);
        bar.set_position(done as u64);
    })
    .map_err(|e| anyhow!("{e}"))?;
    bar.finish_and_clear();
    if json {
        println!("{}", threads_json(&report));
        return Ok(());
    }
    let c = &report.config;
    println!(
        "tileslide on pools of {:?} threads, {} passes each: {} rays in one batch, {} crowd circles \
         ({} steps), {} broad circles ({} updates); medians",
        c.threads, c.passes, c.rays, c.crowd, c.crowd_steps, c.broad, c.broad_updates
    );
    println!(
        "{:<7} {:>8} {:>12} {:>23} {:>9} {:>18}",
        "work", "threads", "ms", "(fastest–slowest)", "speed-up", "checksum"
    );
    for r in &report.rows {
        let unit = match r.work {
            "rays" => "batch",
            "crowd" => "step",
            _ => "update",
        };
        println!(
            "{:<7} {:>8} {:>12} {:>23} {:>8.2}× {:>18}",
            r.work,
            r.threads,
            format!("{:.3}/{unit}", r.ms),
            format!("({:.3}–{:.3})", r.spread_ms.0, r.spread_ms.1),
            r.speedup,
            format!("{:016x}", r.checksum)
        );
    }
    println!(
        "answers identical on every pool: {}; crowd clean on every pool: {}",
        yes(report.identical),
        yes(report.crowd_clean)
    );
    print_steal(report.host_steal_percent);
    if !report.identical || !report.crowd_clean {
        return Err(anyhow!(
            "the threads changed an answer or the crowd is not clean"
        ));
    }
    Ok(())
}

fn yes(b: bool) -> &'static str {
    if b { "yes" } else { "NO" }
}

fn threads_json(report: &ThreadsReport) -> serde_json::Value {
    let rows: Vec<_> = report
        .rows
        .iter()
        .map(|r| {
            json!({
                "work": r.work,
                "threads": r.threads,
                "ms": r.ms,
                "spread_ms": [r.spread_ms.0, r.spread_ms.1],
                "speedup": r.speedup,
                "checksum": format!("{:016x}", r.checksum),
            })
        })
        .collect();
    json!({
        "scene": "threads",
        "threads": report.config.threads,
        "rays": report.config.rays,
        "crowd": report.config.crowd,
        "crowd_steps": report.config.crowd_steps,
        "broad": report.config.broad,
        "broad_updates": report.config.broad_updates,
        "passes": report.config.passes,
        "identical": report.identical,
        "crowd_clean": report.crowd_clean,
        "host_steal_percent": report.host_steal_percent,
        "results": rows,
    })
}

/// The host's steal time over a bench's runs, as `bench threads` and `bench growth` print it.
fn print_steal(percent: Option<f64>) {
    match percent {
        Some(steal) => println!(
            "host steal time over the runs: {steal:.1} % of the CPU time used or taken \
             (/proc/stat; on a shared virtual machine, read the figures of a run with little)"
        ),
        None => println!("host steal time over the runs: n/a (no /proc/stat)"),
    }
}

fn growth(config: &GrowthConfig, json: bool) -> Result<()> {
    let bar = runs_bar("bench growth");
    let report = run_growth(config, |done, total| {
        bar.set_length(total as u64);
        bar.set_position(done as u64);
    })
    .map_err(|e| anyhow!("{e}"))?;
    bar.finish_and_clear();
    let rows = &report.rows;
    let identical = rows.iter().all(|r| {
        rows.iter()
            .filter(|o| o.k == r.k)
            .all(|o| o.checksum == r.checksum)
    });
    if json {
        let list: Vec<_> = rows
            .iter()
            .map(|r: &GrowthRow| {
                json!({
                    "k": r.k,
                    "bodies": r.bodies,
                    "threads": r.threads,
                    "ms_per_step": r.ms_per_step,
                    "ms_fastest_pass": r.ms_range.0,
                    "ms_slowest_pass": r.ms_range.1,
                    "us_per_body": r.us_per_body,
                    "growth": r.growth,
                    "bytes_per_body": r.bytes_per_body,
                    "checksum": format!("{:016x}", r.checksum),
                })
            })
            .collect();
        println!(
            "{}",
            json!({
                "scene": "growth",
                "n": config.n,
                "steps": config.steps,
                "passes": config.passes,
                "identical": identical,
                "host_steal_percent": report.host_steal_percent,
                "results": list,
            })
        );
        return Ok(());
    }
    println!(
        "the crowd at the density of {} circles per copy of dungeon256, k × k copies, {} steps × {} passes interleaved, median step",
        config.n, config.steps, config.passes
    );
    println!(
        "{:>3} {:>9} {:>8} {:>10} {:>21} {:>9} {:>8} {:>10} {:>18}",
        "k",
        "bodies",
        "threads",
        "ms/step",
        "(passes' medians)",
        "µs/body",
        "growth",
        "B/body",
        "checksum"
    );
    for r in rows {
        println!(
            "{:>3} {:>9} {:>8} {:>10.3} {:>21} {:>9.4} {:>7.2}× {:>10} {:>18}",
            r.k,
            r.bodies,
            r.threads,
            r.ms_per_step,
            format!("({:.3}–{:.3})", r.ms_range.0, r.ms_range.1),
            r.us_per_body,
            r.growth,
            r.bytes_per_body
                .map_or_else(|| "n/a".to_owned(), |b| format!("{b:.0}")),
            format!("{:016x}", r.checksum)
        );
    }
    println!("positions identical on every pool: {}", yes(identical));
    print_steal(report.host_steal_percent);
    if !identical {
        return Err(anyhow!("the threads changed the crowd's positions"));
    }
    Ok(())
}
