//! A map cell's segments in words: each one active or hidden and by which neighbour's
//! segment, and how each active piece's ends join the surface around them (a
//! [`CellExplanation`] of [`TileMap::explain_cell`](tileslide::TileMap::explain_cell)).

use tileslide::{CellExplanation, CellSide, EndJoin, PieceEnd, SegmentExplanation, SegmentFlags};

use crate::words::{cell, placed, point};

/// Which side of its cell a segment lies on, in words.
#[must_use]
pub fn side_words(side: CellSide) -> &'static str {
    match side {
        CellSide::MinX => "its min-x side",
        CellSide::MaxX => "its max-x side",
        CellSide::MinY => "its min-y side",
        CellSide::MaxY => "its max-y side",
    }
}

/// A segment's flags, in words.
#[must_use]
pub fn flags_words(flags: SegmentFlags) -> String {
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
#[must_use]
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

/// An end of an active piece: where it is, what it continues into and how it joins.
#[must_use]
pub fn end_words(end: &PieceEnd) -> String {
    let into = match end.into {
        Some(s) => format!(" into {}", placed(&s)),
        None => String::new(),
    };
    format!("end {}{into}: {}", point(end.point), join_words(end.join))
}

/// One segment of a cell: its line, normal and flags, what hides it, its active pieces
/// and their ends; two-space indented, one line a fact.
#[must_use]
pub fn segment_words(s: &SegmentExplanation) -> String {
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

/// A cell's explanation in words: its tile, then each segment ([`segment_words`]).
#[must_use]
pub fn explanation_words(e: &CellExplanation) -> String {
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

/// A segment's state in a few words: `active`, `partly hidden`, or `hidden by` the first
/// segment that covers it.
#[must_use]
pub fn state_words(s: &SegmentExplanation) -> String {
    if s.active.is_empty() {
        match s.hidden.first() {
            Some(h) => format!("hidden by {}", placed(&h.by)),
            None => "hidden".to_owned(),
        }
    } else if s.hidden.is_empty() {
        "active".to_owned()
    } else {
        "partly hidden".to_owned()
    }
}

#[cfg(test)]
mod tests {
    use tileslide::Cell;
    use tileslide::io::ascii;

    use super::*;

    #[test]
    fn a_seam_segment_is_hidden_by_its_neighbour() {
        let map = ascii::parse("##\n..", "test.txt", 1.0).unwrap();
        let e = map.explain_cell(Cell::new(0, 0)).unwrap();
        let words = explanation_words(&e);
        assert!(words.starts_with("cell (0, 0): tile "), "{words}");
        assert!(words.contains("covered by cell (1, 0) tile "), "{words}");
        let seam = e
            .segments
            .iter()
            .find(|s| s.side == Some(CellSide::MaxX))
            .unwrap();
        assert!(state_words(seam).starts_with("hidden by cell (1, 0) tile "));
        let floor = e
            .segments
            .iter()
            .find(|s| s.side == Some(CellSide::MaxY))
            .unwrap();
        assert_eq!(state_words(floor), "active");
    }

    #[test]
    fn an_empty_cell_says_so() {
        let map = ascii::parse("#.", "test.txt", 1.0).unwrap();
        let e = map.explain_cell(Cell::new(1, 0)).unwrap();
        assert_eq!(explanation_words(&e), "cell (1, 0): empty\n");
    }
}
