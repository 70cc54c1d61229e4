#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
//! Proves that every error of the Replica Island loaders (tile set and level) is reported
//! with the right kind at the right byte offset, and that its message names the file; and
//! that a level's objects and hot spots are read from hand-made bytes as FORMAT.md and the
//! game lay them out.

use std::sync::Arc;

use tileslide::io::replica::{HotSpotKind, ObjectKind};
use tileslide::io::{LoadError, LoadErrorKind, Location, replica};
use tileslide::{Cell, ShapeError, TileId, TileMap, TileSet, TileSetError, Vec2};

// ---------------------------------------------------------------------------------------
// Building files by hand (FORMAT.md), little-endian.

/// One segment: start, end, normal.
type Seg = [f32; 6];

const TOP: Seg = [0.0, 32.0, 32.0, 32.0, 0.0, 1.0];
const RIGHT: Seg = [32.0, 32.0, 32.0, 0.0, 1.0, 0.0];
const BOTTOM: Seg = [32.0, 0.0, 0.0, 0.0, 0.0, -1.0];
const LEFT: Seg = [0.0, 0.0, 0.0, 32.0, -1.0, 0.0];
const SQUARE: [Seg; 4] = [TOP, RIGHT, BOTTOM, LEFT];

fn tile_bytes(id: u8, segments: &[Seg]) -> Vec<u8> {
    let mut out = vec![id, segments.len() as u8];
    for s in segments {
        for f in s {
            out.extend_from_slice(&f.to_le_bytes());
        }
    }
    out
}

fn tile_set_bytes(tiles: &[(u8, &[Seg])]) -> Vec<u8> {
    let mut out = vec![52, tiles.len() as u8];
    for (id, segments) in tiles {
        out.extend(tile_bytes(*id, segments));
    }
    out
}

fn square_set() -> Arc<TileSet> {
    Arc::new(replica::parse_tile_set(&tile_set_bytes(&[(1, &SQUARE)]), "set.bin").unwrap())
}

/// A layer: type, then a tile map of `w × h` cells (`cells` may be shorter than claimed).
fn layer_bytes(kind: i8, w: i32, h: i32, cells: &[i8]) -> Vec<u8> {
    let mut out = vec![kind as u8, 0];
    out.extend_from_slice(&1.0f32.to_le_bytes());
    out.push(42);
    out.extend_from_slice(&w.to_le_bytes());
    out.extend_from_slice(&h.to_le_bytes());
    out.extend(cells.iter().map(|&c| c as u8));
    out
}

fn level_bytes(layers: &[Vec<u8>]) -> Vec<u8> {
    let mut out = vec![96, layers.len() as u8, 0];
    for l in layers {
        out.extend_from_slice(l);
    }
    out
}

/// Offsets in a level with its first layer at byte 3.
const FIRST_LAYER: usize = 3;
const MAP_SIGNATURE_AT: u64 = (FIRST_LAYER + 6) as u64;
const WIDTH_AT: u64 = MAP_SIGNATURE_AT + 1;
const HEIGHT_AT: u64 = WIDTH_AT + 4;
const CELLS_AT: u64 = HEIGHT_AT + 4;

fn set_err(data: &[u8]) -> LoadError {
    replica::parse_tile_set(data, "tiles/collision.bin").unwrap_err()
}

fn level_err(data: &[u8]) -> LoadError {
    replica::parse_level(data, "levels/level_9_9.bin", square_set()).unwrap_err()
}

/// The message names the file and, for a byte location, the offset.
fn assert_names_file(e: &LoadError, file: &str) {
    let text = e.to_string();
    assert!(text.starts_with(file), "{text}");
    if let Location::Byte(at) = e.location {
        assert!(text.contains(&format!("byte {at}")), "{text}");
    }
}

// ---------------------------------------------------------------------------------------
// Tile set.

#[test]
fn tile_set_valid_hand_made_file_loads() {
    let set = replica::parse_tile_set(&tile_set_bytes(&[(1, &SQUARE), (200, &[TOP])]), "set.bin")
        .unwrap();
    assert_eq!(set.len(), 2);
    assert_eq!(set.shape(TileId(200)).unwrap().segments().len(), 1);
}

#[test]
fn tile_set_wrong_signature_is_reported_at_byte_0() {
    let mut data = tile_set_bytes(&[(1, &SQUARE)]);
    data[0] = 53;
    let e = set_err(&data);
    assert_eq!(e.location, Location::Byte(0));
    assert!(
        matches!(
            e.kind,
            LoadErrorKind::BadSignature {
                field: "signature",
                expected: 52,
                found: 53,
                format: "Replica Island collision tile set",
            }
        ),
        "{e}"
    );
    assert_names_file(&e, "tiles/collision.bin");
    assert_eq!(
        e.to_string(),
        "tiles/collision.bin: byte 0: `signature` is 53, expected 52: not a Replica Island \
         collision tile set file"
    );
}

#[test]
fn tile_set_empty_file_is_truncated_in_the_signature() {
    let e = set_err(&[]);
    assert_eq!(e.location, Location::Byte(0));
    assert!(
        matches!(
            e.kind,
            LoadErrorKind::Truncated {
                field: "signature",
                needed: 1
            }
        ),
        "{e}"
    );
    assert_names_file(&e, "tiles/collision.bin");
}

#[test]
fn tile_set_truncated_in_header_names_tile_count_at_byte_1() {
    let e = set_err(&[52]);
    assert_eq!(e.location, Location::Byte(1));
    assert!(
        matches!(
            e.kind,
            LoadErrorKind::Truncated {
                field: "tileCount",
                needed: 1
            }
        ),
        "{e}"
    );
    assert_names_file(&e, "tiles/collision.bin");
}

#[test]
fn tile_set_truncated_before_a_tile_names_tile_index() {
    // Claims 2 tiles, holds 1.
    let mut data = tile_set_bytes(&[(1, &SQUARE)]);
    data[1] = 2;
    let e = set_err(&data);
    assert_eq!(e.location, Location::Byte(data.len() as u64));
    assert!(
        matches!(
            e.kind,
            LoadErrorKind::Truncated {
                field: "tileIndex",
                needed: 1
            }
        ),
        "{e}"
    );
}

#[test]
fn tile_set_truncated_mid_segment_names_the_failing_field_and_its_offset() {
    // Header (2) + tile header (2) + startX, startY, endX, endY (16) + 2 bytes of normalX.
    let data = tile_set_bytes(&[(1, &[TOP])]);
    let cut = &data[..2 + 2 + 16 + 2];
    let e = set_err(cut);
    assert_eq!(e.location, Location::Byte(20));
    assert!(
        matches!(
            e.kind,
            LoadErrorKind::Truncated {
                field: "normalX",
                needed: 2
            }
        ),
        "{e}"
    );
    assert_names_file(&e, "tiles/collision.bin");
    assert!(e.to_string().contains("`normalX`"), "{e}");

    // Cut on a field boundary inside the second segment: the next field is named.
    let data = tile_set_bytes(&[(1, &SQUARE)]);
    let e = set_err(&data[..2 + 2 + 24 + 4]);
    assert_eq!(e.location, Location::Byte(32));
    assert!(
        matches!(
            e.kind,
            LoadErrorKind::Truncated {
                field: "startY",
                needed: 4
            }
        ),
        "{e}"
    );
}

#[test]
fn tile_set_duplicate_tile_id_is_reported_at_the_second_tile() {
    let data = tile_set_bytes(&[(7, &SQUARE), (3, &[TOP]), (7, &[TOP])]);
    let second = 2 + (2 + 4 * 24) + (2 + 24);
    let e = set_err(&data);
    assert_eq!(e.location, Location::Byte(second as u64));
    assert!(matches!(e.kind, LoadErrorKind::DuplicateTile(7)), "{e}");
    assert_names_file(&e, "tiles/collision.bin");
    assert!(e.to_string().contains("tile 7 is defined twice"), "{e}");
}

#[test]
fn tile_set_nan_coordinate_names_the_tile_id() {
    let mut bad = RIGHT;
    bad[1] = f32::NAN;
    let data = tile_set_bytes(&[(1, &SQUARE), (9, &[TOP, bad])]);
    let tile_at = 2 + 2 + 4 * 24;
    let e = set_err(&data);
    assert_eq!(e.location, Location::Byte(tile_at as u64));
    assert!(
        is_invalid_tile(&e.kind, 9, ShapeError::NonFinite { segment: 1 }),
        "{e}"
    );
    assert_names_file(&e, "tiles/collision.bin");
    assert!(e.to_string().contains("tile 9"), "{e}");
}

/// Whether `kind` is tile `id`'s shape refused for `source`.
fn is_invalid_tile(kind: &LoadErrorKind, id: u32, source: ShapeError) -> bool {
    matches!(kind, LoadErrorKind::TileSet(e) if *e == TileSetError::InvalidTile {
        id: TileId(id),
        source,
    })
}

#[test]
fn tile_set_infinite_normal_is_refused_as_non_finite() {
    let mut bad = TOP;
    bad[5] = f32::INFINITY;
    let e = set_err(&tile_set_bytes(&[(4, &[bad])]));
    assert_eq!(e.location, Location::Byte(2));
    assert!(
        is_invalid_tile(&e.kind, 4, ShapeError::NonFinite { segment: 0 }),
        "{e}"
    );
}

#[test]
fn tile_set_zero_length_segment_names_tile_and_segment() {
    let point: Seg = [5.0, 5.0, 5.0, 5.0, 0.0, 1.0];
    let e = set_err(&tile_set_bytes(&[(12, &[TOP, RIGHT, point])]));
    assert_eq!(e.location, Location::Byte(2));
    assert!(
        is_invalid_tile(&e.kind, 12, ShapeError::ZeroLength { segment: 2 }),
        "{e}"
    );
    assert_names_file(&e, "tiles/collision.bin");
    assert!(e.to_string().contains("tile 12"), "{e}");
}

#[test]
fn tile_set_zero_normal_is_refused() {
    let flat: Seg = [0.0, 32.0, 32.0, 32.0, 0.0, 0.0];
    let e = set_err(&tile_set_bytes(&[(5, &[flat])]));
    assert!(
        is_invalid_tile(&e.kind, 5, ShapeError::ZeroNormal { segment: 0 }),
        "{e}"
    );
}

#[test]
fn tile_set_segment_outside_the_32_pixel_tile_is_refused() {
    let long: Seg = [0.0, 32.0, 64.0, 32.0, 0.0, 1.0];
    let e = set_err(&tile_set_bytes(&[(6, &[long])]));
    assert_eq!(e.location, Location::Byte(2));
    assert!(
        matches!(
            e.kind,
            LoadErrorKind::TileSet(TileSetError::InvalidTile {
                id: TileId(6),
                source: ShapeError::OutsideTile { segment: 0, .. },
            })
        ),
        "{e}"
    );
}

#[test]
fn tile_set_trailing_bytes_are_reported_with_offset_and_count() {
    let mut data = tile_set_bytes(&[(1, &SQUARE)]);
    let end = data.len() as u64;
    data.extend_from_slice(&[0, 0, 0]);
    let e = set_err(&data);
    assert_eq!(e.location, Location::Byte(end));
    assert!(matches!(e.kind, LoadErrorKind::TrailingBytes(3)), "{e}");
    assert_names_file(&e, "tiles/collision.bin");
}

#[test]
fn tile_set_missing_file_is_an_io_error_naming_it() {
    let path = "/nonexistent-tileslide-dir/collision.bin";
    let e = replica::load_tile_set(path).unwrap_err();
    assert_eq!(e.location, Location::File);
    assert_eq!(e.io_error_kind(), Some(std::io::ErrorKind::NotFound), "{e}");
    assert!(e.to_string().starts_with(path), "{e}");
}

// ---------------------------------------------------------------------------------------
// Level.

#[test]
fn level_hand_made_file_flips_rows_so_row_0_is_the_bottom() {
    // 3 × 2 cells, file rows top first: the top row holds a square at column 0.
    let data = level_bytes(&[layer_bytes(1, 3, 2, &[1, -1, -1, -1, -1, 1])]);
    let map = replica::parse_level(&data, "l.bin", square_set()).unwrap();
    assert_eq!((map.width(), map.height()), (3, 2));
    assert_eq!(map.tile(Cell::new(0, 1)), Some(TileId(1)));
    assert_eq!(map.tile(Cell::new(2, 0)), Some(TileId(1)));
    assert_eq!(map.tile(Cell::new(0, 0)), None);
    assert_eq!(map.tile(Cell::new(2, 1)), None);
}

#[test]
fn level_negative_and_unknown_tile_ids_are_empty_cells() {
    // -1 and -128 are empty; 2, 13 and 127 are not in the set.
    let data = level_bytes(&[layer_bytes(1, 6, 1, &[-1, -128, 2, 13, 127, 1])]);
    let map = replica::parse_level(&data, "l.bin", square_set()).unwrap();
    let tiles: Vec<_> = (0..6).map(|c| map.tile(Cell::new(c, 0))).collect();
    assert_eq!(tiles, [None, None, None, None, None, Some(TileId(1))]);
    assert_eq!(map.placed_segment_count(), 4);
}

#[test]
fn level_layers_after_the_collision_layer_are_not_read() {
    // A second layer that is pure garbage (bad map signature, cut short) does not matter.
    let mut data = level_bytes(&[layer_bytes(1, 1, 1, &[1]), vec![2, 0, 0, 0]]);
    data[1] = 2;
    let map = replica::parse_level(&data, "l.bin", square_set()).unwrap();
    assert_eq!(map.tile(Cell::new(0, 0)), Some(TileId(1)));
}

#[test]
fn level_layers_before_the_collision_layer_are_skipped() {
    let data = level_bytes(&[
        layer_bytes(0, 4, 4, &[5; 16]),
        layer_bytes(1, 2, 1, &[-1, 1]),
    ]);
    let map = replica::parse_level(&data, "l.bin", square_set()).unwrap();
    assert_eq!((map.width(), map.height()), (2, 1));
    assert_eq!(map.tile(Cell::new(1, 0)), Some(TileId(1)));
}

#[test]
fn level_wrong_signature_is_reported_at_byte_0() {
    let mut data = level_bytes(&[layer_bytes(1, 1, 1, &[1])]);
    data[0] = 95;
    let e = level_err(&data);
    assert_eq!(e.location, Location::Byte(0));
    assert!(
        matches!(
            e.kind,
            LoadErrorKind::BadSignature {
                field: "signature",
                expected: 96,
                found: 95,
                format: "Replica Island level",
            }
        ),
        "{e}"
    );
    assert_names_file(&e, "levels/level_9_9.bin");
}

#[test]
fn level_collision_tile_set_given_as_level_is_a_bad_signature() {
    let e = level_err(&tile_set_bytes(&[(1, &SQUARE)]));
    assert_eq!(e.location, Location::Byte(0));
    assert!(
        matches!(
            e.kind,
            LoadErrorKind::BadSignature {
                found: 52,
                expected: 96,
                ..
            }
        ),
        "{e}"
    );
}

#[test]
fn level_negative_layer_count_is_reported_at_byte_1() {
    let e = level_err(&[96, (-3i8) as u8, 0]);
    assert_eq!(e.location, Location::Byte(1));
    assert!(
        matches!(
            &e.kind,
            LoadErrorKind::BadSize {
                field: "layerCount",
                value: -3,
                ..
            }
        ),
        "{e}"
    );
    assert_names_file(&e, "levels/level_9_9.bin");
}

#[test]
fn level_truncated_header_names_the_field() {
    let e = level_err(&[96, 1]);
    assert_eq!(e.location, Location::Byte(2));
    assert!(
        matches!(
            e.kind,
            LoadErrorKind::Truncated {
                field: "backgroundIndex",
                needed: 1
            }
        ),
        "{e}"
    );
    // Cut inside the first layer's scroll speed.
    let data = level_bytes(&[layer_bytes(1, 1, 1, &[1])]);
    let e = level_err(&data[..FIRST_LAYER + 2 + 1]);
    assert_eq!(e.location, Location::Byte((FIRST_LAYER + 2) as u64));
    assert!(
        matches!(
            e.kind,
            LoadErrorKind::Truncated {
                field: "scrollSpeed",
                needed: 3
            }
        ),
        "{e}"
    );
    assert_names_file(&e, "levels/level_9_9.bin");
}

#[test]
fn level_bad_tile_map_signature_is_reported_at_its_offset() {
    let mut data = level_bytes(&[layer_bytes(1, 1, 1, &[1])]);
    data[MAP_SIGNATURE_AT as usize] = 41;
    let e = level_err(&data);
    assert_eq!(e.location, Location::Byte(MAP_SIGNATURE_AT));
    assert!(
        matches!(
            e.kind,
            LoadErrorKind::BadSignature {
                field: "tile map signature",
                expected: 42,
                found: 41,
                format: "Replica Island level",
            }
        ),
        "{e}"
    );
    assert_names_file(&e, "levels/level_9_9.bin");
}

#[test]
fn level_bad_tile_map_signature_of_a_later_layer_is_at_that_layers_offset() {
    let first = layer_bytes(0, 2, 2, &[0; 4]);
    let second_at = FIRST_LAYER + first.len();
    let mut data = level_bytes(&[first, layer_bytes(1, 1, 1, &[1])]);
    data[second_at + 6] = 0;
    let e = level_err(&data);
    assert_eq!(e.location, Location::Byte((second_at + 6) as u64));
    assert!(
        matches!(e.kind, LoadErrorKind::BadSignature { found: 0, .. }),
        "{e}"
    );
}

#[test]
fn level_zero_width_is_reported_at_the_width_field() {
    let e = level_err(&level_bytes(&[layer_bytes(1, 0, 5, &[])]));
    assert_eq!(e.location, Location::Byte(WIDTH_AT));
    assert!(
        matches!(
            &e.kind,
            LoadErrorKind::BadSize {
                field: "width",
                value: 0,
                ..
            }
        ),
        "{e}"
    );
    assert_names_file(&e, "levels/level_9_9.bin");
}

#[test]
fn level_negative_height_is_reported_at_the_height_field() {
    let e = level_err(&level_bytes(&[layer_bytes(1, 5, -5, &[])]));
    assert_eq!(e.location, Location::Byte(HEIGHT_AT));
    assert!(
        matches!(
            &e.kind,
            LoadErrorKind::BadSize {
                field: "height",
                value: -5,
                ..
            }
        ),
        "{e}"
    );
    let e = level_err(&level_bytes(&[layer_bytes(1, 5, i32::MIN, &[])]));
    assert_eq!(e.location, Location::Byte(HEIGHT_AT));
    assert!(
        matches!(
            &e.kind,
            LoadErrorKind::BadSize {
                field: "height",
                ..
            }
        ),
        "{e}"
    );
}

#[test]
fn level_absurd_size_field_is_refused_before_allocating() {
    // 2³¹ − 1 columns: the loader must compare against the bytes present (here 4) and say
    // so, not try to allocate two gigabytes.
    let data = level_bytes(&[layer_bytes(1, i32::MAX, 1, &[1, 1, 1, 1])]);
    let e = level_err(&data);
    assert_eq!(e.location, Location::Byte(WIDTH_AT));
    let LoadErrorKind::BadSize {
        field,
        value,
        reason,
    } = &e.kind
    else {
        panic!("{e}")
    };
    assert_eq!(*field, "width × height");
    assert_eq!(*value, i64::from(i32::MAX));
    assert!(reason.contains("2147483647 bytes"), "{reason}");
    assert!(reason.contains("only 4 remain"), "{reason}");
    assert_names_file(&e, "levels/level_9_9.bin");

    // Both fields at 2³¹ − 1: the product does not overflow either.
    let e = level_err(&level_bytes(&[layer_bytes(1, i32::MAX, i32::MAX, &[])]));
    let expected = i64::from(i32::MAX) * i64::from(i32::MAX);
    assert!(
        matches!(&e.kind, LoadErrorKind::BadSize { value, .. } if *value == expected),
        "{e}"
    );
    assert!(e.to_string().contains("only 0 remain"), "{e}");
}

#[test]
fn level_absurd_size_in_a_skipped_layer_is_refused_too() {
    let data = level_bytes(&[layer_bytes(2, i32::MAX, 2, &[0; 8])]);
    let e = level_err(&data);
    assert_eq!(e.location, Location::Byte(WIDTH_AT));
    assert!(e.to_string().contains("only 8 remain"), "{e}");
}

#[test]
fn level_truncated_collision_layer_says_bytes_needed_and_remaining() {
    // 4 × 4 cells claimed, 10 present.
    let e = level_err(&level_bytes(&[layer_bytes(1, 4, 4, &[1; 10])]));
    assert_eq!(e.location, Location::Byte(WIDTH_AT));
    let LoadErrorKind::BadSize {
        field,
        value,
        reason,
    } = &e.kind
    else {
        panic!("{e}")
    };
    assert_eq!((*field, *value), ("width × height", 16));
    assert!(
        reason.contains("need 16 bytes but only 10 remain"),
        "{reason}"
    );
    assert_names_file(&e, "levels/level_9_9.bin");
    // Exactly one byte short is still refused; the exact size loads.
    let e = level_err(&level_bytes(&[layer_bytes(1, 4, 4, &[1; 15])]));
    assert!(e.to_string().contains("only 15 remain"), "{e}");
    assert!(
        replica::parse_level(
            &level_bytes(&[layer_bytes(1, 4, 4, &[1; 16])]),
            "l",
            square_set()
        )
        .is_ok()
    );
}

#[test]
fn level_truncated_before_cells_at_data_end_is_the_same_error() {
    let data = level_bytes(&[layer_bytes(1, 2, 2, &[])]);
    let e = level_err(&data);
    assert_eq!(e.location, Location::Byte(WIDTH_AT));
    assert!(e.to_string().contains("only 0 remain"), "{e}");
    assert_eq!(data.len() as u64, CELLS_AT);
}

#[test]
fn level_without_collision_layer_is_reported_for_the_whole_file() {
    let e = level_err(&level_bytes(&[
        layer_bytes(0, 2, 2, &[1; 4]),
        layer_bytes(3, 1, 1, &[0]),
    ]));
    assert_eq!(e.location, Location::File);
    assert!(matches!(e.kind, LoadErrorKind::NoCollisionLayer), "{e}");
    assert_eq!(
        e.to_string(),
        "levels/level_9_9.bin: the level has no collision layer (type 1)"
    );
    // No layers at all.
    let e = level_err(&[96, 0, 0]);
    assert!(matches!(e.kind, LoadErrorKind::NoCollisionLayer), "{e}");
}

#[test]
fn level_collision_layer_larger_than_the_map_limit_is_refused() {
    // 8193 × 8193 > 2²⁶ cells, with the bytes actually present (64 MiB of -1).
    let (w, h) = (8193, 8193);
    let mut data = level_bytes(&[layer_bytes(1, w, h, &[])]);
    data.resize(data.len() + (w * h) as usize, 0xff);
    let e = level_err(&data);
    assert_eq!(e.location, Location::Byte(WIDTH_AT));
    assert!(
        matches!(
            &e.kind,
            LoadErrorKind::BadSize {
                field: "width × height",
                ..
            }
        ),
        "{e}"
    );
    assert_names_file(&e, "levels/level_9_9.bin");
}

#[test]
fn level_missing_file_is_an_io_error_naming_it() {
    let path = "/nonexistent-tileslide-dir/level_1_1_island.bin";
    let e = replica::load_level(path, square_set()).unwrap_err();
    assert_eq!(e.location, Location::File);
    assert_eq!(e.io_error_kind(), Some(std::io::ErrorKind::NotFound), "{e}");
    assert!(e.to_string().starts_with(path), "{e}");
}

#[test]
fn level_loaded_from_disk_names_the_path_it_was_given() {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("loader_replica_errors");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("bad_level.bin");
    std::fs::write(&path, [96u8, 1, 0, 1, 0]).unwrap();
    let e = replica::load_level(&path, square_set()).unwrap_err();
    assert_eq!(e.path, path);
    assert_eq!(e.location, Location::Byte(5));
    assert!(
        e.to_string().starts_with(&path.display().to_string()),
        "{e}"
    );
}

#[test]
fn loaded_map_matches_one_built_directly() {
    // The loader is a thin layer: same tiles, same active segments as TileMap::from_tiles.
    let data = level_bytes(&[layer_bytes(1, 3, 2, &[1, 1, -1, -1, 1, 1])]);
    let map = replica::parse_level(&data, "l.bin", square_set()).unwrap();
    let t = Some(TileId(1));
    let direct =
        TileMap::from_tiles(square_set(), 3, 2, Vec2::ZERO, &[None, t, t, t, t, None]).unwrap();
    assert_eq!(map.active_segment_count(), direct.active_segment_count());
    for r in 0..2 {
        for c in 0..3 {
            let cell = Cell::new(c, r);
            assert_eq!(map.tile(cell), direct.tile(cell));
            assert!(map.active_segments(cell).eq(direct.active_segments(cell)));
        }
    }
}

// ---------------------------------------------------------------------------------------
// Objects and hot spots (`parse_objects`).

fn objects_err(data: &[u8]) -> LoadError {
    replica::parse_objects(data, "levels/level_9_9.bin").unwrap_err()
}

/// Offset of the `n`-th layer's `type` byte in a level of `w × h` layers.
fn layer_at(n: usize, w: i32, h: i32) -> u64 {
    (FIRST_LAYER + n * (15 + (w * h) as usize)) as u64
}

#[test]
fn objects_are_read_with_their_type_number_kind_cell_and_pixels() {
    // 3 × 2 cells, top row first: a coin and a bat on top, the player bottom right; -1
    // and -7 are empty, 4 is a number the game does not define.
    let data = level_bytes(&[
        layer_bytes(0, 5, 1, &[1; 5]),
        layer_bytes(1, 3, 2, &[-1; 6]),
        layer_bytes(2, 3, 2, &[1, 6, -1, 4, -7, 0]),
        layer_bytes(3, 3, 2, &[9, -1, 39, -1, -1, 13]),
    ]);
    let level = replica::parse_objects(&data, "l.bin").unwrap();
    assert_eq!((level.width, level.height), (3, 2));
    let got: Vec<(u8, Option<ObjectKind>, Cell, Vec2)> = level
        .objects
        .iter()
        .map(|o| (o.type_number, o.kind, o.cell, o.position))
        .collect();
    assert_eq!(
        got,
        [
            (
                1,
                Some(ObjectKind::Coin),
                Cell::new(0, 1),
                Vec2::new(0.0, 32.0)
            ),
            (
                6,
                Some(ObjectKind::Bat),
                Cell::new(1, 1),
                Vec2::new(32.0, 32.0)
            ),
            (4, None, Cell::new(0, 0), Vec2::new(0.0, 0.0)),
            (
                0,
                Some(ObjectKind::Player),
                Cell::new(2, 0),
                Vec2::new(64.0, 0.0)
            ),
        ]
    );
    assert_eq!(level.player_spawn().unwrap().cell, Cell::new(2, 0));
    assert_eq!(level.of_kind(ObjectKind::Bat).count(), 1);
    let spots = level.hot_spots.as_ref().unwrap();
    assert_eq!(spots.kind(Cell::new(0, 1)), Some(HotSpotKind::Die));
    assert_eq!(
        spots.kind(Cell::new(2, 1)),
        Some(HotSpotKind::NpcSelectDialog {
            character: 2,
            entry: 2
        })
    );
    assert_eq!(spots.kind(Cell::new(2, 0)), Some(HotSpotKind::EndLevel));
    assert_eq!(spots.iter().count(), 3);
    assert_eq!(level.cut_short, None);
}

#[test]
fn objects_of_a_level_without_object_or_hot_spot_layers_are_none() {
    let level =
        replica::parse_objects(&level_bytes(&[layer_bytes(1, 2, 1, &[1, 1])]), "l").unwrap();
    assert!(level.objects.is_empty());
    assert_eq!(level.hot_spots, None);
    assert_eq!(level.player_spawn(), None);
}

#[test]
fn objects_the_game_spawns_twice_start_the_player_at_the_last() {
    // The game spawns a player at each `PLAYER` cell and plays the last one spawned.
    let data = level_bytes(&[
        layer_bytes(1, 2, 2, &[-1; 4]),
        layer_bytes(2, 2, 2, &[0, -1, -1, 0]),
    ]);
    let level = replica::parse_objects(&data, "l").unwrap();
    assert_eq!(level.of_kind(ObjectKind::Player).count(), 2);
    assert_eq!(level.player_spawn().unwrap().cell, Cell::new(1, 0));
}

#[test]
fn objects_a_cut_short_last_object_or_hot_spot_layer_is_read_as_empty_and_reported() {
    for layer_type in [2, 3] {
        let data = level_bytes(&[
            layer_bytes(1, 2, 2, &[1; 4]),
            layer_bytes(layer_type, 2, 2, &[0, 1]),
        ]);
        let level = replica::parse_objects(&data, "l").unwrap();
        let cut = level.cut_short.unwrap();
        assert_eq!(
            (cut.index, cut.layer_type, cut.cells, cut.present),
            (1, layer_type, 4, 2)
        );
        assert_eq!(cut.cells_at, layer_at(1, 2, 2) + 15);
        assert!(level.objects.is_empty() && level.hot_spots.is_none());
    }
}

#[test]
fn objects_a_cut_short_layer_that_is_not_the_last_is_an_error() {
    // Three layers declared, the file ends in the second.
    let mut data = level_bytes(&[layer_bytes(1, 2, 2, &[1; 4]), layer_bytes(2, 2, 2, &[0, 1])]);
    data[1] = 3;
    let e = objects_err(&data);
    assert_eq!(e.location, Location::Byte(layer_at(1, 2, 2) + 7));
    assert!(
        e.to_string().contains("need 4 bytes but only 2 remain"),
        "{e}"
    );
    assert_names_file(&e, "levels/level_9_9.bin");
    // A cut-short background or collision layer is an error even when it is the last.
    for layer_type in [0, 1] {
        let data = level_bytes(&[
            layer_bytes(1, 2, 2, &[1; 4]),
            layer_bytes(layer_type, 2, 2, &[1; 3]),
        ]);
        let e = objects_err(&data);
        assert!(e.to_string().contains("only 3 remain"), "{layer_type}: {e}");
    }
    // And so is a cut-short last object layer whose size is not the collision layer's.
    let data = level_bytes(&[layer_bytes(1, 2, 2, &[1; 4]), layer_bytes(2, 3, 2, &[0])]);
    let e = objects_err(&data);
    assert_eq!(e.location, Location::Byte(layer_at(1, 2, 2) + 7));
    assert!(
        e.to_string().contains("3×2 cells, the collision layer 2×2"),
        "{e}"
    );
}

#[test]
fn objects_absurd_object_layer_size_is_refused_before_allocating() {
    let data = level_bytes(&[
        layer_bytes(1, 2, 2, &[1; 4]),
        layer_bytes(2, i32::MAX, i32::MAX, &[0; 8]),
        layer_bytes(3, 2, 2, &[0; 4]),
    ]);
    let e = objects_err(&data);
    assert_eq!(e.location, Location::Byte(layer_at(1, 2, 2) + 7));
    let expected = i64::from(i32::MAX) * i64::from(i32::MAX);
    assert!(
        matches!(&e.kind, LoadErrorKind::BadSize { value, .. } if *value == expected),
        "{e}"
    );
    assert!(e.to_string().contains("only 27 remain"), "{e}");
    // A negative size is refused at its field.
    let data = level_bytes(&[layer_bytes(1, 2, 2, &[1; 4]), layer_bytes(2, 2, -2, &[])]);
    let e = objects_err(&data);
    assert_eq!(e.location, Location::Byte(layer_at(1, 2, 2) + 11));
    assert!(
        matches!(
            e.kind,
            LoadErrorKind::BadSize {
                field: "height",
                ..
            }
        ),
        "{e}"
    );
}

#[test]
fn objects_a_layer_of_another_size_than_the_collision_layer_is_refused() {
    for layer_type in [2, 3] {
        // Before the collision layer, or after it: the same error at the layer's width.
        let (small, big) = (
            layer_bytes(layer_type, 1, 2, &[0, 0]),
            layer_bytes(1, 2, 2, &[1; 4]),
        );
        let e = objects_err(&level_bytes(&[small.clone(), big.clone()]));
        assert_eq!(e.location, Location::Byte(WIDTH_AT));
        assert!(
            e.to_string().contains(&format!(
                "the layer of type {layer_type} has 1×2 cells, the collision layer 2×2"
            )),
            "{e}"
        );
        let e = objects_err(&level_bytes(&[big, small]));
        assert_eq!(e.location, Location::Byte(layer_at(1, 2, 2) + 7));
    }
}

#[test]
fn objects_a_second_object_or_hot_spot_layer_is_refused_at_its_type() {
    for layer_type in [2, 3] {
        let data = level_bytes(&[
            layer_bytes(1, 1, 1, &[1]),
            layer_bytes(layer_type, 1, 1, &[0]),
            layer_bytes(layer_type, 1, 1, &[0]),
        ]);
        let e = objects_err(&data);
        assert_eq!(e.location, Location::Byte(layer_at(2, 1, 1)));
        assert_eq!(
            e.to_string(),
            format!(
                "levels/level_9_9.bin: byte {}: layer 2: `type` is {layer_type} again, \
                 expected at most one object layer (2) and one hot-spot layer (3)",
                layer_at(2, 1, 1)
            )
        );
    }
}

#[test]
fn objects_bytes_after_the_last_layer_are_refused() {
    let mut data = level_bytes(&[layer_bytes(1, 1, 1, &[1]), layer_bytes(2, 1, 1, &[0])]);
    let end = data.len() as u64;
    data.extend([7, 7]);
    let e = objects_err(&data);
    assert_eq!(e.location, Location::Byte(end));
    assert!(matches!(e.kind, LoadErrorKind::TrailingBytes(2)), "{e}");
}

#[test]
fn objects_of_a_file_that_is_not_a_level_are_refused_as_parse_level_refuses_them() {
    let set = tile_set_bytes(&[(1, &SQUARE)]);
    for data in [
        set.as_slice(),
        &[96],
        &[96, 0xff, 0],
        &[96, 0, 0],
        &[96, 1, 0, 1, 0, 0, 0, 0, 0, 41],
    ] {
        let e = objects_err(data);
        let f = level_err(data);
        assert_eq!((e.location, e.to_string()), (f.location, f.to_string()));
    }
}

#[test]
fn objects_loaded_from_disk_name_the_path_they_were_given() {
    let path = "/nonexistent-tileslide-dir/level_1_1_island.bin";
    let e = replica::load_objects(path).unwrap_err();
    assert_eq!(e.io_error_kind(), Some(std::io::ErrorKind::NotFound), "{e}");
    assert!(e.to_string().starts_with(path), "{e}");
}
