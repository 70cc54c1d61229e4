//! The `scene` fuzz target's checks (fuzz/src/scene.rs, which reads scene files with the
//! CLI's own reader) on stable, over its seeds (`fuzz/corpus/scene/`) and every input a
//! campaign found and kept (`fuzz/regressions/scene/`), and over scenes that break each rule
//! the reader enforces. See docs/fuzzing.md.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::{Path, PathBuf};

#[path = "../../../fuzz/src/inputs.rs"]
mod inputs;
#[path = "../../../fuzz/src/scene.rs"]
mod scene_check;

fn fuzz_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fuzz")
}

#[test]
fn every_scene_seed_and_kept_input_passes_the_checks() {
    let (seeds, kept) = inputs::seeds_and_kept(&fuzz_dir(), "scene");
    assert!(seeds.len() >= 4, "fuzz/corpus/scene/ lost its seeds");
    for file in seeds.iter().chain(&kept) {
        let data = std::fs::read(file).unwrap();
        let outcome = std::panic::catch_unwind(|| scene_check::check(&data));
        assert!(outcome.is_ok(), "{} fails the scene checks", file.display());
    }
}

#[test]
fn the_seeds_run_bodies_and_characters() {
    // The seeds are read, not refused: the checks above ran the scenes, not only the reader.
    for name in ["corridor", "one-way", "ramp-circle"] {
        let data = std::fs::read(fuzz_dir().join("corpus/scene").join(name)).unwrap();
        assert!(
            !scene_check::run_bits(std::str::from_utf8(&data).unwrap()).is_empty(),
            "{name} was refused"
        );
    }
}

#[test]
fn bad_scenes_are_refused_without_a_panic() {
    for text in [
        "",
        "{",
        "[]",
        r####"{"ascii": "###", "cell": -1}"####,
        r####"{"ascii": "#.#", "cell": 1e39}"####,
        r####"{"ascii": "#.#", "bodies": [{"x": 1.5, "y": 0.5, "r": 0}]}"####,
        r####"{"ascii": "#..#", "bodies": [{"x": 1e30, "y": 0.5, "r": 0.4}]}"####,
        r####"{"ascii": "#..#", "character": {"x": 1.5, "y": 0.5, "r": 0.4, "half_width": 1}}"####,
        r####"{"ascii": "#..#", "character": {"x": 1.5, "y": 0.5, "r": 0.4, "script": [{"steps": 18446744073709551615}, {"steps": 2}]}}"####,
        r####"{"ascii": "#..#", "steps": 18446744073709551615}"####,
        r####"{"map": "/dev/zero"}"####,
        r####"{"ascii": "#", "surprise": 1}"####,
    ] {
        assert!(
            scene_check::run_bits(text).is_empty(),
            "{text} was not refused"
        );
        scene_check::check(text.as_bytes());
    }
}

#[test]
fn a_move_out_of_range_ends_the_run_where_it_started() {
    // 3e38 is finite, so the scene is read; the resolver refuses the move, as `simulate`
    // reports, and nothing moved.
    let text = r####"{"ascii": "#..#", "bodies": [{"x": 1.5, "y": 0.5, "r": 0.4, "vx": 3e38}]}"####;
    assert_eq!(
        scene_check::run_bits(text),
        [1.5f32.to_bits(), 0.5f32.to_bits()]
    );
}
