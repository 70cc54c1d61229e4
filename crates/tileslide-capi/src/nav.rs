//! Paths from C: a navigation grid built from a map once, shortest paths for a circle of
//! any radius up to the grid's widest, and flow fields for crowds sharing a goal (the core's
//! `NavGrid` and `FlowField`).

use tileslide::{FlowField, NavConfig, NavError, NavGrid, TileMap, Vec2};

use crate::{
    Failure, coordinate, fill, free_boxed, give_boxed, guarded, map_ref, ts_map, ts_status,
};

/// A map's navigation grid (opaque): made by `ts_nav_create`, freed by `ts_nav_free`.
pub struct ts_nav {
    pub(crate) nav: NavGrid,
}

/// The way to one goal for circles of one radius from everywhere on a map (opaque): made
/// by `ts_flow_field_create`, freed by `ts_flow_field_free`.
pub struct ts_flow_field {
    pub(crate) field: FlowField,
}

fn nav_failure(e: &NavError) -> Failure {
    Failure::invalid(e.to_string())
}

/// The point (`x`, `y`), its coordinates named `names` in errors.
fn point(names: [&str; 2], x: f32, y: f32) -> Result<Vec2, Failure> {
    Ok(Vec2::new(
        coordinate(names[0], x)?,
        coordinate(names[1], y)?,
    ))
}

/// # Safety
/// `nav` is null or a live grid.
pub(crate) unsafe fn nav_ref<'a>(nav: *const ts_nav) -> Result<&'a NavGrid, Failure> {
    // SAFETY: null or a live grid, as the caller promises.
    unsafe { nav.as_ref() }
        .map(|n| &n.nav)
        .ok_or_else(|| Failure::null("nav"))
}

/// # Safety
/// `field` is null or a live field.
pub(crate) unsafe fn field_ref<'a>(field: *const ts_flow_field) -> Result<&'a FlowField, Failure> {
    // SAFETY: null or a live field, as the caller promises.
    unsafe { field.as_ref() }
        .map(|f| &f.field)
        .ok_or_else(|| Failure::null("field"))
}

/// The grid and the map a query runs on.
///
/// # Safety
/// `nav` and `map` are null or live.
unsafe fn nav_and_map<'a>(
    nav: *const ts_nav,
    map: *const ts_map,
) -> Result<(&'a NavGrid, &'a TileMap), Failure> {
    // SAFETY: as the caller promises.
    Ok(unsafe { (nav_ref(nav)?, map_ref(map)?) })
}

/// Builds the navigation grid of `map` for circles up to `max_radius` wide (positive, at
/// most 31 of the map's shorter cell side; building costs more the larger it is). Solid
/// segments block; one-way platforms block from their front only. On `TS_OK`, `*out` is
/// the grid, for `ts_nav_free`; use it with this map only.
///
/// # Safety
/// `map` is a live map; `out` points to a writable `ts_nav*`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_nav_create(
    map: *const ts_map,
    max_radius: f32,
    out: *mut *mut ts_nav,
) -> ts_status {
    guarded("ts_nav_create", || {
        // SAFETY: as the caller promises.
        let map = unsafe { map_ref(map) }?;
        if out.is_null() {
            return Err(Failure::null("out"));
        }
        let config = NavConfig {
            max_radius,
            ..NavConfig::default()
        };
        let nav = NavGrid::new(map, config).map_err(|e| nav_failure(&e))?;
        // SAFETY: not null, writable as the caller promises.
        unsafe { give_boxed(out, ts_nav { nav }) };
        Ok(())
    })
}

/// Frees a navigation grid (null is ignored).
///
/// # Safety
/// `nav` is null or a grid from this library not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_nav_free(nav: *mut ts_nav) {
    // SAFETY: null or from `ts_nav_create`, freed once, as the caller promises.
    unsafe { free_boxed(nav) };
}

/// The shortest path for a circle of `radius` from (`x0`, `y0`) to (`x1`, `y1`) on `map`
/// (the grid's map), smoothed into straight runs each clear by the map's circle cast
/// (`NavGrid::find_path`): its corners from start to goal into `out_xy`, `out_xy[2k]`,
/// `out_xy[2k + 1]` for corner k, room for `capacity` corners; `*count` is how many. A
/// path has at least two corners; `TS_OK` with `*count` 0 means there is none (the circle
/// does not fit at an end, or cannot get from one to the other), which is not an error.
/// When the corners do not fit, `TS_ERROR_BUFFER_TOO_SMALL` with only `*count` written.
///
/// # Safety
/// `nav` is a live grid, `map` a live map; `out_xy` has room for `2 capacity` floats (or is
/// null when `capacity` is 0); `count` is writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_nav_find_path(
    nav: *const ts_nav,
    map: *const ts_map,
    x0: f32,
    y0: f32,
    x1: f32,
    y1: f32,
    radius: f32,
    out_xy: *mut f32,
    capacity: usize,
    count: *mut usize,
) -> ts_status {
    guarded("ts_nav_find_path", || {
        // SAFETY: as the caller promises.
        let (nav, map) = unsafe { nav_and_map(nav, map) }?;
        if count.is_null() {
            return Err(Failure::null("count"));
        }
        let from = point(["x0", "y0"], x0, y0)?;
        let to = point(["x1", "y1"], x1, y1)?;
        let path = nav
            .find_path(map, from, to, radius)
            .map_err(|e| nav_failure(&e))?;
        let corners = path.as_ref().map_or(&[][..], |p| p.points());
        let pairs = corners.iter().map(|p| [p.x, p.y]);
        // SAFETY: `out_xy` has room for `capacity` pairs of floats, as the caller promises
        // (a `[f32; 2]` is two floats, aligned as one).
        unsafe {
            fill(
                pairs,
                corners.len(),
                out_xy.cast::<[f32; 2]>(),
                capacity,
                count,
                "path corners",
            )
        }
    })
}

/// Builds the flow field of the goal (`x`, `y`) for circles of `radius` on `map` (the
/// grid's map): every place's way to the goal, for crowds that share it. If the circle
/// does not fit at the goal, nothing reaches it. On `TS_OK`, `*out` is the field, for
/// `ts_flow_field_free`.
///
/// # Safety
/// `nav` is a live grid, `map` a live map; `out` points to a writable `ts_flow_field*`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_flow_field_create(
    nav: *const ts_nav,
    map: *const ts_map,
    x: f32,
    y: f32,
    radius: f32,
    out: *mut *mut ts_flow_field,
) -> ts_status {
    guarded("ts_flow_field_create", || {
        // SAFETY: as the caller promises.
        let (nav, map) = unsafe { nav_and_map(nav, map) }?;
        if out.is_null() {
            return Err(Failure::null("out"));
        }
        let goal = point(["x", "y"], x, y)?;
        let field = FlowField::new(nav, map, goal, radius).map_err(|e| nav_failure(&e))?;
        // SAFETY: not null, writable as the caller promises.
        unsafe { give_boxed(out, ts_flow_field { field }) };
        Ok(())
    })
}

/// Frees a flow field (null is ignored).
///
/// # Safety
/// `field` is null or a field from this library not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_flow_field_free(field: *mut ts_flow_field) {
    // SAFETY: null or from `ts_flow_field_create`, freed once, as the caller promises.
    unsafe { free_boxed(field) };
}

/// The unit direction a circle at (`x`, `y`) should move in to reach the field's goal
/// (`FlowField::direction`), into `*dx`, `*dy`: (0, 0) when it cannot reach the goal or
/// is on it. `nav` and `map` are the field's.
///
/// # Safety
/// `field`, `nav` and `map` are live; `dx` and `dy` are writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_flow_field_direction(
    field: *const ts_flow_field,
    nav: *const ts_nav,
    map: *const ts_map,
    x: f32,
    y: f32,
    dx: *mut f32,
    dy: *mut f32,
) -> ts_status {
    guarded("ts_flow_field_direction", || {
        // SAFETY: as the caller promises.
        let field = unsafe { field_ref(field) }?;
        // SAFETY: as the caller promises.
        let (nav, map) = unsafe { nav_and_map(nav, map) }?;
        if dx.is_null() || dy.is_null() {
            return Err(Failure::null(if dx.is_null() { "dx" } else { "dy" }));
        }
        let p = point(["x", "y"], x, y)?;
        let d = field
            .direction(nav, map, p)
            .map_err(|e| nav_failure(&e))?
            .unwrap_or(Vec2::ZERO);
        // SAFETY: not null, writable as the caller promises.
        unsafe {
            dx.write(d.x);
            dy.write(d.y);
        }
        Ok(())
    })
}

/// The length of the way from (`x`, `y`) to the field's goal along the field
/// (`FlowField::distance`), into `*out`: infinity when a circle there cannot reach it.
///
/// # Safety
/// `field`, `nav` and `map` are live; `out` is writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_flow_field_distance(
    field: *const ts_flow_field,
    nav: *const ts_nav,
    map: *const ts_map,
    x: f32,
    y: f32,
    out: *mut f32,
) -> ts_status {
    guarded("ts_flow_field_distance", || {
        // SAFETY: as the caller promises.
        let field = unsafe { field_ref(field) }?;
        // SAFETY: as the caller promises.
        let (nav, map) = unsafe { nav_and_map(nav, map) }?;
        if out.is_null() {
            return Err(Failure::null("out"));
        }
        let p = point(["x", "y"], x, y)?;
        let distance = field
            .distance(nav, map, p)
            .map_err(|e| nav_failure(&e))?
            .unwrap_or(f32::INFINITY);
        // SAFETY: not null, writable as the caller promises.
        unsafe { out.write(distance) };
        Ok(())
    })
}
