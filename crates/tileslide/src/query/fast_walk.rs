//! The common case of the closest-hit walk, specialised for speed.
//!
//! A ray that starts strictly inside the map, off every grid line, parallel to neither axis,
//! and crosses no cell corner is walked here with Amanatides & Woo (1987) in its plainest
//! form. Anything else returns [`FastWalk::Fallback`] and the caller walks it again from the
//! start with the general `traversal::walk`; hits found so far stay valid, since every hit
//! recorded is a true hit.
//!
//! The walk reads one byte per visited cell, the cell's *kind* (see `tiles::store`): empty,
//! general (test its segments), or the set of whole-edge solid faces it exposes. For a
//! front-face query, a ray entering a cell of the last sort hits it exactly when it enters
//! through one of those faces, which the walk knows from the step it just took: the decision
//! needs no segment data at all.

use std::cell::LazyCell;

use glam::Vec2;

use super::segment_test::{SegmentTest, cell_segments};
use super::traversal::{GridRay, TOUCH_TOLERANCE};
use crate::tiles::face_kind::{FACE_MAX_X, FACE_MAX_Y, FACE_MIN_X, FACE_MIN_Y, KIND_GENERAL};
use crate::tiles::store::HotSegment;

/// How the fast walk ended. Small, so it comes back in a register.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum FastWalk {
    /// The walk finished; the nearest hit on a general cell, if any, is in the `best`
    /// argument.
    Done,
    /// The ray enters cell `index` through its exposed whole-edge face `face` (a `FACE_*`
    /// bit; `kind` is the cell's kind) before any hit found so far: that face is the nearest
    /// hit, up to the exact intersection the caller computes.
    Face {
        index: u32,
        col: u32,
        row: u32,
        face: u8,
        kind: u8,
    },
    /// The ray needs the general walk.
    Fallback,
}

/// The map data the walk reads.
pub(crate) struct WalkData<'a> {
    pub kinds: &'a [u8],
    pub starts: &'a [u32],
    pub hot: &'a [HotSegment],
}

/// Where the fast walk of a ray starts: its state before the first cell is visited.
#[derive(Clone, Copy, Debug)]
pub(crate) struct WalkStart {
    /// The ray's origin, in grid units.
    pub o: Vec2,
    /// `1 / delta`, per axis.
    pub inv: Vec2,
    /// The touch tolerance as a ray fraction, along the faster-moving axis.
    pub tol_t: f32,
    /// The walk ends once a cell's exit lies past this fraction (see `new`).
    pub t_stop: f32,
    /// The next grid line on each axis...
    pub line_x: i32,
    pub line_y: i32,
    /// ...and the ray fraction where it is crossed.
    pub tx: f32,
    pub ty: f32,
    /// The start cell's index, and the index steps along x and y (a map has fewer than
    /// 2³¹ cells: `MAX_CELLS`). All fields are 32 bits wide, so that rays set up side by
    /// side fill SIMD lanes evenly.
    pub index: i32,
    pub index_step_x: i32,
    pub index_step_y: i32,
    /// ±1: the grid-line steps along x and y.
    pub step_x: i32,
    pub step_y: i32,
    /// The face a step along x (y) enters the next cell through.
    pub enter_x: u8,
    pub enter_y: u8,
}

impl WalkStart {
    /// The start of `ray`'s fast walk up to `limit`, or `None` when the ray needs the
    /// general walk: it starts outside the map or within the touch tolerance of a grid
    /// line, or it is parallel to an axis.
    #[inline(always)]
    pub fn new(ray: &GridRay, limit: f32) -> Option<Self> {
        let (fits, start) = Self::lane(ray, limit);
        fits.then_some(start)
    }

    /// [`new`](Self::new) without a branch, for rays walked side by side in SIMD lanes
    /// (`ray_batch`): whether the fast walk fits the ray, and its start, which is
    /// meaningless (but computed without overflow or panic, with `index` 0) when it does
    /// not fit. Both forms share this arithmetic, so a ray's walk is the same bit for bit
    /// whichever form started it.
    #[inline(always)]
    pub fn lane(ray: &GridRay, limit: f32) -> (bool, Self) {
        let (o, d) = (ray.origin, ray.delta);
        let (w, h) = (ray.width as i32, ray.height as i32);
        let inside = (o.x > 0.0) & (o.y > 0.0) & (o.x < w as f32) & (o.y < h as f32);
        let (col, row) = (floor_off_line(o.x), floor_off_line(o.y));
        // A start within the tolerance of a grid line touches the cells on its other side.
        // (This also rejects every start whose `floor_off_line` is not its floor.)
        let (fx, fy) = (o.x - col as f32, o.y - row as f32);
        let off_line = |f: f32| (f > TOUCH_TOLERANCE) & (f < 1.0 - TOUCH_TOLERANCE);
        let fits = inside & (d.x != 0.0) & (d.y != 0.0) & off_line(fx) & off_line(fy);
        let step_x: i32 = if d.x > 0.0 { 1 } else { -1 };
        let step_y: i32 = if d.y > 0.0 { 1 } else { -1 };
        let inv = d.recip();
        // (Comparisons rather than `f32::min`, whose NaN handling costs instructions: a NaN
        // here only ever reaches a ray that does not fit.)
        let (ax, ay) = (inv.x.abs(), inv.y.abs());
        let tol_t = TOUCH_TOLERANCE * if ax < ay { ax } else { ay };
        // The next grid line on each axis, and the ray fraction there (computed from the
        // origin each time, so no error accumulates). Kept as integers: a float-to-int
        // conversion costs several instructions in Rust (it saturates), the other way one.
        let line_x = col.wrapping_add((step_x > 0) as i32);
        let line_y = row.wrapping_add((step_y > 0) as i32);
        // The walk ends when the next cell starts past `limit` or outside the map. The
        // second happens at `t_leave`, computed by the same formula as the crossings at the
        // map's last grid line; one comparison with `t_stop` checks both: stop when
        // `t_exit > limit || t_exit >= t_leave`.
        let edge_x = if step_x > 0 { w as f32 } else { 0.0 };
        let edge_y = if step_y > 0 { h as f32 } else { 0.0 };
        let (leave_x, leave_y) = ((edge_x - o.x) * inv.x, (edge_y - o.y) * inv.y);
        let t_leave = if leave_x < leave_y { leave_x } else { leave_y };
        let limit = limit + tol_t;
        let t_stop = if t_leave <= limit {
            // The largest float below `t_leave` (> 0 when the origin is strictly inside).
            f32::from_bits(t_leave.to_bits().wrapping_sub(1))
        } else {
            limit
        };
        let index = row.wrapping_mul(w).wrapping_add(col);
        let start = Self {
            o,
            inv,
            tol_t,
            t_stop,
            line_x,
            line_y,
            tx: (line_x as f32 - o.x) * inv.x,
            ty: (line_y as f32 - o.y) * inv.y,
            index: if fits { index } else { 0 },
            index_step_x: step_x,
            index_step_y: step_y.wrapping_mul(w),
            step_x,
            step_y,
            enter_x: if step_x > 0 { FACE_MIN_X } else { FACE_MAX_X },
            enter_y: if step_y > 0 { FACE_MIN_Y } else { FACE_MAX_Y },
        };
        (fits, start)
    }
}

/// `x.floor()` as an integer for every `x` in `[0, 2²²)` at least [`TOUCH_TOLERANCE`] from
/// an integer, and for anything else some integer without panic or overflow (the caller's
/// `fits` test rejects those starts anyway: their fraction `x − floor` comes out within the
/// tolerance of 0 or 1, or the start lies outside the map).
///
/// Rounding `x − ½` to an integer by adding `1.5 · 2²³` (the float's own rounding does
/// it) costs three instructions, and as many in SIMD lanes; Rust's `as i32` saturates and
/// maps NaN to 0, which takes about ten, and more than twice that in lanes.
#[inline(always)]
fn floor_off_line(x: f32) -> i32 {
    const ROUND: f32 = 12_582_912.0; // 1.5 · 2²³: its ulp is 1
    let rounded = (x - 0.5) + ROUND;
    (rounded.to_bits() as i32).wrapping_sub(ROUND.to_bits() as i32)
}

/// Walks `ray` up to `limit`, testing general cells' segments with `test` and recording a
/// nearer hit in `best_t` and `best` (cell index, segment index); stops once `best_t` lies
/// before the current cell's exit, or at the first exposed face it enters when `by_faces`
/// (see [`SegmentTest::decides_by_faces`]). `test` is built only if a cell's segments are
/// tested: a face hit needs none.
#[inline(always)]
pub(crate) fn fast_walk(
    ray: &GridRay,
    data: &WalkData<'_>,
    test: &LazyCell<SegmentTest, impl FnOnce() -> SegmentTest>,
    by_faces: bool,
    limit: f32,
    best_t: &mut f32,
    best: &mut Option<(usize, u32)>,
) -> FastWalk {
    let Some(start) = WalkStart::new(ray, limit) else {
        return FastWalk::Fallback;
    };
    let WalkStart {
        o,
        inv,
        tol_t,
        t_stop,
        mut line_x,
        mut line_y,
        mut tx,
        mut ty,
        index,
        index_step_x,
        index_step_y,
        step_x,
        step_y,
        enter_x,
        enter_y,
    } = start;
    let kinds = data.kinds;
    // The start cell is inside the map, so its index is not negative.
    let mut index = index as usize;
    let (index_step_x, index_step_y) = (index_step_x as isize, index_step_y as isize);
    // Faces decide only front-face queries that see solid segments; otherwise face cells
    // are tested like general ones.
    let face_mask: u8 = if by_faces { 0x0f } else { 0 };
    let general_mask: u8 = if by_faces { KIND_GENERAL } else { 0xff };
    // The start cell is not entered through any face.
    let mut entered: u8 = 0;
    // Four steps to a turn of the outer loop: measured about 6 % faster on the rays scene
    // (each step's branches get their own address in the predictor, and the loop's own
    // branch runs a quarter as often).
    loop {
        for _ in 0..4 {
            // Not `f32::min`: its NaN handling costs instructions, and no NaN gets here.
            let t_exit = if tx < ty { tx } else { ty };
            let kind = kinds[index];
            if kind != 0 {
                if kind & entered & face_mask != 0 {
                    // The cell from the grid lines ahead of it: no division of `index`.
                    let col = line_x - (step_x > 0) as i32;
                    let row = line_y - (step_y > 0) as i32;
                    return FastWalk::Face {
                        index: index as u32,
                        col: col as u32,
                        row: row as u32,
                        face: entered,
                        kind,
                    };
                }
                if kind & general_mask != 0
                    && test_cell(data, test, index, t_exit - tol_t, best_t, best)
                {
                    return FastWalk::Done;
                }
            }
            // Within the tolerance of a corner, both side cells must be visited, which only
            // the general walk does. Checked before the end of the walk: a ray leaving the map
            // through a corner touches the side cell still inside it.
            if (tx - ty).abs() <= tol_t {
                return FastWalk::Fallback;
            }
            if t_exit > t_stop {
                return FastWalk::Done;
            }
            if tx < ty {
                index = index.wrapping_add_signed(index_step_x);
                line_x += step_x;
                tx = (line_x as f32 - o.x) * inv.x;
                entered = enter_x;
            } else {
                index = index.wrapping_add_signed(index_step_y);
                line_y += step_y;
                ty = (line_y as f32 - o.y) * inv.y;
                entered = enter_y;
            }
        }
    }
}

/// Tests the segments of the cell at `index`, recording a nearer hit in `best_t` and `best`;
/// true when the nearest hit lies before `t_exit` (the caller passes the cell's exit less
/// the touch tolerance: a hit within rounding of the exit may be beaten by one a hair
/// nearer in the next cell), so the walk is over. Out of line so
/// that the walk's loop stays small.
#[inline(never)]
fn test_cell(
    data: &WalkData<'_>,
    test: &SegmentTest,
    index: usize,
    t_exit: f32,
    best_t: &mut f32,
    best: &mut Option<(usize, u32)>,
) -> bool {
    if let Some(i) = test.nearest(cell_segments(data.starts, data.hot, index), best_t) {
        *best = Some((index, i));
    }
    *best_t <= t_exit
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn floor_off_line_is_the_floor_away_from_integers_and_never_panics() {
        // Fractions at and just past the touch tolerance, and mid-cell, at small and large
        // coordinates (up to 2²² − 1, where the float's ulp is half a cell).
        for base in [0u32, 1, 2, 7, 255, 1000, 65_535, (1 << 22) - 2] {
            for frac in [2e-4f32, 0.25, 0.5, 0.75, 0.9998] {
                let x = base as f32 + frac;
                let off = x - x.floor();
                if off > TOUCH_TOLERANCE && off < 1.0 - TOUCH_TOLERANCE {
                    assert_eq!(floor_off_line(x), x.floor() as i32, "x = {x}");
                }
            }
        }
        // Within the tolerance of an integer the result may be either neighbour, but then
        // the start's fraction tells the caller so.
        for x in [3.0f32, 3.00005, 2.99995, 1e6] {
            let col = floor_off_line(x);
            let f = x - col as f32;
            assert!(
                f <= TOUCH_TOLERANCE || f >= 1.0 - TOUCH_TOLERANCE,
                "x = {x}"
            );
        }
        for x in [
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            -1e30,
            1e30,
            f32::MAX,
        ] {
            let _ = floor_off_line(x);
        }
    }
}
