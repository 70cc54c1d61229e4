//! Numbers, points and sources as the explanations word them.

use tileslide::{Cell, PlacedSegment, Vec2, WallSource};

/// `x` to three decimals, without a sign on zero.
#[must_use]
pub fn num(x: f32) -> String {
    let text = format!("{x:.3}");
    if text == "-0.000" {
        "0.000".to_owned()
    } else {
        text
    }
}

/// `(x, y)` to three decimals.
#[must_use]
pub fn point(p: Vec2) -> String {
    format!("({}, {})", num(p.x), num(p.y))
}

/// `(col, row)`.
#[must_use]
pub fn cell(c: Cell) -> String {
    format!("({}, {})", c.col, c.row)
}

/// A tile segment: its cell, tile and index in the tile's shape.
#[must_use]
pub fn placed(s: &PlacedSegment) -> String {
    format!(
        "cell {} tile {} segment {}",
        cell(s.cell),
        s.tile.0,
        s.index
    )
}

/// Where a wall comes from.
#[must_use]
pub fn wall(source: &WallSource) -> String {
    match source {
        WallSource::Tile { segment, .. } => placed(segment),
        WallSource::Temporary { owner, index } => {
            format!("temporary segment {index} of owner {}", owner.0)
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
