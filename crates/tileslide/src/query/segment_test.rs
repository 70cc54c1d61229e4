//! The per-segment part of a ray cast: the filter, then the exact intersection.

use glam::Vec2;

use super::{Faces, RayFilter};
use crate::geometry::ray::{solve_parts, solve_wide};
use crate::tiles::SegmentFlags;
use crate::tiles::store::{HotSegment, NO_SEGMENTS};

/// A ray and filter, ready to test segments against.
pub(crate) struct SegmentTest {
    p0: Vec2,
    delta: Vec2,
    /// A face counts when `dot(normal, face_dir) < face_limit`: the filter's direction and 0,
    /// or (both faces) zero and 1, which every face passes. No branch on the filter's kind.
    face_dir: Vec2,
    face_limit: f32,
    mask: u32,
}

impl SegmentTest {
    pub fn new(p0: Vec2, delta: Vec2, filter: &RayFilter) -> Self {
        let (face_dir, face_limit) = match filter.face_direction(delta) {
            Some(dir) => (dir, 0.0),
            None => (Vec2::ZERO, 1.0),
        };
        Self {
            p0,
            delta,
            face_dir,
            face_limit,
            mask: filter.mask.0,
        }
    }

    /// True when cells of whole-edge solid faces can be decided by the face a ray enters
    /// through: front faces only, and solid segments count (see `fast_walk`).
    #[inline(always)]
    pub fn decides_by_faces(filter: &RayFilter) -> bool {
        matches!(filter.faces, Faces::Front) && filter.mask.contains(SegmentFlags::SOLID)
    }

    /// Whether the filter lets the ray hit `s`, and `t` if the ray crosses it (`t` is
    /// meaningless when the first is false).
    #[inline(always)]
    fn test(&self, s: &HotSegment) -> (bool, f32) {
        let (inside, tn, _, den) = solve_parts(self.p0, self.delta, s.a, s.e);
        (self.passes(s) & inside, tn / den)
    }

    /// Whether the filter lets the ray hit `s` (its face and mask).
    #[inline(always)]
    fn passes(&self, s: &HotSegment) -> bool {
        let face_ok = s.normal.dot(self.face_dir) < self.face_limit;
        let mask_ok = s.flags.0 & self.mask != 0;
        face_ok & mask_ok
    }

    /// `t` where the ray hits `s`, if the filter lets it.
    #[inline(always)]
    pub fn hit(&self, s: &HotSegment) -> Option<f32> {
        let (ok, t) = self.test(s);
        ok.then_some(t)
    }

    /// `t` and the point where the ray hits `s` by the `f64` kernel, if the filter lets it:
    /// for rays the `f32` walks do not take (`GridRay::is_ordinary`). The point is taken
    /// on the segment (`a + s·e`): on such a ray `origin + t·delta` can lose every bit to
    /// the origin's magnitude or to a subnormal `t`.
    pub fn hit_wide(&self, s: &HotSegment) -> Option<(f32, Vec2)> {
        if !self.passes(s) {
            return None;
        }
        solve_wide(self.p0, self.delta, s.a, s.e).map(|(t, u)| (t, s.a + s.e * u))
    }

    /// Tests `segs`; if one is hit before `best_t`, lowers `best_t` and returns the index of
    /// the nearest such segment (the first of equals).
    #[inline(always)]
    pub fn nearest(&self, segs: &[HotSegment], best_t: &mut f32) -> Option<u32> {
        let mut found = None;
        for (i, s) in segs.iter().enumerate() {
            let (ok, t) = self.test(s);
            if ok & (t < *best_t) {
                *best_t = t;
                found = Some(i as u32);
            }
        }
        found
    }
}

/// The active segments of the cell at `index`.
#[inline(always)]
pub(crate) fn cell_segments<'a>(
    starts: &[u32],
    hot: &'a [HotSegment],
    index: usize,
) -> &'a [HotSegment] {
    let start = starts[index];
    if start == NO_SEGMENTS {
        return &[];
    }
    let start = start as usize;
    &hot[start..start + hot[start].count as usize]
}
