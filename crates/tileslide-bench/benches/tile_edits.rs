//! What one tile edit costs (`TileMap::set_tile`: culling and end-point links of the cell and
//! its neighbours), on a 64 × 64 map and a 4096 × 4096 one: the same, since an edit touches
//! only the cells around it. And what a navigation grid's catching up with an edit costs
//! (`NavGrid::sync`), alone and followed by a path query, on dungeon256.
//! `cargo bench -p tileslide-bench --bench tile_edits`.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic, missing_docs)]

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use tileslide::io::ascii;
use tileslide::{Cell, NavConfig, NavGrid, TileMap, Vec2};
use tileslide_bench::paths::PathScene;

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

/// Brings `nav` up to date with `map`'s edits.
fn catch_up(nav: &mut NavGrid, map: &TileMap) {
    black_box(nav.sync(map).unwrap());
}

fn nav_edits(c: &mut Criterion) {
    let scene = PathScene::dungeon256().unwrap();
    let mut map = scene.map().clone();
    let mut nav = NavGrid::new(&map, NavConfig::default()).unwrap();
    let radius = 0.4;
    let queries = scene.queries(radius, 1).unwrap();
    let (from, to) = (queries[0].from, queries[0].to);
    // A wall cell beside open floor in the middle of the map: filled and dug alternately
    // (two edits per iteration, so the map is the same after each).
    let cell = (0..map.width() * map.height())
        .map(|k| Cell::new(128 + k % 64, 128 + k / 64))
        .find(|&c| map.tile(c).is_some() && map.tile(Cell::new(c.col + 1, c.row)).is_none())
        .unwrap();
    let wall = map.tile(cell);
    let mut group = c.benchmark_group("nav_edit");
    group.bench_function("edit_and_catch_up", |b| {
        b.iter(|| {
            map.set_tile(black_box(cell), None).unwrap();
            catch_up(&mut nav, &map);
            map.set_tile(black_box(cell), wall).unwrap();
            catch_up(&mut nav, &map);
        });
    });
    group.bench_function("edit_catch_up_and_find_path", |b| {
        b.iter(|| {
            map.set_tile(black_box(cell), None).unwrap();
            catch_up(&mut nav, &map);
            black_box(nav.find_path(&map, from, to, radius).unwrap());
            map.set_tile(black_box(cell), wall).unwrap();
            catch_up(&mut nav, &map);
            black_box(nav.find_path(&map, from, to, radius).unwrap());
        });
    });
    group.finish();
}

criterion_group!(benches, edits, nav_edits);
criterion_main!(benches);
