//! `tileslide render` and `tileslide simulate --gif` as a user runs them: the files they
//! write decode to the expected size and frame count, and bad arguments are refused with
//! errors that name them.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use serde_json::Value;
use support::{example, replica_dir, scratch_in, stderr, stdout, tileslide};

mod support;

/// A fresh scratch folder for one test.
fn folder(name: &str) -> PathBuf {
    let dir = folder_path(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The scratch folder of one test, as [`folder`] made it.
fn folder_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("cli_render")
        .join(name)
}

/// Width and height of a PNG file, decoded.
fn png_size(path: &Path) -> (u32, u32) {
    let file = std::fs::File::open(path).unwrap();
    let mut reader = png::Decoder::new(std::io::BufReader::new(file))
        .read_info()
        .unwrap();
    let mut pixels = vec![0; reader.output_buffer_size().unwrap()];
    let frame = reader.next_frame(&mut pixels).unwrap();
    (frame.width, frame.height)
}

/// Width, height and frame count of a GIF file, decoded.
fn gif_frames(path: &Path) -> (u16, u16, usize) {
    let file = std::fs::File::open(path).unwrap();
    let mut decoder = gif::DecodeOptions::new()
        .read_info(std::io::BufReader::new(file))
        .unwrap();
    let (width, height) = (decoder.width(), decoder.height());
    let mut frames = 0;
    while let Some(frame) = decoder.read_next_frame().unwrap() {
        assert_eq!((frame.width, frame.height), (width, height));
        frames += 1;
    }
    (width, height, frames)
}

/// Runs `render MAP ARGS… -o OUT`, checks that it succeeded, and returns the PNG's size
/// and what it printed.
fn render_ok(map: &Path, args: &[&str], out: &Path) -> ((u32, u32), String) {
    let mut all = vec!["render", map.to_str().unwrap()];
    all.extend_from_slice(args);
    all.extend_from_slice(&["-o", out.to_str().unwrap()]);
    let o = tileslide(&all);
    assert!(o.status.success(), "{}", stderr(&o));
    (png_size(out), stdout(&o))
}

#[test]
fn render_writes_a_png_of_the_map_size_times_the_scale() {
    let out = folder("scaled").join("cave.png");
    let (size, said) = render_ok(example("cave.txt").as_ref(), &["--scale", "10"], &out);
    // cave.txt is 40 × 16 cells.
    assert_eq!(size, (400, 160));
    assert!(said.contains("cave.png: 400 × 160 pixels"), "{said}");
}

#[test]
fn render_writes_to_the_map_stem_in_the_current_directory_by_default() {
    let dir = folder("default");
    let o: Output = Command::new(env!("CARGO_BIN_EXE_tileslide"))
        .args(["render", &example("cave.txt")])
        .current_dir(&dir)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(png_size(&dir.join("cave.png")), (40 * 16, 16 * 16));
}

#[test]
fn render_reads_tiled_maps_and_their_layer_option() {
    let out = folder("tiled").join("cave_tmj.png");
    let (size, _) = render_ok(example("cave.tmj").as_ref(), &["--scale", "4"], &out);
    // 30 × 16 tiles.
    assert_eq!(size, (120, 64));
    let args = ["render", &example("cave.tmj"), "--layer", "no such layer"];
    fails_with(&args, &["no such layer"]);
}

#[test]
fn render_draws_a_replica_island_level() {
    let Some(dir) = replica_dir() else { return };
    let level = dir.join("level_1_1_island.bin");
    let set = dir.join("collision.bin");
    let out = folder("replica").join("island.png");
    let args = ["--tileset", set.to_str().unwrap(), "--scale", "2"];
    let (size, _) = render_ok(&level, &args, &out);
    // 90 × 50 tiles, drawn y up.
    assert_eq!(size, (180, 100));
}

/// Runs `tileslide ARGS…`, checks that it failed, and returns stderr, which must contain
/// every one of `needles`.
fn fails_with(args: &[&str], needles: &[&str]) -> String {
    let o = tileslide(args);
    assert!(!o.status.success(), "{args:?} succeeded");
    let err = stderr(&o);
    for needle in needles {
        assert!(err.contains(needle), "{args:?}: no {needle:?} in {err}");
    }
    err
}

#[test]
fn render_refuses_a_map_that_does_not_exist() {
    let dir = folder("missing");
    let map = dir.join("nowhere.txt");
    fails_with(&["render", map.to_str().unwrap()], &["nowhere.txt"]);
    assert!(!dir.join("nowhere.png").exists());
}

#[test]
fn render_refuses_bad_scales_naming_them() {
    let cave = example("cave.txt");
    for scale in ["0", "-2", "NaN", "inf"] {
        fails_with(
            &["render", &cave, "--scale", scale],
            &["--scale", "positive"],
        );
    }
    fails_with(&["render", &cave, "--scale", "sixteen"], &["sixteen"]);
}

#[test]
fn render_refuses_an_image_too_large_naming_its_size() {
    let out = folder("huge").join("huge.png");
    let args = [
        "render",
        &example("cave.txt"),
        "--scale",
        "1000",
        "-o",
        out.to_str().unwrap(),
    ];
    fails_with(&args, &["40000 × 16000", "too large"]);
    assert!(!out.exists());
}

#[test]
fn render_names_an_output_it_cannot_write() {
    let out = folder("unwritable").join("no/such/folder/cave.png");
    let args = ["render", &example("cave.txt"), "-o", out.to_str().unwrap()];
    fails_with(&args, &["no/such/folder/cave.png"]);
}

/// A 10 × 4 room with two circles sliding towards each other for 10 steps.
fn scene(name: &str) -> PathBuf {
    let scene = serde_json::json!({
        "ascii": "##########\n#........#\n#........#\n##########",
        "steps": 10,
        "bodies": [
            {"x": 1.5, "y": 1.5, "r": 0.4, "vx": 0.2},
            {"x": 8.5, "y": 2.5, "r": 0.3, "vx": -0.2}
        ]
    });
    scratch_in("cli_render", name, &scene.to_string())
}

/// Runs `simulate SCENE --gif OUT ARGS…` on [`scene`], checks that it succeeded, and
/// returns the GIF's width, height and frame count, stdout and stderr.
fn simulate_ok(test: &str, args: &[&str]) -> ((u16, u16, usize), String, String) {
    let scene = scene(&format!("{test}.json"));
    let out = folder(test).join("run.gif");
    let mut all = vec![
        "simulate",
        scene.to_str().unwrap(),
        "--gif",
        out.to_str().unwrap(),
    ];
    all.extend_from_slice(args);
    let o = tileslide(&all);
    assert!(o.status.success(), "{}", stderr(&o));
    (gif_frames(&out), stdout(&o), stderr(&o))
}

#[test]
fn simulate_gif_records_a_frame_every_n_steps_and_the_last() {
    let (gif, said, _) = simulate_ok("gif_every", &["--every", "3"]);
    // Steps 0, 3, 6, 9 and the last, 10; 10 × 4 cells of 16 pixels.
    assert_eq!(gif, (160, 64, 5));
    assert!(
        said.contains("run.gif: 160 × 64 pixels, 5 frames"),
        "{said}"
    );
    assert!(said.contains("2 bodies, 10 steps"), "{said}");
}

#[test]
fn simulate_gif_draws_each_body_in_a_colour_of_its_own() {
    let _ = simulate_ok("gif_colours", &[]);
    let out = folder_path("gif_colours").join("run.gif");
    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::RGBA);
    let mut decoder = options
        .read_info(std::io::BufReader::new(std::fs::File::open(&out).unwrap()))
        .unwrap();
    let frame = decoder.read_next_frame().unwrap().unwrap();
    let count = |c: tileslide_render::Rgba| {
        frame
            .buffer
            .chunks_exact(4)
            .filter(|p| p[..3] == [c.r, c.g, c.b])
            .count()
    };
    // Bodies 0 (radius 0.4) and 1 (radius 0.3) at 16 pixels a cell: discs of the
    // first two colours of the palette, the larger one larger.
    let (first, second) = (
        count(tileslide_render::categorical(0)),
        count(tileslide_render::categorical(1)),
    );
    assert!(
        first > 80 && second > 40 && first > second,
        "{first} {second}"
    );
}

#[test]
fn simulate_gif_keeps_the_json_output_one_object() {
    let (gif, said, note) = simulate_ok("gif_json", &["--json", "--scale", "8"]);
    assert_eq!(gif, (80, 32, 11));
    let v: Value = serde_json::from_str(&said).unwrap();
    assert_eq!(v["steps"], 10);
    assert!(note.contains("11 frames"), "{note}");
}

#[test]
fn simulate_gif_refuses_bad_arguments() {
    let scene = scene("gif_bad.json");
    let scene = scene.to_str().unwrap();
    let out = folder("gif_bad").join("run.gif");
    let out = out.to_str().unwrap();
    fails_with(
        &["simulate", scene, "--gif", out, "--every", "0"],
        &["--every 0"],
    );
    fails_with(
        &["simulate", scene, "--gif", out, "--scale", "0"],
        &["--scale 0"],
    );
    // --every means nothing without --gif.
    fails_with(&["simulate", scene, "--every", "2"], &["--gif"]);
    let many = ["simulate", scene, "--steps", "1000000", "--gif", out];
    fails_with(&many, &["1000001 frames", "--every"]);
    assert!(!Path::new(out).exists());
}
