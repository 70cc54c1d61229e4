//! The inputs a target's stable regression test replays: the seeds (`corpus/TARGET/`) and
//! every input a campaign found and kept (`regressions/TARGET/`), sorted. Included by path
//! in the regression tests (crates/tileslide/tests/fuzz_regressions.rs,
//! crates/tileslide-cli/tests/fuzz_scene.rs).

use std::path::{Path, PathBuf};

/// The seeds of `target` under the fuzz folder `fuzz`, then its kept inputs.
pub fn seeds_and_kept(fuzz: &Path, target: &str) -> (Vec<PathBuf>, Vec<PathBuf>) {
    (
        files(&fuzz.join("corpus").join(target)),
        files(&fuzz.join("regressions").join(target)),
    )
}

/// The files of `dir` (none when it does not exist), sorted.
fn files(dir: &Path) -> Vec<PathBuf> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut files: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.is_file())
        .collect();
    files.sort();
    files
}
