//! The command line as a user meets it: output names checked before the work, one message
//! per error, negative numbers as values, exit statuses, and the inputs other commands
//! used to refuse or misreport.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::PathBuf;

use serde_json::Value;
use support::{example, scratch_in, stderr, stdout, tileslide};

mod support;

fn scratch(name: &str, contents: &str) -> PathBuf {
    scratch_in("cli_outputs", name, contents)
}

/// A folder of its own for output files, empty.
fn out_dir(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("cli_outputs_out")
        .join(name);
    if dir.exists() {
        std::fs::remove_dir_all(&dir).unwrap();
    }
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Asserts a refusal: exit status 1, one `error: ` line containing `needle`, nothing on
/// stdout (the command did none of its work).
fn assert_refused(o: &std::process::Output, needle: &str) {
    let err = stderr(o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.starts_with("error: ") && err.contains(needle), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(stdout(o).is_empty(), "{}", stdout(o));
}

#[test]
fn demos_refuse_an_output_that_is_not_a_gif_before_running() {
    let dir = out_dir("not_gif");
    let png = dir.join("out.png");
    for demo in ["dungeon", "platformer"] {
        let o = tileslide(&["demo", demo, "-o", png.to_str().unwrap()]);
        assert_refused(&o, "give a file name ending in .gif");
        assert!(!png.exists(), "{demo} wrote {}", png.display());
    }
}

#[test]
fn demos_refuse_a_folder_as_output() {
    let dir = out_dir("folder");
    let missing = format!("{}/", dir.join("somedir").display());
    for output in [dir.to_str().unwrap(), missing.as_str()] {
        let o = tileslide(&["demo", "dungeon", "-o", output]);
        assert_refused(&o, "is a folder");
    }
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0);
}

#[test]
fn render_refuses_a_gif_name_for_its_png() {
    let dir = out_dir("render_gif");
    let gif = dir.join("c.gif");
    let o = tileslide(&["render", &example("cave.txt"), "-o", gif.to_str().unwrap()]);
    assert_refused(
        &o,
        "this writes a PNG picture; give a file name ending in .png",
    );
    assert!(!gif.exists());
}

#[test]
fn bake_refuses_a_name_the_other_commands_would_not_read_as_baked() {
    let dir = out_dir("bake_bin");
    let bin = dir.join("cave.bin");
    let o = tileslide(&["bake", &example("cave.txt"), "-o", bin.to_str().unwrap()]);
    assert_refused(&o, "ending in .tsm");
    assert!(!bin.exists());
}

#[test]
fn simulate_refuses_a_gif_in_a_missing_folder_before_running() {
    let scene =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/scenes/corridor.json");
    let o = tileslide(&[
        "simulate",
        scene.to_str().unwrap(),
        "--gif",
        "/no-such-folder/x.gif",
    ]);
    // Refused before the run: no summary on stdout.
    assert_refused(
        &o,
        "--gif /no-such-folder/x.gif: the folder /no-such-folder does not exist",
    );
}

#[cfg(target_os = "linux")]
#[test]
fn a_write_error_says_its_cause_once() {
    // /proc exists, but no file can be created in it.
    let o = tileslide(&[
        "render",
        &example("cave.txt"),
        "-o",
        "/proc/tileslide-test.png",
    ]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.contains("/proc/tileslide-test.png: cannot write"),
        "{err}"
    );
    assert_eq!(err.matches("os error").count(), 1, "{err}");
}

#[test]
fn negative_numbers_are_values_not_flags() {
    // A value the command refuses: exit status 1, its own message.
    let o = tileslide(&["info", &example("cave.txt"), "--cell", "-1"]);
    assert_refused(&o, "cell size -1 is not positive");
    let o = tileslide(&["render", &example("cave.txt"), "--scale", "-2"]);
    assert_refused(&o, "--scale -2");
    // A negative count or seed is no number of the kind asked: clap's usage error, exit
    // status 2, about the value, not an "unexpected argument" with a wrong tip.
    let scene =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/scenes/corridor.json");
    for args in [
        vec!["simulate", scene.to_str().unwrap(), "--steps", "-1"],
        vec!["demo", "dungeon", "--seed", "-3"],
    ] {
        let o = tileslide(&args);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains("invalid value '-"), "{args:?}: {err}");
        assert!(!err.contains("unexpected argument"), "{args:?}: {err}");
        assert!(!err.contains("tip:"), "{args:?}: {err}");
    }
}

#[test]
fn usage_errors_exit_with_2_and_errors_found_running_with_1() {
    let o = tileslide(&["info", &example("cave.txt"), "--cells", "2"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("--cells"), "{}", stderr(&o));
    let o = tileslide(&["info", "no-such-map.txt"]);
    assert_refused(&o, "no-such-map.txt");
}

#[test]
fn help_names_every_command_in_its_first_line() {
    let o = tileslide(&["--help"]);
    assert!(o.status.success());
    let out = stdout(&o);
    let first = out.lines().next().unwrap();
    for command in [
        "inspect",
        "cast rays",
        "paths",
        "simulate",
        "draw",
        "bake",
        "demo",
        "benchmark",
    ] {
        assert!(first.contains(command), "{command}: {first}");
    }
    for command in [
        "info", "raycast", "path", "simulate", "render", "bake", "bench", "demo",
    ] {
        assert!(out.contains(&format!("\n  {command} ")), "{command}: {out}");
    }
}

#[test]
fn info_on_a_folder_says_it_is_a_folder() {
    let folder = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let o = tileslide(&["info", folder.to_str().unwrap()]);
    assert_refused(&o, "is a folder; give a map file");
    assert!(!stderr(&o).contains("unknown map format"), "{}", stderr(&o));
}

#[test]
fn info_and_render_read_the_platformer_level() {
    let level = example("platformer.txt");
    let o = tileslide(&["info", &level, "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(v["format"], "ascii-platformer");
    assert_eq!(
        (v["width"].as_u64(), v["height"].as_u64()),
        (Some(64), Some(16))
    );
    // The markers are empty cells: the same map as the level with them replaced by '.'.
    let text = std::fs::read_to_string(&level).unwrap();
    let plain: String = text
        .lines()
        .map(|l| {
            if l.starts_with(';') {
                l.to_owned()
            } else {
                l.chars()
                    .map(|c| if "PGoEM".contains(c) { '.' } else { c })
                    .collect()
            }
        })
        .collect::<Vec<_>>()
        .join("\n");
    let plain_map = scratch("platformer_plain.txt", &plain);
    let o = tileslide(&["info", plain_map.to_str().unwrap(), "--json"]);
    let w: Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(w["format"], "ascii");
    for key in ["tile_counts", "segments_placed", "segments_active"] {
        assert_eq!(v[key], w[key], "{key}");
    }
    let png = out_dir("platformer_render").join("p.png");
    let o = tileslide(&["render", &level, "-o", png.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(&png).unwrap()));
    let info = decoder.read_info().unwrap();
    assert_eq!((info.info().width, info.info().height), (1024, 256));
    // Its cells are of size 1.
    let o = tileslide(&["info", &level, "--cell", "2"]);
    assert_refused(&o, "a platformer level");
}

#[test]
fn a_file_with_an_unknown_character_that_is_no_marker_is_still_an_ascii_error() {
    let map = scratch("bad_char.txt", "####\n#.x#\n####\n");
    let o = tileslide(&["info", map.to_str().unwrap()]);
    assert_refused(&o, "bad_char.txt:2:3: unknown tile character 'x'");
}

#[test]
fn info_prints_tiled_gids_with_flip_letters_not_flip_bits() {
    let o = tileslide(&["info", &example("cave.tmx")]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(out.contains(" 2h×3 "), "{out}");
    assert!(out.contains(" 2hv×1 "), "{out}");
    assert!(!out.contains("1073741826"), "{out}");
    assert!(!out.contains("2147483650"), "{out}");
}

#[test]
fn raycast_json_marks_one_way_hits() {
    let o = tileslide(&[
        "raycast",
        &example("cave.txt"),
        "--from",
        "35.5,7",
        "--to",
        "35.5,13",
        "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(v["tile"], 4);
    assert_eq!(v["one_way"], true);
    let o = tileslide(&[
        "raycast",
        &example("cave.txt"),
        "--from",
        "12,12.5",
        "--to",
        "4,12.5",
        "--json",
    ]);
    let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(v["one_way"], false);
}

#[test]
fn simulate_refuses_a_body_that_starts_inside_a_wall() {
    let scene = scratch(
        "in_wall.json",
        &serde_json::json!({"ascii": "#####\n#...#\n#####", "bodies": [
            {"x": 2.5, "y": 1.5, "r": 0.4},
            {"x": 0.5, "y": 1.5, "r": 0.3, "vx": 0.1}
        ]})
        .to_string(),
    );
    let o = tileslide(&["simulate", scene.to_str().unwrap()]);
    assert_refused(
        &o,
        "bodies[1].x/y: the circle at (0.5, 1.5) of radius 0.3 starts inside a wall",
    );
    // Touching a wall is not inside it.
    let touching = scratch(
        "touching.json",
        &serde_json::json!({"ascii": "#####\n#...#\n#####", "bodies": [{"x": 1.4, "y": 1.5, "r": 0.4}]})
            .to_string(),
    );
    let o = tileslide(&["simulate", touching.to_str().unwrap(), "--steps", "1"]);
    assert!(o.status.success(), "{}", stderr(&o));
}

#[test]
fn a_corrupt_baked_file_names_the_checksum_field_in_hex() {
    let dir = out_dir("corrupt_baked");
    let baked = dir.join("cave.tsm");
    let o = tileslide(&["bake", &example("cave.txt"), "-o", baked.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let good = std::fs::read(&baked).unwrap();
    let mut bytes = good.clone();
    *bytes.last_mut().unwrap() ^= 0x40;
    std::fs::write(&baked, &bytes).unwrap();
    let o = tileslide(&["info", baked.to_str().unwrap()]);
    let err = stderr(&o);
    assert_refused(&o, ": byte 24: `checksum` is 0x");
    assert!(
        err.contains("CRC-32 is 0x") && err.contains("corrupt"),
        "{err}"
    );
    assert!(!err.contains("out of range"), "{err}");
    // A file that is not a baked map at all: its first bytes as text, not a number.
    let mut bytes = good;
    bytes[..4].copy_from_slice(b"PK\x03\x04");
    std::fs::write(&baked, &bytes).unwrap();
    let o = tileslide(&["info", baked.to_str().unwrap()]);
    assert_refused(&o, r#"`magic` is b"PK\x03\x04MAP\x1a""#);
    assert!(
        stderr(&o).contains("not a tileslide baked map"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn a_map_that_cannot_be_read_says_why_once() {
    // The loader keeps the operating system's error as the cause; the message quotes it, and
    // the command line does not repeat it.
    let o = tileslide(&["info", "no-such-map.txt"]);
    assert_refused(&o, "no-such-map.txt: cannot read the file: ");
    let err = stderr(&o);
    let os = err.trim_end().rsplit(": ").next().unwrap();
    assert!(os.contains("os error"), "{err}");
    assert_eq!(err.matches(os).count(), 1, "{err}");
}

#[cfg(not(feature = "peers"))]
#[test]
fn bench_without_the_peers_says_how_to_build_them() {
    let o = tileslide(&["bench", "crowd", "--n", "100"]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stdout(&o).is_empty(), "{}", stdout(&o));
    assert!(
        stderr(&o).contains("build it with the `peers` feature"),
        "{}",
        stderr(&o)
    );
    assert!(
        stderr(&o).contains(
            "cargo run --release -p tileslide-cli --features peers -- bench crowd --n 100"
        ),
        "{}",
        stderr(&o)
    );
}
