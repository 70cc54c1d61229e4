use glam::Vec2;

use super::traversal::{GridRay, walk};
use super::{RayFilter, RayHit, SegmentSource};
use crate::geometry::Ray;
use crate::geometry::ray::solve;
use crate::tiles::store::{HotSegment, SegmentRef};
use crate::tiles::{Cell, TileId, TileMap};

impl TileMap {
    /// The nearest segment the ray hits, or `None`.
    ///
    /// Build the ray with [`Ray::between`]`(p0, p1)` for a move from `p0` to `p1`, or as
    /// `Ray { origin, delta: dir * length }` for a direction and a length (which keeps the
    /// bits that rounding `origin + dir * length` to an end point would lose).
    ///
    /// The grid is walked cell by cell from `p0` (see `query::traversal`), testing each
    /// visited cell's active segments and the temporary segments, and stops once the nearest
    /// hit so far lies before the current cell's exit: the result is the **global** nearest
    /// hit, not the first cell's. Defined cases:
    /// - a ray that starts and ends in one cell tests that cell;
    /// - a ray ending exactly on a surface hits it at `t = 1`;
    /// - a ray running along a surface does not hit it (see [`cast_ray_segment`]), but does
    ///   hit a wall it runs into;
    /// - a ray starting exactly on a front face is not stopped by it (its motion leaves the
    ///   face); with [`Faces::Both`] it is, at `t = 0`;
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
        let face_dir = filter.face_direction(delta);
        let mask = filter.mask;
        let mut best_t = f32::INFINITY;
        let mut best: Option<Found> = None;
        if !self.temporaries.is_empty() {
            for (index, tmp) in self.temporaries.iter().enumerate() {
                if filter.exclude_owner == Some(tmp.owner)
                    || !tmp.flags.intersects(mask)
                    || face_dir.is_some_and(|f| tmp.normal.dot(f) >= 0.0)
                {
                    continue;
                }
                let e = tmp.segment.b - tmp.segment.a;
                if let Some((t, _)) = solve(p0, delta, tmp.segment.a, e)
                    && t < best_t
                {
                    best_t = t;
                    best = Some(Found::Temporary(index));
                }
            }
        }
        let slots = self.store.slots();
        let hot = self.store.hot();
        let ray = self.grid_ray(p0, delta);
        let limit = if best_t.is_finite() { best_t } else { 1.0 };
        walk(&ray, limit, |cell, t_exit| {
            let slot = slots[cell];
            if slot.len != 0 {
                let segs = &hot[slot.start as usize..(slot.start + slot.len) as usize];
                for (i, s) in segs.iter().enumerate() {
                    if !s.flags.intersects(mask) || face_dir.is_some_and(|f| s.normal.dot(f) >= 0.0)
                    {
                        continue;
                    }
                    if let Some((t, _)) = solve(p0, delta, s.a, s.e)
                        && t < best_t
                    {
                        best_t = t;
                        best = Some(Found::Tile(cell, i as u32));
                    }
                }
            }
            best_t <= t_exit
        });
        best.map(|found| self.make_hit(found, best_t, p0, delta))
    }

    /// Every segment the ray hits, sorted by `t` (ties in walk order).
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
        let face_dir = filter.face_direction(delta);
        let mask = filter.mask;
        for (index, tmp) in self.temporaries.iter().enumerate() {
            if filter.exclude_owner == Some(tmp.owner)
                || !tmp.flags.intersects(mask)
                || face_dir.is_some_and(|f| tmp.normal.dot(f) >= 0.0)
            {
                continue;
            }
            let e = tmp.segment.b - tmp.segment.a;
            if let Some((t, _)) = solve(p0, delta, tmp.segment.a, e) {
                out.push(self.make_hit(Found::Temporary(index), t, p0, delta));
            }
        }
        let mut found: Vec<(f32, usize, u32)> = Vec::new();
        let slots = self.store.slots();
        let hot = self.store.hot();
        walk(&self.grid_ray(p0, delta), 1.0, |cell, _| {
            let slot = slots[cell];
            let segs: &[HotSegment] = &hot[slot.start as usize..(slot.start + slot.len) as usize];
            for (i, s) in segs.iter().enumerate() {
                if !s.flags.intersects(mask) || face_dir.is_some_and(|f| s.normal.dot(f) >= 0.0) {
                    continue;
                }
                if let Some((t, _)) = solve(p0, delta, s.a, s.e)
                    && !found.iter().any(|&(_, c, j)| c == cell && j == i as u32)
                {
                    found.push((t, cell, i as u32));
                }
            }
            false
        });
        out.extend(
            found
                .into_iter()
                .map(|(t, cell, i)| self.make_hit(Found::Tile(cell, i), t, p0, delta)),
        );
        out.sort_by(|a, b| a.t.total_cmp(&b.t));
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
            Found::Tile(cell_index, i) => {
                let w = self.width() as usize;
                let cell = Cell::new((cell_index % w) as u32, (cell_index / w) as u32);
                let s = self.store.cell(cell_index)[i as usize];
                RayHit {
                    t,
                    point,
                    normal: s.normal,
                    flags: s.flags,
                    source: SegmentSource::Tile {
                        segment: SegmentRef { cell, index: i },
                        tile: self.tile(cell).unwrap_or(TileId(u32::MAX)),
                        source: s.source,
                    },
                }
            }
        }
    }
}

#[derive(Clone, Copy)]
enum Found {
    Temporary(usize),
    Tile(usize, u32),
}
