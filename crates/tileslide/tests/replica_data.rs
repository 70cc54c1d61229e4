#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
//! Proves that the Replica Island loaders read the game's real files as FORMAT.md describes
//! them: the tile set's ids and shapes, every level's size and collision layer (checked cell
//! by cell against an independent reading of the bytes), and the known truncated level.

use crate::replica_support;

use std::path::Path;
use std::sync::Arc;

use replica_support::{
    DATA_DIR, RawGrid, TILE, data_dir, level_names, raw_level, raw_tile_set, read, resolve_data_dir,
};
use tileslide::io::{LoadErrorKind, Location, replica};
use tileslide::{Cell, TileId, TileSet, Vec2};

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

fn collision_set(dir: &Path) -> TileSet {
    replica::load_tile_set(dir.join("collision.bin")).unwrap()
}

#[test]
fn data_dir_path_resolves_to_the_shared_replica_island_directory() {
    let Some(dir) = data_dir() else { return };
    let canonical = dir.canonicalize().unwrap();
    assert!(
        canonical.ends_with("shared/data/replica-island"),
        "{}",
        canonical.display()
    );
    assert!(canonical.join("FORMAT.md").is_file());
    assert!(canonical.join("collision.bin").is_file());
    // The data is read in place, never copied into the repository.
    let repo = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .canonicalize()
        .unwrap();
    assert!(
        !canonical.starts_with(&repo),
        "data must live outside the repository"
    );
}

#[test]
fn missing_data_dir_fails_naming_the_path_in_ci_and_skips_otherwise() {
    let missing = Path::new(DATA_DIR).join("no-such-subdirectory");
    let err = resolve_data_dir(&missing, true).unwrap_err();
    assert!(err.contains(&missing.display().to_string()), "{err}");
    assert_eq!(resolve_data_dir(&missing, false), Ok(None));
}

#[test]
fn collision_bin_defines_the_53_tiles_format_md_lists() {
    let Some(dir) = data_dir() else { return };
    let set = collision_set(&dir);
    let expected: Vec<u32> = (0..=12)
        .chain(15..=28)
        .chain(31..=44)
        .chain([48, 49])
        .chain(51..=60)
        .collect();
    assert_eq!(expected.len(), 53);
    assert_eq!(set.len(), 53);
    let ids: Vec<u32> = set.iter().map(|(id, _)| id.0).collect();
    assert_eq!(ids, expected);
    assert_eq!(set.tile_size(), Vec2::splat(TILE));
}

#[test]
fn collision_bin_tile_1_is_the_full_square() {
    let Some(dir) = data_dir() else { return };
    let set = collision_set(&dir);
    let shape = set.shape(TileId(1)).unwrap();
    let got: Vec<(Vec2, Vec2, Vec2)> = shape
        .segments()
        .iter()
        .map(|s| (s.a, s.b, s.normal))
        .collect();
    assert_eq!(
        got,
        vec![
            (v(0.0, 32.0), v(32.0, 32.0), v(0.0, 1.0)),
            (v(32.0, 32.0), v(32.0, 0.0), v(1.0, 0.0)),
            (v(32.0, 0.0), v(0.0, 0.0), v(0.0, -1.0)),
            (v(0.0, 0.0), v(0.0, 32.0), v(-1.0, 0.0)),
        ]
    );
    assert!(shape.has_inside());
    for p in [v(0.5, 0.5), v(16.0, 16.0), v(31.5, 31.5)] {
        assert!(shape.contains_point(p), "{p}");
    }
}

#[test]
fn collision_bin_tile_36_is_the_45_degree_ramp_rising_right() {
    let Some(dir) = data_dir() else { return };
    let set = collision_set(&dir);
    let shape = set.shape(TileId(36)).unwrap();
    assert_eq!(shape.segments().len(), 3);
    let surface = shape.segments()[0];
    assert_eq!((surface.a, surface.b), (v(0.0, 0.0), v(32.0, 32.0)));
    let h = std::f32::consts::FRAC_1_SQRT_2;
    assert!(
        (surface.normal - v(-h, h)).length() < 1e-6,
        "{}",
        surface.normal
    );
    // FORMAT.md's figure, to its 4 decimals.
    let rounded = (surface.normal * 1e4).round();
    assert_eq!(rounded, v(-7071.0, 7071.0));
    // Solid below-right of the diagonal, empty above-left.
    assert!(shape.has_inside());
    assert!(shape.contains_point(v(24.0, 8.0)));
    assert!(!shape.contains_point(v(8.0, 24.0)));
}

#[test]
fn collision_bin_tile_60_keeps_its_duplicated_edge_once() {
    let Some(dir) = data_dir() else { return };
    let raw = raw_tile_set(&read(&dir, "collision.bin"));
    let raw60 = raw.iter().find(|t| t.id == 60).unwrap();
    // In the file: 5 segments, the last two identical.
    assert_eq!(raw60.segments.len(), 5);
    assert_eq!(raw60.segments[3], raw60.segments[4]);

    let set = collision_set(&dir);
    let shape = set.shape(TileId(60)).unwrap();
    assert_eq!(shape.segments().len(), 4);
    let left = |s: &&tileslide::TileSegment| s.a == v(0.0, 0.0) && s.b == v(0.0, 32.0);
    assert_eq!(shape.segments().iter().filter(left).count(), 1);
    assert!(shape.has_inside(), "the outline is still closed");
}

#[test]
fn collision_bin_shapes_match_the_raw_bytes_bit_for_bit() {
    let Some(dir) = data_dir() else { return };
    let raw = raw_tile_set(&read(&dir, "collision.bin"));
    let set = collision_set(&dir);
    assert_eq!(raw.len(), set.len());
    for tile in &raw {
        let shape = set.shape(TileId(tile.id.into())).unwrap();
        // The loader keeps exact duplicates once and nothing else changes.
        let mut unique = tile.segments.clone();
        unique.dedup();
        assert_eq!(shape.segments().len(), unique.len(), "tile {}", tile.id);
        for (s, r) in shape.segments().iter().zip(&unique) {
            assert_eq!(s.a, Vec2::from(r.start), "tile {}", tile.id);
            assert_eq!(s.b, Vec2::from(r.end), "tile {}", tile.id);
            let n = Vec2::from(r.normal);
            assert!(
                (s.normal - n / n.length()).length() < 1e-6,
                "tile {}",
                tile.id
            );
            assert!((s.normal.length() - 1.0).abs() < 1e-6, "tile {}", tile.id);
        }
    }
}

#[test]
fn collisiontest_bin_is_a_level_not_a_tile_set() {
    // FORMAT.md calls collisiontest.bin "a second, smaller tile set"; its bytes say otherwise:
    // it starts with the level signature 96 and holds 3 layers of 50×13 cells, the first one
    // the collision layer. The tile set loader must refuse it cleanly, the level loader read it.
    let Some(dir) = data_dir() else { return };
    let path = dir.join("collisiontest.bin");
    let bytes = read(&dir, "collisiontest.bin");
    assert_eq!(bytes[0], 96);

    let err = replica::load_tile_set(&path).unwrap_err();
    assert_eq!(err.location, Location::Byte(0));
    assert!(
        matches!(
            err.kind,
            LoadErrorKind::BadSignature {
                field: "signature",
                expected: 52,
                found: 96,
                format: "Replica Island collision tile set",
            }
        ),
        "{err}"
    );
    assert!(err.to_string().contains("collisiontest.bin"), "{err}");

    let raw = raw_level(&bytes);
    assert_eq!(raw.claimed_len, bytes.len());
    assert_eq!(raw.layers.len(), 3);
    assert_eq!(
        (
            raw.layers[0].kind,
            raw.layers[0].width,
            raw.layers[0].height
        ),
        (1, 50, 13)
    );
    let map = replica::load_level(&path, Arc::new(collision_set(&dir))).unwrap();
    assert_eq!((map.width(), map.height()), (50, 13));
    assert!(map.active_segment_count() > 0);
}

#[test]
fn every_level_loads_with_its_header_size_and_some_active_segments() {
    let Some(dir) = data_dir() else { return };
    let set = Arc::new(collision_set(&dir));
    let names = level_names(&dir);
    assert!(
        names.len() >= 40,
        "only {} level files: {names:?}",
        names.len()
    );
    for name in &names {
        let bytes = read(&dir, name);
        let raw = raw_level(&bytes);
        let collision = raw.layers.iter().find(|l| l.kind == 1).unwrap();
        let map = replica::load_level(dir.join(name), Arc::clone(&set))
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(
            (map.width() as i32, map.height() as i32),
            (collision.width, collision.height),
            "{name}"
        );
        assert_eq!(map.cell_size(), Vec2::splat(TILE), "{name}");
        assert_eq!(map.origin(), Vec2::ZERO, "{name}");
        assert!(map.active_segment_count() > 0, "{name}");
        assert!(
            map.active_segment_count() <= map.placed_segment_count(),
            "{name}: {} active > {} placed",
            map.active_segment_count(),
            map.placed_segment_count()
        );
    }
}

#[test]
fn every_level_places_the_tile_of_each_byte_with_row_0_at_the_bottom() {
    let Some(dir) = data_dir() else { return };
    let raw_set = raw_tile_set(&read(&dir, "collision.bin"));
    let set = Arc::new(collision_set(&dir));
    for name in level_names(&dir) {
        let bytes = read(&dir, &name);
        let grid = RawGrid::from_level(&bytes);
        let map = replica::parse_level(&bytes, &name, Arc::clone(&set)).unwrap();
        let mut placed = 0usize;
        for (col, row) in grid.cells() {
            let expected = grid.tile(col, row, &raw_set);
            assert_eq!(
                map.tile(Cell::new(col, row)),
                expected.map(|id| TileId(id.into())),
                "{name} cell ({col}, {row})"
            );
            if let Some(id) = expected {
                let tile = raw_set.iter().find(|t| t.id == id).unwrap();
                let mut unique = tile.segments.clone();
                unique.dedup();
                placed += unique.len();
            }
        }
        assert_eq!(map.placed_segment_count(), placed, "{name}");
    }
}

#[test]
fn level_1_4_island_loads_although_its_final_layer_is_truncated() {
    let Some(dir) = data_dir() else { return };
    let bytes = read(&dir, "level_1_4_island.bin");
    let raw = raw_level(&bytes);
    // The file really is shorter than its headers claim...
    assert!(
        bytes.len() < raw.claimed_len,
        "{} bytes, headers claim {}",
        bytes.len(),
        raw.claimed_len
    );
    assert_eq!(raw.claimed_len - bytes.len(), 2738);
    // ...in its last layer, the hot spots (type 3), after the collision layer.
    let last = raw.layers.last().unwrap();
    assert_eq!(raw.layers.len(), raw.layer_count as usize);
    assert_eq!(last.kind, 3);
    assert!(last.cells_at < bytes.len());
    let collision = raw.layers.iter().find(|l| l.kind == 1).unwrap();
    assert!(collision.cells_at + (collision.width * collision.height) as usize <= bytes.len());

    let map = replica::load_level(
        dir.join("level_1_4_island.bin"),
        Arc::new(collision_set(&dir)),
    )
    .unwrap();
    assert_eq!((map.width(), map.height()), (80, 80));
    assert!(map.active_segment_count() > 0);
}

#[test]
fn level_1_1_island_is_90_by_50_with_5_layers() {
    let Some(dir) = data_dir() else { return };
    let bytes = read(&dir, "level_1_1_island.bin");
    let raw = raw_level(&bytes);
    assert_eq!(raw.layer_count, 5);
    assert!(raw.layers.iter().all(|l| (l.width, l.height) == (90, 50)));
    let map = replica::parse_level(
        &bytes,
        "level_1_1_island.bin",
        Arc::new(collision_set(&dir)),
    )
    .unwrap();
    assert_eq!((map.width(), map.height()), (90, 50));
    assert_eq!(map.bounds().max, v(90.0 * 32.0, 50.0 * 32.0));
}
