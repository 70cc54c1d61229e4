//! The baked map format (`io::baked`): a baked and loaded map is the same map, bit for bit
//! (ASCII maps and every Replica Island level), and every malformed file is an error naming
//! the byte offset of the field at fault, never a panic or a huge allocation: also a file
//! whose checksum was recomputed over culled segments that are not what its tiles make.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use crate::replica_support;

use std::sync::Arc;

use proptest::prelude::*;
use replica_support::{data_dir, level_names};
use tileslide::io::{BakedFault, LoadError, LoadErrorKind, Location, ascii, baked, replica};
use tileslide::{Cell, QueryFilter, Ray, TileMap, Vec2};

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
            a.cast_ray(ray, &QueryFilter::default()),
            b.cast_ray(ray, &QueryFilter::default())
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
    assert!(
        error(&magic).0.contains(r#"`magic` is b"TSLXMAP\x1a""#),
        "{}",
        error(&magic).0
    );
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
        text.contains("`checksum` is 0x")
            && text.contains("CRC-32 is 0x")
            && text.contains("corrupt"),
        "{text}"
    );
    assert!(!text.contains("out of range"), "{text}");
    assert_eq!(at, 24);
}

#[test]
fn a_corrupt_file_reports_the_checksums_and_the_offset_a_program_can_read() {
    let good = baked::to_bytes(&ascii::parse(CAVE, "cave.txt", 1.0).unwrap());
    let stored = u64::from_le_bytes(good[24..32].try_into().unwrap());
    let mut flipped = good.clone();
    let last = flipped.len() - 1;
    flipped[last] ^= 0x40;
    let e = baked::parse(&flipped, "bad.tsm").unwrap_err();
    assert_eq!(e.location, Location::Byte(24));
    let LoadErrorKind::ChecksumMismatch {
        stored: read,
        computed,
    } = e.kind
    else {
        panic!("not a checksum mismatch: {e}");
    };
    assert_eq!(read, stored);
    assert_ne!(computed, stored);
    // Not a baked map at all: the magic bytes it holds instead.
    let mut zip = good;
    zip[..4].copy_from_slice(b"PK\x03\x04");
    let e = baked::parse(&zip, "bad.tsm").unwrap_err();
    assert_eq!(e.location, Location::Byte(0));
    assert!(
        matches!(&e.kind, LoadErrorKind::BadMagic { found, .. } if found.starts_with(b"PK")),
        "{e}"
    );
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

// A baked map's checksum guards against accidents only: a file whose culled segments were
// rewritten and its checksum recomputed must still be refused, with an error naming the
// segment (or cell) at fault and its byte offset, whenever a stored segment, link or cap is
// not what the map's tiles make. Each test below edits a real baked map's payload and puts
// a right checksum back.

/// Bytes of one baked active segment, and where its fields are.
const RECORD: usize = 40;
const NORMAL_X: usize = 16;
const FLAGS: usize = 24;
const SOURCE: usize = 28;
const CAPS: usize = 30;
const LINK_A: usize = 32;

/// The header's size: payload offsets plus this are file offsets.
const HEADER: usize = 32;

fn cave() -> TileMap {
    ascii::parse(CAVE, "cave.txt", 1.0).unwrap()
}

/// The error for a tampered `payload` (given a right checksum): its text and byte offset.
fn refused(payload: &[u8]) -> (String, u64) {
    error(&wrap(payload))
}

/// The error for a well-wrapped `payload`.
fn refused_error(payload: &[u8]) -> LoadError {
    baked::parse(&wrap(payload), "bad.tsm").unwrap_err()
}

/// The baked payload of `map`, and the payload offset of its first active segment.
fn baked_payload(map: &TileMap) -> (Vec<u8>, usize) {
    let payload = baked::to_bytes(map)[HEADER..].to_vec();
    let first = payload.len() - RECORD * map.active_segment_count();
    (payload, first)
}

fn f32_at(p: &[u8], at: usize) -> f32 {
    f32::from_le_bytes(p[at..at + 4].try_into().unwrap())
}

fn put_f32(p: &mut [u8], at: usize, v: f32) {
    p[at..at + 4].copy_from_slice(&v.to_le_bytes());
}

#[test]
fn a_segment_moved_out_of_its_cell_with_a_non_unit_normal_is_refused_despite_its_checksum() {
    // The first active segment shifted ten cells right (out of its cell; past the map's
    // edge) with its normal doubled: the checksum is right, the segment is not.
    let map = cave();
    let (mut p, first) = baked_payload(&map);
    let ax = f32_at(&p, first);
    put_f32(&mut p, first, ax + 10.0);
    for k in 0..2 {
        let at = first + NORMAL_X + 4 * k;
        let n = f32_at(&p, at);
        put_f32(&mut p, at, 2.0 * n);
    }
    let e = refused_error(&p);
    assert!(
        matches!(
            e.kind,
            LoadErrorKind::BakedSegments {
                segment: Some(0),
                fault: BakedFault::NotWhatTheTilesMake,
                ..
            }
        ),
        "{e}"
    );
    assert_eq!(e.location, Location::Byte((HEADER + first) as u64));
    // Before this was checked, the file loaded and answered rays differently from its
    // source; what the source answers is what a loaded map must answer.
    let ray = Ray::between(Vec2::new(9.5, 0.5), Vec2::new(11.5, 0.5));
    assert!(map.cast_ray(ray, &QueryFilter::default()).is_none());
}

/// A change to the record at a payload offset.
type Edit = fn(&mut [u8], usize);

#[test]
fn any_field_of_any_stored_segment_changed_is_refused_naming_the_segment() {
    let map = cave();
    let (good, first) = baked_payload(&map);
    let active = map.active_segment_count();
    // Each coordinate moved a little (a hundredth: still inside the cell), the normal
    // turned, the flags changed, the source renumbered.
    let edits: [(&str, Edit); 8] = [
        ("a.x", |p, at| put_f32(p, at, f32_at(p, at) + 0.01)),
        ("a.y", |p, at| put_f32(p, at + 4, f32_at(p, at + 4) + 0.01)),
        ("e.x", |p, at| put_f32(p, at + 8, f32_at(p, at + 8) * 0.99)),
        ("e.y", |p, at| {
            put_f32(p, at + 12, f32_at(p, at + 12) * 0.99)
        }),
        ("normal", |p, at| {
            let (x, y) = (f32_at(p, at + NORMAL_X), f32_at(p, at + NORMAL_X + 4));
            let (s, c) = 0.1f32.sin_cos();
            put_f32(p, at + NORMAL_X, x * c - y * s);
            put_f32(p, at + NORMAL_X + 4, x * s + y * c);
        }),
        ("flags", |p, at| p[at + FLAGS] ^= 0x02),
        ("source", |p, at| p[at + SOURCE] ^= 0x01),
        ("caps", |p, at| p[at + CAPS] ^= 0x01),
    ];
    for k in 0..active {
        let at = first + RECORD * k;
        for (field, edit) in &edits {
            let mut p = good.clone();
            edit(&mut p, at);
            if p == good {
                continue;
            }
            let (text, offset) = refused(&p);
            let named = format!("active segment {k}:");
            // A change to one segment can show first as its cell's kind, or in a segment a
            // link of which reaches it; it is never accepted.
            assert!(
                text.contains(&named) || text.contains("active segment") || text.contains("kind"),
                "{field} of segment {k}: {text}"
            );
            if text.contains("not what its tile makes") {
                assert!(text.contains(&named), "{field} of segment {k}: {text}");
                assert_eq!(offset, (HEADER + at) as u64, "{field} of segment {k}");
            }
        }
    }
}

/// Active segment `k` of `map`, counting cell by cell.
fn nth_active(map: &TileMap, k: usize) -> tileslide::ActiveSegment {
    (0..map.height())
        .flat_map(|row| (0..map.width()).map(move |col| Cell::new(col, row)))
        .flat_map(|cell| map.active_segments(cell).collect::<Vec<_>>())
        .nth(k)
        .unwrap()
}

#[test]
fn links_that_do_not_join_touching_segments_are_refused() {
    let map = cave();
    let (good, first) = baked_payload(&map);
    let active = map.active_segment_count();
    let mut rejected = 0;
    for k in 0..active {
        let at = first + RECORD * k + LINK_A;
        let raw = u32::from_le_bytes(good[at..at + 4].try_into().unwrap());
        if raw == u32::MAX {
            continue;
        }
        // Point it at every other segment of the same neighbour cell, and at itself.
        let (cell, index) = (raw >> 16, raw & 0xFFFF);
        for other in (0..4u32).filter(|&i| i != index) {
            let mut p = good.clone();
            p[at..at + 4].copy_from_slice(&(cell << 16 | other).to_le_bytes());
            if let Ok(back) = baked::parse(&wrap(&p), "tampered.tsm") {
                // Accepted only if that segment touches the end too, as the original does.
                let s = nth_active(&back, k);
                let to = back.active_segment(s.continues[0].unwrap()).unwrap();
                let end = s.segment.a;
                assert!(
                    to.segment.a.distance(end) < 1e-4 || to.segment.b.distance(end) < 1e-4,
                    "segment {k} linked to {to:?}"
                );
                continue;
            }
            let (text, _) = refused(&p);
            assert!(text.contains("active segment"), "{text}");
            rejected += 1;
        }
    }
    assert!(rejected > 10, "only {rejected} links refused");
}

#[test]
fn a_cell_whose_segments_were_dropped_is_refused() {
    // The first wall cell's segments removed (its count zeroed, its kind cleared, its
    // records cut out): its tiles make segments there.
    let map = cave();
    let (good, first) = baked_payload(&map);
    let cells = (map.width() * map.height()) as usize;
    let counts = first - 8 - cells - 2 * cells;
    let cell = (0..cells)
        .find(|&c| u16::from_le_bytes([good[counts + 2 * c], good[counts + 2 * c + 1]]) > 0)
        .unwrap();
    let n = usize::from(u16::from_le_bytes([
        good[counts + 2 * cell],
        good[counts + 2 * cell + 1],
    ]));
    let before: usize = (0..cell)
        .map(|c| {
            usize::from(u16::from_le_bytes([
                good[counts + 2 * c],
                good[counts + 2 * c + 1],
            ]))
        })
        .sum();
    let mut p = good.clone();
    p[counts + 2 * cell..counts + 2 * cell + 2].copy_from_slice(&0u16.to_le_bytes());
    p[counts + 2 * cells + cell] = 0;
    let active_at = first - 8;
    let active = map.active_segment_count() - n;
    p[active_at..first].copy_from_slice(&(active as u64).to_le_bytes());
    let cut = first + RECORD * before;
    p.drain(cut..cut + RECORD * n);
    // And no link reaches into it any more.
    let width = map.width() as i64;
    let mut record = first;
    for c in 0..cells {
        let count = u16::from_le_bytes([p[counts + 2 * c], p[counts + 2 * c + 1]]);
        for _ in 0..count {
            for end in 0..2 {
                let at = record + LINK_A + 4 * end;
                let raw = u32::from_le_bytes(p[at..at + 4].try_into().unwrap());
                let (dr, dc) = (i64::from(raw >> 16) / 3 - 1, i64::from(raw >> 16) % 3 - 1);
                if raw != u32::MAX && c as i64 + dr * width + dc == cell as i64 {
                    p[at..at + 4].copy_from_slice(&u32::MAX.to_le_bytes());
                }
            }
            record += RECORD;
        }
    }
    let e = refused_error(&p);
    let width = map.width();
    let LoadErrorKind::BakedSegments {
        cell: at_cell,
        segment: None,
        fault: BakedFault::WrongCount { stored: 0, made },
    } = e.kind
    else {
        panic!("not a cell holding too few segments: {e}");
    };
    assert_eq!(at_cell, Cell::new(cell as u32 % width, cell as u32 / width));
    assert_eq!(made, n as u64, "{e}");
    assert!(e.to_string().contains("it holds 0 active segments"), "{e}");
    assert_eq!(
        e.location,
        Location::Byte((HEADER + counts + 2 * cell) as u64)
    );
}

/// A 96 × 96 map of noise: each cell empty or one of 16 blocks of different heights (a
/// full one among them), so nearly every cell and its neighbours make a pattern of their own.
fn noise() -> TileMap {
    let mut set = tileslide::TileSet::new(Vec2::ONE).unwrap();
    for k in 1..=16u32 {
        let top = 1.0 - k as f32 / 16.0;
        let shape = tileslide::TileShape::polygon(&[
            Vec2::new(0.0, top),
            Vec2::new(1.0, top),
            Vec2::new(1.0, 1.0),
            Vec2::new(0.0, 1.0),
        ])
        .unwrap();
        set.insert(tileslide::TileId(k), shape).unwrap();
    }
    let mut rng = tileslide_scenes::SplitMix64::new(0x9E37_79B9_7F4A_7C15);
    let tiles: Vec<_> = (0..96 * 96)
        .map(|_| {
            let k = rng.below(18);
            (k > 1).then(|| tileslide::TileId(k as u32 - 1))
        })
        .collect();
    TileMap::from_tiles(Arc::new(set), 96, 96, Vec2::new(-3.0, 5.0), &tiles).unwrap()
}

#[test]
fn a_map_of_noise_too_varied_to_check_pattern_by_pattern_is_checked_whole() {
    let map = noise();
    let back = baked::parse(&baked::to_bytes(&map), "noise.tsm").unwrap();
    assert_same(&map, &back);
    // Its last segment (past the patterns checked one by one) renumbered: only comparing
    // with the tiles can tell.
    let (mut p, first) = baked_payload(&map);
    let last = first + RECORD * (map.active_segment_count() - 1);
    p[last + SOURCE] ^= 1;
    let (text, at) = refused(&p);
    let k = map.active_segment_count() - 1;
    assert!(
        text.contains(&format!("active segment {k}: in cell"))
            && text.contains("not what its tiles make"),
        "{text}"
    );
    assert_eq!(at, (HEADER + last) as u64);
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
