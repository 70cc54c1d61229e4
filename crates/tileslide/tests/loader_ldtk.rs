#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
//! The LDtk loader (`io::ldtk`): the example projects cell by cell against an independent
//! reading of their JSON, world layouts, entities and fields, the game's mappings, flipped
//! tiles, every error with the file and JSON path it names, and random IntGrid layers.

use std::path::{Path, PathBuf};

use proptest::prelude::*;
use serde_json::{Value, json};
use tileslide::io::ldtk::{
    self, Collision, FLIP_X_BIT, FLIP_Y_BIT, FieldValue, LdtkMap, LdtkOptions, LdtkProject,
    WorldLayout,
};
use tileslide::io::{LdtkFault, LoadError, LoadErrorKind, Location, ascii};
use tileslide::{Cell, QueryFilter, Ray, TileId, TileShape, Vec2};

fn example(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/maps/ldtk")
        .join(name)
}

fn load(name: &str, options: &LdtkOptions) -> LdtkMap {
    ldtk::load(example(name), options).unwrap_or_else(|e| panic!("{e}"))
}

fn read_json(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// The tile ids the built-in collisions have, written out here rather than asked of the
/// loader.
fn id_of_name(name: &str) -> Option<TileId> {
    Some(TileId(match name {
        "Solid" => 1,
        "Ramp_up_right" => 2,
        "Ramp_down_right" => 3,
        "One_way" => 4,
        "Gentle_ramp_up_right_low" => 5,
        "Gentle_ramp_up_right_high" => 6,
        "Gentle_ramp_down_right_high" => 7,
        "Gentle_ramp_down_right_low" => 8,
        _ => return None,
    }))
}

/// Every cell of `map`, row by row.
fn cells(map: &tileslide::TileMap) -> Vec<Option<TileId>> {
    (0..map.height())
        .flat_map(|row| (0..map.width()).map(move |col| Cell::new(col, row)))
        .map(|cell| map.tile(cell))
        .collect()
}

/// A one-level project around `layers` (JSON), in a free layout at the origin.
fn project_with(layers: Value, defs: Value) -> String {
    json!({
        "jsonVersion": "1.5.3",
        "worldLayout": "Free",
        "defs": defs,
        "levels": [{ "identifier": "One", "iid": "l1", "worldX": 0, "worldY": 0,
            "pxWid": 64, "pxHei": 32, "layerInstances": layers }]
    })
    .to_string()
}

/// An IntGrid layer `identifier` of `w × h` cells of `grid` pixels.
fn int_grid(identifier: &str, w: i64, h: i64, grid: i64, csv: &[i64]) -> Value {
    json!({ "__identifier": identifier, "__type": "IntGrid", "__cWid": w, "__cHei": h,
        "__gridSize": grid, "layerDefUid": 1, "intGridCsv": csv })
}

fn parse(text: &str, options: &LdtkOptions) -> Result<LdtkMap, LoadError> {
    ldtk::parse(text, "test.ldtk", options)
}

/// The LDtk fault of an error, with its JSON path.
fn fault(e: &LoadError) -> (&str, &LdtkFault) {
    match &e.kind {
        LoadErrorKind::Ldtk { json_path, fault } => (json_path.as_str(), fault),
        other => panic!("not an LDtk fault: {other:?} ({e})"),
    }
}

// ---------------------------------------------------------------- the example projects

#[test]
fn platformer_cells_are_the_intgrid_values_named_shapes() {
    let level = load("platformer.ldtk", &LdtkOptions::default());
    let json = read_json(&example("platformer.ldtk"));
    let layer = &json["levels"][0]["layerInstances"][1];
    assert_eq!(layer["__identifier"], "Collisions");
    let names: std::collections::BTreeMap<i64, String> = json["defs"]["layers"][1]["intGridValues"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| {
            (
                v["value"].as_i64().unwrap(),
                v["identifier"].as_str().unwrap().to_owned(),
            )
        })
        .collect();
    let expected: Vec<Option<TileId>> = layer["intGridCsv"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| match v.as_i64().unwrap() {
            0 => None,
            v => id_of_name(&names[&v]),
        })
        .collect();
    assert_eq!((level.map.width(), level.map.height()), (60, 20));
    assert_eq!(level.map.cell_size(), Vec2::splat(16.0));
    assert_eq!(cells(&level.map), expected);
    // Every shape the level is meant to show is there.
    let counts = level.map.tile_counts();
    for id in 1..=8 {
        assert!(
            counts.contains_key(&TileId(id)),
            "no tile {id} in {counts:?}"
        );
    }
    assert_eq!(
        level.int_grid_value(Cell::new(0, 0)),
        Some(1),
        "the left wall"
    );
    assert_eq!(level.int_grid_value(Cell::new(60, 0)), None);
}

#[test]
fn platformer_surfaces_are_where_the_level_draws_them() {
    let level = load("platformer.ldtk", &LdtkOptions::default());
    let down = |x: f32| {
        let ray = Ray::between(Vec2::new(x, 4.0), Vec2::new(x, 400.0));
        level.map.cast_ray(ray, &QueryFilter::default()).unwrap()
    };
    // The one-way ledge over the start (row 13) stops a ray from above.
    assert_eq!(down(120.0).point.y, 208.0);
    // The 45° ramp at column 14: halfway across, 8 pixels above the ground.
    let ramp = down(14.0 * 16.0 + 8.0);
    assert_eq!(ramp.point.y, 264.0);
    assert!((ramp.normal - Vec2::new(-1.0, -1.0).normalize()).length() < 1e-6);
    // The gentle ramp: at the far edge of its low cell, half a cell up.
    let gentle = down(35.0 * 16.0 + 15.0);
    assert!((gentle.point.y - (272.0 - 7.5)).abs() < 1e-3, "{gentle:?}");
    // The pit: its floor two cells below the ground; the one-way over it, further right.
    assert_eq!(down(24.0 * 16.0 + 8.0).point.y, 304.0);
    assert_eq!(down(26.0 * 16.0 + 8.0).point.y, 160.0);
    // A one-way platform does not stop a ray from below.
    let up = Ray::between(Vec2::new(120.0, 260.0), Vec2::new(120.0, 4.0));
    assert!(level.map.cast_ray(up, &QueryFilter::default()).is_none());
}

#[test]
fn platformer_entities_come_with_positions_and_fields() {
    let level = load("platformer.ldtk", &LdtkOptions::default());
    let layer = level.entity_layer("Entities").unwrap();
    let start = layer.entity("PlayerStart").unwrap();
    assert_eq!(start.position, Vec2::new(40.0, 272.0));
    assert_eq!(
        (start.size, start.pivot),
        (Vec2::new(16.0, 24.0), Vec2::new(0.5, 1.0))
    );
    assert_eq!(start.top_left(), Vec2::new(32.0, 248.0));
    assert_eq!(start.tags, ["actor"]);
    let platforms: Vec<_> = layer.entities_of("MovingPlatform").collect();
    assert_eq!(platforms.len(), 2);
    let ferry = platforms[0];
    assert_eq!(ferry.top_left(), Vec2::new(384.0, 272.0));
    assert_eq!(ferry.size, Vec2::new(48.0, 8.0));
    assert_eq!(
        ferry.field("speed").and_then(FieldValue::as_float),
        Some(40.0)
    );
    assert_eq!(
        ferry.field("loop").and_then(FieldValue::as_bool),
        Some(false)
    );
    // The path: cell centres in world pixels, and the cells' corners.
    assert_eq!(
        ferry.field("path").unwrap().as_points().unwrap(),
        [Vec2::new(392.0, 280.0), Vec2::new(472.0, 280.0)]
    );
    let Some(FieldValue::Array(points)) = ferry.field("path") else {
        panic!("{ferry:?}")
    };
    let FieldValue::Point(first) = &points[0] else {
        panic!()
    };
    assert_eq!(
        (first.cx, first.cy, first.corner),
        (24, 17, ferry.top_left())
    );
    let elevator = platforms[1];
    assert_eq!(elevator.size, Vec2::new(32.0, 8.0));
    assert_eq!(
        elevator.field("loop").and_then(FieldValue::as_bool),
        Some(true)
    );
    assert_eq!(layer.entities_of("Coin").count(), 4);
    assert_eq!(level.entities().count(), 8);
    assert_eq!(level.layers, ["Entities", "Collisions"]);
}

/// The tile ids of a dungeon room, read from its level file: solid where the tile set tags
/// the tile `Solid` or its custom data says so.
fn dungeon_expected(room: &str) -> (u32, Vec<Option<TileId>>) {
    let project = read_json(&example("dungeon.ldtk"));
    let set = &project["defs"]["tilesets"][0];
    let mut solid: Vec<i64> = set["enumTags"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|t| t["enumValueId"] == "Solid")
        .flat_map(|t| {
            t["tileIds"]
                .as_array()
                .unwrap()
                .iter()
                .map(|i| i.as_i64().unwrap())
        })
        .collect();
    for data in set["customData"].as_array().unwrap() {
        if data["data"].as_str().unwrap().contains("collision: solid") {
            solid.push(data["tileId"].as_i64().unwrap());
        }
    }
    let level = read_json(&example(&format!("dungeon/{room}.ldtkl")));
    let layer = &level["layerInstances"][1];
    let w = layer["__cWid"].as_u64().unwrap() as u32;
    let h = layer["__cHei"].as_u64().unwrap() as usize;
    let mut out = vec![None; w as usize * h];
    for tile in layer["gridTiles"].as_array().unwrap() {
        let (x, y) = (
            tile["px"][0].as_u64().unwrap(),
            tile["px"][1].as_u64().unwrap(),
        );
        let i = (y / 16) as usize * w as usize + (x / 16) as usize;
        out[i] = solid
            .contains(&tile["t"].as_i64().unwrap())
            .then_some(TileId(1));
    }
    (w, out)
}

#[test]
fn dungeon_rooms_block_where_their_tiles_are_tagged_solid() {
    let project = LdtkProject::load(example("dungeon.ldtk")).unwrap();
    for room in ["Entrance", "Crypt"] {
        let level = project
            .build(&LdtkOptions::default().with_level(room))
            .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(level.collision_layer, "Floor_and_walls");
        let (w, expected) = dungeon_expected(room);
        assert_eq!(level.map.width(), w);
        assert_eq!(cells(&level.map), expected, "{room}");
        assert!(level.int_grid_value(Cell::new(0, 0)).is_none());
    }
}

#[test]
fn a_game_maps_an_enum_tag_to_a_shape_of_its_own() {
    const WATER: TileId = TileId(100);
    let square = TileShape::polygon(&[
        Vec2::new(0.0, 0.0),
        Vec2::new(1.0, 0.0),
        Vec2::new(1.0, 1.0),
        Vec2::new(0.0, 1.0),
    ])
    .unwrap();
    let options = LdtkOptions::default()
        .with_name("Water", Collision::Tile(WATER))
        .with_tile_shape(WATER, square);
    let level = load("dungeon.ldtk", &options);
    // The pond of the entrance, at cells (11, 2) to (12, 3).
    assert_eq!(level.map.tile(Cell::new(11, 2)), Some(WATER));
    assert!(level.map.is_point_solid(Vec2::new(11.5 * 16.0, 2.5 * 16.0)));
    assert_eq!(Collision::of_tile_id(WATER), Collision::Tile(WATER));
    // Without the mapping, water blocks nothing.
    let plain = load("dungeon.ldtk", &LdtkOptions::default());
    assert_eq!(plain.map.tile(Cell::new(11, 2)), None);
}

#[test]
fn dungeon_levels_lie_one_after_the_other_and_their_entities_with_them() {
    let project = LdtkProject::load(example("dungeon.ldtk")).unwrap();
    let levels = project.levels();
    assert_eq!(levels[0].layout, WorldLayout::LinearHorizontal);
    assert_eq!(levels[0].world_position, Vec2::ZERO);
    assert_eq!(levels[1].world_position, Vec2::new(256.0 + 48.0, 0.0));
    assert_eq!(
        levels[1].external_file.as_deref(),
        Some("dungeon/Crypt.ldtkl")
    );
    let crypt = project
        .build(&LdtkOptions::default().with_level("Crypt"))
        .unwrap();
    assert_eq!(crypt.map.origin(), Vec2::new(304.0, 0.0));
    let spawns: Vec<_> = crypt
        .entity_layer("Entities")
        .unwrap()
        .entities_of("Spawn")
        .collect();
    assert_eq!(spawns.len(), 2);
    assert_eq!(
        spawns[0].position,
        Vec2::new(304.0 + 2.5 * 16.0, 3.5 * 16.0)
    );
    assert_eq!(
        spawns[1].field("team").and_then(FieldValue::as_str),
        Some("Monsters")
    );
    assert_eq!(
        spawns[1].field("count").and_then(FieldValue::as_int),
        Some(4)
    );
    assert_eq!(crypt.level_info().unwrap().identifier, "Crypt");
}

#[test]
fn level_files_given_in_memory_build_the_same_map() {
    let text = std::fs::read_to_string(example("dungeon.ldtk")).unwrap();
    let crypt = std::fs::read(example("dungeon/Crypt.ldtkl")).unwrap();
    let options = LdtkOptions::default()
        .with_level("Crypt")
        .with_file("dungeon/Crypt.ldtkl", crypt);
    let from_memory = ldtk::parse(&text, "nowhere/dungeon.ldtk", &options).unwrap();
    let from_disk = load("dungeon.ldtk", &LdtkOptions::default().with_level("Crypt"));
    assert_eq!(cells(&from_memory.map), cells(&from_disk.map));
    assert_eq!(from_memory.entity_layers, from_disk.entity_layers);
    // A file the project needs and the caller did not give: NotFound, naming what was given.
    let options = LdtkOptions::default().with_file("dungeon/Crypt.ldtkl", b"{}".to_vec());
    let e = ldtk::parse(&text, "nowhere/dungeon.ldtk", &options).unwrap_err();
    assert_eq!(e.io_error_kind(), Some(std::io::ErrorKind::NotFound));
    assert!(
        e.to_string()
            .contains("`dungeon/Entrance.ldtkl` is not among the files given"),
        "{e}"
    );
}

#[test]
fn loading_twice_gives_the_same_segments() {
    let a = load("platformer.ldtk", &LdtkOptions::default());
    let b = load("platformer.ldtk", &LdtkOptions::default());
    for row in 0..a.map.height() {
        for col in 0..a.map.width() {
            let cell = Cell::new(col, row);
            let sa: Vec<_> = a.map.active_segments(cell).collect();
            let sb: Vec<_> = b.map.active_segments(cell).collect();
            assert_eq!(format!("{sa:?}"), format!("{sb:?}"));
        }
    }
}

// ---------------------------------------------------------------- world layouts

/// A project of three levels of these sizes, with these stored positions.
fn three_levels(layout: &str, stored: [(i64, i64); 3]) -> LdtkProject {
    let sizes = [(64, 32), (32, 48), (16, 16)];
    let levels: Vec<Value> = (0..3)
        .map(|i| {
            json!({ "identifier": format!("L{i}"), "worldX": stored[i].0, "worldY": stored[i].1,
                "pxWid": sizes[i].0, "pxHei": sizes[i].1, "layerInstances": [
                    int_grid("g", sizes[i].0 / 16, sizes[i].1 / 16, 16,
                        &vec![1; (sizes[i].0 / 16 * sizes[i].1 / 16) as usize])] })
        })
        .collect();
    let text =
        json!({ "jsonVersion": "1.5.3", "worldLayout": layout, "levels": levels }).to_string();
    LdtkProject::parse(&text, "w.ldtk").unwrap()
}

#[test]
fn world_layouts_place_levels_as_ldtk_does() {
    let at =
        |p: &LdtkProject| -> Vec<Vec2> { p.levels().iter().map(|l| l.world_position).collect() };
    let stored = [(-64, 0), (256, -512), (1024, 768)];
    let grid = three_levels("GridVania", stored);
    assert_eq!(
        at(&grid),
        [
            Vec2::new(-64.0, 0.0),
            Vec2::new(256.0, -512.0),
            Vec2::new(1024.0, 768.0)
        ]
    );
    assert_eq!(at(&three_levels("Free", stored)), at(&grid));
    // The linear layouts ignore what is stored (LDtk writes -1) and lay levels out 48 apart.
    let horizontal = three_levels("LinearHorizontal", [(-1, -1); 3]);
    assert_eq!(
        at(&horizontal),
        [Vec2::ZERO, Vec2::new(112.0, 0.0), Vec2::new(192.0, 0.0)]
    );
    let vertical = three_levels("LinearVertical", stored);
    assert_eq!(
        at(&vertical),
        [Vec2::ZERO, Vec2::new(0.0, 80.0), Vec2::new(0.0, 176.0)]
    );
    // The map of a level is where the level is.
    let map = vertical
        .build(&LdtkOptions::default().with_level("L2"))
        .unwrap();
    assert_eq!(map.map.origin(), Vec2::new(0.0, 176.0));
    assert!(map.map.is_point_solid(Vec2::new(8.0, 184.0)));
}

#[test]
fn multi_world_projects_list_every_world_s_levels() {
    let level = |name: &str| {
        json!({ "identifier": name, "worldX": 0, "worldY": 0, "pxWid": 16, "pxHei": 16,
            "layerInstances": [int_grid("g", 1, 1, 16, &[1])] })
    };
    let text = json!({ "jsonVersion": "1.5.3", "flags": ["MultiWorlds"], "worldLayout": null,
        "levels": [], "worlds": [
            { "identifier": "Overworld", "worldLayout": "Free", "levels": [level("A")] },
            { "identifier": "Underworld", "worldLayout": "LinearVertical", "levels": [level("B"), level("C")] }
        ] })
    .to_string();
    let project = LdtkProject::parse(&text, "w.ldtk").unwrap();
    let names: Vec<_> = project
        .levels()
        .iter()
        .map(|l| (l.world.as_str(), l.identifier.as_str()))
        .collect();
    assert_eq!(
        names,
        [("Overworld", "A"), ("Underworld", "B"), ("Underworld", "C")]
    );
    assert_eq!(
        project.level("C").unwrap().world_position,
        Vec2::new(0.0, 64.0)
    );
    let c = project
        .build(&LdtkOptions::default().with_level("C"))
        .unwrap();
    assert_eq!(c.map.origin(), Vec2::new(0.0, 64.0));
}

// ---------------------------------------------------------------- layers and tiles

#[test]
fn the_default_layer_is_the_first_intgrid_and_layer_chooses_another() {
    let text = project_with(
        json!([
            { "__identifier": "Things", "__type": "Entities", "__cWid": 4, "__cHei": 2, "__gridSize": 16 },
            int_grid("Front", 4, 2, 16, &[1, 0, 0, 0, 0, 0, 0, 0]),
            int_grid("Back", 4, 2, 16, &[0, 0, 0, 1, 0, 0, 0, 0]),
        ]),
        json!({}),
    );
    let front = parse(&text, &LdtkOptions::default()).unwrap();
    assert_eq!(front.collision_layer, "Front");
    assert_eq!(front.map.tile(Cell::new(0, 0)), Some(ascii::SOLID));
    let back = parse(&text, &LdtkOptions::default().with_layer("Back")).unwrap();
    assert_eq!(back.map.tile(Cell::new(3, 0)), Some(ascii::SOLID));
    assert_eq!(back.map.tile(Cell::new(0, 0)), None);
}

#[test]
fn the_game_maps_values_by_number_before_their_names() {
    let defs = json!({ "layers": [{ "uid": 1, "intGridValues": [
        { "value": 1, "identifier": "walls" }, { "value": 2, "identifier": "ledge" },
        { "value": 3, "identifier": "One_way" }, { "value": 4 } ] }] });
    let text = project_with(json!([int_grid("g", 4, 1, 16, &[1, 2, 3, 4])]), defs);
    let plain = parse(&text, &LdtkOptions::default()).unwrap();
    assert_eq!(
        cells(&plain.map),
        [Some(ascii::SOLID), None, Some(ascii::ONE_WAY), None]
    );
    let options = LdtkOptions::default()
        .with_name("ledge", Collision::OneWay)
        .with_value(4, Collision::RampUpRight)
        .with_value(1, Collision::Empty)
        .with_name("One_way", Collision::Solid);
    let mapped = parse(&text, &options).unwrap();
    assert_eq!(
        cells(&mapped.map),
        [
            None,
            Some(ascii::ONE_WAY),
            Some(ascii::SOLID),
            Some(ascii::RAMP_UP_RIGHT)
        ]
    );
}

/// A tile layer of `tiles` (`[x, y, t, f]`) over a 4 × 2 grid, with a tile set of 16-pixel
/// tiles: tile 0 tagged `Ramp_up_right`, tile 1 with custom data `collision: one_way`.
fn tile_project(tiles: &[[i64; 4]], tileset: Value) -> String {
    let grid_tiles: Vec<Value> = tiles
        .iter()
        .map(|[x, y, t, f]| json!({ "px": [x, y], "src": [0, 0], "t": t, "f": f }))
        .collect();
    project_with(
        json!([{ "__identifier": "Art", "__type": "Tiles", "__cWid": 4, "__cHei": 2, "__gridSize": 16,
            "__tilesetDefUid": 7, "gridTiles": grid_tiles }]),
        json!({ "tilesets": [tileset] }),
    )
}

fn ramp_tiles() -> Value {
    json!({ "uid": 7, "identifier": "Ramps", "tileGridSize": 16,
        "enumTags": [{ "enumValueId": "Ramp_up_right", "tileIds": [0] }, { "enumValueId": "Grass", "tileIds": [0, 1] }],
        "customData": [{ "tileId": 1, "data": "collision: one_way" }, { "tileId": 2, "data": "a lamp" }] })
}

#[test]
fn flipped_tiles_are_mirrored_and_their_ids_say_so() {
    let text = tile_project(
        &[
            [0, 0, 0, 0],
            [16, 0, 0, 1],
            [32, 0, 0, 2],
            [48, 0, 1, 0],
            [0, 16, 2, 0],
            [16, 16, 0, 3],
        ],
        ramp_tiles(),
    );
    let level = parse(&text, &LdtkOptions::default()).unwrap();
    let up = ascii::RAMP_UP_RIGHT.0;
    assert_eq!(
        cells(&level.map),
        [
            Some(TileId(up)),
            Some(TileId(up | FLIP_X_BIT)),
            Some(TileId(up | FLIP_Y_BIT)),
            Some(ascii::ONE_WAY),
            None,
            Some(TileId(up | FLIP_X_BIT | FLIP_Y_BIT)),
            None,
            None,
        ]
    );
    // The ramp rises to the right; flipped in x it falls: a ray down the middle of each
    // meets its slope facing up-left, then up-right.
    let down = |x: f32| {
        let ray = Ray::between(Vec2::new(x, -4.0), Vec2::new(x, 12.0));
        level
            .map
            .cast_ray(ray, &QueryFilter::default())
            .unwrap()
            .normal
    };
    assert!(down(8.0).x < 0.0 && down(24.0).x > 0.0);
    // Flipped in y, its slope faces down: a ray from below meets it.
    let up_ray = Ray::between(Vec2::new(40.0, 15.0), Vec2::new(40.0, -4.0));
    let hit = level.map.cast_ray(up_ray, &QueryFilter::default()).unwrap();
    assert!(
        hit.normal.y > 0.0 && (hit.point.y - 8.0).abs() < 1e-4,
        "{hit:?}"
    );
}

#[test]
fn stacked_tiles_collide_by_the_top_one_that_names_a_shape() {
    // Cell (0, 0): the ramp, then a lamp over it (names nothing): still the ramp. Cell
    // (1, 0): the ramp, then the one-way over it: the one-way.
    let text = tile_project(
        &[[0, 0, 0, 0], [0, 0, 2, 0], [16, 0, 0, 0], [16, 0, 1, 0]],
        ramp_tiles(),
    );
    let level = parse(&text, &LdtkOptions::default()).unwrap();
    assert_eq!(level.map.tile(Cell::new(0, 0)), Some(ascii::RAMP_UP_RIGHT));
    assert_eq!(level.map.tile(Cell::new(1, 0)), Some(ascii::ONE_WAY));
}

// ---------------------------------------------------------------- errors

#[test]
fn malformed_json_names_the_line_and_column() {
    let text = project_with(json!([int_grid("g", 1, 1, 16, &[1])]), json!({}));
    let cut = &text[..text.len() / 2];
    let e = parse(cut, &LdtkOptions::default()).unwrap_err();
    assert!(
        matches!(
            e.kind,
            LoadErrorKind::Syntax {
                truncated: true,
                ..
            }
        ),
        "{e}"
    );
    assert!(
        matches!(e.location, Location::LineColumn { line: 1, .. }),
        "{e}"
    );
    assert!(e.to_string().starts_with("test.ldtk:1:"), "{e}");
}

#[test]
fn a_value_of_the_wrong_type_names_its_json_path() {
    let text = project_with(json!([int_grid("g", 2, 1, 16, &[1, 0])]), json!({}));
    let bad = text.replace("\"__gridSize\":16", "\"__gridSize\":\"16\"");
    assert_ne!(bad, text);
    let e = parse(&bad, &LdtkOptions::default()).unwrap_err();
    let (path, why) = fault(&e);
    assert_eq!(path, "levels[0].layerInstances[0].__gridSize");
    assert!(
        matches!(why, LdtkFault::Schema(m) if m.contains("expected i64")),
        "{e}"
    );
    assert!(matches!(e.location, Location::LineColumn { line: 1, .. }));
    // A missing field names the object that lacks it.
    let e = parse(&text.replace("\"pxWid\":64,", ""), &LdtkOptions::default()).unwrap_err();
    assert_eq!(fault(&e).0, "levels[0]");
    assert!(e.to_string().contains("missing field `pxWid`"), "{e}");
}

#[test]
fn an_unknown_level_or_layer_lists_the_names_there_are() {
    let e = ldtk::load(
        example("dungeon.ldtk"),
        &LdtkOptions::default().with_level("Attic"),
    )
    .unwrap_err();
    assert_eq!(
        e.to_string(),
        format!(
            "{}: levels: the project has no level \"Attic\" (its levels: \"Entrance\", \"Crypt\")",
            example("dungeon.ldtk").display()
        )
    );
    assert!(matches!(fault(&e).1, LdtkFault::UnknownLevel { levels, .. } if levels.len() == 2));
    let e = ldtk::load(
        example("platformer.ldtk"),
        &LdtkOptions::default().with_layer("Entities"),
    )
    .unwrap_err();
    let (path, f) = fault(&e);
    assert_eq!(path, "levels[0].layerInstances");
    assert_eq!(
        f.to_string(),
        "level \"Meadow\" has no IntGrid, auto-layer or tile layer \"Entities\" (its layers: \"Collisions\")"
    );
    // A level with no layer that can collide says so, listing its layers.
    let text = project_with(
        json!([{ "__identifier": "Things", "__type": "Entities", "__cWid": 1, "__cHei": 1, "__gridSize": 16 }]),
        json!({}),
    );
    let e = parse(&text, &LdtkOptions::default()).unwrap_err();
    assert!(
        matches!(fault(&e).1, LdtkFault::NoCollisionLayer { layers, .. } if layers == &["Things"]),
        "{e}"
    );
    let e = parse(
        &json!({ "levels": [] }).to_string(),
        &LdtkOptions::default(),
    )
    .unwrap_err();
    assert!(matches!(fault(&e).1, LdtkFault::NoLevels));
}

#[test]
fn absurd_sizes_are_refused_before_allocating() {
    // 2^20 × 2^20 cells, declared with a one-value CSV: refused by size, not by count.
    let huge = project_with(
        json!([int_grid("g", 1 << 20, 1 << 20, 16, &[1])]),
        json!({}),
    );
    let e = parse(&huge, &LdtkOptions::default()).unwrap_err();
    let (path, f) = fault(&e);
    assert_eq!(path, "levels[0].layerInstances[0].__cWid");
    assert!(
        matches!(
            f,
            LdtkFault::Size {
                field: "__cWid × __cHei",
                ..
            }
        ),
        "{e}"
    );
    // The largest sizes a layer can declare: the product is named, not overflowed.
    let most = i64::from(u32::MAX);
    let widest = project_with(json!([int_grid("g", most, most, 16, &[1])]), json!({}));
    let e = parse(&widest, &LdtkOptions::default()).unwrap_err();
    assert!(
        matches!(
            fault(&e).1,
            LdtkFault::Size {
                value: i64::MAX,
                ..
            }
        ),
        "{e}"
    );
    // Below the crate's limit, but above the game's.
    let small = project_with(json!([int_grid("g", 8, 8, 16, &[0; 64])]), json!({}));
    let e = parse(&small, &LdtkOptions::default().with_max_cells(63)).unwrap_err();
    assert!(e.to_string().contains("raise it to load this level"), "{e}");
    for grid in [0, -16, 1 << 40] {
        let text = project_with(json!([int_grid("g", 1, 1, grid, &[1])]), json!({}));
        let e = parse(&text, &LdtkOptions::default()).unwrap_err();
        assert!(
            matches!(fault(&e), (p, LdtkFault::Size { field: "__gridSize", .. }) if p.ends_with("__gridSize")),
            "{e}"
        );
    }
    for cwid in [0, -3, 1 << 40] {
        let text = project_with(json!([int_grid("g", cwid, 1, 16, &[1])]), json!({}));
        let e = parse(&text, &LdtkOptions::default()).unwrap_err();
        assert!(matches!(fault(&e).1, LdtkFault::Size { .. }), "{e}");
    }
    let wide = json!({ "levels": [{ "identifier": "W", "pxWid": 1i64 << 40, "pxHei": 16, "layerInstances": [] }] });
    let e = parse(&wide.to_string(), &LdtkOptions::default()).unwrap_err();
    assert_eq!(fault(&e).0, "levels[0].pxWid");
}

#[test]
fn an_intgrid_of_the_wrong_length_or_with_negative_values_is_refused() {
    let text = project_with(json!([int_grid("g", 2, 2, 16, &[1, 0, 1])]), json!({}));
    let e = parse(&text, &LdtkOptions::default()).unwrap_err();
    assert_eq!(fault(&e).0, "levels[0].layerInstances[0].intGridCsv");
    assert_eq!(
        *fault(&e).1,
        LdtkFault::CellCount {
            found: 3,
            expected: 4
        }
    );
    let text = project_with(json!([int_grid("g", 2, 1, 16, &[1, -2])]), json!({}));
    let e = parse(&text, &LdtkOptions::default()).unwrap_err();
    assert_eq!(fault(&e).0, "levels[0].layerInstances[0].intGridCsv[1]");
    assert_eq!(*fault(&e).1, LdtkFault::NegativeValue(-2));
}

#[test]
fn tiles_off_the_grid_or_naming_two_shapes_are_refused() {
    let e = parse(
        &tile_project(&[[8, 0, 0, 0]], ramp_tiles()),
        &LdtkOptions::default(),
    )
    .unwrap_err();
    assert_eq!(fault(&e).0, "levels[0].layerInstances[0].gridTiles[0]");
    assert!(matches!(fault(&e).1, LdtkFault::TileOffGrid { x: 8, .. }));
    let e = parse(
        &tile_project(&[[64, 0, 0, 0]], ramp_tiles()),
        &LdtkOptions::default(),
    )
    .unwrap_err();
    assert!(
        matches!(fault(&e).1, LdtkFault::TileOffGrid { x: 64, .. }),
        "{e}"
    );
    let mut two = ramp_tiles();
    two["customData"][0]["tileId"] = json!(0);
    let e = parse(&tile_project(&[[0, 0, 0, 0]], two), &LdtkOptions::default()).unwrap_err();
    assert_eq!(fault(&e).0, "defs.tilesets[0].customData[0]");
    assert_eq!(
        fault(&e).1.to_string(),
        "tile 0 of tile set \"Ramps\" names two collision shapes, \"Ramp_up_right\" and \"one_way\""
    );
    let mut unknown = ramp_tiles();
    unknown["customData"][0]["data"] = json!("collision: slippery");
    let e = parse(
        &tile_project(&[[0, 0, 1, 0]], unknown),
        &LdtkOptions::default(),
    )
    .unwrap_err();
    assert!(
        matches!(fault(&e).1, LdtkFault::UnknownShape { name, .. } if name == "slippery"),
        "{e}"
    );
    let mut big = ramp_tiles();
    big["tileGridSize"] = json!(32);
    let e = parse(&tile_project(&[[0, 0, 0, 0]], big), &LdtkOptions::default()).unwrap_err();
    assert!(
        matches!(fault(&e).1, LdtkFault::TileSize { tile_size: 32, .. }),
        "{e}"
    );
    let e = parse(
        &tile_project(&[], json!({ "uid": 8, "tileGridSize": 16 })),
        &LdtkOptions::default().with_layer("Art"),
    )
    .unwrap_err();
    assert!(
        matches!(fault(&e).1, LdtkFault::UnknownUid { uid: 7, .. }),
        "{e}"
    );
}

#[test]
fn a_game_tile_without_a_shape_or_out_of_range_is_refused() {
    let text = project_with(json!([int_grid("g", 1, 1, 16, &[1])]), json!({}));
    let e = parse(
        &text,
        &LdtkOptions::default().with_value(1, Collision::Tile(TileId(40))),
    )
    .unwrap_err();
    assert!(
        matches!(&e.kind, LoadErrorKind::Parameter(m) if m.contains("no shape")),
        "{e}"
    );
    let e = parse(
        &text,
        &LdtkOptions::default().with_value(1, Collision::Tile(TileId(2))),
    )
    .unwrap_err();
    assert!(
        matches!(&e.kind, LoadErrorKind::Parameter(m) if m.contains("out of range")),
        "{e}"
    );
}

/// A project in its own folder under the test's scratch space, with a level file.
fn scratch_project(name: &str, rel: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("loader_ldtk")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("levels")).unwrap();
    let level = json!({ "identifier": "One", "pxWid": 16, "pxHei": 16, "layerInstances": [int_grid("g", 1, 1, 16, &[1])] });
    std::fs::write(dir.join("levels/One.ldtkl"), level.to_string()).unwrap();
    let project = json!({ "levels": [{ "identifier": "One", "pxWid": 16, "pxHei": 16,
        "externalRelPath": rel, "layerInstances": null }] });
    let path = dir.join("project.ldtk");
    std::fs::write(&path, project.to_string()).unwrap();
    path
}

#[test]
fn level_files_are_read_inside_the_project_folder_only() {
    let ok = ldtk::load(
        scratch_project("inside", "levels/One.ldtkl"),
        &LdtkOptions::default(),
    )
    .unwrap();
    assert_eq!(ok.map.tile(Cell::new(0, 0)), Some(ascii::SOLID));
    for (name, rel, why) in [
        ("absolute", "/etc/hostname", "an absolute path"),
        (
            "climbs",
            "levels/../../inside/levels/One.ldtkl",
            "\"..\" climbs above the folder",
        ),
    ] {
        let e = ldtk::load(scratch_project(name, rel), &LdtkOptions::default()).unwrap_err();
        assert_eq!(fault(&e).0, "levels[0].externalRelPath");
        assert_eq!(
            *fault(&e).1,
            LdtkFault::OutsideProject {
                path: rel.into(),
                why
            }
        );
    }
    let e = ldtk::load(
        scratch_project("missing", "levels/Two.ldtkl"),
        &LdtkOptions::default(),
    )
    .unwrap_err();
    assert_eq!(e.io_error_kind(), Some(std::io::ErrorKind::NotFound));
    assert!(
        matches!(&e.kind, LoadErrorKind::Io { referenced: Some(p), .. } if p.ends_with("levels/Two.ldtkl")),
        "{e}"
    );
    // A file of another level.
    let path = scratch_project("swapped", "levels/One.ldtkl");
    let text = std::fs::read_to_string(&path)
        .unwrap()
        .replace("\"One\"", "\"Uno\"");
    std::fs::write(&path, text).unwrap();
    let e = ldtk::load(&path, &LdtkOptions::default()).unwrap_err();
    assert!(
        matches!(fault(&e).1, LdtkFault::WrongLevelFile { .. }),
        "{e}"
    );
    assert!(e.path.ends_with("levels/One.ldtkl"));
}

#[cfg(unix)]
#[test]
fn a_symbolic_link_out_of_the_folder_is_not_followed() {
    let path = scratch_project("linked", "out/One.ldtkl");
    let dir = path.parent().unwrap();
    let elsewhere = scratch_project("elsewhere", "levels/One.ldtkl");
    std::os::unix::fs::symlink(elsewhere.parent().unwrap().join("levels"), dir.join("out"))
        .unwrap();
    let e = ldtk::load(&path, &LdtkOptions::default()).unwrap_err();
    assert!(
        matches!(
            fault(&e).1,
            LdtkFault::OutsideProject {
                why: "a symbolic link leads out",
                ..
            }
        ),
        "{e}"
    );
    // And the project's resolver refuses the same.
    let project = LdtkProject::load(&path).unwrap();
    assert!(project.resolve("out/One.ldtkl").is_err());
    assert!(
        project
            .resolve("levels/One.ldtkl")
            .unwrap()
            .ends_with("levels/One.ldtkl")
    );
}

// ---------------------------------------------------------------- random layers

proptest! {
    /// A random IntGrid layer builds the cells its CSV says, read independently: value 1
    /// solid, a value named after a shape that shape, others empty; and the values come
    /// back as they were.
    #[test]
    fn random_intgrid_csvs_round_trip(
        (w, h, csv) in (1i64..12, 1i64..12).prop_flat_map(|(w, h)| {
            (Just(w), Just(h), proptest::collection::vec(0i64..5, (w * h) as usize))
        }),
        grid in prop_oneof![Just(8i64), Just(16), Just(24)],
        origin in (-4i64..4, -4i64..4),
    ) {
        let defs = json!({ "layers": [{ "uid": 1, "intGridValues": [
            { "value": 2, "identifier": "One_way" }, { "value": 3, "identifier": "lava" } ] }] });
        let text = json!({ "worldLayout": "GridVania", "defs": defs, "levels": [{
            "identifier": "R", "worldX": origin.0 * 256, "worldY": origin.1 * 256,
            "pxWid": w * grid, "pxHei": h * grid,
            "layerInstances": [int_grid("g", w, h, grid, &csv)] }] }).to_string();
        let level = parse(&text, &LdtkOptions::default()).unwrap();
        let expected: Vec<Option<TileId>> = csv.iter().map(|v| match v {
            1 => Some(TileId(1)),
            2 => Some(TileId(4)),
            _ => None,
        }).collect();
        prop_assert_eq!(cells(&level.map), expected);
        prop_assert_eq!(level.map.origin(), Vec2::new((origin.0 * 256) as f32, (origin.1 * 256) as f32));
        for (i, v) in csv.iter().enumerate() {
            let cell = Cell::new((i as i64 % w) as u32, (i as i64 / w) as u32);
            prop_assert_eq!(level.int_grid_value(cell), Some(*v));
        }
    }

    /// Random edits of the example project give a level or an error, never a panic.
    #[test]
    fn mutated_projects_never_panic(
        edits in proptest::collection::vec((any::<prop::sample::Index>(), any::<u8>()), 1..8),
        cut in any::<prop::sample::Index>(),
    ) {
        let mut bytes = std::fs::read(example("platformer.ldtk")).unwrap();
        for (at, byte) in edits {
            let i = at.index(bytes.len());
            bytes[i] = b"0123456789-.e\"[]{},:1 tnulf"[byte as usize % 27];
        }
        if cut.index(4) == 0 {
            bytes.truncate(cut.index(bytes.len()));
        }
        if let Ok(text) = std::str::from_utf8(&bytes) {
            let _ = ldtk::parse(text, example("platformer.ldtk"), &LdtkOptions::default());
        }
    }
}

#[test]
fn projects_and_levels_can_move_between_threads() {
    // Engines load assets on worker threads and share them: a project and a built level
    // are `Send + Sync + 'static`.
    fn shared<T: Send + Sync + 'static>() {}
    shared::<LdtkProject>();
    shared::<LdtkMap>();
    shared::<LdtkOptions>();
    shared::<LoadError>();
}
