//! tileslide's C API (maps, ray casts, bodies, the character, hit volumes, paths, debug
//! lines), in the manner of Box2D v3's: opaque handles, ids passed by value, definition
//! structs with defaults, a status on every fallible call, the reason in
//! `ts_last_error_message()` (per thread), caller-supplied buffers for batches. No panic
//! crosses the boundary: each call runs under `catch_unwind` and a panic becomes
//! `TS_ERROR_PANIC`. Null pointers and coordinates that are not finite are refused
//! with a status, never read.
//!
//! The header, `include/tileslide.h`, is generated from this crate by cbindgen
//! (`tests/header.rs` fails when it is stale).

// The C boundary: raw pointers from C, `no_mangle` exports. Every `unsafe` block says why
// it is sound.
#![allow(unsafe_code)]
// C's names for C's types.
#![allow(non_camel_case_types)]

use std::cell::RefCell;
use std::ffi::{CStr, CString, c_char};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::Path;

mod bodies;
mod character;
mod debug;
mod hit_world;
mod nav;

pub use bodies::*;
pub use character::*;
pub use debug::*;
pub use hit_world::*;
pub use nav::*;
use tileslide::io::{LoadErrorKind, ascii};
use tileslide::limits::MAX_COORD;
use tileslide::{Faces, Owner, QueryFilter, Ray, RayHit, TileMap, Vec2};

/// What a call did: `TS_OK`, or why it did nothing (`ts_last_error_message()` says more).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ts_status {
    /// Done.
    TS_OK = 0,
    /// A pointer that must not be null was null.
    TS_ERROR_NULL_POINTER = 1,
    /// An argument was out of range: a coordinate that is not finite, a string that is not
    /// UTF-8, a cell size that is not positive, flags not defined.
    TS_ERROR_INVALID_ARGUMENT = 2,
    /// A file does not exist.
    TS_ERROR_NOT_FOUND = 3,
    /// A file could not be read.
    TS_ERROR_IO = 4,
    /// A file was read but is not a map tileslide can load (the message names the file,
    /// the position and the cause).
    TS_ERROR_LOAD = 5,
    /// tileslide panicked: a bug, reported rather than carried across the boundary.
    TS_ERROR_PANIC = 6,
    /// A body or hit object id whose body or object was removed (or that never named one).
    TS_ERROR_STALE_HANDLE = 7,
    /// A caller's buffer has less room than the answer needs: nothing was written to it,
    /// and the call's `count` says how many entries it needs.
    TS_ERROR_BUFFER_TOO_SMALL = 8,
}

/// A collision map (opaque): made by `ts_map_load_file` or `ts_map_from_ascii`, freed by
/// `ts_map_free`.
pub struct ts_map {
    map: TileMap,
}

/// A ray's hit: where along the ray (`t` in [0, 1] from start to end), the point, the
/// outward unit normal of the face hit, and the tile's cell and id (`TS_NONE` for each when
/// the face is not a tile's). In a batch, a ray that hits nothing has `t` NaN.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ts_ray_hit {
    /// Fraction of the way from the start to the end, in [0, 1]; NaN for a miss in a batch.
    pub t: f32,
    /// The point hit, x.
    pub x: f32,
    /// The point hit, y.
    pub y: f32,
    /// The face's outward unit normal, x.
    pub nx: f32,
    /// The face's outward unit normal, y.
    pub ny: f32,
    /// The column of the tile hit.
    pub col: u32,
    /// The row of the tile hit.
    pub row: u32,
    /// The id of the tile hit.
    pub tile: u32,
}

/// `col`, `row` and `tile` of a hit on no tile.
pub const TS_NONE: u32 = u32::MAX;

/// Ray flag: faces count from both sides (by default only faces the ray meets head-on).
pub const TS_RAY_BOTH_SIDES: u32 = 1;

const MISS: ts_ray_hit = ts_ray_hit {
    t: f32::NAN,
    x: f32::NAN,
    y: f32::NAN,
    nx: f32::NAN,
    ny: f32::NAN,
    col: TS_NONE,
    row: TS_NONE,
    tile: TS_NONE,
};

thread_local! {
    static LAST_ERROR: RefCell<CString> = RefCell::new(CString::default());
}

/// Shape: a circle (of a character or a hit volume).
pub const TS_SHAPE_CIRCLE: u32 = 0;

/// Shape: an axis-aligned rectangle, by its half width and half height.
pub const TS_SHAPE_RECT: u32 = 1;

/// Keeps `message` as this thread's last error.
fn set_error(message: &str) {
    // A message with a NUL in it (from a file name) is cut there rather than lost.
    let cut = message.split('\0').next().unwrap_or_default();
    let text = CString::new(cut).unwrap_or_default();
    LAST_ERROR.with(|e| *e.borrow_mut() = text);
}

/// A failure: its status and its message.
pub(crate) struct Failure(pub(crate) ts_status, pub(crate) String);

impl Failure {
    pub(crate) fn null(what: &str) -> Self {
        Failure(
            ts_status::TS_ERROR_NULL_POINTER,
            format!("{what} is a null pointer"),
        )
    }

    pub(crate) fn invalid(why: String) -> Self {
        Failure(ts_status::TS_ERROR_INVALID_ARGUMENT, why)
    }
}

/// The owner a body or hit object has in the core: its id, `(generation << 32) | index`,
/// so that hit events and debug lines name it.
pub(crate) fn owner_of(index: u32, generation: u32) -> Owner {
    Owner(u64::from(generation) << 32 | u64::from(index))
}

/// The id (`index`, `generation`) an owner from [`owner_of`] stands for.
pub(crate) fn id_parts(owner: Owner) -> (u32, u32) {
    (owner.0 as u32, (owner.0 >> 32) as u32)
}

/// `value`, named `what` in errors, when it is finite and within tileslide's coordinate
/// range (`MAX_COORD`, 2²⁴ map units from the origin).
/// Whether `n` values of `T` fit in memory: a slice of them may be made (its size in bytes
/// at most `isize::MAX`). A count past that cannot describe the caller's memory, and making
/// the slice would be undefined behaviour: such a count is refused first.
pub(crate) fn slice_fits<T>(n: usize) -> bool {
    n.checked_mul(std::mem::size_of::<T>())
        .is_some_and(|bytes| isize::try_from(bytes).is_ok())
}

pub(crate) fn coordinate(what: &str, value: f32) -> Result<f32, Failure> {
    if value.is_finite() && value.abs() <= MAX_COORD {
        Ok(value)
    } else {
        Err(Failure::invalid(format!(
            "{what} is {value}: it must be finite and at most {MAX_COORD} in magnitude"
        )))
    }
}

/// Writes `items` (`n` of them) into the caller's buffer `out` (room for `capacity`) and
/// `n` into `*count`, `what` naming them in errors. When they do not fit, only `*count` is
/// written (`TS_ERROR_BUFFER_TOO_SMALL`), so the caller can make room and ask again; a null
/// `out` with room said is refused before anything is written.
///
/// # Safety
/// `count` is null or writable; `out` is null or has room for `capacity` items.
pub(crate) unsafe fn fill<T>(
    items: impl Iterator<Item = T>,
    n: usize,
    out: *mut T,
    capacity: usize,
    count: *mut usize,
    what: &str,
) -> Result<(), Failure> {
    if count.is_null() {
        return Err(Failure::null("count"));
    }
    // A buffer with room is a buffer: null there is a mistake, whatever the answer's size.
    if capacity > 0 && out.is_null() {
        return Err(Failure::null("out"));
    }
    // SAFETY: not null, writable as the caller promises.
    unsafe { count.write(n) };
    if n > capacity {
        return Err(Failure(
            ts_status::TS_ERROR_BUFFER_TOO_SMALL,
            format!("{n} {what} do not fit in a buffer of {capacity}"),
        ));
    }
    for (k, item) in items.take(n).enumerate() {
        // SAFETY: k < n <= capacity, and `out` has room for `capacity` items.
        unsafe { out.add(k).write(item) };
    }
    Ok(())
}

/// Puts `value` in a box behind `out`, for the C caller to own until it frees it with
/// [`free_boxed`].
///
/// # Safety
/// `out` is not null and points to writable memory for a pointer.
pub(crate) unsafe fn give_boxed<T>(out: *mut *mut T, value: T) {
    // SAFETY: checked not null by the caller; writable as the C caller promises.
    unsafe { out.write(Box::into_raw(Box::new(value))) };
}

/// Frees what [`give_boxed`] gave (null is ignored). Dropping does not panic; catching one
/// anyway keeps it on this side.
///
/// # Safety
/// `ptr` is null or came from `give_boxed` and is not yet freed.
pub(crate) unsafe fn free_boxed<T>(ptr: *mut T) {
    if ptr.is_null() {
        return;
    }
    let _ = catch_unwind(AssertUnwindSafe(|| {
        // SAFETY: from `Box::into_raw` in `give_boxed`, freed once as the caller promises.
        drop(unsafe { Box::from_raw(ptr) });
    }));
}

/// Runs `body` with panics caught: its status, with the message kept on failure.
pub(crate) fn guarded(name: &str, body: impl FnOnce() -> Result<(), Failure>) -> ts_status {
    match catch_unwind(AssertUnwindSafe(body)) {
        Ok(Ok(())) => ts_status::TS_OK,
        Ok(Err(Failure(status, message))) => {
            set_error(&format!("{name}: {message}"));
            status
        }
        Err(_) => {
            set_error(&format!(
                "{name}: tileslide panicked (a bug: please report it)"
            ));
            ts_status::TS_ERROR_PANIC
        }
    }
}

/// The UTF-8 string at `ptr`, named `what` in errors.
///
/// # Safety
/// `ptr` is null or points to a NUL-terminated string that stays valid for the call.
unsafe fn text<'a>(ptr: *const c_char, what: &str) -> Result<&'a str, Failure> {
    if ptr.is_null() {
        return Err(Failure::null(what));
    }
    // SAFETY: not null, and the caller promises a NUL-terminated string.
    let c = unsafe { CStr::from_ptr(ptr) };
    c.to_str()
        .map_err(|e| Failure::invalid(format!("{what} is not UTF-8 ({e})")))
}

/// The map behind `map`, named in errors.
///
/// # Safety
/// `map` is null or a live map from this library.
pub(crate) unsafe fn map_ref<'a>(map: *const ts_map) -> Result<&'a TileMap, Failure> {
    // SAFETY: null or a live map, as the caller promises.
    unsafe { map.as_ref() }
        .map(|m| &m.map)
        .ok_or_else(|| Failure::null("map"))
}

fn load_failure(e: &tileslide::io::LoadError) -> Failure {
    let status = match e.io_error_kind() {
        Some(std::io::ErrorKind::NotFound) => ts_status::TS_ERROR_NOT_FOUND,
        Some(_) => ts_status::TS_ERROR_IO,
        None if matches!(e.kind, LoadErrorKind::Parameter(_)) => {
            ts_status::TS_ERROR_INVALID_ARGUMENT
        }
        None => ts_status::TS_ERROR_LOAD,
    };
    Failure(status, e.to_string())
}

/// This thread's last error: which call failed and why (the file, the position and the
/// cause for a map that did not load). Empty before any failure. The text stays valid until
/// the next failing call on this thread.
#[unsafe(no_mangle)]
pub extern "C" fn ts_last_error_message() -> *const c_char {
    LAST_ERROR.with(|e| e.borrow().as_ptr())
}

/// tileslide's version, as "major.minor.patch".
#[unsafe(no_mangle)]
pub extern "C" fn ts_version() -> *const c_char {
    concat!(env!("CARGO_PKG_VERSION"), "\0").as_ptr().cast()
}

/// Loads the map at `path` (UTF-8), its format told by its extension: `.txt` ASCII (unit
/// cells), `.bin` Replica Island (needs `tileset_path_or_null`, its `collision.bin`),
/// `.tsm` baked, `.tmx`/`.tmj`/`.json` Tiled, `.ldtk` LDtk (the first level). On `TS_OK`,
/// `*out` is the map, for `ts_map_free`; otherwise `*out` is left as it was.
///
/// # Safety
/// `path` is a NUL-terminated string; `tileset_path_or_null` is one or null; `out` points
/// to a writable `ts_map*`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_map_load_file(
    path: *const c_char,
    tileset_path_or_null: *const c_char,
    out: *mut *mut ts_map,
) -> ts_status {
    guarded("ts_map_load_file", || {
        if out.is_null() {
            return Err(Failure::null("out"));
        }
        // SAFETY: as the caller promises.
        let path = unsafe { text(path, "path") }?;
        let tileset = if tileset_path_or_null.is_null() {
            None
        } else {
            // SAFETY: not null, and a string as the caller promises.
            Some(Path::new(unsafe {
                text(tileset_path_or_null, "tileset_path")
            }?))
        };
        let map = tileslide::io::load_file(path, tileset).map_err(|e| load_failure(&e))?;
        // SAFETY: `out` is not null and writable.
        unsafe { give_boxed(out, ts_map { map }) };
        Ok(())
    })
}

/// Builds a map from ASCII text (`#` solid, `.` empty, `/` `\` ramps, `=` one-way; rows
/// top to bottom) with square cells of side `cell`. On `TS_OK`, `*out` is the map.
///
/// # Safety
/// `text` is a NUL-terminated string; `out` points to a writable `ts_map*`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_map_from_ascii(
    text: *const c_char,
    cell: f32,
    out: *mut *mut ts_map,
) -> ts_status {
    guarded("ts_map_from_ascii", || {
        if out.is_null() {
            return Err(Failure::null("out"));
        }
        // SAFETY: as the caller promises.
        let source = unsafe { self::text(text, "text") }?;
        if !(cell.is_finite() && cell > 0.0) {
            return Err(Failure::invalid(format!(
                "cell is {cell}: it must be finite and positive"
            )));
        }
        let map = ascii::parse(source, "<ascii>", cell).map_err(|e| load_failure(&e))?;
        // SAFETY: `out` is not null and writable.
        unsafe { give_boxed(out, ts_map { map }) };
        Ok(())
    })
}

/// Frees a map (null is ignored).
///
/// # Safety
/// `map` is null or a map from this library not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_map_free(map: *mut ts_map) {
    // SAFETY: null or a map from this library, freed once, as the caller promises.
    unsafe { free_boxed(map) };
}

/// The map's size in cells (`width`, `height`, either pointer may be null) and its cells'
/// size (`cell_w`, `cell_h`, either may be null).
///
/// # Safety
/// `map` is a live map; the others are null or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_map_size(
    map: *const ts_map,
    width: *mut u32,
    height: *mut u32,
    cell_w: *mut f32,
    cell_h: *mut f32,
) -> ts_status {
    guarded("ts_map_size", || {
        // SAFETY: as the caller promises.
        let m = unsafe { map_ref(map) }?;
        let cell = m.cell_size();
        // SAFETY: each is null (skipped) or writable, as the caller promises.
        unsafe {
            for (ptr, value) in [(width, m.width()), (height, m.height())] {
                if let Some(slot) = ptr.as_mut() {
                    *slot = value;
                }
            }
            for (ptr, value) in [(cell_w, cell.x), (cell_h, cell.y)] {
                if let Some(slot) = ptr.as_mut() {
                    *slot = value;
                }
            }
        }
        Ok(())
    })
}

/// The query filter of `flags`.
fn filter_of(flags: u32) -> Result<QueryFilter, Failure> {
    if flags & !TS_RAY_BOTH_SIDES != 0 {
        return Err(Failure::invalid(format!(
            "flags {flags:#x} has bits no flag defines (TS_RAY_BOTH_SIDES is {TS_RAY_BOTH_SIDES})"
        )));
    }
    let mut filter = QueryFilter::default();
    if flags & TS_RAY_BOTH_SIDES != 0 {
        filter.faces = Faces::Both;
    }
    Ok(filter)
}

fn hit_of(hit: &RayHit) -> ts_ray_hit {
    let cell = hit.cell();
    ts_ray_hit {
        t: hit.t,
        x: hit.point.x,
        y: hit.point.y,
        nx: hit.normal.x,
        ny: hit.normal.y,
        col: cell.map_or(TS_NONE, |c| c.col),
        row: cell.map_or(TS_NONE, |c| c.row),
        tile: hit.tile().map_or(TS_NONE, |t| t.0),
    }
}

/// The ray from (`x0`, `y0`) to (`x1`, `y1`), or why not.
fn ray_of(x0: f32, y0: f32, x1: f32, y1: f32) -> Result<Ray, String> {
    let ray = Ray::between(Vec2::new(x0, y0), Vec2::new(x1, y1));
    if ray.is_finite() {
        Ok(ray)
    } else {
        Err(format!(
            "the ray ({x0}, {y0}) to ({x1}, {y1}) is not finite"
        ))
    }
}

/// Casts the ray from (`x0`, `y0`) to (`x1`, `y1`): true, with the first hit in `*out`,
/// when it hits a face; false when it hits nothing, and false with
/// `ts_last_error_message()` set when it could not be cast (a null pointer, a coordinate
/// that is not finite, undefined flags). `flags`: 0 or `TS_RAY_BOTH_SIDES`.
///
/// # Safety
/// `map` is a live map; `out` points to a writable `ts_ray_hit`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_map_cast_ray(
    map: *const ts_map,
    x0: f32,
    y0: f32,
    x1: f32,
    y1: f32,
    flags: u32,
    out: *mut ts_ray_hit,
) -> bool {
    let mut found = false;
    guarded("ts_map_cast_ray", || {
        // SAFETY: as the caller promises.
        let m = unsafe { map_ref(map) }?;
        if out.is_null() {
            return Err(Failure::null("out"));
        }
        let filter = filter_of(flags)?;
        let ray = ray_of(x0, y0, x1, y1).map_err(Failure::invalid)?;
        if let Some(hit) = m.cast_ray(ray, &filter) {
            // SAFETY: not null, writable as the caller promises.
            unsafe { out.write(hit_of(&hit)) };
            found = true;
        }
        Ok(())
    });
    found
}

/// Rays cast a chunk at a time, so the batch's buffers stay small whatever `n` is.
const CHUNK: usize = 4096;

/// Casts `n` rays, `rays[4k..4k+4]` = x0, y0, x1, y1 of ray k, with the batch's SIMD walk:
/// `out[k]` is ray k's first hit, or a miss (`t` NaN, `col`, `row` and `tile` `TS_NONE`).
/// Every ray is checked before any is cast: a coordinate that is not finite, or ends so far
/// apart that the ray's length overflows a float, fails the call
/// (`TS_ERROR_INVALID_ARGUMENT`, naming the ray) and leaves `out` as it was.
///
/// # Safety
/// `map` is a live map; `rays` points to `4 n` floats and `out` to `n` writable
/// `ts_ray_hit`s (either may be null when `n` is 0).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_map_cast_rays(
    map: *const ts_map,
    rays: *const f32,
    n: usize,
    flags: u32,
    out: *mut ts_ray_hit,
) -> ts_status {
    guarded("ts_map_cast_rays", || {
        // SAFETY: as the caller promises.
        let m = unsafe { map_ref(map) }?;
        let filter = filter_of(flags)?;
        if n == 0 {
            return Ok(());
        }
        if rays.is_null() {
            return Err(Failure::null("rays"));
        }
        if out.is_null() {
            return Err(Failure::null("out"));
        }
        let Some(floats) = n
            .checked_mul(4)
            .filter(|&f| slice_fits::<f32>(f) && slice_fits::<ts_ray_hit>(n))
        else {
            return Err(Failure::invalid(format!("n = {n} rays is too many")));
        };
        // SAFETY: `rays` holds 4 n floats and `out` n hits, as the caller promises; C
        // memory does not alias a Rust reference.
        let (input, output) = unsafe {
            (
                std::slice::from_raw_parts(rays, floats),
                std::slice::from_raw_parts_mut(out, n),
            )
        };
        // Coordinates that are not finite, or ends so far apart that the ray's length
        // overflows (which would cast as a silent miss).
        let bad = input
            .chunks_exact(4)
            .position(|r| !Ray::between(Vec2::new(r[0], r[1]), Vec2::new(r[2], r[3])).is_finite());
        if let Some(ray) = bad {
            let r = &input[ray * 4..ray * 4 + 4];
            let why = if r.iter().all(|v| v.is_finite()) {
                "is too long to cast"
            } else {
                "is not finite"
            };
            return Err(Failure::invalid(format!(
                "ray {ray}, ({}, {}) to ({}, {}), {why}",
                r[0], r[1], r[2], r[3]
            )));
        }
        let mut batch = Vec::with_capacity(CHUNK.min(n));
        let mut hits = Vec::with_capacity(CHUNK.min(n));
        for (coords, slots) in input.chunks(CHUNK * 4).zip(output.chunks_mut(CHUNK)) {
            batch.clear();
            batch.extend(
                coords
                    .chunks_exact(4)
                    .map(|r| Ray::between(Vec2::new(r[0], r[1]), Vec2::new(r[2], r[3]))),
            );
            m.cast_rays_into(&batch, &filter, &mut hits);
            for (slot, hit) in slots.iter_mut().zip(&hits) {
                *slot = hit.as_ref().map_or(MISS, hit_of);
            }
        }
        Ok(())
    })
}
