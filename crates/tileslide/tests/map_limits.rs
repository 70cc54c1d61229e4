//! Map size limits: what `MAX_CELLS` promises is accepted, what exceeds it is refused.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::sync::Arc;

use tileslide::limits::{MAX_CELLS, MAX_FILE_BYTES};
use tileslide::{Cell, MapError, TileId, TileMap, TileSet, TileShape, Vec2};

fn round_tile(vertices: usize) -> TileSet {
    let mut set = TileSet::new(Vec2::ONE).unwrap();
    let points: Vec<Vec2> = (0..vertices)
        .map(|i| {
            let a = i as f32 / vertices as f32 * std::f32::consts::TAU;
            Vec2::new(0.5 + 0.45 * a.cos(), 0.5 + 0.45 * a.sin())
        })
        .collect();
    set.insert(TileId(1), TileShape::polygon(&points).unwrap())
        .unwrap();
    set
}

#[test]
fn large_map_with_many_segment_tiles_is_accepted() {
    // Regression: a pessimistic bound on the segment pool refused maps well within
    // MAX_CELLS as soon as a tile had many segments (here 1024 × 512 cells of a 1024-gon).
    let set = Arc::new(round_tile(1024));
    let mut map = TileMap::new(set, 1024, 512, Vec2::ZERO).unwrap();
    map.set_tile(Cell::new(3, 4), Some(TileId(1))).unwrap();
    assert_eq!(map.active_segment_count(), 1024);
}

#[test]
fn more_cells_than_max_cells_is_refused() {
    let set = Arc::new(round_tile(8));
    let side = (MAX_CELLS as f64).sqrt() as u32 + 1;
    assert_eq!(
        TileMap::new(set, side, side, Vec2::ZERO).unwrap_err(),
        MapError::TooLarge {
            width: side,
            height: side
        }
    );
}

#[test]
fn an_edit_that_would_overfill_a_cell_is_refused_and_changes_nothing() {
    use tileslide::{QueryFilter, Ray, SegmentFlags, TileSegment};
    let v = Vec2::new;
    let mut set = TileSet::new(Vec2::ONE).unwrap();
    // Tile 1: 300 overlapping segments along its right edge (normals differ by a hair, so
    // none is a duplicate), and a floor across the middle.
    let mut a: Vec<TileSegment> = (0..300)
        .map(|i| {
            TileSegment::new(
                v(1.0, 0.0),
                v(1.0, 1.0),
                v(1.0, i as f32 * 1e-6),
                SegmentFlags::SOLID,
            )
        })
        .collect();
    a.push(TileSegment::new(
        v(0.0, 0.5),
        v(1.0, 0.5),
        v(0.0, -1.0),
        SegmentFlags::SOLID,
    ));
    set.insert(TileId(1), TileShape::from_segments(a).unwrap())
        .unwrap();
    // Tile 2: 300 short solid covers along its left edge, facing left.
    let b: Vec<TileSegment> = (0..300)
        .map(|k| {
            let y = k as f32 / 300.0;
            TileSegment::new(
                v(0.0, y),
                v(0.0, y + 0.5 / 300.0),
                v(-1.0, 0.0),
                SegmentFlags::SOLID,
            )
        })
        .collect();
    set.insert(TileId(2), TileShape::from_segments(b).unwrap())
        .unwrap();
    let mut map = TileMap::new(Arc::new(set), 2, 1, Vec2::ZERO).unwrap();
    map.set_tile(Cell::new(0, 0), Some(TileId(1))).unwrap();
    let down = Ray::between(v(0.5, 0.1), v(0.5, 0.9));
    let before = map.cast_ray(down, &QueryFilter::default());
    assert!(
        before.is_some_and(|h| (h.point.y - 0.5).abs() < 1e-6),
        "{before:?}"
    );
    // Each of the 300 edge segments would be cut into 301 pieces: more than a cell holds.
    assert_eq!(
        map.set_tile(Cell::new(1, 0), Some(TileId(2))),
        Err(MapError::TooManySegments)
    );
    assert_eq!(map.tile(Cell::new(1, 0)), None);
    assert_eq!(map.cast_ray(down, &QueryFilter::default()), before);
    assert_eq!(map.active_segment_count(), 301);
}

#[test]
fn tile_id_u32_max_is_reserved() {
    use tileslide::TileSetError;
    let mut set = TileSet::new(Vec2::ONE).unwrap();
    let square = TileShape::polygon(&[Vec2::ZERO, Vec2::X, Vec2::ONE, Vec2::Y]).unwrap();
    assert_eq!(
        set.insert(TileId(u32::MAX), square),
        Err(TileSetError::ReservedId)
    );
}

#[test]
fn cell_at_agrees_with_cell_corner_for_awkward_cell_sizes() {
    for size in [0.1f32, 0.3, 0.7, 1.1, 3.3, 32.0] {
        let set = Arc::new(TileSet::new(Vec2::splat(size)).unwrap());
        let map = TileMap::new(set, 40, 3, Vec2::new(0.1, 0.1)).unwrap();
        for col in 0..40 {
            let cell = Cell::new(col, 1);
            assert_eq!(
                map.cell_at(map.cell_corner(cell)),
                Some(cell),
                "size {size}, col {col}"
            );
        }
    }
}

#[test]
fn a_map_reaching_past_max_coord_is_refused() {
    use tileslide::limits::MAX_COORD;
    // 2^20 cells of 32 map units reach 2^25, past the coordinate range.
    let mut set = TileSet::new(Vec2::splat(32.0)).unwrap();
    set.insert(
        TileId(1),
        TileShape::polygon(&[
            Vec2::ZERO,
            Vec2::X * 32.0,
            Vec2::splat(32.0),
            Vec2::Y * 32.0,
        ])
        .unwrap(),
    )
    .unwrap();
    let set = Arc::new(set);
    let err = TileMap::new(set.clone(), 1 << 20, 1, Vec2::ZERO).unwrap_err();
    assert!(matches!(err, MapError::OutOfRange { far_x, .. } if far_x == 33_554_432.0));
    assert!(err.to_string().contains("MAX_COORD"), "{err}");
    // An origin past the range, and one whose map ends exactly on it.
    assert!(matches!(
        TileMap::new(set.clone(), 1, 1, Vec2::new(0.0, -2.0 * MAX_COORD)),
        Err(MapError::OutOfRange { .. })
    ));
    assert!(TileMap::new(set, 4, 4, Vec2::splat(MAX_COORD - 128.0)).is_ok());
}

#[test]
fn a_map_file_larger_than_max_file_bytes_is_refused_before_it_is_read() {
    // A sparse file one byte past the limit: its size says so, and nothing is read.
    let path = std::env::temp_dir().join(format!("tileslide-huge-{}.txt", std::process::id()));
    let file = std::fs::File::create(&path).unwrap();
    file.set_len(MAX_FILE_BYTES + 1).unwrap();
    drop(file);
    let e = tileslide::io::ascii::load(&path, 1.0).unwrap_err();
    std::fs::remove_file(&path).unwrap();
    assert_eq!(e.io_error_kind(), Some(std::io::ErrorKind::FileTooLarge));
    let message = e.to_string();
    assert!(
        message.contains("tileslide-huge") && message.contains("MAX_FILE_BYTES"),
        "{message}"
    );
}
