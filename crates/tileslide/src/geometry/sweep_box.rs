//! Moving boxes: the exact time of impact of an axis-aligned box swept along a straight move
//! against the front of a segment.
//!
//! The box and the segment first touch where the box's centre meets the boundary of their
//! Minkowski sum (Ericson, *Real-Time Collision Detection*, 5.5.7): the segment pushed out by
//! the box's support feature along the segment's normal (a corner, or a whole side when the
//! segment is axis-aligned), and near the segment's ends, the box's sides meeting an end
//! point. Both are solved in closed form, so a move of any length is checked whole.

use glam::Vec2;

use super::sweep::{largest, ordinary, rescaled};
use super::{EndCaps, Segment, SweepHit};

/// Relative distance within which a slanted face's support corner reaching the line and
/// reaching the segment's end are one event (a corner contact): a few roundings of the
/// projections they are computed from.
const CORNER_ROUNDING: f32 = 8.0 * f32::EPSILON;

/// Time of impact of an axis-aligned box with half extents `half`, centred at `center` and
/// moving by `motion`, against the front of `segment`, whose unit `normal` points to its
/// front; `caps` says at which ends the box's sides may catch the segment's end point.
///
/// The rules are those of [`sweep_circle_segment`](super::sweep_circle_segment): back faces
/// never block (a box whose centre is behind the segment's line is not stopped by it); the
/// flat side is met when the box's lowest point along `-normal` reaches the line, moving
/// towards it, while the box's extent along the segment overlaps it; a box already across
/// the line and over the segment, moving closer, gets `t = 0`. An end point counts where
/// `caps` says so, and only while the box's centre is in front of the segment's line (as a
/// circle's cap counts only its front half): a box whose centre is below a one-way platform
/// passes its ends, and at a seam (no cap) the neighbour's flat side decides. The contact
/// normal points from the segment towards the box.
///
/// **Which face a contact reports.** The reported contact is the first moment the box's
/// *inside* would take in a point of the segment, and its normal is the face through which
/// that happens (the edge of the Minkowski sum of box and segment the centre's path enters,
/// Ericson 5.5.7):
/// - the segment's face, when the box reaches the segment's line while its extent along the
///   segment overlaps the segment by more than a point;
/// - an end point's box side (`±x` or `±y`), when the end point comes into the box through
///   that side: the box reached the extent of a segment whose line it had already crossed
///   (it is beside a step, not above it), so the end point is what it runs into. Without a
///   cap there, the segment reports nothing: the surface continuing from that end decides;
/// - nothing, for a touch that never moves into the box: a side sliding along an end point
///   (a box flush with a block's top passing over its corner), or a face left just as the
///   line is reached.
///
/// When two of these happen at the same `t` (the box's corner meets the segment's end point
/// exactly), the one the motion runs into most head-on wins: the largest `-normal · motion`;
/// on equal terms a box side wins over a slanted face, and `±x` over `±y`. So every segment
/// of a corner reports the same normal for the same contact, whatever order a caller tests
/// them in: a box moving right and dipping into the top-left corner of a block it is level
/// with gets the block's side `(-1, 0)` from the block's top as from its side. (In a concave
/// corner reached exactly, the box's bottom landing on the floor as its side reaches the
/// wall, both faces are met at once and each reports its own normal: either keeps the box
/// out, and a caller wanting one answer ranks equal `t` by `-normal · motion`.)
///
/// **Every finite input** is answered, whatever its magnitude: `t` is never NaN and lies in
/// `[0, 1]`, and a motion that crosses the segment's face is reported at the time the box
/// reaches it. While the magnitudes of the components of `center − segment.a`, the
/// segment's `b − a`, the motion and the half extents add up to between 2⁻²⁰ and 2³⁰, it
/// runs in `f32` as written; otherwise (where the segment's squared length or an offset would overflow
/// or underflow), the problem is moved to `a` in `f64` and scaled by a power of two into
/// that range first, which changes neither `t` nor the normal. A NaN or infinite input
/// hits nothing.
///
/// ```
/// # use tileslide::geometry::{EndCaps, sweep_box_segment};
/// # use tileslide::{Segment, Vec2};
/// // A floor along y = 0 facing up; a 1 × 2 box falls onto it from y = 3 (its bottom at 2).
/// let floor = Segment::new(Vec2::new(-5.0, 0.0), Vec2::new(5.0, 0.0));
/// let hit = sweep_box_segment(Vec2::new(0.0, 3.0), Vec2::new(0.5, 1.0), Vec2::new(0.0, -4.0), &floor, Vec2::Y, EndCaps::BOTH).unwrap();
/// assert_eq!(hit.t, 0.5);
/// assert_eq!(hit.normal, Vec2::Y);
/// // A box whose edge overhangs the floor's end by less than its half width still lands.
/// let hit = sweep_box_segment(Vec2::new(5.4, 3.0), Vec2::new(0.5, 1.0), Vec2::new(0.0, -4.0), &floor, Vec2::Y, EndCaps::BOTH);
/// assert_eq!(hit.map(|h| h.t), Some(0.5));
/// // A box beside a step (its bottom below the step's top at y = 0, from x = 5) moving right
/// // and down runs into the step's corner with its side: the side's normal, not the top's.
/// let step = Segment::new(Vec2::new(5.0, 0.0), Vec2::new(8.0, 0.0));
/// let hit = sweep_box_segment(Vec2::new(3.0, 0.9), Vec2::new(1.0, 1.0), Vec2::new(2.0, -0.1), &step, Vec2::Y, EndCaps::BOTH).unwrap();
/// assert_eq!((hit.t, hit.normal), (0.5, Vec2::NEG_X));
/// ```
#[must_use]
pub fn sweep_box_segment(
    center: Vec2,
    half: Vec2,
    motion: Vec2,
    segment: &Segment,
    normal: Vec2,
    caps: EndCaps,
) -> Option<SweepHit> {
    let size = largest([center - segment.a, segment.delta(), motion, half], []);
    // Out of the ordinary sizes the problem is moved to `a` and scaled (see `rescaled`),
    // into the ordinary sizes (not a recursive call: this function must stay inlinable).
    let (center, half, motion, segment) = if ordinary(size) {
        (center, half, motion, *segment)
    } else {
        let a = segment.a.as_dvec2();
        let sizes = [
            center.as_dvec2() - a,
            segment.b.as_dvec2() - a,
            motion.as_dvec2(),
            half.as_dvec2(),
        ];
        let ([p, e, motion, half], []) = rescaled(sizes, [])?;
        (p, half, motion, Segment::new(Vec2::ZERO, e))
    };
    let (a, e) = (segment.a, segment.delta());
    let len2 = e.length_squared();
    let h0 = (center - a).dot(normal);
    let vn = motion.dot(normal);
    let mut best: Option<SweepHit> = None;
    if h0 >= 0.0 && vn < 0.0 && len2 > 0.0 {
        best = sweep_box_face(center, half, motion, &segment, normal);
    }
    for (end, capped) in [(a, caps.a), (segment.b, caps.b)] {
        if capped
            && let Some(hit) = sweep_box_point(center, half, motion, end)
            && in_front_at(h0, vn, hit.t)
            && best.is_none_or(|b| hit.t < b.t)
        {
            best = Some(hit);
        }
    }
    best
}

/// The flat side of [`sweep_box_segment`]: the time the box, in front of the segment's line
/// (`h0 >= 0`) and moving towards it, meets the face itself; `None` when it meets only an
/// end point (the end's business) or nothing.
fn sweep_box_face(
    center: Vec2,
    half: Vec2,
    motion: Vec2,
    segment: &Segment,
    normal: Vec2,
) -> Option<SweepHit> {
    let (a, e) = (segment.a, segment.delta());
    let h0 = (center - a).dot(normal);
    let vn = motion.dot(normal);
    // How far the box reaches towards the line from its centre.
    let support = half.x * normal.x.abs() + half.y * normal.y.abs();
    // The support feature's extent along the segment, relative to the centre: one corner,
    // or a whole side when the segment is axis-aligned (its normal has a zero component, as
    // every grid-aligned tile face has).
    let len = e.length();
    let u = e / len;
    let corner = Vec2::new(-half.x.copysign(normal.x), -half.y.copysign(normal.y));
    let (lo, hi) = if normal.x == 0.0 {
        let r = half.x * u.x.abs();
        (corner.y * u.y - r, corner.y * u.y + r)
    } else if normal.y == 0.0 {
        let r = half.y * u.y.abs();
        (corner.x * u.x - r, corner.x * u.x + r)
    } else {
        let s = corner.dot(u);
        (s, s)
    };
    // The feature overlaps the segment by more than a point while `s(t) + lo < len` and
    // `s(t) + hi > 0`: for `t` strictly between `t_in` and `t_out`.
    let (s0, se) = ((center - a).dot(u), motion.dot(u));
    let (t_in, t_out) = if se == 0.0 {
        if s0 + lo < len && s0 + hi > 0.0 {
            (f32::NEG_INFINITY, f32::INFINITY)
        } else {
            return None;
        }
    } else {
        let (t0, t1) = ((-hi - s0) / se, (len - lo - s0) / se);
        (t0.min(t1), t0.max(t1))
    };
    if h0 < support {
        // Already across the line: held by the face only if over the segment now (its
        // support feature, and for a slanted segment the box itself, whose corner may be
        // over the segment while the box is beside its end). A box that comes over it later,
        // across its line, runs into its end point instead.
        let over = t_in < 0.0 && 0.0 < t_out;
        let b = segment.b;
        let beside = (normal.x != 0.0 && normal.y != 0.0)
            && ((center - half).cmpge(a.max(b)).any() || (center + half).cmple(a.min(b)).any());
        return (over && !beside).then_some(SweepHit { t: 0.0, normal });
    }
    let t = (h0 - support) / -vn;
    if t > 1.0 || t >= t_out {
        return None;
    }
    // The feature reaches the line as it reaches the segment's end: a corner meets the end
    // point. Exactly so for an axis-aligned face (its terms are exact differences, so equal
    // times round equal); within rounding for a slanted one, whose terms are rounded
    // projections (a box walking flush along a floor into a ramp's foot).
    let corner = if normal.x == 0.0 || normal.y == 0.0 {
        t == t_in
    } else {
        let scale = h0.abs() + support + s0.abs() + lo.abs() + hi.abs() + len;
        (t - t_in).abs() * (-vn).max(se.abs()) <= CORNER_ROUNDING * scale
    };
    if corner {
        return face_wins_corner(normal, motion, se).then_some(SweepHit { t, normal });
    }
    (t > t_in).then_some(SweepHit { t, normal })
}

/// At a corner contact (the box's support feature meets the segment's end point as it
/// reaches the line), whether the face's `normal` beats the box's sides there: it must
/// oppose `motion` strictly more than each side that the end point comes in through (on
/// equal terms a side wins, and of an axis-aligned face only an `x` face wins). `se` is the
/// motion along the segment.
fn face_wins_corner(normal: Vec2, motion: Vec2, se: f32) -> bool {
    let into_face = -motion.dot(normal);
    if normal.y == 0.0 {
        // A side (x) face: the end point comes in through the box's top or bottom.
        into_face >= se.abs()
    } else if normal.x == 0.0 {
        into_face > se.abs()
    } else {
        // A slanted face: the end point is at the box's corner, and comes in through both
        // sides there (those facing the segment, as its normal does) only if the motion runs
        // into both; otherwise it slides along one of them, and the face near the end point
        // is what enters the box (a box walking along a floor into a ramp's foot).
        let (x, y) = (-normal.x.signum() * motion.x, -normal.y.signum() * motion.y);
        x <= 0.0 || y <= 0.0 || into_face > x.max(y)
    }
}

/// Whether the box's centre is on or in front of the segment's line at `t`, for a centre
/// that starts at height `h0` above it and rises by `vn` over the move: compared as `t`
/// against the time of crossing, so a contact exactly on the line counts whatever the
/// rounding of `center + motion · t`.
fn in_front_at(h0: f32, vn: f32, t: f32) -> bool {
    if vn < 0.0 {
        h0 >= 0.0 && t <= h0 / -vn
    } else if vn > 0.0 {
        h0 >= 0.0 || t >= -h0 / vn
    } else {
        h0 >= 0.0
    }
}

/// Time of impact of the box against a point: the point, moving by `-motion`, entering the
/// box's inside through one of its sides (a slab test). The normal is that side's outward
/// normal, negated: from the point towards the box. A point that enters through a corner
/// (both sides at once) takes the side the motion runs into more (`x` on equal terms). A
/// point strictly inside the box gives `t = 0` with the normal of the side it is nearest,
/// if the move takes the box further onto it. `None` when the point misses the box, only
/// slides along a side or touches a corner, enters after `t = 1`, or is inside and the box
/// moves off it.
fn sweep_box_point(center: Vec2, half: Vec2, motion: Vec2, point: Vec2) -> Option<SweepHit> {
    // The point relative to the box, moving by -motion.
    let p = point - center;
    if p.abs().cmplt(half).all() {
        // Inside: the nearest side decides.
        let depth = half - p.abs();
        let normal = if depth.x < depth.y {
            Vec2::new(-p.x.signum(), 0.0)
        } else {
            Vec2::new(0.0, -p.y.signum())
        };
        return (motion.dot(normal) < 0.0).then_some(SweepHit { t: 0.0, normal });
    }
    let d = -motion;
    let mut t_enter = f32::NEG_INFINITY;
    let mut t_exit = f32::INFINITY;
    let mut normal = Vec2::ZERO;
    let mut speed = 0.0;
    for (axis, unit) in [(0, Vec2::X), (1, Vec2::Y)] {
        let (pa, da, ha) = (p[axis], d[axis], half[axis]);
        if da == 0.0 {
            // Never crosses this slab's sides: inside it all along, or (on a side or
            // beyond) never inside the box.
            if pa <= -ha || pa >= ha {
                return None;
            }
            continue;
        }
        let (t0, t1) = ((-ha - pa) / da, (ha - pa) / da);
        let (near, far) = if t0 < t1 { (t0, t1) } else { (t1, t0) };
        if near > t_enter || (near == t_enter && da.abs() > speed) {
            t_enter = near;
            speed = da.abs();
            // Entering through the side facing the point's approach: the point moves along
            // `da`, so it comes through the side at `-sign(da)`; the contact normal from the
            // point towards the box is `+sign(da)` on this axis.
            normal = unit * da.signum();
        }
        t_exit = t_exit.min(far);
    }
    (t_enter >= 0.0 && t_enter < t_exit && t_enter <= 1.0)
        .then_some(SweepHit { t: t_enter, normal })
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn v(x: f32, y: f32) -> Vec2 {
        Vec2::new(x, y)
    }

    /// The up-left normal of the ramp of [`drop_on_ramp`].
    fn ramp_normal() -> Vec2 {
        v(-1.0, 1.0).normalize()
    }

    /// A unit box at `center` falling by `fall` onto a ramp rising to the right (y up) from
    /// (0, 0) to (2, 2), with `caps`.
    fn drop_on_ramp(center: Vec2, fall: f32, caps: EndCaps) -> Option<SweepHit> {
        let ramp = Segment::new(v(0.0, 0.0), v(2.0, 2.0));
        sweep_box_segment(
            center,
            v(0.5, 0.5),
            v(0.0, -fall),
            &ramp,
            ramp_normal(),
            caps,
        )
    }

    fn floor() -> Segment {
        Segment::new(v(0.0, 0.0), v(4.0, 0.0))
    }

    #[test]
    fn a_box_resting_on_a_floor_slides_along_it_unhindered() {
        // Bottom exactly on the floor, moving along it: not approaching.
        let hit = sweep_box_segment(
            v(1.0, 0.5),
            v(0.5, 0.5),
            v(2.0, 0.0),
            &floor(),
            Vec2::Y,
            EndCaps::BOTH,
        );
        assert!(hit.is_none());
        // Pressing into it: t = 0.
        let hit = sweep_box_segment(
            v(1.0, 0.5),
            v(0.5, 0.5),
            v(1.0, -1.0),
            &floor(),
            Vec2::Y,
            EndCaps::BOTH,
        );
        assert_eq!(hit.map(|h| h.t), Some(0.0));
    }

    #[test]
    fn the_corner_of_a_box_lands_on_a_ramp() {
        // A unit box above the ramp's middle falls straight down: its bottom-right corner
        // (1.5, y − 0.5) meets the ramp where y − 0.5 = 1.5.
        let hit = drop_on_ramp(v(1.0, 5.0), 10.0, EndCaps::BOTH).unwrap();
        let center = 5.0 - 10.0 * hit.t;
        assert!((center - 2.0).abs() < 1e-5, "{hit:?}");
        assert_eq!(hit.normal, ramp_normal());
    }

    #[test]
    fn an_end_point_catches_a_box_in_front_of_its_line_only_where_capped() {
        // The top of a ramp ends at (2, 2), capped. A box whose bottom-left corner is
        // right of the end lands on the end point with its bottom side.
        let hit = drop_on_ramp(v(2.3, 4.0), 4.0, EndCaps::BOTH).unwrap();
        assert_eq!(hit.normal, Vec2::Y);
        assert!((4.0 - 4.0 * hit.t - 2.5).abs() < 1e-5);
        // Without the cap (the surface continues), the end point does not count.
        assert!(drop_on_ramp(v(2.6, 4.0), 4.0, EndCaps { a: true, b: false }).is_none());
        // Moving sideways into a one-way floor's end: passes with the centre below its
        // line, is caught by the side with the centre above it.
        let platform = Segment::new(v(0.0, 0.0), v(2.0, 0.0));
        let sideways = |y: f32| {
            let (c, half, m) = (v(-1.0, y), v(0.5, 0.5), v(4.0, 0.0));
            sweep_box_segment(c, half, m, &platform, Vec2::Y, EndCaps::BOTH)
        };
        assert!(sideways(-0.1).is_none());
        let hit = sideways(0.1).unwrap();
        assert_eq!((hit.t, hit.normal), (0.125, -Vec2::X));
    }

    #[test]
    fn a_box_already_over_a_capped_end_is_held_as_a_circle_would_be() {
        // The ramp's top end (1, 1) is inside the box; moving down-right onto it: t = 0.
        let ramp = Segment::new(v(0.0, 0.0), v(1.0, 1.0));
        let n = ramp_normal();
        let hit = sweep_box_segment(
            v(1.1, 1.3),
            v(0.5, 0.5),
            v(0.5, -0.5),
            &ramp,
            n,
            EndCaps::BOTH,
        );
        assert_eq!(hit.map(|h| h.t), Some(0.0));
        // Moving off it: no contact.
        let away = sweep_box_segment(
            v(1.1, 1.3),
            v(0.5, 0.5),
            v(0.0, 0.5),
            &ramp,
            n,
            EndCaps::BOTH,
        );
        assert!(away.is_none());
    }

    #[test]
    fn back_faces_and_receding_moves_do_not_block() {
        assert!(
            sweep_box_segment(
                v(1.0, -2.0),
                v(0.5, 0.5),
                v(0.0, 4.0),
                &floor(),
                Vec2::Y,
                EndCaps::BOTH
            )
            .is_none()
        );
        assert!(
            sweep_box_segment(
                v(1.0, 0.2),
                v(0.5, 0.5),
                v(0.0, 4.0),
                &floor(),
                Vec2::Y,
                EndCaps::BOTH
            )
            .is_none()
        );
    }

    /// Whether the box at `c` and the segment share a point, with the box shrunk by `eps`.
    fn overlaps(c: Vec2, half: Vec2, s: &Segment, eps: f32) -> bool {
        let b = crate::geometry::Aabb::from_center(c, half - Vec2::splat(eps));
        b.overlaps_segment(s)
    }

    proptest! {
        /// Against dense sampling: no sample before the reported `t` has the box overlapping
        /// the segment from its front (by more than rounding), and when nothing is reported
        /// no sample overlaps while the centre is in front.
        #[test]
        fn no_overlap_is_missed_before_the_time_of_impact(
            cx in -3.0f32..7.0, cy in 0.8f32..4.0,
            mx in -6.0f32..6.0, my in -6.0f32..0.5,
            hx in 0.1f32..1.0, hy in 0.1f32..1.0,
            ax in -1.0f32..2.0, bx in 2.5f32..5.0, ay in -0.5f32..0.5, by in -0.5f32..0.5,
        ) {
            let (a, b) = (v(ax, ay), v(bx, by));
            let s = Segment::new(a, b);
            let n = (b - a).perp().normalize();
            let (c, half, m) = (v(cx, cy), v(hx, hy), v(mx, my));
            // Start clear of the segment and in front of it.
            prop_assume!(!overlaps(c, half, &s, 0.0) && (c - a).dot(n) > 0.0);
            let hit = sweep_box_segment(c, half, m, &s, n, EndCaps::BOTH);
            let end = hit.map_or(1.0, |h| h.t);
            for k in 0..=400 {
                let t = end * k as f32 / 400.0;
                let p = c + m * t;
                if (p - a).dot(n) < 0.0 {
                    break;
                }
                prop_assert!(!overlaps(p, half, &s, 1e-3), "overlap at t = {} before {:?}", t, hit);
            }
            if let Some(h) = hit {
                // At the reported time, the box touches the segment.
                let p = c + m * h.t;
                prop_assert!(overlaps(p, half + Vec2::splat(2e-3), &s, 0.0), "{:?}", h);
            }
        }
    }
}
