//! Debug lines from C: a buffer the map, bodies, the character, the hit world and flow
//! fields fill with the core's kinded segments, circles, points and boxes (`DebugLines`),
//! read into the caller's array of `ts_debug_line`s to draw.

use tileslide::debug::DebugKinds;
use tileslide::{Aabb, DebugKind, DebugLines, Owner, Vec2};

use crate::character::ts_character;
use crate::hit_world::{ts_hit_world, world_ref};
use crate::nav::{field_ref, nav_ref, ts_flow_field, ts_nav};
use crate::{
    Failure, coordinate, fill, free_boxed, give_boxed, guarded, map_ref, ts_bodies, ts_map,
    ts_status,
};

/// What a debug line shows (the core's `DebugKind`, by the same numbers): a front end picks
/// its colour and layer by it.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ts_debug_kind {
    /// An active solid segment of the map, after seam culling (a segment).
    TS_DEBUG_ACTIVE_SEGMENT = 0,
    /// An active one-way platform segment (a segment).
    TS_DEBUG_ONE_WAY_SEGMENT = 1,
    /// A segment's outward normal, from its middle (a segment).
    TS_DEBUG_NORMAL = 2,
    /// A piece of a tile's segment that seam culling hides (a segment).
    TS_DEBUG_HIDDEN_SEGMENT = 3,
    /// A temporary segment: a moving platform, a door (a segment).
    TS_DEBUG_TEMPORARY_SEGMENT = 4,
    /// A body's circle (a circle; one per circle of a compound).
    TS_DEBUG_BODY = 5,
    /// A character's shape (a circle or a box).
    TS_DEBUG_CHARACTER = 6,
    /// A surface a character touched, from the contact along its normal (a segment).
    TS_DEBUG_CONTACT = 7,
    /// A ray (a segment).
    TS_DEBUG_RAY = 8,
    /// Where a ray hit (a point).
    TS_DEBUG_RAY_HIT = 9,
    /// An attack volume (a circle or a box).
    TS_DEBUG_ATTACK_VOLUME = 10,
    /// A vulnerability volume (a circle or a box).
    TS_DEBUG_VULNERABILITY_VOLUME = 11,
    /// An accepted hit, where it happened (a point).
    TS_DEBUG_HIT = 12,
    /// A refused hit (a point).
    TS_DEBUG_REFUSED_HIT = 13,
    /// A leg of a navigation path (a segment).
    TS_DEBUG_PATH = 14,
    /// A flow field's next move out of a lattice node (a segment).
    TS_DEBUG_FLOW_ARROW = 15,
    /// A box the broadphase files something under (a box).
    TS_DEBUG_BROADPHASE_BOX = 16,
}

/// Which shape a debug line is, and so what its four numbers say.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ts_debug_shape {
    /// From (`x0`, `y0`) to (`x1`, `y1`).
    TS_DEBUG_SEGMENT = 0,
    /// Centred on (`x0`, `y0`), of radius `x1` (`y1` is 0).
    TS_DEBUG_CIRCLE = 1,
    /// At (`x0`, `y0`) (`x1`, `y1` are the same).
    TS_DEBUG_POINT = 2,
    /// An axis-aligned box from its lowest corner (`x0`, `y0`) to its highest (`x1`, `y1`).
    TS_DEBUG_BOX = 3,
}

/// One debug shape, in map units.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ts_debug_line {
    /// See `shape`.
    pub x0: f32,
    /// See `shape`.
    pub y0: f32,
    /// See `shape`.
    pub x1: f32,
    /// See `shape`.
    pub y1: f32,
    /// What it shows.
    pub kind: ts_debug_kind,
    /// What the four numbers say.
    pub shape: ts_debug_shape,
    /// Whose it is: a body's or hit object's id as `(generation << 32) | index`, the owner
    /// given for a character, 0 for the map's own.
    pub owner: u64,
}

/// Every debug kind, for `ts_debug_lines_set_kinds`.
pub const TS_DEBUG_ALL_KINDS: u32 = u32::MAX;

/// A buffer of debug lines (opaque): made by `ts_debug_lines_create`, freed by
/// `ts_debug_lines_free`. Keep one, clear it each frame and fill it again: once it has
/// grown to a frame's size it allocates no more.
pub struct ts_debug_lines {
    lines: DebugLines,
    /// Scratch: the lines as C reads them.
    flat: Vec<ts_debug_line>,
}

/// The C kind of `kind` (`None` for a kind a later core adds and this API does not know
/// yet; the unit test below keeps the two lists equal).
fn kind_of(kind: DebugKind) -> Option<ts_debug_kind> {
    use ts_debug_kind::*;
    Some(match kind {
        DebugKind::ActiveSegment => TS_DEBUG_ACTIVE_SEGMENT,
        DebugKind::OneWaySegment => TS_DEBUG_ONE_WAY_SEGMENT,
        DebugKind::Normal => TS_DEBUG_NORMAL,
        DebugKind::HiddenSegment => TS_DEBUG_HIDDEN_SEGMENT,
        DebugKind::TemporarySegment => TS_DEBUG_TEMPORARY_SEGMENT,
        DebugKind::Body => TS_DEBUG_BODY,
        DebugKind::Character => TS_DEBUG_CHARACTER,
        DebugKind::Contact => TS_DEBUG_CONTACT,
        DebugKind::Ray => TS_DEBUG_RAY,
        DebugKind::RayHit => TS_DEBUG_RAY_HIT,
        DebugKind::AttackVolume => TS_DEBUG_ATTACK_VOLUME,
        DebugKind::VulnerabilityVolume => TS_DEBUG_VULNERABILITY_VOLUME,
        DebugKind::Hit => TS_DEBUG_HIT,
        DebugKind::RefusedHit => TS_DEBUG_REFUSED_HIT,
        DebugKind::Path => TS_DEBUG_PATH,
        DebugKind::FlowArrow => TS_DEBUG_FLOW_ARROW,
        DebugKind::BroadphaseBox => TS_DEBUG_BROADPHASE_BOX,
        _ => return None,
    })
}

/// A C line of `shape` with `kind` and `owner`, or `None` for a kind C does not know.
fn line(
    kind: DebugKind,
    shape: ts_debug_shape,
    xy: [f32; 4],
    owner: Owner,
) -> Option<ts_debug_line> {
    Some(ts_debug_line {
        x0: xy[0],
        y0: xy[1],
        x1: xy[2],
        y1: xy[3],
        kind: kind_of(kind)?,
        shape,
        owner: owner.0,
    })
}

/// `lines` as C reads them, into `flat`: segments, then circles, points and boxes.
fn flatten(lines: &DebugLines, flat: &mut Vec<ts_debug_line>) {
    use ts_debug_shape::*;
    flat.clear();
    flat.extend(lines.segments().iter().filter_map(|s| {
        let (a, b) = (s.segment.a, s.segment.b);
        line(s.kind, TS_DEBUG_SEGMENT, [a.x, a.y, b.x, b.y], s.owner)
    }));
    flat.extend(lines.circles().iter().filter_map(|c| {
        let (p, r) = (c.circle.center, c.circle.radius);
        line(c.kind, TS_DEBUG_CIRCLE, [p.x, p.y, r, 0.0], c.owner)
    }));
    flat.extend(lines.points().iter().filter_map(|p| {
        let at = p.point;
        line(p.kind, TS_DEBUG_POINT, [at.x, at.y, at.x, at.y], p.owner)
    }));
    flat.extend(lines.boxes().iter().filter_map(|b| {
        let (lo, hi) = (b.aabb.min, b.aabb.max);
        line(b.kind, TS_DEBUG_BOX, [lo.x, lo.y, hi.x, hi.y], b.owner)
    }));
}

/// # Safety
/// `lines` is null or a live buffer.
unsafe fn lines_mut<'a>(lines: *mut ts_debug_lines) -> Result<&'a mut ts_debug_lines, Failure> {
    // SAFETY: null or a live buffer, as the caller promises.
    unsafe { lines.as_mut() }.ok_or_else(|| Failure::null("lines"))
}

/// Runs `fill_with` on the core buffer behind `lines`, for the call `name`.
///
/// # Safety
/// `lines` is null or a live buffer.
unsafe fn filled(
    name: &str,
    lines: *mut ts_debug_lines,
    fill_with: impl FnOnce(&mut DebugLines) -> Result<(), Failure>,
) -> ts_status {
    guarded(name, || {
        // SAFETY: as the caller promises.
        let buffer = unsafe { lines_mut(lines) }?;
        fill_with(&mut buffer.lines)
    })
}

/// Makes an empty buffer of debug lines that takes every kind, everywhere. On `TS_OK`,
/// `*out` is the buffer, for `ts_debug_lines_free`.
///
/// # Safety
/// `out` points to a writable `ts_debug_lines*`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_debug_lines_create(out: *mut *mut ts_debug_lines) -> ts_status {
    guarded("ts_debug_lines_create", || {
        if out.is_null() {
            return Err(Failure::null("out"));
        }
        let buffer = ts_debug_lines {
            lines: DebugLines::new(),
            flat: Vec::new(),
        };
        // SAFETY: not null, writable as the caller promises.
        unsafe { give_boxed(out, buffer) };
        Ok(())
    })
}

/// Frees a buffer of debug lines (null is ignored).
///
/// # Safety
/// `lines` is null or a buffer from this library not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_debug_lines_free(lines: *mut ts_debug_lines) {
    // SAFETY: null or from `ts_debug_lines_create`, freed once, as the caller promises.
    unsafe { free_boxed(lines) };
}

/// Empties the buffer, keeping its memory, kinds and view.
///
/// # Safety
/// `lines` is a live buffer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_debug_lines_clear(lines: *mut ts_debug_lines) -> ts_status {
    // SAFETY: as the caller promises.
    unsafe {
        filled("ts_debug_lines_clear", lines, |l| {
            l.clear();
            Ok(())
        })
    }
}

/// Takes only the kinds in `kinds` from now on: bit `1 << k` for `ts_debug_kind` k
/// (`TS_DEBUG_ALL_KINDS` for every kind). Fillers skip the work for kinds left out (the
/// map works out no hidden pieces unless `TS_DEBUG_HIDDEN_SEGMENT` is in).
///
/// # Safety
/// `lines` is a live buffer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_debug_lines_set_kinds(
    lines: *mut ts_debug_lines,
    kinds: u32,
) -> ts_status {
    // SAFETY: as the caller promises.
    unsafe {
        filled("ts_debug_lines_set_kinds", lines, |l| {
            l.set_kinds(DebugKinds(kinds));
            Ok(())
        })
    }
}

/// Takes only shapes touching the box `view` from now on (4 floats: lowest x and y, then
/// highest x and y, in map units), or shapes anywhere for null: a map then visits only the
/// cells the view overlaps.
///
/// # Safety
/// `lines` is a live buffer; `view` is null or points to 4 floats.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_debug_lines_set_view(
    lines: *mut ts_debug_lines,
    view: *const f32,
) -> ts_status {
    // SAFETY: as the caller promises.
    unsafe {
        filled("ts_debug_lines_set_view", lines, |l| {
            if view.is_null() {
                l.set_view(None);
                return Ok(());
            }
            // SAFETY: not null, 4 floats as the caller promises.
            let v = std::slice::from_raw_parts(view, 4);
            let names = ["view[0]", "view[1]", "view[2]", "view[3]"];
            for (name, value) in names.iter().zip(v) {
                coordinate(name, *value)?;
            }
            if v[0] > v[2] || v[1] > v[3] {
                return Err(Failure::invalid(format!(
                    "view ({}, {}) to ({}, {}) has its lowest corner above its highest",
                    v[0], v[1], v[2], v[3]
                )));
            }
            let corners = (Vec2::new(v[0], v[1]), Vec2::new(v[2], v[3]));
            l.set_view(Some(Aabb::from_corners(corners.0, corners.1)));
            Ok(())
        })
    }
}

/// How many shapes the buffer holds (0 for null).
///
/// # Safety
/// `lines` is null or a live buffer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_debug_lines_count(lines: *const ts_debug_lines) -> usize {
    // SAFETY: null or a live buffer, as the caller promises.
    unsafe { lines.as_ref() }.map_or(0, |l| l.lines.len())
}

/// The buffer's shapes into `out` (room for `capacity`): segments first, then circles,
/// points and boxes, each in the order they were added; `*count` is how many. When they do
/// not fit, `TS_ERROR_BUFFER_TOO_SMALL` with only `*count` written.
///
/// # Safety
/// `lines` is a live buffer; `out` has room for `capacity` lines (or is null when
/// `capacity` is 0); `count` is writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_debug_lines_read(
    lines: *mut ts_debug_lines,
    out: *mut ts_debug_line,
    capacity: usize,
    count: *mut usize,
) -> ts_status {
    guarded("ts_debug_lines_read", || {
        // SAFETY: as the caller promises.
        let buffer = unsafe { lines_mut(lines) }?;
        flatten(&buffer.lines, &mut buffer.flat);
        let flat = &buffer.flat;
        // SAFETY: as the caller promises.
        unsafe {
            fill(
                flat.iter().copied(),
                flat.len(),
                out,
                capacity,
                count,
                "debug lines",
            )
        }
    })
}

/// Adds the map to `lines` (`TileMap::debug_lines`): cell by cell, each active segment
/// (`TS_DEBUG_ACTIVE_SEGMENT` or `TS_DEBUG_ONE_WAY_SEGMENT`) followed by its
/// `TS_DEBUG_NORMAL`, and each piece seam culling hides (`TS_DEBUG_HIDDEN_SEGMENT`).
///
/// # Safety
/// `map` is a live map, `lines` a live buffer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_map_debug_lines(
    map: *const ts_map,
    lines: *mut ts_debug_lines,
) -> ts_status {
    // SAFETY: as the caller promises.
    unsafe {
        filled("ts_map_debug_lines", lines, |l| {
            map_ref(map)?.debug_lines(l);
            Ok(())
        })
    }
}

/// Adds every body to `lines` (`Bodies::debug_lines`): each circle where it is
/// (`TS_DEBUG_BODY`), and after a step the box the broadphase filed it under
/// (`TS_DEBUG_BROADPHASE_BOX`), with the body's id as owner.
///
/// # Safety
/// `bodies` is a live set, `lines` a live buffer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_bodies_debug_lines(
    bodies: *const ts_bodies,
    lines: *mut ts_debug_lines,
) -> ts_status {
    // SAFETY: as the caller promises.
    unsafe {
        filled("ts_bodies_debug_lines", lines, |l| {
            crate::bodies::set_ref(bodies)?.debug_lines(l);
            Ok(())
        })
    }
}

/// Adds the character to `lines` with `owner` (`Character::debug_lines`): its shape
/// (`TS_DEBUG_CHARACTER`, a box or a circle) and each surface its last move touched
/// (`TS_DEBUG_CONTACT`, from the shape's edge along the surface's normal).
///
/// # Safety
/// `character` is a live character, `lines` a live buffer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_character_debug_lines(
    character: *const ts_character,
    owner: u64,
    lines: *mut ts_debug_lines,
) -> ts_status {
    // SAFETY: as the caller promises.
    unsafe {
        filled("ts_character_debug_lines", lines, |l| {
            let c = character
                .as_ref()
                .ok_or_else(|| Failure::null("character"))?;
            c.character.debug_lines(Some(&c.contacts), Owner(owner), l);
            Ok(())
        })
    }
}

/// Adds the hit world's objects as at the last step to `lines` (`HitWorld::debug_lines`):
/// attack and vulnerability volumes (`TS_DEBUG_ATTACK_VOLUME`,
/// `TS_DEBUG_VULNERABILITY_VOLUME`) and the box each swept (`TS_DEBUG_BROADPHASE_BOX`), with
/// the object's id as owner, then the step's hits where they happened (`TS_DEBUG_HIT`,
/// `TS_DEBUG_REFUSED_HIT`) with the victim's.
///
/// # Safety
/// `world` is a live world, `lines` a live buffer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_hit_world_debug_lines(
    world: *const ts_hit_world,
    lines: *mut ts_debug_lines,
) -> ts_status {
    // SAFETY: as the caller promises.
    unsafe {
        filled("ts_hit_world_debug_lines", lines, |l| {
            world_ref(world)?.world.debug_lines(l);
            Ok(())
        })
    }
}

/// Adds the flow field's next move out of every lattice node that reaches its goal to
/// `lines` (`FlowField::debug_lines`, `TS_DEBUG_FLOW_ARROW`); `nav` is the field's grid.
///
/// # Safety
/// `field` is a live field, `nav` a live grid, `lines` a live buffer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_flow_field_debug_lines(
    field: *const ts_flow_field,
    nav: *const ts_nav,
    lines: *mut ts_debug_lines,
) -> ts_status {
    // SAFETY: as the caller promises.
    unsafe {
        filled("ts_flow_field_debug_lines", lines, |l| {
            field_ref(field)?.debug_lines(nav_ref(nav)?, l);
            Ok(())
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_core_kind_has_its_c_kind_by_the_same_number() {
        assert_eq!(
            DebugKind::ALL.len(),
            17,
            "a new core kind: add it to ts_debug_kind"
        );
        for kind in DebugKind::ALL {
            let c = kind_of(kind).map(|k| k as u32);
            assert_eq!(c, Some(kind as u32), "{kind:?}");
        }
    }
}
