//! `HitWorld` for JavaScript: attack and vulnerability volumes registered frame by frame,
//! and the hits between them. Values are converted here; the tests are the core's.

use js_sys::{Array, Function};
use tileslide::broadphase::PairMethod;
use tileslide::{Facing, HitObject, HitTypes, ObjectId, TeamRule, Vec2, Volume};
use wasm_bindgen::prelude::*;

use crate::args::{self, Options, error};
use crate::debug::DebugLines;
use crate::values::{object, owner_number};

#[wasm_bindgen(typescript_custom_section)]
const TS_TYPES: &str = r#"
/** An object registered for one frame: who it is, where its volumes' local origin is at the
 * end of the frame, its size (volumes are mirrored about it), and optionally how far it
 * moved this frame (its volumes are swept along it), which way it faces, its team, whether
 * it refuses hits, and the swing it is making (each victim is hit at most once per swing). */
export interface HitObjectDesc {
    owner: number;
    x: number;
    y: number;
    size: [number, number];
    motion?: [number, number];
    flipX?: boolean;
    flipY?: boolean;
    team?: number;
    invulnerable?: boolean;
    swing?: number | null;
}

/** A volume in object-local coordinates: a circle or a box (centre and half extents), with
 * the hit types (bits of `HitType`) it deals (attack) or accepts (vulnerability). */
export type VolumeDesc =
    | { x: number; y: number; radius: number; hit: number }
    | { x: number; y: number; halfWidth: number; halfHeight: number; hit: number };

/** One hit: an attack volume of `attacker` met a vulnerability volume of `victim` (ids from
 * `register`, with the owners they were registered with) accepting `hitType`; `accepted`
 * says whether the rule let the victim take it. `t` is when the volumes first touched, as a
 * fraction of the frame's move (0 for volumes that overlap where the frame starts; of a
 * fireball's victims the least `t` is the first it reached), `[x, y]` where. */
export interface HitEvent {
    attacker: number;
    victim: number;
    attackerOwner: number;
    victimOwner: number;
    hitType: number;
    accepted: boolean;
    t: number;
    x: number;
    y: number;
}
"#;

/// Hit types, bits a volume deals or accepts (combine them with `|`; `0xFFFFFFFF` accepts
/// any).
#[wasm_bindgen]
#[derive(Clone, Copy, Debug)]
pub enum HitType {
    /// An ordinary hit.
    Hit = 1,
    /// Instant death.
    Death = 2,
    /// Picking up.
    Collect = 4,
    /// Taking control.
    Possess = 8,
    /// Pressing (a button).
    Depress = 16,
    /// Launching.
    Launch = 32,
}

/// Attack and vulnerability volumes of the objects of one frame, and the hits between them.
/// Each frame: `beginFrame()`, `register` every object with the volumes of its current
/// animation frame, then `detect()`. Events come in a fixed order (by pair in registration
/// order, then each direction).
#[wasm_bindgen]
pub struct HitWorld {
    world: tileslide::HitWorld,
}

#[wasm_bindgen]
impl HitWorld {
    /// An empty world; `broadphase` is `"sweepAndPrune"` (the default) or `"uniformGrid"`
    /// (the results are the same either way).
    #[wasm_bindgen(constructor)]
    pub fn new(
        #[wasm_bindgen(unchecked_optional_param_type = "\"sweepAndPrune\" | \"uniformGrid\"")]
        broadphase: Option<String>,
    ) -> Result<HitWorld, JsError> {
        let method = match broadphase.as_deref() {
            None | Some("sweepAndPrune") => PairMethod::SweepAndPrune,
            Some("uniformGrid") => PairMethod::UniformGrid,
            Some(other) => {
                return Err(error(format!(
                    "HitWorld: broadphase is \"{other}\", not \"sweepAndPrune\" or \"uniformGrid\""
                )));
            }
        };
        Ok(Self {
            world: tileslide::HitWorld::with_broadphase(method),
        })
    }

    /// Starts a frame: forgets the last frame's objects and ends the swings nobody
    /// registered in it.
    #[wasm_bindgen(js_name = beginFrame)]
    pub fn begin_frame(&mut self) {
        self.world.begin_frame();
    }

    /// Registers an object for this frame with its attack and vulnerability volumes, and
    /// returns its id for this frame (0, 1, 2, … in registration order).
    pub fn register(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "HitObjectDesc")] object: JsValue,
        #[wasm_bindgen(unchecked_param_type = "VolumeDesc[]")] attack: JsValue,
        #[wasm_bindgen(unchecked_param_type = "VolumeDesc[]")] vulnerable: JsValue,
    ) -> Result<u32, JsError> {
        let object = hit_object(object)?;
        let attack = volumes("register: attack", &attack)?;
        let vulnerable = volumes("register: vulnerable", &vulnerable)?;
        let id = self
            .world
            .register(object, &attack, &vulnerable)
            .map_err(error)?;
        Ok(id.0)
    }

    /// Adds this frame's objects to `out`, in the order they were registered: each attack
    /// volume as an `AttackVolume` circle or box, each vulnerability volume as a
    /// `VulnerabilityVolume`, and the box everything it sweeps during the frame as a
    /// `BroadphaseBox`, with the object's owner; then the last `detect`'s events where each
    /// hit happened, as `Hit` or `RefusedHit` points with the victim's owner.
    #[wasm_bindgen(js_name = fillDebugLines)]
    pub fn fill_debug_lines(&self, out: &mut DebugLines) {
        self.world.debug_lines(out.lines_mut());
    }

    /// Finds this frame's hits and returns them. Without `rule`, a victim takes hits from
    /// other teams while it is not invulnerable; with it, `rule(attacker, victim, hitType)`
    /// decides (an exception it throws is rethrown after the detection, the hit refused).
    #[wasm_bindgen(unchecked_return_type = "HitEvent[]")]
    pub fn detect(
        &mut self,
        #[wasm_bindgen(
            unchecked_optional_param_type = "(attacker: number, victim: number, hitType: number) => boolean"
        )]
        rule: Option<Function>,
    ) -> Result<Array, JsError> {
        let events = match rule {
            None => self.world.detect(&mut TeamRule).to_vec(),
            Some(rule) => {
                let mut thrown: Option<JsValue> = None;
                // The core's rule sees objects; JavaScript's sees their ids. The objects it is
                // shown are the world's own (the core passes references into its list), so
                // their addresses name them.
                let ids: Vec<*const HitObject> = (0..)
                    .map_while(|i| self.world.object(ObjectId(i)).map(std::ptr::from_ref))
                    .collect();
                let id_of = |o: &HitObject| {
                    ids.iter()
                        .position(|&p| std::ptr::eq(p, o))
                        .map_or(JsValue::NULL, |i| JsValue::from_f64(i as f64))
                };
                let mut ask = |a: &HitObject, v: &HitObject, hit: HitTypes| {
                    if thrown.is_some() {
                        return false;
                    }
                    match rule.call3(&JsValue::NULL, &id_of(a), &id_of(v), &hit.bits().into()) {
                        Ok(answer) => answer.is_truthy(),
                        Err(e) => {
                            thrown = Some(e);
                            false
                        }
                    }
                };
                let events = self.world.detect(&mut ask).to_vec();
                if let Some(e) = thrown {
                    let message = e
                        .dyn_ref::<js_sys::Error>()
                        .map_or_else(|| format!("{e:?}"), |e| String::from(e.message()));
                    return Err(error(format!("detect: the rule threw: {message}")));
                }
                events
            }
        };
        event_array(&events)
    }

    /// The last `detect`'s events, kept until the next `detect` (`beginFrame` and
    /// `register` leave them). Their `attacker` and `victim` number the objects of the frame
    /// `detect` ran in; the owners still say who they were once a new frame has begun.
    #[wasm_bindgen(unchecked_return_type = "HitEvent[]")]
    pub fn events(&self) -> Result<Array, JsError> {
        event_array(self.world.events())
    }

    /// The owner of the object registered as `id` this frame, or `null`.
    #[wasm_bindgen(unchecked_return_type = "number | null")]
    pub fn owner(&self, id: f64) -> Result<JsValue, JsError> {
        let id = args::whole("owner: id", id).map_err(error)?;
        Ok(self
            .world
            .object(ObjectId(id))
            .map_or(JsValue::NULL, |o| JsValue::from_f64(o.owner.0 as f64)))
    }

    /// `[x, y, radius]`: a circle holding every volume of `id` at the end of the frame, or
    /// `null` for an object without volumes or an unknown id.
    #[wasm_bindgen(js_name = boundingCircle, unchecked_return_type = "[number, number, number] | null")]
    pub fn bounding_circle(&self, id: f64) -> Result<JsValue, JsError> {
        let id = args::whole("boundingCircle: id", id).map_err(error)?;
        Ok(self
            .world
            .bounding_circle(ObjectId(id))
            .map_or(JsValue::NULL, |c| {
                Array::of3(&c.center.x.into(), &c.center.y.into(), &c.radius.into()).into()
            }))
    }
}

/// `events` as JavaScript `HitEvent`s.
fn event_array(events: &[tileslide::HitEvent]) -> Result<Array, JsError> {
    let out = Array::new();
    for e in events {
        let event = object(&[
            ("attacker", e.attacker.0.into()),
            ("victim", e.victim.0.into()),
            ("attackerOwner", owner_number(e.attacker_owner)),
            ("victimOwner", owner_number(e.victim_owner)),
            ("hitType", e.hit_type.bits().into()),
            ("accepted", e.accepted.into()),
            ("t", e.t.into()),
            ("x", e.point.x.into()),
            ("y", e.point.y.into()),
        ])?;
        out.push(&event);
    }
    Ok(out)
}

/// The `HitObject` a description asks for.
fn hit_object(value: JsValue) -> Result<HitObject, JsError> {
    let mut o = Options::new("register: object", Some(value)).map_err(error)?;
    let owner = match o.number("owner").map_err(error)? {
        Some(n) => args::owner("register: object `owner`", n).map_err(error)?,
        None => return Err(error("register: object needs an `owner`")),
    };
    let (x, y) = (o.number("x").map_err(error)?, o.number("y").map_err(error)?);
    let (Some(x), Some(y)) = (x, y) else {
        return Err(error("register: object needs `x` and `y`"));
    };
    let position = args::vec2("register: object position", x, y).map_err(error)?;
    let size = o
        .pair("size")
        .map_err(error)?
        .ok_or_else(|| error("register: object needs a `size` [w, h]"))?;
    let motion = o.pair("motion").map_err(error)?.unwrap_or(Vec2::ZERO);
    let facing = Facing {
        flip_x: o.bool_or("flipX", false).map_err(error)?,
        flip_y: o.bool_or("flipY", false).map_err(error)?,
    };
    let team = o.u32_or("team", 0).map_err(error)?;
    let invulnerable = o.bool_or("invulnerable", false).map_err(error)?;
    let swing = match o.number("swing").map_err(error)? {
        None => None,
        Some(s) => Some(args::owner("register: object `swing`", s).map_err(error)?.0),
    };
    o.finish().map_err(error)?;
    Ok(HitObject {
        motion,
        facing,
        team,
        invulnerable,
        swing,
        ..HitObject::new(owner, position, size)
    })
}

/// The volumes of an array of descriptions, each error naming the volume's index.
fn volumes(what: &str, value: &JsValue) -> Result<Vec<Volume>, JsError> {
    if value.is_undefined() || value.is_null() {
        return Ok(Vec::new());
    }
    if !Array::is_array(value) {
        return Err(error(format!("{what} must be an array of volumes")));
    }
    Array::from(value)
        .iter()
        .enumerate()
        .map(|(i, v)| volume(&format!("{what}[{i}]"), v))
        .collect()
}

/// One volume `{x, y, radius, hit}` or `{x, y, halfWidth, halfHeight, hit}`.
fn volume(what: &str, value: JsValue) -> Result<Volume, JsError> {
    let mut o = Options::new(what, Some(value)).map_err(error)?;
    let x = o.number("x").map_err(error)?.unwrap_or(0.0);
    let y = o.number("y").map_err(error)?.unwrap_or(0.0);
    let center = args::vec2(&format!("{what} centre"), x, y).map_err(error)?;
    let hit = HitTypes::from_bits(o.u32_or("hit", HitTypes::HIT.bits()).map_err(error)?);
    let radius = o.number("radius").map_err(error)?;
    let half = (
        o.number("halfWidth").map_err(error)?,
        o.number("halfHeight").map_err(error)?,
    );
    o.finish().map_err(error)?;
    let volume = match (radius, half) {
        (Some(r), (None, None)) => {
            let r = args::finite(&format!("{what} radius"), r).map_err(error)?;
            Volume::circle(center, r, hit)
        }
        (None, (Some(w), Some(h))) => {
            let half = args::vec2(&format!("{what} half extents"), w, h).map_err(error)?;
            Volume::rect(center, half, hit)
        }
        _ => {
            return Err(error(format!(
                "{what} must have a `radius` or a `halfWidth` and `halfHeight`"
            )));
        }
    };
    volume.map_err(|e| error(format!("{what}: {e}")))
}
