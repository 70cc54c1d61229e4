//! Shared by `tests/query_absurd_rays.rs` and `tests/query_absurd_circles.rs`: small random
//! maps of the ASCII tile set, on cell sizes and origins whose lattice points are exact.

use std::sync::Arc;

use proptest::prelude::*;
use tileslide::io::ascii;
use tileslide::{Owner, Segment, SegmentFlags, TemporarySegment, TileMap, Vec2};

/// The map whose rows are `rows` (ASCII tiles), with cells of `cell` from `origin`.
pub fn map_of(rows: &str, cell: f32, origin: Vec2) -> TileMap {
    let lines: Vec<&str> = rows.lines().collect();
    let (width, height) = (lines[0].len() as u32, lines.len() as u32);
    let set = Arc::new(ascii::tile_set(cell).unwrap());
    let tiles: Vec<_> = lines
        .iter()
        .flat_map(|l| l.chars())
        .map(|c| ascii::tile_for_char(c).unwrap())
        .collect();
    TileMap::from_tiles(set, width, height, origin, &tiles).unwrap()
}

/// `chars` as the rows of a map `width` cells wide.
pub fn rows_of(chars: &[char], width: u32) -> String {
    let rows: Vec<String> = chars
        .chunks(width as usize)
        .map(|r| r.iter().collect())
        .collect();
    rows.join("\n")
}

/// Random maps of 1 to 8 × 1 to 8 cells of 1, 0.5, 32 or 0.25 units (solid blocks, ramps
/// both ways, one-way platforms), with or without a temporary segment from the origin by
/// (3, 2) cells, at `origin_of(width, height, cell, k)` for a random `k` in `0..3`.
pub fn small_map_at(
    origin_of: impl Fn(u32, u32, f32, usize) -> Vec2 + Clone + 'static,
) -> impl Strategy<Value = TileMap> {
    (1u32..=8, 1u32..=8, 0usize..4, 0usize..3, any::<bool>()).prop_flat_map(
        move |(w, h, cell, k, temporary)| {
            let cell = [1.0f32, 0.5, 32.0, 0.25][cell];
            let origin = origin_of(w, h, cell, k);
            proptest::collection::vec(
                prop_oneof![4 => Just('.'), 3 => Just('#'), 1 => Just('/'), 1 => Just('\\'),
                    1 => Just('=')],
                (w * h) as usize,
            )
            .prop_map(move |chars| {
                let mut map = map_of(&rows_of(&chars, w), cell, origin);
                if temporary {
                    map.add_temporary(TemporarySegment {
                        segment: Segment::new(origin, origin + Vec2::new(3.0, 2.0) * cell),
                        normal: Vec2::new(-2.0, 3.0),
                        flags: SegmentFlags::SOLID,
                        owner: Owner(1),
                        velocity: Vec2::ZERO,
                    })
                    .unwrap();
                }
                map
            })
        },
    )
}
