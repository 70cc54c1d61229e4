//! `Bodies` for JavaScript: circles and compounds of circles that slide around each other
//! and along walls. Values are converted here; the handle table and packing are in
//! [`crate::body_set`], what a step does in the core.

use js_sys::{Float32Array, Float64Array, Object, WebAssembly};
use tileslide::broadphase::PairMethod;
use tileslide::{
    BodyDesc, BodyFilter, BodyShape, Circle, Owner, ResolveConfig, ResolveReport, SlideMode,
};
use wasm_bindgen::prelude::*;

use crate::args::{self, Options, error};
use crate::body_set::BodySet;
use crate::debug::DebugLines;
use crate::map::TileMap;
use crate::values::{object, pair};

#[wasm_bindgen(typescript_custom_section)]
const TS_TYPES: &str = r#"
/** How `Bodies` resolves moves (every field optional; distances in map units). */
export interface ResolveConfig {
    /** What happens to the blocked part of a move: `"fullLength"` (the default: redirected
     * along the contact with its whole length), `"tangential"` (only its part along the
     * contact) or `"stop"`. */
    slide?: "fullLength" | "tangential" | "stop";
    /** Passes of detect-and-slide, 0 to 64 (default 4). */
    passes?: number;
    /** Pair finding: `"uniformGrid"` (the default) or `"sweepAndPrune"`. */
    broadphase?: "uniformGrid" | "sweepAndPrune";
    /** The separation moving bodies keep, 0 up to the coordinate range (default 0.001:
     * scale it with the cell size). */
    gap?: number;
}

/** Which bodies a body collides with (two collide when each one's `groups` meets the
 * other's `collidesWith`), and which wall segments stop it (bits of segment flags: 1 solid,
 * 2 one-way). */
export interface BodyFilter {
    groups?: number;
    collidesWith?: number;
    walls?: number;
}

/** What `addCircle` and `addCompound` take besides the shape. */
export interface BodyOptions {
    filter?: BodyFilter;
    /** The game's entity, a whole number (default 0); tileslide never reads it. */
    owner?: number;
}

/** What a `resolve` or `step` did. */
export interface ResolveReport {
    /** Bodies with a non-zero proposed move. */
    moving: number;
    /** Contacts met (each sweep that stopped at something counts once). */
    contactCount: number;
    /** Bodies whose remainder was still blocked after the last pass, cut at first contact. */
    cutShort: number;
}
"#;

/// Free-moving bodies (circles and compounds of circles): each step, `propose` a move per
/// body, then `step(map)` resolves the moves against each other and the map's walls (no
/// overlap, no tunnelling; blocked moves slide) and makes them.
///
/// A body is named by a handle number from `addCircle`/`addCompound`; a removed body's
/// handle is stale for good (an `Error`, never another body).
#[wasm_bindgen]
pub struct Bodies {
    pub(crate) set: BodySet,
}

#[wasm_bindgen]
impl Bodies {
    /// No bodies, resolved with `config` (see `ResolveConfig`; defaults suit cells of
    /// size 1).
    #[wasm_bindgen(constructor)]
    pub fn new(
        #[wasm_bindgen(unchecked_optional_param_type = "ResolveConfig")] config: Option<JsValue>,
    ) -> Result<Bodies, JsError> {
        let config = resolve_config(config)?;
        Ok(Self {
            set: BodySet::new(config).map_err(error)?,
        })
    }

    /// Changes the resolve settings (the fields given; the others keep their defaults).
    #[wasm_bindgen(js_name = setConfig)]
    pub fn set_config(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "ResolveConfig")] config: JsValue,
    ) -> Result<(), JsError> {
        let config = resolve_config(Some(config))?;
        self.set.bodies.set_config(config).map_err(error)
    }

    /// Adds a circle of `radius` centred at (`x`, `y`) and returns its handle.
    #[wasm_bindgen(js_name = addCircle)]
    pub fn add_circle(
        &mut self,
        x: f64,
        y: f64,
        radius: f64,
        #[wasm_bindgen(unchecked_optional_param_type = "BodyOptions")] options: Option<JsValue>,
    ) -> Result<f64, JsError> {
        let radius = args::finite("addCircle: radius", radius).map_err(error)?;
        let shape = BodyShape::circle(radius).map_err(error)?;
        self.add("addCircle", x, y, shape, options)
    }

    /// Adds a compound body at (`x`, `y`): `circles` holds 3 numbers a circle (the
    /// centre's offset from the body's position, then the radius). Returns its handle.
    #[wasm_bindgen(js_name = addCompound)]
    pub fn add_compound(
        &mut self,
        x: f64,
        y: f64,
        circles: &[f64],
        #[wasm_bindgen(unchecked_optional_param_type = "BodyOptions")] options: Option<JsValue>,
    ) -> Result<f64, JsError> {
        if !circles.len().is_multiple_of(3) {
            return Err(error(format!(
                "addCompound: {} numbers is not a whole number of circles (3 a circle: dx, dy, radius)",
                circles.len()
            )));
        }
        let circles = circles
            .chunks_exact(3)
            .enumerate()
            .map(|(i, c)| {
                let what = format!("addCompound: circle {i}");
                let offset = args::vec2(&format!("{what} offset"), c[0], c[1])?;
                let radius = args::finite(&format!("{what} radius"), c[2])?;
                Ok(Circle::new(offset, radius))
            })
            .collect::<Result<Vec<_>, String>>()
            .map_err(error)?;
        let shape = BodyShape::compound(circles).map_err(error)?;
        self.add("addCompound", x, y, shape, options)
    }

    fn add(
        &mut self,
        what: &str,
        x: f64,
        y: f64,
        shape: BodyShape,
        options: Option<JsValue>,
    ) -> Result<f64, JsError> {
        let position = args::vec2(&format!("{what}: position"), x, y).map_err(error)?;
        let mut options = Options::new(format!("{what}: options"), options).map_err(error)?;
        let filter = body_filter(options.nested("filter").map_err(error)?)?;
        let owner = options.owner_or("owner", Owner(0)).map_err(error)?;
        options.finish().map_err(error)?;
        let desc = BodyDesc::new(position, shape)
            .with_filter(filter)
            .with_owner(owner);
        self.set.add(desc).map_err(error)
    }

    /// Removes `handle`'s body; the handle is stale from now on.
    pub fn remove(&mut self, handle: f64) -> Result<(), JsError> {
        self.set.remove(handle).map_err(error)
    }

    /// True while `handle`'s body exists.
    pub fn contains(&self, handle: f64) -> bool {
        self.set.core(handle).is_ok()
    }

    /// Number of bodies.
    #[wasm_bindgen(getter)]
    pub fn count(&self) -> usize {
        self.set.bodies.len()
    }

    /// Sets the move (`dx`, `dy`) `handle`'s body wants to make this step (zero: it stays
    /// and others slide around it).
    pub fn propose(&mut self, handle: f64, dx: f64, dy: f64) -> Result<(), JsError> {
        let motion = args::vec2("propose: move", dx, dy).map_err(error)?;
        self.set.propose(handle, motion).map_err(error)
    }

    /// Proposes many moves at once: `moves` holds 2 floats (`dx, dy`) for each handle of
    /// `handles`. An error names the first bad entry; the entries before it are proposed.
    #[wasm_bindgen(js_name = proposeMany)]
    pub fn propose_many(&mut self, handles: &[f64], moves: &[f32]) -> Result<(), JsError> {
        self.set.propose_many(handles, moves).map_err(error)
    }

    /// Moves `handle`'s body to (`x`, `y`) without collision (a teleport).
    #[wasm_bindgen(js_name = setPosition)]
    pub fn set_position(&mut self, handle: f64, x: f64, y: f64) -> Result<(), JsError> {
        let position = args::vec2("setPosition: position", x, y).map_err(error)?;
        let core = self.set.core(handle).map_err(error)?;
        self.set.bodies.set_position(core, position).map_err(error)
    }

    /// Changes `handle`'s body's filter (the fields given; the others keep their defaults).
    #[wasm_bindgen(js_name = setFilter)]
    pub fn set_filter(
        &mut self,
        handle: f64,
        #[wasm_bindgen(unchecked_param_type = "BodyFilter")] filter: JsValue,
    ) -> Result<(), JsError> {
        let filter = body_filter(Options::new("setFilter: filter", Some(filter)).map_err(error)?)?;
        let core = self.set.core(handle).map_err(error)?;
        self.set.bodies.set_filter(core, filter).map_err(error)
    }

    /// Changes `handle`'s body's owner.
    #[wasm_bindgen(js_name = setOwner)]
    pub fn set_owner(&mut self, handle: f64, owner: f64) -> Result<(), JsError> {
        let owner = args::owner("setOwner: owner", owner).map_err(error)?;
        let core = self.set.core(handle).map_err(error)?;
        self.set.bodies.set_owner(core, owner).map_err(error)
    }

    /// `[x, y]`: where `handle`'s body is.
    #[wasm_bindgen(unchecked_return_type = "[number, number]")]
    pub fn position(&self, handle: f64) -> Result<JsValue, JsError> {
        let core = self.set.core(handle).map_err(error)?;
        Ok(pair(self.set.bodies.get(core).map_err(error)?.position()))
    }

    /// `[dx, dy]`: the move `resolve` settled on for `handle`'s body (before `resolve`,
    /// the proposed move).
    #[wasm_bindgen(js_name = resolvedMove, unchecked_return_type = "[number, number]")]
    pub fn resolved_move(&self, handle: f64) -> Result<JsValue, JsError> {
        let core = self.set.core(handle).map_err(error)?;
        Ok(pair(
            self.set.bodies.get(core).map_err(error)?.resolved_move(),
        ))
    }

    /// The owner of `handle`'s body.
    pub fn owner(&self, handle: f64) -> Result<f64, JsError> {
        let core = self.set.core(handle).map_err(error)?;
        Ok(self.set.bodies.get(core).map_err(error)?.owner().0 as f64)
    }

    /// Adjusts every proposed move so that, made together, no two bodies overlap and none
    /// crosses a wall of `map` (read them with `resolvedMove`; `integrate` makes them).
    #[wasm_bindgen(unchecked_return_type = "ResolveReport")]
    pub fn resolve(&mut self, map: &TileMap) -> Result<Object, JsError> {
        report(&self.set.resolve(map.inner()))
    }

    /// Every body makes its resolved move; proposed moves are cleared.
    pub fn integrate(&mut self) {
        self.set.bodies.integrate();
    }

    /// `resolve` then `integrate`: one whole step.
    #[wasm_bindgen(unchecked_return_type = "ResolveReport")]
    pub fn step(&mut self, map: &TileMap) -> Result<Object, JsError> {
        report(&self.set.step(map.inner()))
    }

    /// Adds every body to `out`: each circle of its shape as a `Body` circle with the
    /// body's owner, and (after a step, until a body is added, removed or changed) the box
    /// the broadphase filed that circle under, as a `BroadphaseBox`. The resolver keeps no
    /// contacts between bodies, so there are none to draw.
    #[wasm_bindgen(js_name = fillDebugLines)]
    pub fn fill_debug_lines(&self, out: &mut DebugLines) {
        self.set.bodies.debug_lines(out.lines_mut());
    }

    /// A copy of every body's position, 2 floats a body (`x, y`) in the order of
    /// `handles()` (slot order, the order of the resolve).
    pub fn positions(&mut self) -> Float32Array {
        Float32Array::from(self.set.positions())
    }

    /// The same positions without a copy: a view of the package's memory, refreshed by this
    /// call. It is invalidated by the next call into the package that may grow its
    /// memory (adding bodies, loading a map, any call that returns an array or object):
    /// read it at once, or call `positions()` for a copy to keep.
    #[wasm_bindgen(js_name = positionsView)]
    pub fn positions_view(&mut self) -> Result<Float32Array, JsError> {
        let positions = self.set.positions();
        let start = u32::try_from(positions.as_ptr() as usize)
            .map_err(|_| error("positionsView: memory beyond 4 GiB"))?;
        let length = u32::try_from(positions.len())
            .map_err(|_| error("positionsView: too many bodies for a view"))?;
        let memory: WebAssembly::Memory = wasm_bindgen::memory().unchecked_into();
        Ok(Float32Array::new_with_byte_offset_and_length(
            &memory.buffer(),
            start,
            length,
        ))
    }

    /// Every body's handle, in slot order (the order of `positions()`).
    pub fn handles(&self) -> Float64Array {
        Float64Array::from(self.set.handles().as_slice())
    }
}

/// The `ResolveConfig` an options object asks for (missing fields: the defaults), checked
/// as the core checks it.
fn resolve_config(value: Option<JsValue>) -> Result<ResolveConfig, JsError> {
    let defaults = ResolveConfig::default();
    let mut options = Options::new("resolve config", value).map_err(error)?;
    let slide = match options.string("slide").map_err(error)?.as_deref() {
        None => defaults.slide,
        Some("fullLength") => SlideMode::FullLength,
        Some("tangential") => SlideMode::Tangential,
        Some("stop") => SlideMode::Stop,
        Some(other) => {
            return Err(error(format!(
                "resolve config: `slide` is \"{other}\", not \"fullLength\", \"tangential\" or \"stop\""
            )));
        }
    };
    let broadphase = match options.string("broadphase").map_err(error)?.as_deref() {
        None => defaults.broadphase,
        Some("uniformGrid") => PairMethod::UniformGrid,
        Some("sweepAndPrune") => PairMethod::SweepAndPrune,
        Some(other) => {
            return Err(error(format!(
                "resolve config: `broadphase` is \"{other}\", not \"uniformGrid\" or \"sweepAndPrune\""
            )));
        }
    };
    let passes = options.u32_or("passes", defaults.passes).map_err(error)?;
    let gap = options.f32_or("gap", defaults.gap).map_err(error)?;
    options.finish().map_err(error)?;
    let config = ResolveConfig {
        slide,
        passes,
        broadphase,
        gap,
    };
    config.validate().map_err(error)?;
    Ok(config)
}

/// The `BodyFilter` of a filter object (missing fields: the defaults).
fn body_filter(mut options: Options) -> Result<BodyFilter, JsError> {
    let defaults = BodyFilter::default();
    let filter = BodyFilter {
        groups: options.u32_or("groups", defaults.groups).map_err(error)?,
        collides_with: options
            .u32_or("collidesWith", defaults.collides_with)
            .map_err(error)?,
        walls: options.flags_or("walls", defaults.walls).map_err(error)?,
    };
    options.finish().map_err(error)?;
    Ok(filter)
}

/// `{moving, contactCount, cutShort}`.
fn report(report: &ResolveReport) -> Result<Object, JsError> {
    object(&[
        ("moving", (report.moving as f64).into()),
        ("contactCount", (report.contact_count as f64).into()),
        ("cutShort", (report.cut_short as f64).into()),
    ])
}
