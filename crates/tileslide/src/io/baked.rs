//! tileslide's own binary map format (`.tsm`): a map's tile set and tiles, baked so that
//! loading is reading numbers, with no text to parse. Layout (all little-endian; described
//! in `docs/baked-format.md`):
//!
//! ```text
//! offset  size  field
//! 0       8     magic        "TSLDMAP" then 0x1A
//! 8       4     version      u32 = 1
//! 12      4     reserved     u32 = 0 (checked)
//! 16      8     payload_len  u64: bytes after the 32-byte header
//! 24      8     checksum     u64: FNV-1a 64 of the payload
//! 32      ...   payload:
//!   f32 tile_width, f32 tile_height, f32 origin_x, f32 origin_y
//!   u32 width, u32 height
//!   u32 shape_count, then per shape (by increasing id):
//!     u32 id, u32 segment_count, then per segment:
//!       f32 ax, ay, bx, by, nx, ny; u32 flags
//!   width × height × u32 tiles, row by row (0xFFFF_FFFF = empty)
//! ```
//!
//! The segments are the shapes' as stored (already validated and normalised), so a baked
//! and loaded map has the very same segments, bit for bit, and answers every query as the
//! original does.
//!
//! ```
//! use tileslide::io::{ascii, baked};
//! let map = ascii::parse("#####\n#./.#\n#####", "doc.txt", 1.0)?;
//! let bytes = baked::to_bytes(&map);
//! let back = baked::parse(&bytes, "doc.tsm")?;
//! assert_eq!(back.active_segment_count(), map.active_segment_count());
//! // A flipped byte is caught by the checksum, with the offset of the payload.
//! let mut bad = bytes.clone();
//! bad[40] ^= 1;
//! assert!(baked::parse(&bad, "bad.tsm").unwrap_err().to_string().contains("checksum"));
//! # Ok::<(), tileslide::io::LoadError>(())
//! ```

use std::path::Path;
use std::sync::Arc;

use glam::Vec2;

use super::bytes::ByteReader;
use super::error::read_file;
use super::{LoadError, LoadErrorKind};
use crate::tiles::{
    Cell, MAX_CELLS, MAX_SHAPE_SEGMENTS, SegmentFlags, TileId, TileMap, TileSegment, TileSet,
    TileSetError, TileShape,
};

/// The first eight bytes of every baked map.
pub const MAGIC: [u8; 8] = *b"TSLDMAP\x1a";
/// The format version this build writes and reads.
pub const VERSION: u32 = 1;
/// Bytes before the payload.
const HEADER_LEN: usize = 32;
/// The tile value of an empty cell.
const EMPTY: u32 = u32::MAX;
/// Bytes of one baked segment.
const SEGMENT_LEN: usize = 28;

/// The baked bytes of `map` (its tile set, size, origin and tiles; not its temporary
/// segments, which live for a frame).
#[must_use]
pub fn to_bytes(map: &TileMap) -> Vec<u8> {
    let mut payload = Vec::new();
    let set = map.tile_set();
    for v in [
        set.tile_size().x,
        set.tile_size().y,
        map.origin().x,
        map.origin().y,
    ] {
        payload.extend_from_slice(&v.to_le_bytes());
    }
    for v in [map.width(), map.height(), set.len() as u32] {
        payload.extend_from_slice(&v.to_le_bytes());
    }
    for (id, shape) in set.iter() {
        payload.extend_from_slice(&id.0.to_le_bytes());
        payload.extend_from_slice(&(shape.segments().len() as u32).to_le_bytes());
        for s in shape.segments() {
            for v in [s.a.x, s.a.y, s.b.x, s.b.y, s.normal.x, s.normal.y] {
                payload.extend_from_slice(&v.to_le_bytes());
            }
            payload.extend_from_slice(&s.flags.0.to_le_bytes());
        }
    }
    for row in 0..map.height() {
        for col in 0..map.width() {
            let id = map.tile(Cell::new(col, row));
            payload.extend_from_slice(&id.map_or(EMPTY, |t| t.0).to_le_bytes());
        }
    }
    let mut out = Vec::with_capacity(HEADER_LEN + payload.len());
    out.extend_from_slice(&MAGIC);
    out.extend_from_slice(&VERSION.to_le_bytes());
    out.extend_from_slice(&0u32.to_le_bytes());
    out.extend_from_slice(&(payload.len() as u64).to_le_bytes());
    out.extend_from_slice(&fnv1a(&payload).to_le_bytes());
    out.extend_from_slice(&payload);
    out
}

/// Writes `map` baked to `path`.
pub fn save(map: &TileMap, path: impl AsRef<Path>) -> std::io::Result<()> {
    std::fs::write(path, to_bytes(map))
}

/// Loads a baked map file.
pub fn load(path: impl AsRef<Path>) -> Result<TileMap, LoadError> {
    let path = path.as_ref();
    parse(&read_file(path)?, path)
}

/// Parses a baked map; `path` names it in errors, which give the byte offset of the field
/// at fault. Sizes are checked against the bytes actually there before anything is
/// allocated.
pub fn parse(data: &[u8], path: impl AsRef<Path>) -> Result<TileMap, LoadError> {
    let path = path.as_ref();
    let mut r = ByteReader::new(data, path);
    let magic = r.take(MAGIC.len(), "magic")?;
    if magic != MAGIC {
        return Err(r.error_at(
            0,
            LoadErrorKind::BadSignature {
                field: "magic",
                expected: i64::from_le_bytes(MAGIC),
                found: i64::from_le_bytes(magic.try_into().unwrap_or([0; 8])),
                format: "tileslide baked map",
            },
        ));
    }
    let version = r.u32("version")?;
    if version != VERSION {
        return Err(r.error_at(
            8,
            LoadErrorKind::BadSize {
                field: "version",
                value: version.into(),
                reason: format!("this build reads version {VERSION}; re-bake the map"),
            },
        ));
    }
    let reserved = r.u32("reserved")?;
    if reserved != 0 {
        return Err(r.error_at(
            12,
            LoadErrorKind::BadSize {
                field: "reserved",
                value: reserved.into(),
                reason: "must be 0 in version 1".into(),
            },
        ));
    }
    let length = r.u64("payload_len")?;
    let checksum = r.u64("checksum")?;
    if length != r.remaining() as u64 {
        return Err(r.error_at(
            16,
            LoadErrorKind::BadSize {
                field: "payload_len",
                value: length as i64,
                reason: format!("the file holds {} bytes after the header", r.remaining()),
            },
        ));
    }
    let payload = &data[HEADER_LEN..];
    let found = fnv1a(payload);
    if found != checksum {
        return Err(r.error_at(
            HEADER_LEN as u64,
            LoadErrorKind::BadSize {
                field: "checksum",
                value: checksum as i64,
                reason: format!("the payload's FNV-1a is {found:#018x}: the file is corrupt"),
            },
        ));
    }
    let tile_size = Vec2::new(r.f32("tile_width")?, r.f32("tile_height")?);
    let origin = Vec2::new(r.f32("origin_x")?, r.f32("origin_y")?);
    let size_at = r.offset();
    let (width, height) = (r.u32("width")?, r.u32("height")?);
    let cells = u64::from(width) * u64::from(height);
    if cells > MAX_CELLS || cells * 4 > r.remaining() as u64 {
        return Err(r.error_at(
            size_at,
            LoadErrorKind::BadSize {
                field: "width × height",
                value: cells as i64,
                reason: format!("more cells than the limit ({MAX_CELLS}) or than the file holds"),
            },
        ));
    }
    let mut set = TileSet::new(tile_size).map_err(|e| r.error_at(0, e.into()))?;
    let count_at = r.offset();
    let shape_count = r.u32("shape_count")?;
    // Each shape takes at least 8 bytes.
    if u64::from(shape_count) * 8 > r.remaining() as u64 {
        return Err(r.error_at(
            count_at,
            LoadErrorKind::BadSize {
                field: "shape_count",
                value: shape_count.into(),
                reason: "more shapes than the file holds".into(),
            },
        ));
    }
    for _ in 0..shape_count {
        let shape_at = r.offset();
        let id = TileId(r.u32("id")?);
        let segment_count = r.u32("segment_count")? as usize;
        if segment_count > MAX_SHAPE_SEGMENTS || segment_count * SEGMENT_LEN > r.remaining() {
            return Err(r.error_at(
                shape_at + 4,
                LoadErrorKind::BadSize {
                    field: "segment_count",
                    value: segment_count as i64,
                    reason: format!(
                        "more than {MAX_SHAPE_SEGMENTS} segments, or more than the file holds"
                    ),
                },
            ));
        }
        let mut segments = Vec::with_capacity(segment_count);
        for _ in 0..segment_count {
            let mut v = [0.0f32; 6];
            for x in &mut v {
                *x = r.f32("segment")?;
            }
            let flags = SegmentFlags(r.u32("flags")?);
            segments.push(TileSegment::new(
                Vec2::new(v[0], v[1]),
                Vec2::new(v[2], v[3]),
                Vec2::new(v[4], v[5]),
                flags,
            ));
        }
        if set.shape(id).is_some() {
            return Err(r.error_at(shape_at, LoadErrorKind::DuplicateTile(id.0)));
        }
        let shape = TileShape::from_segments(segments).map_err(|source| {
            r.error_at(shape_at, TileSetError::InvalidTile { id, source }.into())
        })?;
        set.insert(id, shape)
            .map_err(|e| r.error_at(shape_at, e.into()))?;
    }
    let tiles_at = r.offset();
    let mut tiles = Vec::with_capacity(cells as usize);
    for _ in 0..cells {
        let raw = r.u32("tiles")?;
        tiles.push((raw != EMPTY).then_some(TileId(raw)));
    }
    if r.remaining() > 0 {
        return Err(r.error_at(
            r.offset(),
            LoadErrorKind::TrailingBytes(r.remaining() as u64),
        ));
    }
    TileMap::from_tiles(Arc::new(set), width, height, origin, &tiles)
        .map_err(|e| r.error_at(tiles_at, e.into()))
}

/// FNV-1a, 64 bits: a checksum against corruption (not against tampering).
fn fnv1a(data: &[u8]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for &byte in data {
        h ^= u64::from(byte);
        h = h.wrapping_mul(0x0100_0000_01b3);
    }
    h
}
