//! What `TileMap::cast_circle` costs: 1024 casts of a circle of radius 0.3 from random free
//! points of a 64 × 64 map (solid blocks, ramps and one-way platforms), by motions of up to
//! 2 cells (a step) and up to 16 cells (a dash). `cargo bench -p tileslide-bench --bench
//! circle_casts`.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic, missing_docs)]

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use tileslide::io::ascii;
use tileslide::{QueryFilter, TileMap, Vec2};

/// A `side × side` map of the ASCII tile set with about one cell in four filled: solid
/// blocks, ramps both ways and one-way platforms.
fn map(side: u32) -> TileMap {
    let set = std::sync::Arc::new(ascii::tile_set(1.0).unwrap());
    let kinds = [
        ascii::tile_for_char('#').unwrap(),
        ascii::tile_for_char('/').unwrap(),
        ascii::tile_for_char('\\').unwrap(),
        ascii::tile_for_char('=').unwrap(),
    ];
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let tiles: Vec<_> = (0..side * side)
        .map(|_| {
            state = next(state);
            if state.is_multiple_of(4) {
                kinds[(state >> 8) as usize % kinds.len()]
            } else {
                None
            }
        })
        .collect();
    TileMap::from_tiles(set, side, side, Vec2::ZERO, &tiles).unwrap()
}

/// One step of a 64-bit xorshift.
fn next(mut x: u64) -> u64 {
    x ^= x << 13;
    x ^= x >> 7;
    x ^ (x << 17)
}

/// `n` casts (start, motion) from the centres of empty cells, by motions of up to `reach`
/// cells along each axis.
fn casts(map: &TileMap, n: usize, reach: f32) -> Vec<(Vec2, Vec2)> {
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    let mut unit = || {
        state = next(state);
        (state >> 40) as f32 / (1u64 << 24) as f32
    };
    let side = map.width() as f32;
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let start = Vec2::new((unit() * side).floor(), (unit() * side).floor()) + 0.5;
        if map.is_point_solid(start) {
            continue;
        }
        let motion = Vec2::new(unit() * 2.0 - 1.0, unit() * 2.0 - 1.0) * reach;
        out.push((start, motion));
    }
    out
}

fn circle_casts(c: &mut Criterion) {
    let m = map(64);
    let filter = QueryFilter::default();
    let mut group = c.benchmark_group("cast_circle_1024");
    for reach in [2.0f32, 16.0] {
        let list = casts(&m, 1024, reach);
        group.bench_with_input(BenchmarkId::from_parameter(reach), &list, |b, list| {
            b.iter(|| {
                let mut hits = 0u32;
                for &(start, motion) in list {
                    let hit = m
                        .cast_circle(black_box(start), 0.3, black_box(motion), &filter)
                        .ok()
                        .flatten();
                    hits += u32::from(hit.is_some());
                }
                hits
            });
        });
    }
    group.finish();
}

criterion_group!(benches, circle_casts);
criterion_main!(benches);
