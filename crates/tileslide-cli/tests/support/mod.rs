//! Running the `tileslide` binary from the CLI tests.
#![allow(clippy::expect_used, clippy::unwrap_used, dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Runs `tileslide` with `args`.
pub fn tileslide(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tileslide"))
        .args(args)
        .output()
        .expect("the tileslide binary runs")
}

/// What it printed on stdout.
pub fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// What it printed on stderr.
pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// The path of a bundled example map (`examples/maps/NAME`).
pub fn example(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/maps")
        .join(name)
        .to_str()
        .unwrap()
        .to_owned()
}

/// Writes `contents` to `name` in the test's scratch folder `folder`, and returns its path.
pub fn scratch_in(folder: &str, name: &str, contents: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(folder);
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, contents).unwrap();
    path
}

/// The Replica Island data beside the checkout, or `None` (with a note) when it is missing
/// outside CI; in CI its absence fails the test.
pub fn replica_dir() -> Option<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/data/replica-island");
    if dir.is_dir() {
        return Some(dir);
    }
    assert!(
        std::env::var_os("CI").is_none(),
        "CI is set but the Replica Island data is missing at {}",
        dir.display()
    );
    eprintln!("skipping: no Replica Island data at {}", dir.display());
    None
}
