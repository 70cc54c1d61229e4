//! Hit volumes from C: objects with attack and vulnerability volumes (circles and
//! rectangles with hit types), kept from step to step and named by generation-checked ids,
//! and the hits between them that each step finds (the core's `HitWorld` with its
//! `TeamRule`).
//!
//! The core's `HitWorld` is told every object anew each frame; here the world remembers
//! them, as the Bevy plugin's `HitVolumes` components are remembered: each step registers
//! every live object in slot order, with the move from where it was at the last step (so
//! its volumes are swept along it), and its id as its owner.

use tileslide::limits::{MAX_HIT_OBJECTS, MAX_OBJECT_VOLUMES};
use tileslide::{
    Facing, HitEvent, HitObject, HitTypes, HitWorld, Owner, TeamRule, Vec2, Volume, VolumeError,
};

use crate::{
    Failure, TS_SHAPE_CIRCLE, TS_SHAPE_RECT, coordinate, fill, free_boxed, give_boxed, guarded,
    id_parts, owner_of, ts_status,
};

/// Hit type: damage.
pub const TS_HIT_TYPE_HIT: u32 = 1;
/// Hit type: kills outright.
pub const TS_HIT_TYPE_DEATH: u32 = 2;
/// Hit type: picks up (a coin, a gem).
pub const TS_HIT_TYPE_COLLECT: u32 = 4;
/// Hit type: takes control of (a robot).
pub const TS_HIT_TYPE_POSSESS: u32 = 8;
/// Hit type: presses (a button).
pub const TS_HIT_TYPE_DEPRESS: u32 = 16;
/// Hit type: throws (a spring, a cannon).
pub const TS_HIT_TYPE_LAUNCH: u32 = 32;
/// Every hit type: a vulnerability volume of it accepts anything.
pub const TS_HIT_TYPE_ANY: u32 = u32::MAX;

// Literals, for cbindgen to write into the header; the core's numbers.
const _: () = {
    assert!(TS_HIT_TYPE_HIT == HitTypes::HIT.bits());
    assert!(TS_HIT_TYPE_DEATH == HitTypes::DEATH.bits());
    assert!(TS_HIT_TYPE_COLLECT == HitTypes::COLLECT.bits());
    assert!(TS_HIT_TYPE_POSSESS == HitTypes::POSSESS.bits());
    assert!(TS_HIT_TYPE_DEPRESS == HitTypes::DEPRESS.bits());
    assert!(TS_HIT_TYPE_LAUNCH == HitTypes::LAUNCH.bits());
    assert!(TS_HIT_TYPE_ANY == HitTypes::ANY.bits());
};

/// `swing` of an object making no swing.
pub const TS_NO_SWING: u64 = u64::MAX;

/// A hit object's id, passed by value. Once its object is removed the id is stale for
/// good: calls with it return `TS_ERROR_STALE_HANDLE`, even after its slot is given to
/// another object.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ts_hit_object_id {
    /// The object's slot (objects are tested in slot order).
    pub index: u32,
    /// How many objects had the slot before this one.
    pub generation: u32,
}

/// An attack or vulnerability volume in its object's coordinates: a circle or a rectangle,
/// and the hit types it deals (attack) or accepts (vulnerability).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ts_volume {
    /// `TS_SHAPE_CIRCLE` (by `radius`) or `TS_SHAPE_RECT` (by `half_width`, `half_height`).
    pub shape: u32,
    /// The centre's offset from the object's position, x.
    pub x: f32,
    /// The centre's offset, y.
    pub y: f32,
    /// A circle's radius (not negative).
    pub radius: f32,
    /// A rectangle's half width (not negative).
    pub half_width: f32,
    /// A rectangle's half height (not negative).
    pub half_height: f32,
    /// Hit types (`TS_HIT_TYPE_*` bits; bits 6 and up are the game's own).
    pub hit: u32,
}

/// What a hit object is: start from `ts_default_hit_object_def()` and set what differs.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct ts_hit_object_def {
    /// The position (its volumes' origin), x.
    pub x: f32,
    /// The position, y.
    pub y: f32,
    /// Its width: volumes are mirrored about the middle of its size when it is flipped.
    pub width: f32,
    /// Its height.
    pub height: f32,
    /// Mirrors its volumes left to right (facing left, for volumes drawn facing right).
    pub flip_x: bool,
    /// Mirrors its volumes top to bottom.
    pub flip_y: bool,
    /// Its team: hits within a team are refused.
    pub team: u32,
    /// Refuses every hit (a hero blinking after one).
    pub invulnerable: bool,
    /// The attack it is making, to hit each victim at most once until it ends (the first
    /// step in which no object makes it), or `TS_NO_SWING`.
    pub swing: u64,
    /// Its attack volumes (`attack_count` of them; null when 0). The first that meets a
    /// vulnerability volume accepting one of its types gives the hit.
    pub attack: *const ts_volume,
    /// How many `attack` holds.
    pub attack_count: usize,
    /// Its vulnerability volumes (`vulnerable_count` of them; null when 0).
    pub vulnerable: *const ts_volume,
    /// How many `vulnerable` holds.
    pub vulnerable_count: usize,
}

/// One hit of the last step: an attack volume of `attacker` met a vulnerability volume of
/// `victim` accepting `hit_type`.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ts_hit_event {
    /// Who hit.
    pub attacker: ts_hit_object_id,
    /// Who was hit.
    pub victim: ts_hit_object_id,
    /// The types dealt: the attack volume's that the vulnerability volume accepts.
    pub hit_type: u32,
    /// Whether the victim took it: they are on different teams and the victim is not
    /// invulnerable.
    pub accepted: bool,
    /// When the volumes first touched, as a fraction of the step's move in [0, 1] (0 when
    /// they overlap where it starts).
    pub t: f32,
    /// Where they touched then, x.
    pub x: f32,
    /// Where they touched then, y.
    pub y: f32,
}

/// An object as the world keeps it between steps.
#[derive(Clone, Debug)]
struct Object {
    /// Its position, size, facing, team and swing; `motion` is filled in at each step.
    core: HitObject,
    /// Where it was at the last step (or where it was added): its move starts there.
    last: Vec2,
    attack: Vec<Volume>,
    vulnerable: Vec<Volume>,
}

#[derive(Clone, Debug, Default)]
struct Slot {
    generation: u32,
    object: Option<Object>,
}

/// Hit objects and the hits between them (opaque): made by `ts_hit_world_create`, freed by
/// `ts_hit_world_free`.
pub struct ts_hit_world {
    pub(crate) world: HitWorld,
    slots: Vec<Slot>,
    /// Slots free for reuse (a slot whose generation is spent is never reused).
    free: Vec<u32>,
    live: usize,
    /// The last step's events.
    events: Vec<ts_hit_event>,
}

fn id_of(owner: Owner) -> ts_hit_object_id {
    let (index, generation) = id_parts(owner);
    ts_hit_object_id { index, generation }
}

fn event_of(e: &HitEvent) -> ts_hit_event {
    ts_hit_event {
        attacker: id_of(e.attacker_owner),
        victim: id_of(e.victim_owner),
        hit_type: e.hit_type.bits(),
        accepted: e.accepted,
        t: e.t,
        x: e.point.x,
        y: e.point.y,
    }
}

/// The core volume `v` describes, `what` naming it in errors.
fn volume_of(what: &str, v: &ts_volume) -> Result<Volume, Failure> {
    let center = Vec2::new(v.x, v.y);
    let hit = HitTypes::from_bits(v.hit);
    let volume = match v.shape {
        TS_SHAPE_CIRCLE => Volume::circle(center, v.radius, hit),
        TS_SHAPE_RECT => Volume::rect(center, Vec2::new(v.half_width, v.half_height), hit),
        other => {
            return Err(Failure::invalid(format!(
                "{what}.shape is {other}: it must be TS_SHAPE_CIRCLE ({TS_SHAPE_CIRCLE}) or TS_SHAPE_RECT ({TS_SHAPE_RECT})"
            )));
        }
    };
    volume.map_err(|e| Failure::invalid(format!("{what}: {e}")))
}

/// The core volumes of the `count` at `list`, `what` naming them in errors.
///
/// # Safety
/// `list` is null or holds `count` volumes.
unsafe fn volumes_of(
    what: &str,
    list: *const ts_volume,
    count: usize,
) -> Result<Vec<Volume>, Failure> {
    if count == 0 {
        return Ok(Vec::new());
    }
    // (Before the slice is made: a count past `isize::MAX` bytes would make it undefined.)
    if count > MAX_OBJECT_VOLUMES {
        return Err(Failure::invalid(format!(
            "{what}: {count} volumes, at most {MAX_OBJECT_VOLUMES}"
        )));
    }
    if list.is_null() {
        return Err(Failure::null(what));
    }
    // SAFETY: not null, and `count` volumes as the caller promises.
    let list = unsafe { std::slice::from_raw_parts(list, count) };
    list.iter()
        .enumerate()
        .map(|(k, v)| volume_of(&format!("{what}[{k}]"), v))
        .collect()
}

fn volume_failure(what: &str, e: &VolumeError) -> Failure {
    Failure::invalid(format!("{what}: {e}"))
}

/// The object `def` describes, checked as registering it will check it.
///
/// # Safety
/// `def`'s lists hold as many volumes as it says (or are null).
unsafe fn object_of(def: &ts_hit_object_def) -> Result<Object, Failure> {
    let position = Vec2::new(coordinate("def.x", def.x)?, coordinate("def.y", def.y)?);
    let size = Vec2::new(
        coordinate("def.width", def.width)?,
        coordinate("def.height", def.height)?,
    );
    let core = HitObject {
        facing: Facing {
            flip_x: def.flip_x,
            flip_y: def.flip_y,
        },
        team: def.team,
        invulnerable: def.invulnerable,
        swing: (def.swing != TS_NO_SWING).then_some(def.swing),
        ..HitObject::new(Owner::default(), position, size)
    };
    core.check().map_err(|e| volume_failure("def", &e))?;
    // SAFETY: as the caller promises.
    let attack = unsafe { volumes_of("def.attack", def.attack, def.attack_count) }?;
    // SAFETY: as the caller promises.
    let vulnerable = unsafe { volumes_of("def.vulnerable", def.vulnerable, def.vulnerable_count) }?;
    Ok(Object {
        core,
        last: position,
        attack,
        vulnerable,
    })
}

impl ts_hit_world {
    /// The live object `id` names, or a stale-handle failure.
    fn object_mut(&mut self, id: ts_hit_object_id) -> Result<&mut Object, Failure> {
        self.slots
            .get_mut(id.index as usize)
            .filter(|s| s.generation == id.generation)
            .and_then(|s| s.object.as_mut())
            .ok_or_else(|| stale(id))
    }

    fn add(&mut self, object: Object) -> Result<ts_hit_object_id, Failure> {
        // Each step registers every object with the core's world, which takes this many.
        if self.live >= MAX_HIT_OBJECTS {
            return Err(Failure::invalid(format!(
                "the hit world holds {MAX_HIT_OBJECTS} objects already, the most it takes"
            )));
        }
        let index = match self.free.pop() {
            Some(index) => index,
            None => {
                let index = u32::try_from(self.slots.len()).map_err(|_| {
                    Failure::invalid("the hit world holds 2^32 objects already".to_owned())
                })?;
                self.slots.push(Slot::default());
                index
            }
        };
        let slot = &mut self.slots[index as usize];
        slot.object = Some(object);
        self.live += 1;
        Ok(ts_hit_object_id {
            index,
            generation: slot.generation,
        })
    }

    fn remove(&mut self, id: ts_hit_object_id) -> Result<(), Failure> {
        self.object_mut(id)?;
        let slot = &mut self.slots[id.index as usize];
        slot.object = None;
        self.live -= 1;
        // A slot whose generations are spent is retired, so no id ever names two objects.
        if let Some(next) = slot.generation.checked_add(1) {
            slot.generation = next;
            self.free.push(id.index);
        }
        Ok(())
    }

    /// One step: every live object registered in slot order with its move since the last
    /// step, the hits found, the moves' ends remembered.
    fn step(&mut self) -> Result<(), Failure> {
        self.world.begin_frame();
        for (index, slot) in (0u32..).zip(&self.slots) {
            let Some(o) = &slot.object else {
                continue;
            };
            let object = HitObject {
                owner: owner_of(index, slot.generation),
                motion: o.core.position - o.last,
                ..o.core
            };
            self.world
                .register(object, &o.attack, &o.vulnerable)
                .map_err(|e| volume_failure(&format!("object {index}"), &e))?;
        }
        self.events.clear();
        self.events
            .extend(self.world.detect(&mut TeamRule).iter().map(event_of));
        for o in self.slots.iter_mut().filter_map(|s| s.object.as_mut()) {
            o.last = o.core.position;
        }
        Ok(())
    }
}

fn stale(id: ts_hit_object_id) -> Failure {
    Failure(
        ts_status::TS_ERROR_STALE_HANDLE,
        format!(
            "stale hit object id (index {}, generation {}): its object was removed, or never was",
            id.index, id.generation
        ),
    )
}

/// # Safety
/// `world` is null or a live hit world.
unsafe fn world_mut<'a>(world: *mut ts_hit_world) -> Result<&'a mut ts_hit_world, Failure> {
    // SAFETY: null or a live world, as the caller promises.
    unsafe { world.as_mut() }.ok_or_else(|| Failure::null("world"))
}

/// # Safety
/// `world` is null or a live hit world.
pub(crate) unsafe fn world_ref<'a>(
    world: *const ts_hit_world,
) -> Result<&'a ts_hit_world, Failure> {
    // SAFETY: null or a live world, as the caller promises.
    unsafe { world.as_ref() }.ok_or_else(|| Failure::null("world"))
}

/// A hit object definition's defaults: at (0, 0), of size 0 (volumes mirror about the
/// position), facing right, team 0, not invulnerable, no swing, no volumes.
#[unsafe(no_mangle)]
pub extern "C" fn ts_default_hit_object_def() -> ts_hit_object_def {
    ts_hit_object_def {
        x: 0.0,
        y: 0.0,
        width: 0.0,
        height: 0.0,
        flip_x: false,
        flip_y: false,
        team: 0,
        invulnerable: false,
        swing: TS_NO_SWING,
        attack: std::ptr::null(),
        attack_count: 0,
        vulnerable: std::ptr::null(),
        vulnerable_count: 0,
    }
}

/// Makes an empty hit world (sweep and prune on x, as Replica Island's). On `TS_OK`,
/// `*out` is the world, for `ts_hit_world_free`.
///
/// # Safety
/// `out` points to a writable `ts_hit_world*`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_hit_world_create(out: *mut *mut ts_hit_world) -> ts_status {
    guarded("ts_hit_world_create", || {
        if out.is_null() {
            return Err(Failure::null("out"));
        }
        let world = ts_hit_world {
            world: HitWorld::new(),
            slots: Vec::new(),
            free: Vec::new(),
            live: 0,
            events: Vec::new(),
        };
        // SAFETY: not null, writable as the caller promises.
        unsafe { give_boxed(out, world) };
        Ok(())
    })
}

/// Frees a hit world (null is ignored); its ids are meaningless afterwards.
///
/// # Safety
/// `world` is null or a world from this library not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_hit_world_free(world: *mut ts_hit_world) {
    // SAFETY: null or from `ts_hit_world_create`, freed once, as the caller promises.
    unsafe { free_boxed(world) };
}

/// Adds an object as `def` says (its volumes are copied). On `TS_OK`, `*out` is its id.
/// A position or size that is not finite or beyond the coordinate range, a negative radius
/// or half extent, an unknown shape, and a count with a null list are refused, named.
///
/// # Safety
/// `world` is a live world; `def` points to a definition whose lists hold as many volumes
/// as it says (or are null); `out` points to a writable `ts_hit_object_id`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_hit_world_add(
    world: *mut ts_hit_world,
    def: *const ts_hit_object_def,
    out: *mut ts_hit_object_id,
) -> ts_status {
    guarded("ts_hit_world_add", || {
        // SAFETY: as the caller promises.
        let w = unsafe { world_mut(world) }?;
        // SAFETY: null or a definition, as the caller promises.
        let Some(def) = (unsafe { def.as_ref() }) else {
            return Err(Failure::null("def"));
        };
        if out.is_null() {
            return Err(Failure::null("out"));
        }
        // SAFETY: the lists as the caller promises.
        let object = unsafe { object_of(def) }?;
        let id = w.add(object)?;
        // SAFETY: not null, writable as the caller promises.
        unsafe { out.write(id) };
        Ok(())
    })
}

/// Replaces what the object is (volumes, size, facing, team, invulnerability, swing) with
/// what `def` says; its position becomes `def`'s as `ts_hit_world_move` moves it (swept at
/// the next step from where it was at the last).
///
/// # Safety
/// `world` is a live world; `def` as for `ts_hit_world_add`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_hit_world_set(
    world: *mut ts_hit_world,
    id: ts_hit_object_id,
    def: *const ts_hit_object_def,
) -> ts_status {
    guarded("ts_hit_world_set", || {
        // SAFETY: as the caller promises.
        let w = unsafe { world_mut(world) }?;
        // SAFETY: null or a definition, as the caller promises.
        let Some(def) = (unsafe { def.as_ref() }) else {
            return Err(Failure::null("def"));
        };
        let object = w.object_mut(id)?;
        // SAFETY: the lists as the caller promises.
        let new = unsafe { object_of(def) }?;
        *object = Object {
            last: object.last,
            ..new
        };
        Ok(())
    })
}

/// Moves an object to (`x`, `y`): at the next step its volumes are swept from where they
/// were at the last step (or where it was added) to here, so a fast one cannot pass
/// through a target.
///
/// # Safety
/// `world` is a live world.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_hit_world_move(
    world: *mut ts_hit_world,
    id: ts_hit_object_id,
    x: f32,
    y: f32,
) -> ts_status {
    guarded("ts_hit_world_move", || {
        // SAFETY: as the caller promises.
        let w = unsafe { world_mut(world) }?;
        let position = Vec2::new(coordinate("x", x)?, coordinate("y", y)?);
        w.object_mut(id)?.core.position = position;
        Ok(())
    })
}

/// Removes an object; its id is stale from now on. The last step's events still name it.
///
/// # Safety
/// `world` is a live world.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_hit_world_remove(
    world: *mut ts_hit_world,
    id: ts_hit_object_id,
) -> ts_status {
    guarded("ts_hit_world_remove", || {
        // SAFETY: as the caller promises.
        unsafe { world_mut(world) }?.remove(id)
    })
}

/// The number of objects in the world (0 for null).
///
/// # Safety
/// `world` is null or a live world.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_hit_world_count(world: *const ts_hit_world) -> usize {
    // SAFETY: as the caller promises.
    unsafe { world_ref(world) }.map_or(0, |w| w.live)
}

/// One step: every object's volumes tested against the others' along their moves since
/// the last step; the hits, in a fixed order (by pair of objects in slot order, then each
/// direction), kept for `ts_hit_world_events` until the next step. A victim takes a hit
/// from another team while it is not invulnerable; an attack with a swing hits each
/// victim once until the swing ends.
///
/// # Safety
/// `world` is a live world.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_hit_world_step(world: *mut ts_hit_world) -> ts_status {
    guarded("ts_hit_world_step", || {
        // SAFETY: as the caller promises.
        unsafe { world_mut(world) }?.step()
    })
}

/// The last step's hits, into `out` (room for `capacity`); `*count` is how many. When
/// they do not fit, `TS_ERROR_BUFFER_TOO_SMALL` with only `*count` written: the events stay
/// until the next step, so ask again with more room.
///
/// # Safety
/// `world` is a live world; `out` has room for `capacity` events (or is null when
/// `capacity` is 0); `count` is writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_hit_world_events(
    world: *const ts_hit_world,
    out: *mut ts_hit_event,
    capacity: usize,
    count: *mut usize,
) -> ts_status {
    guarded("ts_hit_world_events", || {
        // SAFETY: as the caller promises.
        let w = unsafe { world_ref(world) }?;
        let events = &w.events;
        // SAFETY: as the caller promises.
        unsafe {
            fill(
                events.iter().copied(),
                events.len(),
                out,
                capacity,
                count,
                "events",
            )
        }
    })
}
