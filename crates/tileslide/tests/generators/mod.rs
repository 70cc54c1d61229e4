//! Generators shared by the property tests: random maps of `io::ascii` tiles on any cell size
//! and origin, and random query filters. A test that draws inside a case seeds
//! `tileslide_scenes::SplitMix64` from a value proptest chose, so a failing case replays.

// Each test uses a different part of this module.
#![allow(dead_code)]

use std::sync::Arc;

use proptest::prelude::*;
use proptest::strategy::Union;
use tileslide::io::ascii;
use tileslide::{
    Faces, Owner, QueryFilter, Segment, SegmentFlags, TemporarySegment, TileMap, Vec2,
};

/// The map of `chars`, ASCII tile characters row by row, `width` to a row (`width > 0`),
/// with cells `cell` map units wide and its top-left corner at `origin`.
pub fn tile_map(width: u32, chars: &[char], cell: f32, origin: Vec2) -> TileMap {
    let set = Arc::new(ascii::tile_set(cell).unwrap());
    let tiles: Vec<_> = chars
        .iter()
        .map(|&c| ascii::tile_for_char(c).unwrap())
        .collect();
    let height = chars.len() as u32 / width;
    TileMap::from_tiles(set, width, height, origin, &tiles).unwrap()
}

/// The map whose rows are the lines of `rows` (ASCII tile characters, all lines as long),
/// with cells `cell` map units wide and its top-left corner at `origin`.
pub fn map_of(rows: &str, cell: f32, origin: Vec2) -> TileMap {
    let width = rows.lines().next().map_or(0, |l| l.chars().count()) as u32;
    let chars: Vec<char> = rows.lines().flat_map(str::chars).collect();
    tile_map(width, &chars, cell, origin)
}

/// `chars` as text, `width` to a row: what `ascii::parse` reads, and how a failure message
/// shows a map.
pub fn rows(width: u32, chars: &[char]) -> String {
    chars
        .chunks(width as usize)
        .map(|r| r.iter().collect::<String>())
        .collect::<Vec<_>>()
        .join("\n")
}

/// Makes the outer ring of cells of `chars`, `width` to a row, solid (`#`): the map walled in.
pub fn wall_in(width: u32, chars: &mut [char]) {
    let width = width as usize;
    let height = chars.len() / width;
    for (i, c) in chars.iter_mut().enumerate() {
        let (col, row) = (i % width, i / width);
        if row == 0 || col == 0 || row + 1 == height || col + 1 == width {
            *c = '#';
        }
    }
}

/// `len` characters drawn from `mix`, pairs of a weight and a character.
pub fn tile_chars(mix: &[(u32, char)], len: usize) -> impl Strategy<Value = Vec<char>> + use<> {
    let choices: Vec<(u32, Just<char>)> = mix
        .iter()
        .filter(|(weight, _)| *weight > 0)
        .map(|&(weight, c)| (weight, Just(c)))
        .collect();
    proptest::collection::vec(Union::new_weighted(choices), len)
}

/// `len` tile characters of every kind in a mix drawn per map: some maps mostly empty, some
/// mostly solid, some all slopes or one-way platforms.
pub fn varied_tile_chars(len: usize) -> impl Strategy<Value = Vec<char>> {
    (0u32..=10, 0u32..=4, 0u32..=4, 0u32..=3).prop_flat_map(move |(solid, slash, back, one)| {
        tile_chars(
            &[
                (6, '.'),
                (solid, '#'),
                (slash, '/'),
                (back, '\\'),
                (one, '='),
            ],
            len,
        )
    })
}

/// Any query filter: front faces, both faces or faces against a direction (small integer
/// components, the zero vector included), every flag or one, and no owner or one of the
/// first three excluded.
pub fn query_filter() -> impl Strategy<Value = QueryFilter> {
    let faces = prop_oneof![
        3 => Just(Faces::Front),
        2 => Just(Faces::Both),
        1 => (-2i32..=2, -2i32..=2)
            .prop_map(|(x, y)| Faces::Against(Vec2::new(x as f32, y as f32))),
    ];
    let mask = prop_oneof![
        4 => Just(SegmentFlags::ALL),
        1 => Just(SegmentFlags::SOLID),
        1 => Just(SegmentFlags::ONE_WAY),
    ];
    let exclude = prop_oneof![Just(None), (0u64..3).prop_map(|o| Some(Owner(o)))];
    (faces, mask, exclude).prop_map(|(faces, mask, exclude_owner)| QueryFilter {
        faces,
        mask,
        exclude_owner,
    })
}

/// Random maps of 1 to 8 × 1 to 8 cells of 1, 0.5, 32 or 0.25 units (solid blocks, ramps
/// both ways, one-way platforms), with or without a temporary segment from the origin by
/// (3, 2) cells, at `origin_of(width, height, cell, k)` for a random `k` in `0..3`: origins
/// the caller chooses so that the lattice points are exact.
pub fn small_map_at(
    origin_of: impl Fn(u32, u32, f32, usize) -> Vec2 + Clone + 'static,
) -> impl Strategy<Value = TileMap> {
    (1u32..=8, 1u32..=8, 0usize..4, 0usize..3, any::<bool>()).prop_flat_map(
        move |(w, h, cell, k, temporary)| {
            let cell = [1.0f32, 0.5, 32.0, 0.25][cell];
            let origin = origin_of(w, h, cell, k);
            tile_chars(
                &[(4, '.'), (3, '#'), (1, '/'), (1, '\\'), (1, '=')],
                (w * h) as usize,
            )
            .prop_map(move |chars| {
                let mut map = tile_map(w, &chars, cell, origin);
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

/// Runs `work` in a rayon pool of `threads` threads (one pool per size, made once), so that
/// with the `parallel` feature the same work can be compared across thread counts; without
/// it, on the calling thread.
pub fn on_threads<R: Send>(threads: usize, work: impl FnOnce() -> R + Send) -> R {
    #[cfg(feature = "parallel")]
    {
        use std::sync::OnceLock;
        static POOLS: [OnceLock<rayon::ThreadPool>; 9] = [const { OnceLock::new() }; 9];
        let pool = POOLS[threads.clamp(1, 8)].get_or_init(|| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads.clamp(1, 8))
                .build()
                .unwrap()
        });
        pool.install(work)
    }
    #[cfg(not(feature = "parallel"))]
    {
        let _ = threads;
        work()
    }
}
