//! The grid walk under every ray query: Amanatides & Woo, "A Fast Voxel Traversal Algorithm
//! for Ray Tracing" (Eurographics 1987), extended so that the walk visits **every cell whose
//! closed rectangle the ray touches**:
//!
//! - where the ray crosses a cell corner exactly (or within rounding of it), both cells
//!   beside the corner are visited before the diagonal one (Bresenham, which Replica Island
//!   used, skips them);
//! - the cells that only touch the start point (a ray starting on a cell boundary) are
//!   visited;
//! - a ray running exactly along a grid line walks the strips of cells on both sides.
//!
//! Every segment lies in the closed rectangle of its own cell, so a segment the ray hits is
//! always in a visited cell; together with visiting cells in order of entry this lets the
//! caller stop as soon as its nearest hit lies before the current cell's exit (the hit is
//! then the global nearest).

use glam::Vec2;

/// How close (in cells) a ray may pass to a cell for the walk to visit it anyway. It
/// covers the rounding of world-to-grid coordinates and of the walk's own arithmetic: a
/// cell visited needlessly costs a little time (hits are decided by the exact segment
/// test), a cell the ray touches but the walk skips would lose a hit.
pub(crate) const TOUCH_TOLERANCE: f32 = 1e-4;

/// `a <= b`, false when either is NaN (so a NaN ends a walk).
#[inline(always)]
fn at_most(a: f32, b: f32) -> bool {
    matches!(
        a.partial_cmp(&b),
        Some(std::cmp::Ordering::Less | std::cmp::Ordering::Equal)
    )
}

/// A ray in grid units (cell (c, r) covers `[c, c+1) × [r, r+1)`).
pub(crate) struct GridRay {
    pub origin: Vec2,
    pub delta: Vec2,
    pub width: u32,
    pub height: u32,
}

/// How far outside the map (in cells, beyond its larger side) a ray may start and still
/// be walked in `f32` (see [`GridRay::is_ordinary`]).
const ORDINARY_MARGIN: f32 = 8.0;
/// The longest motion along an axis (in cells) walked in `f32`: 2³². Longer rays, and the
/// world lengths they stand for (at most 2³² cells of at most 2²⁵ units, within
/// `geometry::ray::NARROW`), keep every crossing fraction and its inverse normal.
const ORDINARY_MAX_DELTA: f32 = 4_294_967_296.0;
/// The shortest non-zero motion along an axis (in cells) walked in `f32`: 2⁻³², so that
/// `1 / delta` stays finite.
const ORDINARY_MIN_DELTA: f32 = 1.0 / 4_294_967_296.0;

impl GridRay {
    /// Whether the walks in `f32` (`fast_walk`, [`walk`], the batch) and the `f32` ray–segment
    /// kernel answer this ray: it starts within the map's larger side plus
    /// [`ORDINARY_MARGIN`] cells of the map, and each axis of its motion is 0 or between
    /// [`ORDINARY_MIN_DELTA`] and [`ORDINARY_MAX_DELTA`] cells. There the grid coordinates
    /// keep the precision the touch tolerance assumes, nothing overflows, and the world
    /// coordinates stay within `geometry::ray::NARROW`. False for NaN and infinities.
    /// Other rays take the `f64` path (`TileMap::cast_ray_wide`). No branch: the batch
    /// evaluates it in SIMD lanes.
    // `&` rather than `contains`' `&&`: no branch, as the batch's lanes want.
    #[allow(clippy::manual_range_contains)]
    #[inline(always)]
    pub fn is_ordinary(&self) -> bool {
        let (w, h) = (self.width as f32, self.height as f32);
        let margin = if w > h { w } else { h } + ORDINARY_MARGIN;
        let o = self.origin;
        let near = (o.x >= -margin) & (o.x <= w + margin) & (o.y >= -margin) & (o.y <= h + margin);
        let length_ok = |x: f32| {
            let a = x.abs();
            (x == 0.0) | ((a >= ORDINARY_MIN_DELTA) & (a <= ORDINARY_MAX_DELTA))
        };
        near & length_ok(self.delta.x) & length_ok(self.delta.y)
    }

    /// [`TOUCH_TOLERANCE`] as a ray fraction, along the faster-moving axis (0 for a
    /// zero-length ray).
    pub fn tolerance_t(&self) -> f32 {
        let longest = self.delta.x.abs().max(self.delta.y.abs());
        if longest > 0.0 {
            TOUCH_TOLERANCE / longest
        } else {
            0.0
        }
    }
}

/// Calls `visit(cell_index, t_exit)` for every cell the ray touches up to `t_limit`
/// (within [`TOUCH_TOLERANCE`]), roughly in order of entry; stops when `visit` returns
/// `true`. `t_exit` is the ray fraction at which the walk leaves the cell, or `-∞` for an
/// extra cell (a corner's side cell, a cell touching only the start) after which the caller
/// must not stop.
#[inline(always)]
pub(crate) fn walk(ray: &GridRay, t_limit: f32, mut visit: impl FnMut(usize, f32) -> bool) {
    let (o, d) = (ray.origin, ray.delta);
    if !(o.is_finite() && d.is_finite()) || d == Vec2::ZERO {
        return;
    }
    let size = Vec2::new(ray.width as f32, ray.height as f32);
    let tol_t = ray.tolerance_t();
    // Clip [0, t_limit] (widened by the tolerance) to the map rectangle, also widened, so
    // that a ray touching the map's border is not clipped away by rounding (slab test).
    let (mut t_lo, mut t_hi) = (0.0f32, t_limit + tol_t);
    for axis in 0..2 {
        let (o, d, n) = (o[axis], d[axis], size[axis]);
        let (lo, hi) = (-TOUCH_TOLERANCE, n + TOUCH_TOLERANCE);
        if d == 0.0 {
            if !(o >= lo && o <= hi) {
                return;
            }
        } else {
            let inv = 1.0 / d;
            let (t0, t1) = ((lo - o) * inv, (hi - o) * inv);
            t_lo = t_lo.max(t0.min(t1));
            t_hi = t_hi.min(t0.max(t1));
        }
    }
    if !at_most(t_lo, t_hi) {
        return;
    }
    let start = o + d * t_lo;
    let clamp = |v: f32, n: u32| (v.floor().max(0.0) as u32).min(n - 1);
    let (col, row) = (clamp(start.x, ray.width), clamp(start.y, ray.height));
    // Every cell within the tolerance of the start point touches the ray there.
    let (c_lo, c_hi) = (
        clamp(start.x - TOUCH_TOLERANCE, ray.width),
        clamp(start.x + TOUCH_TOLERANCE, ray.width),
    );
    let (r_lo, r_hi) = (
        clamp(start.y - TOUCH_TOLERANCE, ray.height),
        clamp(start.y + TOUCH_TOLERANCE, ray.height),
    );
    let w = ray.width as usize;
    for r in r_lo..=r_hi {
        for c in c_lo..=c_hi {
            if (c, r) != (col, row) && visit(r as usize * w + c as usize, f32::NEG_INFINITY) {
                return;
            }
        }
    }
    walk_strip(ray, t_hi, tol_t, col, row, &mut visit);
    // A ray running along a grid line touches the strip of cells on its other side too.
    // Each strip's early stop is valid only within it, so the other strip is walked even
    // when the first one stopped.
    if d.y == 0.0 {
        for r in (r_lo..=r_hi).filter(|&r| r != row) {
            walk_strip(ray, t_hi, tol_t, col, r, &mut visit);
        }
    } else if d.x == 0.0 {
        for c in (c_lo..=c_hi).filter(|&c| c != col) {
            walk_strip(ray, t_hi, tol_t, c, row, &mut visit);
        }
    }
}

/// The Amanatides & Woo loop from cell (`col`, `row`). Returns `true` if `visit` stopped it.
#[inline(always)]
fn walk_strip(
    ray: &GridRay,
    t_hi: f32,
    tol_t: f32,
    mut col: u32,
    mut row: u32,
    visit: &mut impl FnMut(usize, f32) -> bool,
) -> bool {
    let w = ray.width;
    let (o, d) = (ray.origin, ray.delta);
    let step_x: i32 = if d.x > 0.0 {
        1
    } else if d.x < 0.0 {
        -1
    } else {
        0
    };
    let step_y: i32 = if d.y > 0.0 {
        1
    } else if d.y < 0.0 {
        -1
    } else {
        0
    };
    let inv = Vec2::new(1.0 / d.x, 1.0 / d.y);
    // The ray fraction where it crosses the next vertical (x) or horizontal (y) grid line,
    // computed from the origin each time rather than accumulated, so no error builds up.
    let next_x = |col: u32| -> f32 {
        match step_x {
            1 => (col as f32 + 1.0 - o.x) * inv.x,
            -1 => (col as f32 - o.x) * inv.x,
            _ => f32::INFINITY,
        }
    };
    let next_y = |row: u32| -> f32 {
        match step_y {
            1 => (row as f32 + 1.0 - o.y) * inv.y,
            -1 => (row as f32 - o.y) * inv.y,
            _ => f32::INFINITY,
        }
    };
    let (mut tx, mut ty) = (next_x(col), next_y(row));
    // Each step moves one column or row (a corner step both) in a fixed direction, so no
    // walk is longer than this; the bound also ends it if rounding ever produced a NaN.
    let max_steps = ray.width as u64 + ray.height as u64 + 2;
    for _ in 0..max_steps {
        let t_next = tx.min(ty);
        if visit((row * w + col) as usize, t_next) {
            return true;
        }
        if !at_most(t_next, t_hi) {
            return false;
        }
        let corner = step_x != 0 && step_y != 0 && (tx - ty).abs() <= tol_t;
        if corner {
            // Through a corner: visit both side cells, then go on diagonally.
            let nc = col as i64 + step_x as i64;
            let nr = row as i64 + step_y as i64;
            let in_x = nc >= 0 && nc < w as i64;
            let in_y = nr >= 0 && nr < ray.height as i64;
            if in_x && visit((row * w) as usize + nc as usize, f32::NEG_INFINITY) {
                return true;
            }
            if in_y && visit(nr as usize * w as usize + col as usize, f32::NEG_INFINITY) {
                return true;
            }
            if !(in_x && in_y) {
                return false;
            }
            col = nc as u32;
            row = nr as u32;
            tx = next_x(col);
            ty = next_y(row);
        } else if tx < ty {
            let nc = col as i64 + step_x as i64;
            if nc < 0 || nc >= w as i64 {
                return false;
            }
            col = nc as u32;
            tx = next_x(col);
        } else {
            let nr = row as i64 + step_y as i64;
            if nr < 0 || nr >= ray.height as i64 {
                return false;
            }
            row = nr as u32;
            ty = next_y(row);
        }
    }
    false
}
