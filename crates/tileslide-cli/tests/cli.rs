//! The `tileslide` command line as a user runs it: outputs, JSON formats, and errors that
//! name what and where.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::PathBuf;

use serde_json::Value;
use support::{replica_dir, stderr, stdout, tileslide};

mod support;

fn scratch(name: &str, contents: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("tileslide-cli-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, contents).unwrap();
    path
}

const ROOM: &str = "\
; a room with a ramp and a one-way ledge
########
#......#
#..=...#
#...../#
########
";

#[test]
fn info_json_reports_size_tiles_and_segments() {
    let map = scratch("info.txt", ROOM);
    let o = tileslide(&["info", map.to_str().unwrap(), "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(v["width"], 8);
    assert_eq!(v["height"], 5);
    assert_eq!(v["format"], "ascii");
    assert_eq!(v["cell_size"], serde_json::json!([1.0, 1.0]));
    // '#' × 22, '=' × 1, '/' × 1.
    assert_eq!(v["tile_counts"]["1"], 22);
    assert_eq!(v["tiles_used"], 3);
    let (placed, active) = (
        v["segments_placed"].as_u64().unwrap(),
        v["segments_active"].as_u64().unwrap(),
    );
    assert_eq!(placed, 22 * 4 + 1 + 3);
    assert!(active < placed, "seams are culled: {active} of {placed}");
}

#[test]
fn info_text_names_the_segment_counts() {
    let map = scratch("info_text.txt", ROOM);
    let o = tileslide(&["info", map.to_str().unwrap()]);
    assert!(o.status.success());
    let out = stdout(&o);
    assert!(out.contains("8 × 5 cells"), "{out}");
    assert!(out.contains("active after seam culling"), "{out}");
}

#[test]
fn raycast_json_prints_one_object_per_ray_in_input_order() {
    let map = scratch("rays_map.txt", ROOM);
    let rays = scratch(
        "rays.csv",
        "# x0,y0,x1,y1\n1.5,1.5,9.5,1.5\n3.5,3.5,3.5,0.5\n3.5,1.5,3.5,4.5\n\n6.75,1.5,6.75,4.5\n",
    );
    let o = tileslide(&[
        "raycast",
        map.to_str().unwrap(),
        "--rays",
        rays.to_str().unwrap(),
        "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let lines: Vec<Value> = stdout(&o)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(lines.len(), 4);
    // Right into the east wall.
    assert_eq!(lines[0]["hit"], true);
    assert_eq!(lines[0]["x"], 7.0);
    assert_eq!(lines[0]["nx"], -1.0);
    assert_eq!(lines[0]["cell"], serde_json::json!([7, 1]));
    assert_eq!(lines[0]["tile"], 1);
    // Up through the one-way ledge's back face: it reaches the ceiling.
    assert_eq!(lines[1]["y"], 1.0);
    // Down onto the ledge's top.
    assert_eq!(lines[2]["y"], 2.0);
    assert_eq!(lines[2]["tile"], 4);
    // Down onto the ramp in (6, 3): its surface runs from (6, 4) to (7, 3).
    assert_eq!(lines[3]["tile"], 2);
    assert!((lines[3]["y"].as_f64().unwrap() - 3.25).abs() < 1e-6);
    // The documented key order.
    assert!(
        stdout(&o).starts_with("{\"hit\":true,\"t\":"),
        "{}",
        stdout(&o)
    );
}

#[test]
fn raycast_both_sides_hits_the_ledge_from_below() {
    let map = scratch("both.txt", ROOM);
    let args = [
        "raycast",
        map.to_str().unwrap(),
        "--from",
        "3.5,3.5",
        "--to",
        "3.5,0.5",
        "--json",
    ];
    let front: Value = serde_json::from_str(&stdout(&tileslide(&args))).unwrap();
    let mut both_args = args.to_vec();
    both_args.push("--both-sides");
    let both: Value = serde_json::from_str(&stdout(&tileslide(&both_args))).unwrap();
    assert_eq!(front["y"], 1.0);
    assert_eq!(both["y"], 2.0);
}

#[test]
fn raycast_whose_length_overflows_the_grid_answers_instead_of_panicking() {
    // Delta / cell size overflows f32 here: the walk used to run off the map (exit 101).
    let map = scratch("open.txt", "...\n...\n..#\n");
    let m = map.to_str().unwrap();
    let args = ["raycast", m, "--cell", "0.5", "--from", "0.2565,0.2605"];
    let o = tileslide(&[&args[..], &["--to", "0.5565,3.4e38", "--json"]].concat());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(stdout(&o).trim(), "{\"hit\":false}");
    // Up the third column it meets the solid cell's floor at y = 1.
    let o = tileslide(&[
        "raycast",
        m,
        "--cell",
        "0.5",
        "--from",
        "1.25,0.25",
        "--to",
        "1.25,3.4e38",
        "--json",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(
        (v["hit"].clone(), v["y"].clone()),
        (Value::Bool(true), serde_json::json!(1.0))
    );
    // End points too far apart for an f32 motion are an error naming the ray.
    let o = tileslide(&["raycast", m, "--from", "-3e38,0.5", "--to", "3e38,0.5"]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("ray 1") && stderr(&o).contains("too far apart"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn a_miss_is_hit_false() {
    let map = scratch("miss.txt", ROOM);
    let o = tileslide(&[
        "raycast",
        map.to_str().unwrap(),
        "--from",
        "2.5,1.5",
        "--to",
        "2.6,1.5",
        "--json",
    ]);
    assert_eq!(stdout(&o).trim(), "{\"hit\":false}");
}

#[test]
fn bad_arguments_are_errors_naming_them() {
    let map = scratch("args.txt", ROOM);
    let m = map.to_str().unwrap();
    let o = tileslide(&["raycast", m, "--from", "1.5", "--to", "2,2"]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("--from"), "{}", stderr(&o));
    let o = tileslide(&["raycast", m, "--from", "1,NaN", "--to", "2,2"]);
    assert!(stderr(&o).contains("not finite"), "{}", stderr(&o));
    let o = tileslide(&["raycast", "map.png", "--from", "1,1", "--to", "2,2"]);
    assert!(
        stderr(&o).contains("map.png") && stderr(&o).contains("unknown map format"),
        "{}",
        stderr(&o)
    );
    let rays = scratch("bad.csv", "1,1,2,2\n1,1,x,2\n");
    let o = tileslide(&["raycast", m, "--rays", rays.to_str().unwrap()]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("bad.csv:2:5"), "{}", stderr(&o));
    let o = tileslide(&[
        "raycast",
        m,
        "--rays",
        rays.to_str().unwrap(),
        "--from",
        "1,1",
        "--to",
        "2,2",
    ]);
    assert!(
        !o.status.success(),
        "--rays and --from together are refused"
    );
}

#[test]
fn map_errors_name_file_and_line() {
    let map = scratch("broken.txt", "###\n#?#\n");
    let o = tileslide(&["info", map.to_str().unwrap()]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("broken.txt:2:2"), "{}", stderr(&o));
}

#[test]
fn replica_level_needs_its_tile_set_and_casts_in_pixels() {
    let Some(dir) = replica_dir() else { return };
    let level = dir.join("level_1_1_island.bin");
    let set = dir.join("collision.bin");
    let o = tileslide(&["info", level.to_str().unwrap()]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("--tileset"), "{}", stderr(&o));
    let o = tileslide(&[
        "info",
        level.to_str().unwrap(),
        "--tileset",
        set.to_str().unwrap(),
        "--cell",
        "2",
    ]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("--cell"), "{}", stderr(&o));
    let o = tileslide(&[
        "raycast",
        level.to_str().unwrap(),
        "--tileset",
        set.to_str().unwrap(),
        "--from",
        "176,200",
        "--to",
        "176,0",
        "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
    // The floor of tile 1 in cell (5, 1): its top is y = 64 px, facing up (y up).
    assert_eq!(v["y"], 64.0);
    assert_eq!(v["ny"], 1.0);
    assert_eq!(v["cell"], serde_json::json!([5, 1]));
    assert_eq!(v["tile"], 1);
}

#[test]
fn simulate_json_reports_positions_and_a_clean_audit() {
    let map = scratch("sim_room.txt", ROOM);
    let scene = scratch(
        "sim.json",
        r#"{"map": "sim_room.txt", "steps": 40, "bodies": [
            {"x": 1.5, "y": 1.5, "r": 0.3, "vx": 0.25, "vy": 0.0},
            {"x": 6.5, "y": 1.5, "r": 0.3, "vx": -0.25, "vy": 0.0},
            {"x": 4.0, "y": 1.5, "r": 0.3}
        ]}"#,
    );
    assert!(map.exists());
    let o = tileslide(&["simulate", scene.to_str().unwrap(), "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["steps"], 40);
    let bodies = v["bodies"].as_array().unwrap();
    assert_eq!(bodies.len(), 3);
    // The body without a move stays; the others went round it or stopped against it.
    assert_eq!(bodies[2]["x"].as_f64(), Some(4.0));
    assert_eq!(bodies[2]["y"].as_f64(), Some(1.5));
    assert_eq!(v["audit"]["overlapping_pairs"], 0);
    assert_eq!(v["audit"]["wall_penetrations"], 0);
    assert!(v["ms_per_step"].as_f64().unwrap() >= 0.0);
    // --steps overrides the scene.
    let o = tileslide(&[
        "simulate",
        scene.to_str().unwrap(),
        "--json",
        "--steps",
        "0",
    ]);
    let v: Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["steps"], 0);
    assert_eq!(v["bodies"][0]["x"].as_f64(), Some(1.5));
}

#[test]
fn simulate_errors_name_the_field() {
    let cases = [
        (
            r####"{"ascii": "###\n#.#\n###", "bodies": [{"x": 1.5, "y": 1.5, "r": 0}]}"####,
            "bodies[0].r",
        ),
        (
            r####"{"ascii": "###\n#.#\n###", "bodies": [{"x": 1.5, "y": "a", "r": 1}]}"####,
            "line 1 column",
        ),
        (
            r####"{"ascii": "###\n#.#\n###", "bodys": []}"####,
            "unknown field `bodys`",
        ),
        (r####"{"bodies": []}"####, "missing the map"),
        (
            r####"{"ascii": "#?#", "bodies": []}"####,
            "(field \"ascii\"):1:2",
        ),
        (
            r####"{"ascii": "###", "cell": -1, "bodies": []}"####,
            "cell",
        ),
        (
            r####"{"ascii": "###", "steps": 99999999999, "bodies": []}"####,
            "steps",
        ),
    ];
    for (i, (text, expected)) in cases.iter().enumerate() {
        let scene = scratch(&format!("bad_scene_{i}.json"), text);
        let o = tileslide(&["simulate", scene.to_str().unwrap()]);
        assert!(!o.status.success(), "case {i} should fail");
        let err = stderr(&o);
        assert!(err.contains(expected), "case {i}: {err}");
        assert!(
            err.contains(&format!("bad_scene_{i}.json")),
            "case {i}: {err}"
        );
    }
}

#[test]
fn a_baked_map_answers_info_and_raycast_as_its_source_does() {
    let source = scratch("bake_room.txt", ROOM);
    let baked = source.with_extension("tsm");
    let o = tileslide(&[
        "bake",
        source.to_str().unwrap(),
        "-o",
        baked.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).contains("bytes"), "{}", stdout(&o));
    let ray = ["--from", "1.5,1.5", "--to", "9.5,2.5", "--json"];
    let mut a = vec!["raycast", source.to_str().unwrap()];
    a.extend(ray);
    let mut b = vec!["raycast", baked.to_str().unwrap()];
    b.extend(ray);
    let (from_text, from_baked) = (tileslide(&a), tileslide(&b));
    assert!(from_baked.status.success(), "{}", stderr(&from_baked));
    assert_eq!(stdout(&from_text), stdout(&from_baked));
    let info = tileslide(&["info", baked.to_str().unwrap(), "--json"]);
    let v: Value = serde_json::from_str(stdout(&info).trim()).unwrap();
    assert_eq!(v["format"], "baked");
    // A corrupt baked file: an error naming the file and the checksum field's offset.
    let mut bytes = std::fs::read(&baked).unwrap();
    let last = bytes.len() - 1;
    bytes[last] ^= 1;
    let corrupt = source.with_extension("bad.tsm");
    std::fs::write(&corrupt, &bytes).unwrap();
    let o = tileslide(&["info", corrupt.to_str().unwrap()]);
    assert!(!o.status.success());
    let err = stderr(&o);
    assert!(
        err.contains("bad.tsm") && err.contains("byte 24") && err.contains("checksum"),
        "{err}"
    );
    // A baked map takes no --cell.
    let o = tileslide(&["info", baked.to_str().unwrap(), "--cell", "2"]);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("drop --tileset and --cell"),
        "{}",
        stderr(&o)
    );
}
