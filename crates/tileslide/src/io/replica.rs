//! Replica Island's collision files: the tile set (`collision.bin`) and levels
//! (`level_*.bin`). Format: `FORMAT.md` beside the data; all little-endian.
//!
//! Tiles are 32 × 32 pixels with y up. The map built from a level has its origin at (0, 0)
//! and row 0 at the **bottom** (file rows are stored top first), so a segment point `p` of
//! the tile in cell (col, row) is at `p + 32·(col, row)` in world pixels, as in the game.
//!
//! The loader reads a level's layers up to and including its collision layer and no
//! further: later layers (background art, object spawns, hot spots) carry nothing for
//! collision. One real level (`level_1_4_island.bin`) has a hot-spot layer cut short by
//! 2,738 bytes; it loads because that layer comes after the collision layer.

use std::path::Path;
use std::sync::Arc;

use glam::Vec2;

use super::bytes::ByteReader;
use super::error::read_file;
use super::{LoadError, LoadErrorKind, Location};
use crate::tiles::{
    MAX_CELLS, SegmentFlags, TileId, TileMap, TileSegment, TileSet, TileSetError, TileShape,
};

/// Side of a Replica Island tile, in pixels.
pub const TILE_SIZE: f32 = 32.0;
const TILE_SET_SIGNATURE: u8 = 52;
const LEVEL_SIGNATURE: i8 = 96;
const TILE_MAP_SIGNATURE: i8 = 42;
const COLLISION_LAYER: i8 = 1;

/// Loads a collision tile set file.
pub fn load_tile_set(path: impl AsRef<Path>) -> Result<TileSet, LoadError> {
    let path = path.as_ref();
    parse_tile_set(&read_file(path)?, path)
}

/// Parses a collision tile set; `path` names it in errors.
pub fn parse_tile_set(data: &[u8], path: impl AsRef<Path>) -> Result<TileSet, LoadError> {
    let path = path.as_ref();
    let mut r = ByteReader::new(data, path);
    let signature = r.u8("signature")?;
    if signature != TILE_SET_SIGNATURE {
        return Err(r.error_at(
            0,
            LoadErrorKind::BadSignature {
                field: "signature",
                expected: TILE_SET_SIGNATURE.into(),
                found: signature.into(),
                format: "Replica Island collision tile set",
            },
        ));
    }
    let count = r.u8("tileCount")?;
    let mut set = TileSet::new(Vec2::splat(TILE_SIZE)).map_err(|e| r.error_at(0, e.into()))?;
    for _ in 0..count {
        let tile_offset = r.offset();
        let id = TileId(r.u8("tileIndex")?.into());
        let segment_count = r.u8("segmentCount")?;
        let mut segments = Vec::with_capacity(segment_count.into());
        for _ in 0..segment_count {
            let mut f = [0f32; 6];
            for (v, name) in f
                .iter_mut()
                .zip(["startX", "startY", "endX", "endY", "normalX", "normalY"])
            {
                *v = r.f32(name)?;
            }
            segments.push(TileSegment::new(
                Vec2::new(f[0], f[1]),
                Vec2::new(f[2], f[3]),
                Vec2::new(f[4], f[5]),
                SegmentFlags::SOLID,
            ));
        }
        if set.shape(id).is_some() {
            return Err(r.error_at(tile_offset, LoadErrorKind::DuplicateTile(id.0)));
        }
        let shape = TileShape::from_segments(segments).map_err(|source| {
            r.error_at(tile_offset, TileSetError::InvalidTile { id, source }.into())
        })?;
        set.insert(id, shape)
            .map_err(|e| r.error_at(tile_offset, e.into()))?;
    }
    if r.remaining() > 0 {
        return Err(r.error_at(
            r.offset(),
            LoadErrorKind::TrailingBytes(r.remaining() as u64),
        ));
    }
    Ok(set)
}

/// Loads a level file's collision layer as a map of `tile_set`'s tiles.
pub fn load_level(path: impl AsRef<Path>, tile_set: Arc<TileSet>) -> Result<TileMap, LoadError> {
    let path = path.as_ref();
    parse_level(&read_file(path)?, path, tile_set)
}

/// Parses a level's collision layer; `path` names it in errors. Tile ids that are negative,
/// or that the tile set does not define, are empty cells (as in the game).
pub fn parse_level(
    data: &[u8],
    path: impl AsRef<Path>,
    tile_set: Arc<TileSet>,
) -> Result<TileMap, LoadError> {
    let path = path.as_ref();
    let mut r = ByteReader::new(data, path);
    let signature = r.i8("signature")?;
    if signature != LEVEL_SIGNATURE {
        return Err(r.error_at(
            0,
            LoadErrorKind::BadSignature {
                field: "signature",
                expected: LEVEL_SIGNATURE.into(),
                found: signature.into(),
                format: "Replica Island level",
            },
        ));
    }
    let layer_count_offset = r.offset();
    let layer_count = r.i8("layerCount")?;
    if layer_count < 0 {
        return Err(r.error_at(
            layer_count_offset,
            LoadErrorKind::BadSize {
                field: "layerCount",
                value: layer_count.into(),
                reason: "negative".into(),
            },
        ));
    }
    r.i8("backgroundIndex")?;
    for _ in 0..layer_count {
        let kind = r.i8("type")?;
        r.i8("tileIndex")?;
        r.f32("scrollSpeed")?;
        let map_signature_offset = r.offset();
        let map_signature = r.i8("tile map signature")?;
        if map_signature != TILE_MAP_SIGNATURE {
            return Err(r.error_at(
                map_signature_offset,
                LoadErrorKind::BadSignature {
                    field: "tile map signature",
                    expected: TILE_MAP_SIGNATURE.into(),
                    found: map_signature.into(),
                    format: "Replica Island level",
                },
            ));
        }
        let width_offset = r.offset();
        let width = r.i32("width")?;
        let height_offset = r.offset();
        let height = r.i32("height")?;
        for (field, value, offset) in [
            ("width", width, width_offset),
            ("height", height, height_offset),
        ] {
            if value <= 0 {
                return Err(r.error_at(
                    offset,
                    LoadErrorKind::BadSize {
                        field,
                        value: value.into(),
                        reason: "must be at least 1".into(),
                    },
                ));
            }
        }
        // Check the size against the bytes actually present before allocating anything.
        let cells = width as u64 * height as u64;
        if cells > r.remaining() as u64 {
            return Err(r.error_at(
                width_offset,
                LoadErrorKind::BadSize {
                    field: "width × height",
                    value: cells as i64,
                    reason: format!(
                        "{width}×{height} cells need {cells} bytes but only {} remain",
                        r.remaining()
                    ),
                },
            ));
        }
        let cells_data = r.take(cells as usize, "tiles")?;
        if kind != COLLISION_LAYER {
            continue;
        }
        if cells > MAX_CELLS {
            return Err(r.error_at(
                width_offset,
                LoadErrorKind::BadSize {
                    field: "width × height",
                    value: cells as i64,
                    reason: format!("more than {MAX_CELLS} cells"),
                },
            ));
        }
        let (w, h) = (width as usize, height as usize);
        let mut tiles = vec![None; w * h];
        for (file_row, line) in cells_data.chunks_exact(w).enumerate() {
            let row = h - 1 - file_row;
            for (col, &byte) in line.iter().enumerate() {
                let id = byte as i8;
                if id >= 0 && tile_set.shape(TileId(id as u32)).is_some() {
                    tiles[row * w + col] = Some(TileId(id as u32));
                }
            }
        }
        return TileMap::from_tiles(tile_set, width as u32, height as u32, Vec2::ZERO, &tiles)
            .map_err(|e| LoadError::new(path, Location::File, e.into()));
    }
    Err(LoadError::new(
        path,
        Location::File,
        LoadErrorKind::NoCollisionLayer,
    ))
}
