//! `HitWorld`, `Volume`, `HitType`, `ObjectId` and `HitEvent`: attack and vulnerability
//! volumes registered frame by frame, and the hits between them. Values are converted
//! here; the detection is the core's.

use std::collections::HashMap;

use pyo3::exceptions::{PyKeyError, PyValueError};
use pyo3::prelude::*;
use tileslide::broadphase::PairMethod;
use tileslide::{Facing, HitObject, HitTypes, ObjectId as CoreId, Owner, TeamRule};

use crate::errors::{finite, finite_point, whole, whole_or};

/// Hit types: the bits a volume deals (attack) or accepts (vulnerability); combine them
/// with `|`. Bits 6 and up are the game's own.
#[pyclass(module = "tileslide", frozen)]
pub struct HitType;

#[pymethods]
impl HitType {
    /// No type: a volume with it never hits and is never hit.
    #[classattr]
    const NONE: u32 = HitTypes::NONE.bits();
    /// Every type: matches everything.
    #[classattr]
    const ANY: u32 = HitTypes::ANY.bits();
    /// Damage.
    #[classattr]
    const HIT: u32 = HitTypes::HIT.bits();
    /// Kills outright.
    #[classattr]
    const DEATH: u32 = HitTypes::DEATH.bits();
    /// Picks up a coin or a gem.
    #[classattr]
    const COLLECT: u32 = HitTypes::COLLECT.bits();
    /// Takes control of a robot.
    #[classattr]
    const POSSESS: u32 = HitTypes::POSSESS.bits();
    /// Presses a button.
    #[classattr]
    const DEPRESS: u32 = HitTypes::DEPRESS.bits();
    /// Throws the victim (a spring, a cannon).
    #[classattr]
    const LAUNCH: u32 = HitTypes::LAUNCH.bits();
}

/// An attack or vulnerability volume in object-local coordinates: a circle, a rectangle or
/// a capsule, with the hit types it deals or accepts.
#[pyclass(module = "tileslide", frozen, from_py_object)]
#[derive(Clone, Debug)]
pub struct Volume {
    volume: tileslide::Volume,
}

fn hit_types(hit: Option<&Bound<'_, PyAny>>) -> PyResult<HitTypes> {
    let bits = whole_or("hit", hit, u32::MAX.into(), HitTypes::HIT.bits().into())?;
    Ok(HitTypes::from_bits(bits as u32))
}

fn volume_error(e: &tileslide::VolumeError) -> PyErr {
    PyValueError::new_err(e.to_string())
}

#[pymethods]
impl Volume {
    /// A disc centred at (`x`, `y`) of `radius` (≥ 0); `hit` the types (default `HIT`).
    #[staticmethod]
    #[pyo3(signature = (x, y, radius, hit = None))]
    fn circle(x: f32, y: f32, radius: f32, hit: Option<Bound<'_, PyAny>>) -> PyResult<Self> {
        let center = finite_point(["x", "y"], x, y)?;
        let radius = finite("radius", radius)?;
        let volume = tileslide::Volume::circle(center, radius, hit_types(hit.as_ref())?)
            .map_err(|e| volume_error(&e))?;
        Ok(Volume { volume })
    }

    /// The rectangle centred at (`x`, `y`) with half extents `half_width` × `half_height`
    /// (≥ 0), as the character's box takes them.
    #[staticmethod]
    #[pyo3(signature = (x, y, half_width, half_height, hit = None))]
    fn rect(
        x: f32,
        y: f32,
        half_width: f32,
        half_height: f32,
        hit: Option<Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let center = finite_point(["x", "y"], x, y)?;
        let half = finite_point(["half_width", "half_height"], half_width, half_height)?;
        let volume = tileslide::Volume::rect(center, half, hit_types(hit.as_ref())?)
            .map_err(|e| volume_error(&e))?;
        Ok(Volume { volume })
    }

    /// The capsule whose middle line runs from (`x0`, `y0`) to (`x1`, `y1`), of `radius`
    /// (≥ 0): a blade, a beam.
    #[staticmethod]
    #[pyo3(signature = (x0, y0, x1, y1, radius, hit = None))]
    fn capsule(
        x0: f32,
        y0: f32,
        x1: f32,
        y1: f32,
        radius: f32,
        hit: Option<Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let a = finite_point(["x0", "y0"], x0, y0)?;
        let b = finite_point(["x1", "y1"], x1, y1)?;
        let radius = finite("radius", radius)?;
        let volume = tileslide::Volume::capsule(a, b, radius, hit_types(hit.as_ref())?)
            .map_err(|e| volume_error(&e))?;
        Ok(Volume { volume })
    }

    /// The hit types it deals or accepts.
    #[getter]
    fn hit(&self) -> u32 {
        self.volume.hit.bits()
    }

    fn __repr__(&self) -> String {
        format!(
            "Volume({:?}, hit={})",
            self.volume.shape,
            self.volume.hit.bits()
        )
    }
}

/// An object's id for one frame: its place in the frame's registrations. It is stale (a
/// `KeyError`) once the next frame begins.
#[pyclass(module = "tileslide", frozen, eq, hash, from_py_object)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ObjectId {
    /// 0, 1, 2, … in registration order.
    #[pyo3(get)]
    index: u32,
    /// The frame it was registered in (how many frames had begun before).
    #[pyo3(get)]
    frame: u64,
}

#[pymethods]
impl ObjectId {
    fn __repr__(&self) -> String {
        format!("ObjectId(index={}, frame={})", self.index, self.frame)
    }
}

/// One hit: an attack volume of `attacker` met a vulnerability volume of `victim`.
#[pyclass(module = "tileslide", frozen, get_all)]
#[derive(Clone, Debug)]
pub struct HitEvent {
    /// Who hit, and who was hit, as registered in the frame `detect` ran in.
    attacker: ObjectId,
    victim: ObjectId,
    /// Their owners (the game's keys for them, stable across frames).
    attacker_owner: u64,
    victim_owner: u64,
    /// The types dealt: the attack's types that the vulnerability accepts (bits of
    /// `HitType`).
    hit_type: u32,
    /// Whether the victim (the rule) took the hit.
    accepted: bool,
    /// When the volumes first touched, as a fraction of the frame's move in [0, 1].
    t: f32,
    /// Where they touched then.
    x: f32,
    y: f32,
}

#[pymethods]
impl HitEvent {
    fn __repr__(&self) -> String {
        format!(
            "HitEvent(attacker_owner={}, victim_owner={}, hit_type={}, accepted={}, t={}, x={}, y={})",
            self.attacker_owner,
            self.victim_owner,
            self.hit_type,
            if self.accepted { "True" } else { "False" },
            self.t,
            self.x,
            self.y
        )
    }
}

/// Attack and vulnerability volumes of the objects of one frame, and the hits between
/// them: each frame, `begin_frame()`, `register` every object with the volumes of its
/// current animation frame, then `detect()`.
#[pyclass(module = "tileslide")]
pub struct HitWorld {
    pub(crate) world: tileslide::HitWorld,
    /// Frames begun: the ids of this frame carry it.
    frame: u64,
    /// The frame the last `detect` ran in (its events' ids carry it).
    detected: u64,
}

impl HitWorld {
    /// The core's id for `id`, or a `KeyError` unless it names an object of this frame.
    fn core_id(&self, id: ObjectId) -> PyResult<CoreId> {
        if id.frame != self.frame {
            return Err(PyKeyError::new_err(format!(
                "stale object id {id:?}: it was registered in frame {}, and this is frame {} \
                 (ids last one frame)",
                id.frame, self.frame
            )));
        }
        let core = CoreId(id.index);
        match self.world.object(core) {
            Some(_) => Ok(core),
            None => Err(PyKeyError::new_err(format!(
                "no object {} in this frame ({} registered)",
                id.index,
                self.len()
            ))),
        }
    }

    fn len(&self) -> usize {
        (0..)
            .take_while(|&i| self.world.object(CoreId(i)).is_some())
            .count()
    }

    fn events_of(&self, events: &[tileslide::HitEvent]) -> Vec<HitEvent> {
        let id = |o: CoreId| ObjectId {
            index: o.0,
            frame: self.detected,
        };
        events
            .iter()
            .map(|e| HitEvent {
                attacker: id(e.attacker),
                victim: id(e.victim),
                attacker_owner: e.attacker_owner.0,
                victim_owner: e.victim_owner.0,
                hit_type: e.hit_type.bits(),
                accepted: e.accepted,
                t: e.t,
                x: e.point.x,
                y: e.point.y,
            })
            .collect()
    }
}

#[pymethods]
impl HitWorld {
    /// An empty world; `broadphase` is `"sweep_and_prune"` (the default, as Replica
    /// Island) or `"uniform_grid"` (the results are the same either way).
    #[new]
    #[pyo3(signature = (broadphase = "sweep_and_prune"))]
    fn new(broadphase: &str) -> PyResult<Self> {
        let method = match broadphase {
            "sweep_and_prune" => PairMethod::SweepAndPrune,
            "uniform_grid" => PairMethod::UniformGrid,
            other => {
                return Err(PyValueError::new_err(format!(
                    "broadphase is {other:?}: it must be \"sweep_and_prune\" or \"uniform_grid\""
                )));
            }
        };
        Ok(HitWorld {
            world: tileslide::HitWorld::with_broadphase(method),
            frame: 0,
            detected: 0,
        })
    }

    /// Frames begun so far: the ids registered now carry it.
    #[getter]
    fn frame(&self) -> u64 {
        self.frame
    }

    /// Starts a frame: forgets the last frame's objects (their ids go stale) and ends the
    /// swings nobody registered in it. The last `detect`'s events stay readable.
    fn begin_frame(&mut self) {
        self.world.begin_frame();
        self.frame += 1;
    }

    /// Registers an object of `owner` (the game's key for it) for this frame: its volumes'
    /// local origin at (`x`, `y`) at the end of the frame, its size `width` × `height`
    /// (volumes are mirrored about its middle), its `attack` and `vulnerable` volumes.
    /// `motion` is how far it moved this frame (its volumes are swept along it); `flip_x`,
    /// `flip_y` mirror it; `aim` turns its attack volumes to point along a direction;
    /// `team` and `invulnerable` feed the default rule; `swing` names the attack it makes
    /// (each victim is hit at most once per swing). Returns its id for this frame.
    #[pyo3(signature = (
        owner, x, y, width, height, *, attack = Vec::new(), vulnerable = Vec::new(),
        motion = (0.0, 0.0), flip_x = false, flip_y = false, aim = None, team = None,
        invulnerable = false, swing = None,
    ))]
    #[allow(clippy::too_many_arguments)]
    fn register(
        &mut self,
        owner: Bound<'_, PyAny>,
        x: f32,
        y: f32,
        width: f32,
        height: f32,
        attack: Vec<Volume>,
        vulnerable: Vec<Volume>,
        motion: (f32, f32),
        flip_x: bool,
        flip_y: bool,
        aim: Option<(f32, f32)>,
        team: Option<Bound<'_, PyAny>>,
        invulnerable: bool,
        swing: Option<Bound<'_, PyAny>>,
    ) -> PyResult<ObjectId> {
        let owner = Owner(whole("owner", &owner, u64::MAX)?);
        let position = finite_point(["x", "y"], x, y)?;
        let size = finite_point(["width", "height"], width, height)?;
        if size.x < 0.0 || size.y < 0.0 {
            return Err(PyValueError::new_err(format!(
                "the size is {width} × {height}: it must not be negative"
            )));
        }
        let motion = finite_point(["motion[0]", "motion[1]"], motion.0, motion.1)?;
        let aim = aim
            .map(|(ax, ay)| finite_point(["aim[0]", "aim[1]"], ax, ay))
            .transpose()?;
        let object = HitObject {
            motion,
            facing: Facing { flip_x, flip_y },
            aim,
            team: whole_or("team", team.as_ref(), u32::MAX.into(), 0)? as u32,
            invulnerable,
            swing: swing.map(|s| whole("swing", &s, u64::MAX)).transpose()?,
            ..HitObject::new(owner, position, size)
        };
        let attack: Vec<_> = attack.into_iter().map(|v| v.volume).collect();
        let vulnerable: Vec<_> = vulnerable.into_iter().map(|v| v.volume).collect();
        let id = self
            .world
            .register(object, &attack, &vulnerable)
            .map_err(|e| volume_error(&e))?;
        Ok(ObjectId {
            index: id.0,
            frame: self.frame,
        })
    }

    /// Finds this frame's hits and returns them in a fixed order. Without `rule`, a victim
    /// takes hits from other teams while it is not invulnerable; with it,
    /// `rule(attacker, victim, hit_type)` (two `ObjectId`s and the types' bits) decides,
    /// and an exception it raises is raised again after the detection (the hit refused).
    #[pyo3(signature = (rule = None))]
    fn detect(&mut self, rule: Option<Bound<'_, PyAny>>) -> PyResult<Vec<HitEvent>> {
        self.detected = self.frame;
        let Some(rule) = rule else {
            let events = self.world.detect(&mut TeamRule).to_vec();
            return Ok(self.events_of(&events));
        };
        // The core's rule sees objects; Python's sees their ids. The objects it is shown
        // are the world's own (the core passes references into its list), so their
        // addresses name them.
        let frame = self.frame;
        let ids: HashMap<*const HitObject, u32> = (0..)
            .map_while(|i| {
                self.world
                    .object(CoreId(i))
                    .map(|o| (std::ptr::from_ref(o), i))
            })
            .collect();
        let id_of = |o: &HitObject| {
            ids.get(&std::ptr::from_ref(o))
                .map(|&index| ObjectId { index, frame })
        };
        let mut raised: Option<PyErr> = None;
        let mut ask = |a: &HitObject, v: &HitObject, hit: HitTypes| {
            if raised.is_some() {
                return false;
            }
            match rule
                .call1((id_of(a), id_of(v), hit.bits()))
                .and_then(|answer| answer.is_truthy())
            {
                Ok(answer) => answer,
                Err(e) => {
                    raised = Some(e);
                    false
                }
            }
        };
        let events = self.world.detect(&mut ask).to_vec();
        if let Some(e) = raised {
            return Err(e);
        }
        Ok(self.events_of(&events))
    }

    /// The last `detect`'s events, kept until the next `detect`.
    fn events(&self) -> Vec<HitEvent> {
        self.events_of(self.world.events())
    }

    /// The owner of the object `id` of this frame.
    fn owner(&self, id: ObjectId) -> PyResult<u64> {
        let core = self.core_id(id)?;
        Ok(self.world.object(core).map_or(0, |o| o.owner.0))
    }

    /// `(x, y, radius)`: a circle holding every volume of `id` at the end of the frame, or
    /// None for an object without volumes.
    fn bounding_circle(&self, id: ObjectId) -> PyResult<Option<(f32, f32, f32)>> {
        let core = self.core_id(id)?;
        Ok(self
            .world
            .bounding_circle(core)
            .map(|c| (c.center.x, c.center.y, c.radius)))
    }

    /// Whether `id` names an object of this frame.
    fn __contains__(&self, id: ObjectId) -> bool {
        self.core_id(id).is_ok()
    }

    /// Objects registered this frame.
    fn __len__(&self) -> usize {
        self.len()
    }

    fn __repr__(&self) -> String {
        format!("HitWorld(frame={}, objects={})", self.frame, self.len())
    }
}
