//! What each fuzz target checks, for any bytes: the loader returns `Ok` or `Err` (never
//! panics, never allocates without bound: libFuzzer's `-rss_limit_mb` catches that), and a
//! map it returns answers ray casts sanely: every hit finite, `t` in [0, 1], a unit normal,
//! and `cast_ray_all`'s first hit equal to `cast_ray`'s.
//!
//! The same functions run on stable over the seed corpora and every crash input kept in
//! `regressions/` (crates/tileslide/tests/fuzz_regressions.rs), so what was found once stays
//! found.

use std::collections::BTreeMap;

use tileslide::io::bitmap::{BitmapOptions, parse_tile_set};
use tileslide::io::tiled::{TiledOptions, parse_tmj, parse_tmx};
use tileslide::io::{ascii, baked, ldtk, replica};
use tileslide::{QueryFilter, Ray, TileMap, Vec2};

/// A target's check: any bytes in, a panic for a finding.
pub type Check = fn(&[u8]);

/// The targets by name, for the regression test: each file of `corpus/NAME/` and
/// `regressions/NAME/` goes through `check`.
pub const TARGETS: [(&str, Check); 15] = [
    ("ascii", ascii),
    ("tmx", tmx),
    ("tmj", tmj),
    ("ldtk", ldtk),
    ("baked", baked),
    ("tsx", tsx),
    ("tsj", tsj),
    ("replica_tileset", replica_tileset),
    ("replica_level", replica_level),
    ("bitmap", bitmap),
    ("bodies", super::api::bodies),
    ("character", super::api::character),
    ("casts", super::api::casts),
    ("paths", super::api::paths),
    ("volumes", super::api::volumes),
];

/// Casts rays across a loaded map and checks what they hit.
pub fn poke(map: &TileMap) {
    let b = map.bounds();
    let mid = (b.min + b.max) * 0.5;
    let rays = [
        Ray::between(b.min, b.max),
        Ray::between(Vec2::new(b.min.x, b.max.y), Vec2::new(b.max.x, b.min.y)),
        Ray::between(mid, b.min),
        Ray::between(
            Vec2::new(b.min.x - 1.0, mid.y),
            Vec2::new(b.max.x + 1.0, mid.y),
        ),
    ];
    for ray in rays {
        if !ray.is_finite() {
            continue;
        }
        for filter in [QueryFilter::default(), QueryFilter::both_sides()] {
            let first = map.cast_ray(ray, &filter);
            if let Some(hit) = &first {
                assert!((0.0..=1.0).contains(&hit.t), "t = {} outside [0, 1]", hit.t);
                assert!(hit.point.is_finite() && hit.normal.is_finite(), "{hit:?}");
                assert!(
                    (hit.normal.length() - 1.0).abs() < 1e-3,
                    "normal {} is not a unit vector",
                    hit.normal
                );
            }
            let all = map.cast_ray_all(ray, &filter);
            assert_eq!(all.first(), first.as_ref(), "cast_ray_all's first hit");
        }
    }
    let _ = map.is_point_solid(mid);
}

/// An ASCII map: the first byte picks the cell size, the rest is the text.
pub fn ascii(data: &[u8]) {
    let Some((&pick, rest)) = data.split_first() else {
        return;
    };
    let cell = [1.0, 0.5, 16.0, 1e-3, 3e4, 0.0, -1.0, f32::NAN][usize::from(pick % 8)];
    if let Ok(text) = std::str::from_utf8(rest)
        && let Ok(map) = ascii::parse(text, "fuzz.txt", cell)
    {
        poke(&map);
    }
}

/// The external files a fuzzed Tiled map may name: one real tile set, so nothing is read
/// from disk.
fn tiled_options() -> TiledOptions {
    let files: BTreeMap<String, Vec<u8>> = [
        (
            "tiles.tsx".to_owned(),
            include_bytes!("../../examples/maps/tiles.tsx").to_vec(),
        ),
        (
            "tiles.tsj".to_owned(),
            include_bytes!("../../examples/maps/tiles.tsj").to_vec(),
        ),
    ]
    .into();
    TiledOptions {
        files,
        ..TiledOptions::default()
    }
}

/// A Tiled map as XML (`.tmx`).
pub fn tmx(data: &[u8]) {
    if let Ok(text) = std::str::from_utf8(data)
        && let Ok(tiled) = parse_tmx(text, "fuzz.tmx", &tiled_options())
    {
        poke(&tiled.map);
    }
}

/// A Tiled map as JSON (`.tmj`).
pub fn tmj(data: &[u8]) {
    if let Ok(text) = std::str::from_utf8(data)
        && let Ok(tiled) = parse_tmj(text, "fuzz.tmj", &tiled_options())
    {
        poke(&tiled.map);
    }
}

/// A map (4 by 3 cells of 16 pixels, one layer) whose tile set is the given bytes, as the
/// external file its `source` names: what a Tiled tile set file makes of a map.
const TSX_MAP: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<map version="1.10" orientation="orthogonal" renderorder="right-down" width="4" height="3" tilewidth="16" tileheight="16" infinite="0">
 <tileset firstgid="1" source="fuzz.tsx"/>
 <layer id="1" name="collision" width="4" height="3">
  <data encoding="csv">
1,2,3,4,
5,0,6,7,
8,9,10,11
</data>
 </layer>
</map>"#;

/// [`TSX_MAP`] as JSON, its tile set in `fuzz.tsj`.
const TSJ_MAP: &str = r#"{"type": "map", "version": "1.10", "orientation": "orthogonal",
 "renderorder": "right-down", "width": 4, "height": 3, "tilewidth": 16, "tileheight": 16,
 "infinite": false,
 "tilesets": [{"firstgid": 1, "source": "fuzz.tsj"}],
 "layers": [{"id": 1, "name": "collision", "type": "tilelayer", "width": 4, "height": 3,
   "x": 0, "y": 0, "opacity": 1, "visible": true,
   "data": [1, 2, 3, 4, 5, 0, 6, 7, 8, 9, 10, 11]}]}"#;

/// Tiled options whose only external file is `name`, holding `data`.
fn tile_set_file(name: &str, data: &[u8]) -> TiledOptions {
    TiledOptions {
        files: [(name.to_owned(), data.to_vec())].into(),
        ..TiledOptions::default()
    }
}

/// A Tiled tile set as XML (`.tsx`), loaded as a map's external tile set.
pub fn tsx(data: &[u8]) {
    if let Ok(tiled) = parse_tmx(TSX_MAP, "fuzz.tmx", &tile_set_file("fuzz.tsx", data)) {
        poke(&tiled.map);
    }
}

/// A Tiled tile set as JSON (`.tsj`), loaded as a map's external tile set.
pub fn tsj(data: &[u8]) {
    if let Ok(tiled) = parse_tmj(TSJ_MAP, "fuzz.tmj", &tile_set_file("fuzz.tsj", data)) {
        poke(&tiled.map);
    }
}

/// An LDtk project with its levels inline (a level in a separate file is not found: the
/// project's folder does not exist).
pub fn ldtk(data: &[u8]) {
    if let Ok(text) = std::str::from_utf8(data)
        && let Ok(level) = ldtk::parse(
            text,
            "/nonexistent/fuzz.ldtk",
            &ldtk::LdtkOptions::default(),
        )
    {
        poke(&level.map);
    }
}

/// A baked map (`.tsm`); a map that loads bakes back to bytes that load to the same map.
pub fn baked(data: &[u8]) {
    if let Ok(map) = baked::parse(data, "fuzz.tsm") {
        poke(&map);
        let again = baked::parse(&baked::to_bytes(&map), "again.tsm");
        assert!(
            again.is_ok(),
            "a loaded map's own bytes do not load: {again:?}"
        );
    }
}

/// A Replica Island tile set (`collision.bin`).
pub fn replica_tileset(data: &[u8]) {
    let _ = replica::parse_tile_set(data, "fuzz.bin");
}

/// A Replica Island level (`level.bin`), over the tile set of an ASCII map (its ids 0 to 7,
/// some solid, some ramps, some one-way).
pub fn replica_level(data: &[u8]) {
    let Ok(tiles) = ascii::parse("#/\\=.#/=\n", "tiles.txt", 1.0) else {
        panic!("the tile set's map does not load")
    };
    if let Ok(map) = replica::parse_level(data, "fuzz.bin", tiles.tile_set().clone()) {
        poke(&map);
    }
}

/// A PNG tile sheet, traced: the first two bytes pick the tile size.
pub fn bitmap(data: &[u8]) {
    let [w, h, rest @ ..] = data else {
        return;
    };
    let options = BitmapOptions::new(u32::from(*w % 33), u32::from(*h % 33));
    let _ = parse_tile_set(rest, "fuzz.png", &options);
}
