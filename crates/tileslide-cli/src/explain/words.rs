//! Points and sources as `explain`'s JSON gives them; in words, [`tileslide_explain::words`].

use serde_json::{Value, json};
use tileslide::{PlacedSegment, Vec2, WallSource};
pub use tileslide_explain::words::{cell, num, point, wall};

use crate::json::number;

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
