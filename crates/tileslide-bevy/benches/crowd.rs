//! The plugin's overhead: the standard crowd (BENCHMARKS.md's "crowd", 10,000 circles of
//! radius 0.3 in dungeon256) stepped by the core's API alone (`tileslide bench crowd`'s
//! contender), by the plugin's fixed step
//! (`FixedUpdate` run directly: the game's proposals, the plugin's copying in, the resolve,
//! the `Transform` writes), and by a whole Bevy frame with one fixed step (`App::update`:
//! time, the fixed loop, transform propagation), in the same run.
//! `cargo bench -p tileslide-bevy --bench crowd`.
//!
//! Every contender steps its own copy of the scene from the start and starts again after
//! 100 steps (BENCHMARKS.md runs 100), untimed, so all are measured over the same steps.
//! Before criterion's groups, an interleaved run takes the three in turn, step by step, and
//! prints their medians and ratios: on a shared machine the load drifts between criterion's
//! groups, minutes apart.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic, missing_docs)]

use std::time::{Duration, Instant};

use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use criterion::Criterion;
use tileslide::TileMap;
use tileslide_bench::crowd::{CrowdContender, TileslideCrowd};
use tileslide_bevy::{Body, CollisionMap, ProposedMove, TileslidePlugin, TileslideSet};
use tileslide_scenes::{CROWD_RADIUS, CrowdBody, dungeon256, scene_crowd};

const N: usize = 10_000;
const STEPS_PER_RUN: u32 = 100;

/// A crowd body's constant move per step (world units).
#[derive(Component)]
struct CrowdMove(Vec2);

/// The game's part: every body proposes its move, as the core's loop does.
fn propose_crowd(mut crowd: Query<(&CrowdMove, &mut ProposedMove)>) {
    for (step, mut proposed) in &mut crowd {
        proposed.0 = step.0;
    }
}

/// The crowd in a headless Bevy app with the plugin.
fn bevy_crowd(map: &TileMap, crowd: &[CrowdBody]) -> App {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, TileslidePlugin::default()))
        .insert_resource(CollisionMap::new(map.clone()))
        .insert_resource(Time::<Fixed>::from_hz(60.0))
        .insert_resource(TimeUpdateStrategy::FixedTimesteps(1))
        .add_systems(FixedUpdate, propose_crowd.before(TileslideSet::SyncIn));
    for b in crowd {
        let (p, v) = (b.position, b.velocity);
        app.world_mut().spawn((
            Body::circle(CROWD_RADIUS),
            CrowdMove(Vec2::new(v.x, -v.y)),
            Transform::from_xyz(p.x, -p.y, 0.0),
        ));
    }
    app.finish();
    app.cleanup();
    // The first update starts the clocks and runs no fixed step.
    app.update();
    app
}

/// Times `iters` steps of `step`, starting a new scene with `fresh` every
/// [`STEPS_PER_RUN`] steps (untimed).
fn timed<S>(
    scene: &mut (S, u32),
    iters: u64,
    fresh: &impl Fn() -> S,
    step: impl Fn(&mut S),
) -> Duration {
    let mut total = Duration::ZERO;
    for _ in 0..iters {
        if scene.1 == STEPS_PER_RUN {
            *scene = (fresh(), 0);
        }
        let start = Instant::now();
        step(&mut scene.0);
        total += start.elapsed();
        scene.1 += 1;
    }
    total
}

fn crowd(c: &mut Criterion) {
    let grid = dungeon256();
    let map = grid.to_tile_map().unwrap();
    let crowd = scene_crowd(&grid, N);
    let mut group = c.benchmark_group("crowd_10k_step");
    group.sample_size(20);
    group.measurement_time(Duration::from_secs(20));

    // The core's contender of `tileslide bench crowd`: propose every body's move, step.
    let core_fresh = || TileslideCrowd::new(&grid, &crowd, CROWD_RADIUS).unwrap();
    let mut core = (core_fresh(), 0);
    group.bench_function("core", |b| {
        b.iter_custom(|iters| timed(&mut core, iters, &core_fresh, TileslideCrowd::step));
    });

    let bevy_fresh = || bevy_crowd(&map, &crowd);
    let mut fixed = (bevy_fresh(), 0);
    group.bench_function("bevy_fixed_step", |b| {
        b.iter_custom(|iters| {
            timed(&mut fixed, iters, &bevy_fresh, |app| {
                app.world_mut().run_schedule(FixedUpdate);
            })
        });
    });

    let mut frame = (bevy_fresh(), 0);
    group.bench_function("bevy_frame", |b| {
        b.iter_custom(|iters| timed(&mut frame, iters, &bevy_fresh, App::update));
    });
    group.finish();
}

/// Rounds of the interleaved run.
const ROUNDS: usize = 10;

/// The same three contenders taken in turn, round after round, each for a whole run of
/// [`STEPS_PER_RUN`] steps from the start: on a shared machine the load drifts over
/// criterion's minutes, and turns taken within seconds see the same load. Prints each
/// one's median step and its ratio to the core's.
fn interleaved(grid: &tileslide_scenes::SolidGrid, map: &TileMap, crowd: &[CrowdBody]) {
    let mut times: [Vec<Duration>; 3] = Default::default();
    let time = |f: &mut dyn FnMut()| {
        let start = Instant::now();
        f();
        start.elapsed()
    };
    for _ in 0..ROUNDS {
        let mut core = TileslideCrowd::new(grid, crowd, CROWD_RADIUS).unwrap();
        let mut fixed = bevy_crowd(map, crowd);
        let mut frame = bevy_crowd(map, crowd);
        for _ in 0..STEPS_PER_RUN {
            times[0].push(time(&mut || core.step()));
            times[1].push(time(&mut || fixed.world_mut().run_schedule(FixedUpdate)));
            times[2].push(time(&mut || frame.update()));
        }
    }
    let median = |v: &mut Vec<Duration>| {
        v.sort_unstable();
        v[v.len() / 2].as_secs_f64() * 1e3
    };
    let core = median(&mut times[0]);
    println!("crowd, 10,000 circles, {ROUNDS} interleaved runs of {STEPS_PER_RUN} steps:");
    for (name, t) in ["core", "bevy_fixed_step", "bevy_frame"]
        .iter()
        .zip(&mut times)
    {
        let m = median(t);
        println!(
            "  {name:<16} median {m:.3} ms/step  {:.2}x the core",
            m / core
        );
    }
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    // `cargo test --benches` runs benchmarks once each as tests: no interleaved run then.
    if !std::env::args().any(|a| a == "--test") {
        let grid = dungeon256();
        let map = grid.to_tile_map().unwrap();
        interleaved(&grid, &map, &scene_crowd(&grid, N));
    }
    crowd(&mut c);
    c.final_summary();
}
