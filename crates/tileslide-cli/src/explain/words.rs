//! Numbers, points and sources as `explain` words them, and as its JSON gives them.

use serde_json::{Value, json};
use tileslide::{Cell, PlacedSegment, Vec2, WallSource};

use crate::json::number;

/// `x` to three decimals, without a sign on zero.
pub fn num(x: f32) -> String {
    let text = format!("{x:.3}");
    if text == "-0.000" {
        "0.000".to_owned()
    } else {
        text
    }
}

/// `(x, y)` to three decimals.
pub fn point(p: Vec2) -> String {
    format!("({}, {})", num(p.x), num(p.y))
}

/// `(col, row)`.
pub fn cell(c: Cell) -> String {
    format!("({}, {})", c.col, c.row)
}

/// A tile segment: its cell, tile and index in the tile's shape.
pub fn placed(s: &PlacedSegment) -> String {
    format!(
        "cell {} tile {} segment {}",
        cell(s.cell),
        s.tile.0,
        s.index
    )
}

/// Where a wall comes from.
pub fn wall(source: &WallSource) -> String {
    match source {
        WallSource::Tile { segment, .. } => placed(segment),
        WallSource::Temporary { owner, index } => {
            format!("temporary segment {index} of owner {}", owner.0)
        }
    }
}

/// A point as JSON: `[x, y]`.
pub fn point_json(p: Vec2) -> Value {
    json!([number(p.x), number(p.y)])
}

/// A tile segment as JSON.
pub fn placed_json(s: &PlacedSegment) -> Value {
    json!({"cell": [s.cell.col, s.cell.row], "tile": s.tile.0, "segment": s.index})
}

/// Where a wall comes from, as JSON.
pub fn wall_json(source: &WallSource) -> Value {
    match source {
        WallSource::Tile { segment, .. } => json!({"tile": placed_json(segment)}),
        WallSource::Temporary { owner, index } => {
            json!({"temporary": {"owner": owner.0, "index": index}})
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_have_three_decimals_and_no_negative_zero() {
        assert_eq!(num(-0.0001), "0.000");
        assert_eq!(num(2.5996), "2.600");
        assert_eq!(point(Vec2::new(-1.0, 0.25)), "(-1.000, 0.250)");
    }
}
