//! Maps through Bevy's asset server: each format gives the core loader's map, bit for bit;
//! external tile sets come through the asset source; bad files fail naming the file; the
//! collision map follows its asset when it changes.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod support;

use std::path::PathBuf;

use bevy::asset::LoadState;
use bevy::prelude::*;
use support::{app_reading, assert_loaded, load, maps_dir, wait_for};
use tileslide::io::ldtk::{self, LdtkOptions};
use tileslide::io::tiled::{self, TiledOptions};
use tileslide::io::{ascii, baked};
use tileslide::{HitTypes, TileId, TileMap};
use tileslide_bevy::{CollisionMap, TileMapAsset, TileMapSettings};

/// The loaded map of `handle`, as baked bytes (every tile, shape and flag).
fn baked_bytes(app: &App, handle: &Handle<TileMapAsset>) -> Vec<u8> {
    let asset = app
        .world()
        .resource::<Assets<TileMapAsset>>()
        .get(handle)
        .unwrap();
    baked::to_bytes(&asset.map)
}

#[test]
fn every_format_loads_the_map_the_core_loader_gives() {
    let dir = maps_dir();
    let mut app = app_reading(&dir);
    let ascii_map = ascii::load(dir.join("cave.txt"), 1.0).unwrap();
    let cave = tiled::load(dir.join("cave.tmj"), &TiledOptions::default()).unwrap();
    let dungeon = tiled::load(dir.join("dungeon.tmx"), &TiledOptions::default()).unwrap();
    for (path, expected) in [
        ("cave.txt", &ascii_map),
        ("cave.tmj", &cave.map),
        ("dungeon.tmx", &dungeon.map),
    ] {
        let handle = load(&mut app, path);
        assert_loaded(&mut app, &handle);
        assert_eq!(
            baked_bytes(&app, &handle),
            baked::to_bytes(expected),
            "{path}"
        );
    }
}

#[test]
fn a_baked_map_loads_as_it_was_saved() {
    let root = scratch_dir("baked");
    let map = ascii::load(maps_dir().join("corner.txt"), 1.0).unwrap();
    baked::save(&map, root.join("corner.tsm")).unwrap();
    let mut app = app_reading(&root);
    let handle = load(&mut app, "corner.tsm");
    assert_loaded(&mut app, &handle);
    assert_eq!(baked_bytes(&app, &handle), baked::to_bytes(&map));
}

#[test]
fn an_ascii_map_takes_its_cell_size_from_the_settings() {
    let mut app = app_reading(&maps_dir());
    let handle = app
        .world()
        .resource::<AssetServer>()
        .load_builder()
        .with_settings(|s: &mut TileMapSettings| s.cell_size = 16.0)
        .load("cave.txt");
    assert_loaded(&mut app, &handle);
    let assets = app.world().resource::<Assets<TileMapAsset>>();
    let map = &assets.get(&handle).unwrap().map;
    assert_eq!(map.cell_size(), tileslide::Vec2::splat(16.0));
}

#[test]
fn a_tiled_map_brings_its_tiles_hit_types_and_object_layers() {
    let mut app = app_reading(&maps_dir());
    let handle = load(&mut app, "cave.tmj");
    assert_loaded(&mut app, &handle);
    let asset = app
        .world()
        .resource::<Assets<TileMapAsset>>()
        .get(&handle)
        .unwrap();
    // The spikes, tile 4 of the external tile set `tiles.tsj` (gid 5), deal DEATH.
    assert_eq!(asset.tile_hits.get(&TileId(5)), Some(&HitTypes::DEATH));
    assert_eq!(asset.tile_hits.len(), 1);
    let spawns = asset
        .object_layers
        .iter()
        .find(|l| l.name == "spawns")
        .unwrap();
    assert!(spawns.object("player").is_some());
}

/// The loaded asset of `handle`.
fn asset<'a>(app: &'a App, handle: &Handle<TileMapAsset>) -> &'a TileMapAsset {
    app.world()
        .resource::<Assets<TileMapAsset>>()
        .get(handle)
        .unwrap()
}

#[test]
fn an_ldtk_level_loads_as_the_core_builds_it_with_its_entities() {
    let dir = maps_dir();
    let mut app = app_reading(&dir);
    let path = dir.join("ldtk/platformer.ldtk");
    let expected = ldtk::load(&path, &LdtkOptions::default()).unwrap();
    let handle = load(&mut app, "ldtk/platformer.ldtk");
    assert_loaded(&mut app, &handle);
    assert_eq!(baked_bytes(&app, &handle), baked::to_bytes(&expected.map));
    let loaded = asset(&app, &handle);
    assert_eq!(loaded.entity_layers, expected.entity_layers);
    assert_eq!(loaded.level.as_ref().unwrap().identifier, "Meadow");
    let entities = &loaded.entity_layers[0];
    assert_eq!(entities.entities_of("MovingPlatform").count(), 2);
    assert!(entities.entity("PlayerStart").is_some());
}

#[test]
fn an_ldtk_level_in_its_own_file_is_read_through_the_asset_source() {
    let dir = maps_dir();
    let mut app = app_reading(&dir);
    let expected = ldtk::load(
        dir.join("ldtk/dungeon.ldtk"),
        &LdtkOptions::default().with_level("Crypt"),
    )
    .unwrap();
    let handle = app
        .world()
        .resource::<AssetServer>()
        .load_builder()
        .with_settings(|s: &mut TileMapSettings| s.level = Some("Crypt".into()))
        .load("ldtk/dungeon.ldtk");
    assert_loaded(&mut app, &handle);
    assert_eq!(baked_bytes(&app, &handle), baked::to_bytes(&expected.map));
    let loaded = asset(&app, &handle);
    assert_eq!(loaded.level.as_ref().unwrap().identifier, "Crypt");
    assert_eq!(loaded.entity_layers, expected.entity_layers);
}

#[test]
fn an_ldtk_level_file_outside_the_project_folder_is_refused_unread() {
    // The project in `root/maps` names `../secret.ldtkl`, which exists: the core refuses
    // the path before the loader is asked for the file, so it is never read.
    let root = scratch_dir("ldtk-outside");
    std::fs::create_dir_all(root.join("maps")).unwrap();
    let project = std::fs::read_to_string(maps_dir().join("ldtk/dungeon.ldtk")).unwrap();
    let project = project.replace("dungeon/Entrance.ldtkl", "../secret.ldtkl");
    std::fs::write(root.join("maps/dungeon.ldtk"), project).unwrap();
    std::fs::copy(
        maps_dir().join("ldtk/dungeon/Entrance.ldtkl"),
        root.join("secret.ldtkl"),
    )
    .unwrap();
    let message = load_error(&mut app_reading(&root), "maps/dungeon.ldtk");
    assert!(
        message.contains("maps/dungeon.ldtk")
            && message.contains("../secret.ldtkl")
            && message.contains("climbs above the folder"),
        "{message}"
    );
}

#[test]
fn a_missing_ldtk_level_file_fails_naming_it() {
    let root = scratch_dir("ldtk-missing");
    std::fs::copy(
        maps_dir().join("ldtk/dungeon.ldtk"),
        root.join("dungeon.ldtk"),
    )
    .unwrap();
    let message = load_error(&mut app_reading(&root), "dungeon.ldtk");
    assert!(
        message.contains("dungeon.ldtk") && message.contains("dungeon/Entrance.ldtkl"),
        "{message}"
    );
}

#[test]
fn a_broken_map_fails_naming_the_file_and_the_place() {
    let root = scratch_dir("broken");
    std::fs::write(root.join("level.tmj"), "{\n  \"width\": 3,\n  \"height\": ").unwrap();
    std::fs::write(root.join("room.txt"), "##\n#?\n").unwrap();
    let mut app = app_reading(&root);
    for (path, expected) in [
        ("level.tmj", "level.tmj:3:"),
        ("room.txt", "room.txt:2:2: "),
    ] {
        let message = load_error(&mut app, path);
        assert!(message.contains(expected), "{path}: {message}");
    }
}

#[test]
fn a_missing_tile_set_fails_naming_it() {
    let root = scratch_dir("missing");
    std::fs::copy(maps_dir().join("cave.tmj"), root.join("cave.tmj")).unwrap();
    let message = load_error(&mut app_reading(&root), "cave.tmj");
    assert!(
        message.contains("cave.tmj") && message.contains("tiles.tsj"),
        "{message}"
    );
}

#[test]
fn the_collision_map_follows_its_asset_when_it_loads_and_changes() {
    let mut app = app_reading(&maps_dir());
    let handle = load(&mut app, "cave.txt");
    app.insert_resource(CollisionMap::from_asset(handle.clone()));
    assert_loaded(&mut app, &handle);
    app.update();
    let expected = ascii::load(maps_dir().join("cave.txt"), 1.0).unwrap();
    {
        let map = app.world().resource::<CollisionMap>();
        assert_eq!(map.generation(), 1);
        assert_eq!(
            baked::to_bytes(map.map().unwrap()),
            baked::to_bytes(&expected)
        );
    }
    // The asset changes (as a reload of a changed file changes it): the map follows.
    let smaller: TileMap = ascii::parse("###\n#.#\n###", "small.txt", 1.0).unwrap();
    app.world_mut()
        .resource_mut::<Assets<TileMapAsset>>()
        .insert(handle.id(), TileMapAsset::new(smaller.clone()))
        .unwrap();
    app.update();
    app.update();
    let map = app.world().resource::<CollisionMap>();
    assert_eq!(map.generation(), 2);
    assert_eq!(
        baked::to_bytes(map.map().unwrap()),
        baked::to_bytes(&smaller)
    );
}

/// The error loading `path` fails with (a panic if it loads).
fn load_error(app: &mut App, path: &str) -> String {
    let handle = load(app, path);
    let LoadState::Failed(error) = wait_for(app, &handle) else {
        panic!("{path} loaded");
    };
    error.to_string()
}

/// A fresh folder for one test's files.
fn scratch_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("tileslide-bevy-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}
