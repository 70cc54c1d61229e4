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
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic, missing_docs)]

use std::time::{Duration, Instant};

use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use criterion::{Criterion, criterion_group, criterion_main};
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

criterion_group!(benches, crowd);
criterion_main!(benches);
