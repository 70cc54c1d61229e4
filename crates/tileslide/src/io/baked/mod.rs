//! tileslide's own binary map format (`.tsm`): a map's tile set, its tiles, and its culled
//! segments with their end-point links, baked so that loading is reading numbers: no text to
//! parse and no seam culling to recompute. Layout (all little-endian; described in
//! `docs/baked-format.md`):
//!
//! ```text
//! offset  size  field
//! 0       8     magic        "TSLDMAP" then 0x1A
//! 8       4     version      u32 = 3
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
//!     u32 link_a, u32 link_b (the linked segment: neighbour cell (dr+1)·3 + (dc+1) in
//!     bits 16.., its index in that cell in bits 0..16; 0xFFFF_FFFF for none)
//! ```
//!
//! Everything is written as the map holds it, so a baked and loaded map has the very same
//! tiles, segments and links, bit for bit, and answers every query as the original does.
//! On load the culled segments are checked against the tiles, not trusted for their
//! checksum: each cell's segments must be what its tile and its four neighbours make there
//! (culled once per distinct pattern of five tiles, see `expected`), its kind the one they
//! make, every link must join two segments that touch, and every cap be what the links give.
//!
//! ```
//! use tileslide::io::{ascii, baked};
//! let map = ascii::parse("#####\n#./.#\n#####", "doc.txt", 1.0)?;
//! let bytes = baked::to_bytes(&map);
//! let back = baked::parse(&bytes, "doc.tsm")?;
//! assert_eq!(back.active_segment_count(), map.active_segment_count());
//! // A flipped byte is caught by the checksum (the error points at its field, byte 24).
//! let mut bad = bytes.clone();
//! bad[40] ^= 1;
//! assert!(baked::parse(&bad, "bad.tsm").unwrap_err().to_string().contains("checksum"));
//! # Ok::<(), tileslide::io::LoadError>(())
//! ```

use std::path::Path;
use std::sync::Arc;

use glam::Vec2;

mod expected;
mod fault;

pub use fault::BakedFault;

use expected::{Expected, check_link, expected_caps, pattern_of};

use super::bytes::ByteReader;
use super::error::read_file;
use super::{LoadError, LoadErrorKind};
use crate::tiles::link::Link;
use crate::tiles::map::placed_segments;
use crate::tiles::store::{HotSegment, NO_SEGMENTS, SegmentStore, block_capacity};
use crate::tiles::{
    Cell, MAX_CELLS, MAX_SHAPE_SEGMENTS, MapError, SegmentFlags, TileId, TileMap, TileSegment,
    TileSet, TileSetError, TileShape,
};

/// The first eight bytes of every baked map.
pub const MAGIC: [u8; 8] = *b"TSLDMAP\x1a";
/// The format version this build writes and reads.
pub const VERSION: u32 = 3;
/// Bytes before the payload.
const HEADER_LEN: usize = 32;
/// The tile value of an empty cell.
const EMPTY: u32 = u32::MAX;
/// Bytes of one baked tile-shape segment.
const SEGMENT_LEN: usize = 28;
/// Bytes of one baked active segment.
const ACTIVE_LEN: usize = 40;

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
        // The bytes as text (`b"PK\x03\x04..."`), not as a signed number.
        return Err(r.error_at(
            0,
            LoadErrorKind::BadMagic {
                expected: &MAGIC,
                found: magic.to_vec(),
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
                reason: format!("must be 0 in version {VERSION}"),
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
        // At the checksum field, both values in hex.
        return Err(r.error_at(
            24,
            LoadErrorKind::ChecksumMismatch {
                stored: checksum,
                computed: found,
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
    let placed = placed_segments(&set, &tiles).map_err(|k| {
        r.error_at(
            tiles_at + 4 * k as u64,
            MapError::UnknownTile {
                id: TileId(tiles[k]),
            }
            .into(),
        )
    })?;
    let set = Arc::new(set);
    let grid = Grid {
        width,
        height,
        cell_size: tile_size,
        origin,
        tiles: &tiles,
    };
    let mut expected = Expected::new(set.clone());
    let (store, segments_at) = read_store(&mut r, &grid, &mut expected)?;
    if expected.gave_up() {
        compare_culled(&r, &grid, &set, &store, segments_at)?;
    }
    TileMap::from_store(set, width, height, origin, tiles, store, placed)
        .map_err(|e| r.error_at(tiles_at, e.into()))
}

/// Appends the map's culled segments: counts, kinds, then each active segment with its
/// links as the store holds them (see [`Link`]).
fn write_store(map: &TileMap, out: &mut Vec<u8>) {
    let store = &map.store;
    let cells = (map.width() * map.height()) as usize;
    for cell in 0..cells {
        out.extend_from_slice(&(store.cell(cell).len() as u16).to_le_bytes());
    }
    out.extend_from_slice(store.kinds());
    out.extend_from_slice(&(store.active_count() as u64).to_le_bytes());
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
            out.extend_from_slice(&links[k][0].raw().to_le_bytes());
            out.extend_from_slice(&links[k][1].raw().to_le_bytes());
        }
    }
}

/// One baked active segment, decoded but not yet checked.
struct ActiveRecord {
    hot: HotSegment,
    caps: u8,
    /// Its links as stored (see [`Link::raw`]).
    links: [u32; 2],
}

impl ActiveRecord {
    /// The record in `b` (laid out as [`write_store`] writes it), for a cell of `count`.
    #[inline(always)]
    fn decode(b: &[u8; ACTIVE_LEN], count: u16) -> Self {
        let word = |at: usize| [b[at], b[at + 1], b[at + 2], b[at + 3]];
        let f = |i: usize| f32::from_le_bytes(word(4 * i));
        Self {
            hot: HotSegment {
                a: Vec2::new(f(0), f(1)),
                e: Vec2::new(f(2), f(3)),
                normal: Vec2::new(f(4), f(5)),
                flags: SegmentFlags(u32::from_le_bytes(word(24))),
                source: u16::from_le_bytes([b[28], b[29]]),
                count,
            },
            caps: b[30],
            links: [u32::from_le_bytes(word(32)), u32::from_le_bytes(word(36))],
        }
    }

    /// Finite, and not of zero length.
    fn is_valid(&self) -> bool {
        let s = &self.hot;
        s.a.is_finite() && s.e.is_finite() && s.normal.is_finite() && s.e != Vec2::ZERO
    }
}

/// The error for active segment `k` (by rank, at `segments_at`) of cell `cell` of a map
/// `width` cells wide: kept out of the load loop.
#[cold]
fn bad_segment(
    r: &ByteReader<'_>,
    segments_at: u64,
    k: usize,
    (cell, width): (usize, u32),
    fault: BakedFault,
) -> LoadError {
    r.error_at(
        segments_at + (k * ACTIVE_LEN) as u64,
        LoadErrorKind::BakedSegments {
            cell: cell_at(cell, width),
            segment: Some(k as u64),
            fault,
        },
    )
}

/// The error for cell `cell` of a map `width` cells wide, at `offset`.
#[cold]
fn bad_cell(
    r: &ByteReader<'_>,
    offset: u64,
    (cell, width): (usize, u32),
    fault: BakedFault,
) -> LoadError {
    r.error_at(
        offset,
        LoadErrorKind::BakedSegments {
            cell: cell_at(cell, width),
            segment: None,
            fault,
        },
    )
}

/// Cell number `index` (row by row) of a map `width` cells wide.
fn cell_at(index: usize, width: u32) -> Cell {
    let width = width.max(1) as usize;
    Cell::new((index % width) as u32, (index / width) as u32)
}

/// A baked map's grid: its size, cells and tiles (raw ids, row by row).
struct Grid<'a> {
    width: u32,
    height: u32,
    cell_size: Vec2,
    origin: Vec2,
    tiles: &'a [u32],
}

/// Reads and checks the culled segments written by [`write_store`], into a store laid out as
/// edits lay one out (each cell's block at its [`block_capacity`]). Every cell's segments
/// must be what its tile and its neighbours make there (see [`expected`]), and every link
/// and cap what joining them gives.
/// Returns the store and the offset of its first segment record.
fn read_store(
    r: &mut ByteReader<'_>,
    grid: &Grid<'_>,
    expected: &mut Expected,
) -> Result<(SegmentStore, u64), LoadError> {
    let (width, height) = (grid.width, grid.height);
    let cells = (width * height) as usize;
    let counts_at = r.offset();
    let counts_raw = r.take(cells * 2, "counts")?;
    let (counts, _) = counts_raw.as_chunks::<2>();
    let count_of = |cell: usize| usize::from(u16::from_le_bytes(counts[cell]));
    let kinds_at = r.offset();
    let kinds = r.take(cells, "kinds")?.to_vec();
    let active_at = r.offset();
    let active = r.u64("active")?;
    let total: u64 = counts
        .iter()
        .map(|&c| u64::from(u16::from_le_bytes(c)))
        .sum();
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
    let segments_at = r.offset();
    let (records, _) = r
        .take(active as usize * ACTIVE_LEN, "segments")?
        .as_chunks::<ACTIVE_LEN>();
    let mut records = records.iter();
    let mut rank = 0usize;
    let mut starts = vec![NO_SEGMENTS; cells];
    let mut hot = Vec::with_capacity(active as usize);
    let mut links = Vec::with_capacity(active as usize);
    let mut caps = Vec::with_capacity(active as usize);
    let (w, h) = (i64::from(width), i64::from(height));
    let (mut row, mut row_start) = (0i64, 0usize);
    let pattern = |cell| pattern_of(grid.tiles, width as usize, height as usize, cell);
    let mut cell = 0;
    loop {
        // Most cells are empty: skip a run of them at a time, checking their kinds are 0 and
        // that their tiles make no segments there (a solid among solids).
        let next = (cell + zero_bytes(&counts_raw[2 * cell..]) / 2).min(cells);
        if kinds[cell..next].iter().fold(0, |any, &k| any | k) != 0 {
            let bad = (cell..next).find(|&c| kinds[c] != 0).unwrap_or(cell);
            return Err(bad_kind(r, kinds_at, (bad, width), kinds[bad]));
        }
        for c in (cell..next).filter(|&c| grid.tiles[c] != EMPTY) {
            let made = expected
                .count(pattern(c))
                .map_err(|e| r.error_at(counts_at, e.into()))?;
            if made != 0 {
                return Err(bad_cell(
                    r,
                    counts_at + 2 * c as u64,
                    (c, width),
                    BakedFault::WrongCount {
                        stored: 0,
                        made: made as u64,
                    },
                ));
            }
        }
        cell = next;
        if cell == cells {
            break;
        }
        while cell >= row_start + width as usize {
            (row, row_start) = (row + 1, row_start + width as usize);
        }
        let col = (cell - row_start) as i64;
        let count = count_of(cell);
        let block = hot.len();
        if block + block_capacity(count) >= NO_SEGMENTS as usize {
            return Err(r.error_at(
                active_at,
                LoadErrorKind::BadSize {
                    field: "active",
                    value: active as i64,
                    reason: "more segments than a map can hold".into(),
                },
            ));
        }
        starts[cell] = block as u32;
        // Links reach into the next row, which the scan has not read yet: touch its counts a
        // little ahead so the link checks below find them in cache.
        if let Some(ahead) = counts.get(cell + width as usize + 32) {
            std::hint::black_box(*ahead);
        }
        for b in records.by_ref().take(count) {
            let segment = ActiveRecord::decode(b, count as u16);
            if !segment.is_valid() {
                return Err(bad_segment(
                    r,
                    segments_at,
                    rank,
                    (cell, width),
                    BakedFault::NotFinite,
                ));
            }
            let mut ends = [Link::NONE; 2];
            for (end, raw) in ends.iter_mut().zip(segment.links) {
                let link = Link::from_raw(raw).ok_or_else(|| {
                    bad_segment(
                        r,
                        segments_at,
                        rank,
                        (cell, width),
                        BakedFault::LinkToNoNeighbour,
                    )
                })?;
                if let Some((dc, dr, index)) = link.target() {
                    let (c, rr) = (col + dc, row + dr);
                    let inside = c >= 0 && rr >= 0 && c < w && rr < h;
                    if !inside || index as usize >= count_of((rr * w + c) as usize) {
                        return Err(bad_segment(
                            r,
                            segments_at,
                            rank,
                            (cell, width),
                            BakedFault::LinkToMissingSegment,
                        ));
                    }
                }
                *end = link;
            }
            links.push(ends);
            hot.push(segment.hot);
            caps.push(segment.caps);
            rank += 1;
        }
        // The segments must be what the cell's tile and its neighbours make there, and the
        // cell's kind the one they make (the ray walk trusts it).
        let base = grid.origin + Vec2::new(col as f32, row as f32) * grid.cell_size;
        let kind = expected
            .check_cell(pattern(cell), base, &hot[block..])
            .map_err(|e| r.error_at(counts_at + 2 * cell as u64, e.into()))?
            .map_err(|m| match m.index {
                Some(index) => {
                    let at = rank - count + index.min(count.saturating_sub(1));
                    bad_segment(r, segments_at, at, (cell, width), m.fault)
                }
                None => bad_cell(r, counts_at + 2 * cell as u64, (cell, width), m.fault),
            })?;
        if kind != kinds[cell] {
            return Err(bad_kind(r, kinds_at, (cell, width), kinds[cell]));
        }
        // Padding up to the block's capacity (never read; overwritten on reuse).
        let capacity = block + block_capacity(count);
        if capacity > hot.len() {
            let pad = hot[block];
            hot.resize(capacity, pad);
            links.resize(capacity, [Link::NONE; 2]);
            caps.resize(capacity, 0);
        }
        cell += 1;
    }
    let store = SegmentStore::from_layout(starts, kinds, hot, links, caps, active as usize);
    check_joins(r, grid, segments_at, &store)?;
    Ok((store, segments_at))
}

/// Compares `store`, read from the file, with the map's tiles culled and linked at once:
/// for a map of too many distinct patterns to check one by one (see [`Expected`]).
fn compare_culled(
    r: &ByteReader<'_>,
    grid: &Grid<'_>,
    set: &Arc<TileSet>,
    store: &SegmentStore,
    segments_at: u64,
) -> Result<(), LoadError> {
    let tiles: Vec<Option<TileId>> = grid
        .tiles
        .iter()
        .map(|&t| (t != EMPTY).then_some(TileId(t)))
        .collect();
    let map = TileMap::from_tiles(set.clone(), grid.width, grid.height, grid.origin, &tiles)
        .map_err(|e| r.error_at(segments_at, e.into()))?;
    let culled = &map.store;
    let mut rank = 0;
    for cell in 0..tiles.len() {
        let (made, stored) = (culled.cell(cell), store.cell(cell));
        let same = |k: usize| {
            let (x, s) = (&made[k], &stored[k]);
            (x.a, x.e, x.normal, x.flags, x.source) == (s.a, s.e, s.normal, s.flags, s.source)
                && culled.links(cell)[k] == store.links(cell)[k]
                && culled.caps(cell)[k] == store.caps(cell)[k]
        };
        if let Some(k) = (0..stored.len()).find(|&k| k >= made.len() || !same(k)) {
            return Err(bad_segment(
                r,
                segments_at,
                rank + k,
                (cell, grid.width),
                BakedFault::NotWhatTheTilesMake,
            ));
        }
        if made.len() != stored.len() {
            return Err(bad_cell(
                r,
                segments_at,
                (cell, grid.width),
                BakedFault::WrongCount {
                    stored: stored.len() as u64,
                    made: made.len() as u64,
                },
            ));
        }
        rank += stored.len();
    }
    Ok(())
}

/// Checks every link (it joins two segments that touch there) and cap (as those joins give
/// it) of the segments read into `store`.
fn check_joins(
    r: &ByteReader<'_>,
    grid: &Grid<'_>,
    segments_at: u64,
    store: &SegmentStore,
) -> Result<(), LoadError> {
    let width = grid.width as usize;
    let mut rank = 0;
    for cell in 0..width * grid.height as usize {
        let (segments, links, caps) = (store.cell(cell), store.links(cell), store.caps(cell));
        for (i, segment) in segments.iter().enumerate() {
            let mut others = [None; 2];
            for (end, link) in links[i].iter().enumerate() {
                if let Some((dc, dr, index)) = link.target() {
                    // In the map, and below its cell's count: checked as the link was read.
                    let target = (cell as i64 + dr * width as i64 + dc) as usize;
                    let other = &store.cell(target)[index as usize];
                    let fault = if target == cell && index as usize == i {
                        Some(BakedFault::LinkToItself)
                    } else {
                        check_link(segment, end, other, grid.cell_size)
                    };
                    if let Some(fault) = fault {
                        return Err(bad_segment(r, segments_at, rank, (cell, grid.width), fault));
                    }
                    others[end] = Some(other);
                }
            }
            if caps[i] != expected_caps(segment, others) {
                return Err(bad_segment(
                    r,
                    segments_at,
                    rank,
                    (cell, grid.width),
                    BakedFault::WrongCaps,
                ));
            }
            rank += 1;
        }
    }
    Ok(())
}

/// How many bytes at the start of `bytes` are zero (eight at a time).
fn zero_bytes(bytes: &[u8]) -> usize {
    let mut words = bytes.chunks_exact(8);
    let mut zeros = 0;
    for w in words.by_ref() {
        let w = u64::from_le_bytes([w[0], w[1], w[2], w[3], w[4], w[5], w[6], w[7]]);
        if w != 0 {
            return zeros + (w.trailing_zeros() / 8) as usize;
        }
        zeros += 8;
    }
    zeros + words.remainder().iter().take_while(|&&b| b == 0).count()
}

/// The error for a cell whose kind is not the one its segments make.
#[cold]
fn bad_kind(r: &ByteReader<'_>, kinds_at: u64, (cell, width): (usize, u32), kind: u8) -> LoadError {
    bad_cell(
        r,
        kinds_at + cell as u64,
        (cell, width),
        BakedFault::WrongKind(kind),
    )
}
