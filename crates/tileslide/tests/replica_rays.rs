#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
//! Proves that ray casts on real Replica Island levels return hand-computed hits: cells,
//! tiles and expected points are worked out from the raw level bytes in this file (y up,
//! 32-pixel tiles, row 0 at the bottom), never from the loader.

use crate::replica_support;

use std::path::Path;
use std::sync::Arc;

use replica_support::{RawGrid, RawTile, TILE, data_dir, raw_tile_set, read};
use tileslide::io::replica;
use tileslide::{Cell, QueryFilter, Ray, RayHit, SegmentFlags, TileId, TileMap, Vec2};

/// The levels every ray test runs on (at least three, of different worlds).
const LEVELS: [&str; 5] = [
    "level_1_1_island.bin",
    "level_2_1_grass.bin",
    "level_3_2_sewer.bin",
    "level_4_5_underground.bin",
    "collisiontest.bin",
];

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

struct Level {
    name: &'static str,
    map: TileMap,
    grid: RawGrid,
    tiles: Vec<RawTile>,
}

impl Level {
    /// The tile at world (col, row) by the raw bytes, `None` outside the map or empty.
    fn tile(&self, col: i64, row: i64) -> Option<u8> {
        if col < 0 || row < 0 || col >= self.grid.width as i64 || row >= self.grid.height as i64 {
            return None;
        }
        self.grid.tile(col as u32, row as u32, &self.tiles)
    }

    fn cells_where(&self, pred: impl Fn(i64, i64) -> bool) -> Vec<(u32, u32)> {
        self.grid
            .cells()
            .filter(|&(c, r)| pred(c.into(), r.into()))
            .collect()
    }

    /// Cells holding `id` with an empty cell inside the map directly above.
    fn open_above(&self, id: u8) -> Vec<(u32, u32)> {
        let h = i64::from(self.grid.height);
        self.cells_where(|c, r| {
            self.tile(c, r) == Some(id) && r + 1 < h && self.tile(c, r + 1).is_none()
        })
    }

    /// True when tile `id`'s raw shape has the whole edge from `a` to `b` (either direction)
    /// with `normal`.
    fn has_edge(&self, id: u8, a: [f32; 2], b: [f32; 2], normal: [f32; 2]) -> bool {
        self.tiles.iter().find(|t| t.id == id).is_some_and(|t| {
            t.segments.iter().any(|s| {
                ((s.start == a && s.end == b) || (s.start == b && s.end == a))
                    && (Vec2::from(s.normal) - Vec2::from(normal)).length() < 1e-6
            })
        })
    }
}

fn load(dir: &Path, name: &'static str) -> Level {
    let tiles = raw_tile_set(&read(dir, "collision.bin"));
    let set = Arc::new(replica::load_tile_set(dir.join("collision.bin")).unwrap());
    let bytes = read(dir, name);
    Level {
        name,
        map: replica::parse_level(&bytes, name, set).unwrap(),
        grid: RawGrid::from_level(&bytes),
        tiles,
    }
}

fn levels() -> Option<Vec<Level>> {
    let dir = data_dir()?;
    Some(LEVELS.iter().map(|name| load(&dir, name)).collect())
}

fn cell_of(hit: &RayHit) -> (u32, u32) {
    let cell = hit.cell().unwrap();
    (cell.col, cell.row)
}

/// Straight down from the middle of the empty cell above onto the floor: the hit is exactly
/// on the floor's top edge at y = 32·(row+1), half way along the ray.
fn assert_floor_hit(level: &Level, col: u32, row: u32) {
    let x = TILE * col as f32 + 16.0;
    let top = TILE * (row + 1) as f32;
    let ray = Ray::between(v(x, top + 16.0), v(x, top - 16.0));
    let hit = level
        .map
        .cast_ray(ray, &QueryFilter::default())
        .unwrap_or_else(|| panic!("{}: no hit on floor ({col}, {row})", level.name));
    let at = format!("{} floor ({col}, {row})", level.name);
    assert_eq!(hit.point, v(x, top), "{at}");
    assert_eq!(hit.t, 0.5, "{at}");
    assert_eq!(hit.normal, v(0.0, 1.0), "{at}");
    assert_eq!(hit.tile(), Some(TileId(1)), "{at}");
    assert_eq!(cell_of(&hit), (col, row), "{at}");
    assert_eq!(hit.flags, SegmentFlags::SOLID, "{at}");
}

#[test]
fn level_1_1_island_ray_down_onto_floor_at_cell_5_1_hits_y_64() {
    // By hand: the bottom-most floor with air above in level_1_1_island.bin is file row 48
    // (world row 1), column 5, holding tile 1; the file row above it holds -1.
    let Some(dir) = data_dir() else { return };
    let level = load(&dir, "level_1_1_island.bin");
    assert_eq!(level.grid.id(5, 1), 1);
    assert!(level.grid.id(5, 2) < 0);
    let hit = level
        .map
        .cast_ray(
            Ray::between(v(176.0, 80.0), v(176.0, 48.0)),
            &QueryFilter::default(),
        )
        .unwrap();
    assert_eq!(hit.point, v(176.0, 64.0));
    assert_eq!(hit.normal, v(0.0, 1.0));
    assert_eq!(hit.tile(), Some(TileId(1)));
    assert_eq!(hit.cell(), Some(Cell::new(5, 1)));
}

#[test]
fn ray_down_onto_every_open_floor_tile_1_hits_its_top_edge_exactly() {
    let Some(levels) = levels() else { return };
    for level in &levels {
        let floors = level.open_above(1);
        assert!(!floors.is_empty(), "{}: no open floor", level.name);
        for &(col, row) in &floors {
            assert_floor_hit(level, col, row);
        }
    }
}

#[test]
fn long_ray_down_an_empty_column_hits_the_floor_at_its_bottom() {
    // A ray through many empty cells (from just under whatever closes the column above, or
    // the map's top): the walk must cross them all and report the floor.
    let Some(levels) = levels() else { return };
    for level in &levels {
        let h = i64::from(level.grid.height);
        let mut longest = 0;
        for (col, row) in level.open_above(1) {
            let (c, r) = (i64::from(col), i64::from(row));
            let empty_above = ((r + 1)..h)
                .take_while(|&rr| level.tile(c, rr).is_none())
                .count() as u32;
            longest = longest.max(empty_above);
            if empty_above < 3 {
                continue;
            }
            let x = TILE * col as f32 + 16.0;
            let top = TILE * (row + 1) as f32;
            let start = TILE * (row + 1 + empty_above) as f32 - 1.0;
            let ray = Ray::between(v(x, start), v(x, top - 16.0));
            let hit = level.map.cast_ray(ray, &QueryFilter::default()).unwrap();
            let at = format!("{} column {col}", level.name);
            assert!((hit.point.y - top).abs() < 1e-3, "{at}: {}", hit.point);
            assert_eq!(hit.point.x, x, "{at}");
            assert_eq!(hit.normal, v(0.0, 1.0), "{at}");
            assert_eq!(cell_of(&hit), (col, row), "{at}");
        }
        assert!(
            longest >= 3,
            "{}: no floor with 3 empty cells above",
            level.name
        );
    }
}

/// Straight down onto a ramp at tile-local x = `lx`: the surface height is `surface(lx)`.
fn assert_ramp_hits(level: &Level, id: u8, surface: fn(f32) -> f32, normal: Vec2) -> usize {
    let ramps = level.open_above(id);
    for &(col, row) in &ramps {
        for lx in [1.0, 4.0, 8.0, 13.5, 16.0, 24.0, 31.0] {
            let x = TILE * col as f32 + lx;
            let base = TILE * row as f32;
            let ray = Ray::between(v(x, base + TILE + 16.0), v(x, base + 0.5));
            let at = format!("{} tile {id} at ({col}, {row}), x {lx}", level.name);
            let hit = level
                .map
                .cast_ray(ray, &QueryFilter::default())
                .unwrap_or_else(|| panic!("{at}: no hit"));
            let expected = base + surface(lx);
            assert!(
                (hit.point.y - expected).abs() < 1e-3,
                "{at}: y {} expected {expected}",
                hit.point.y
            );
            assert_eq!(hit.point.x, x, "{at}");
            assert!(
                (hit.normal - normal).length() < 1e-6,
                "{at}: {}",
                hit.normal
            );
            assert_eq!(hit.tile(), Some(TileId(id.into())), "{at}");
            assert_eq!(cell_of(&hit), (col, row), "{at}");
        }
    }
    ramps.len()
}

#[test]
fn ray_down_onto_ramp_36_hits_y_equal_to_local_x() {
    // Tile 36: surface (0,0)→(32,32), so at tile-local x the surface is at y = x.
    let Some(levels) = levels() else { return };
    let h = std::f32::consts::FRAC_1_SQRT_2;
    for level in &levels {
        let n = assert_ramp_hits(level, 36, |x| x, v(-h, h));
        assert!(n > 0, "{}: no open tile 36", level.name);
    }
}

#[test]
fn ray_down_onto_ramp_37_hits_y_equal_to_32_minus_local_x() {
    // Tile 37: surface (0,32)→(32,0), so at tile-local x the surface is at y = 32 − x.
    let Some(levels) = levels() else { return };
    let h = std::f32::consts::FRAC_1_SQRT_2;
    for level in &levels {
        let n = assert_ramp_hits(level, 37, |x| 32.0 - x, v(h, h));
        assert!(n > 0, "{}: no open tile 37", level.name);
    }
}

#[test]
fn horizontal_direction_filter_ignores_floors_that_the_default_filter_hits() {
    // A ray falling down-right into an open floor tile 1. From (4, 44) to (28, 12) tile-local
    // relative to the floor cell's corner, it crosses the top edge y = 32 at t = 12/32, x = 13,
    // then ends inside the tile; it never reaches another cell's segments.
    let Some(levels) = levels() else { return };
    for level in &levels {
        for (col, row) in level.open_above(1) {
            let corner = v(TILE * col as f32, TILE * row as f32);
            let ray = Ray::between(corner + v(4.0, 44.0), corner + v(28.0, 12.0));
            let at = format!("{} floor ({col}, {row})", level.name);

            let hit = level.map.cast_ray(ray, &QueryFilter::default()).unwrap();
            assert_eq!(hit.point, corner + v(13.0, 32.0), "{at}");
            assert_eq!(hit.t, 0.375, "{at}");
            assert_eq!(hit.normal, v(0.0, 1.0), "{at}");

            // Replica Island's horizontal pass: only faces opposing +x count; the floor's
            // normal (0, 1) is perpendicular to it, so it is ignored, and so are the tile's
            // right and bottom edges, which face along or away from +x.
            let horizontal = QueryFilter::against(Vec2::X);
            assert_eq!(level.map.cast_ray(ray, &horizontal), None, "{at}");

            // The vertical pass (moving down) sees the floor again.
            let vertical = QueryFilter::against(Vec2::NEG_Y);
            assert_eq!(level.map.cast_ray(ray, &vertical), Some(hit), "{at}");
        }
    }
}

#[test]
fn horizontal_ray_into_a_wall_hits_its_face_and_floor_only_filter_ignores_it() {
    // Walls: any tile whose raw shape has the full left edge x = 0 facing −x, with an empty
    // cell to its left. A ray from the middle of that empty cell to the middle of the wall
    // cell crosses x = 32·col half way.
    let Some(levels) = levels() else { return };
    let mut total = 0;
    for level in &levels {
        let walls = level.cells_where(|c, r| {
            level
                .tile(c, r)
                .is_some_and(|id| level.has_edge(id, [0.0, 0.0], [0.0, 32.0], [-1.0, 0.0]))
                && c > 0
                && level.tile(c - 1, r).is_none()
        });
        total += walls.len();
        for (col, row) in walls {
            let y = TILE * row as f32 + 16.0;
            let x = TILE * col as f32;
            let ray = Ray::between(v(x - 16.0, y), v(x + 16.0, y));
            let at = format!("{} wall ({col}, {row})", level.name);

            let hit = level
                .map
                .cast_ray(ray, &QueryFilter::against(Vec2::X))
                .unwrap();
            assert_eq!(hit.point, v(x, y), "{at}");
            assert_eq!(hit.normal, v(-1.0, 0.0), "{at}");
            assert_eq!(cell_of(&hit), (col, row), "{at}");
            assert_eq!(
                level.map.cast_ray(ray, &QueryFilter::default()),
                Some(hit),
                "{at}"
            );
            // A filter that only lets floors through (faces opposing a downward move).
            assert_eq!(
                level.map.cast_ray(ray, &QueryFilter::against(Vec2::NEG_Y)),
                None,
                "{at}"
            );
        }
    }
    assert!(total > 0, "no open wall in any test level");
}

#[test]
fn ray_up_into_a_ceiling_hits_its_bottom_edge_exactly() {
    // Ceilings: tiles whose raw shape has the full bottom edge facing −y, with an empty cell
    // below.
    let Some(levels) = levels() else { return };
    let mut total = 0;
    for level in &levels {
        let ceilings = level.cells_where(|c, r| {
            level
                .tile(c, r)
                .is_some_and(|id| level.has_edge(id, [0.0, 0.0], [32.0, 0.0], [0.0, -1.0]))
                && r > 0
                && level.tile(c, r - 1).is_none()
        });
        total += ceilings.len();
        for (col, row) in ceilings {
            let x = TILE * col as f32 + 16.0;
            let y = TILE * row as f32;
            let hit = level
                .map
                .cast_ray(
                    Ray::between(v(x, y - 16.0), v(x, y + 16.0)),
                    &QueryFilter::default(),
                )
                .unwrap();
            let at = format!("{} ceiling ({col}, {row})", level.name);
            assert_eq!(hit.point, v(x, y), "{at}");
            assert_eq!(hit.normal, v(0.0, -1.0), "{at}");
            assert_eq!(cell_of(&hit), (col, row), "{at}");
        }
    }
    assert!(total > 0, "no open ceiling in any test level");
}

#[test]
fn open_floor_cells_expose_their_top_edge_and_are_solid_inside() {
    let Some(levels) = levels() else { return };
    for level in &levels {
        for (col, row) in level.open_above(1) {
            let corner = v(TILE * col as f32, TILE * row as f32);
            let at = format!("{} floor ({col}, {row})", level.name);
            let top: Vec<_> = level
                .map
                .active_segments(Cell::new(col, row))
                .filter(|s| s.normal == v(0.0, 1.0))
                .collect();
            assert_eq!(top.len(), 1, "{at}");
            let s = top[0];
            let mut ends = [s.segment.a.x, s.segment.b.x];
            ends.sort_by(f32::total_cmp);
            assert_eq!(ends, [corner.x, corner.x + TILE], "{at}");
            assert_eq!(s.segment.a.y, corner.y + TILE, "{at}");
            assert_eq!(s.segment.b.y, corner.y + TILE, "{at}");
            assert_eq!(s.tile, TileId(1), "{at}");
            assert!(level.map.is_point_solid(corner + v(16.0, 16.0)), "{at}");
            assert!(!level.map.is_point_solid(corner + v(16.0, 48.0)), "{at}");
        }
    }
}

#[test]
fn ramp_36_cells_are_solid_below_the_diagonal_only() {
    let Some(levels) = levels() else { return };
    for level in &levels {
        for (col, row) in level.open_above(36) {
            let corner = v(TILE * col as f32, TILE * row as f32);
            let at = format!("{} ramp ({col}, {row})", level.name);
            assert!(level.map.is_point_solid(corner + v(24.0, 8.0)), "{at}");
            assert!(!level.map.is_point_solid(corner + v(8.0, 24.0)), "{at}");
        }
    }
}
