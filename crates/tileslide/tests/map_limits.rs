//! Map size limits: what `MAX_CELLS` promises is accepted, what exceeds it is refused.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::sync::Arc;

use tileslide::{Cell, MAX_CELLS, MapError, TileId, TileMap, TileSet, TileShape, Vec2};

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
