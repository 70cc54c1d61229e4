//! The `tileslide` commands on LDtk projects: every command that takes a MAP reads the
//! example `.ldtk` projects, with `--level` and `--layer`, and refuses `--level` elsewhere.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use serde_json::Value;
use support::{example, scratch_in, stderr, stdout, tileslide};

mod support;

fn platformer() -> String {
    example("ldtk/platformer.ldtk")
}

fn dungeon() -> String {
    example("ldtk/dungeon.ldtk")
}

/// `info --json` of `args`.
fn info(args: &[&str]) -> Value {
    let mut all = vec!["info"];
    all.extend_from_slice(args);
    all.push("--json");
    let o = tileslide(&all);
    assert!(o.status.success(), "{}", stderr(&o));
    serde_json::from_str(&stdout(&o)).unwrap()
}

#[test]
fn info_reads_a_level_of_an_ldtk_project() {
    let p = platformer();
    let v = info(&[&p]);
    assert_eq!(v["format"], "ldtk");
    assert_eq!(
        (v["width"].as_u64(), v["height"].as_u64()),
        (Some(60), Some(20))
    );
    assert_eq!(v["cell_size"], serde_json::json!([16.0, 16.0]));
    assert_eq!(v["tiles_used"], 8);
    // The dungeon's second room lies after the first, 48 pixels apart.
    let d = dungeon();
    let crypt = info(&[&d, "--level", "Crypt"]);
    assert_eq!(crypt["origin"], serde_json::json!([304.0, 0.0]));
    assert_eq!(
        (crypt["width"].as_u64(), crypt["height"].as_u64()),
        (Some(20), Some(12))
    );
    let entrance = info(&[&d]);
    assert_eq!(entrance["origin"], serde_json::json!([0.0, 0.0]));
    let o = tileslide(&["info", &p]);
    assert!(stdout(&o).contains("(ldtk)") && stdout(&o).contains("60 × 20 cells of 16 × 16"));
}

#[test]
fn raycast_hits_the_ground_ramps_and_one_way_platforms() {
    let rays = scratch_in(
        "cli_ldtk",
        "rays.csv",
        "# the ground below the start\n40,8,40,400\n# the one-way ledge\n120,8,120,400\n# up through it\n120,260,120,8\n",
    );
    let o = tileslide(&[
        "raycast",
        &platformer(),
        "--rays",
        rays.to_str().unwrap(),
        "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let hits: Vec<Value> = stdout(&o)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    let y = |i: usize| hits[i]["y"].as_f64();
    assert_eq!((y(0), y(1)), (Some(272.0), Some(208.0)));
    assert_eq!(hits[1]["tile"], 4);
    assert_eq!(hits[2]["hit"], false);
}

#[test]
fn layer_and_level_choose_and_unknown_names_are_listed() {
    let o = tileslide(&["info", &dungeon(), "--level", "Attic"]);
    assert!(!o.status.success());
    assert!(
        stderr(&o)
            .contains("the project has no level \"Attic\" (its levels: \"Entrance\", \"Crypt\")"),
        "{}",
        stderr(&o)
    );
    let o = tileslide(&["info", &platformer(), "--layer", "Decor"]);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("levels[0].layerInstances: level \"Meadow\" has no IntGrid, auto-layer or tile layer \"Decor\" (its layers: \"Collisions\")"),
        "{}",
        stderr(&o)
    );
    let v = info(&[&platformer(), "--layer", "Collisions"]);
    assert_eq!(v["tiles_used"], 8);
    // --level is for LDtk projects only, as --layer is for Tiled maps and LDtk projects.
    for map in [example("cave.tmx"), example("cave.txt")] {
        let o = tileslide(&["info", &map, "--level", "Meadow"]);
        assert!(!o.status.success());
        assert!(
            stderr(&o).contains("--level chooses the level of an LDtk project (.ldtk); drop it"),
            "{}",
            stderr(&o)
        );
    }
    let o = tileslide(&["info", &example("cave.txt"), "--layer", "walls"]);
    assert!(
        stderr(&o).contains("or an LDtk project (.ldtk); drop it"),
        "{}",
        stderr(&o)
    );
    let o = tileslide(&["info", &platformer(), "--cell", "8"]);
    assert!(
        stderr(&o).contains("drop --tileset and --cell"),
        "{}",
        stderr(&o)
    );
    let o = tileslide(&["info", &platformer(), "--max-chunk-spread", "8"]);
    assert!(
        stderr(&o).contains("--max-chunk-spread bounds infinite Tiled maps"),
        "{}",
        stderr(&o)
    );
    let o = tileslide(&["info", &platformer(), "--max-cells", "1000"]);
    assert!(
        stderr(&o).contains("is more than 1000 cells"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn path_render_bake_and_explain_take_an_ldtk_level() {
    let o = tileslide(&[
        "path",
        &dungeon(),
        "--from",
        "40,168",
        "--to",
        "200,200",
        "--radius",
        "5",
        "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let path: Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(path["found"], true, "{path}");
    let png = scratch_in("cli_ldtk", "crypt.png", "");
    let o = tileslide(&[
        "render",
        &dungeon(),
        "--level",
        "Crypt",
        "-o",
        png.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(std::fs::read(&png).unwrap().starts_with(b"\x89PNG"));
    // A baked level is the same map.
    let tsm = scratch_in("cli_ldtk", "crypt.tsm", "");
    let o = tileslide(&[
        "bake",
        &dungeon(),
        "--level",
        "Crypt",
        "-o",
        tsm.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let mut baked = info(&[tsm.to_str().unwrap()]);
    let mut source = info(&[&dungeon(), "--level", "Crypt"]);
    for v in [&mut baked, &mut source] {
        let o = v.as_object_mut().unwrap();
        o.remove("map");
        o.remove("format");
    }
    assert_eq!(baked, source);
    let o = tileslide(&["explain", &platformer(), "--cell", "14,16", "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).contains("\"tile\":2"), "{}", stdout(&o));
    let o = tileslide(&["explain", &dungeon(), "--cell", "0,4", "--level", "Crypt"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stdout(&o).starts_with("cell (0, 4): tile 1"),
        "{}",
        stdout(&o)
    );
}

#[test]
fn simulate_reads_a_scene_on_an_ldtk_level() {
    let scene = scratch_in(
        "cli_ldtk",
        "scene.json",
        &format!(
            r#"{{ "map": {:?}, "level": "Entrance", "steps": 20,
                 "bodies": [{{ "x": 40, "y": 168, "r": 5, "vx": -4, "vy": 0 }}] }}"#,
            dungeon()
        ),
    );
    let o = tileslide(&["simulate", scene.to_str().unwrap(), "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
    // It walks left into the wall of column 0 and stops against it.
    let x = v["bodies"][0]["x"].as_f64().unwrap();
    assert!((x - 21.0).abs() < 0.01, "{v}");
}
