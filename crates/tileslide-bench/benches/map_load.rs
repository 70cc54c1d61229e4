//! Loading a 1024 × 1024 map: from Tiled's JSON (`.tmj`) and from tileslide's baked format
//! (`.tsm`), in the same run, both from bytes already in memory (the `.tmj` map's external
//! tile set is read from `examples/maps/tiles.tsj` each time, as a load does).
//! `cargo bench -p tileslide-bench --bench map_load`.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic, missing_docs)]

use std::hint::black_box;
use std::path::PathBuf;

use criterion::{Criterion, criterion_group, criterion_main};
use serde_json::Value;
use tileslide::io::baked;
use tileslide::io::tiled::{self, TiledOptions};

const SIDE: usize = 1024;

/// The example cave's JSON, with its collision layer tiled out to `SIDE × SIDE` cells (and
/// the other layers dropped); and the path it pretends to live at (beside its tile set).
fn big_tmj() -> (String, PathBuf) {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/maps");
    let text = std::fs::read_to_string(dir.join("cave.tmj")).unwrap();
    let mut map: Value = serde_json::from_str(&text).unwrap();
    let (w, h) = (
        map["width"].as_u64().unwrap() as usize,
        map["height"].as_u64().unwrap() as usize,
    );
    let layers = map["layers"].as_array().unwrap();
    let mut walls = layers
        .iter()
        .find(|l| l["name"] == "walls")
        .unwrap()
        .clone();
    let data: Vec<u64> = walls["data"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_u64().unwrap())
        .collect();
    let tiled: Vec<u64> = (0..SIDE * SIDE)
        .map(|i| data[(i / SIDE % h) * w + i % SIDE % w])
        .collect();
    walls["data"] = tiled.into();
    walls["width"] = SIDE.into();
    walls["height"] = SIDE.into();
    map["layers"] = vec![walls].into();
    map["width"] = SIDE.into();
    map["height"] = SIDE.into();
    (map.to_string(), dir.join("big.tmj"))
}

fn loads(c: &mut Criterion) {
    let (text, path) = big_tmj();
    let options = TiledOptions::default();
    let map = tiled::parse_tmj(&text, &path, &options).unwrap().map;
    let bytes = baked::to_bytes(&map);
    let mut group = c.benchmark_group("load 1024x1024");
    group.sample_size(10);
    group.bench_function("tmj", |b| {
        b.iter(|| tiled::parse_tmj(black_box(&text), &path, &options).unwrap())
    });
    group.bench_function("baked", |b| {
        b.iter(|| baked::parse(black_box(&bytes), "big.tsm").unwrap())
    });
    group.finish();
}

criterion_group!(benches, loads);
criterion_main!(benches);
