//! `tileslide explain MAP --cell C,R`: each segment of a cell's tile, active or hidden and
//! by what, and how each active piece's ends join the surface around them.

use std::path::Path;

use anyhow::{Result, anyhow};
use serde_json::{Value, json};
use tileslide::{
    CellExplanation, CellSide, EndJoin, PieceEnd, SegmentExplanation, SegmentFlags, Vec2,
};
use tileslide_render::{Rgba, Style, Swatch};

use super::picture::{Row, Sketch};
use super::words::{cell, placed, placed_json, point, point_json};
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

fn side_words(side: CellSide) -> &'static str {
    match side {
        CellSide::MinX => "its min-x side",
        CellSide::MaxX => "its max-x side",
        CellSide::MinY => "its min-y side",
        CellSide::MaxY => "its max-y side",
    }
}

fn flags_words(flags: SegmentFlags) -> String {
    let mut names = Vec::new();
    if flags.contains(SegmentFlags::SOLID) {
        names.push("solid".to_owned());
    }
    if flags.contains(SegmentFlags::ONE_WAY) {
        names.push("one-way".to_owned());
    }
    let other = flags.0 & !(SegmentFlags::SOLID.0 | SegmentFlags::ONE_WAY.0);
    if other != 0 {
        names.push(format!("flags {other:#x}"));
    }
    if names.is_empty() {
        "no flags".to_owned()
    } else {
        names.join(", ")
    }
}

/// How an end joins, in words.
pub fn join_words(join: EndJoin) -> &'static str {
    match join {
        EndJoin::Flat => "continues flat: no cap",
        EndJoin::Concave => "turns concave: no cap",
        EndJoin::Open => "nothing continues it: rounded cap",
        EndJoin::Convex => "convex corner: rounded cap",
        EndJoin::FlagsChange => "continues into other flags: rounded cap",
        EndJoin::OneWay => "end of a one-way platform: rounded cap",
        _ => "rounded cap",
    }
}

fn end_words(end: &PieceEnd) -> String {
    let into = match end.into {
        Some(s) => format!(" into {}", placed(&s)),
        None => String::new(),
    };
    format!("end {}{into}: {}", point(end.point), join_words(end.join))
}

fn segment_words(s: &SegmentExplanation) -> String {
    let on = s
        .side
        .map(|side| format!(", on {}", side_words(side)))
        .unwrap_or_default();
    let mut text = format!(
        "  segment {}: {} to {}, normal {}, {}{on}\n",
        s.index,
        point(s.segment.a),
        point(s.segment.b),
        point(s.normal),
        flags_words(s.flags)
    );
    for h in &s.hidden {
        text += &format!(
            "    hidden from {} to {}: covered by {}, solid and facing back\n",
            point(h.part.a),
            point(h.part.b),
            placed(&h.by)
        );
    }
    if s.active.is_empty() {
        text += "    wholly hidden: no query, body or character ever meets it\n";
    }
    for p in &s.active {
        text += &format!(
            "    active {} to {} (active segment {} of the cell)\n",
            point(p.segment.a),
            point(p.segment.b),
            p.active.index
        );
        for end in &p.ends {
            text += &format!("      {}\n", end_words(end));
        }
    }
    text
}

fn explanation_words(e: &CellExplanation) -> String {
    let Some(tile) = e.tile else {
        return format!("cell {}: empty\n", cell(e.cell));
    };
    let n = e.segments.len();
    let mut text = format!(
        "cell {}: tile {}, {n} segment{}\n",
        cell(e.cell),
        tile.0,
        if n == 1 { "" } else { "s" }
    );
    for s in &e.segments {
        text += &segment_words(s);
    }
    text
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
        let state = if s.active.is_empty() {
            match s.hidden.first() {
                Some(h) => format!("hidden by {}", placed(&h.by)),
                None => "hidden".to_owned(),
            }
        } else if s.hidden.is_empty() {
            "active".to_owned()
        } else {
            "partly hidden".to_owned()
        };
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
