//! The playground's explanations (the `explain` feature; the npm package leaves it out):
//! a body's last step and a map cell's segments in words, worded by `tileslide-explain` as
//! `tileslide explain` words them. The plain Rust first (tested natively), then the
//! JavaScript methods `Bodies.traceNextSteps`, `Bodies.storyOf` and `TileMap.explainCell`.

use js_sys::Array;
use tileslide::{BodyHandle, Cell, ResolveTrace, Vec2};
use tileslide_explain::{body, cell};
use wasm_bindgen::prelude::*;

use crate::args::{error, whole};
use crate::bodies::Bodies;
use crate::body_set::BodySet;
use crate::map::TileMap;
use crate::values::{object, pair};

impl BodySet {
    /// Starts (`true`) or stops tracing the steps: while on, each resolve keeps what it did
    /// with every body until the next one; stopping drops the trace.
    pub fn trace_next_steps(&mut self, on: bool) {
        if on != self.trace.is_some() {
            self.trace = on.then(ResolveTrace::new);
        }
    }

    /// `handle`'s body's last traced step in words, or `None` when steps are not traced or
    /// the body was added since the last one.
    ///
    /// # Errors
    /// A stale or unknown handle, named.
    pub fn story_of(&self, handle: f64) -> Result<Option<String>, String> {
        let core = self.core(handle)?;
        let Some(story) = self.trace.as_ref().and_then(|t| t.body(core)) else {
            return Ok(None);
        };
        let name = |h: BodyHandle| self.number_of(h).map(|n| format!("body {n}"));
        let heading = format!("body {handle}, last step");
        Ok(Some(body::step_words(&heading, story, &name)))
    }
}

/// An end of an active piece of a segment: where it is, whether it has a rounded cap, and
/// what it continues into in words.
#[derive(Clone, Debug, PartialEq)]
pub struct EndView {
    /// The end point.
    pub at: Vec2,
    /// Whether the end has a rounded cap (nothing continues it flat or concave).
    pub cap: bool,
    /// The end in words.
    pub words: String,
}

/// A segment of a cell's tile as the playground shows it under the mouse.
#[derive(Clone, Debug, PartialEq)]
pub struct SegmentView {
    /// Its index in the tile's shape.
    pub index: u32,
    /// Its start, in map units.
    pub from: Vec2,
    /// Its end.
    pub to: Vec2,
    /// Wholly hidden: no active piece.
    pub hidden: bool,
    /// `active`, `partly hidden` or `hidden by` the neighbour's segment.
    pub state: String,
    /// The segment in words: what hides it, its active pieces and their ends.
    pub words: String,
    /// The ends of its active pieces.
    pub ends: Vec<EndView>,
}

/// A cell's explanation as the playground shows it.
#[derive(Clone, Debug, PartialEq)]
pub struct CellView {
    /// The cell.
    pub cell: Cell,
    /// Its tile, or `None` for an empty cell.
    pub tile: Option<u32>,
    /// The whole explanation in words.
    pub words: String,
    /// Each segment of its tile.
    pub segments: Vec<SegmentView>,
}

/// Explains cell (`col`, `row`) of `map`.
///
/// # Errors
/// A coordinate that is not a whole number, or a cell outside the map, named.
pub fn explain_cell(map: &tileslide::TileMap, col: f64, row: f64) -> Result<CellView, String> {
    let at = Cell::new(
        whole("explainCell: col", col)?,
        whole("explainCell: row", row)?,
    );
    let e = map
        .explain_cell(at)
        .map_err(|e| format!("explainCell: {e}"))?;
    let segments = e
        .segments
        .iter()
        .map(|s| SegmentView {
            index: s.index,
            from: s.segment.a,
            to: s.segment.b,
            hidden: s.active.is_empty(),
            state: cell::state_words(s),
            words: cell::segment_words(s),
            ends: s
                .active
                .iter()
                .flat_map(|p| &p.ends)
                .map(|end| EndView {
                    at: end.point,
                    cap: end.join.needs_cap(),
                    words: cell::end_words(end),
                })
                .collect(),
        })
        .collect();
    Ok(CellView {
        cell: at,
        tile: e.tile.map(|t| t.0),
        words: cell::explanation_words(&e),
        segments,
    })
}

#[wasm_bindgen(typescript_custom_section)]
const TS_TYPES: &str = r#"
/** An end of an active piece of a segment. */
export interface SegmentEnd {
    at: [number, number];
    /** A rounded cap: nothing continues the surface flat or concave there. */
    cap: boolean;
    words: string;
}

/** A segment of a cell's tile, active or hidden and why. */
export interface SegmentExplanation {
    index: number;
    from: [number, number];
    to: [number, number];
    /** Wholly hidden by a neighbour's segment: nothing ever meets it. */
    hidden: boolean;
    /** `"active"`, `"partly hidden"` or `"hidden by cell (c, r) tile t segment i"`. */
    state: string;
    words: string;
    ends: SegmentEnd[];
}

/** `TileMap.explainCell`'s answer. */
export interface CellExplanation {
    cell: [number, number];
    tile: number | null;
    words: string;
    segments: SegmentExplanation[];
}
"#;

#[wasm_bindgen]
impl Bodies {
    /// Starts (`true`) or stops tracing steps for `storyOf` (off by default: an untraced
    /// step records nothing).
    #[wasm_bindgen(js_name = traceNextSteps)]
    pub fn trace_next_steps(&mut self, on: bool) {
        self.set.trace_next_steps(on);
    }

    /// The body's last step in words, as `tileslide explain --body` tells it (each pass,
    /// every contact with its cell and tile or body, what the resolver did), or `null`
    /// when steps are not traced or the body came after the last step.
    #[wasm_bindgen(js_name = storyOf, unchecked_return_type = "string | null")]
    pub fn story_of(&self, handle: f64) -> Result<JsValue, JsError> {
        let story = self.set.story_of(handle).map_err(error)?;
        Ok(story.map_or(JsValue::NULL, JsValue::from))
    }
}

#[wasm_bindgen]
impl TileMap {
    /// Why each segment of cell (`col`, `row`) is active or hidden, and how its ends join,
    /// as `tileslide explain MAP --cell` tells it: words and each segment's line.
    #[wasm_bindgen(js_name = explainCell, unchecked_return_type = "CellExplanation")]
    pub fn explain_cell(&self, col: f64, row: f64) -> Result<JsValue, JsError> {
        let view = explain_cell(self.inner(), col, row).map_err(error)?;
        let segments = Array::new();
        for s in &view.segments {
            let ends = Array::new();
            for end in &s.ends {
                let end = object(&[
                    ("at", pair(end.at)),
                    ("cap", end.cap.into()),
                    ("words", end.words.as_str().into()),
                ])?;
                ends.push(&end);
            }
            let segment = object(&[
                ("index", s.index.into()),
                ("from", pair(s.from)),
                ("to", pair(s.to)),
                ("hidden", s.hidden.into()),
                ("state", s.state.as_str().into()),
                ("words", s.words.as_str().into()),
                ("ends", ends.into()),
            ])?;
            segments.push(&segment);
        }
        let cell = Array::of2(&view.cell.col.into(), &view.cell.row.into());
        Ok(object(&[
            ("cell", cell.into()),
            ("tile", view.tile.map_or(JsValue::NULL, JsValue::from)),
            ("words", view.words.as_str().into()),
            ("segments", segments.into()),
        ])?
        .into())
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use tileslide::io::ascii;
    use tileslide::{BodyDesc, BodyShape};

    use super::*;

    fn room() -> tileslide::TileMap {
        ascii::parse("#####\n#...#\n#####", "room.txt", 1.0).unwrap()
    }

    #[test]
    fn a_body_stopped_by_a_wall_tells_the_walls_cell_and_tile() {
        let map = room();
        let mut set = BodySet::default();
        let ball = BodyDesc::new(Vec2::new(1.5, 1.5), BodyShape::circle(0.4).unwrap());
        let a = set.add(ball).unwrap();
        set.propose(a, Vec2::new(-1.0, 0.0)).unwrap();
        set.step(&map);
        assert_eq!(set.story_of(a).unwrap(), None, "untraced");
        set.trace_next_steps(true);
        set.propose(a, Vec2::new(-1.0, 0.0)).unwrap();
        set.step(&map);
        let story = set.story_of(a).unwrap().unwrap();
        assert!(
            story.starts_with(&format!("body {a}, last step: at ")),
            "{story}"
        );
        assert!(story.contains("cell (0, 1) tile 1 segment"), "{story}");
        set.remove(a).unwrap();
        assert!(set.story_of(a).unwrap_err().contains("stale"));
        set.trace_next_steps(false);
        assert!(set.trace.is_none());
    }

    #[test]
    fn a_seam_segment_is_hidden_by_the_neighbour_that_covers_it() {
        let view = explain_cell(&room(), 1.0, 0.0).unwrap();
        assert_eq!(view.tile, Some(1));
        let seam = view
            .segments
            .iter()
            .find(|s| s.from.x == 2.0 && s.to.x == 2.0)
            .unwrap();
        assert!(seam.hidden);
        assert!(
            seam.state.starts_with("hidden by cell (2, 0) tile 1"),
            "{}",
            seam.state
        );
        // The side facing the room below: its ceiling, joined flat or concave at both ends.
        let ceiling = view
            .segments
            .iter()
            .find(|s| s.from.y == 1.0 && s.to.y == 1.0)
            .unwrap();
        assert!(!ceiling.hidden);
        assert_eq!(ceiling.state, "active");
        assert_eq!(ceiling.ends.len(), 2);
        assert!(ceiling.ends.iter().all(|end| !end.cap));
        assert!(view.words.starts_with("cell (1, 0): tile 1"));
    }

    #[test]
    fn a_cell_outside_the_map_or_not_whole_is_refused() {
        assert!(
            explain_cell(&room(), 9.0, 0.0)
                .unwrap_err()
                .starts_with("explainCell: ")
        );
        assert!(explain_cell(&room(), 0.5, 0.0).unwrap_err().contains("col"));
    }
}
