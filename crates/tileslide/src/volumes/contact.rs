//! When and where a hit happens: for two placed volumes that meet during the frame, the
//! time of impact along the frame's move and the point where they touch.
//!
//! Circles and upright rectangles are each a box rounded by a radius (a circle is its
//! centre rounded by its radius, a rectangle itself rounded by 0), and two such shapes
//! touch when the gap between their boxes closes to the sum of the radii: the moving one's
//! path against their Minkowski difference, a box rounded by that sum. The time is exact:
//! a slab test for the flat sides, `sweep_circle_circle` for a rounded corner (Ericson,
//! *Real-Time Collision Detection*, 5.5.7). Turned rectangles and capsules use the sweeps
//! of `rounded.rs`, each corner against each side.
//!
//! The sweeps count a contact only where the shapes move into each other, so for a pair
//! whose paths only graze (the pair test, which counts touching, says they meet; the
//! sweeps see no approach) the time comes from the distance between the shapes' cores
//! instead, which is convex along the move (the distance from a point moving on a line to
//! a convex set, their Minkowski difference): a golden-section search finds its least, the
//! nearest approach; where the shapes touch there, bisection finds the first time they do,
//! on the stretch before, where the distance only falls. (For a path that only grazes, that
//! is within about √ε of the sizes of the true touch: `f32` distances cannot tell a
//! tangent approach from a touch closer than that. Bisecting the swept pair test itself
//! is not enough: for an exactly tangent path it answers by rounding for every time past
//! the touch, so the bisection can end anywhere after it.)

use glam::Vec2;

use super::placed::{Placed, segment_entry};
use crate::geometry::{Aabb, sweep_circle_circle};

/// When and where two volumes first touch during the frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Contact {
    /// Fraction of the frame's move, in `[0, 1]`: 0 when they overlap from the start.
    pub t: f32,
    /// A point both volumes hold at `t`, in world coordinates.
    pub point: Vec2,
}

/// Bisection steps for a grazing pair: `t` halves its interval each step, so 32 reach the
/// spacing of `f32` near 1 (2⁻²⁴) with room to spare; the loop also stops as soon as the
/// middle of the interval rounds to one of its ends.
const BISECTION_STEPS: u32 = 32;

/// Golden-section steps for a grazing pair's nearest approach: the interval shrinks to
/// 0.618 of itself each step, so 48 reach 10⁻¹⁰ (below the spacing of `f32` near 1); the
/// loop also stops as soon as its two inner points round together or onto an end.
const GOLDEN_STEPS: u32 = 48;

/// The share of the interval between each end and the inner point nearer it, 1 − 1/φ.
const GOLDEN_SHARE: f32 = 0.381_966;

impl Placed {
    /// When and where `self`, placed where the frame starts and moving by `motion`, first
    /// touches `other`, placed where the frame starts and moving by `other_motion`, for a
    /// pair that [`meets`](Self::meets) along the relative move. The point is one both hold
    /// at that time: where they touch, the point of contact; where they overlap, see
    /// [`rounded_box_point`] (and `Rounded::contact_point` for turned rectangles and
    /// capsules).
    pub fn contact(&self, motion: Vec2, other: &Placed, other_motion: Vec2) -> Contact {
        let relative = motion - other_motion;
        #[cfg(feature = "aim")]
        if !(self.is_rounded_box() && other.is_rounded_box()) {
            let (a, b) = (self.rounded(), other.rounded());
            let t = if relative != Vec2::ZERO && !self.meets(Vec2::ZERO, other) {
                a.time_of_impact(relative, &b)
                    .unwrap_or_else(|| self.first_meeting(relative, other))
            } else {
                0.0
            };
            let point = a
                .moved(motion * t)
                .contact_point(&b.moved(other_motion * t));
            return Contact { t, point };
        }
        let ((a, ra), (b, rb)) = (self.rounded_box(), other.rounded_box());
        let t = if relative == Vec2::ZERO {
            0.0
        } else {
            // `a` moved by `relative · t` is within `ra + rb` of `b` when `relative · t` is
            // within it of the box of offsets `b − a` (0 when it already is).
            let offsets = Aabb {
                min: b.min - a.max,
                max: b.max - a.min,
            };
            rounded_box_entry(Vec2::ZERO, relative, &offsets, ra + rb)
                .unwrap_or_else(|| self.first_meeting(relative, other))
        };
        let (a, b) = (moved(a, motion * t), moved(b, other_motion * t));
        Contact {
            t,
            point: rounded_box_point(&a, ra, &b, rb),
        }
    }

    /// The first `t` at which `self`, moved by `motion · t`, touches `other`, for a pair
    /// the sweeps see no approach in (see the module's notes): the nearest approach, or the
    /// first time before it at which the gap closes.
    fn first_meeting(&self, motion: Vec2, other: &Placed) -> f32 {
        // The squared distance between the cores is convex in `t` too (the square of a
        // convex function that is never negative), and its comparison with the squared
        // reach resolves a tangent approach as finely as `f32` can.
        let apart = |t: f32| self.core_distance_squared(motion * t, other);
        let reach = self.reach(other);
        let touches = |t: f32| apart(t) <= reach * reach;
        let (mut lo, mut hi) = (0.0f32, 1.0f32);
        for _ in 0..GOLDEN_STEPS {
            let share = (hi - lo) * GOLDEN_SHARE;
            let (m1, m2) = (lo + share, hi - share);
            if !(lo < m1 && m1 < m2 && m2 < hi) {
                break;
            }
            // On a tie (a stretch where the distance is flat) the earlier part is kept.
            if apart(m1) <= apart(m2) {
                hi = m2;
            } else {
                lo = m1;
            }
        }
        let nearest = if apart(lo) <= apart(hi) { lo } else { hi };
        if !touches(nearest) {
            return nearest;
        }
        // The distance only falls from 0 to `nearest`, and the pair does not touch at 0:
        // the first time it does.
        let (mut lo, mut hi) = (0.0f32, nearest);
        for _ in 0..BISECTION_STEPS {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if touches(mid) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        hi
    }

    /// The squared distance between the cores of `self` moved by `offset` and of `other`
    /// (0 where they overlap): convex in `offset`.
    fn core_distance_squared(&self, offset: Vec2, other: &Placed) -> f32 {
        #[cfg(feature = "aim")]
        if !(self.is_rounded_box() && other.is_rounded_box()) {
            let moved = self.rounded().moved(offset);
            return moved.core_distance_squared(&other.rounded());
        }
        let (a, b) = (moved(self.rounded_box().0, offset), other.rounded_box().0);
        (b.min - a.max)
            .max(a.min - b.max)
            .max(Vec2::ZERO)
            .length_squared()
    }

    /// The sum of the radii that round the two cores.
    fn reach(&self, other: &Placed) -> f32 {
        #[cfg(feature = "aim")]
        if !(self.is_rounded_box() && other.is_rounded_box()) {
            return self.rounded().reach(&other.rounded());
        }
        self.rounded_box().1 + other.rounded_box().1
    }
}

/// `b` moved by `offset`.
fn moved(b: Aabb, offset: Vec2) -> Aabb {
    Aabb {
        min: b.min + offset,
        max: b.max + offset,
    }
}

/// The first fraction of the move by `motion` at which `start` comes within `radius` of
/// the closed box `core` (0 when it starts there): its path against the box grown by the
/// radius with rounded corners (Ericson, *Real-Time Collision Detection*, 5.5.7, in two
/// dimensions). The path enters the grown box with square corners first (a slab test);
/// where it enters beside a side, that is the contact; where it enters a corner's square,
/// the rounded corner decides (a path through that square that misses the corner's circle
/// misses the box: the square's borders with the sides' regions lie within the radius of
/// the corner). `None` when it misses, or only grazes a corner (`sweep_circle_circle`
/// counts a contact only where the path moves into the circle).
fn rounded_box_entry(start: Vec2, motion: Vec2, core: &Aabb, radius: f32) -> Option<f32> {
    let grown = Aabb {
        min: core.min - Vec2::splat(radius),
        max: core.max + Vec2::splat(radius),
    };
    let t = segment_entry(start, motion, &grown)?;
    let at = start + motion * t;
    let corner = at.clamp(core.min, core.max);
    if radius > 0.0 && corner.x != at.x && corner.y != at.y {
        if t == 0.0 && at.distance_squared(corner) <= radius * radius {
            // Already within the corner's circle.
            return Some(0.0);
        }
        sweep_circle_circle(start, motion, corner, radius).map(|hit| hit.t)
    } else {
        Some(t)
    }
}

/// A point held by both the box `a` rounded by `ra` and the box `b` rounded by `rb`, for
/// shapes that touch or overlap. On each axis where the boxes' extents overlap, the middle
/// of the overlap; on the others, the ends of the extents that face each other; then, on
/// the line between the two points so found (the boxes' nearest points), the point `ra`
/// from `a`'s side in `ra + rb`. So for two rectangles, the middle of their common
/// rectangle; for a circle and a rectangle, the rectangle's point nearest the circle's
/// centre; for two circles, the point of the line between their centres that divides it
/// as their radii do. Where the shapes only touch, the point of contact.
pub(super) fn rounded_box_point(a: &Aabb, ra: f32, b: &Aabb, rb: f32) -> Vec2 {
    let (lo, hi) = (a.min.max(b.min), a.max.min(b.max));
    let overlap = lo.cmple(hi);
    let middle = (lo + hi) * 0.5;
    // Where the extents are apart, `a`'s end nearest `b` is where `b.min` clamps to in
    // `a` (whichever side `b` is on), and `b`'s end nearest that.
    let near_a = Vec2::select(overlap, middle, b.min.clamp(a.min, a.max));
    let near_b = Vec2::select(overlap, middle, near_a.clamp(b.min, b.max));
    let reach = ra + rb;
    if reach > 0.0 {
        near_a + (near_b - near_a) * (ra / reach)
    } else {
        near_a
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::volumes::placed::tests::{circle, rect};

    /// The contact of `a` moving by `motion` against still `b`, checked to meet first.
    fn hit(a: Placed, motion: Vec2, b: Placed) -> Contact {
        assert!(a.meets(motion, &b), "{a:?} by {motion} misses {b:?}");
        a.contact(motion, &b, Vec2::ZERO)
    }

    #[test]
    fn moving_circles_and_rects_touch_at_the_hand_computed_time_and_point() {
        let right = Vec2::new(4.0, 0.0);
        // Circles of radius 0.5, centres 3 apart: they touch when the gap of 2 is closed,
        // halfway, at the middle of the contact line.
        let c = hit(circle(0.0, 0.0, 0.5), right, circle(3.0, 0.0, 0.5));
        assert_eq!((c.t, c.point), (0.5, Vec2::new(2.5, 0.0)));
        // Unit boxes 2 apart: the leading side reaches x = 3 halfway; the point is the
        // middle of the shared side.
        let c = hit(rect(0.0, 0.0, 1.0, 1.0), right, rect(3.0, 0.0, 4.0, 1.0));
        assert_eq!((c.t, c.point), (0.5, Vec2::new(3.0, 0.5)));
        // A circle into a box's side: its front (x + 0.5) reaches 3 at t = 2.5 / 4.
        let c = hit(circle(0.0, 0.5, 0.5), right, rect(3.0, 0.0, 4.0, 1.0));
        assert_eq!((c.t, c.point), (0.625, Vec2::new(3.0, 0.5)));
        // A box into a circle: its side reaches the circle's left point 3.5 at t = 2.5 / 4.
        let c = hit(rect(0.0, 0.0, 1.0, 1.0), right, circle(4.0, 0.5, 0.5));
        assert_eq!((c.t, c.point), (0.625, Vec2::new(3.5, 0.5)));
        // A circle of radius 1 flying diagonally at a box's corner (0, 0) from (−2, −2):
        // touching when its centre is 1 from the corner, at t = 1 − 1 / (2√2).
        let c = hit(
            circle(-2.0, -2.0, 1.0),
            Vec2::new(2.0, 2.0),
            rect(0.0, 0.0, 1.0, 1.0),
        );
        let expected = 1.0 - 1.0 / (2.0 * 2f32.sqrt());
        assert!((c.t - expected).abs() < 1e-6, "{c:?}");
        assert!(c.point.length() < 1e-6, "{c:?}");
    }

    #[test]
    fn both_moving_they_touch_where_they_meet_in_the_world() {
        // Each moves 2 towards the other; the gap of 3 closes at t = 0.75, with the centres
        // at 1.5 and 2.5 and the contact point between them.
        let (a, b) = (circle(0.0, 0.0, 0.5), circle(4.0, 0.0, 0.5));
        let (ma, mb) = (Vec2::new(2.0, 0.0), Vec2::new(-2.0, 0.0));
        assert!(a.meets(ma - mb, &b));
        let c = a.contact(ma, &b, mb);
        assert_eq!((c.t, c.point), (0.75, Vec2::new(2.0, 0.0)));
    }

    #[test]
    fn overlapping_from_the_start_is_time_zero_at_a_point_of_the_overlap() {
        // Whatever the motion, even away.
        for motion in [Vec2::ZERO, Vec2::new(3.0, 0.0), Vec2::new(-3.0, 1.0)] {
            // Equal circles with centres 1.5 apart: the middle of the line between them.
            let c = hit(circle(0.0, 0.0, 1.0), motion, circle(1.5, 0.0, 1.0));
            assert_eq!((c.t, c.point), (0.0, Vec2::new(0.75, 0.0)));
            let c = hit(rect(0.0, 0.0, 2.0, 2.0), motion, rect(1.0, 1.5, 4.0, 4.0));
            assert_eq!((c.t, c.point), (0.0, Vec2::new(1.5, 1.75)));
            // A circle whose centre is inside the box: the centre.
            let c = hit(circle(0.5, 0.5, 1.0), motion, rect(0.0, 0.0, 1.0, 1.0));
            assert_eq!((c.t, c.point), (0.0, Vec2::new(0.5, 0.5)));
            // A circle overlapping a box's corner: the corner.
            let c = hit(circle(1.5, 1.5, 1.0), motion, rect(0.0, 0.0, 1.0, 1.0));
            assert_eq!((c.t, c.point), (0.0, Vec2::ONE));
        }
        // A small circle inside a large one: 3 / 3.5 of the way from the large one's centre
        // to the small one's, inside both.
        let c = hit(circle(0.0, 0.0, 3.0), Vec2::ZERO, circle(0.5, 0.0, 0.5));
        assert_eq!(c.t, 0.0);
        assert!(c.point.distance(Vec2::new(3.0 / 7.0, 0.0)) < 1e-6, "{c:?}");
    }

    #[test]
    fn a_grazing_path_touches_at_its_closest_approach() {
        // Passing exactly 1 above a circle with radius sum 1: the sweep sees no approach,
        // the pair test a touch at x = 0, halfway. Bisection finds it, to within what the
        // squared distances resolve near a tangent (x² below an ulp of 1: |x| < 3·10⁻⁴).
        let c = hit(
            circle(-2.0, 1.0, 0.5),
            Vec2::new(4.0, 0.0),
            circle(0.0, 0.0, 0.5),
        );
        assert!((c.t - 0.5).abs() < 1e-4, "{c:?}");
        assert!(c.point.distance(Vec2::new(0.0, 0.5)) < 4e-4, "{c:?}");
        // A box sliding along another's top, flush: it touches when it reaches x = 3.
        let c = hit(
            rect(0.0, 1.0, 1.0, 2.0),
            Vec2::new(4.0, 0.0),
            rect(3.0, 0.0, 4.0, 1.0),
        );
        assert_eq!(c.t, 0.5);
        assert_eq!(c.point, Vec2::new(3.0, 1.0));
    }

    #[test]
    fn an_exactly_tangent_path_touches_at_its_closest_approach_not_later() {
        // A circle of radius 0.25 from (2.25, −2.625) by (−5.625, 7.5) past a rectangle of
        // width 0 from (−0.125, −0.5) to (−0.125, 0.125): the centre's path is tangent to
        // the circle of radius 0.25 round the top end, at t = 29/75 (the quadratic's
        // discriminant is exactly 0). The swept pair test answers by rounding for every
        // time past that; the time reported is the touch.
        let c = hit(
            circle(2.25, -2.625, 0.25),
            Vec2::new(-5.625, 7.5),
            rect(-0.125, -0.5, -0.125, 0.125),
        );
        assert!((c.t - 29.0 / 75.0).abs() < 1e-4, "{c:?}");
        let centre = Vec2::new(2.25, -2.625) + Vec2::new(-5.625, 7.5) * c.t;
        let top = Vec2::new(-0.125, 0.125);
        assert!((centre.distance(top) - 0.25).abs() < 1e-4, "{c:?}");
        assert!(c.point.distance(top) < 1e-4, "{c:?}");
    }

    #[cfg(feature = "aim")]
    #[test]
    fn a_turned_rect_and_a_capsule_touch_at_the_hand_computed_time() {
        // A square of half side 1 turned 45° (a diamond, corners 1.414 from its centre on
        // the axes) moving right into a box whose left side is at x = 5: its right corner
        // gets there when the centre is at 5 − √2.
        let diamond = Placed::Turned {
            center: Vec2::ZERO,
            axis: Vec2::ONE.normalize(),
            half: Vec2::ONE,
        };
        let c = hit(diamond, Vec2::new(10.0, 0.0), rect(5.0, -1.0, 6.0, 1.0));
        assert!((c.t - (5.0 - 2f32.sqrt()) / 10.0).abs() < 1e-6, "{c:?}");
        assert!(c.point.distance(Vec2::new(5.0, 0.0)) < 1e-5, "{c:?}");
        // A capsule lying along x, radius 0.25, falling 4 onto a circle of radius 0.25
        // whose centre is 2 below its segment: the gap of 1.5 closes at t = 0.375, at the
        // middle of the line between the segment and the circle's centre.
        let blade = Placed::Capsule {
            a: Vec2::new(-1.0, 2.0),
            b: Vec2::new(1.0, 2.0),
            radius: 0.25,
        };
        let c = hit(blade, Vec2::new(0.0, -4.0), circle(0.5, 0.0, 0.25));
        assert_eq!(c.t, 0.375);
        assert_eq!(c.point, Vec2::new(0.5, 0.25));
    }
}
