//! Moving circles: the exact time of impact of a circle swept along a straight move against
//! another circle (a point, for the end of a segment) and against a segment's capsule.
//!
//! Both solve the contact condition in closed form, so a move of any length is checked
//! whole: nothing tunnels, whatever the speed. Only *approaching* contacts count: a circle
//! that already overlaps something and moves away from it is not held back, so bodies that
//! start overlapping (spawned so, or after rounding) can always separate.

use std::cmp::Ordering;

use glam::{DVec2, Vec2};

use super::{EndCaps, Segment};

/// Relative depth below which a path that touches a circle only grazes it (see
/// [`sweep_circle_circle`]): about four float roundings of the squared radius.
const GRAZE: f32 = 4.0 * f32::EPSILON;

/// The largest size (2³⁰) a sweep solves in `f32` as written, where its size is the sum of
/// the magnitudes of the components of the offsets, lengths, radii and motion it works with:
/// up to it (and, for the circles' quadratic, twice it) every square and product of two of
/// them, and the quadratic's fourth-degree terms, stay below `f32::MAX`.
const ORDINARY_MAX: f32 = 1_073_741_824.0;

/// The smallest nonzero size (2⁻²⁰) a sweep solves in `f32` as written: above it the
/// quadratic's fourth-degree terms stay normal floats rather than underflowing to zero.
const ORDINARY_MIN: f32 = 1.0 / 1_048_576.0;

/// The size a sweep works with: the sum of the magnitudes of the components of `vectors`
/// and `scalars` (between their largest and 8 times it; NaN for a NaN). A sum, not a
/// maximum: additions cost less than `f32::max`'s NaN handling on the sweeps' hot path.
#[inline(always)]
pub(super) fn largest<const N: usize, const K: usize>(
    vectors: [Vec2; N],
    scalars: [f32; K],
) -> f32 {
    let v = vectors.iter().fold(Vec2::ZERO, |m, v| m + v.abs());
    scalars.iter().fold(v.x + v.y, |m, s| m + s.abs())
}

/// Whether a sweep whose size is `size` (see [`largest`]) runs in `f32` as written: true
/// for every ordinary game input, false past `ORDINARY_MAX` (including an offset that
/// overflowed to infinity), below `ORDINARY_MIN` but not 0, and for a NaN (which then
/// hits nothing).
#[inline(always)]
pub(super) fn ordinary(size: f32) -> bool {
    size <= ORDINARY_MAX && (size >= ORDINARY_MIN || size == 0.0)
}

/// The sizes of a sweep that is not [`ordinary`], computed in `f64` (where the offset of two
/// finite `f32` points cannot overflow), scaled together by the power of two that brings
/// the largest to about 2²⁸, and rounded to `f32`. The scaling is exact and a
/// sweep's `t` and normal do not depend on its scale, so the `f32` sweep of the result
/// answers the original; a size below about 2⁻¹²⁰ of the largest underflows, as any `f32`
/// sum with the largest would lose it. `None` when an input is not finite. Out of line: no
/// game input comes here.
#[cold]
#[inline(never)]
pub(super) fn rescaled<const N: usize, const K: usize>(
    vectors: [DVec2; N],
    scalars: [f64; K],
) -> Option<([Vec2; N], [f32; K])> {
    let finite = vectors.iter().all(|v| v.is_finite()) && scalars.iter().all(|s| s.is_finite());
    if !finite {
        return None;
    }
    let size = vectors
        .iter()
        .fold(0.0f64, |m, v| m.max(v.x.abs()).max(v.y.abs()));
    let size = scalars.iter().fold(size, |m, s| m.max(s.abs()));
    // `size` is at most 2¹²⁹ (the offset of two f32 points) and, if not 0, at least 2⁻¹⁴⁹,
    // so the power lies within f64's exponents and multiplying by it is exact.
    let k = if size > 0.0 {
        28 - size.log2().floor() as i32
    } else {
        0
    };
    let scale = 2f64.powi(k);
    Some((
        vectors.map(|v| (v * scale).as_vec2()),
        scalars.map(|s| (s * scale) as f32),
    ))
}

/// Where a swept circle first touches an obstacle.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SweepHit {
    /// Fraction of the move, in `[0, 1]`, at which the circles touch.
    pub t: f32,
    /// Unit contact normal, from the obstacle towards the moving circle's centre.
    pub normal: Vec2,
}

/// Time of impact of a circle at `center` moving by `motion` against a static circle at
/// `other`, where `radius_sum` is the sum of both radii (a point obstacle: just the moving
/// circle's radius). For two moving circles pass the *relative* motion.
///
/// Solves `|d + t·m| = R` for the smaller root (`d = center − other`), in the form that does
/// not cancel (`t = c / (−b + √disc)`). `None` when the circle does not approach the
/// obstacle, misses it, or meets it after `t = 1`; `t = 0` when it already overlaps and
/// moves closer. A path that only grazes the obstacle (its closest approach equals the
/// radius sum to within rounding) is not a contact.
///
/// Every finite input is answered, whatever its magnitude: `t` is never NaN and lies in
/// `[0, 1]`, and the normal is a unit vector. While the magnitudes of the components of the
/// offset `center − other`, the motion and the radius sum add up to between 2⁻²⁰ and 2³⁰
/// (or to 0), the quadratic is solved in `f32` as written; otherwise (a motion of 10²⁰, points 10³⁸ apart, a
/// problem 10⁻³⁰ across), where its squares and products would overflow or underflow, the
/// offset is taken in `f64` and the whole problem scaled by a power of two to that range
/// first, which changes neither `t` nor the normal. A size below about 2⁻¹²⁰ of the
/// largest then counts as zero, as `f32` rounding would count it next to the largest. A
/// NaN or infinite input hits nothing.
///
/// ```
/// # use tileslide::geometry::sweep_circle_circle;
/// # use tileslide::Vec2;
/// // A circle of radius 1 moving 10 to the right meets one of radius 1 whose centre is 5 away.
/// let hit = sweep_circle_circle(Vec2::ZERO, Vec2::new(10.0, 0.0), Vec2::new(5.0, 0.0), 2.0).unwrap();
/// assert_eq!(hit.t, 0.3);
/// assert_eq!(hit.normal, Vec2::new(-1.0, 0.0));
/// // Moving away: no hit, even when overlapping.
/// assert!(sweep_circle_circle(Vec2::ZERO, Vec2::new(-1.0, 0.0), Vec2::new(1.0, 0.0), 2.0).is_none());
/// ```
#[must_use]
pub fn sweep_circle_circle(
    center: Vec2,
    motion: Vec2,
    other: Vec2,
    radius_sum: f32,
) -> Option<SweepHit> {
    let d = center - other;
    if !ordinary(largest([d, motion], [radius_sum])) {
        // (Out of the ordinary sizes: moved and scaled, see `rescaled`.)
        let offset = center.as_dvec2() - other.as_dvec2();
        let ([d, motion], [radius_sum]) =
            rescaled([offset, motion.as_dvec2()], [f64::from(radius_sum)])?;
        return circle_circle(d, motion, radius_sum);
    }
    circle_circle(d, motion, radius_sum)
}

/// [`sweep_circle_circle`] in `f32` as written, for the offset `d = center − other`, without
/// the size check: for callers whose inputs are known to be ordinary (the resolver's).
#[inline]
pub(crate) fn circle_circle(d: Vec2, motion: Vec2, radius_sum: f32) -> Option<SweepHit> {
    let a = motion.length_squared();
    let b = d.dot(motion);
    // Not approaching (this also rejects a zero or NaN motion).
    if !(b < 0.0 && a > 0.0) {
        return None;
    }
    let c = d.length_squared() - radius_sum * radius_sum;
    let t = if c <= 0.0 {
        0.0
    } else {
        // `b² − a·c`. Its two products are of the offset's length squared, so they cancel
        // when the circle starts many radii away (68 radii off, it lost 0.02 of a 17 and
        // moved the contact 3·10⁻⁴ into the obstacle: a relative error of about 2ε times
        // the offset squared over R²): from more than 8 radii away it is taken as
        // `a·R² − (d × m)²` (Lagrange's identity), whose error grows with the offset only.
        // Nearer (every sweep of a crowd's ordinary step), the first form stays: its error
        // is below 10⁻⁵ of the contact there, and it decides grazes as it always has.
        let r2 = radius_sum * radius_sum;
        let disc = if c <= 63.0 * r2 {
            b * b - a * c
        } else {
            let cross = d.perp_dot(motion);
            a * r2 - cross * cross
        };
        // `disc = a·(R² − closest²)`: a path whose closest approach is the radius sum to
        // within rounding only grazes (a circle sliding past a corner at exactly its
        // radius); counting that as a contact would stop the slide for nothing.
        // (Written so that a NaN also returns.)
        if disc.partial_cmp(&(a * radius_sum * radius_sum * GRAZE)) != Some(Ordering::Greater) {
            return None;
        }
        let t = c / (disc.sqrt() - b);
        if t.partial_cmp(&1.0).is_none_or(Ordering::is_gt) {
            return None;
        }
        t
    };
    let at = d + motion * t;
    let normal = at.try_normalize().unwrap_or(-motion / a.sqrt());
    Some(SweepHit { t, normal })
}

/// Time of impact of a circle of `radius` at `center` moving by `motion` against the front
/// of `segment`, whose unit `normal` points to its front: the segment's capsule, with a
/// rounded cap at each end where `caps` says so.
///
/// Back faces never block: a circle whose centre is behind the segment's line (inside the
/// solid, or below a one-way platform) is not stopped by it, and a cap only counts the
/// half in front of the line. The flat side is met when the
/// centre comes within `radius` of the line, moving towards it, over the segment's extent;
/// a cap when the centre comes within `radius` of the end point. A circle already within
/// `radius` and moving closer gets `t = 0`. A cap is left out where the surface continues
/// into a collinear or concave neighbour: there it is covered by the neighbour's flat side,
/// and leaving it in would snag a circle sliding over the seam.
///
/// Every finite input is answered, whatever its magnitude, as [`sweep_circle_circle`]
/// answers it: `t` is never NaN and lies in `[0, 1]`, and a motion that crosses the
/// segment's face is reported at the time it reaches it. While the magnitudes of the
/// components of `center − segment.a`, the segment's `b − a`, the motion and the radius add
/// up to between 2⁻²⁰ and 2³⁰, it runs in `f32` as written; otherwise the problem is moved to `a` in `f64`
/// and scaled by a power of two into that range first.
///
/// ```
/// # use tileslide::geometry::{EndCaps, sweep_circle_segment};
/// # use tileslide::{Segment, Vec2};
/// // A floor along y = 0 facing up; a circle of radius 0.5 falls onto it from y = 3.
/// let floor = Segment::new(Vec2::new(-5.0, 0.0), Vec2::new(5.0, 0.0));
/// let hit = sweep_circle_segment(Vec2::new(0.0, 3.0), 0.5, Vec2::new(0.0, -5.0), &floor, Vec2::Y, EndCaps::BOTH).unwrap();
/// assert_eq!(hit.t, 0.5);
/// assert_eq!(hit.normal, Vec2::Y);
/// // From below, the back face lets it through.
/// assert!(sweep_circle_segment(Vec2::new(0.0, -3.0), 0.5, Vec2::new(0.0, 5.0), &floor, Vec2::Y, EndCaps::BOTH).is_none());
/// ```
#[must_use]
pub fn sweep_circle_segment(
    center: Vec2,
    radius: f32,
    motion: Vec2,
    segment: &Segment,
    normal: Vec2,
    caps: EndCaps,
) -> Option<SweepHit> {
    let size = largest([center - segment.a, segment.delta(), motion], [radius]);
    // Out of the ordinary sizes the problem is moved to `a` and scaled (see `rescaled`),
    // into the ordinary sizes (not a recursive call: this function must stay inlinable).
    let (center, radius, motion, segment) = if ordinary(size) {
        (center, radius, motion, *segment)
    } else {
        let a = segment.a.as_dvec2();
        let offsets = [center.as_dvec2() - a, segment.b.as_dvec2() - a];
        let ([p, e, motion], [radius]) = rescaled(
            [offsets[0], offsets[1], motion.as_dvec2()],
            [f64::from(radius)],
        )?;
        (p, radius, motion, Segment::new(Vec2::ZERO, e))
    };
    circle_segment(center, radius, motion, &segment, normal, caps.to_array())
}

/// [`sweep_circle_segment`] in `f32` as written, without the size check, the caps as
/// `[a, b]`: for callers whose inputs are known to be ordinary. The resolver's bodies are (positions, moves and radii
/// within [`MAX_COORD`](crate::limits::MAX_COORD), radii positive), so its hot loop runs exactly
/// the arithmetic it ran before the check existed.
#[inline]
pub(crate) fn circle_segment(
    center: Vec2,
    radius: f32,
    motion: Vec2,
    segment: &Segment,
    normal: Vec2,
    caps: [bool; 2],
) -> Option<SweepHit> {
    let (a, e) = (segment.a, segment.delta());
    let h0 = (center - a).dot(normal);
    let mut best: Option<SweepHit> = None;
    let vn = motion.dot(normal);
    let len2 = e.length_squared();
    // A centre behind the line never meets the flat side from the front (it may still come
    // round an end and meet a cap's front half, below).
    if h0 >= 0.0 && vn < 0.0 && len2 > 0.0 {
        // The flat side is met at the first `t` where the centre is within `radius` of the
        // line *and* over the segment's extent. The second can come later: a circle that
        // slides along a wall into the next segment's extent enters its slab from the side
        // (at a seam without a cap, nothing else would catch it).
        let t_near = if h0 <= radius {
            0.0
        } else {
            (h0 - radius) / -vn
        };
        // Past the line the centre is behind the face: no front contact from then on.
        let t_line = h0 / -vn;
        let (s0, se) = ((center - a).dot(e), motion.dot(e));
        let (t_in, t_out) = if se == 0.0 {
            if (0.0..=len2).contains(&s0) {
                (0.0, f32::INFINITY)
            } else {
                (f32::INFINITY, f32::NEG_INFINITY)
            }
        } else {
            let (t0, t1) = (-s0 / se, (len2 - s0) / se);
            (t0.min(t1), t0.max(t1))
        };
        let t = t_near.max(t_in).max(0.0);
        if t <= 1.0 && t <= t_out && t <= t_line {
            best = Some(SweepHit { t, normal });
        }
    }
    for (end, capped) in [(a, caps[0]), (segment.b, caps[1])] {
        if !capped {
            continue;
        }
        // Only the cap's front half belongs to this face: behind the line, the neighbouring
        // face (or nothing, for a one-way platform) decides.
        if let Some(hit) = sweep_circle_circle(center, motion, end, radius)
            && hit.normal.dot(normal) >= 0.0
            && best.is_none_or(|b| hit.t < b.t)
        {
            best = Some(hit);
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn v(x: f32, y: f32) -> Vec2 {
        Vec2::new(x, y)
    }

    #[test]
    fn head_on_circles_touch_at_the_sum_of_radii() {
        let hit = sweep_circle_circle(v(0.0, 0.0), v(4.0, 0.0), v(3.0, 0.0), 1.0).unwrap();
        assert_eq!(hit.t, 0.5);
        assert_eq!(hit.normal, v(-1.0, 0.0));
    }

    #[test]
    fn grazing_and_missing_circles() {
        // Passing at distance exactly 1 with radius sum 1 only grazes: no contact.
        assert!(sweep_circle_circle(v(-2.0, 1.0), v(4.0, 0.0), v(0.0, 0.0), 1.0).is_none());
        // A hair closer is a contact, just before the closest approach.
        let hit = sweep_circle_circle(v(-2.0, 0.999), v(4.0, 0.0), v(0.0, 0.0), 1.0).unwrap();
        assert!((hit.t - 0.488_82).abs() < 1e-4, "{}", hit.t);
        assert!(sweep_circle_circle(v(-2.0, 1.01), v(4.0, 0.0), v(0.0, 0.0), 1.0).is_none());
        // Stops short.
        assert!(sweep_circle_circle(v(-3.0, 0.0), v(1.5, 0.0), v(0.0, 0.0), 1.0).is_none());
    }

    /// The case the soak found: a circle cast 18 cells onto a block's corner stopped
    /// 1.2·10⁻⁴ inside it.
    #[test]
    fn a_circle_cast_from_afar_onto_a_corner_stops_touching_it() {
        let (c, r, m) = (
            v(55.914_715, 71.498_19),
            0.223_694_18,
            v(-11.791_868, -14.046_258),
        );
        let corner = v(46.0, 60.0);
        let hit = sweep_circle_circle(c, m, corner, r).unwrap();
        let at = c.as_dvec2() + m.as_dvec2() * f64::from(hit.t);
        let gap = (at - corner.as_dvec2()).length() - f64::from(r);
        assert!(gap.abs() < 1e-5, "gap {gap}");
    }

    #[test]
    fn overlapping_circles_block_approach_but_not_escape() {
        let hit = sweep_circle_circle(v(0.5, 0.0), v(-1.0, 0.0), v(0.0, 0.0), 1.0).unwrap();
        assert_eq!(hit.t, 0.0);
        assert_eq!(hit.normal, v(1.0, 0.0));
        assert!(sweep_circle_circle(v(0.5, 0.0), v(1.0, 0.0), v(0.0, 0.0), 1.0).is_none());
        // Tangential motion is not approach.
        assert!(sweep_circle_circle(v(0.5, 0.0), v(0.0, 1.0), v(0.0, 0.0), 1.0).is_none());
    }

    #[test]
    fn zero_and_nan_motion_never_hit() {
        assert!(sweep_circle_circle(v(0.5, 0.0), Vec2::ZERO, Vec2::ZERO, 1.0).is_none());
        assert!(sweep_circle_circle(v(0.5, 0.0), v(f32::NAN, 0.0), Vec2::ZERO, 1.0).is_none());
        let floor = Segment::new(v(-1.0, 0.0), v(1.0, 0.0));
        assert!(
            sweep_circle_segment(v(0.0, 1.0), 0.5, Vec2::ZERO, &floor, Vec2::Y, EndCaps::BOTH)
                .is_none()
        );
        assert!(
            sweep_circle_segment(
                v(0.0, 1.0),
                0.5,
                v(0.0, f32::NAN),
                &floor,
                Vec2::Y,
                EndCaps::BOTH
            )
            .is_none()
        );
    }

    #[test]
    fn segment_flat_side_caps_and_seams() {
        let floor = Segment::new(v(0.0, 0.0), v(1.0, 0.0));
        // Sliding along the floor at exactly the radius: not approaching, no hit.
        assert!(
            sweep_circle_segment(
                v(0.5, 0.5),
                0.5,
                v(2.0, 0.0),
                &floor,
                Vec2::Y,
                EndCaps::BOTH
            )
            .is_none()
        );
        // Moving diagonally past the end: the cap at b rounds the corner.
        let hit = sweep_circle_segment(
            v(2.0, 1.0),
            0.5,
            v(-2.0, -2.0),
            &floor,
            Vec2::Y,
            EndCaps::BOTH,
        )
        .unwrap();
        let at = v(2.0, 1.0) + v(-2.0, -2.0) * hit.t;
        assert!((at.distance(v(1.0, 0.0)) - 0.5).abs() < 1e-5);
        assert!(hit.normal.x > 0.0 && hit.normal.y > 0.0);
        // Without the cap (the floor continues there), that path meets nothing of this segment.
        assert!(
            sweep_circle_segment(
                v(2.0, 1.0),
                0.5,
                v(-0.9, -0.9),
                &floor,
                Vec2::Y,
                EndCaps { a: true, b: false }
            )
            .is_none()
        );
        // Penetrating and pushing in: t = 0.
        let hit = sweep_circle_segment(
            v(0.5, 0.25),
            0.5,
            v(0.0, -1.0),
            &floor,
            Vec2::Y,
            EndCaps::BOTH,
        )
        .unwrap();
        assert_eq!(hit.t, 0.0);
        assert_eq!(hit.normal, Vec2::Y);
    }

    /// Distance from the circle's centre to the obstacle, sampled along the move.
    fn min_gap_before(t_end: f32, gap_at: impl Fn(f32) -> f32) -> f32 {
        (0..=1000)
            .map(|i| gap_at(t_end * i as f32 / 1000.0))
            .fold(f32::INFINITY, f32::min)
    }

    proptest! {
        /// Against brute force: up to the reported `t` the circles never come closer than
        /// the radius sum (beyond rounding); a reported contact is at the radius sum; and
        /// when there is no hit, the sampled path never overlaps while approaching.
        #[test]
        fn circle_sweep_matches_sampling(
            cx in -5.0f32..5.0, cy in -5.0f32..5.0,
            mx in -10.0f32..10.0, my in -10.0f32..10.0,
            r in 0.1f32..2.0,
        ) {
            let (c, m) = (v(cx, cy), v(mx, my));
            prop_assume!(c.length() > r + 1e-3);
            let gap_at = |t: f32| (c + m * t).length() - r;
            match sweep_circle_circle(c, m, Vec2::ZERO, r) {
                Some(hit) => {
                    prop_assert!(min_gap_before(hit.t, gap_at) > -1e-3);
                    prop_assert!(gap_at(hit.t).abs() < 1e-3);
                }
                None => prop_assert!(min_gap_before(1.0, gap_at) > -1e-3),
            }
        }

        /// A circle from far off (up to 64 away, aimed at the obstacle) stops where it
        /// touches, to within a few roundings of the positions: the gap at the reported `t`,
        /// computed in `f64`, is under 10⁻⁵ plus 2·10⁻⁷ of the distance travelled. (Solved
        /// as `b² − a·c` at any distance, the contact was off by up to 3·10⁻⁴ at 18 cells.)
        #[test]
        fn a_circle_from_far_off_stops_where_it_touches(
            cx in -64.0f32..64.0, cy in -64.0f32..64.0,
            tx in -1.0f32..1.0, ty in -1.0f32..1.0,
            over in 1.0f32..2.0,
            r in 0.05f32..1.0,
        ) {
            let c = v(cx, cy);
            prop_assume!(c.length() > r + 1e-3);
            let m = (v(tx, ty) * r * 1.2 - c) * over;
            if let Some(hit) = sweep_circle_circle(c, m, Vec2::ZERO, r) {
                let at = c.as_dvec2() + m.as_dvec2() * f64::from(hit.t);
                let gap = at.length() - f64::from(r);
                let travelled = f64::from(m.length() * hit.t);
                prop_assert!(gap.abs() < 1e-5 + 2e-7 * travelled, "gap {gap} after {travelled}");
            }
        }

        /// The segment sweep against sampling: never inside the capsule (front side) before
        /// `t`, and a miss never enters it from the front.
        #[test]
        fn segment_sweep_matches_sampling(
            cx in -3.0f32..3.0, cy in 0.0f32..3.0,
            mx in -6.0f32..6.0, my in -6.0f32..6.0,
            r in 0.1f32..1.0,
        ) {
            let seg = Segment::new(v(-1.0, 0.0), v(1.0, 0.0));
            let (c, m) = (v(cx, cy), v(mx, my));
            prop_assume!(seg.distance_squared_to(c).sqrt() > r + 1e-3);
            // Inside the capsule while the centre is still on the front side.
            let gap_at = |t: f32| {
                let p = c + m * t;
                if p.y < 0.0 { f32::INFINITY } else { seg.distance_squared_to(p).sqrt() - r }
            };
            // Once behind the line the test no longer applies: sample only up to there.
            let front_until = if m.y < 0.0 { (cy / -my).min(1.0) } else { 1.0 };
            match sweep_circle_segment(c, r, m, &seg, Vec2::Y, EndCaps::BOTH) {
                Some(hit) => {
                    prop_assert!(min_gap_before(hit.t, gap_at) > -1e-3);
                    prop_assert!(gap_at(hit.t).abs() < 1e-3);
                }
                None => prop_assert!(min_gap_before(front_until, gap_at) > -1e-3),
            }
        }
    }
}
