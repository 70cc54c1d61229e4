use std::cell::LazyCell;

use glam::{DVec2, Vec2};

use super::fast_walk::{FastWalk, WalkData, fast_walk};
use super::segment_test::{SegmentTest, cell_segments};
use super::traversal::{GridRay, TOUCH_TOLERANCE, walk};
use super::{QueryFilter, RayHit, SegmentSource};
use crate::geometry::Ray;
use crate::geometry::in_range;
use crate::geometry::ray::{solve, solve_wide};
use crate::tiles::SegmentRef;
use crate::tiles::face_kind::{face_index, face_normal, face_segment};
use crate::tiles::{Cell, SegmentFlags, TileId, TileMap};

impl TileMap {
    /// The nearest segment the ray hits, or `None`.
    ///
    /// Build the ray with [`Ray::between`]`(p0, p1)` for a move from `p0` to `p1`, or as
    /// `Ray { origin, delta: dir * length }` for a direction and a length (which keeps the
    /// bits that rounding `origin + dir * length` to an end point would lose).
    ///
    /// The grid is walked cell by cell from the origin (Amanatides & Woo, visiting every
    /// cell the ray touches, corners included), testing each visited cell's active segments
    /// and the temporary segments, and stops once the nearest hit so far lies before the
    /// current cell's exit: the result is the **global** nearest hit, not the first cell's.
    /// Defined cases:
    /// - a ray that starts and ends in one cell tests that cell;
    /// - a ray ending exactly on a surface hits it at `t = 1`;
    /// - a ray running along a surface does not hit it (see [`cast_ray_segment`]), but does
    ///   hit a wall it runs into;
    /// - a ray starting exactly on a surface and moving into it hits at `t = 0`; one moving
    ///   away from it is not stopped by it (for that motion it is a back face), unless the
    ///   filter is [`Faces::Both`];
    /// - a zero-length ray, or one with a NaN or infinite coordinate, hits nothing;
    /// - on equal `t`, the first found wins: temporary segments, then cells in walk order;
    /// - every finite ray is answered, however far or long: a ray that starts far from the
    ///   map, or whose motion is longer than 2³² or shorter than 2⁻³² cells along an axis,
    ///   is solved in `f64` on the part of it that crosses the map, with no early stop, and
    ///   its hit point is taken on the segment; from an origin beyond
    ///   [`MAX_COORD`](crate::limits::MAX_COORD) every cell is tested (see `docs/ray-casting.md`).
    ///
    /// [`cast_ray_segment`]: crate::geometry::cast_ray_segment
    /// [`Faces::Both`]: crate::Faces::Both
    ///
    /// ```
    /// # use tileslide::{io::ascii, Ray, QueryFilter, Vec2};
    /// let map = ascii::parse("\
    /// #####
    /// #...#
    /// #####", "doc.txt", 1.0)?;
    /// let ray = Ray::between(Vec2::new(1.5, 1.5), Vec2::new(9.5, 1.5));
    /// let hit = map.cast_ray(ray, &QueryFilter::default()).unwrap();
    /// assert_eq!(hit.point, Vec2::new(4.0, 1.5));
    /// assert_eq!(hit.normal, Vec2::new(-1.0, 0.0));
    /// # Ok::<(), tileslide::io::LoadError>(())
    /// ```
    #[must_use]
    pub fn cast_ray(&self, ray: Ray, filter: &QueryFilter) -> Option<RayHit> {
        let (p0, delta) = (ray.origin, ray.delta);
        let grid = self.grid_ray(p0, delta);
        // (False for a NaN or infinite coordinate too: the wide path answers those.)
        if !grid.is_ordinary() {
            return self.cast_ray_wide(p0, delta, filter);
        }
        let mut best_t = f32::INFINITY;
        let mut best: Option<Found> = None;
        // Temporary segments first (none: no cost); their nearest hit shortens the walk.
        if !self.temporaries.is_empty() {
            for (index, t, _) in self.temporary_hits(p0, delta, filter, false) {
                if t < best_t {
                    best_t = t;
                    best = Some(Found::Temporary(index));
                }
            }
        }
        // Built only if some cell's segments are tested: a face hit needs none.
        let test = LazyCell::new(|| SegmentTest::new(p0, delta, filter));
        let by_faces = SegmentTest::decides_by_faces(filter);
        let limit = if best_t.is_finite() { best_t } else { 1.0 };
        let data = WalkData {
            kinds: self.store.kinds(),
            starts: self.store.starts(),
            hot: self.store.hot(),
        };
        let mut general = None;
        let mut fallback = false;
        match fast_walk(
            &grid,
            &data,
            &test,
            by_faces,
            limit,
            &mut best_t,
            &mut general,
        ) {
            FastWalk::Done => {}
            FastWalk::Face {
                index,
                col,
                row,
                face,
                kind,
            } => {
                // The face's exact intersection, from the cell's geometry alone (the store
                // keeps whole-edge faces in this very form: see `face_segment`), so no
                // segment data is read. Rounding at the face's very end can disagree with
                // the walk's step; then the general walk decides.
                let cell = Cell::new(col, row);
                match self.face_t(p0, delta, cell, face) {
                    Some(t) if t < best_t => {
                        best_t = t;
                        best = Some(Found::Face(
                            cell,
                            index as usize,
                            face_index(kind, face),
                            face,
                        ));
                        general = None;
                    }
                    Some(_) => {}
                    None => fallback = true,
                }
            }
            FastWalk::Fallback => fallback = true,
        }
        if let Some((index, i)) = general {
            best = Some(Found::Tile(self.cell_of(index), index, i));
        }
        if fallback && let Some(found) = self.general_walk(&grid, &test, limit, &mut best_t) {
            best = Some(found);
        }
        best.map(|found| self.make_hit(found, best_t, p0 + delta * best_t))
    }

    /// Every segment the ray hits, sorted by `t`, each once, starting with exactly
    /// [`cast_ray`](Self::cast_ray)'s hit, bit for bit; empty when `cast_ray` finds
    /// nothing. Same rules as `cast_ray`.
    ///
    /// The list is `cast_ray`'s hit followed by every other segment hit at or after its
    /// `t`. Ties keep the order in which `cast_ray` meets them (temporary segments first,
    /// then cells in walk order, each cell's segments by index). A hit that rounding places
    /// before `cast_ray`'s is left out: only a ray grazing a segment can have one (at a
    /// tiny angle the intersection's `t` is ill-conditioned, and `f32` can put it before
    /// the segment's own cell, which the walk of `cast_ray` rightly stops short of), and
    /// listing it first would contradict `cast_ray`.
    #[must_use]
    pub fn cast_ray_all(&self, ray: Ray, filter: &QueryFilter) -> Vec<RayHit> {
        let mut out = Vec::new();
        self.cast_ray_all_into(ray, filter, &mut out);
        out
    }

    /// [`cast_ray_all`](Self::cast_ray_all) into a buffer the caller reuses (cleared first).
    pub fn cast_ray_all_into(&self, ray: Ray, filter: &QueryFilter, out: &mut Vec<RayHit>) {
        out.clear();
        // The rule of `cast_ray_all`: its first hit is this one, whatever the other hits'
        // rounding says.
        let Some(first) = self.cast_ray(ray, filter) else {
            return;
        };
        self.every_hit(ray, filter, out);
        out.retain(|h| h.source != first.source && h.t >= first.t);
        out.insert(0, first);
    }

    /// Every segment the ray hits, sorted by `t` (ties in the order `cast_ray` meets them),
    /// each once, into the empty `out`: the walk of `cast_ray` without its early stop.
    fn every_hit(&self, ray: Ray, filter: &QueryFilter, out: &mut Vec<RayHit>) {
        let (p0, delta) = (ray.origin, ray.delta);
        let grid = self.grid_ray(p0, delta);
        let wide = !grid.is_ordinary();
        if !(p0.is_finite() && delta.is_finite()) {
            return;
        }
        for (index, t, point) in self.temporary_hits(p0, delta, filter, wide) {
            out.push(self.make_hit(Found::Temporary(index), t, point));
        }
        let test = SegmentTest::new(p0, delta, filter);
        let (starts, hot) = (self.store.starts(), self.store.hot());
        let mut visit = |index: usize| {
            for (i, s) in cell_segments(starts, hot, index).iter().enumerate() {
                let hit = if wide {
                    test.hit_wide(s)
                } else {
                    test.hit(s).map(|t| (t, p0 + delta * t))
                };
                if let Some((t, point)) = hit {
                    let found = Found::Tile(self.cell_of(index), index, i as u32);
                    out.push(self.make_hit(found, t, point));
                }
            }
        };
        if wide {
            self.wide_cells(p0, delta, visit);
        } else {
            walk(&grid, 1.0, |index, _| {
                visit(index);
                false
            });
        }
        // By `t` alone, keeping the order found (a stable sort; `t` is never NaN, and -0 and
        // +0 count as equal, as they do for `cast_ray`). A cell can be visited twice (a
        // start cell that is also a corner's side cell): its hits are then identical, in
        // one run of equal `t`, and are reported once.
        out.sort_by(|a, b| a.t.partial_cmp(&b.t).unwrap_or(std::cmp::Ordering::Equal));
        let mut kept = 0;
        for i in 0..out.len() {
            let hit = out[i];
            let seen = out[..kept]
                .iter()
                .rev()
                .take_while(|k| k.t == hit.t)
                .any(|k| k.source == hit.source);
            if !seen {
                out[kept] = hit;
                kept += 1;
            }
        }
        out.truncate(kept);
    }

    /// [`cast_ray`](Self::cast_ray) for a ray the `f32` walks do not take (see
    /// `GridRay::is_ordinary`): one that starts far from the map, or whose motion is
    /// longer than 2³² or shorter than 2⁻³² cells along an axis, or that is not finite.
    /// Every segment it may meet is solved in `f64` (`solve_wide`), with no early stop:
    /// the nearest hit, the first found of equals, in the order `cast_ray_all` lists them.
    #[inline(never)]
    fn cast_ray_wide(&self, p0: Vec2, delta: Vec2, filter: &QueryFilter) -> Option<RayHit> {
        if !(p0.is_finite() && delta.is_finite()) {
            return None;
        }
        let mut best: Option<(Found, f32, Vec2)> = None;
        let mut consider = |found: Found, t: f32, point: Vec2| {
            if best.is_none_or(|(_, b, _)| t < b) {
                best = Some((found, t, point));
            }
        };
        for (index, t, point) in self.temporary_hits(p0, delta, filter, true) {
            consider(Found::Temporary(index), t, point);
        }
        let test = SegmentTest::new(p0, delta, filter);
        let (starts, hot) = (self.store.starts(), self.store.hot());
        self.wide_cells(p0, delta, |index| {
            for (i, s) in cell_segments(starts, hot, index).iter().enumerate() {
                if let Some((t, point)) = test.hit_wide(s) {
                    consider(Found::Tile(self.cell_of(index), index, i as u32), t, point);
                }
            }
        });
        best.map(|(found, t, point)| self.make_hit(found, t, point))
    }

    /// Calls `visit` with the index of every cell a finite ray that is not ordinary may
    /// hit a segment in, in walk order (a cell may come more than once).
    ///
    /// From an origin within [`MAX_COORD`](crate::limits::MAX_COORD), the ray is first clipped in
    /// `f64` to the map's rectangle widened by the touch tolerance, where the products of
    /// `f32` values are exact and nothing overflows; the clipped piece, in grid units,
    /// lies within the map (so `f32` holds it as well as any ray inside the map) and is
    /// walked to its end. From farther out, the `f64` line itself is too coarse near the
    /// map (an `f64` keeps 53 bits of the origin's magnitude) to say which cells it
    /// crosses, so every cell is visited: such an origin is outside the range tileslide
    /// handles, and the answer is then the `f64` kernel's on every segment.
    fn wide_cells(&self, p0: Vec2, delta: Vec2, visit: impl FnMut(usize)) {
        if !in_range(p0) {
            (0..self.width() as usize * self.height() as usize).for_each(visit);
            return;
        }
        let Some((origin, delta)) = self.clipped_grid_ray(p0, delta) else {
            return;
        };
        walk_wide(origin, delta, self.width(), self.height(), visit);
    }

    /// The part of the ray from `p0` (within `MAX_COORD`) by `delta` inside the map's
    /// rectangle widened by twice the touch tolerance, in grid units, computed in `f64`:
    /// its start and its motion; `None` when the ray misses that rectangle.
    fn clipped_grid_ray(&self, p0: Vec2, delta: Vec2) -> Option<(DVec2, DVec2)> {
        // (Subtracted in f64: in f32 the origin's rounding would move the line by up to a
        // unit at 2²⁴.)
        let (o, d) = (p0.as_dvec2() - self.origin().as_dvec2(), delta.as_dvec2());
        let cell = self.cell_size().as_dvec2();
        let size = DVec2::new(f64::from(self.width()), f64::from(self.height())) * cell;
        let margin = cell * f64::from(2.0 * TOUCH_TOLERANCE);
        let (lo, hi) = (-margin, size + margin);
        let (mut t_lo, mut t_hi) = (0.0f64, 1.0f64);
        for axis in 0..2 {
            if d[axis] == 0.0 {
                if !(o[axis] >= lo[axis] && o[axis] <= hi[axis]) {
                    return None;
                }
            } else {
                let (t0, t1) = (
                    (lo[axis] - o[axis]) / d[axis],
                    (hi[axis] - o[axis]) / d[axis],
                );
                t_lo = t_lo.max(t0.min(t1));
                t_hi = t_hi.min(t0.max(t1));
            }
        }
        if t_lo > t_hi {
            return None;
        }
        let start = o + d * t_lo;
        let end = o + d * t_hi;
        Some((start / cell, (end - start) / cell))
    }

    /// The closest-hit walk for the rays the fast walk declines (kept out of line so the
    /// fast path stays small).
    #[inline(never)]
    fn general_walk(
        &self,
        ray: &GridRay,
        test: &SegmentTest,
        limit: f32,
        best_t: &mut f32,
    ) -> Option<Found> {
        let (starts, hot) = (self.store.starts(), self.store.hot());
        let tol_t = ray.tolerance_t();
        let mut best = None;
        walk(ray, limit, |index, t_exit| {
            if let Some(i) = test.nearest(cell_segments(starts, hot, index), best_t) {
                best = Some(Found::Tile(self.cell_of(index), index, i));
            }
            // Stop once the nearest hit is clearly before the cell's exit: a hit within
            // rounding of the exit may be beaten by one a hair nearer in the next cell.
            *best_t + tol_t <= t_exit
        });
        best
    }

    /// Where the ray from `p0` by `delta` meets whole-edge face `face` of `cell`, computed
    /// from the cell's geometry alone, exactly as the store keeps the face (see
    /// `face_segment`); `None` when rounding at the face's very end makes it a miss.
    #[inline(always)]
    pub(super) fn face_t(&self, p0: Vec2, delta: Vec2, cell: Cell, face: u8) -> Option<f32> {
        let (a, e) = face_segment(self.cell_corner(cell), self.cell_size(), face);
        solve(p0, delta, a, e).map(|(t, _)| t)
    }

    #[inline(always)]
    pub(crate) fn cell_of(&self, index: usize) -> Cell {
        // 32-bit division: a 64-bit one costs several times more on x86-64.
        let (index, width) = (index as u32, self.width());
        Cell::new(index % width, index / width)
    }

    pub(crate) fn grid_ray(&self, p0: Vec2, delta: Vec2) -> GridRay {
        let inv = self.inv_cell_size();
        GridRay {
            origin: (p0 - self.origin()) * inv,
            delta: delta * inv,
            width: self.width(),
            height: self.height(),
        }
    }

    /// The hit on `found` at `t` and `point`.
    fn make_hit(&self, found: Found, t: f32, point: Vec2) -> RayHit {
        match found {
            Found::Temporary(index) => {
                let tmp = &self.temporaries[index];
                RayHit {
                    t,
                    point,
                    normal: tmp.normal,
                    flags: tmp.flags,
                    source: SegmentSource::Temporary {
                        owner: tmp.owner,
                        index,
                        velocity: tmp.velocity,
                    },
                }
            }
            Found::Face(cell, index, i, face) => self.face_hit(cell, index, i, face, t, point),
            Found::Tile(cell, index, i) => {
                let s = cell_segments(self.store.starts(), self.store.hot(), index)[i as usize];
                RayHit {
                    t,
                    point,
                    normal: s.normal,
                    flags: s.flags,
                    source: SegmentSource::Tile {
                        segment: SegmentRef { cell, index: i },
                        tile: self.tile_at_index(index).unwrap_or(TileId(u32::MAX)),
                    },
                }
            }
        }
    }

    /// The hit on whole-edge face `face` (segment `i` of the cell at `index`) at `t` and
    /// `point`. Always inlined: built in place, the hit goes straight to where the caller
    /// keeps it (a hit returned through memory and copied cost the batch cast 12 %, in
    /// stalled loads of the just-written fields).
    #[inline(always)]
    pub(super) fn face_hit(
        &self,
        cell: Cell,
        index: usize,
        i: u32,
        face: u8,
        t: f32,
        point: Vec2,
    ) -> RayHit {
        RayHit {
            t,
            point,
            normal: face_normal(face),
            flags: SegmentFlags::SOLID,
            source: SegmentSource::Tile {
                segment: SegmentRef { cell, index: i },
                tile: self.tile_at_index(index).unwrap_or(TileId(u32::MAX)),
            },
        }
    }

    /// The temporary segments `filter` lets a ray from `p0` by `delta` hit: (index, t,
    /// point), by the `f64` kernel when `wide` (see [`cast_ray_wide`](Self::cast_ray_wide)),
    /// with the point then taken on the segment as `SegmentTest::hit_wide` takes it.
    fn temporary_hits(
        &self,
        p0: Vec2,
        delta: Vec2,
        filter: &QueryFilter,
        wide: bool,
    ) -> impl Iterator<Item = (usize, f32, Vec2)> {
        self.temporaries
            .iter()
            .enumerate()
            .filter_map(move |(index, tmp)| {
                if !filter.accepts(delta, tmp.normal, tmp.flags, Some(tmp.owner)) {
                    return None;
                }
                let e = tmp.segment.b - tmp.segment.a;
                let a = tmp.segment.a;
                if wide {
                    solve_wide(p0, delta, a, e).map(|(t, s)| (index, t, a + e * s))
                } else {
                    solve(p0, delta, a, e).map(|(t, _)| (index, t, p0 + delta * t))
                }
            })
    }
}

#[derive(Clone, Copy)]
enum Found {
    Temporary(usize),
    /// A whole-edge face: its cell, the cell's index, the face's index in the cell, and its
    /// `FACE_*` bit.
    Face(Cell, usize, u32, u8),
    /// Cell, its index, and the segment's index in it.
    Tile(Cell, usize, u32),
}

/// Calls `visit` with every cell of a `width` × `height` grid that the piece from `o` by
/// `d` (grid units, in `f64`; within the grid widened by a little) passes through, in walk
/// order, each with its eight neighbours (a cell may come more than once). Walked in `f64`:
/// rounded to `f32` grid units, a piece a hair beside a grid line can lie on the wrong side
/// of it for its whole length (a ray from (−6e-8, 1) by (0.25, 6.5e7) on a map whose right
/// edge is x = 0 rounds onto that edge and would leave the map at once, losing every floor
/// after the first); the neighbours cover what rounding is left.
fn walk_wide(o: DVec2, d: DVec2, width: u32, height: u32, mut visit: impl FnMut(usize)) {
    let (w, h) = (i64::from(width), i64::from(height));
    let cell = |v: f64, n: i64| (v.floor() as i64).clamp(0, n - 1);
    let (mut col, mut row) = (cell(o.x, w), cell(o.y, h));
    let step = |d: f64| i64::from(d > 0.0) - i64::from(d < 0.0);
    let (step_x, step_y) = (step(d.x), step(d.y));
    // The fraction of the piece where it crosses the grid line past cell `c` along an
    // axis (never, for no motion along it).
    let next = |c: i64, step: i64, o: f64, d: f64| {
        if step == 0 {
            f64::INFINITY
        } else {
            ((c + i64::from(step > 0)) as f64 - o) / d
        }
    };
    loop {
        for r in (row - 1).max(0)..=(row + 1).min(h - 1) {
            for c in (col - 1).max(0)..=(col + 1).min(w - 1) {
                visit((r * w + c) as usize);
            }
        }
        let (tx, ty) = (next(col, step_x, o.x, d.x), next(row, step_y, o.y, d.y));
        if tx.min(ty) > 1.0 {
            return;
        }
        if tx <= ty {
            col += step_x;
        } else {
            row += step_y;
        }
        if !(0..w).contains(&col) || !(0..h).contains(&row) {
            return;
        }
    }
}
