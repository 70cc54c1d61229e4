//! The `tileslide` commands on Tiled maps: `info`, `raycast` and `bake` read the example
//! `.tmx` and `.tmj` maps, and the two formats of one map give the same answers.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::{Path, PathBuf};

use serde_json::Value;
use support::{example, scratch_in, stderr, stdout, tileslide};

mod support;

fn scratch(name: &str, contents: &str) -> PathBuf {
    scratch_in("cli_tiled", name, contents)
}

/// `info --json`, without the fields that name the file and its format.
fn info(map: &str) -> Value {
    let o = tileslide(&["info", map, "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let mut v: Value = serde_json::from_str(&stdout(&o)).unwrap();
    let object = v.as_object_mut().unwrap();
    object.remove("map");
    object.remove("format");
    v
}

/// Rays through the cave, in its pixels (y down), with what each must hit.
const CAVE_RAYS: &str = "\
# Down onto the floor at x = 40: y = 224.
40,20,40,300
# Down onto the one-way ledge (cells 14-17 of row 4): y = 64.
232,20,232,200
# Up through the ledge: it does not block; the ceiling does, at y = 16.
232,100,232,0
# Down onto the hill's left ramp: its slope at (184, 200).
184,150,184,230
# Right into the fence at x = 120.
60,120,200,120
# Down onto the spikes: the valley between their two tips, at (376, 204).
376,150,376,300
";

#[test]
fn info_is_the_same_for_the_tmx_and_tmj_of_a_map() {
    for name in ["cave", "dungeon"] {
        let tmx = info(&example(&format!("{name}.tmx")));
        let tmj = info(&example(&format!("{name}.tmj")));
        assert_eq!(tmx, tmj, "{name}");
    }
    let cave = info(&example("cave.tmx"));
    assert_eq!(
        (cave["width"].as_u64(), cave["height"].as_u64()),
        (Some(30), Some(16))
    );
    assert_eq!(cave["cell_size"], serde_json::json!([16.0, 16.0]));
    // The infinite dungeon: its chunks' bounding box, origin at the top-left chunk.
    let dungeon = info(&example("dungeon.tmj"));
    assert_eq!(dungeon["origin"], serde_json::json!([-256.0, -256.0]));
    assert_eq!(
        (dungeon["width"].as_u64(), dungeon["height"].as_u64()),
        (Some(48), Some(32))
    );
}

#[test]
fn info_names_the_tiled_formats() {
    for (file, format) in [("cave.tmx", "tiled-tmx"), ("cave.tmj", "tiled-tmj")] {
        let o = tileslide(&["info", &example(file), "--json"]);
        assert!(o.status.success(), "{}", stderr(&o));
        let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
        assert_eq!(v["format"], format);
    }
    let o = tileslide(&["info", &example("cave.tmx")]);
    assert!(stdout(&o).contains("(tiled-tmx)") && stdout(&o).contains("30 × 16 cells of 16 × 16"));
}

#[test]
fn raycast_gives_the_same_hits_on_both_formats() {
    let rays = scratch("cave_rays.csv", CAVE_RAYS);
    let run = |map: &str| {
        let o = tileslide(&["raycast", map, "--rays", rays.to_str().unwrap(), "--json"]);
        assert!(o.status.success(), "{}", stderr(&o));
        stdout(&o)
    };
    let tmx = run(&example("cave.tmx"));
    let tmj = run(&example("cave.tmj"));
    assert_eq!(tmx, tmj);
    let hits: Vec<Value> = tmx
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(hits.len(), 6);
    let at = |i: usize| {
        (
            hits[i]["x"].as_f64().unwrap(),
            hits[i]["y"].as_f64().unwrap(),
        )
    };
    assert_eq!(at(0), (40.0, 224.0));
    assert_eq!(
        (hits[0]["nx"].as_f64(), hits[0]["ny"].as_f64()),
        (Some(0.0), Some(-1.0))
    );
    assert_eq!(at(1), (232.0, 64.0));
    assert_eq!(at(2), (232.0, 16.0));
    assert_eq!(at(3), (184.0, 200.0));
    assert_eq!(at(4), (120.0, 120.0));
    assert_eq!(at(5), (376.0, 204.0));
    assert!(hits.iter().all(|h| h["hit"] == true));
    // The dungeon too.
    let door = |map: &str| {
        let o = tileslide(&[
            "raycast", map, "--from", "200,-168", "--to", "300,-168", "--json",
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        stdout(&o)
    };
    let tmx = door(&example("dungeon.tmx"));
    assert_eq!(tmx, door(&example("dungeon.tmj")));
    let hit: Value = serde_json::from_str(tmx.trim()).unwrap();
    assert_eq!(
        (hit["x"].as_f64(), hit["tile"].as_u64()),
        (Some(262.0), Some(9))
    );
}

#[test]
fn layer_chooses_the_collision_layer() {
    // The background layer holds only moss, which blocks nothing.
    let o = tileslide(&[
        "raycast",
        &example("cave.tmx"),
        "--from",
        "40,20",
        "--to",
        "40,300",
        "--layer",
        "background",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).contains("no hit"), "{}", stdout(&o));
    let o = tileslide(&["info", &example("cave.tmj"), "--layer", "lava"]);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("the map has no tile layer named \"lava\""),
        "{}",
        stderr(&o)
    );
    // --layer is for Tiled maps only, and Tiled maps refuse --cell and --tileset.
    let o = tileslide(&["info", &example("cave.txt"), "--layer", "walls"]);
    assert!(stderr(&o).contains("--layer chooses the collision layer of a Tiled map"));
    let o = tileslide(&["info", &example("cave.tmx"), "--cell", "2"]);
    assert!(
        stderr(&o).contains("drop --tileset and --cell"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn bake_reads_tiled_maps() {
    let out = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("cli_tiled")
        .join("cave.tsm");
    std::fs::create_dir_all(out.parent().unwrap()).unwrap();
    let o = tileslide(&["bake", &example("cave.tmx"), "-o", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(info(out.to_str().unwrap()), info(&example("cave.tmx")));
}

#[test]
fn a_broken_tiled_map_is_named_with_line_and_column() {
    let map = scratch(
        "broken.tmx",
        "<map version=\"1.10\" orientation=\"isometric\" width=\"2\" height=\"1\" \
         tilewidth=\"16\" tileheight=\"16\">\n</map>\n",
    );
    let o = tileslide(&["info", map.to_str().unwrap()]);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains(&format!(
            "{}:1:1: orientation \"isometric\" is not supported",
            map.display()
        )),
        "{}",
        stderr(&o)
    );
    let map = scratch(
        "cut.tmj",
        "{\n \"orientation\": \"orthogonal\",\n \"width\": 2,",
    );
    let o = tileslide(&["info", map.to_str().unwrap()]);
    assert!(
        stderr(&o).contains(&format!("{}:3:13: truncated JSON", map.display())),
        "{}",
        stderr(&o)
    );
}

#[test]
fn simulate_runs_a_scene_on_a_tiled_map_in_either_format() {
    let mut outputs = Vec::new();
    for name in ["cave.tmx", "cave.tmj"] {
        let scene = scratch(
            &format!("scene_{name}.json"),
            &format!(
                r#"{{"map": {:?}, "steps": 30, "bodies": [
                    {{"x": 40, "y": 40, "r": 5, "vx": 3, "vy": 2}},
                    {{"x": 100, "y": 40, "r": 5, "vx": -3, "vy": 2}}]}}"#,
                example(name)
            ),
        );
        let o = tileslide(&["simulate", scene.to_str().unwrap(), "--json"]);
        assert!(o.status.success(), "{}", stderr(&o));
        let v: Value = serde_json::from_str(stdout(&o).trim()).unwrap();
        assert_eq!(v["audit"]["overlapping_pairs"], 0);
        assert_eq!(v["audit"]["wall_penetrations"], 0);
        outputs.push(v["bodies"].clone());
    }
    assert_eq!(outputs[0], outputs[1]);
    // A Tiled map takes no cell size.
    let scene = scratch(
        "scene_cell.json",
        &format!(
            r#"{{"map": {:?}, "cell": 2, "bodies": []}}"#,
            example("cave.tmx")
        ),
    );
    let o = tileslide(&["simulate", scene.to_str().unwrap()]);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("drop --tileset and --cell"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn a_tiled_json_map_named_json_loads_and_other_json_is_named() {
    // Tiled saves JSON maps as `.json` as often as `.tmj`: the same cave, renamed, beside
    // its tile set.
    scratch(
        "tiles.tsj",
        &std::fs::read_to_string(example("tiles.tsj")).unwrap(),
    );
    let cave = scratch(
        "cave.json",
        &std::fs::read_to_string(example("cave.tmj")).unwrap(),
    );
    assert_eq!(info(cave.to_str().unwrap()), info(&example("cave.tmj")));
    // A Tiled tile set saved as `.json` is not a map, and the error says what it is.
    let set = scratch(
        "tileset.json",
        &std::fs::read_to_string(example("tiles.tsj")).unwrap(),
    );
    let o = tileslide(&["info", set.to_str().unwrap()]);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains(&format!(
            "{}: a Tiled tile set (\"type\": \"tileset\"), not a map",
            set.display()
        )),
        "{}",
        stderr(&o)
    );
    // Any other JSON (here a scene file) is not a map either.
    let scene = scratch("scene_as_map.json", r#"{"map": "cave.txt", "bodies": []}"#);
    let o = tileslide(&["info", scene.to_str().unwrap()]);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("not a Tiled JSON map"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn layer_chooses_between_layers_that_share_a_name() {
    // Two tile layers named "walls": a block at cell 0, then a block at cell 1.
    scratch(
        "tiles.tsj",
        &std::fs::read_to_string(example("tiles.tsj")).unwrap(),
    );
    let map = scratch(
        "same_names.tmj",
        r#"{"type": "map", "orientation": "orthogonal", "width": 2, "height": 1,
            "tilewidth": 16, "tileheight": 16,
            "tilesets": [{"firstgid": 1, "source": "tiles.tsj"}],
            "layers": [
              {"type": "tilelayer", "name": "walls", "width": 2, "height": 1, "data": [1, 0]},
              {"type": "tilelayer", "name": "walls", "width": 2, "height": 1, "data": [0, 1]}]}"#,
    );
    let hit_x = |layer: &str| {
        let o = tileslide(&[
            "raycast",
            map.to_str().unwrap(),
            "--from",
            "40,8",
            "--to",
            "-10,8",
            "--layer",
            layer,
            "--json",
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        let hit: Value = serde_json::from_str(stdout(&o).trim()).unwrap();
        hit["x"].as_f64()
    };
    assert_eq!(hit_x("walls"), Some(16.0));
    assert_eq!(hit_x("walls#2"), Some(32.0));
    assert_eq!(hit_x("#2"), Some(32.0));
    let o = tileslide(&["info", map.to_str().unwrap(), "--layer", "walls#3"]);
    assert!(
        stderr(&o).contains("the map has 2 tile layers named \"walls\", so no \"walls#3\""),
        "{}",
        stderr(&o)
    );
}

#[test]
fn load_limits_refuse_far_apart_chunks_until_raised() {
    // Two one-cell chunks 1024 cells apart: 1025² cells, two of them drawn.
    let map = scratch(
        "far.tmj",
        r#"{"type": "map", "orientation": "orthogonal", "infinite": true, "width": 1,
            "height": 1, "tilewidth": 16, "tileheight": 16,
            "tilesets": [{"firstgid": 1, "name": "t", "tilewidth": 16, "tileheight": 16,
              "tilecount": 1}],
            "layers": [{"type": "tilelayer", "name": "l", "width": 1, "height": 1, "chunks": [
              {"x": 0, "y": 0, "width": 1, "height": 1, "data": [1]},
              {"x": 1024, "y": 1024, "width": 1, "height": 1, "data": [1]}]}]}"#,
    );
    let map = map.to_str().unwrap();
    let o = tileslide(&["info", map]);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("raise `max_chunk_spread`"),
        "{}",
        stderr(&o)
    );
    let o = tileslide(&["info", map, "--max-chunk-spread", "1000000", "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(v["width"], 1025);
    let o = tileslide(&[
        "info",
        map,
        "--max-chunk-spread",
        "1000000",
        "--max-cells",
        "1000",
    ]);
    assert!(
        stderr(&o).contains("more than 1000 cells"),
        "{}",
        stderr(&o)
    );
    let o = tileslide(&["info", &example("cave.txt"), "--max-cells", "10"]);
    assert!(
        stderr(&o).contains("--max-cells bounds Tiled maps"),
        "{}",
        stderr(&o)
    );
}
