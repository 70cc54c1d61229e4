//! Running the `tileslide` binary from the CLI tests.
#![allow(clippy::expect_used, dead_code)]

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
