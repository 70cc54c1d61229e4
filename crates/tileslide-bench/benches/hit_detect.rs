//! What a frame of `HitWorld` costs: `begin_frame`, registering 2,000 objects and `detect`,
//! on a sparse field (200 × 200 units, a few hundred hits) and a crowded one (60 × 60, a few
//! thousand hits); and each half alone. Every object has a 1 × 1 body; a third also punch (a circle in front of
//! them), and a tenth are fireballs (a circle swept along a move of up to 3 units, no body).
//! `cargo bench -p tileslide-bench --bench hit_detect`.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic, missing_docs)]

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use tileslide::{HitObject, HitTypes, HitWorld, Owner, TeamRule, Vec2, Volume};
use tileslide_scenes::SplitMix64;

/// One object of the frame: what `register` takes.
struct Object {
    object: HitObject,
    attack: Vec<Volume>,
    vulnerable: Vec<Volume>,
}

/// `n` objects scattered over a `side × side` square from `seed`.
fn objects(n: usize, side: f32, seed: u64) -> Vec<Object> {
    let mut rng = SplitMix64::new(seed);
    let body = Volume::rect(Vec2::splat(0.5), Vec2::splat(0.5), HitTypes::ANY).unwrap();
    let fist = Volume::circle(Vec2::new(1.3, 0.5), 0.3, HitTypes::HIT).unwrap();
    let ball = Volume::circle(Vec2::ZERO, 0.2, HitTypes::HIT).unwrap();
    (0..n)
        .map(|i| {
            let position = Vec2::new(rng.range(0.0, side), rng.range(0.0, side));
            let team = rng.below(2) as u32;
            let roll = rng.below(30);
            let mut object = HitObject {
                team,
                ..HitObject::new(Owner(i as u64), position, Vec2::ONE)
            };
            if roll < 3 {
                object.size = Vec2::ZERO;
                object.motion = Vec2::new(rng.range(-3.0, 3.0), rng.range(-3.0, 3.0));
                Object {
                    object,
                    attack: vec![ball],
                    vulnerable: Vec::new(),
                }
            } else {
                object.facing.flip_x = rng.below(2) == 0;
                Object {
                    object,
                    attack: if roll < 13 { vec![fist] } else { Vec::new() },
                    vulnerable: vec![body],
                }
            }
        })
        .collect()
}

fn hit_detect(c: &mut Criterion) {
    let mut group = c.benchmark_group("hit_frame_2000");
    for (name, side) in [("sparse", 200.0f32), ("crowded", 60.0)] {
        let list = objects(2000, side, 0x5eed_0b1e_c75e_ed00);
        let mut world = HitWorld::new();
        let register = |world: &mut HitWorld, list: &[Object]| {
            world.begin_frame();
            for o in list {
                world
                    .register(black_box(o.object), &o.attack, &o.vulnerable)
                    .unwrap();
            }
        };
        group.bench_with_input(BenchmarkId::new("frame", name), &list, |b, list| {
            b.iter(|| {
                register(&mut world, list);
                world.detect(&mut TeamRule).len()
            });
        });
        // The two halves: registering alone, and `detect` alone on the registered frame
        // (without swings, detecting again finds the same hits).
        group.bench_with_input(BenchmarkId::new("register", name), &list, |b, list| {
            b.iter(|| register(&mut world, list));
        });
        register(&mut world, &list);
        group.bench_function(BenchmarkId::new("detect", name), |b| {
            b.iter(|| world.detect(&mut TeamRule).len());
        });
    }
    group.finish();
}

criterion_group!(benches, hit_detect);
criterion_main!(benches);
