//! `NavGrid` and `FlowField` for JavaScript: paths for circles of a radius, and flow fields
//! that lead many agents to one goal. Values are converted here; the searches are the
//! core's.

use js_sys::{Array, Float32Array, Object};
use tileslide::{DebugKind, NavConfig, NavError, Segment, Vec2};
use wasm_bindgen::prelude::*;

use crate::args::{self, Options, error};
use crate::debug::DebugLines;
use crate::map::TileMap;
use crate::values::{object, pair};

#[wasm_bindgen(typescript_custom_section)]
const TS_TYPES: &str = r#"
/** How a `NavGrid` is built (every field optional). */
export interface NavConfig {
    /** The widest circle the grid serves, in map units (default 1); at most 31 cells. */
    maxRadius?: number;
    /** Segment flags that block (default 3: solid, and one-way platforms from the front). */
    mask?: number;
}

/** What the map's edits changed in a `NavGrid` since it last caught up. */
export interface NavChange {
    /** Moves whose clearance changed (0 after a rebuild). */
    changedMoves: number;
    /** True when the grid was built anew (too many edits behind): every path is affected. */
    rebuilt: boolean;
    /** `[minX, minY, maxX, maxY]` of the changed moves, or null when none changed. */
    region: [number, number, number, number] | null;
}
"#;

/// Navigation data for one map: move clearances on a half-cell lattice. Paths and flow
/// fields are for circles of a radius up to `maxRadius`. Every query takes the map: after
/// editing it (`setTile`), call `sync(map)` before the next query (until then queries throw
/// that the grid is behind the map).
#[wasm_bindgen]
pub struct NavGrid {
    nav: tileslide::NavGrid,
}

#[wasm_bindgen]
impl NavGrid {
    /// The navigation grid of `map`, built by `config`.
    #[wasm_bindgen(constructor)]
    pub fn new(
        map: &TileMap,
        #[wasm_bindgen(unchecked_optional_param_type = "NavConfig")] config: Option<JsValue>,
    ) -> Result<NavGrid, JsError> {
        let d = NavConfig::default();
        let mut o = Options::new("nav config", config).map_err(error)?;
        let config = NavConfig {
            max_radius: o.f32_or("maxRadius", d.max_radius).map_err(error)?,
            mask: o.flags_or("mask", d.mask).map_err(error)?,
        };
        o.finish().map_err(error)?;
        let nav = tileslide::NavGrid::new(map.inner(), config).map_err(error)?;
        Ok(Self { nav })
    }

    /// The widest circle the grid serves.
    #[wasm_bindgen(getter, js_name = maxRadius)]
    pub fn max_radius(&self) -> f32 {
        self.nav.max_radius()
    }

    /// The shortest path for a circle of `radius` from (`fromX`, `fromY`) to (`toX`,
    /// `toY`), smoothed into straight runs each clear of walls: 2 floats a point (`x, y`),
    /// from the start to the goal; `null` when the circle does not fit at an end or cannot
    /// get from one to the other.
    #[wasm_bindgen(js_name = findPath, unchecked_return_type = "Float32Array | null")]
    #[allow(clippy::too_many_arguments)]
    pub fn find_path(
        &self,
        map: &TileMap,
        #[wasm_bindgen(js_name = fromX)] from_x: f64,
        #[wasm_bindgen(js_name = fromY)] from_y: f64,
        #[wasm_bindgen(js_name = toX)] to_x: f64,
        #[wasm_bindgen(js_name = toY)] to_y: f64,
        radius: f64,
    ) -> Result<JsValue, JsError> {
        let from = args::vec2("findPath: from", from_x, from_y).map_err(error)?;
        let to = args::vec2("findPath: to", to_x, to_y).map_err(error)?;
        let radius = args::finite("findPath: radius", radius).map_err(error)?;
        let path = self
            .nav
            .find_path(map.inner(), from, to, radius)
            .map_err(nav_error("findPath"))?;
        Ok(path.map_or(JsValue::NULL, |p| {
            let flat: Vec<f32> = p.points().iter().flat_map(|v| [v.x, v.y]).collect();
            Float32Array::from(flat.as_slice()).into()
        }))
    }

    /// Adds the legs of a path `findPath` found (`points`: 2 floats a point, `x, y`) to
    /// `out` as `Path` segments from the start to the goal, with `owner` (a whole number;
    /// default 0), as the core's `NavPath` draws itself.
    #[wasm_bindgen(js_name = fillPathDebugLines)]
    pub fn fill_path_debug_lines(
        points: &[f32],
        out: &mut DebugLines,
        owner: Option<f64>,
    ) -> Result<(), JsError> {
        const CALL: &str = "fillPathDebugLines";
        let owner = args::owner(&format!("{CALL}: owner"), owner.unwrap_or(0.0)).map_err(error)?;
        if !points.len().is_multiple_of(2) {
            return Err(error(format!(
                "{CALL}: {} floats is not a whole number of points (2 a point: x, y)",
                points.len()
            )));
        }
        if let Some(i) = points.iter().position(|v| !v.is_finite()) {
            return Err(error(format!(
                "{CALL}: point {}.{} is {}, not a finite number",
                i / 2,
                ["x", "y"][i % 2],
                points[i]
            )));
        }
        let lines = out.lines_mut();
        for leg in points.chunks_exact(2).collect::<Vec<_>>().windows(2) {
            let (a, b) = (
                Vec2::new(leg[0][0], leg[0][1]),
                Vec2::new(leg[1][0], leg[1][1]),
            );
            lines.push_segment(DebugKind::Path, Segment::new(a, b), owner);
        }
        Ok(())
    }

    /// True when a circle of `radius` fits at (`x`, `y`), clear of walls.
    pub fn fits(&self, map: &TileMap, x: f64, y: f64, radius: f64) -> Result<bool, JsError> {
        let p = args::vec2("fits: point", x, y).map_err(error)?;
        let radius = args::finite("fits: radius", radius).map_err(error)?;
        self.nav
            .fits(map.inner(), p, radius)
            .map_err(nav_error("fits"))
    }

    /// Catches up with `map`'s tile edits since the grid was built or last synced, and
    /// says what changed.
    #[wasm_bindgen(unchecked_return_type = "NavChange")]
    pub fn sync(&mut self, map: &TileMap) -> Result<Object, JsError> {
        let change = self.nav.sync(map.inner()).map_err(nav_error("sync"))?;
        let region = change.region().map_or(JsValue::NULL, |r| {
            let a = Array::of2(&r.min.x.into(), &r.min.y.into());
            a.push(&r.max.x.into());
            a.push(&r.max.y.into());
            a.into()
        });
        object(&[
            ("changedMoves", (change.changed_moves() as f64).into()),
            ("rebuilt", change.is_rebuild().into()),
            ("region", region),
        ])
    }
}

/// Distances to one goal for circles of one radius, over a whole map: every agent asks it
/// which way to go. After the map is edited and the grid synced, `sync` the field too.
#[wasm_bindgen]
pub struct FlowField {
    field: tileslide::FlowField,
}

#[wasm_bindgen]
impl FlowField {
    /// The field of the goal (`goalX`, `goalY`) for circles of `radius` on `map`, whose
    /// grid is `nav`.
    #[wasm_bindgen(constructor)]
    pub fn new(
        nav: &NavGrid,
        map: &TileMap,
        #[wasm_bindgen(js_name = goalX)] goal_x: f64,
        #[wasm_bindgen(js_name = goalY)] goal_y: f64,
        radius: f64,
    ) -> Result<FlowField, JsError> {
        let goal = args::vec2("FlowField: goal", goal_x, goal_y).map_err(error)?;
        let radius = args::finite("FlowField: radius", radius).map_err(error)?;
        let field = tileslide::FlowField::new(&nav.nav, map.inner(), goal, radius)
            .map_err(nav_error("FlowField"))?;
        Ok(Self { field })
    }

    /// `[x, y]`: the goal.
    #[wasm_bindgen(getter, unchecked_return_type = "[number, number]")]
    pub fn goal(&self) -> JsValue {
        pair(self.field.goal())
    }

    /// The radius of the circles it leads.
    #[wasm_bindgen(getter)]
    pub fn radius(&self) -> f32 {
        self.field.radius()
    }

    /// `[dx, dy]`: the unit direction a circle at (`x`, `y`) should move in to reach the
    /// goal, or `null` when it cannot reach it or is on it.
    #[wasm_bindgen(unchecked_return_type = "[number, number] | null")]
    pub fn direction(
        &self,
        nav: &NavGrid,
        map: &TileMap,
        x: f64,
        y: f64,
    ) -> Result<JsValue, JsError> {
        let p = args::vec2("direction: point", x, y).map_err(error)?;
        let dir = self
            .field
            .direction(&nav.nav, map.inner(), p)
            .map_err(nav_error("direction"))?;
        Ok(dir.map_or(JsValue::NULL, pair))
    }

    /// The directions at many points at once: `points` holds 2 floats a point (`x, y`);
    /// the answer 2 a point (`dx, dy`), both NaN where `direction` is `null`.
    pub fn directions(
        &self,
        nav: &NavGrid,
        map: &TileMap,
        points: &[f32],
    ) -> Result<Float32Array, JsError> {
        self.each_point("directions", points, |p| {
            self.field.direction(&nav.nav, map.inner(), p)
        })
    }

    /// `[dx, dy]`: a cheap direction for a circle at (`x`, `y`), along the field's lattice
    /// moves with no straight-line checks (a few array reads, where `direction` checks a
    /// dozen lines against the walls): for crowds of thousands that ask every step. It
    /// steers along 45° moves rather than cutting corners, and may press a circle against
    /// a corner for a resolver (`Bodies`) to slide it round. `null` when no node around
    /// the point reaches the goal, or on the goal.
    #[wasm_bindgen(js_name = latticeDirection, unchecked_return_type = "[number, number] | null")]
    pub fn lattice_direction(
        &self,
        nav: &NavGrid,
        map: &TileMap,
        x: f64,
        y: f64,
    ) -> Result<JsValue, JsError> {
        let p = args::vec2("latticeDirection: point", x, y).map_err(error)?;
        let dir = self
            .field
            .lattice_direction(&nav.nav, map.inner(), p)
            .map_err(nav_error("latticeDirection"))?;
        Ok(dir.map_or(JsValue::NULL, pair))
    }

    /// `latticeDirection` at many points at once: `points` holds 2 floats a point
    /// (`x, y`); the answer 2 a point (`dx, dy`), both NaN where it is `null`.
    #[wasm_bindgen(js_name = latticeDirections)]
    pub fn lattice_directions(
        &self,
        nav: &NavGrid,
        map: &TileMap,
        points: &[f32],
    ) -> Result<Float32Array, JsError> {
        self.each_point("latticeDirections", points, |p| {
            self.field.lattice_direction(&nav.nav, map.inner(), p)
        })
    }

    /// The length of the way from (`x`, `y`) to the goal along the field (map units), or
    /// `null` if a circle there cannot reach it.
    #[wasm_bindgen(unchecked_return_type = "number | null")]
    pub fn distance(
        &self,
        nav: &NavGrid,
        map: &TileMap,
        x: f64,
        y: f64,
    ) -> Result<JsValue, JsError> {
        let p = args::vec2("distance: point", x, y).map_err(error)?;
        let distance = self
            .field
            .distance(&nav.nav, map.inner(), p)
            .map_err(nav_error("distance"))?;
        Ok(distance.map_or(JsValue::NULL, JsValue::from))
    }

    /// Adds the field's next move out of every lattice node that reaches the goal to `out`,
    /// as `FlowArrow` segments from the node half of the way to the next node (or towards
    /// the goal); with a view set on `out`, only the nodes in it. `nav` is the grid the
    /// field was made on; for another grid nothing is added.
    #[wasm_bindgen(js_name = fillDebugLines)]
    pub fn fill_debug_lines(&self, nav: &NavGrid, out: &mut DebugLines) {
        self.field.debug_lines(&nav.nav, out.lines_mut());
    }

    /// Catches up with the map's edits once `nav` has (`nav.sync(map)`); true when the
    /// field was recomputed (its directions may then differ).
    pub fn sync(&mut self, nav: &NavGrid, map: &TileMap) -> Result<bool, JsError> {
        self.field
            .sync(&nav.nav, map.inner())
            .map_err(nav_error("FlowField.sync"))
    }
}

impl FlowField {
    /// `direction` at each point of `points` (2 floats a point), as 2 floats a point, NaN
    /// for `None`; an error names `call` and the point (formatted only then: a crowd asks
    /// every step).
    fn each_point(
        &self,
        call: &str,
        points: &[f32],
        direction: impl Fn(Vec2) -> Result<Option<Vec2>, NavError>,
    ) -> Result<Float32Array, JsError> {
        if !points.len().is_multiple_of(2) {
            return Err(error(format!(
                "{call}: {} floats is not a whole number of points (2 a point: x, y)",
                points.len()
            )));
        }
        let mut out = Vec::with_capacity(points.len());
        for (i, p) in points.chunks_exact(2).enumerate() {
            let what = || format!("{call}: point {i}");
            let p = Vec2::new(p[0], p[1]);
            if !p.is_finite() {
                // Names the coordinate as the one-point calls do.
                args::vec2(&what(), f64::from(p.x), f64::from(p.y)).map_err(error)?;
            }
            let dir = direction(p)
                .map_err(|e| error(format!("{}: {e}", what())))?
                .unwrap_or(Vec2::NAN);
            out.extend_from_slice(&[dir.x, dir.y]);
        }
        Ok(Float32Array::from(out.as_slice()))
    }
}

/// A navigation error as an `Error` naming the call.
fn nav_error(call: &str) -> impl Fn(NavError) -> JsError + '_ {
    move |e| error(format!("{call}: {e}"))
}
