//! The collision map of a tile-map layer: which tiles collide and how
//! ([`TilemapCollision`]), and the map built from the layer's tiles and kept in step with
//! them. The `ecs_tilemap` feature reads bevy_ecs_tilemap's components into a [`LayerGrid`]
//! and the layer's tiles; everything after that is here, free of the renderer.

use std::collections::{BTreeMap, BTreeSet};
use std::sync::Arc;

use bevy::prelude::*;
use tileslide::io::ldtk::Collision;
use tileslide::limits::MAX_CELLS;
use tileslide::{Cell, TileId, TileMap, TileSet, TileShape};

use crate::map::CollisionMap;
use crate::units::MapUnits;

/// Which tiles of a bevy_ecs_tilemap layer collide, and as what: put it on the tilemap
/// entity (the one with the `TileStorage`), and with the `ecs_tilemap` feature the plugin
/// builds the [`CollisionMap`] from the layer's tiles and keeps it in step as tiles are
/// added, removed, retextured or flipped (digging, building, doors).
///
/// A tile collides by its texture index: as the collision given for that index
/// ([`with_texture`](Self::with_texture)), or else as the one given for every other index
/// ([`with_others`](Self::with_others); solid by default, so a layer drawn only where walls
/// are needs nothing more). Cells without a tile are empty. Tiles flipped in x or y
/// (`TileFlip`) collide flipped; a diagonal flip keeps solid squares and 45° ramps (which
/// it maps onto themselves or their mirror image) and is refused for other shapes (a
/// [`TileslideError`](crate::TileslideError) names the tile, which is left out).
///
/// The layer is the truth: its tiles replace any edit made to the map through
/// [`CollisionMap::map_mut`] the next time the layer changes, and a map from an asset
/// ([`CollisionMap::from_asset`]) gives way to it. One layer a world: a second one is
/// refused with an error. Square tilemaps only (isometric and hexagonal ones are refused);
/// the layer's `Transform` (and its parents') may translate and scale it, not rotate it.
/// The map's cells are the layer's grid (`TilemapGridSize`), its row 0 the layer's top
/// row, in map units ([`MapUnits`]).
///
/// ```
/// use tileslide::io::ldtk::Collision;
/// use tileslide_bevy::TilemapCollision;
///
/// // Texture 0 is floor (no collision), 3 a one-way platform, 5 a ramp; every other
/// // texture is a wall.
/// let layer = TilemapCollision::default()
///     .with_texture(0, Collision::Empty)
///     .with_texture(3, Collision::OneWay)
///     .with_texture(5, Collision::RampUpRight);
/// assert_eq!(layer.collision(3), Collision::OneWay);
/// assert_eq!(layer.collision(9), Collision::Solid);
/// ```
#[derive(Component, Clone, Debug, PartialEq)]
pub struct TilemapCollision {
    by_texture: BTreeMap<u32, Collision>,
    others: Collision,
    tile_shapes: BTreeMap<TileId, TileShape>,
}

impl Default for TilemapCollision {
    /// Every tile solid.
    fn default() -> Self {
        Self {
            by_texture: BTreeMap::new(),
            others: Collision::Solid,
            tile_shapes: BTreeMap::new(),
        }
    }
}

impl TilemapCollision {
    /// The same, with tiles of texture `index` colliding as `collision`.
    #[must_use]
    pub fn with_texture(mut self, index: u32, collision: Collision) -> Self {
        self.by_texture.insert(index, collision);
        self
    }

    /// The same, with tiles of every texture not given to
    /// [`with_texture`](Self::with_texture) colliding as `collision` (
    /// [`Collision::Empty`] for a layer where only the listed textures collide).
    #[must_use]
    pub fn with_others(mut self, collision: Collision) -> Self {
        self.others = collision;
        self
    }

    /// The same, with the game's own tile `id` (a [`Collision::Tile`]) shaped as `shape`,
    /// given in a unit cell (`[0, 1]²`, y down), as
    /// `tileslide::io::ldtk::LdtkOptions::with_tile_shape` takes it.
    #[must_use]
    pub fn with_tile_shape(mut self, id: TileId, shape: TileShape) -> Self {
        self.tile_shapes.insert(id, shape);
        self
    }

    /// How tiles of texture `index` collide.
    #[must_use]
    pub fn collision(&self, index: u32) -> Collision {
        self.by_texture.get(&index).copied().unwrap_or(self.others)
    }

    /// Every collision a tile can take, in order.
    fn collisions(&self) -> BTreeSet<Collision> {
        self.by_texture
            .values()
            .copied()
            .chain([self.others])
            .filter(|c| *c != Collision::Empty)
            .collect()
    }

    /// The tile set of every collision a tile can take, in each of its four flips, for
    /// cells of `cell` (map units).
    fn tile_set(&self, cell: tileslide::Vec2) -> Result<TileSet, String> {
        let mut set = TileSet::new(cell).map_err(|e| e.to_string())?;
        for collision in self.collisions() {
            let own = match collision {
                Collision::Tile(id) => {
                    let range = Collision::FIRST_FREE_ID..=Collision::LAST_FREE_ID;
                    if !range.contains(&id.0) {
                        return Err(format!(
                            "the game's tile id {id} is out of range: its own tiles are {} to {}",
                            range.start(),
                            range.end()
                        ));
                    }
                    let Some(shape) = self.tile_shapes.get(&id) else {
                        return Err(format!(
                            "the game's tile id {id} has no shape (TilemapCollision::with_tile_shape)"
                        ));
                    };
                    Some(shape)
                }
                _ => None,
            };
            for flip in 0..4 {
                let (Some(id), Some(shape)) = (
                    collision.flipped_tile_id(flip),
                    collision.shape_in_cell(cell, flip, own),
                ) else {
                    continue;
                };
                let shape = shape.map_err(|e| format!("the shape of tile {id}: {e}"))?;
                set.insert(id, shape).map_err(|e| e.to_string())?;
            }
        }
        Ok(set)
    }

    /// The tile id of a tile of texture `index` flipped as `flip` says; `Ok(None)` for an
    /// empty cell, `Err` for a diagonal flip of a shape it does not map onto itself.
    fn tile_id(&self, index: u32, flip: TileFlips) -> Result<Option<TileId>, String> {
        let collision = self.collision(index);
        let mut bits = u32::from(flip.x) | u32::from(flip.y) << 1;
        if flip.d {
            // Transposed (x and y swapped, before the other flips), a solid square and the
            // ramp rising to the right are themselves; the ramp falling to the right is
            // itself mirrored in x and y.
            match collision {
                Collision::Empty | Collision::Solid | Collision::RampUpRight => {}
                Collision::RampDownRight => bits ^= 3,
                other => {
                    return Err(format!(
                        "a diagonal flip of a {other:?} tile is not supported (only solid \
                         squares and 45° ramps): the tile is left out"
                    ));
                }
            }
        }
        Ok(collision.flipped_tile_id(bits))
    }
}

/// A tile's flips: in x, in y, and across its diagonal (x and y swapped first), as
/// bevy_ecs_tilemap's `TileFlip` holds them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct TileFlips {
    pub x: bool,
    pub y: bool,
    pub d: bool,
}

/// A layer's tile: its texture index and flips.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct LayerTile {
    pub texture: u32,
    pub flip: TileFlips,
}

/// Where a square layer's grid lies in the world (y up, tile (0, 0) at the bottom left).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct LayerGrid {
    /// Tiles across.
    pub width: u32,
    /// Tiles up.
    pub height: u32,
    /// A cell's size in the world (the grid size times the layer's scale).
    pub cell: Vec2,
    /// The centre of tile (0, 0) in the world.
    pub first_centre: Vec2,
}

impl LayerGrid {
    /// The map's origin (its top-left corner) and cell size, in map units.
    fn placement(&self, units: &MapUnits) -> Result<(tileslide::Vec2, tileslide::Vec2), String> {
        if !(self.cell.x.is_finite() && self.cell.y.is_finite())
            || self.cell.x <= 0.0
            || self.cell.y <= 0.0
        {
            return Err(format!(
                "the layer's cells are {} × {} world units: a grid size and scale must make them \
                 finite and positive",
                self.cell.x, self.cell.y
            ));
        }
        let corner = Vec2::new(
            self.first_centre.x - self.cell.x * 0.5,
            self.first_centre.y + (self.height as f32 - 0.5) * self.cell.y,
        );
        if !(corner.x.is_finite() && corner.y.is_finite()) {
            return Err(format!(
                "the layer's top-left corner is at ({}, {}): its transform must be finite",
                corner.x, corner.y
            ));
        }
        let cell = tileslide::Vec2::new(
            units.length_to_map(self.cell.x),
            units.length_to_map(self.cell.y),
        );
        Ok((units.to_map(corner), cell))
    }

    /// The map cell of tile (`x`, `y`): the same column, rows counted from the top.
    fn cell_of(&self, x: u32, y: u32) -> Cell {
        Cell::new(x, self.height - 1 - y)
    }
}

/// What [`apply_layer`] did to the map.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct Applied {
    /// Whether the map was built anew (the first time, or the layer's size, place or
    /// collisions changed).
    pub rebuilt: bool,
    /// The cells edited in place.
    pub edited: usize,
    /// The tiles left out, and why.
    pub refused: Vec<String>,
}

/// Puts the collision of the layer `grid`, whose tiles are `tiles` (`y · width + x`, as
/// bevy_ecs_tilemap's `TileStorage` keeps them; `None` where there is no tile), in `map`:
/// the cells that differ are edited in place (so bodies, characters and navigation catch
/// up from the map's journal), unless the map is not this layer's (another size, place or
/// tile set, or none: `rules_changed` says the tile set may have changed), when it is built
/// anew.
pub(crate) fn apply_layer(
    map: &mut CollisionMap,
    rules: &TilemapCollision,
    rules_changed: bool,
    grid: &LayerGrid,
    tiles: &[Option<LayerTile>],
    units: &MapUnits,
) -> Result<Applied, String> {
    let cells = u64::from(grid.width) * u64::from(grid.height);
    if grid.width == 0 || grid.height == 0 {
        return Err(format!(
            "the layer is {} × {} tiles: it needs at least one",
            grid.width, grid.height
        ));
    }
    // Before the cells are gathered: the core would refuse the map only after.
    if cells > MAX_CELLS {
        return Err(format!(
            "the layer is {} × {} tiles, {cells} cells: a map holds at most {MAX_CELLS}",
            grid.width, grid.height
        ));
    }
    // (At most MAX_CELLS now, which fits a usize wherever the core builds.)
    let cells = cells as usize;
    if tiles.len() != cells {
        return Err(format!(
            "the layer's tile storage holds {} cells for a {} × {} map",
            tiles.len(),
            grid.width,
            grid.height
        ));
    }
    let (origin, cell) = grid.placement(units)?;
    let mut applied = Applied::default();
    let mut wanted = vec![None; cells];
    for (i, tile) in tiles.iter().enumerate() {
        let Some(tile) = tile else { continue };
        let (x, y) = (
            (i % grid.width as usize) as u32,
            (i / grid.width as usize) as u32,
        );
        let c = grid.cell_of(x, y);
        match rules.tile_id(tile.texture, tile.flip) {
            Ok(id) => wanted[c.row as usize * grid.width as usize + c.col as usize] = id,
            Err(why) => applied.refused.push(format!("tile ({x}, {y}): {why}")),
        }
    }
    let fits = map.map().is_some_and(|m| {
        !rules_changed
            && m.width() == grid.width
            && m.height() == grid.height
            && m.origin() == origin
            && m.cell_size() == cell
    });
    if fits && let Some(m) = map.map_mut() {
        for (i, want) in wanted.iter().enumerate() {
            let at = Cell::new(
                (i % grid.width as usize) as u32,
                (i / grid.width as usize) as u32,
            );
            if m.tile(at) != *want {
                m.set_tile(at, *want)
                    .map_err(|e| format!("cell ({}, {}): {e}", at.col, at.row))?;
                applied.edited += 1;
            }
        }
        return Ok(applied);
    }
    let set = rules.tile_set(cell)?;
    let built = TileMap::from_tiles(Arc::new(set), grid.width, grid.height, origin, &wanted)
        .map_err(|e| e.to_string())?;
    map.put_layer_map(built);
    applied.rebuilt = true;
    Ok(applied)
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;

    fn tile(texture: u32) -> Option<LayerTile> {
        Some(LayerTile {
            texture,
            flip: TileFlips::default(),
        })
    }

    /// A 4 × 3 layer of 16-unit cells, tile (0, 0)'s centre at (8, 8): the map's top-left
    /// corner is at world (0, 48).
    fn grid() -> LayerGrid {
        LayerGrid {
            width: 4,
            height: 3,
            cell: Vec2::splat(16.0),
            first_centre: Vec2::splat(8.0),
        }
    }

    #[test]
    fn the_bottom_row_of_the_layer_is_the_last_row_of_the_map_and_the_corners_agree() {
        // A floor along the bottom (y = 0) and one block at (2, 2), the top right.
        let mut tiles = vec![None; 12];
        for floor in &mut tiles[..4] {
            *floor = tile(1);
        }
        tiles[2 * 4 + 2] = tile(1);
        let mut map = CollisionMap::default();
        let units = MapUnits::default();
        let applied = apply_layer(
            &mut map,
            &TilemapCollision::default(),
            false,
            &grid(),
            &tiles,
            &units,
        )
        .unwrap();
        assert!(applied.rebuilt);
        let m = map.map().unwrap();
        assert_eq!((m.width(), m.height()), (4, 3));
        assert_eq!(m.origin(), tileslide::Vec2::new(0.0, -48.0));
        assert_eq!(m.cell_size(), tileslide::Vec2::splat(16.0));
        for col in 0..4 {
            assert!(m.tile(Cell::new(col, 2)).is_some(), "floor at column {col}");
        }
        assert!(m.tile(Cell::new(2, 0)).is_some());
        assert_eq!(m.tile_counts().values().sum::<usize>(), 5);
        // The world point in the middle of tile (2, 2) is in that map cell.
        let centre = units.to_map(Vec2::new(8.0 + 32.0, 8.0 + 32.0));
        assert_eq!(m.cell_at(centre), Some(Cell::new(2, 0)));
    }

    #[test]
    fn a_changed_tile_edits_one_cell_in_place_and_a_moved_layer_is_built_anew() {
        let mut tiles = vec![None; 12];
        tiles[0] = tile(1);
        let mut map = CollisionMap::default();
        let rules = TilemapCollision::default();
        let units = MapUnits::default();
        apply_layer(&mut map, &rules, false, &grid(), &tiles, &units).unwrap();
        let generation = map.generation();
        let revision = map.map().unwrap().revision();
        tiles[0] = None;
        tiles[5] = tile(7);
        let applied = apply_layer(&mut map, &rules, false, &grid(), &tiles, &units).unwrap();
        assert_eq!((applied.rebuilt, applied.edited), (false, 2));
        assert_eq!(map.generation(), generation, "edited, not replaced");
        let m = map.map().unwrap();
        let journal: Vec<Cell> = m.changes_since(&revision).unwrap().collect();
        assert_eq!(journal, [Cell::new(1, 1), Cell::new(0, 2)]);
        assert_eq!(m.tile(Cell::new(0, 2)), None);
        assert!(m.tile(Cell::new(1, 1)).is_some());
        // Nothing changed: nothing edited.
        let again = apply_layer(&mut map, &rules, false, &grid(), &tiles, &units).unwrap();
        assert_eq!((again.rebuilt, again.edited), (false, 0));
        // The layer moved a cell right: a new map, its origin moved with it.
        let moved = LayerGrid {
            first_centre: Vec2::new(24.0, 8.0),
            ..grid()
        };
        let applied = apply_layer(&mut map, &rules, false, &moved, &tiles, &units).unwrap();
        assert!(applied.rebuilt);
        assert_eq!(map.generation(), generation + 1);
        assert_eq!(
            map.map().unwrap().origin(),
            tileslide::Vec2::new(16.0, -48.0)
        );
    }

    #[test]
    fn textures_collide_as_the_rules_say_and_flips_mirror_the_shapes() {
        let rules = TilemapCollision::default()
            .with_texture(0, Collision::Empty)
            .with_texture(2, Collision::OneWay)
            .with_texture(3, Collision::RampUpRight)
            .with_texture(4, Collision::RampDownRight);
        let flipped = |texture, x, y, d| {
            Some(LayerTile {
                texture,
                flip: TileFlips { x, y, d },
            })
        };
        let tiles = vec![
            tile(0),
            tile(2),
            flipped(3, true, false, false),
            flipped(3, false, false, true),
            flipped(4, false, false, true),
            tile(9),
            flipped(2, false, false, true),
            None,
        ];
        let grid = LayerGrid {
            width: 8,
            height: 1,
            cell: Vec2::ONE,
            first_centre: Vec2::splat(0.5),
        };
        let mut map = CollisionMap::default();
        let applied =
            apply_layer(&mut map, &rules, false, &grid, &tiles, &MapUnits::default()).unwrap();
        let m = map.map().unwrap();
        let id = |col| m.tile(Cell::new(col, 0));
        let c = |c: Collision, f| c.flipped_tile_id(f);
        assert_eq!(id(0), None, "texture 0 is floor");
        assert_eq!(id(1), c(Collision::OneWay, 0));
        assert_eq!(id(2), c(Collision::RampUpRight, 1), "mirrored in x");
        assert_eq!(id(3), c(Collision::RampUpRight, 0), "its own transpose");
        assert_eq!(
            id(4),
            c(Collision::RampDownRight, 3),
            "transposed: mirrored twice"
        );
        assert_eq!(id(5), c(Collision::Solid, 0), "unlisted textures are walls");
        assert_eq!(id(6), None, "a one-way platform cannot be transposed");
        assert_eq!(applied.refused.len(), 1);
        assert!(applied.refused[0].starts_with("tile (6, 0): a diagonal flip of a OneWay tile"));
        // The ramp mirrored in x falls to the right: solid low on its left side.
        let shape = m.tile_set().shape(id(2).unwrap()).unwrap();
        assert!(shape.contains_point(tileslide::Vec2::new(0.1, 0.9)));
        assert!(!shape.contains_point(tileslide::Vec2::new(0.9, 0.1)));
    }

    #[test]
    fn only_listed_textures_collide_when_the_others_are_empty_and_game_tiles_need_a_shape() {
        let only_walls = TilemapCollision::default()
            .with_others(Collision::Empty)
            .with_texture(6, Collision::Solid);
        let mut map = CollisionMap::default();
        let grid = LayerGrid {
            width: 2,
            height: 1,
            cell: Vec2::ONE,
            first_centre: Vec2::splat(0.5),
        };
        let units = MapUnits::default();
        apply_layer(
            &mut map,
            &only_walls,
            false,
            &grid,
            &[tile(5), tile(6)],
            &units,
        )
        .unwrap();
        let m = map.map().unwrap();
        assert_eq!(m.tile(Cell::new(0, 0)), None);
        assert!(m.tile(Cell::new(1, 0)).is_some());
        let game = TilemapCollision::default().with_texture(1, Collision::Tile(TileId(40)));
        let err = apply_layer(&mut map, &game, true, &grid, &[tile(1), None], &units).unwrap_err();
        assert!(err.contains("tile id 40 has no shape"), "{err}");
        let low = TilemapCollision::default().with_texture(1, Collision::Tile(TileId(3)));
        let err = apply_layer(&mut map, &low, true, &grid, &[tile(1), None], &units).unwrap_err();
        assert!(err.contains("out of range"), "{err}");
        let half = TileShape::polygon(&[
            tileslide::Vec2::new(0.0, 0.5),
            tileslide::Vec2::new(1.0, 0.5),
            tileslide::Vec2::new(1.0, 1.0),
            tileslide::Vec2::new(0.0, 1.0),
        ])
        .unwrap();
        let shaped = game.with_tile_shape(TileId(40), half);
        apply_layer(&mut map, &shaped, true, &grid, &[tile(1), None], &units).unwrap();
        assert_eq!(map.map().unwrap().tile(Cell::new(0, 0)), Some(TileId(40)));
    }

    #[test]
    fn a_layer_that_cannot_be_a_map_is_refused_with_what_is_wrong() {
        let mut map = CollisionMap::default();
        let rules = TilemapCollision::default();
        let units = MapUnits::default();
        let flat = LayerGrid {
            cell: Vec2::new(16.0, 0.0),
            ..grid()
        };
        let err = apply_layer(&mut map, &rules, false, &flat, &[None; 12], &units).unwrap_err();
        assert!(err.contains("16 × 0 world units"), "{err}");
        let far = LayerGrid {
            first_centre: Vec2::new(f32::NAN, 0.0),
            ..grid()
        };
        let err = apply_layer(&mut map, &rules, false, &far, &[None; 12], &units).unwrap_err();
        assert!(err.contains("transform must be finite"), "{err}");
        let err = apply_layer(&mut map, &rules, false, &grid(), &[None; 5], &units).unwrap_err();
        assert!(err.contains("holds 5 cells for a 4 × 3 map"), "{err}");
        let huge = LayerGrid {
            width: 1 << 20,
            height: 1 << 20,
            ..grid()
        };
        let err = apply_layer(&mut map, &rules, false, &huge, &[], &units).unwrap_err();
        // Refused for its size, before its cells are gathered (the storage check after).
        assert!(
            err.contains("1099511627776 cells: a map holds at most 67108864"),
            "{err}"
        );
        assert!(map.map().is_none(), "nothing was put in place");
    }
}
