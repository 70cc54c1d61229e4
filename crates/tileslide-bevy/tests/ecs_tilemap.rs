//! A bevy_ecs_tilemap layer as the collision map: built from the layer's tiles where the
//! layer is drawn, edited in place as tiles are dug out, built and retextured, and bodies on
//! it move as the core moves them on the same map.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod support;

use bevy::prelude::*;
use bevy_ecs_tilemap::prelude::*;
use tileslide::io::ascii;
use tileslide::io::ldtk::Collision;
use tileslide::{Bodies, BodyDesc, BodyShape, Cell};
use tileslide_bevy::{
    Body, CollisionMap, MapUnits, ProposedMove, TilemapCollision, TileslideError, TileslidePlugin,
    TileslideSet,
};

/// The room, y down as the map reads it: walls round it and a block in the middle.
const ROOM: &str = "\
##########
#........#
#...##...#
#........#
##########";
const W: u32 = 10;
const H: u32 = 5;
const GRID: f32 = 16.0;

/// A headless app with the room as a bevy_ecs_tilemap layer of 16-unit tiles (texture 1
/// walls), its top-left corner at the world's origin; the layer's entity.
fn room_app() -> (App, Entity) {
    let mut app = support::headless(TileslidePlugin::default());
    support::collect::<TileslideError>(&mut app);
    let layer = spawn_layer(
        app.world_mut(),
        ROOM,
        // Tile (0, 0)'s centre: half a cell in from the bottom-left corner at (0, −80).
        Transform::from_xyz(GRID / 2.0, -(H as f32) * GRID + GRID / 2.0, 0.0),
        TilemapAnchor::None,
        TilemapCollision::default(),
    );
    (app, layer)
}

/// Spawns a layer drawn from `text` (y down; `#` a tile of texture 1, `=` of texture 2).
fn spawn_layer(
    world: &mut World,
    text: &str,
    transform: Transform,
    anchor: TilemapAnchor,
    collision: TilemapCollision,
) -> Entity {
    let rows: Vec<&str> = text.lines().collect();
    let size = TilemapSize {
        x: rows[0].len() as u32,
        y: rows.len() as u32,
    };
    let layer = world.spawn_empty().id();
    let mut storage = TileStorage::empty(size);
    for (row, line) in rows.iter().enumerate() {
        for (col, c) in line.chars().enumerate() {
            let texture = match c {
                '#' => 1,
                '=' => 2,
                _ => continue,
            };
            let position = TilePos {
                x: col as u32,
                y: size.y - 1 - row as u32,
            };
            let tile = world
                .spawn(TileBundle {
                    position,
                    tilemap_id: TilemapId(layer),
                    texture_index: TileTextureIndex(texture),
                    ..default()
                })
                .id();
            storage.set(&position, tile);
        }
    }
    world.entity_mut(layer).insert((
        storage,
        size,
        TilemapGridSize { x: GRID, y: GRID },
        TilemapTileSize { x: GRID, y: GRID },
        TilemapType::Square,
        anchor,
        transform,
        collision,
    ));
    layer
}

fn tile_at(app: &App, cell: Cell) -> Option<tileslide::TileId> {
    app.world()
        .resource::<CollisionMap>()
        .map()
        .unwrap()
        .tile(cell)
}

/// A body's constant move per step (world units).
#[derive(Component)]
struct Push(Vec2);

fn push(mut bodies: Query<(&Push, &mut ProposedMove)>) {
    for (push, mut proposed) in &mut bodies {
        proposed.0 = push.0;
    }
}

#[test]
fn the_layer_is_the_map_its_tiles_make_and_bodies_move_on_it_as_on_the_core() {
    let (mut app, _) = room_app();
    app.add_systems(FixedUpdate, push.before(TileslideSet::SyncIn));
    let moves = [
        (
            tileslide::Vec2::new(24.0, 24.0),
            tileslide::Vec2::new(3.1, 0.7),
        ),
        (
            tileslide::Vec2::new(120.0, 56.0),
            tileslide::Vec2::new(-2.3, -1.9),
        ),
        (
            tileslide::Vec2::new(40.0, 56.0),
            tileslide::Vec2::new(1.7, -2.6),
        ),
    ];
    let entities: Vec<Entity> = moves
        .iter()
        .map(|(p, v)| {
            app.world_mut()
                .spawn((
                    Body::circle(5.0),
                    Push(Vec2::new(v.x, -v.y)),
                    Transform::from_xyz(p.x, -p.y, 0.0),
                ))
                .id()
        })
        .collect();
    support::run_steps(&mut app, 60);
    assert!(support::collected::<TileslideError>(&app).is_empty());

    // The same room as an ASCII map of 16-unit cells: the same tiles, cells and origin.
    let core_map = ascii::parse(ROOM, "room.txt", GRID).unwrap();
    let map = app.world().resource::<CollisionMap>().map().unwrap();
    assert_eq!((map.width(), map.height()), (W, H));
    assert_eq!(map.origin(), core_map.origin());
    assert_eq!(map.cell_size(), core_map.cell_size());
    for row in 0..H {
        for col in 0..W {
            let cell = Cell::new(col, row);
            assert_eq!(map.tile(cell), core_map.tile(cell), "cell ({col}, {row})");
        }
    }
    let mut bodies = Bodies::new();
    let handles: Vec<_> = moves
        .iter()
        .map(|(p, _)| {
            bodies
                .add(BodyDesc::new(*p, BodyShape::circle(5.0).unwrap()))
                .unwrap()
        })
        .collect();
    for _ in 0..60 {
        for (h, (_, v)) in handles.iter().zip(&moves) {
            bodies.propose(*h, *v).unwrap();
        }
        bodies.step(&core_map);
    }
    for (entity, handle) in entities.iter().zip(&handles) {
        let at = app.world().get::<Transform>(*entity).unwrap().translation;
        let core = bodies.get(*handle).unwrap().position();
        assert_eq!(
            (at.x.to_bits(), (-at.y).to_bits()),
            (core.x.to_bits(), core.y.to_bits()),
            "plugin ({}, {}), core {core}",
            at.x,
            -at.y
        );
    }
}

#[test]
fn digging_building_and_retexturing_tiles_edit_the_map_in_place() {
    let (mut app, layer) = room_app();
    support::run_steps(&mut app, 1);
    let generation = app.world().resource::<CollisionMap>().generation();
    assert!(tile_at(&app, Cell::new(4, 2)).is_some(), "the block");
    assert!(tile_at(&app, Cell::new(2, 2)).is_none());

    // Dig the block's left tile out (tile (4, 2): the layer's y counts up), build a wall
    // tile at (2, 2), and turn the right wall's middle tile into a one-way platform.
    let world = app.world_mut();
    let dug = world
        .get_mut::<TileStorage>(layer)
        .unwrap()
        .remove(&TilePos { x: 4, y: 2 })
        .unwrap();
    world.despawn(dug);
    let position = TilePos { x: 2, y: 2 };
    let built = world
        .spawn(TileBundle {
            position,
            tilemap_id: TilemapId(layer),
            texture_index: TileTextureIndex(1),
            ..default()
        })
        .id();
    world
        .get_mut::<TileStorage>(layer)
        .unwrap()
        .set(&position, built);
    let wall = world
        .get::<TileStorage>(layer)
        .unwrap()
        .get(&TilePos { x: 9, y: 2 })
        .unwrap();
    world.get_mut::<TileTextureIndex>(wall).unwrap().0 = 2;
    world
        .entity_mut(layer)
        .insert(TilemapCollision::default().with_texture(2, Collision::OneWay));
    support::run_steps(&mut app, 1);

    assert!(tile_at(&app, Cell::new(4, 2)).is_none(), "dug out");
    assert_eq!(
        tile_at(&app, Cell::new(2, 2)),
        Collision::Solid.tile_id(),
        "built"
    );
    assert_eq!(tile_at(&app, Cell::new(9, 2)), Collision::OneWay.tile_id());
    // New collisions build the map anew; the next edits are made in place.
    let rebuilt = app.world().resource::<CollisionMap>().generation();
    assert_eq!(rebuilt, generation + 1);
    let tile = app
        .world()
        .get::<TileStorage>(layer)
        .unwrap()
        .get(&TilePos { x: 2, y: 2 })
        .unwrap();
    app.world_mut().get_mut::<TileFlip>(tile).unwrap().x = true;
    app.world_mut().get_mut::<TileTextureIndex>(tile).unwrap().0 = 7;
    support::run_steps(&mut app, 1);
    assert_eq!(
        tile_at(&app, Cell::new(2, 2)),
        Collision::Solid.flipped_tile_id(1),
        "a flipped wall"
    );
    // The one-way tile retextured back to a wall, nothing else changed.
    app.world_mut().get_mut::<TileTextureIndex>(wall).unwrap().0 = 1;
    support::run_steps(&mut app, 1);
    assert_eq!(tile_at(&app, Cell::new(9, 2)), Collision::Solid.tile_id());
    assert_eq!(app.world().resource::<CollisionMap>().generation(), rebuilt);
    assert!(support::collected::<TileslideError>(&app).is_empty());
}

#[test]
fn a_layer_under_a_moved_and_scaled_parent_collides_where_it_is_drawn() {
    let mut app = support::headless(TileslidePlugin::default().with_scale(2.0));
    support::collect::<TileslideError>(&mut app);
    let parent = app
        .world_mut()
        .spawn(Transform::from_xyz(100.0, 36.0, 0.0).with_scale(Vec3::new(0.5, 0.5, 1.0)))
        .id();
    let layer = spawn_layer(
        app.world_mut(),
        ROOM,
        Transform::from_xyz(-16.0, 8.0, 0.0),
        TilemapAnchor::Center,
        TilemapCollision::default(),
    );
    app.world_mut().entity_mut(layer).insert(ChildOf(parent));
    support::run_steps(&mut app, 1);
    assert!(support::collected::<TileslideError>(&app).is_empty());

    // Where bevy_ecs_tilemap draws each tile's centre (its own arithmetic), scaled and
    // moved by the two transforms: inside the map cell of that tile, at its centre.
    let units = *app.world().resource::<MapUnits>();
    let map = app.world().resource::<CollisionMap>().map().unwrap();
    let size = TilemapSize { x: W, y: H };
    let grid = TilemapGridSize { x: GRID, y: GRID };
    let global = Transform::from_xyz(100.0, 36.0, 0.0)
        .with_scale(Vec3::new(0.5, 0.5, 1.0))
        .mul_transform(Transform::from_xyz(-16.0, 8.0, 0.0));
    for (x, y) in [(0, 0), (3, 1), (9, 4)] {
        let local = TilePos { x, y }.center_in_world(
            &size,
            &grid,
            &TilemapTileSize { x: GRID, y: GRID },
            &TilemapType::Square,
            &TilemapAnchor::Center,
        );
        let world = global.transform_point(local.extend(0.0)).truncate();
        let cell = Cell::new(x, H - 1 - y);
        assert_eq!(
            map.cell_at(units.to_map(world)),
            Some(cell),
            "tile ({x}, {y})"
        );
        let rect = map.cell_rect(cell);
        assert_eq!(
            units.to_world((rect.min + rect.max) * 0.5),
            world,
            "tile ({x}, {y})"
        );
        // A cell is 16 × 0.5 world units, 4 map units at 2 world units a map unit.
        assert_eq!(map.cell_size(), tileslide::Vec2::splat(4.0));
    }
}

#[test]
fn a_hexagonal_layer_and_a_second_layer_are_refused_with_errors_naming_them() {
    let (mut app, first) = room_app();
    let second = spawn_layer(
        app.world_mut(),
        "##\n##",
        Transform::default(),
        TilemapAnchor::None,
        TilemapCollision::default(),
    );
    support::run_steps(&mut app, 2);
    assert_last_error(&app, 1, second, "already follows layer");

    // The followed layer turns hexagonal: refused, and the map stays as it was.
    app.world_mut()
        .entity_mut(first)
        .insert(TilemapType::Hexagon(HexCoordSystem::Row));
    support::run_steps(&mut app, 2);
    assert_last_error(&app, 2, first, "only square tilemaps");
}

/// Asserts that `count` errors were sent, the last naming `entity` and saying `words`, and
/// that the map is still the room's.
fn assert_last_error(app: &App, count: usize, entity: Entity, words: &str) {
    let errors = support::collected::<TileslideError>(app);
    assert_eq!(errors.len(), count, "{errors:?}");
    let last = errors.last().unwrap();
    assert_eq!(last.entity, entity);
    assert!(last.message.contains(words), "{}", last.message);
    let map = app.world().resource::<CollisionMap>().map().unwrap();
    assert_eq!(map.width(), W);
}
