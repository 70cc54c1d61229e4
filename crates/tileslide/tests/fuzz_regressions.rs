//! The fuzz targets' checks (fuzz/src/checks.rs) on stable, over every file of the seed
//! corpora (`fuzz/corpus/TARGET/`) and every crash input kept (`fuzz/regressions/TARGET/`):
//! what a fuzzing campaign found once stays found. See docs/fuzzing.md.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::{Path, PathBuf};

#[path = "../../../fuzz/src/api.rs"]
mod api;
#[path = "../../../fuzz/src/checks.rs"]
mod checks;
#[path = "../../../fuzz/src/inputs.rs"]
mod inputs;

fn fuzz_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fuzz")
}

#[test]
fn every_seed_and_every_kept_crash_input_passes_its_targets_checks() {
    for (name, check) in checks::TARGETS {
        let (seeds, kept) = inputs::seeds_and_kept(&fuzz_dir(), name);
        assert!(!seeds.is_empty(), "fuzz/corpus/{name}/ has no seed");
        for file in seeds.iter().chain(&kept) {
            let data = std::fs::read(file).unwrap();
            let outcome = std::panic::catch_unwind(|| check(&data));
            assert!(
                outcome.is_ok(),
                "{name}: {} fails its checks",
                file.display()
            );
        }
    }
}

#[test]
fn a_sound_map_and_empty_input_pass_the_checks() {
    let map = tileslide::io::ascii::parse("###\n#.#\n###\n", "t.txt", 1.0).unwrap();
    checks::poke(&map);
    for (_, check) in checks::TARGETS {
        check(&[]);
    }
}
