//! The per-segment part of a ray cast: the filter, then the exact intersection.

use glam::Vec2;

use super::{Faces, QueryFilter};
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
    pub fn new(p0: Vec2, delta: Vec2, filter: &QueryFilter) -> Self {
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
    pub fn decides_by_faces(filter: &QueryFilter) -> bool {
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

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;
    use crate::tiles::Owner;

    /// Finite components: small, zero of either sign, or any finite `f32`.
    fn component() -> impl Strategy<Value = f32> {
        prop_oneof![
            4 => -4.0f32..4.0,
            1 => Just(0.0f32),
            1 => Just(-0.0f32),
            1 => any::<f32>().prop_filter("finite", |x| x.is_finite()),
        ]
    }

    fn vector() -> impl Strategy<Value = Vec2> {
        (component(), component()).prop_map(|(x, y)| Vec2::new(x, y))
    }

    /// A unit normal, as stored segments have: axis-aligned or any direction.
    fn normal() -> impl Strategy<Value = Vec2> {
        prop_oneof![
            Just(Vec2::X),
            Just(Vec2::NEG_X),
            Just(Vec2::Y),
            Just(Vec2::NEG_Y),
            (0.0f32..std::f32::consts::TAU).prop_map(Vec2::from_angle),
        ]
    }

    fn faces() -> impl Strategy<Value = Faces> {
        prop_oneof![
            Just(Faces::Front),
            Just(Faces::Both),
            vector().prop_map(Faces::Against),
        ]
    }

    fn flags() -> impl Strategy<Value = SegmentFlags> {
        prop_oneof![
            Just(SegmentFlags::SOLID),
            Just(SegmentFlags::ONE_WAY),
            Just(SegmentFlags::ALL),
            Just(SegmentFlags::NONE),
            any::<u32>().prop_map(SegmentFlags),
        ]
    }

    fn segment(normal: Vec2, flags: SegmentFlags) -> HotSegment {
        HotSegment {
            a: Vec2::ZERO,
            e: normal.perp(),
            normal,
            flags,
            source: 0,
            count: 1,
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(2_000))]

        /// The walks' branch-free filter (`dot(normal, face_dir) < face_limit` and a mask
        /// test) lets through exactly the segments `QueryFilter::accepts` accepts.
        #[test]
        fn the_branch_free_filter_is_query_filter_accepts(
            faces in faces(),
            mask in flags(),
            delta in vector(),
            normal in normal(),
            segment_flags in flags(),
        ) {
            let filter = QueryFilter { faces, mask, exclude_owner: None };
            let test = SegmentTest::new(Vec2::ZERO, delta, &filter);
            prop_assert_eq!(
                test.passes(&segment(normal, segment_flags)),
                filter.accepts(delta, normal, segment_flags, None)
            );
        }

        /// Where a cell of whole-edge solid faces is decided by the face the walk enters
        /// through (`fast_walk` and the batch walk), the filter accepts a face exactly when
        /// the ray enters through it: `dot(normal, delta) < 0` for the face's outward normal.
        #[test]
        fn faces_decide_a_cell_only_where_the_filter_accepts_exactly_the_faces_entered(
            faces in faces(),
            mask in flags(),
            delta in vector(),
            face in 0usize..4,
        ) {
            let filter = QueryFilter { faces, mask, exclude_owner: None };
            let normal = [Vec2::X, Vec2::NEG_X, Vec2::Y, Vec2::NEG_Y][face];
            if SegmentTest::decides_by_faces(&filter) {
                prop_assert_eq!(
                    filter.accepts(delta, normal, SegmentFlags::SOLID, None),
                    normal.dot(delta) < 0.0
                );
            }
        }
    }

    #[test]
    fn a_temporary_segment_of_the_excluded_owner_is_refused_and_a_tiles_is_not() {
        let filter = QueryFilter::both_sides().excluding(Owner(3));
        let (delta, normal) = (Vec2::X, Vec2::NEG_X);
        assert!(!filter.accepts(delta, normal, SegmentFlags::SOLID, Some(Owner(3))));
        assert!(filter.accepts(delta, normal, SegmentFlags::SOLID, Some(Owner(4))));
        assert!(filter.accepts(delta, normal, SegmentFlags::SOLID, None));
        assert!(QueryFilter::default().accepts(delta, normal, SegmentFlags::SOLID, Some(Owner(3))));
    }
}
