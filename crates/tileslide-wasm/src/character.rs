//! `Character` for JavaScript: a platformer's box or circle moved through a map. Values are
//! converted here; the move is the core's.

use js_sys::Object;
use tileslide::{CharacterShape, Contact, Contacts, ControllerConfig, MoveOptions, Vec2};
use wasm_bindgen::prelude::*;

use crate::args::{self, Options, error};
use crate::debug::DebugLines;
use crate::map::TileMap;
use crate::values::{object, pair, source_fields};

#[wasm_bindgen(typescript_custom_section)]
const TS_TYPES: &str = r#"
/** A character's shape, centred on its position: a circle, or a box by its half extents. */
export type CharacterShape = { radius: number } | { halfWidth: number; halfHeight: number };

/** How a character moves (every field optional; distances in map units, defaults for cells
 * of size 1). */
export interface ControllerConfig {
    /** The steepest walkable slope, degrees from level, in [0, 90) (default 50). */
    maxSlopeDegrees?: number;
    /** How far below its feet a grounded character looks for ground to stay on (0.3). */
    snapDistance?: number;
    /** The gap kept from every surface it stops against (0.001). */
    skin?: number;
    /** How many times one move may hit a surface and slide on, at least 1 (4). */
    maxSlides?: number;
    /** The highest ledge a walk steps up onto (0: none). */
    stepHeight?: number;
    /** Segment flags that block it (default 3: solid and one-way). */
    mask?: number;
}

/** Requests for one move. */
export interface MoveOptions {
    /** Fall through one-way platforms during this move (hold it until the platform is
     * cleared). */
    dropThrough?: boolean;
}

/** One surface a character touched: its unit normal (pointing towards the character), its
 * segment flags (2: one-way), and where it comes from: a tile's `cell` and `tile`, or a
 * temporary segment's `owner` and `velocity` (a moving platform; zero for a tile). */
export interface Contact {
    nx: number;
    ny: number;
    flags: number;
    cell: [number, number] | null;
    tile: number | null;
    owner: number | null;
    velocity: [number, number];
}

/** What a move did: where the character is, whether it stands on walkable ground, and the
 * surfaces it touched by kind (`ground` under it at the end, the last `ceiling`, `left`
 * and `right` wall met, and `crush` when a moving platform pressed it into the world). */
export interface MoveResult {
    x: number;
    y: number;
    grounded: boolean;
    ground: Contact | null;
    ceiling: Contact | null;
    left: Contact | null;
    right: Contact | null;
    crush: Contact | null;
}

/** `moveAndSlide`'s result: the move's, with the velocity the surfaces leave. */
export interface SlideResult extends MoveResult {
    vx: number;
    vy: number;
}
"#;

/// A platformer character: a box or circle at a position, with an up direction, moved by
/// the displacement the game wants each step (velocity × dt, gravity included). It walks
/// along slopes, snaps to the ground, jumps up through one-way platforms and drops through
/// them on request, rides moving platforms (temporary segments with a velocity); jumps,
/// gravity and coyote time are the game's rules.
#[wasm_bindgen]
pub struct Character {
    character: tileslide::Character,
    /// What the last move touched, for `clipVelocity`.
    last: Contacts,
}

#[wasm_bindgen]
impl Character {
    /// A character of `shape` centred at (`x`, `y`) whose up is `up` (default `[0, -1]`:
    /// y-down maps, as ASCII and Tiled maps are), moving by `config`.
    #[wasm_bindgen(constructor)]
    pub fn new(
        #[wasm_bindgen(unchecked_param_type = "CharacterShape")] shape: JsValue,
        x: f64,
        y: f64,
        #[wasm_bindgen(unchecked_optional_param_type = "[number, number]")] up: Option<JsValue>,
        #[wasm_bindgen(unchecked_optional_param_type = "ControllerConfig")] config: Option<JsValue>,
    ) -> Result<Character, JsError> {
        let shape = character_shape(shape)?;
        let position = args::vec2("Character: position", x, y).map_err(error)?;
        let up = match up.filter(|u| !u.is_undefined() && !u.is_null()) {
            None => Vec2::NEG_Y,
            Some(u) => args::pair("Character: up", &u).map_err(error)?,
        };
        let config = controller_config(config)?;
        let character = tileslide::Character::new(shape, position, up, config).map_err(error)?;
        Ok(Self {
            character,
            last: Contacts::default(),
        })
    }

    /// The x of the shape's centre.
    #[wasm_bindgen(getter)]
    pub fn x(&self) -> f32 {
        self.character.position.x
    }

    /// The y of the shape's centre.
    #[wasm_bindgen(getter)]
    pub fn y(&self) -> f32 {
        self.character.position.y
    }

    /// `[x, y]`: the unit up direction.
    #[wasm_bindgen(getter, unchecked_return_type = "[number, number]")]
    pub fn up(&self) -> JsValue {
        pair(self.character.up())
    }

    /// The ground under the character after its last move, or `null` in the air.
    #[wasm_bindgen(getter, unchecked_return_type = "Contact | null")]
    pub fn ground(&self) -> Result<JsValue, JsError> {
        contact(self.character.ground())
    }

    /// Moves the character to (`x`, `y`) without a sweep, forgetting its ground.
    pub fn teleport(&mut self, x: f64, y: f64) -> Result<(), JsError> {
        let position = args::vec2("teleport: position", x, y).map_err(error)?;
        self.last = Contacts::default();
        self.character.teleport(position).map_err(error)
    }

    /// Moves the character by (`dx`, `dy`) through `map` and its temporary segments, as
    /// far as they let it, and returns where it is and what it touched.
    #[wasm_bindgen(js_name = moveBy, unchecked_return_type = "MoveResult")]
    pub fn move_by(
        &mut self,
        map: &TileMap,
        dx: f64,
        dy: f64,
        #[wasm_bindgen(unchecked_optional_param_type = "MoveOptions")] options: Option<JsValue>,
    ) -> Result<Object, JsError> {
        let displacement = args::vec2("moveBy: displacement", dx, dy).map_err(error)?;
        let options = move_options("moveBy", options)?;
        let contacts = self
            .character
            .move_by(map.inner(), displacement, options)
            .map_err(error)?;
        self.last = contacts;
        self.result(&contacts, &[])
    }

    /// Moves the character by velocity (`vx`, `vy`) × `dt`, then takes out of the velocity
    /// what the surfaces it touched stopped (landing zeroes the fall, a ceiling the rise, a
    /// wall the speed into it): the result's `vx`, `vy`, for the game to keep.
    #[wasm_bindgen(js_name = moveAndSlide, unchecked_return_type = "SlideResult")]
    pub fn move_and_slide(
        &mut self,
        map: &TileMap,
        vx: f64,
        vy: f64,
        dt: f64,
        #[wasm_bindgen(unchecked_optional_param_type = "MoveOptions")] options: Option<JsValue>,
    ) -> Result<Object, JsError> {
        let mut velocity = args::vec2("moveAndSlide: velocity", vx, vy).map_err(error)?;
        let dt = args::finite("moveAndSlide: dt", dt).map_err(error)?;
        let options = move_options("moveAndSlide", options)?;
        let contacts = self
            .character
            .move_and_slide(map.inner(), &mut velocity, dt, options)
            .map_err(error)?;
        self.last = contacts;
        self.result(
            &contacts,
            &[("vx", velocity.x.into()), ("vy", velocity.y.into())],
        )
    }

    /// `[vx, vy]`: the velocity (`vx`, `vy`) without what the surfaces touched in the last
    /// move stop (as `moveAndSlide` does), for a displacement the game made with `moveBy`.
    #[wasm_bindgen(js_name = clipVelocity, unchecked_return_type = "[number, number]")]
    pub fn clip_velocity(&self, vx: f64, vy: f64) -> Result<JsValue, JsError> {
        let velocity = args::vec2("clipVelocity: velocity", vx, vy).map_err(error)?;
        let clipped = self.character.clip_velocity(velocity, &self.last);
        Ok(pair(clipped.map_err(error)?))
    }

    /// Adds the character to `out`: its shape as a `Character` circle or box, and what its
    /// last move (`moveBy` or `moveAndSlide`) touched as `Contact` segments along each
    /// surface's normal, all with `owner` (a whole number; default 0).
    #[wasm_bindgen(js_name = fillDebugLines)]
    pub fn fill_debug_lines(
        &self,
        out: &mut DebugLines,
        owner: Option<f64>,
    ) -> Result<(), JsError> {
        let owner = args::owner("fillDebugLines: owner", owner.unwrap_or(0.0)).map_err(error)?;
        self.character
            .debug_lines(Some(&self.last), owner, out.lines_mut());
        Ok(())
    }

    fn result(&self, contacts: &Contacts, extra: &[(&str, JsValue)]) -> Result<Object, JsError> {
        let p = self.character.position;
        let mut entries = vec![
            ("x", p.x.into()),
            ("y", p.y.into()),
            ("grounded", contacts.is_grounded().into()),
            ("ground", contact(contacts.ground.as_ref())?),
            ("ceiling", contact(contacts.ceiling.as_ref())?),
            ("left", contact(contacts.left.as_ref())?),
            ("right", contact(contacts.right.as_ref())?),
            ("crush", contact(contacts.crush.as_ref())?),
        ];
        entries.extend(extra.iter().cloned());
        object(&entries)
    }
}

/// A contact as `{nx, ny, flags, cell, tile, owner, velocity}`, or `null`.
fn contact(contact: Option<&Contact>) -> Result<JsValue, JsError> {
    let Some(c) = contact else {
        return Ok(JsValue::NULL);
    };
    let mut entries = vec![
        ("nx", c.normal.x.into()),
        ("ny", c.normal.y.into()),
        ("flags", c.flags.0.into()),
    ];
    entries.extend(source_fields(&c.source));
    Ok(object(&entries)?.into())
}

/// The shape `{radius}` or `{halfWidth, halfHeight}`, checked as the core checks it.
fn character_shape(value: JsValue) -> Result<CharacterShape, JsError> {
    let mut options = Options::new("Character: shape", Some(value)).map_err(error)?;
    let radius = options.number("radius").map_err(error)?;
    let half = (
        options.number("halfWidth").map_err(error)?,
        options.number("halfHeight").map_err(error)?,
    );
    options.finish().map_err(error)?;
    match (radius, half) {
        (Some(r), (None, None)) => {
            let r = args::finite("Character: shape radius", r).map_err(error)?;
            CharacterShape::circle(r).map_err(error)
        }
        (None, (Some(w), Some(h))) => {
            let half = args::vec2("Character: shape half extents", w, h).map_err(error)?;
            CharacterShape::rect(half).map_err(error)
        }
        _ => Err(error(
            "Character: shape must be {radius} or {halfWidth, halfHeight}",
        )),
    }
}

/// The `ControllerConfig` an options object asks for (missing fields: the defaults),
/// checked as the core checks it.
fn controller_config(value: Option<JsValue>) -> Result<ControllerConfig, JsError> {
    let d = ControllerConfig::default();
    let mut o = Options::new("controller config", value).map_err(error)?;
    let config = ControllerConfig {
        max_slope_degrees: o
            .f32_or("maxSlopeDegrees", d.max_slope_degrees)
            .map_err(error)?,
        snap_distance: o.f32_or("snapDistance", d.snap_distance).map_err(error)?,
        skin: o.f32_or("skin", d.skin).map_err(error)?,
        max_slides: o.u32_or("maxSlides", d.max_slides).map_err(error)?,
        step_height: o.f32_or("stepHeight", d.step_height).map_err(error)?,
        mask: o.flags_or("mask", d.mask).map_err(error)?,
    };
    o.finish().map_err(error)?;
    config.validate().map_err(error)?;
    Ok(config)
}

/// `{dropThrough}`.
fn move_options(what: &str, value: Option<JsValue>) -> Result<MoveOptions, JsError> {
    let mut o = Options::new(format!("{what}: options"), value).map_err(error)?;
    let drop_through = o.bool_or("dropThrough", false).map_err(error)?;
    o.finish().map_err(error)?;
    Ok(MoveOptions { drop_through })
}
