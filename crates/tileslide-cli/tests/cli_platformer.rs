//! `tileslide demo platformer`: writes a GIF and a PNG and prints the summary, on the
//! bundled level and on Replica Island levels played with their objects.
#![allow(clippy::unwrap_used, clippy::expect_used)]

mod support;

use std::path::{Path, PathBuf};

use support::{replica_dir, stderr, stdout, tileslide};
use tileslide::io::replica::{self, ObjectKind};
use tileslide_platformer::ReplicaRole;

fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("cli_platformer");
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

/// The GIF's size and frame count.
fn gif_frames(path: &Path) -> ((u16, u16), usize) {
    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::RGBA);
    let mut decoder = options
        .read_info(std::fs::File::open(path).unwrap())
        .unwrap();
    let size = (decoder.width(), decoder.height());
    let mut frames = 0;
    while decoder.read_next_frame().unwrap().is_some() {
        frames += 1;
    }
    (size, frames)
}

#[test]
fn demo_platformer_writes_a_gif_a_png_and_a_summary() {
    let gif = scratch("p.gif");
    let out = tileslide(&["demo", "platformer", "-o", gif.to_str().unwrap()]);
    assert!(out.status.success(), "{}", stderr(&out));
    let text = stdout(&out);
    assert!(text.contains("coins 10/10"), "{text}");
    assert!(text.contains("goal reached"), "{text}");
    assert!(
        text.contains("steps inside solid 0, tunnels 0, max penetration 0 cells"),
        "{text}"
    );
    // The bundled level is 64 × 16 cells, drawn at 16 pixels a cell.
    let (size, frames) = gif_frames(&gif);
    assert_eq!(size, (1024, 280)); // the level, and the legend strip under it
    assert!(frames > 100, "{frames} frames");
    let png = png::Decoder::new(std::io::BufReader::new(
        std::fs::File::open(scratch("p.png")).unwrap(),
    ));
    let info = png.read_info().unwrap();
    assert_eq!((info.info().width, info.info().height), (1024, 280));
}

#[test]
fn demo_platformer_json_summary() {
    let gif = scratch("pj.gif");
    let out = tileslide(&["demo", "platformer", "-o", gif.to_str().unwrap(), "--json"]);
    assert!(out.status.success(), "{}", stderr(&out));
    let s: serde_json::Value = serde_json::from_str(stdout(&out).trim()).unwrap();
    assert_eq!(s["goal"], "marked");
    assert_eq!(s["reached"], true);
    assert_eq!(s["coins_collected"], s["coins_total"]);
    assert_eq!(s["enemies_defeated"], 2);
    assert_eq!(s["ignored_objects"], serde_json::json!([]));
    assert_eq!(s["audit"]["inside_solid"], 0);
    assert_eq!(s["audit"]["tunnels"], 0);
}

/// The levels the core's Replica Island run crosses (left to right, nothing a runner
/// cannot jump): the runner must reach their right end.
const CROSSED: [&str; 3] = ["level_0_1_sewer_kyle", "level_2_4_grass", "level_3_6_sewer"];

#[test]
fn demo_platformer_crosses_replica_island_levels_without_entering_solid() {
    let Some(dir) = replica_dir() else {
        return;
    };
    for name in CROSSED {
        let gif = scratch(&format!("{name}.gif"));
        let level = dir.join(format!("{name}.bin"));
        let out = tileslide(&[
            "demo",
            "platformer",
            level.to_str().unwrap(),
            "--tileset",
            dir.join("collision.bin").to_str().unwrap(),
            "-o",
            gif.to_str().unwrap(),
            "--json",
        ]);
        assert!(out.status.success(), "{name}: {}", stderr(&out));
        let s: serde_json::Value = serde_json::from_str(stdout(&out).trim()).unwrap();
        assert_eq!(s["level"], format!("{name}.bin"));
        // A Replica Island level has no goal: the run ends at its right end.
        assert_eq!(s["goal"], "right_end", "{s}");
        assert_eq!(s["reached"], true, "{s}");
        assert_eq!(s["audit"]["inside_solid"], 0, "{s}");
        assert_eq!(s["audit"]["tunnels"], 0, "{s}");
        let (_, frames) = gif_frames(&gif);
        assert!(frames > 10, "{name}: {frames} frames");
        // The level's objects, as the loader reads them: every one a coin, an enemy, the
        // start or counted as ignored.
        let objects = replica::load_objects(&level).unwrap().objects;
        let count = |role| {
            (objects.iter())
                .filter(|o| o.kind.and_then(ReplicaRole::of) == Some(role))
                .count()
        };
        assert_eq!(s["coins_total"], count(ReplicaRole::Coin), "{name}");
        let enemies = count(ReplicaRole::Walker) + count(ReplicaRole::Flyer);
        assert_eq!(s["enemies_total"], enemies, "{name}");
        let ignored: u64 = (s["ignored_objects"].as_array().unwrap().iter())
            .map(|i| i["count"].as_u64().unwrap())
            .sum();
        assert_eq!(
            ignored as usize,
            objects.len() - 1 - count(ReplicaRole::Coin) - enemies
        );
    }
}

#[test]
fn demo_platformer_plays_level_1_2_island_with_its_objects() {
    let Some(dir) = replica_dir() else {
        return;
    };
    let gif = scratch("level_1_2_island_text.gif");
    let out = tileslide(&[
        "demo",
        "platformer",
        dir.join("level_1_2_island.bin").to_str().unwrap(),
        "--tileset",
        dir.join("collision.bin").to_str().unwrap(),
        "-o",
        gif.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    // The whole run, as deterministic as the bundled one: 45 coins (42 pearls, 3 gems) and
    // 7 enemies (5 brobots, a karaguin, a snail bomb) placed, its doors and buttons
    // ignored; the runner takes a coin and stomps an enemy on its way out.
    let expected = "\
platformer (level_1_2_island.bin): 303 steps (5.0 game s)
  coins 1/45, enemies defeated 1/7, hits taken 0, jumps 3, steps riding the platform 0
  right end reached (the level has no goal)
  objects ignored 6: DOOR_RED (32) ×2, DOOR_BLUE (33) ×1, BUTTON_RED (35) ×2, BUTTON_BLUE (36) ×1
  audit: steps inside solid 0, tunnels 0, max penetration 0 cells
";
    let text = stdout(&out);
    let (summary, wrote) = text.split_at(text.find("  wrote ").unwrap());
    assert_eq!(summary, expected);
    assert!(wrote.contains("level_1_2_island_text.gif"), "{wrote}");
}

#[test]
fn demo_platformer_help_names_every_object_it_places() {
    let out = tileslide(&["demo", "platformer", "--help"]);
    assert!(out.status.success(), "{}", stderr(&out));
    let help = stdout(&out);
    let placed: Vec<&str> = (ObjectKind::ALL.iter())
        .filter(|&&k| ReplicaRole::of(k).is_some())
        .map(|k| k.name())
        .collect();
    assert_eq!(placed.len(), 13);
    for name in placed {
        assert!(help.contains(name), "{name} is not in the help:\n{help}");
    }
    assert!(
        help.contains("is ignored and counted in the summary"),
        "{help}"
    );
}

#[test]
fn demo_platformer_needs_a_tile_set_for_a_replica_island_level() {
    let out = tileslide(&["demo", "platformer", "level.bin"]);
    assert!(!out.status.success());
    assert!(
        stderr(&out).contains("--tileset collision.bin"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn demo_platformer_refuses_a_missing_output_folder() {
    let out = tileslide(&["demo", "platformer", "-o", "no/such/folder/p.gif"]);
    assert!(!out.status.success());
    assert!(stderr(&out).contains("does not exist"), "{}", stderr(&out));
}

#[test]
fn demo_platformer_on_a_level_without_a_goal_reports_its_right_end() {
    let level = support::scratch_in(
        "cli_platformer",
        "no_goal.txt",
        "#........\n#P.......\n#########\n",
    );
    let gif = scratch("no_goal.gif");
    let run = |json: bool| {
        let mut args = vec![
            "demo",
            "platformer",
            level.to_str().unwrap(),
            "-o",
            gif.to_str().unwrap(),
        ];
        args.extend(json.then_some("--json"));
        let out = tileslide(&args);
        assert!(out.status.success(), "{}", stderr(&out));
        stdout(&out)
    };
    let text = run(false);
    assert!(
        text.contains("  right end reached (the level has no goal)"),
        "{text}"
    );
    assert!(!text.contains("goal reached"), "{text}");
    let s: serde_json::Value = serde_json::from_str(run(true).trim()).unwrap();
    assert_eq!(s["goal"], "right_end", "{s}");
    assert_eq!(s["reached"], true, "{s}");
}
