use std::cell::LazyCell;

use glam::Vec2;

use super::fast_walk::{FastWalk, WalkData, fast_walk};
use super::segment_test::{SegmentTest, cell_segments};
use super::traversal::{GridRay, walk};
use super::{RayFilter, RayHit, SegmentSource};
use crate::geometry::Ray;
use crate::geometry::ray::solve;
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
    /// - on equal `t`, the first found wins: temporary segments, then cells in walk order.
    ///
    /// [`cast_ray_segment`]: crate::cast_ray_segment
    /// [`Faces::Both`]: crate::Faces::Both
    ///
    /// ```
    /// # use tileslide::{io::ascii, Ray, RayFilter, Vec2};
    /// let map = ascii::parse("\
    /// #####
    /// #...#
    /// #####", "doc.txt", 1.0)?;
    /// let ray = Ray::between(Vec2::new(1.5, 1.5), Vec2::new(9.5, 1.5));
    /// let hit = map.cast_ray(ray, &RayFilter::default()).unwrap();
    /// assert_eq!(hit.point, Vec2::new(4.0, 1.5));
    /// assert_eq!(hit.normal, Vec2::new(-1.0, 0.0));
    /// # Ok::<(), tileslide::io::LoadError>(())
    /// ```
    #[must_use]
    pub fn cast_ray(&self, ray: Ray, filter: &RayFilter) -> Option<RayHit> {
        let (p0, delta) = (ray.origin, ray.delta);
        if !(p0.is_finite() && delta.is_finite()) {
            return None;
        }
        let mut best_t = f32::INFINITY;
        let mut best: Option<Found> = None;
        // Temporary segments first (none: no cost); their nearest hit shortens the walk.
        if !self.temporaries.is_empty() {
            for (index, t) in self.temporary_hits(p0, delta, filter) {
                if t < best_t {
                    best_t = t;
                    best = Some(Found::Temporary(index));
                }
            }
        }
        let grid = self.grid_ray(p0, delta);
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
        best.map(|found| self.make_hit(found, best_t, p0, delta))
    }

    /// Every segment the ray hits, sorted by `t` (ties: temporary segments first, then by
    /// cell row, column and index), each once.
    /// Same rules as [`cast_ray`](Self::cast_ray).
    #[must_use]
    pub fn cast_ray_all(&self, ray: Ray, filter: &RayFilter) -> Vec<RayHit> {
        let mut out = Vec::new();
        self.cast_ray_all_into(ray, filter, &mut out);
        out
    }

    /// [`cast_ray_all`](Self::cast_ray_all) into a buffer the caller reuses (cleared first).
    pub fn cast_ray_all_into(&self, ray: Ray, filter: &RayFilter, out: &mut Vec<RayHit>) {
        out.clear();
        let (p0, delta) = (ray.origin, ray.delta);
        if !(p0.is_finite() && delta.is_finite()) {
            return;
        }
        for (index, t) in self.temporary_hits(p0, delta, filter) {
            out.push(self.make_hit(Found::Temporary(index), t, p0, delta));
        }
        let test = SegmentTest::new(p0, delta, filter);
        let starts = self.store.starts();
        let hot = self.store.hot();
        walk(&self.grid_ray(p0, delta), 1.0, |index, _| {
            for (i, s) in cell_segments(starts, hot, index).iter().enumerate() {
                if let Some(t) = test.hit(s) {
                    let found = Found::Tile(self.cell_of(index), index, i as u32);
                    out.push(self.make_hit(found, t, p0, delta));
                }
            }
            false
        });
        // By `t`, then temporary segments first, then by cell and index. A cell can be
        // visited twice (a start cell that is also a corner's side cell): its hits are then
        // identical and adjacent after the sort, and are reported once.
        let key = |h: &RayHit| match h.source {
            SegmentSource::Temporary { index, .. } => (0, index, 0, 0),
            SegmentSource::Tile { segment, .. } => (
                1,
                segment.cell.row as usize,
                segment.cell.col,
                segment.index,
            ),
        };
        out.sort_by(|a, b| a.t.total_cmp(&b.t).then_with(|| key(a).cmp(&key(b))));
        out.dedup_by(|a, b| a.t == b.t && key(a) == key(b));
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

    fn make_hit(&self, found: Found, t: f32, p0: Vec2, delta: Vec2) -> RayHit {
        let point = p0 + delta * t;
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
            Found::Face(cell, index, i, face) => self.face_hit(cell, index, i, face, t, p0, delta),
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

    /// The hit on whole-edge face `face` (segment `i` of the cell at `index`) at `t`.
    /// Always inlined: built in place, the hit goes straight to where the caller keeps it
    /// (a hit returned through memory and copied cost the batch cast 12 %, in stalled
    /// loads of the just-written fields).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    pub(super) fn face_hit(
        &self,
        cell: Cell,
        index: usize,
        i: u32,
        face: u8,
        t: f32,
        p0: Vec2,
        delta: Vec2,
    ) -> RayHit {
        RayHit {
            t,
            point: p0 + delta * t,
            normal: face_normal(face),
            flags: SegmentFlags::SOLID,
            source: SegmentSource::Tile {
                segment: SegmentRef { cell, index: i },
                tile: self.tile_at_index(index).unwrap_or(TileId(u32::MAX)),
            },
        }
    }

    /// The temporary segments `filter` lets a ray from `p0` by `delta` hit: (index, t).
    fn temporary_hits(
        &self,
        p0: Vec2,
        delta: Vec2,
        filter: &RayFilter,
    ) -> impl Iterator<Item = (usize, f32)> {
        let face_dir = filter.face_direction(delta);
        self.temporaries
            .iter()
            .enumerate()
            .filter_map(move |(index, tmp)| {
                if filter.exclude_owner == Some(tmp.owner)
                    || !tmp.flags.intersects(filter.mask)
                    || face_dir.is_some_and(|f| tmp.normal.dot(f) >= 0.0)
                {
                    return None;
                }
                let e = tmp.segment.b - tmp.segment.a;
                solve(p0, delta, tmp.segment.a, e).map(|(t, _)| (index, t))
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
