//! `tileslide path` as a user runs it: paths in text and JSON
//! on ASCII and Tiled maps, no path, and arguments refused with errors that name them.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::PathBuf;

use serde_json::Value;
use support::{example, replica_dir, scratch_in, stderr, stdout, tileslide};

mod support;

fn scratch(name: &str, contents: &str) -> PathBuf {
    scratch_in("cli_path", name, contents)
}

/// Two rooms joined by a corridor one cell wide (row 3, x in [5, 6]): a circle of radius
/// 0.4 gets through, one of 0.6 does not, though it fits in either room.
const ROOMS: &str = "\
############
#....#.....#
#....#.....#
#..........#
#....#.....#
#....#.....#
############
";

/// Runs `path` and parses its JSON output.
fn path_json(map: &str, from: &str, to: &str, radius: &str) -> Value {
    let o = tileslide(&[
        "path", map, "--from", from, "--to", to, "--radius", radius, "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    serde_json::from_str(&stdout(&o)).unwrap()
}

fn points(v: &Value) -> Vec<(f64, f64)> {
    v["points"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| (p[0].as_f64().unwrap(), p[1].as_f64().unwrap()))
        .collect()
}

fn polyline_length(points: &[(f64, f64)]) -> f64 {
    points
        .windows(2)
        .map(|w| (w[1].0 - w[0].0).hypot(w[1].1 - w[0].1))
        .sum()
}

#[test]
fn path_on_the_cave_goes_over_the_pillar_from_start_to_goal() {
    let cave = example("cave.txt");
    let v = path_json(&cave, "2.5,12.5", "37.5,12.5", "0.4");
    let keys: Vec<&str> = v.as_object().unwrap().keys().map(String::as_str).collect();
    assert_eq!(keys, ["found", "length", "points"]);
    assert_eq!(v["found"], true);
    let points = points(&v);
    assert_eq!(points.first(), Some(&(2.5, 12.5)));
    assert_eq!(points.last(), Some(&(37.5, 12.5)));
    let length = v["length"].as_f64().unwrap();
    assert!((length - polyline_length(&points)).abs() < 1e-3, "{v}");
    // Longer than the straight line, which the pillar (cols 6-7, rows 11-14) blocks.
    assert!(length > 35.0 && length < 40.0, "{v}");
    assert!(points.len() > 2, "{v}");

    // The text form: a summary line, then one point per line, the same points.
    let o = tileslide(&[
        "path",
        &cave,
        "--from",
        "2.5,12.5",
        "--to",
        "37.5,12.5",
        "--radius",
        "0.4",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    let lines: Vec<&str> = out.lines().collect();
    assert!(
        lines[0].starts_with("path from (2.5, 12.5) to (37.5, 12.5) for radius 0.4: length "),
        "{out}"
    );
    assert!(
        lines[0].ends_with(&format!("{} points", points.len())),
        "{out}"
    );
    assert_eq!(lines.len(), points.len() + 1, "{out}");
    assert_eq!(lines[1], "(2.5, 12.5)");
    assert_eq!(lines[lines.len() - 1], "(37.5, 12.5)");
}

#[test]
fn a_circle_too_wide_for_the_corridor_finds_no_path() {
    let rooms = scratch("rooms.txt", ROOMS);
    let rooms = rooms.to_str().unwrap();
    let narrow = path_json(rooms, "2.5,3.5", "8.5,3.5", "0.4");
    assert_eq!(narrow["found"], true);
    // Straight through the corridor.
    assert_eq!(points(&narrow), [(2.5, 3.5), (8.5, 3.5)]);
    assert_eq!(narrow["length"], 6.0);

    let wide = path_json(rooms, "2.5,3.5", "8.5,3.5", "0.6");
    assert_eq!(wide.to_string(), r#"{"found":false}"#);
    let o = tileslide(&[
        "path", rooms, "--from", "2.5,3.5", "--to", "8.5,3.5", "--radius", "0.6",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(
        stdout(&o).trim(),
        "no path from (2.5, 3.5) to (8.5, 3.5) for radius 0.6: no way between them is wide enough"
    );

    // Ends where the circle does not fit: in a wall, outside the map.
    for (from, to, why) in [
        ("0.5,0.5", "8.5,3.5", "does not fit at the start (--from)"),
        ("2.5,3.5", "-40,3.5", "does not fit at the goal (--to)"),
    ] {
        let o = tileslide(&["path", rooms, "--from", from, "--to", to, "--radius", "0.4"]);
        assert!(o.status.success(), "{}", stderr(&o));
        assert!(stdout(&o).contains(why), "{}", stdout(&o));
        assert_eq!(
            path_json(rooms, from, to, "0.4").to_string(),
            r#"{"found":false}"#
        );
    }
}

#[test]
fn path_on_a_tiled_map_is_in_its_pixels_and_the_same_for_tmx_and_tmj() {
    let tmj = path_json(&example("cave.tmj"), "40,200", "440,100", "6");
    assert_eq!(tmj["found"], true);
    let points = points(&tmj);
    assert_eq!(points.first(), Some(&(40.0, 200.0)));
    assert_eq!(points.last(), Some(&(440.0, 100.0)));
    assert_eq!(
        path_json(&example("cave.tmx"), "40,200", "440,100", "6"),
        tmj
    );
    // The cave is 16 cells of 16 pixels high: no circle of radius 200 fits.
    assert_eq!(
        path_json(&example("cave.tmj"), "40,200", "440,100", "200").to_string(),
        r#"{"found":false}"#
    );
}

#[test]
fn path_on_a_baked_map_is_its_sources() {
    let rooms = scratch("baked_rooms.txt", ROOMS);
    let baked = rooms.with_extension("tsm");
    let o = tileslide(&[
        "bake",
        rooms.to_str().unwrap(),
        "-o",
        baked.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    for (from, to) in [("1.5,1.5", "10.5,5.5"), ("2.5,3.5", "8.5,3.5")] {
        let source = path_json(rooms.to_str().unwrap(), from, to, "0.4");
        assert_eq!(source["found"], true, "{source}");
        assert_eq!(path_json(baked.to_str().unwrap(), from, to, "0.4"), source);
    }
}

#[test]
fn path_on_a_replica_island_level_needs_its_tile_set_and_is_in_pixels() {
    let Some(dir) = replica_dir() else { return };
    let level = dir.join("level_1_1_island.bin");
    let level = level.to_str().unwrap();
    let set = dir.join("collision.bin");
    let args = ["--from", "176,200", "--to", "600,200", "--radius", "12"];
    let o = tileslide(&[&["path", level][..], &args].concat());
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("--tileset"), "{}", stderr(&o));
    let o = tileslide(
        &[
            &["path", level, "--tileset", set.to_str().unwrap()][..],
            &args,
            &["--json"],
        ]
        .concat(),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(v["found"], true, "{v}");
    let points = points(&v);
    assert_eq!(points.first(), Some(&(176.0, 200.0)));
    assert_eq!(points.last(), Some(&(600.0, 200.0)));
}

#[test]
fn bad_arguments_are_errors_that_name_them() {
    let cave = example("cave.txt");
    for (from, to, radius, needles) in [
        ("2.5,12.5", "37.5,12.5", "-1", &["--radius", "positive"][..]),
        ("2.5,12.5", "37.5,12.5", "0", &["--radius", "positive"]),
        ("2.5,12.5", "37.5,12.5", "NaN", &["--radius", "not finite"]),
        ("2.5,12.5", "37.5,12.5", "inf", &["--radius", "not finite"]),
        (
            "2.5,12.5",
            "37.5,12.5",
            "wide",
            &["--radius", "not a number"],
        ),
        ("2.5,12.5", "37.5,12.5", "40", &["--radius", "at most 31"]),
        ("2.5", "37.5,12.5", "0.4", &["--from", "X,Y"]),
        ("2.5,12.5", "37.5,NaN", "0.4", &["--to", "not finite"]),
        ("2.5,12.5", "37.5;12.5", "0.4", &["--to", "X,Y"]),
        ("a,12.5", "37.5,12.5", "0.4", &["--from", "not a number"]),
    ] {
        let o = tileslide(&[
            "path", &cave, "--from", from, "--to", to, "--radius", radius,
        ]);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(1), "{from} {to} {radius}: {err}");
        assert!(err.starts_with("error: "), "{err}");
        assert!(!err.contains("panicked"), "{err}");
        for needle in needles {
            assert!(err.contains(needle), "{from} {to} {radius}: {err}");
        }
        assert!(stdout(&o).is_empty());
    }
    // A missing argument is clap's error, naming it.
    let o = tileslide(&["path", &cave, "--from", "2.5,12.5", "--to", "37.5,12.5"]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("--radius"), "{}", stderr(&o));
    // A missing map names the file.
    let o = tileslide(&[
        "path",
        "no-such-map.txt",
        "--from",
        "1,1",
        "--to",
        "2,2",
        "--radius",
        "0.4",
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("no-such-map.txt"), "{}", stderr(&o));
}
