//! `tileslide demo dungeon`: writes a GIF and a PNG and prints the summary.
#![allow(clippy::unwrap_used, clippy::expect_used)]

mod support;

use support::{stderr, stdout, tileslide};

#[test]
fn demo_dungeon_writes_a_gif_a_png_and_a_json_summary() {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("cli_demo");
    std::fs::create_dir_all(&dir).unwrap();
    let gif = dir.join("dungeon.gif");
    let out = tileslide(&[
        "demo",
        "dungeon",
        "--minutes",
        "0.2",
        "-o",
        gif.to_str().unwrap(),
        "--json",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let summary: serde_json::Value = serde_json::from_str(stdout(&out).trim()).unwrap();
    assert_eq!(summary["steps"], 360);
    assert_eq!(summary["audit"]["overlapping_pairs"], 0);
    assert_eq!(summary["audit"]["wall_penetrations"], 0);

    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::RGBA);
    let mut decoder = options
        .read_info(std::fs::File::open(&gif).unwrap())
        .unwrap();
    assert_eq!((decoder.width(), decoder.height()), (680, 720));
    let mut frames = 0;
    while decoder.read_next_frame().unwrap().is_some() {
        frames += 1;
    }
    assert!(frames > 10, "{frames} frames");

    let png = png::Decoder::new(std::io::BufReader::new(
        std::fs::File::open(dir.join("dungeon.png")).unwrap(),
    ));
    let info = png.read_info().unwrap();
    assert_eq!((info.info().width, info.info().height), (680, 720));
}

#[test]
fn demo_dungeon_refuses_negative_minutes() {
    let out = tileslide(&["demo", "dungeon", "--minutes=-1"]);
    assert!(!out.status.success());
    assert!(
        stderr(&out).contains("--minutes -1: must be between 0 and 600"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn demo_dungeon_refuses_an_output_folder_that_does_not_exist_before_running() {
    let out = tileslide(&[
        "demo",
        "dungeon",
        "--minutes",
        "0.1",
        "-o",
        "no/such/folder/dungeon.gif",
    ]);
    assert!(!out.status.success());
    let err = stderr(&out);
    assert!(
        err.contains("no/such/folder/dungeon.gif") && err.contains("does not exist"),
        "{err}"
    );
}
