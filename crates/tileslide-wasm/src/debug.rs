//! Debug lines for JavaScript: a `DebugLines` buffer whose shapes come out as typed arrays
//! ready for a canvas, the kinds as the `DebugKind` constants, and `map.debugLines(view?)`.
//!
//! The layout, for each sort of shape (coordinates in map units):
//!
//! | getter | array | per shape |
//! |---|---|---|
//! | `segments` | `Float32Array` | `x0, y0, x1, y1` |
//! | `circles` | `Float32Array` | `x, y, r` |
//! | `points` | `Float32Array` | `x, y` |
//! | `boxes` | `Float32Array` | `minX, minY, maxX, maxY` |
//! | `segmentKinds`, `circleKinds`, `pointKinds`, `boxKinds` | `Uint8Array` | a `DebugKind` |
//! | `segmentOwners`, `circleOwners`, `pointOwners`, `boxOwners` | `Float64Array` | the owner's id |
//!
//! Any object with debug lines fills a buffer the same way, with one method taking
//! `out: &mut DebugLines` that hands [`DebugLines::lines_mut`] to the core's
//! `debug_lines` (`TileMap::fillDebugLines` below is the model): a game keeps one buffer,
//! clears it each frame, has the map, bodies, characters and hit world fill it, and draws
//! the arrays.

use js_sys::{Float32Array, Float64Array, Uint8Array};
use tileslide::{Aabb, DebugKinds, Vec2};
use wasm_bindgen::prelude::*;

use crate::map::TileMap;

/// What a debug shape shows (the numbers of the Rust `tileslide::DebugKind`): a front end
/// picks colours and layers by it.
#[wasm_bindgen]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DebugKind {
    /// An active solid segment of the map (a segment).
    ActiveSegment = 0,
    /// An active one-way platform segment (a segment).
    OneWaySegment = 1,
    /// A segment's outward normal, from its middle (a segment).
    Normal = 2,
    /// A piece of a tile segment hidden by seam culling (a segment).
    HiddenSegment = 3,
    /// A temporary segment: a moving platform, a door (a segment).
    TemporarySegment = 4,
    /// A body's circle (a circle).
    Body = 5,
    /// A character's shape (a circle or a box).
    Character = 6,
    /// A surface a character touched, along its normal (a segment).
    Contact = 7,
    /// A ray (a segment).
    Ray = 8,
    /// Where a ray hit (a point).
    RayHit = 9,
    /// An attack volume (a circle or a box).
    AttackVolume = 10,
    /// A vulnerability volume (a circle or a box).
    VulnerabilityVolume = 11,
    /// An accepted hit event (a point).
    Hit = 12,
    /// A refused hit event (a point).
    RefusedHit = 13,
    /// A leg of a navigation path (a segment).
    Path = 14,
    /// A flow field's next move out of a node (a segment).
    FlowArrow = 15,
    /// A box the broadphase files something under (a box).
    BroadphaseBox = 16,
}

/// A buffer of debug shapes (segments, circles, points, boxes), each with a kind and an
/// owner, read as typed arrays (see the module's table). Keep one, `clear()` it each
/// frame and fill it again.
#[wasm_bindgen]
#[derive(Default)]
pub struct DebugLines {
    lines: tileslide::DebugLines,
}

/// A JavaScript `Error` with `message`.
fn error(message: impl std::fmt::Display) -> JsError {
    JsError::new(&message.to_string())
}

/// The box `[minX, minY, maxX, maxY]`, or an error naming `what` and the values.
pub fn view_of(what: &str, view: &[f32]) -> Result<Aabb, String> {
    match *view {
        [x0, y0, x1, y1] if view.iter().all(|v| v.is_finite()) && x0 <= x1 && y0 <= y1 => {
            Ok(Aabb::from_corners(Vec2::new(x0, y0), Vec2::new(x1, y1)))
        }
        _ => Err(format!(
            "{what}: a view is 4 finite numbers [minX, minY, maxX, maxY] with min <= max, got {view:?}"
        )),
    }
}

/// The kinds numbered in `kinds` as a set, or an error naming the first number no kind has.
pub fn kinds_of(kinds: &[u8]) -> Result<DebugKinds, String> {
    kinds.iter().try_fold(DebugKinds::NONE, |set, &n| {
        tileslide::DebugKind::from_u8(n)
            .map(|k| set.with(k))
            .ok_or_else(|| format!("setKinds: {n} is not a DebugKind"))
    })
}

/// `N` floats for each item, in order.
pub fn flat<T, const N: usize>(items: &[T], coords: impl Fn(&T) -> [f32; N]) -> Vec<f32> {
    items.iter().flat_map(coords).collect()
}

/// The segments' coordinates, `x0, y0, x1, y1` each.
pub fn segment_coords(lines: &tileslide::DebugLines) -> Vec<f32> {
    flat(lines.segments(), |s| {
        let (a, b) = (s.segment.a, s.segment.b);
        [a.x, a.y, b.x, b.y]
    })
}

/// The circles' coordinates, `x, y, r` each.
pub fn circle_coords(lines: &tileslide::DebugLines) -> Vec<f32> {
    flat(lines.circles(), |c| {
        [c.circle.center.x, c.circle.center.y, c.circle.radius]
    })
}

/// The points' coordinates, `x, y` each.
pub fn point_coords(lines: &tileslide::DebugLines) -> Vec<f32> {
    flat(lines.points(), |p| [p.point.x, p.point.y])
}

/// The boxes' coordinates, `minX, minY, maxX, maxY` each.
pub fn box_coords(lines: &tileslide::DebugLines) -> Vec<f32> {
    flat(lines.boxes(), |b| {
        [b.aabb.min.x, b.aabb.min.y, b.aabb.max.x, b.aabb.max.y]
    })
}

/// Each item's kind and owner, as the typed arrays hold them.
fn kinds_and_owners<T>(
    items: &[T],
    tag: impl Fn(&T) -> (tileslide::DebugKind, tileslide::Owner),
) -> (Uint8Array, Float64Array) {
    let kinds: Vec<u8> = items.iter().map(|i| tag(i).0 as u8).collect();
    // Owners are ids a game picks; past 2⁵³ a JavaScript number rounds them.
    let owners: Vec<f64> = items.iter().map(|i| tag(i).1.0 as f64).collect();
    (
        Uint8Array::from(kinds.as_slice()),
        Float64Array::from(owners.as_slice()),
    )
}

#[wasm_bindgen]
impl DebugLines {
    /// An empty buffer taking every kind, everywhere.
    #[wasm_bindgen(constructor)]
    pub fn new() -> DebugLines {
        Self::default()
    }

    /// Empties the buffer, keeping its memory, kinds and view.
    pub fn clear(&mut self) {
        self.lines.clear();
    }

    /// Takes only shapes touching `view` (`[minX, minY, maxX, maxY]`, map units) from now
    /// on, or shapes anywhere for `null` or nothing: a map then visits only the cells the
    /// view overlaps.
    #[wasm_bindgen(js_name = setView)]
    pub fn set_view(&mut self, view: Option<Vec<f32>>) -> Result<(), JsError> {
        let view = view
            .map(|v| view_of("setView", &v))
            .transpose()
            .map_err(error)?;
        self.lines.set_view(view);
        Ok(())
    }

    /// Takes only the kinds listed (`DebugKind` values) from now on, or every kind for
    /// `null` or nothing.
    #[wasm_bindgen(js_name = setKinds)]
    pub fn set_kinds(&mut self, kinds: Option<Vec<u8>>) -> Result<(), JsError> {
        let kinds = match kinds {
            Some(k) => kinds_of(&k).map_err(error)?,
            None => DebugKinds::ALL,
        };
        self.lines.set_kinds(kinds);
        Ok(())
    }

    /// How many shapes the buffer holds, of every sort.
    #[wasm_bindgen(getter)]
    pub fn length(&self) -> usize {
        self.lines.len()
    }

    /// How many shapes were left out since the last `clear()` for a NaN or infinite
    /// coordinate.
    #[wasm_bindgen(getter)]
    pub fn skipped(&self) -> usize {
        self.lines.skipped()
    }

    /// The segments: `x0, y0, x1, y1` each.
    #[wasm_bindgen(getter)]
    pub fn segments(&self) -> Float32Array {
        Float32Array::from(segment_coords(&self.lines).as_slice())
    }

    /// The segments' kinds.
    #[wasm_bindgen(getter, js_name = segmentKinds)]
    pub fn segment_kinds(&self) -> Uint8Array {
        kinds_and_owners(self.lines.segments(), |s| (s.kind, s.owner)).0
    }

    /// The segments' owners.
    #[wasm_bindgen(getter, js_name = segmentOwners)]
    pub fn segment_owners(&self) -> Float64Array {
        kinds_and_owners(self.lines.segments(), |s| (s.kind, s.owner)).1
    }

    /// The circles: `x, y, r` each.
    #[wasm_bindgen(getter)]
    pub fn circles(&self) -> Float32Array {
        Float32Array::from(circle_coords(&self.lines).as_slice())
    }

    /// The circles' kinds.
    #[wasm_bindgen(getter, js_name = circleKinds)]
    pub fn circle_kinds(&self) -> Uint8Array {
        kinds_and_owners(self.lines.circles(), |c| (c.kind, c.owner)).0
    }

    /// The circles' owners.
    #[wasm_bindgen(getter, js_name = circleOwners)]
    pub fn circle_owners(&self) -> Float64Array {
        kinds_and_owners(self.lines.circles(), |c| (c.kind, c.owner)).1
    }

    /// The points: `x, y` each.
    #[wasm_bindgen(getter)]
    pub fn points(&self) -> Float32Array {
        Float32Array::from(point_coords(&self.lines).as_slice())
    }

    /// The points' kinds.
    #[wasm_bindgen(getter, js_name = pointKinds)]
    pub fn point_kinds(&self) -> Uint8Array {
        kinds_and_owners(self.lines.points(), |p| (p.kind, p.owner)).0
    }

    /// The points' owners.
    #[wasm_bindgen(getter, js_name = pointOwners)]
    pub fn point_owners(&self) -> Float64Array {
        kinds_and_owners(self.lines.points(), |p| (p.kind, p.owner)).1
    }

    /// The boxes: `minX, minY, maxX, maxY` each.
    #[wasm_bindgen(getter)]
    pub fn boxes(&self) -> Float32Array {
        Float32Array::from(box_coords(&self.lines).as_slice())
    }

    /// The boxes' kinds.
    #[wasm_bindgen(getter, js_name = boxKinds)]
    pub fn box_kinds(&self) -> Uint8Array {
        kinds_and_owners(self.lines.boxes(), |b| (b.kind, b.owner)).0
    }

    /// The boxes' owners.
    #[wasm_bindgen(getter, js_name = boxOwners)]
    pub fn box_owners(&self) -> Float64Array {
        kinds_and_owners(self.lines.boxes(), |b| (b.kind, b.owner)).1
    }
}

impl DebugLines {
    /// The core buffer, for the other classes' `fillDebugLines(out)` to fill.
    pub fn lines_mut(&mut self) -> &mut tileslide::DebugLines {
        &mut self.lines
    }

    /// The core buffer.
    #[must_use]
    pub fn lines(&self) -> &tileslide::DebugLines {
        &self.lines
    }
}

#[wasm_bindgen]
impl TileMap {
    /// The map's debug lines in a new buffer: active segments, their normals, hidden seam
    /// segments and temporary segments, only in `view` (`[minX, minY, maxX, maxY]`) when
    /// one is given.
    #[wasm_bindgen(js_name = debugLines)]
    pub fn debug_lines(&self, view: Option<Vec<f32>>) -> Result<DebugLines, JsError> {
        let mut out = DebugLines::new();
        out.set_view(view)?;
        self.fill_debug_lines(&mut out);
        Ok(out)
    }

    /// Adds the map's debug lines to `out` (with its view and kinds).
    #[wasm_bindgen(js_name = fillDebugLines)]
    pub fn fill_debug_lines(&self, out: &mut DebugLines) {
        self.map.debug_lines(out.lines_mut());
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use tileslide::io::ascii;

    use super::*;

    #[test]
    fn the_js_kinds_have_the_core_numbers() {
        let js = [
            DebugKind::ActiveSegment,
            DebugKind::OneWaySegment,
            DebugKind::Normal,
            DebugKind::HiddenSegment,
            DebugKind::TemporarySegment,
            DebugKind::Body,
            DebugKind::Character,
            DebugKind::Contact,
            DebugKind::Ray,
            DebugKind::RayHit,
            DebugKind::AttackVolume,
            DebugKind::VulnerabilityVolume,
            DebugKind::Hit,
            DebugKind::RefusedHit,
            DebugKind::Path,
            DebugKind::FlowArrow,
            DebugKind::BroadphaseBox,
        ];
        assert_eq!(js.len(), tileslide::DebugKind::COUNT);
        for (j, core) in js.into_iter().zip(tileslide::DebugKind::ALL) {
            assert_eq!(j as u8, core as u8);
            let camel = format!("{j:?}");
            let snake: String = camel
                .chars()
                .enumerate()
                .flat_map(|(i, c)| {
                    let sep = (i > 0 && c.is_ascii_uppercase()).then_some('_');
                    sep.into_iter()
                        .chain(std::iter::once(c.to_ascii_lowercase()))
                })
                .collect();
            assert_eq!(snake, core.name());
        }
    }

    #[test]
    fn segments_are_four_floats_in_order() {
        let map = ascii::parse("#", "one.txt", 2.0).unwrap();
        let mut lines = tileslide::DebugLines::new();
        map.debug_lines(&mut lines);
        let coords = segment_coords(&lines);
        assert_eq!(coords.len(), 4 * lines.segments().len());
        for (s, c) in lines.segments().iter().zip(coords.chunks(4)) {
            assert_eq!(
                c,
                [s.segment.a.x, s.segment.a.y, s.segment.b.x, s.segment.b.y]
            );
        }
    }

    #[test]
    fn bad_views_and_kinds_are_named() {
        assert!(view_of("setView", &[0.0, 0.0, 1.0, 1.0]).is_ok());
        for bad in [
            &[0.0, 0.0, 1.0][..],
            &[0.0, f32::NAN, 1.0, 1.0],
            &[2.0, 0.0, 1.0, 1.0],
        ] {
            let e = view_of("setView", bad).unwrap_err();
            assert!(e.starts_with("setView: a view is 4 finite numbers"), "{e}");
        }
        assert_eq!(
            kinds_of(&[0, 3]).unwrap(),
            DebugKinds::NONE
                .with(tileslide::DebugKind::ActiveSegment)
                .with(tileslide::DebugKind::HiddenSegment)
        );
        assert_eq!(
            kinds_of(&[200]).unwrap_err(),
            "setKinds: 200 is not a DebugKind"
        );
    }
}
