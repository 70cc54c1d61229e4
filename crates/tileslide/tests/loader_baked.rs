//! The baked map format (`io::baked`): a baked and loaded map is the same map, bit for bit
//! (ASCII maps and every Replica Island level), and every malformed file is an error naming
//! the byte offset of the field at fault, never a panic or a huge allocation.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod replica_support;

use std::sync::Arc;

use proptest::prelude::*;
use replica_support::{data_dir, level_names};
use tileslide::io::{Location, ascii, baked, replica};
use tileslide::{Cell, Ray, RayFilter, TileMap, Vec2};

const CAVE: &str = "\
##########
#........#
#..=/\\...#
#.##..#=.#
##########";

/// An active segment's bits (end points, normal, flags, source) and its end-point links.
type SegmentPrint = ([u32; 8], [Option<(u32, u32, u32)>; 2]);

/// Every cell's tile and active segments, to compare two maps exactly.
fn fingerprint(map: &TileMap) -> Vec<(Option<u32>, Vec<SegmentPrint>)> {
    let mut out = Vec::new();
    for row in 0..map.height() {
        for col in 0..map.width() {
            let cell = Cell::new(col, row);
            let segments = map
                .active_segments(cell)
                .map(|s| {
                    let link = |l: Option<tileslide::SegmentRef>| {
                        l.map(|l| (l.cell.col, l.cell.row, l.index))
                    };
                    (
                        [
                            s.segment.a.x.to_bits(),
                            s.segment.a.y.to_bits(),
                            s.segment.b.x.to_bits(),
                            s.segment.b.y.to_bits(),
                            s.normal.x.to_bits(),
                            s.normal.y.to_bits(),
                            s.flags.0,
                            s.source,
                        ],
                        [link(s.continues[0]), link(s.continues[1])],
                    )
                })
                .collect();
            out.push((map.tile(cell).map(|t| t.0), segments));
        }
    }
    out
}

fn assert_same(a: &TileMap, b: &TileMap) {
    assert_eq!((a.width(), a.height()), (b.width(), b.height()));
    assert_eq!(a.origin(), b.origin());
    assert_eq!(a.cell_size(), b.cell_size());
    assert!(fingerprint(a) == fingerprint(b), "segments differ");
    // And the same answers to rays crossing the whole map.
    let size = Vec2::new(a.width() as f32, a.height() as f32) * a.cell_size();
    for k in 0..200 {
        let f = |i: u32| ((k * 7919 + i * 104_729) % 1000) as f32 / 1000.0;
        let p0 = a.origin() + Vec2::new(f(1), f(2)) * size;
        let p1 = a.origin() + Vec2::new(f(3), f(4)) * size;
        let ray = Ray::between(p0, p1);
        assert_eq!(
            a.cast_ray(ray, &RayFilter::default()),
            b.cast_ray(ray, &RayFilter::default())
        );
    }
}

#[test]
fn an_ascii_map_bakes_and_loads_unchanged() {
    let map = ascii::parse(CAVE, "cave.txt", 0.5).unwrap();
    let back = baked::parse(&baked::to_bytes(&map), "cave.tsm").unwrap();
    assert_same(&map, &back);
    // And through a file.
    let path = std::env::temp_dir().join(format!("tileslide-baked-{}.tsm", std::process::id()));
    baked::save(&map, &path).unwrap();
    let from_file = baked::load(&path).unwrap();
    std::fs::remove_file(&path).ok();
    assert_same(&map, &from_file);
}

#[test]
fn a_loaded_baked_map_takes_edits_as_its_source_does() {
    let mut map = ascii::parse(CAVE, "cave.txt", 1.0).unwrap();
    let mut back = baked::parse(&baked::to_bytes(&map), "cave.tsm").unwrap();
    // Dig and build all over, growing and shrinking cells' segment blocks.
    let kinds = [None, Some(tileslide::TileId(1)), Some(tileslide::TileId(2))];
    for k in 0..60u32 {
        let cell = Cell::new(k * 7 % map.width(), k * 3 % map.height());
        let tile = map
            .tile_set()
            .iter()
            .map(|(id, _)| id)
            .nth((k % 3) as usize);
        let tile = if k % 4 == 0 { None } else { tile.or(kinds[1]) };
        map.set_tile(cell, tile).unwrap();
        back.set_tile(cell, tile).unwrap();
    }
    assert_same(&map, &back);
}

#[test]
fn every_replica_island_level_bakes_and_loads_unchanged() {
    let Some(dir) = data_dir() else {
        return;
    };
    let set = Arc::new(replica::load_tile_set(dir.join("collision.bin")).unwrap());
    let mut count = 0;
    for name in level_names(&dir) {
        let Ok(map) = replica::load_level(dir.join(&name), set.clone()) else {
            continue;
        };
        let back = baked::parse(&baked::to_bytes(&map), &name).unwrap();
        assert_same(&map, &back);
        count += 1;
    }
    assert!(count >= 40, "{count} levels");
}

/// A baked file around `payload`, with a correct header (so the payload's own checks are
/// reached).
fn wrap(payload: &[u8]) -> Vec<u8> {
    let mut out = b"TSLDMAP\x1a".to_vec();
    out.extend_from_slice(&baked::VERSION.to_le_bytes());
    out.extend_from_slice(&0u32.to_le_bytes());
    out.extend_from_slice(&(payload.len() as u64).to_le_bytes());
    out.extend_from_slice(&u64::from(crc32fast::hash(payload)).to_le_bytes());
    out.extend_from_slice(payload);
    out
}

/// A payload: unit tiles, origin 0, `w × h`, then `rest` (shapes and tiles).
fn payload(w: u32, h: u32, rest: &[u32]) -> Vec<u8> {
    let mut p = Vec::new();
    for v in [1.0f32, 1.0, 0.0, 0.0] {
        p.extend_from_slice(&v.to_le_bytes());
    }
    for v in [w, h].iter().chain(rest) {
        p.extend_from_slice(&v.to_le_bytes());
    }
    p
}

/// The error for `bytes`: its kind's text and its byte offset.
fn error(bytes: &[u8]) -> (String, u64) {
    let e = baked::parse(bytes, "bad.tsm").unwrap_err();
    let Location::Byte(at) = e.location else {
        panic!("no byte offset: {e}");
    };
    assert!(e.to_string().starts_with("bad.tsm"), "{e}");
    (e.kind.to_string(), at)
}

#[test]
fn header_errors_name_the_field_and_offset() {
    let good = baked::to_bytes(&ascii::parse(CAVE, "cave.txt", 1.0).unwrap());
    let mut magic = good.clone();
    magic[3] = b'X';
    assert!(error(&magic).0.contains("not a tileslide baked map"));
    assert_eq!(error(&magic).1, 0);
    let mut version = good.clone();
    version[8] = 1;
    let (text, at) = error(&version);
    assert!(
        text.contains("version") && text.contains("re-bake"),
        "{text}"
    );
    assert_eq!(at, 8);
    let mut reserved = good.clone();
    reserved[13] = 1;
    let (text, at) = error(&reserved);
    assert!(text.contains("reserved"), "{text}");
    assert_eq!(at, 12);
    let mut length = good.clone();
    length.push(0);
    let (text, at) = error(&length);
    assert!(text.contains("payload_len"), "{text}");
    assert_eq!(at, 16);
    let mut flipped = good.clone();
    let last = flipped.len() - 1;
    flipped[last] ^= 0x40;
    let (text, at) = error(&flipped);
    assert!(
        text.contains("checksum") && text.contains("corrupt"),
        "{text}"
    );
    assert_eq!(at, 32);
}

#[test]
fn every_truncation_is_an_error_and_none_panics() {
    let good = baked::to_bytes(&ascii::parse(CAVE, "cave.txt", 1.0).unwrap());
    for len in 0..good.len() {
        let e = baked::parse(&good[..len], "cut.tsm").unwrap_err();
        assert!(matches!(e.location, Location::Byte(_)), "{len}: {e}");
    }
}

#[test]
fn absurd_sizes_are_refused_before_allocating() {
    // 65536 × 65536 cells in a file of a few bytes.
    let (text, at) = error(&wrap(&payload(65_536, 65_536, &[0])));
    assert!(text.contains("width × height"), "{text}");
    assert_eq!(at, 32 + 16);
    // Four billion shapes.
    let (text, at) = error(&wrap(&payload(1, 1, &[u32::MAX, 0])));
    assert!(text.contains("shape_count"), "{text}");
    assert_eq!(at, 32 + 24);
    // A shape claiming a billion segments.
    let (text, at) = error(&wrap(&payload(1, 1, &[1, 7, 1_000_000_000, 0])));
    assert!(text.contains("segment_count"), "{text}");
    assert_eq!(at, 32 + 28 + 4);
}

#[test]
fn bad_contents_are_errors_at_their_offset() {
    let unit = |x: f32| x.to_bits();
    // A zero-length segment in tile 3.
    let zero = [
        1,
        3,
        1,
        unit(0.0),
        unit(0.0),
        unit(0.0),
        unit(0.0),
        unit(0.0),
        unit(1.0),
        1,
        u32::MAX,
    ];
    let (text, at) = error(&wrap(&payload(1, 1, &zero)));
    assert!(text.contains("tile 3"), "{text}");
    assert_eq!(at, 32 + 28);
    // A cell holding a tile the set does not have (the second cell).
    let mut unknown = payload(2, 1, &[0, u32::MAX, 9]);
    unknown.extend(empty_store(2));
    let (text, at) = error(&wrap(&unknown));
    assert!(text.contains('9'), "{text}");
    assert_eq!(at, 32 + 28 + 4);
    // The same tile twice.
    let twice = [2, 4, 0, 4, 0, u32::MAX];
    let (text, _) = error(&wrap(&payload(1, 1, &twice)));
    assert!(text.contains("tile 4 is defined twice"), "{text}");
    // Bytes after the segments.
    let mut trailing = payload(1, 1, &[0, u32::MAX]);
    trailing.extend(empty_store(1));
    trailing.extend([1, 2, 3, 4]);
    let (text, at) = error(&wrap(&trailing));
    assert!(text.contains("active"), "{text}");
    assert_eq!(at, 32 + 28 + 4 + 2 + 1);
}

/// The culled-segment section of a map of `cells` empty cells: no segments.
fn empty_store(cells: usize) -> Vec<u8> {
    let mut out = vec![0u8; 3 * cells];
    out.extend(0u64.to_le_bytes());
    out
}

/// A real baked map with its payload edited by `edit(payload, cells, active)` and the
/// checksum made right again: the checks behind the checksum must catch it.
fn tampered(edit: impl Fn(&mut Vec<u8>, usize, usize)) -> (String, u64) {
    let map = ascii::parse(CAVE, "cave.txt", 1.0).unwrap();
    let (cells, active) = (
        (map.width() * map.height()) as usize,
        map.active_segment_count(),
    );
    let mut payload = baked::to_bytes(&map)[32..].to_vec();
    edit(&mut payload, cells, active);
    error(&wrap(&payload))
}

#[test]
fn culled_segments_that_do_not_hold_together_are_refused() {
    // A cell's kind that its segments do not make.
    let (text, _) = tampered(|p, cells, active| {
        let kinds = p.len() - 40 * active - 8 - cells;
        let k = (kinds..kinds + cells).find(|&i| p[i] != 0).unwrap();
        p[k] ^= 0x0f;
    });
    assert!(text.contains("does not match its segments"), "{text}");
    // Links that name no neighbour, a cell outside the map (the first active segment is in
    // the top row, so the row above is outside), and a segment its cell does not have.
    let pack = |dc: u32, dr: u32, index: u32| (dr * 3 + dc) << 16 | index;
    for (raw, reason) in [
        (9 << 16, "names no neighbour"),
        (pack(1, 0, 0), "not there"),
        (pack(1, 1, 60_000), "not there"),
    ] {
        let (text, at) = tampered(|p, _, active| {
            let first = p.len() - 40 * active;
            p[first + 32..first + 36].copy_from_slice(&u32::to_le_bytes(raw));
        });
        assert!(
            text.contains("active segment 0") && text.contains(reason),
            "{raw:#x}: {text}"
        );
        assert!(at > 32);
    }
    // A NaN coordinate.
    let (text, _) = tampered(|p, _, active| {
        let first = p.len() - 40 * active;
        p[first..first + 4].copy_from_slice(&f32::NAN.to_le_bytes());
    });
    assert!(text.contains("not finite"), "{text}");
}

proptest! {
    /// Random corruption of a real baked map: an error (the checksum catches nearly all),
    /// never a panic.
    #[test]
    fn corrupt_files_never_panic(flips in prop::collection::vec((any::<usize>(), any::<u8>()), 1..8)) {
        let mut bytes = baked::to_bytes(&ascii::parse(CAVE, "cave.txt", 1.0).unwrap());
        for (at, byte) in flips {
            let at = at % bytes.len();
            bytes[at] ^= byte | 1;
        }
        prop_assert!(baked::parse(&bytes, "corrupt.tsm").is_err());
    }
}
