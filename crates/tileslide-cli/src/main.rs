//! The `tileslide` command-line tool.

fn main() {}
