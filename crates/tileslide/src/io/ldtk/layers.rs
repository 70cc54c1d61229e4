//! The collision layer: which layer of a level it is, and its cells as a [`TileMap`], from
//! IntGrid values or from the tiles of an auto-layer or tile layer.

use std::collections::BTreeMap;
use std::sync::Arc;

use glam::Vec2;

use super::LdtkOptions;
use super::collision::{self, Collision};
use super::entities::Fault;
use super::schema::{DefsJson, LayerInstanceJson, TileJson, TilesetDefJson};
use crate::io::{LdtkFault, LoadErrorKind};
use crate::tiles::{TileId, TileMap, TileSet, TileSetError};

/// The layer types that can collide.
const COLLIDING: [&str; 3] = ["IntGrid", "AutoLayer", "Tiles"];

/// The index of the collision layer among `layers` (of level `level`), or the fault, at the
/// layer whose index is given (`None`: the level's layers as a whole).
pub(super) fn choose(
    layers: &[LayerInstanceJson],
    defs: &DefsJson,
    options: &LdtkOptions,
    level: &str,
) -> Result<usize, (Option<usize>, LdtkFault)> {
    let colliding = |l: &&LayerInstanceJson| COLLIDING.contains(&l.kind.as_str());
    if let Some(name) = &options.layer {
        return layers
            .iter()
            .position(|l| colliding(&l) && &l.identifier == name)
            .ok_or_else(|| {
                let fault = LdtkFault::UnknownLayer {
                    level: level.to_owned(),
                    requested: name.clone(),
                    layers: layers
                        .iter()
                        .filter(colliding)
                        .map(|l| l.identifier.clone())
                        .collect(),
                };
                (None, fault)
            });
    }
    if let Some(i) = layers.iter().position(|l| l.kind == "IntGrid") {
        return Ok(i);
    }
    // A layer of tiles collides by default when its tile set names a shape (or fails to
    // say which, so that building it reports why).
    let names_a_shape = |l: &LayerInstanceJson| {
        l.tileset_def_uid
            .and_then(|uid| defs.tilesets.iter().position(|t| t.uid == uid))
            .is_some_and(|k| {
                tile_collisions(&defs.tilesets[k], k, options)
                    .map_or(true, |m| m.values().any(|c| *c != Collision::Empty))
            })
    };
    layers
        .iter()
        .position(|l| colliding(&l) && names_a_shape(l))
        .ok_or_else(|| {
            let fault = LdtkFault::NoCollisionLayer {
                level: level.to_owned(),
                layers: layers.iter().map(|l| l.identifier.clone()).collect(),
            };
            (None, fault)
        })
}

/// Why a layer could not be built: a fault at a JSON path of the level's file or of the
/// project's definitions, or a map that could not be made.
pub(super) enum BuildError {
    /// At a path of the file the layer is in.
    Fault(String, LdtkFault),
    /// At a path of the project (its definitions).
    ProjectFault(String, LdtkFault),
    /// The tile set or the map refused something.
    Kind(LoadErrorKind),
}

impl From<Fault> for BuildError {
    fn from((at, fault): Fault) -> Self {
        BuildError::Fault(at, fault)
    }
}

/// A built collision layer.
pub(super) struct Built {
    pub map: TileMap,
    /// Its IntGrid values (empty for a layer of tiles).
    pub int_grid: Vec<i64>,
}

/// The layer's cell size, checked.
pub(super) fn grid_size(layer: &LayerInstanceJson, at: &str) -> Result<u32, Fault> {
    if !(1..=super::MAX_GRID_SIZE).contains(&layer.grid_size) {
        return Err((
            format!("{at}.__gridSize"),
            super::build::size_fault(
                "__gridSize",
                layer.grid_size,
                format!("a cell is 1 to {} pixels", super::MAX_GRID_SIZE),
            ),
        ));
    }
    Ok(layer.grid_size as u32)
}

/// The layer's columns and rows, checked against `max_cells` before anything is allocated.
fn grid_cells(layer: &LayerInstanceJson, at: &str, max_cells: u64) -> Result<(u32, u32), Fault> {
    for (field, value) in [("__cWid", layer.columns), ("__cHei", layer.rows)] {
        if !(1..=i64::from(u32::MAX)).contains(&value) {
            return Err((
                format!("{at}.{field}"),
                super::build::size_fault(field, value, "a layer has at least one cell".into()),
            ));
        }
    }
    let cells = layer.columns as u64 * layer.rows as u64;
    if cells > max_cells {
        return Err((
            format!("{at}.__cWid"),
            super::build::size_fault(
                "__cWid × __cHei",
                i64::try_from(cells).unwrap_or(i64::MAX),
                format!(
                    "{} × {} is more than {max_cells} cells{}",
                    layer.columns,
                    layer.rows,
                    if max_cells < crate::tiles::MAX_CELLS {
                        " (`LdtkOptions::max_cells`; raise it to load this level)"
                    } else {
                        ""
                    }
                ),
            ),
        ));
    }
    Ok((layer.columns as u32, layer.rows as u32))
}

/// The collision layer `layer` (at JSON path `at`) of a level at `level_origin`, as a map.
pub(super) fn build(
    layer: &LayerInstanceJson,
    defs: &DefsJson,
    options: &LdtkOptions,
    level_origin: Vec2,
    at: &str,
) -> Result<Built, BuildError> {
    let grid = grid_size(layer, at)?;
    let (columns, rows) = grid_cells(layer, at, options.cell_bound())?;
    let cells = columns as usize * rows as usize;
    let origin = level_origin + Vec2::new(layer.offset_x as f32, layer.offset_y as f32);
    let mut placed = Placed::default();
    let mut tiles = vec![None; cells];
    let mut int_grid = Vec::new();
    if layer.kind == "IntGrid" {
        if layer.int_grid_csv.len() != cells {
            return Err(BuildError::Fault(
                format!("{at}.intGridCsv"),
                LdtkFault::CellCount {
                    found: layer.int_grid_csv.len() as u64,
                    expected: cells as u64,
                },
            ));
        }
        let identifiers: BTreeMap<i64, &str> = defs
            .layers
            .iter()
            .find(|d| d.uid == layer.layer_def_uid)
            .map(|d| {
                d.int_grid_values
                    .iter()
                    .filter_map(|v| Some((v.value, v.identifier.as_deref()?)))
                    .collect()
            })
            .unwrap_or_default();
        let mut by_value = BTreeMap::new();
        for (i, (&value, slot)) in layer.int_grid_csv.iter().zip(&mut tiles).enumerate() {
            if value < 0 {
                return Err(BuildError::Fault(
                    format!("{at}.intGridCsv[{i}]"),
                    LdtkFault::NegativeValue(value),
                ));
            }
            if value == 0 {
                continue;
            }
            let collision = *by_value.entry(value).or_insert_with(|| {
                value_collision(value, identifiers.get(&value).copied(), options)
            });
            *slot = placed.id(collision, 0, options)?;
        }
        int_grid = layer.int_grid_csv.clone();
    } else if let Some(uid) = layer.tileset_def_uid {
        let k = defs
            .tilesets
            .iter()
            .position(|t| t.uid == uid)
            .ok_or_else(|| {
                BuildError::Fault(
                    format!("{at}.__tilesetDefUid"),
                    LdtkFault::UnknownUid {
                        what: "tile set",
                        uid,
                    },
                )
            })?;
        let set = &defs.tilesets[k];
        if set.tile_grid_size != i64::from(grid) {
            return Err(BuildError::Fault(
                format!("{at}.__tilesetDefUid"),
                LdtkFault::TileSize {
                    tile_set: set.identifier.clone(),
                    tile_size: set.tile_grid_size,
                    grid_size: grid,
                },
            ));
        }
        let by_tile = tile_collisions(set, k, options)
            .map_err(|(at, fault)| BuildError::ProjectFault(at, fault))?;
        let (list, field) = if layer.kind == "Tiles" {
            (&layer.grid_tiles, "gridTiles")
        } else {
            (&layer.auto_layer_tiles, "autoLayerTiles")
        };
        for (i, tile) in list.iter().enumerate() {
            let cell = tile_cell(tile, grid, columns, rows).ok_or_else(|| {
                BuildError::Fault(
                    format!("{at}.{field}[{i}]"),
                    off_grid(tile, grid, columns, rows),
                )
            })?;
            let collision = by_tile.get(&tile.t).copied().unwrap_or(Collision::Empty);
            // Tiles are listed bottom to top: the top-most that names a shape counts.
            if collision != Collision::Empty {
                tiles[cell] = placed.id(collision, (tile.f & 3) as u32, options)?;
            }
        }
    }
    let set = placed.tile_set(grid, options)?;
    let map = TileMap::from_tiles(Arc::new(set), columns, rows, origin, &tiles)
        .map_err(|e| BuildError::Kind(LoadErrorKind::Map(e)))?;
    Ok(Built { map, int_grid })
}

/// The collision of IntGrid value `value`, whose identifier is `identifier`.
fn value_collision(value: i64, identifier: Option<&str>, options: &LdtkOptions) -> Collision {
    if let Some(c) = options.values.get(&value) {
        return *c;
    }
    if let Some(c) = identifier.and_then(|n| {
        options
            .names
            .get(n)
            .copied()
            .or_else(|| Collision::from_name(n))
    }) {
        return c;
    }
    if value == 1 {
        Collision::Solid
    } else {
        Collision::Empty
    }
}

/// The collision that a tile set's tiles name, by tile id (tile set `k` of the project).
fn tile_collisions(
    set: &TilesetDefJson,
    k: usize,
    options: &LdtkOptions,
) -> Result<BTreeMap<i64, Collision>, Fault> {
    let named = |name: &str| {
        options
            .names
            .get(name)
            .copied()
            .or_else(|| Collision::from_name(name))
    };
    let mut out: BTreeMap<i64, (Collision, String)> = BTreeMap::new();
    let mut give = |tile: i64, c: Collision, name: &str, at: String| -> Result<(), Fault> {
        match out.get(&tile) {
            Some((old, first)) if *old != c => Err((
                at,
                LdtkFault::TwoShapes {
                    tile_set: set.identifier.clone(),
                    tile,
                    first: first.clone(),
                    second: name.to_owned(),
                },
            )),
            _ => {
                out.insert(tile, (c, name.to_owned()));
                Ok(())
            }
        }
    };
    for (j, tag) in set.enum_tags.iter().enumerate() {
        let Some(c) = named(&tag.enum_value_id) else {
            continue;
        };
        for &tile in &tag.tile_ids {
            give(
                tile,
                c,
                &tag.enum_value_id,
                format!("defs.tilesets[{k}].enumTags[{j}]"),
            )?;
        }
    }
    for (j, data) in set.custom_data.iter().enumerate() {
        let at = format!("defs.tilesets[{k}].customData[{j}]");
        let c = match custom_collision(&data.data) {
            None => continue,
            Some(CustomName::Named(name)) => match named(name) {
                Some(c) => (c, name),
                None => continue,
            },
            Some(CustomName::Key(name)) => match named(name) {
                Some(c) => (c, name),
                None => {
                    return Err((
                        at,
                        LdtkFault::UnknownShape {
                            tile_set: set.identifier.clone(),
                            tile: data.tile_id,
                            name: name.to_owned(),
                        },
                    ));
                }
            },
        };
        give(data.tile_id, c.0, c.1, at)?;
    }
    Ok(out.into_iter().map(|(t, (c, _))| (t, c)).collect())
}

/// What a tile's custom data says of its collision.
enum CustomName<'a> {
    /// `collision: NAME` (or `=`, or a JSON object's `"collision"`): must name a shape.
    Key(&'a str),
    /// The whole text, which may name a shape.
    Named(&'a str),
}

/// The collision name in a tile's custom data: a line `collision: NAME` or `collision =
/// NAME` (quotes and a trailing comma allowed, so a JSON object written one key a line
/// counts too), else the whole text when it is one word.
fn custom_collision(data: &str) -> Option<CustomName<'_>> {
    fn unquote(s: &str) -> &str {
        s.trim()
            .trim_end_matches(',')
            .trim()
            .trim_matches('"')
            .trim()
    }
    for line in data.lines().flat_map(|l| l.split([',', '{', '}'])) {
        let line = line.trim();
        let Some((key, value)) = line.split_once([':', '=']) else {
            continue;
        };
        if unquote(key).eq_ignore_ascii_case("collision") {
            return Some(CustomName::Key(unquote(value)));
        }
    }
    let word = data.trim();
    (!word.is_empty() && !word.contains(char::is_whitespace)).then_some(CustomName::Named(word))
}

/// The index of the cell a tile is placed on, if it is on one.
fn tile_cell(tile: &TileJson, grid: u32, columns: u32, rows: u32) -> Option<usize> {
    let [x, y] = tile.px;
    let g = i64::from(grid);
    if x < 0 || y < 0 || x % g != 0 || y % g != 0 {
        return None;
    }
    let (col, row) = (x / g, y / g);
    (col < i64::from(columns) && row < i64::from(rows))
        .then(|| row as usize * columns as usize + col as usize)
}

fn off_grid(tile: &TileJson, grid: u32, columns: u32, rows: u32) -> LdtkFault {
    LdtkFault::TileOffGrid {
        tile: tile.t,
        x: tile.px[0],
        y: tile.px[1],
        columns,
        rows,
        grid_size: grid,
    }
}

/// The tile ids placed, with their collision and flips, to make the tile set from.
#[derive(Default)]
struct Placed {
    ids: BTreeMap<TileId, (Collision, u32)>,
}

impl Placed {
    /// The tile id of `collision` flipped by `f`, remembered; `None` for empty.
    fn id(
        &mut self,
        collision: Collision,
        f: u32,
        options: &LdtkOptions,
    ) -> Result<Option<TileId>, BuildError> {
        let Some(base) = collision.tile_id() else {
            return Ok(None);
        };
        if let Collision::Tile(id) = collision {
            let range = Collision::FIRST_FREE_ID..=Collision::LAST_FREE_ID;
            if !range.contains(&id.0) {
                return Err(BuildError::Kind(LoadErrorKind::Parameter(format!(
                    "the game's tile id {id} is out of range: its own tiles are {} to {}",
                    range.start(),
                    range.end()
                ))));
            }
            if !options.tile_shapes.contains_key(&id) {
                return Err(BuildError::Kind(LoadErrorKind::Parameter(format!(
                    "the game's tile id {id} has no shape in `LdtkOptions::tile_shapes`"
                ))));
            }
        }
        let id = collision::flipped(base, f);
        self.ids.insert(id, (collision, f));
        Ok(Some(id))
    }

    /// The tile set of every tile placed, for cells of `grid` pixels.
    fn tile_set(&self, grid: u32, options: &LdtkOptions) -> Result<TileSet, BuildError> {
        let size = grid as f32;
        let mut set = TileSet::new(Vec2::splat(size)).map_err(|e| BuildError::Kind(e.into()))?;
        for (&id, &(collision, f)) in &self.ids {
            let own = match collision {
                Collision::Tile(game) => options.tile_shapes.get(&game),
                _ => None,
            };
            let Some(shape) = collision.shape_in_cell(Vec2::splat(size), f, own) else {
                continue;
            };
            let shape = shape.map_err(|source| {
                BuildError::Kind(TileSetError::InvalidTile { id, source }.into())
            })?;
            set.insert(id, shape)
                .map_err(|e| BuildError::Kind(e.into()))?;
        }
        Ok(set)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn custom_data_names_a_shape_by_key_or_as_one_word() {
        let key = |d: &str| match custom_collision(d) {
            Some(CustomName::Key(k)) => Some(k.to_owned()),
            _ => None,
        };
        assert_eq!(key("collision: one_way"), Some("one_way".into()));
        assert_eq!(key("speed = 3\ncollision = solid"), Some("solid".into()));
        assert_eq!(
            key("{\"collision\": \"ramp_up_right\", \"hp\": 3}"),
            Some("ramp_up_right".into())
        );
        assert_eq!(
            key("{\n  \"collision\": \"solid\",\n  \"x\": 1\n}"),
            Some("solid".into())
        );
        assert!(matches!(
            custom_collision(" Solid "),
            Some(CustomName::Named("Solid"))
        ));
        assert!(custom_collision("a torch that flickers").is_none());
        assert!(custom_collision("").is_none());
    }

    #[test]
    fn intgrid_values_follow_the_game_then_their_names_then_value_one() {
        let options = LdtkOptions::default()
            .with_value(2, Collision::RampUpRight)
            .with_name("water", Collision::OneWay);
        assert_eq!(value_collision(1, None, &options), Collision::Solid);
        assert_eq!(
            value_collision(1, Some("walls"), &options),
            Collision::Solid
        );
        assert_eq!(
            value_collision(2, Some("one_way"), &options),
            Collision::RampUpRight
        );
        assert_eq!(
            value_collision(3, Some("one_way"), &options),
            Collision::OneWay
        );
        assert_eq!(
            value_collision(4, Some("water"), &options),
            Collision::OneWay
        );
        assert_eq!(value_collision(5, None, &options), Collision::Empty);
        assert_eq!(
            value_collision(1, Some("empty"), &options),
            Collision::Empty
        );
    }
}
