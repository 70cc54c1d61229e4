//! A [`Document`] (from either format) as a [`TiledMap`]: the collision layer's grid, one
//! tile shape per (tile, flips) placed, and the object layers with their hit types.

use std::collections::BTreeMap;
use std::path::Path;
use std::sync::Arc;

use glam::Vec2;

use super::document::{Document, LayerCells, TileLayerDoc, TileSetDoc};
use super::placement::Placement;
use super::properties::Lookup;
use super::shapes::{self, TileShapeError};
use super::{Flip, SPREAD_FREE_CELLS, TileInfo, TiledMap, TiledOptions};
use crate::io::{LoadError, LoadErrorKind, Location, TilePlacement};
use crate::tiles::{MAX_CELLS, TileId, TileMap, TileSet, TileShape};

/// Builds the map; `path` is the map file, named by errors about its layers.
pub(super) fn build(
    doc: Document,
    options: &TiledOptions,
    path: &Path,
) -> Result<TiledMap, LoadError> {
    let index = collision_layer(&doc, options, path)?;
    let layer = &doc.tile_layers[index];
    let layer_error = |kind: LoadErrorKind| LoadError::new(path, layer.location, kind);
    let grid = Grid::of(layer, doc.tile_size, path, options)?;
    let tile_size = Vec2::new(doc.tile_size.0 as f32, doc.tile_size.1 as f32);

    // The gids placed, checked; each becomes the tile id of its cells.
    let mut tiles = vec![None; grid.width as usize * grid.height as usize];
    // Each gid placed, with the first cell that holds it (for errors).
    let mut placed = BTreeMap::new();
    for (x, y, gid) in grid.cells(layer) {
        // Tiled's 120° rotation bit means something on hexagonal maps only; on an
        // orthogonal map Tiled ignores it, and so does the loader.
        let gid = gid & !Flip::HEXAGONAL_120_BIT;
        if gid == 0 {
            continue;
        }
        let (col, row) = grid.cell_of(x, y);
        tiles[row as usize * grid.width as usize + col as usize] = Some(TileId(gid));
        placed.entry(gid).or_insert((x, y));
    }

    let mut set =
        TileSet::new(tile_size).map_err(|e| LoadError::new(path, Location::File, e.into()))?;
    let mut infos = BTreeMap::new();
    for (gid, (x, y)) in placed {
        let at = Box::new(TilePlacement {
            layer: layer.name.clone(),
            x,
            y,
            gid,
        });
        let number = gid & Flip::GID_MASK;
        let flip = Flip::from_gid(gid);
        let Some(tile_set) = doc.tile_sets.iter().rev().find(|s| s.first_gid <= number) else {
            return Err(layer_error(LoadErrorKind::GidBelowTileSets { at }));
        };
        let local = number - tile_set.first_gid;
        if local >= tile_set.tile_count && !tile_set.tiles.contains_key(&local) {
            return Err(layer_error(LoadErrorKind::TileNotInSet {
                at,
                tile_set: tile_set.name.clone(),
                tile_count: tile_set.tile_count,
                tile: local,
            }));
        }
        let bad_tile =
            |placed: Option<Box<TilePlacement>>, reason: String| LoadErrorKind::BadTile {
                placed,
                tile_set: tile_set.name.clone(),
                tile: local,
                reason,
            };
        let placement = Placement {
            tile: Vec2::new(tile_set.tile_size.0 as f32, tile_set.tile_size.1 as f32),
            cell: tile_size,
            flip,
        };
        // A tile that cannot go where it is placed is the layer's error, naming the cell; a
        // tile wrong wherever it goes is its tile set's.
        let definition_error =
            |reason: String| LoadError::new(&tile_set.file, Location::File, bad_tile(None, reason));
        let shape = tile_shape(tile_set, local, &placement).map_err(|e| match e {
            ShapeFailure::Placement(m) => layer_error(bad_tile(Some(at.clone()), m)),
            ShapeFailure::Definition(m) => definition_error(m),
        })?;
        set.insert(TileId(gid), shape)
            .map_err(|e| definition_error(e.to_string()))?;
        let tile = tile_set.tiles.get(&local);
        let hit_types = match tile {
            Some(t) => Lookup::of(&t.properties)
                .hit_types()
                .map_err(|e| definition_error(e.to_string()))?,
            None => crate::HitTypes::NONE,
        };
        infos.insert(
            TileId(gid),
            TileInfo {
                gid,
                tile_set: tile_set.name.clone(),
                local_id: local,
                flip,
                class: tile.map(|t| t.class.clone()).unwrap_or_default(),
                properties: tile.map(|t| t.properties.clone()).unwrap_or_default(),
                hit_types,
            },
        );
    }

    let map = TileMap::from_tiles(Arc::new(set), grid.width, grid.height, grid.origin, &tiles)
        .map_err(|e| LoadError::new(path, layer.location, LoadErrorKind::Map(e)))?;

    let mut object_layers = doc.object_layers;
    for layer in &mut object_layers {
        for object in &mut layer.objects {
            object.hit_types = Lookup::of(&object.properties).hit_types().map_err(|e| {
                let owner = format!("object layer {:?}, object {}", layer.name, object.id);
                LoadError::new(path, Location::File, e.of(&owner))
            })?;
        }
    }
    Ok(TiledMap {
        map,
        collision_layer: layer.name.clone(),
        collision_layer_index: index,
        tile_layers: doc.tile_layers.iter().map(|l| l.name.clone()).collect(),
        object_layers,
        properties: doc.properties,
        tiles: infos,
    })
}

/// Why a placed tile has no shape.
enum ShapeFailure {
    /// Its collision cannot be placed in its cell (it reaches a neighbour, or the flip is
    /// not defined for the tile): an error of the layer, naming the cell.
    Placement(String),
    /// The tile's own definition is wrong: an error of its tile set's file.
    Definition(String),
}

/// The shape of tile `local` of `set` as `placement` puts it in its cell. A tile without
/// collision objects is empty, whatever its size and flips.
fn tile_shape(
    set: &TileSetDoc,
    local: u32,
    placement: &Placement,
) -> Result<TileShape, ShapeFailure> {
    let error = ShapeFailure::Definition;
    let Some(tile) = set.tiles.get(&local) else {
        return Ok(TileShape::empty());
    };
    if placement.flip.diagonal && placement.tile.x != placement.tile.y && !tile.collision.is_empty()
    {
        return Err(ShapeFailure::Placement(format!(
            "its tile is {}×{} and has collision objects, so it cannot be flipped diagonally \
             (only square tiles can)",
            placement.tile.x, placement.tile.y
        )));
    }
    let segments = shapes::tile_segments(tile, placement).map_err(|e| match e {
        TileShapeError::Definition(m) => error(m),
        TileShapeError::Overhang(m) => ShapeFailure::Placement(m),
    })?;
    TileShape::from_segments(segments.into_iter().map(|s| placement.place(s)))
        .map_err(|e| error(e.to_string()))
}

/// The index of the collision layer: the one the options choose (see [`chosen_layer`]), else
/// the first with `collision = true`, else the first tile layer.
fn collision_layer(
    doc: &Document,
    options: &TiledOptions,
    path: &Path,
) -> Result<usize, LoadError> {
    if let Some(choice) = &options.layer {
        return chosen_layer(&doc.tile_layers, choice).ok_or_else(|| {
            let kind = LoadErrorKind::UnknownLayer {
                requested: choice.clone(),
                layers: doc.tile_layers.iter().map(|l| l.name.clone()).collect(),
            };
            LoadError::new(path, Location::File, kind)
        });
    }
    for (i, layer) in doc.tile_layers.iter().enumerate() {
        let collision = Lookup::of(&layer.properties)
            .bool("collision")
            .map_err(|e| LoadError::new(path, layer.location, e.of(&layer.label)))?;
        if collision == Some(true) {
            return Ok(i);
        }
    }
    if doc.tile_layers.is_empty() {
        return Err(LoadError::new(
            path,
            Location::File,
            LoadErrorKind::NoTileLayer,
        ));
    }
    Ok(0)
}

/// The tile layer `choice` names: the first layer named `choice`; else, for `NAME#N`, the
/// N-th (from 1) tile layer named `NAME`, and for `#N` the N-th tile layer of the file. Tiled
/// lets layers share a name, and this is how to choose the second. `None` when there is no
/// such layer ([`LoadErrorKind::UnknownLayer`] says why).
fn chosen_layer(layers: &[TileLayerDoc], choice: &str) -> Option<usize> {
    if let Some(i) = layers.iter().position(|l| l.name == choice) {
        return Some(i);
    }
    let (name, n) = choice
        .rsplit_once('#')
        .and_then(|(name, n)| Some((name, n.parse::<usize>().ok().filter(|&n| n >= 1)?)))?;
    (0..layers.len())
        .filter(|&i| name.is_empty() || layers[i].name == name)
        .nth(n - 1)
}

/// The collision layer's grid: its size and where its cell (0, 0) is.
struct Grid {
    width: u32,
    height: u32,
    /// Tiled's cell coordinates of the map's cell (0, 0).
    min: (i64, i64),
    origin: Vec2,
}

impl Grid {
    /// The grid of a finite layer, or the bounding box of an infinite layer's chunks,
    /// refused before anything is allocated if it has more cells than the options allow (or
    /// an infinite layer's chunks are spread too thinly over it).
    fn of(
        layer: &TileLayerDoc,
        tile_size: (u32, u32),
        path: &Path,
        options: &TiledOptions,
    ) -> Result<Self, LoadError> {
        let bad_size = |value: u64, reason: String| {
            LoadError::new(
                path,
                layer.location,
                LoadErrorKind::BadSize {
                    field: "width × height",
                    value: value as i64,
                    reason: format!("{}: {reason}", layer.label),
                },
            )
        };
        let (min, max) = match &layer.cells {
            LayerCells::Finite { width, height, .. } => {
                ((0, 0), (i64::from(*width), i64::from(*height)))
            }
            LayerCells::Chunks(chunks) => {
                let mut min = (i64::MAX, i64::MAX);
                let mut max = (i64::MIN, i64::MIN);
                for c in chunks {
                    min = (min.0.min(c.x.into()), min.1.min(c.y.into()));
                    max = (
                        max.0.max(i64::from(c.x) + i64::from(c.width)),
                        max.1.max(i64::from(c.y) + i64::from(c.height)),
                    );
                }
                if chunks.is_empty() {
                    return Err(bad_size(
                        0,
                        "the infinite layer has no chunks, so no cells".into(),
                    ));
                }
                (min, max)
            }
        };
        let (width, height) = (max.0 - min.0, max.1 - min.1);
        let cells = width.saturating_mul(height);
        let bound = options.max_cells.min(MAX_CELLS);
        if width <= 0 || height <= 0 || cells as u64 > bound {
            return Err(bad_size(
                cells as u64,
                format!(
                    "the layer spans {width}×{height} cells, more than {}",
                    super::cell_limit(bound)
                ),
            ));
        }
        if let LayerCells::Chunks(chunks) = &layer.cells {
            // Every cell of the bounding box is built, so chunks far apart cost memory for
            // every empty cell between them: bound the box by what the chunks hold.
            let held: u64 = chunks
                .iter()
                .map(|c| u64::from(c.width) * u64::from(c.height))
                .sum();
            let spread_bound = held
                .saturating_mul(options.max_chunk_spread)
                .max(SPREAD_FREE_CELLS);
            if cells as u64 > spread_bound {
                return Err(bad_size(
                    cells as u64,
                    format!(
                        "the infinite layer's chunks hold {held} cells spread over {width}×{height} \
                         = {cells} cells, more than {} times as many (`TiledOptions::\
                         max_chunk_spread`, for maps over {SPREAD_FREE_CELLS} cells): nearly \
                         all of it empty, and each empty cell costs memory; raise \
                         `max_chunk_spread` to load it",
                        options.max_chunk_spread
                    ),
                ));
            }
        }
        let origin = Vec2::new(
            (min.0 * i64::from(tile_size.0)) as f32,
            (min.1 * i64::from(tile_size.1)) as f32,
        ) + layer.offset;
        Ok(Self {
            width: width as u32,
            height: height as u32,
            min,
            origin,
        })
    }

    /// The map cell of Tiled's cell (x, y).
    fn cell_of(&self, x: i64, y: i64) -> (u32, u32) {
        ((x - self.min.0) as u32, (y - self.min.1) as u32)
    }

    /// Every cell of the layer with its gid, in Tiled's cell coordinates.
    fn cells<'a>(&self, layer: &'a TileLayerDoc) -> Box<dyn Iterator<Item = (i64, i64, u32)> + 'a> {
        match &layer.cells {
            LayerCells::Finite { width, gids, .. } => {
                let width = i64::from(*width);
                Box::new(
                    gids.iter()
                        .enumerate()
                        .map(move |(i, &g)| (i as i64 % width, i as i64 / width, g)),
                )
            }
            LayerCells::Chunks(chunks) => Box::new(chunks.iter().flat_map(|c| {
                let width = i64::from(c.width);
                c.gids.iter().enumerate().map(move |(i, &g)| {
                    (
                        i64::from(c.x) + i as i64 % width,
                        i64::from(c.y) + i as i64 / width,
                        g,
                    )
                })
            })),
        }
    }
}
