//! Bodies from C: a set of circles and compounds of circles that slide round each other and
//! along the map's walls, each named by a `ts_body_id` passed by value.

use std::ptr;

use tileslide::limits::MAX_COMPOUND_CIRCLES;
use tileslide::{Bodies, BodyDesc, BodyError, BodyFilter, BodyHandle, BodyShape, Circle, Vec2};

use crate::{
    Failure, free_boxed, give_boxed, guarded, map_ref, owner_of, slice_fits, ts_map, ts_status,
};

/// A set of bodies (opaque): made by `ts_bodies_create`, freed by `ts_bodies_free`.
pub struct ts_bodies {
    bodies: Bodies,
}

/// A body's id, passed by value. Once its body is removed the id is stale for good: calls
/// with it return `TS_ERROR_STALE_HANDLE`, even after its slot is given to another body.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ts_body_id {
    /// The body's slot (bodies are resolved in slot order).
    pub index: u32,
    /// How many bodies had the slot before this one.
    pub generation: u32,
}

/// One circle of a compound body: its centre's offset from the body's position, and its
/// radius.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ts_circle {
    /// The centre's offset, x.
    pub x: f32,
    /// The centre's offset, y.
    pub y: f32,
    /// The radius (positive).
    pub radius: f32,
}

/// What a body is: start from `ts_default_body_def()` and set what differs.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct ts_body_def {
    /// The position, x.
    pub x: f32,
    /// The position, y.
    pub y: f32,
    /// The radius of a circle centred on the position (when `circle_count` is 0).
    pub radius: f32,
    /// A compound's circles (`circle_count` of them), or null for one circle of `radius`.
    pub circles: *const ts_circle,
    /// How many circles `circles` holds.
    pub circle_count: usize,
    /// The groups the body belongs to (bits).
    pub groups: u32,
    /// The groups it collides with (bits).
    pub collides_with: u32,
}

/// What a step did.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ts_step_report {
    /// Bodies with a move to make.
    pub moving: usize,
    /// Contacts met (each sweep stopped at something counts once).
    pub contacts: usize,
    /// Bodies whose move was still blocked after the last pass, and cut at its first
    /// contact.
    pub cut_short: usize,
}

fn handle(id: ts_body_id) -> BodyHandle {
    BodyHandle::from_parts(id.index, id.generation)
}

fn id_of(handle: BodyHandle) -> ts_body_id {
    ts_body_id {
        index: handle.index(),
        generation: handle.generation(),
    }
}

fn body_failure(e: &BodyError) -> Failure {
    let status = match e {
        BodyError::StaleHandle(_) => ts_status::TS_ERROR_STALE_HANDLE,
        _ => ts_status::TS_ERROR_INVALID_ARGUMENT,
    };
    Failure(status, e.to_string())
}

/// # Safety
/// `bodies` is null or a live set.
unsafe fn set_mut<'a>(bodies: *mut ts_bodies) -> Result<&'a mut Bodies, Failure> {
    // SAFETY: null or a live set, as the caller promises.
    unsafe { bodies.as_mut() }
        .map(|b| &mut b.bodies)
        .ok_or_else(|| Failure::null("bodies"))
}

/// # Safety
/// `bodies` is null or a live set.
pub(crate) unsafe fn set_ref<'a>(bodies: *const ts_bodies) -> Result<&'a Bodies, Failure> {
    // SAFETY: null or a live set, as the caller promises.
    unsafe { bodies.as_ref() }
        .map(|b| &b.bodies)
        .ok_or_else(|| Failure::null("bodies"))
}

/// A body definition's defaults: at (0, 0), one circle of radius 0.5, in group 1,
/// colliding with every group.
#[unsafe(no_mangle)]
pub extern "C" fn ts_default_body_def() -> ts_body_def {
    let filter = BodyFilter::default();
    ts_body_def {
        x: 0.0,
        y: 0.0,
        radius: 0.5,
        circles: ptr::null(),
        circle_count: 0,
        groups: filter.groups,
        collides_with: filter.collides_with,
    }
}

/// Makes an empty set of bodies with the resolver's default settings. On `TS_OK`, `*out` is
/// the set, for `ts_bodies_free`.
///
/// # Safety
/// `out` points to a writable `ts_bodies*`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_bodies_create(out: *mut *mut ts_bodies) -> ts_status {
    guarded("ts_bodies_create", || {
        if out.is_null() {
            return Err(Failure::null("out"));
        }
        let set = ts_bodies {
            bodies: Bodies::new(),
        };
        // SAFETY: not null, writable as the caller promises.
        unsafe { give_boxed(out, set) };
        Ok(())
    })
}

/// Frees a set of bodies (null is ignored); their ids are meaningless afterwards.
///
/// # Safety
/// `bodies` is null or a set from this library not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_bodies_free(bodies: *mut ts_bodies) {
    // SAFETY: null or from `ts_bodies_create`, freed once, as the caller promises.
    unsafe { free_boxed(bodies) };
}

/// Adds a body as `def` says. On `TS_OK`, `*out` is its id, which is also its owner in the
/// core, `(generation << 32) | index`, as its debug lines name it. A radius that is not
/// positive, a position or offset that is not finite or beyond the coordinate range, and a
/// compound with `circle_count` circles but a null `circles` are refused.
///
/// # Safety
/// `bodies` is a live set; `def` points to a definition whose `circles` holds
/// `circle_count` circles (or is null); `out` points to a writable `ts_body_id`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_bodies_add(
    bodies: *mut ts_bodies,
    def: *const ts_body_def,
    out: *mut ts_body_id,
) -> ts_status {
    guarded("ts_bodies_add", || {
        // SAFETY: as the caller promises.
        let set = unsafe { set_mut(bodies) }?;
        // SAFETY: null or a definition, as the caller promises.
        let Some(def) = (unsafe { def.as_ref() }) else {
            return Err(Failure::null("def"));
        };
        if out.is_null() {
            return Err(Failure::null("out"));
        }
        let shape = if def.circle_count == 0 {
            BodyShape::circle(def.radius)
        } else {
            // (Before the slice is made: see `slice_fits`.)
            if def.circle_count > MAX_COMPOUND_CIRCLES {
                return Err(Failure::invalid(format!(
                    "def.circle_count is {}, at most {MAX_COMPOUND_CIRCLES}",
                    def.circle_count
                )));
            }
            if def.circles.is_null() {
                return Err(Failure::null("def.circles"));
            }
            // SAFETY: `circles` holds `circle_count` circles, as the caller promises.
            let circles = unsafe { std::slice::from_raw_parts(def.circles, def.circle_count) };
            BodyShape::compound(
                circles
                    .iter()
                    .map(|c| Circle::new(Vec2::new(c.x, c.y), c.radius)),
            )
        }
        .map_err(|e| body_failure(&e))?;
        let desc = BodyDesc::new(Vec2::new(def.x, def.y), shape).with_filter(BodyFilter {
            groups: def.groups,
            collides_with: def.collides_with,
            ..BodyFilter::default()
        });
        let handle = set.add(desc).map_err(|e| body_failure(&e))?;
        // Its id as its owner, so that its debug lines name it.
        set.set_owner(handle, owner_of(handle.index(), handle.generation()))
            .map_err(|e| body_failure(&e))?;
        // SAFETY: not null, writable as the caller promises.
        unsafe { out.write(id_of(handle)) };
        Ok(())
    })
}

/// Removes a body; its id is stale from now on.
///
/// # Safety
/// `bodies` is a live set.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_bodies_remove(bodies: *mut ts_bodies, id: ts_body_id) -> ts_status {
    guarded("ts_bodies_remove", || {
        // SAFETY: as the caller promises.
        let set = unsafe { set_mut(bodies) }?;
        set.remove(handle(id)).map_err(|e| body_failure(&e))?;
        Ok(())
    })
}

/// The number of bodies in the set (0 for null).
///
/// # Safety
/// `bodies` is null or a live set.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_bodies_count(bodies: *const ts_bodies) -> usize {
    // SAFETY: as the caller promises.
    unsafe { set_ref(bodies) }.map_or(0, Bodies::len)
}

/// Proposes the move (`dx`, `dy`) for the next step (replacing one proposed before).
///
/// # Safety
/// `bodies` is a live set.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_bodies_propose(
    bodies: *mut ts_bodies,
    id: ts_body_id,
    dx: f32,
    dy: f32,
) -> ts_status {
    guarded("ts_bodies_propose", || {
        // SAFETY: as the caller promises.
        let set = unsafe { set_mut(bodies) }?;
        set.propose(handle(id), Vec2::new(dx, dy))
            .map_err(|e| body_failure(&e))
    })
}

/// Proposes `moves[2k]`, `moves[2k + 1]` for `ids[k]`, in order. On a failure the entries
/// before the one named in the message are proposed, the rest are not.
///
/// # Safety
/// `bodies` is a live set; `ids` holds `n` ids and `moves` `2 n` floats (either may be null
/// when `n` is 0).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_bodies_propose_many(
    bodies: *mut ts_bodies,
    ids: *const ts_body_id,
    moves: *const f32,
    n: usize,
) -> ts_status {
    guarded("ts_bodies_propose_many", || {
        // SAFETY: as the caller promises.
        let set = unsafe { set_mut(bodies) }?;
        if n == 0 {
            return Ok(());
        }
        if ids.is_null() {
            return Err(Failure::null("ids"));
        }
        if moves.is_null() {
            return Err(Failure::null("moves"));
        }
        let Some(floats) = n
            .checked_mul(2)
            .filter(|&f| slice_fits::<f32>(f) && slice_fits::<ts_body_id>(n))
        else {
            return Err(Failure::invalid(format!("n = {n} moves is too many")));
        };
        // SAFETY: `ids` holds n ids and `moves` 2 n floats, as the caller promises.
        let (ids, moves) = unsafe {
            (
                std::slice::from_raw_parts(ids, n),
                std::slice::from_raw_parts(moves, floats),
            )
        };
        for (k, (id, m)) in ids.iter().zip(moves.chunks_exact(2)).enumerate() {
            set.propose(handle(*id), Vec2::new(m[0], m[1]))
                .map_err(|e| {
                    let Failure(status, message) = body_failure(&e);
                    Failure(status, format!("entry {k}: {message}"))
                })?;
        }
        Ok(())
    })
}

/// Moves a body to (`x`, `y`) at once (a teleport: no sweep), dropping its proposed move.
///
/// # Safety
/// `bodies` is a live set.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_bodies_set_position(
    bodies: *mut ts_bodies,
    id: ts_body_id,
    x: f32,
    y: f32,
) -> ts_status {
    guarded("ts_bodies_set_position", || {
        // SAFETY: as the caller promises.
        let set = unsafe { set_mut(bodies) }?;
        set.set_position(handle(id), Vec2::new(x, y))
            .map_err(|e| body_failure(&e))
    })
}

/// One step: every proposed move resolved together against `map` and each other (no
/// overlap, no tunnelling), then made. `report` may be null.
///
/// # Safety
/// `bodies` is a live set, `map` a live map; `report` is null or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_bodies_step(
    bodies: *mut ts_bodies,
    map: *const ts_map,
    report: *mut ts_step_report,
) -> ts_status {
    guarded("ts_bodies_step", || {
        // SAFETY: as the caller promises.
        let set = unsafe { set_mut(bodies) }?;
        // SAFETY: as the caller promises.
        let map = unsafe { map_ref(map) }?;
        let done = set.step(map);
        // SAFETY: null (skipped) or writable, as the caller promises.
        if let Some(out) = unsafe { report.as_mut() } {
            *out = ts_step_report {
                moving: done.moving,
                contacts: done.contact_count,
                cut_short: done.cut_short,
            };
        }
        Ok(())
    })
}

/// A body's position, into `*x` and `*y`.
///
/// # Safety
/// `bodies` is a live set; `x` and `y` are writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_bodies_position(
    bodies: *const ts_bodies,
    id: ts_body_id,
    x: *mut f32,
    y: *mut f32,
) -> ts_status {
    guarded("ts_bodies_position", || {
        // SAFETY: as the caller promises.
        let set = unsafe { set_ref(bodies) }?;
        if x.is_null() || y.is_null() {
            return Err(Failure::null(if x.is_null() { "x" } else { "y" }));
        }
        let p = set
            .get(handle(id))
            .map_err(|e| body_failure(&e))?
            .position();
        // SAFETY: not null, writable as the caller promises.
        unsafe {
            x.write(p.x);
            y.write(p.y);
        }
        Ok(())
    })
}

/// The positions of `ids`: `out_xy[2k]`, `out_xy[2k + 1]` for `ids[k]`. Every id is checked
/// first: a stale one fails the call, names its entry, and leaves `out_xy` as it was.
///
/// # Safety
/// `bodies` is a live set; `ids` holds `n` ids and `out_xy` room for `2 n` floats (either
/// may be null when `n` is 0).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_bodies_positions(
    bodies: *const ts_bodies,
    ids: *const ts_body_id,
    n: usize,
    out_xy: *mut f32,
) -> ts_status {
    guarded("ts_bodies_positions", || {
        // SAFETY: as the caller promises.
        let set = unsafe { set_ref(bodies) }?;
        if n == 0 {
            return Ok(());
        }
        if ids.is_null() {
            return Err(Failure::null("ids"));
        }
        if out_xy.is_null() {
            return Err(Failure::null("out_xy"));
        }
        let Some(floats) = n
            .checked_mul(2)
            .filter(|&f| slice_fits::<f32>(f) && slice_fits::<ts_body_id>(n))
        else {
            return Err(Failure::invalid(format!("n = {n} ids is too many")));
        };
        // SAFETY: `ids` holds n ids, as the caller promises.
        let ids = unsafe { std::slice::from_raw_parts(ids, n) };
        if let Some((k, e)) = ids
            .iter()
            .enumerate()
            .find_map(|(k, id)| set.get(handle(*id)).err().map(|e| (k, e)))
        {
            let Failure(status, message) = body_failure(&e);
            return Err(Failure(status, format!("entry {k}: {message}")));
        }
        // SAFETY: `out_xy` has room for 2 n floats, as the caller promises.
        let out = unsafe { std::slice::from_raw_parts_mut(out_xy, floats) };
        for (id, xy) in ids.iter().zip(out.chunks_exact_mut(2)) {
            if let Ok(body) = set.get(handle(*id)) {
                let p = body.position();
                xy[0] = p.x;
                xy[1] = p.y;
            }
        }
        Ok(())
    })
}
