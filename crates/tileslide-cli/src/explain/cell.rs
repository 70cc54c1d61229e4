//! `tileslide explain MAP --cell C,R`: each segment of a cell's tile, active or hidden and
//! by what, and how each active piece's ends join the surface around them.

use std::path::Path;

use anyhow::{Result, anyhow};
use serde_json::{Value, json};
use tileslide::{CellExplanation, SegmentFlags, Vec2};
use tileslide_render::{Rgba, Style, Swatch};

use super::picture::{Row, Sketch};
use tileslide_explain::cell::{end_words, explanation_words, state_words};

use super::words::{cell, placed_json, point_json};
use crate::map_file::{self, MapArgs};

/// Explains cell `text` (`COL,ROW`) of the map.
pub fn run(args: &MapArgs, text: &str, out: Option<&Path>, json: bool) -> Result<()> {
    let at = parse_cell(text)?;
    let (map, format) = map_file::load(args)?;
    let e = map
        .explain_cell(at)
        .map_err(|e| anyhow!("--cell {text}: {e}"))?;
    if json {
        println!("{}", explanation_json(&e));
    } else {
        print!("{}", explanation_words(&e));
    }
    if let Some(out) = out {
        sketch(&e, map.cell_rect(at).min, map.cell_size().min_element())
            .save(&map, format, true, out, json)?;
    }
    Ok(())
}

/// `COL,ROW` as a cell.
fn parse_cell(text: &str) -> Result<tileslide::Cell> {
    let bad = || anyhow!("--cell {text}: expected COL,ROW (two whole numbers from 0, e.g. 3,2)");
    let (c, r) = text.split_once(',').ok_or_else(bad)?;
    let col = c.trim().parse::<u32>().map_err(|_| bad())?;
    let row = r.trim().parse::<u32>().map_err(|_| bad())?;
    Ok(tileslide::Cell::new(col, row))
}

fn explanation_json(e: &CellExplanation) -> Value {
    let segments: Vec<Value> = e
        .segments
        .iter()
        .map(|s| {
            let hidden: Vec<Value> = s
                .hidden
                .iter()
                .map(|h| {
                    json!({
                        "from": point_json(h.part.a),
                        "to": point_json(h.part.b),
                        "by": placed_json(&h.by),
                    })
                })
                .collect();
            let active: Vec<Value> = s
                .active
                .iter()
                .map(|p| {
                    let ends: Vec<Value> = p
                        .ends
                        .iter()
                        .map(|end| {
                            json!({
                                "point": point_json(end.point),
                                "into": end.into.as_ref().map(placed_json),
                                "join": format!("{:?}", end.join),
                                "cap": end.join.needs_cap(),
                            })
                        })
                        .collect();
                    json!({
                        "index": p.active.index,
                        "from": point_json(p.segment.a),
                        "to": point_json(p.segment.b),
                        "ends": ends,
                    })
                })
                .collect();
            json!({
                "index": s.index,
                "from": point_json(s.segment.a),
                "to": point_json(s.segment.b),
                "normal": point_json(s.normal),
                "flags": s.flags.0,
                "side": s.side.map(|side| format!("{side:?}")),
                "hidden": hidden,
                "active": active,
            })
        })
        .collect();
    json!({
        "cell": [e.cell.col, e.cell.row],
        "tile": e.tile.map(|t| t.0),
        "segments": segments,
    })
}

/// The cell and its neighbours, hidden segments shown, each segment numbered (by its index
/// in the tile) inside the cell, each end marked: a rounded cap, or a join.
fn sketch(e: &CellExplanation, corner: Vec2, cell_size: f32) -> Sketch {
    let style = Style::default();
    let cap = Rgba::opaque(255, 120, 40);
    let joined = Rgba::opaque(80, 200, 120);
    let mut sketch = Sketch::new();
    sketch.show(corner, 0.0);
    sketch.show(corner + Vec2::splat(cell_size), 0.0);
    let mut legend = vec![
        Row::Heading(format!("cell {}", cell(e.cell))),
        Row::Key(Swatch::Dot(cap), "end with a rounded cap".to_owned()),
        Row::Key(Swatch::Dot(joined), "end joined: no cap".to_owned()),
    ];
    let mark = 0.06 * cell_size;
    for s in &e.segments {
        let middle = (s.segment.a + s.segment.b) * 0.5;
        // Inside the material, a little behind the segment.
        let at = middle - s.normal * 0.2 * cell_size;
        let color = if s.active.is_empty() {
            Rgba::opaque(170, 170, 190)
        } else if s.flags.contains(SegmentFlags::ONE_WAY) {
            style.one_way
        } else {
            Rgba::opaque(255, 255, 255)
        };
        sketch.label(at, s.index.to_string(), color);
        let state = state_words(s);
        legend.push(Row::Line(format!("{}: {state}", s.index)));
        for p in &s.active {
            for end in &p.ends {
                let color = if end.join.needs_cap() { cap } else { joined };
                sketch
                    .picture
                    .body_with_color(tileslide::Circle::new(end.point, mark), color);
                legend.push(Row::Line(format!("   {}", end_words(end))));
            }
        }
    }
    sketch.legend = legend;
    sketch
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cell_is_two_whole_numbers() {
        assert_eq!(parse_cell("3,2").unwrap(), tileslide::Cell::new(3, 2));
        assert_eq!(parse_cell(" 0 , 7").unwrap(), tileslide::Cell::new(0, 7));
        for bad in ["3", "3,-1", "a,b", "1.5,2", ""] {
            assert!(parse_cell(bad).is_err(), "{bad}");
        }
    }
}
