//! tileslide's own binary map format (`.tsm`): a map's tile set, its tiles, and its culled
//! segments with their end-point links, baked so that loading is reading numbers: no text to
//! parse and no seam culling to recompute. Layout (all little-endian; described in
//! `docs/baked-format.md`):
//!
//! ```text
//! offset  size  field
//! 0       8     magic        "TSLDMAP" then 0x1A
//! 8       4     version      u32 = 2
//! 12      4     reserved     u32 = 0 (checked)
//! 16      8     payload_len  u64: bytes after the 32-byte header
//! 24      8     checksum     u64: CRC-32 (IEEE) of the payload
//! 32      ...   payload:
//!   f32 tile_width, f32 tile_height, f32 origin_x, f32 origin_y
//!   u32 width, u32 height
//!   u32 shape_count, then per shape (by increasing id):
//!     u32 id, u32 segment_count, then per segment:
//!       f32 ax, ay, bx, by, nx, ny; u32 flags
//!   width × height × u32 tiles, row by row (0xFFFF_FFFF = empty)
//!   width × height × u16 active segment counts, then × u8 cell kinds
//!   u64 active, then per active segment, cell by cell (40 bytes):
//!     f32 ax, ay, ex, ey, nx, ny; u32 flags; u16 source; u8 caps; u8 0;
//!     u32 link_a, u32 link_b (the linked segment's rank among all active ones, or
//!     0xFFFF_FFFF for none)
//! ```
//!
//! Everything is written as the map holds it, so a baked and loaded map has the very same
//! tiles, segments and links, bit for bit, and answers every query as the original does.
//! On load the culled segments are checked (finite, links in range, each cell's kind as its
//! segments make it), not recomputed.
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
use crate::tiles::face_kind::kind_of;
use crate::tiles::store::{HotSegment, NO_SEGMENTS, SegmentStore, block_capacity};
use crate::tiles::{
    Cell, MAX_CELLS, MAX_SHAPE_SEGMENTS, MapError, SegmentFlags, SegmentRef, TileId, TileMap,
    TileSegment, TileSet, TileSetError, TileShape,
};

/// The first eight bytes of every baked map.
pub const MAGIC: [u8; 8] = *b"TSLDMAP\x1a";
/// The format version this build writes and reads.
pub const VERSION: u32 = 2;
/// Bytes before the payload.
const HEADER_LEN: usize = 32;
/// The tile value of an empty cell.
const EMPTY: u32 = u32::MAX;
/// Bytes of one baked tile-shape segment.
const SEGMENT_LEN: usize = 28;
/// Bytes of one baked active segment.
const ACTIVE_LEN: usize = 40;
/// A missing link.
const NO_LINK: u32 = u32::MAX;

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
    write_store(map, &mut payload);
    let mut out = Vec::with_capacity(HEADER_LEN + payload.len());
    out.extend_from_slice(&MAGIC);
    out.extend_from_slice(&VERSION.to_le_bytes());
    out.extend_from_slice(&0u32.to_le_bytes());
    out.extend_from_slice(&(payload.len() as u64).to_le_bytes());
    out.extend_from_slice(&u64::from(crc32fast::hash(&payload)).to_le_bytes());
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
    let found = u64::from(crc32fast::hash(payload));
    if found != checksum {
        return Err(r.error_at(
            HEADER_LEN as u64,
            LoadErrorKind::BadSize {
                field: "checksum",
                value: checksum as i64,
                reason: format!("the payload's CRC-32 is {found:#010x}: the file is corrupt"),
            },
        ));
    }
    let tile_size = Vec2::new(r.f32("tile_width")?, r.f32("tile_height")?);
    let origin = Vec2::new(r.f32("origin_x")?, r.f32("origin_y")?);
    let size_at = r.offset();
    let (width, height) = (r.u32("width")?, r.u32("height")?);
    let cells = u64::from(width) * u64::from(height);
    // Tiles, counts and kinds take 7 bytes a cell.
    if cells > MAX_CELLS || cells * 7 > r.remaining() as u64 {
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
    let raw = r.take(cells as usize * 4, "tiles")?;
    let tiles: Vec<u32> = raw
        .chunks_exact(4)
        .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        .collect();
    if let Some(k) = tiles
        .iter()
        .position(|&t| t != EMPTY && set.shape(TileId(t)).is_none())
    {
        return Err(r.error_at(
            tiles_at + 4 * k as u64,
            MapError::UnknownTile {
                id: TileId(tiles[k]),
            }
            .into(),
        ));
    }
    let store = read_store(&mut r, width, height, tile_size, origin)?;
    TileMap::from_store(Arc::new(set), width, height, origin, tiles, store)
        .map_err(|e| r.error_at(tiles_at, e.into()))
}

/// Appends the map's culled segments: counts, kinds, then each active segment with its
/// links as ranks among all active segments.
fn write_store(map: &TileMap, out: &mut Vec<u8>) {
    let store = &map.store;
    let cells = (map.width() * map.height()) as usize;
    let mut first = Vec::with_capacity(cells);
    let mut active = 0u32;
    for cell in 0..cells {
        first.push(active);
        active += store.cell(cell).len() as u32;
    }
    for cell in 0..cells {
        out.extend_from_slice(&(store.cell(cell).len() as u16).to_le_bytes());
    }
    out.extend_from_slice(store.kinds());
    out.extend_from_slice(&u64::from(active).to_le_bytes());
    let width = map.width();
    let rank = |link: Option<SegmentRef>| {
        link.map_or(NO_LINK, |l| {
            first[(l.cell.row * width + l.cell.col) as usize] + l.index
        })
    };
    for cell in 0..cells {
        let links = store.links(cell);
        let caps = store.caps(cell);
        for (k, s) in store.cell(cell).iter().enumerate() {
            for v in [s.a.x, s.a.y, s.e.x, s.e.y, s.normal.x, s.normal.y] {
                out.extend_from_slice(&v.to_le_bytes());
            }
            out.extend_from_slice(&s.flags.0.to_le_bytes());
            out.extend_from_slice(&s.source.to_le_bytes());
            out.extend_from_slice(&[caps[k], 0]);
            out.extend_from_slice(&rank(links[k][0]).to_le_bytes());
            out.extend_from_slice(&rank(links[k][1]).to_le_bytes());
        }
    }
}

/// Reads and checks the culled segments written by [`write_store`].
fn read_store(
    r: &mut ByteReader<'_>,
    width: u32,
    height: u32,
    cell_size: Vec2,
    origin: Vec2,
) -> Result<SegmentStore, LoadError> {
    let cells = (width * height) as usize;
    let counts: Vec<u16> = r
        .take(cells * 2, "counts")?
        .chunks_exact(2)
        .map(|b| u16::from_le_bytes([b[0], b[1]]))
        .collect();
    let kinds_at = r.offset();
    let kinds = r.take(cells, "kinds")?.to_vec();
    let active_at = r.offset();
    let active = r.u64("active")?;
    let total: u64 = counts.iter().map(|&c| u64::from(c)).sum();
    if active != total || active.saturating_mul(ACTIVE_LEN as u64) != r.remaining() as u64 {
        return Err(r.error_at(
            active_at,
            LoadErrorKind::BadSize {
                field: "active",
                value: active as i64,
                reason: format!(
                    "the cells' counts add up to {total}, and the file holds {} bytes of segments",
                    r.remaining()
                ),
            },
        ));
    }
    // The store's layout: each cell's block, sized as edits size them; which cell each
    // active segment (by rank) is in, and each cell's first rank.
    let mut starts = Vec::with_capacity(cells);
    let mut first = Vec::with_capacity(cells);
    let mut cell_of = Vec::with_capacity(active as usize);
    let mut slots = 0usize;
    for (cell, &count) in counts.iter().enumerate() {
        first.push(cell_of.len() as u32);
        cell_of.extend(std::iter::repeat_n(cell as u32, count as usize));
        if count == 0 {
            starts.push(NO_SEGMENTS);
        } else {
            starts.push(slots as u32);
            slots += block_capacity(count as usize);
        }
    }
    if slots >= NO_SEGMENTS as usize {
        return Err(r.error_at(
            active_at,
            LoadErrorKind::BadSize {
                field: "active",
                value: active as i64,
                reason: "more segments than a map can hold".into(),
            },
        ));
    }
    let segments_at = r.offset();
    let raw = r.take(active as usize * ACTIVE_LEN, "segments")?;
    let mut hot = Vec::with_capacity(slots);
    let mut links = Vec::with_capacity(slots);
    let mut caps = Vec::with_capacity(slots);
    let mut records = raw.chunks_exact(ACTIVE_LEN).enumerate();
    for &count in &counts {
        let block = hot.len();
        for _ in 0..count {
            let Some((k, b)) = records.next() else {
                break;
            };
            let f =
                |i: usize| f32::from_le_bytes([b[4 * i], b[4 * i + 1], b[4 * i + 2], b[4 * i + 3]]);
            let u = |at: usize| u32::from_le_bytes([b[at], b[at + 1], b[at + 2], b[at + 3]]);
            let bad = |reason: &str| {
                r.error_at(
                    segments_at + (k * ACTIVE_LEN) as u64,
                    LoadErrorKind::Invalid(format!("active segment {k}: {reason}")),
                )
            };
            let (a, e, normal) = (
                Vec2::new(f(0), f(1)),
                Vec2::new(f(2), f(3)),
                Vec2::new(f(4), f(5)),
            );
            if !(a.is_finite() && e.is_finite() && normal.is_finite()) || e == Vec2::ZERO {
                return Err(bad("a coordinate is not finite, or it has zero length"));
            }
            let link = |rank: u32| -> Result<Option<SegmentRef>, LoadError> {
                if rank == NO_LINK {
                    return Ok(None);
                }
                let cell = *cell_of
                    .get(rank as usize)
                    .ok_or_else(|| bad(&format!("links to segment {rank} of {active}")))?;
                Ok(Some(SegmentRef {
                    cell: Cell::new(cell % width, cell / width),
                    index: rank - first[cell as usize],
                }))
            };
            links.push([link(u(32))?, link(u(36))?]);
            hot.push(HotSegment {
                a,
                e,
                normal,
                flags: SegmentFlags(u(24)),
                source: u16::from_le_bytes([b[28], b[29]]),
                count,
            });
            caps.push(b[30]);
        }
        if count > 0 {
            // Padding up to the block's capacity (never read; overwritten on reuse).
            let capacity = block + block_capacity(count as usize);
            let pad = hot[block];
            hot.resize(capacity, pad);
            links.resize(capacity, [None; 2]);
            caps.resize(capacity, 0);
        }
    }
    // Each cell's kind must be the one its segments make: the ray walk trusts it.
    for (cell, (&count, &start)) in counts.iter().zip(&starts).enumerate() {
        let segments = if count == 0 {
            &[][..]
        } else {
            &hot[start as usize..start as usize + count as usize]
        };
        let col_row = Vec2::new((cell as u32 % width) as f32, (cell as u32 / width) as f32);
        let base = origin + col_row * cell_size;
        if kind_of(segments, base, cell_size) != kinds[cell] {
            return Err(r.error_at(
                kinds_at + cell as u64,
                LoadErrorKind::Invalid(format!(
                    "cell {} kind {} does not match its segments",
                    cell, kinds[cell]
                )),
            ));
        }
    }
    Ok(SegmentStore::from_layout(
        starts,
        kinds,
        hot,
        links,
        caps,
        active as usize,
    ))
}
