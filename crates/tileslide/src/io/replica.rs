//! Replica Island's collision files: the tile set (`collision.bin`) and levels
//! (`level_*.bin`). Format: `FORMAT.md` beside the data; all little-endian.
//!
//! Tiles are 32 × 32 pixels with y up. The map built from a level has its origin at (0, 0)
//! and row 0 at the **bottom** (file rows are stored top first), so a segment point `p` of
//! the tile in cell (col, row) is at `p + 32·(col, row)` in world pixels, as in the game.
//!
//! [`parse_level`] reads a level's layers up to and including its collision layer and no
//! further: later layers (background art, object spawns, hot spots) carry nothing for
//! collision. One real level (`level_1_4_island.bin`) has a hot-spot layer cut short by
//! 2,738 bytes; it loads because that layer comes after the collision layer.
//!
//! [`parse_objects`] reads every layer and returns what the level places beside its
//! collision, as plain data on the same grid and in the same pixels: each object of the
//! object layer with its type number, the game's name for it ([`ObjectKind`]) and its
//! position, and the hot-spot layer's code per cell ([`HotSpots`], [`HotSpotKind`]).

use std::path::Path;
use std::sync::Arc;

use glam::Vec2;

use super::bytes::ByteReader;
use super::error::read_file;
pub use super::replica_objects::{
    CutLayer, HotSpotKind, HotSpots, LevelObjects, ObjectKind, SpawnPoint,
};
use super::{LoadError, LoadErrorKind, Location};
use crate::tiles::{
    Cell, MAX_CELLS, SegmentFlags, TileId, TileMap, TileSegment, TileSet, TileSetError, TileShape,
};

/// Side of a Replica Island tile, in pixels.
pub const TILE_SIZE: f32 = 32.0;
const TILE_SET_SIGNATURE: u8 = 52;
const LEVEL_SIGNATURE: i8 = 96;
const TILE_MAP_SIGNATURE: i8 = 42;
const COLLISION_LAYER: i8 = 1;
const OBJECT_LAYER: i8 = 2;
const HOT_SPOT_LAYER: i8 = 3;

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
    let mut layers = Layers::open(data, path)?;
    while let Some(layer) = layers.next()? {
        let cells_data = layer.cells.ok_or_else(|| layer.cut_error(path))?;
        if layer.kind != COLLISION_LAYER {
            continue;
        }
        layer.check_map_size(path)?;
        let (w, h) = (layer.width as usize, layer.height as usize);
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
        return TileMap::from_tiles(tile_set, layer.width, layer.height, Vec2::ZERO, &tiles)
            .map_err(|e| LoadError::new(path, Location::File, e.into()));
    }
    Err(LoadError::new(
        path,
        Location::File,
        LoadErrorKind::NoCollisionLayer,
    ))
}

/// Loads a level file's object and hot-spot layers (see [`parse_objects`]).
pub fn load_objects(path: impl AsRef<Path>) -> Result<LevelObjects, LoadError> {
    let path = path.as_ref();
    parse_objects(&read_file(path)?, path)
}

/// Parses a level's object layer (type 2: what spawns where) and hot-spot layer (type 3: a
/// code per cell for the objects over it); `path` names it in errors.
///
/// Both are laid on the collision layer's grid (the first collision layer, as
/// [`parse_level`]'s), in its rows: row 0 at the bottom. Every layer is read and checked
/// as `parse_level` checks the layers it reads; besides, a level must have a collision
/// layer, at most one object and one hot-spot layer, each of the collision layer's size,
/// and no bytes after its last layer. The file may cut its last layer short when that is
/// the object or the hot-spot layer (two of the game's files do): the game reads such a
/// layer as empty, and so does this loader, saying so in [`LevelObjects::cut_short`].
///
/// ```
/// use tileslide::io::replica::{self, ObjectKind};
/// use tileslide::Cell;
/// // A level of one collision layer and one object layer of 2 × 2 cells: a coin at the
/// // top left, the player at the bottom right (file rows are stored top first).
/// let mut level = vec![96, 2, 0];
/// for (layer_type, cells) in [(1u8, [1u8, 0xff, 1, 1]), (2, [1, 0xff, 0xff, 0])] {
///     level.extend([layer_type, 0, 0, 0, 0x80, 0x3f, 42, 2, 0, 0, 0, 2, 0, 0, 0]);
///     level.extend(cells);
/// }
/// let objects = replica::parse_objects(&level, "level.bin")?;
/// let player = objects.player_spawn().expect("a player");
/// assert_eq!(player.cell, Cell::new(1, 0));
/// assert_eq!(objects.objects[0].kind, Some(ObjectKind::Coin));
/// assert_eq!(objects.objects[0].center().y, 48.0); // pixels, y up
/// # Ok::<(), tileslide::io::LoadError>(())
/// ```
pub fn parse_objects(data: &[u8], path: impl AsRef<Path>) -> Result<LevelObjects, LoadError> {
    let path = path.as_ref();
    let mut layers = Layers::open(data, path)?;
    let mut grid: Option<Layer<'_>> = None;
    let mut placed: [Option<Layer<'_>>; 2] = [None, None];
    let mut cut_short = None;
    while let Some(layer) = layers.next()? {
        let slot = match layer.kind {
            OBJECT_LAYER => Some(0),
            HOT_SPOT_LAYER => Some(1),
            _ => None,
        };
        match (layer.cells, slot) {
            (None, Some(_)) if layer.is_last => cut_short = Some(layer),
            (None, _) => return Err(layer.cut_error(path)),
            (Some(_), None) if layer.kind == COLLISION_LAYER && grid.is_none() => {
                layer.check_map_size(path)?;
                grid = Some(layer);
            }
            (Some(_), None) => {}
            (Some(_), Some(k)) => {
                if placed[k].is_some() {
                    return Err(layer.second_of_its_type(path));
                }
                placed[k] = Some(layer);
            }
        }
    }
    layers.finish()?;
    let grid =
        grid.ok_or_else(|| LoadError::new(path, Location::File, LoadErrorKind::NoCollisionLayer))?;
    for layer in placed.iter().flatten().chain(&cut_short) {
        layer.check_same_grid(&grid, path)?;
    }
    let [objects, hot_spots] = placed;
    let (w, h) = (grid.width, grid.height);
    let objects = objects
        .and_then(|layer| layer.cells)
        .map_or_else(Vec::new, |cells| spawn_points(cells, w, h));
    let hot_spots = hot_spots
        .and_then(|layer| layer.cells)
        .map(|cells| HotSpots::from_file_rows(w, h, cells));
    Ok(LevelObjects {
        width: w,
        height: h,
        objects,
        hot_spots,
        cut_short: cut_short.map(|layer| CutLayer {
            index: layer.index,
            layer_type: layer.kind,
            cells_at: layer.cells_at,
            cells: layer.cell_count,
            present: layer.present,
        }),
    })
}

/// The spawn points of an object layer of `w × h` cells stored top row first: every cell
/// with a type number of 0 or more, in the file's order.
fn spawn_points(cells: &[u8], w: u32, h: u32) -> Vec<SpawnPoint> {
    (0u32..)
        .zip(cells)
        .filter_map(|(i, &byte)| {
            let number = u8::try_from(byte as i8).ok()?;
            let (col, file_row) = (i % w, i / w);
            Some(SpawnPoint::new(number, Cell::new(col, h - 1 - file_row)))
        })
        .collect()
}

/// A level file's layers, read one at a time after its header.
struct Layers<'a> {
    r: ByteReader<'a>,
    count: usize,
    read: usize,
}

/// One layer as its header declares it, with its cells.
struct Layer<'a> {
    /// Its place among the file's layers, from 0.
    index: usize,
    /// Its `type` byte, and where that is.
    kind: i8,
    type_at: u64,
    width: u32,
    height: u32,
    width_at: u64,
    cells_at: u64,
    cell_count: u64,
    /// The bytes left in the file at its first cell.
    present: u64,
    /// Its cells, top row first; `None` when the file ends before they do.
    cells: Option<&'a [u8]>,
    /// The last layer the header declares.
    is_last: bool,
}

impl<'a> Layers<'a> {
    /// Reads the level's header: signature, layer count, background index.
    fn open(data: &'a [u8], path: &'a Path) -> Result<Self, LoadError> {
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
        let Ok(count) = usize::try_from(layer_count) else {
            return Err(r.error_at(
                layer_count_offset,
                LoadErrorKind::BadSize {
                    field: "layerCount",
                    value: layer_count.into(),
                    reason: "negative".into(),
                },
            ));
        };
        r.i8("backgroundIndex")?;
        Ok(Self { r, count, read: 0 })
    }

    /// The next layer, or `None` after the last. Its size is checked against the bytes
    /// left before anything is allocated; a layer the file cuts short has no cells, and
    /// the file is read to its end.
    fn next(&mut self) -> Result<Option<Layer<'a>>, LoadError> {
        if self.read == self.count {
            return Ok(None);
        }
        let r = &mut self.r;
        let type_at = r.offset();
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
        let width_at = r.offset();
        let width = r.i32("width")?;
        let height_at = r.offset();
        let height = r.i32("height")?;
        for (field, value, offset) in [("width", width, width_at), ("height", height, height_at)] {
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
        // Both are positive, so they fit a u32.
        let (width, height) = (width as u32, height as u32);
        // Check the size against the bytes actually present before allocating anything.
        let cell_count = u64::from(width) * u64::from(height);
        let cells_at = r.offset();
        let present = r.remaining() as u64;
        let cells = if cell_count > present {
            r.take(r.remaining(), "tiles")?;
            None
        } else {
            Some(r.take(cell_count as usize, "tiles")?)
        };
        self.read += 1;
        Ok(Some(Layer {
            index: self.read - 1,
            kind,
            type_at,
            width,
            height,
            width_at,
            cells_at,
            cell_count,
            present,
            cells,
            is_last: self.read == self.count,
        }))
    }

    /// Refuses bytes after the last layer.
    fn finish(self) -> Result<(), LoadError> {
        if self.r.remaining() > 0 {
            return Err(self.r.error_at(
                self.r.offset(),
                LoadErrorKind::TrailingBytes(self.r.remaining() as u64),
            ));
        }
        Ok(())
    }
}

impl Layer<'_> {
    fn size_error(
        &self,
        path: &Path,
        field: &'static str,
        value: i64,
        reason: String,
    ) -> LoadError {
        LoadError::new(
            path,
            Location::Byte(self.width_at),
            LoadErrorKind::BadSize {
                field,
                value,
                reason,
            },
        )
    }

    /// The error for a layer whose cells the file cuts short.
    fn cut_error(&self, path: &Path) -> LoadError {
        let (width, height, cells) = (self.width, self.height, self.cell_count);
        self.size_error(
            path,
            "width × height",
            cells as i64,
            format!(
                "{width}×{height} cells need {cells} bytes but only {} remain",
                self.present
            ),
        )
    }

    /// Refuses a collision layer larger than a map may be.
    fn check_map_size(&self, path: &Path) -> Result<(), LoadError> {
        if self.cell_count > MAX_CELLS {
            return Err(self.size_error(
                path,
                "width × height",
                self.cell_count as i64,
                format!("more than {MAX_CELLS} cells"),
            ));
        }
        Ok(())
    }

    /// Refuses an object or hot-spot layer whose size is not the collision layer's.
    fn check_same_grid(&self, grid: &Layer<'_>, path: &Path) -> Result<(), LoadError> {
        let (w, h) = (grid.width, grid.height);
        if (self.width, self.height) == (w, h) {
            return Ok(());
        }
        let (width, height) = (self.width, self.height);
        Err(self.size_error(
            path,
            "width × height",
            self.cell_count as i64,
            format!(
                "the layer of type {} has {width}×{height} cells, the collision layer {w}×{h}",
                self.kind
            ),
        ))
    }

    /// The error for a second object (or hot-spot) layer.
    fn second_of_its_type(&self, path: &Path) -> LoadError {
        LoadError::new(
            path,
            Location::Byte(self.type_at),
            LoadErrorKind::BadValue {
                owner: format!("layer {}", self.index),
                field: "type",
                found: format!("{} again", self.kind),
                expected: "at most one object layer (2) and one hot-spot layer (3)",
            },
        )
    }
}
