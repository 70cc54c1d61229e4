//! What one tile edit costs (`TileMap::set_tile`: culling and end-point links of the cell and
//! its neighbours), on a 64 × 64 map and a 4096 × 4096 one: the same, since an edit touches
//! only the cells around it. `cargo bench -p tileslide-bench --bench tile_edits`.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic, missing_docs)]

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use tileslide::io::ascii;
use tileslide::{Cell, TileMap, Vec2};

/// A `side × side` map of the ASCII tile set: a checkerboard of solid blocks, ramps and
/// one-way platforms every few cells, so edits meet every kind of neighbour.
fn map(side: u32) -> TileMap {
    let set = std::sync::Arc::new(ascii::tile_set(1.0).unwrap());
    let kinds = [
        None,
        ascii::tile_for_char('#').unwrap(),
        ascii::tile_for_char('/').unwrap(),
        ascii::tile_for_char('=').unwrap(),
    ];
    let tiles: Vec<_> = (0..side * side)
        .map(|i| kinds[((i % side) * 7 + (i / side) * 3) as usize % kinds.len()])
        .collect();
    TileMap::from_tiles(set, side, side, Vec2::ZERO, &tiles).unwrap()
}

fn edits(c: &mut Criterion) {
    let dig = ascii::tile_for_char('#').unwrap();
    let mut group = c.benchmark_group("set_tile");
    for side in [64u32, 4096] {
        let mut m = map(side);
        // Dig and fill a cell in the middle of the map, alternately (two edits per
        // iteration, so the map is the same after each).
        let cell = Cell::new(side / 2, side / 2);
        group.bench_with_input(BenchmarkId::from_parameter(side), &side, |b, _| {
            b.iter(|| {
                m.set_tile(black_box(cell), None).unwrap();
                m.set_tile(black_box(cell), dig).unwrap();
            });
        });
    }
    group.finish();
}

criterion_group!(benches, edits);
criterion_main!(benches);
