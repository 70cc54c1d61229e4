#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
//! Proves, by seeded-random (proptest) inputs, that the loaders never panic: random bytes,
//! and random mutations and truncations of the real `collision.bin` and levels, give `Ok` or
//! `Err` from `parse_tile_set` / `parse_level` / `parse_objects`; random text and cell sizes never panic the
//! ASCII parser, which also agrees cell by cell with a brute-force reference reading.

use crate::replica_support;

use std::sync::Arc;

use proptest::collection::vec;
use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};
use replica_support::{data_dir, raw_level, read};
use tileslide::io::{LoadError, LoadErrorKind, Location, ascii, replica};
use tileslide::{Cell, QueryFilter, Ray, TileId, TileMap, TileSet, Vec2};

/// 256 cases per property unless `PROPTEST_CASES` says otherwise (for long fuzz runs).
fn runner() -> TestRunner {
    TestRunner::new(Config::default())
}

/// Exercises a loaded map a little, so that odd shapes reach the queries too.
fn poke(map: &TileMap) {
    let b = map.bounds();
    let rays = [
        Ray::between(b.min, b.max),
        Ray::between(Vec2::new(b.min.x, b.max.y), Vec2::new(b.max.x, b.min.y)),
        Ray::between((b.min + b.max) * 0.5, b.min),
    ];
    for ray in rays {
        let _ = map.cast_ray(ray, &QueryFilter::default());
        let _ = map.cast_ray(ray, &QueryFilter::both_sides());
        let _ = map.cast_ray_all(ray, &QueryFilter::against(Vec2::NEG_Y));
    }
    let _ = map.is_point_solid((b.min + b.max) * 0.5);
    assert!(map.active_segment_count() <= 5 * map.placed_segment_count().max(1));
}

/// A byte-level edit of a file.
#[derive(Clone, Debug)]
enum Edit {
    /// Overwrite the byte at (index mod len).
    Set(usize, u8),
    /// Overwrite the f32 at (index mod len), aligned to the segment grid when possible.
    Float(usize, f32),
    /// Insert a byte.
    Insert(usize, u8),
    /// Remove a byte.
    Remove(usize),
}

fn interesting_f32() -> impl Strategy<Value = f32> {
    prop_oneof![
        Just(0.0f32),
        Just(32.0),
        Just(16.0),
        Just(-0.0),
        Just(f32::NAN),
        Just(f32::INFINITY),
        Just(1e-30),
        Just(32.000_01),
        -1.0f32..33.0,
        any::<f32>(),
    ]
}

fn edits() -> impl Strategy<Value = Vec<Edit>> {
    vec(
        prop_oneof![
            (any::<usize>(), any::<u8>()).prop_map(|(i, b)| Edit::Set(i, b)),
            (any::<usize>(), interesting_f32()).prop_map(|(i, f)| Edit::Float(i, f)),
            (any::<usize>(), any::<u8>()).prop_map(|(i, b)| Edit::Insert(i, b)),
            any::<usize>().prop_map(Edit::Remove),
        ],
        1..6,
    )
}

/// Applies edits, then keeps `keep` (a fraction) of the file when given. `Float` edits land
/// on one of `floats` (offsets of the file's f32 fields) so that they make odd but readable
/// coordinates, normals and scroll speeds rather than noise.
fn mutate(base: &[u8], edits: &[Edit], floats: &[usize], keep: Option<f64>) -> Vec<u8> {
    let mut d = base.to_vec();
    for edit in edits {
        if d.is_empty() {
            break;
        }
        match *edit {
            Edit::Set(i, b) => {
                let i = i % d.len();
                d[i] = b;
            }
            Edit::Float(i, f) => {
                let at = if floats.is_empty() {
                    i % d.len()
                } else {
                    floats[i % floats.len()]
                };
                if at + 4 <= d.len() {
                    d[at..at + 4].copy_from_slice(&f.to_le_bytes());
                }
            }
            Edit::Insert(i, b) => {
                let i = i % (d.len() + 1);
                d.insert(i, b);
            }
            Edit::Remove(i) => {
                let i = i % d.len();
                d.remove(i);
            }
        }
    }
    if let Some(keep) = keep {
        d.truncate((d.len() as f64 * keep) as usize);
    }
    d
}

/// Offsets of every f32 field of a tile set file.
fn tile_set_floats(d: &[u8]) -> Vec<usize> {
    let mut out = Vec::new();
    let mut p = 2;
    for _ in 0..d[1] {
        let count = usize::from(d[p + 1]);
        p += 2;
        out.extend((0..count * 6).map(|k| p + 4 * k));
        p += 24 * count;
    }
    out
}

/// Offsets of the scroll speeds (the only f32 fields) of a level file.
fn level_floats(d: &[u8]) -> Vec<usize> {
    raw_level(d)
        .layers
        .iter()
        .map(|l| l.cells_at - 13)
        .collect()
}

/// Edits that keep a tile set's structure: coordinates and normals moved to values that
/// stay inside the tile, so that most mutated files load and their odd shapes get built.
fn shape_edits() -> impl Strategy<Value = Vec<Edit>> {
    let value = prop_oneof![
        0.0f32..=32.0,
        -1.0f32..=1.0,
        Just(0.0f32),
        Just(16.0),
        Just(32.0),
    ];
    vec(
        (any::<usize>(), value).prop_map(|(i, f)| Edit::Float(i, f)),
        1..6,
    )
}

fn keep() -> impl Strategy<Value = Option<f64>> {
    prop_oneof![3 => Just(None), 1 => (0.0f64..1.0).prop_map(Some)]
}

fn collision_set(dir: &std::path::Path) -> Arc<TileSet> {
    Arc::new(replica::load_tile_set(dir.join("collision.bin")).unwrap())
}

#[test]
fn random_bytes_never_panic_parse_tile_set() {
    let empty = Arc::new(TileSet::new(Vec2::splat(32.0)).unwrap());
    runner()
        .run(&vec(any::<u8>(), 0..400), |data| {
            let _ = replica::parse_tile_set(&data, "random.bin");
            let _ = replica::parse_level(&data, "random.bin", Arc::clone(&empty));
            let _ = replica::parse_objects(&data, "random.bin");
            Ok(())
        })
        .unwrap();
}

#[test]
fn random_bytes_behind_valid_signatures_never_panic_the_loaders() {
    // Valid signatures get the random bytes past the first check.
    let square = {
        let mut d = vec![52u8, 1, 1, 4];
        for s in [
            [0.0f32, 32.0, 32.0, 32.0, 0.0, 1.0],
            [32.0, 32.0, 32.0, 0.0, 1.0, 0.0],
            [32.0, 0.0, 0.0, 0.0, 0.0, -1.0],
            [0.0, 0.0, 0.0, 32.0, -1.0, 0.0],
        ] {
            s.iter().for_each(|f| d.extend_from_slice(&f.to_le_bytes()));
        }
        Arc::new(replica::parse_tile_set(&d, "square.bin").unwrap())
    };
    let strategy = (any::<u8>(), vec(any::<u8>(), 0..300), 0i32..12, 0i32..12);
    runner()
        .run(&strategy, |(count, tail, w, h)| {
            let mut set = vec![52u8, count];
            set.extend_from_slice(&tail);
            let _ = replica::parse_tile_set(&set, "set.bin");

            let mut level = vec![96u8, 1, 0, (count % 4), 0];
            level.extend_from_slice(&1.0f32.to_le_bytes());
            level.push(42);
            level.extend_from_slice(&w.to_le_bytes());
            level.extend_from_slice(&h.to_le_bytes());
            level.extend_from_slice(&tail);
            if let Ok(map) = replica::parse_level(&level, "level.bin", Arc::clone(&square)) {
                poke(&map);
            }
            let _ = replica::parse_objects(&level, "level.bin");
            Ok(())
        })
        .unwrap();
}

#[test]
fn mutated_collision_bin_never_panics_parse_tile_set() {
    let Some(dir) = data_dir() else { return };
    let base = read(&dir, "collision.bin");
    let floats = tile_set_floats(&base);
    runner()
        .run(&(edits(), keep()), |(edits, keep)| {
            let data = mutate(&base, &edits, &floats, keep);
            match replica::parse_tile_set(&data, "collision.bin") {
                Ok(set) => prop_assert!(set.len() <= 255),
                Err(e) => {
                    prop_assert!(e.to_string().starts_with("collision.bin"));
                    if let Location::Byte(at) = e.location {
                        prop_assert!(at <= data.len() as u64);
                    }
                }
            }
            Ok(())
        })
        .unwrap();
}

#[test]
fn mutated_collision_bin_that_loads_builds_real_levels_without_panicking() {
    // Odd but valid shapes (crossing segments, arbitrary normals, open outlines) go through
    // seam culling, end links and ray casts on real levels.
    let Some(dir) = data_dir() else { return };
    let base = read(&dir, "collision.bin");
    let floats = tile_set_floats(&base);
    let levels = [
        read(&dir, "collisiontest.bin"),
        read(&dir, "level_1_6_island.bin"),
    ];
    let loaded = std::cell::Cell::new(0u32);
    runner()
        .run(&(shape_edits(), any::<bool>()), |(edits, which)| {
            let data = mutate(&base, &edits, &floats, None);
            if let Ok(set) = replica::parse_tile_set(&data, "collision.bin") {
                loaded.set(loaded.get() + 1);
                let level = &levels[usize::from(which)];
                let map = replica::parse_level(level, "level.bin", Arc::new(set)).unwrap();
                poke(&map);
            }
            Ok(())
        })
        .unwrap();
    assert!(
        loaded.get() > 0,
        "no mutation loaded: the test exercised nothing"
    );
}

#[test]
fn mutated_real_levels_never_panic_parse_level_or_parse_objects() {
    let Some(dir) = data_dir() else { return };
    let set = collision_set(&dir);
    let levels = [
        read(&dir, "level_1_1_island.bin"),
        read(&dir, "collisiontest.bin"),
        read(&dir, "level_1_4_island.bin"),
    ];
    let floats: Vec<Vec<usize>> = levels.iter().map(|l| level_floats(l)).collect();
    let strategy = (edits(), keep(), 0usize..3, 0usize..40);
    runner()
        .run(&strategy, |(edits, keep, which, header_edits)| {
            let base = &levels[which];
            // Aim some edits at the 18 header bytes, where the sizes live.
            let mut edits = edits;
            if header_edits % 2 == 0 {
                edits.push(Edit::Set(header_edits % 18, (header_edits * 37) as u8));
            }
            let data = mutate(base, &edits, &floats[which], keep);
            let check = |e: &LoadError| {
                prop_assert!(e.to_string().starts_with("level.bin"));
                if let Location::Byte(at) = e.location {
                    prop_assert!(at <= data.len() as u64);
                }
                Ok(())
            };
            match replica::parse_level(&data, "level.bin", Arc::clone(&set)) {
                Ok(map) => poke(&map),
                Err(e) => check(&e)?,
            }
            match replica::parse_objects(&data, "level.bin") {
                // Every object and hot spot lies on the grid.
                Ok(level) => {
                    for o in &level.objects {
                        prop_assert!(o.cell.col < level.width && o.cell.row < level.height);
                    }
                    if let Some(spots) = &level.hot_spots {
                        prop_assert_eq!(
                            (spots.width(), spots.height()),
                            (level.width, level.height)
                        );
                    }
                }
                Err(e) => check(&e)?,
            }
            Ok(())
        })
        .unwrap();
}

#[test]
fn random_small_levels_load_exactly_the_cells_of_their_bytes() {
    // Model test: a well-formed level with random ids gives the map a brute-force reading
    // of the bytes predicts (negative or unknown ids empty, file rows flipped).
    let Some(dir) = data_dir() else { return };
    let set = collision_set(&dir);
    let strategy = (1i32..12, 1i32..12)
        .prop_flat_map(|(w, h)| (Just(w), Just(h), vec(-3i8..64, (w * h) as usize)));
    runner()
        .run(&strategy, |(w, h, cells)| {
            let mut data = vec![96u8, 1, 0, 1, 0];
            data.extend_from_slice(&1.0f32.to_le_bytes());
            data.push(42);
            data.extend_from_slice(&w.to_le_bytes());
            data.extend_from_slice(&h.to_le_bytes());
            data.extend(cells.iter().map(|&c| c as u8));
            let map = replica::parse_level(&data, "model.bin", Arc::clone(&set)).unwrap();
            prop_assert_eq!((map.width(), map.height()), (w as u32, h as u32));
            for fr in 0..h {
                for c in 0..w {
                    let id = cells[(fr * w + c) as usize];
                    let expected = u32::try_from(id)
                        .ok()
                        .map(TileId)
                        .filter(|t| set.shape(*t).is_some());
                    let cell = Cell::new(c as u32, (h - 1 - fr) as u32);
                    prop_assert_eq!(map.tile(cell), expected);
                }
            }
            poke(&map);
            Ok(())
        })
        .unwrap();
}

// ---------------------------------------------------------------------------------------
// ASCII.

/// What a brute-force reading of the ASCII rules predicts: the rows, or the first unknown
/// character's (line, column), or no rows.
#[derive(Debug, PartialEq)]
enum Expected {
    Rows(Vec<Vec<char>>),
    Unknown(u32, u32, char),
    NoRows,
}

fn reference(text: &str) -> Expected {
    // A leading byte-order mark is not part of the map.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut rows = Vec::new();
    for (i, line) in text.split('\n').enumerate() {
        let line = line.strip_suffix('\r').unwrap_or(line);
        if line.starts_with(';') {
            continue;
        }
        let chars: Vec<char> = line.chars().collect();
        for (j, &c) in chars.iter().enumerate() {
            if !matches!(c, '.' | ' ' | '#' | '/' | '\\' | '=') {
                return Expected::Unknown(i as u32 + 1, j as u32 + 1, c);
            }
        }
        rows.push(chars);
    }
    while rows.last().is_some_and(Vec::is_empty) {
        rows.pop();
    }
    if rows.iter().all(Vec::is_empty) {
        return Expected::NoRows;
    }
    Expected::Rows(rows)
}

fn ascii_text() -> impl Strategy<Value = String> {
    let alphabet = vec![
        '#', '.', '/', '\\', '=', ' ', ';', '\n', '\n', '\r', '\t', 'x', 'é', '\u{feff}',
    ];
    prop_oneof![
        // Mostly valid maps, with the odd bad character.
        4 => vec(prop::sample::select(alphabet), 0..300).prop_map(|c| c.into_iter().collect()),
        // Anything at all.
        1 => any::<String>(),
    ]
}

#[test]
fn random_text_never_panics_and_agrees_with_a_reference_reading() {
    runner()
        .run(&ascii_text(), |text| {
            let got = ascii::parse(&text, "fuzz.txt", 1.0);
            match (reference(&text), got) {
                (Expected::Rows(rows), Ok(map)) => {
                    let width = rows.iter().map(Vec::len).max().unwrap_or(0);
                    prop_assert_eq!(
                        (map.width() as usize, map.height() as usize),
                        (width, rows.len())
                    );
                    for (r, line) in rows.iter().enumerate() {
                        for c in 0..width {
                            let ch = line.get(c).copied().unwrap_or('.');
                            let expected = ascii::tile_for_char(ch).unwrap();
                            prop_assert_eq!(map.tile(Cell::new(c as u32, r as u32)), expected);
                        }
                    }
                    poke(&map);
                }
                (Expected::Unknown(line, column, c), Err(e)) => {
                    prop_assert_eq!(e.location, Location::LineColumn { line, column });
                    prop_assert!(
                        matches!(e.kind, LoadErrorKind::UnknownCharacter(found) if found == c),
                        "{e}"
                    );
                }
                (Expected::NoRows, Err(e)) => {
                    prop_assert!(matches!(e.kind, LoadErrorKind::NoRows), "{e}")
                }
                (expected, got) => {
                    prop_assert!(
                        false,
                        "expected {:?}, got {:?}",
                        expected,
                        got.map(|m| (m.width(), m.height()))
                    );
                }
            }
            Ok(())
        })
        .unwrap();
}

#[test]
fn any_cell_size_never_panics_and_fails_only_as_a_parameter_error() {
    let strategy = (
        prop_oneof![
            any::<f32>(),
            (-40i32..40).prop_map(|e| 10f32.powi(e)),
            Just(f32::MIN_POSITIVE),
            Just(f32::MAX),
        ],
        ascii_text(),
    );
    runner()
        .run(&strategy, |(cell, text)| {
            match ascii::parse("#/\n\\=", "cell.txt", cell) {
                Ok(map) => prop_assert_eq!(map.cell_size(), Vec2::splat(cell)),
                Err(e) => {
                    prop_assert!(matches!(e.kind, LoadErrorKind::Parameter(_)), "{e}");
                    prop_assert!(e.to_string().contains("cell size"), "{e}");
                }
            }
            let _ = ascii::parse(&text, "cell.txt", cell);
            Ok(())
        })
        .unwrap();
}
