//! The repository README's Bevy quick start is the crate README's, which runs as a doctest.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

/// The text of the first code block opened by `fence` after `after` in `text`.
fn block<'a>(text: &'a str, after: &str, fence: &str) -> &'a str {
    let from = text.find(after).unwrap_or_else(|| panic!("no {after:?}"));
    let open = from + text[from..].find(fence).unwrap() + fence.len();
    let close = open + text[open..].find("```\n").unwrap();
    &text[open..close]
}

#[test]
fn the_readme_shows_the_quick_start_the_crate_readme_runs() {
    let root = include_str!("../../../README.md");
    let crate_readme = include_str!("../README.md");
    let shown = block(root, "**Bevy quick start**", "```rust,ignore\n");
    let run = block(crate_readme, "## Quick start", "```rust\n");
    assert!(run.contains("TileslidePlugin"));
    assert_eq!(shown, run);
}
