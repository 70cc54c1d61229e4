//! Maps drawn as text in tests: one line per row, top row first (y grows downward), ASCII
//! tile characters. Indentation and blank lines are ignored, so empty cells are drawn as
//! `.`, never as spaces.

use tileslide::TileMap;
use tileslide::io::ascii;

/// The map `drawing` shows, with unit cells; `name` names it in errors.
pub fn map(drawing: &str, name: &str) -> TileMap {
    let rows: Vec<&str> = drawing
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect();
    match ascii::parse(&rows.join("\n"), name, 1.0) {
        Ok(map) => map,
        Err(e) => panic!("bad drawing: {e}"),
    }
}
