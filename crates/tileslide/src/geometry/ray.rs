use glam::Vec2;

use super::Segment;

/// A ray as a finite segment of motion: from `origin` to `origin + delta`.
///
/// Queries report positions along it as `t` in `[0, 1]`: `t = 0` is the origin, `t = 1`
/// the end point.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// Where the ray starts (`t = 0`).
    pub origin: Vec2,
    /// The motion from start to end: the end point is `origin + delta` (`t = 1`).
    pub delta: Vec2,
}

impl Ray {
    /// The ray from `p0` to `p1`.
    #[must_use]
    pub fn between(p0: Vec2, p1: Vec2) -> Self {
        Self {
            origin: p0,
            delta: p1 - p0,
        }
    }

    /// The end point, `origin + delta`.
    #[must_use]
    pub fn end(&self) -> Vec2 {
        self.origin + self.delta
    }

    /// The point at `t`.
    #[must_use]
    pub fn point_at(&self, t: f32) -> Vec2 {
        self.origin + self.delta * t
    }

    /// True when origin and delta are finite.
    #[must_use]
    pub fn is_finite(&self) -> bool {
        self.origin.is_finite() && self.delta.is_finite()
    }
}

/// Where a ray meets a segment.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RaySegmentHit {
    /// Fraction along the ray, in `[0, 1]`.
    pub t: f32,
    /// Fraction along the segment from `a` to `b`, in `[0, 1]`.
    pub s: f32,
}

/// Exact intersection of a ray with a closed segment, or `None`.
///
/// Solves `origin + t·delta = a + s·(b − a)` by Cramer's rule (Ericson, *Real-Time Collision
/// Detection*, 5.1.9.1), comparing numerators against the denominator so that no division
/// happens for a miss and `t`, `s` are never rounded outside `[0, 1]`.
///
/// Defined cases:
/// - both ends are closed: a ray that ends exactly on the segment, or touches an end point
///   of it, hits (`t = 1`, or `s` = 0 or 1);
/// - a ray parallel to the segment never hits it, **including a collinear ray running along
///   it**: a surface is only ever met through its face. A ray running along a floor into a
///   wall still hits the wall, whose end point it meets at an angle. "Parallel" means moving
///   across the segment's line by less than [`PARALLEL_TOLERANCE`] segment lengths over
///   the ray's whole length, where the intersection is lost to rounding;
/// - a zero-length ray or a zero-length segment never hits (the denominator is zero), nor
///   does a ray or segment with a NaN or infinite coordinate;
/// - every finite input has an answer: no product can overflow or lose its bits to
///   underflow. Up to `NARROW` (2⁶⁰) in every coordinate of the origin, `delta` and the
///   segment, and while the largest components of `delta` and `b − a` multiply to at least
///   2⁻⁸⁰, the kernel runs in `f32` (its products stay below 2¹²³, and a crossing's
///   denominator stays a normal float); otherwise (a coordinate of 10¹⁹, a ray and segment
///   10⁻²⁵ long) the same rule runs in `f64`, where the product of any two `f32` values is
///   exact, no sum of them overflows and none underflows, and `t`, `s` are rounded to `f32`
///   at the end (so `t` may come out subnormal, or 0 for a hit closer to the origin than
///   2⁻¹⁴⁹ of the ray's length). The map's ray queries run the `f32` kernel on every
///   ordinary ray, so they agree with this function bit for bit on maps whose cells are at
///   least 2⁻²⁴ units.
///
/// ```
/// # use tileslide::geometry::cast_ray_segment;
/// # use tileslide::{Ray, Segment, Vec2};
/// let wall = Segment::new(Vec2::new(2.0, -1.0), Vec2::new(2.0, 1.0));
/// let hit = cast_ray_segment(&Ray::between(Vec2::ZERO, Vec2::new(4.0, 0.0)), &wall).unwrap();
/// assert_eq!(hit.t, 0.5);
/// assert_eq!(hit.s, 0.5);
/// // Running along the wall is not a hit.
/// assert!(cast_ray_segment(&Ray::between(Vec2::new(2.0, -2.0), Vec2::new(2.0, 2.0)), &wall).is_none());
/// ```
#[must_use]
pub fn cast_ray_segment(ray: &Ray, segment: &Segment) -> Option<RaySegmentHit> {
    let e = segment.delta();
    let (t, s) = solve_any(ray.origin, ray.delta, segment.a, e)?;
    Some(RaySegmentHit { t, s })
}

/// The largest coordinate magnitude (2⁶⁰) up to which [`cast_ray_segment`] solves in `f32`:
/// then `a − origin` stays below 2⁶¹ and every cross product below 2¹²³, far from
/// `f32::MAX`.
pub(crate) const NARROW: f32 = 1_152_921_504_606_846_976.0;

/// True when every coordinate of `v` is at most [`NARROW`] in magnitude (false for NaN).
#[inline(always)]
pub(crate) fn narrow(v: Vec2) -> bool {
    v.x.abs() <= NARROW && v.y.abs() <= NARROW
}

/// The smallest product (2⁻⁸⁰) of the largest components of a ray's `delta` and a
/// segment's `e` for which [`cast_ray_segment`] solves in `f32`: below it the denominator
/// `delta × e` of a ray crossing at an angle could be a subnormal float, which keeps too
/// few bits to place `t`.
const TINY: f32 = 1.0 / 1_208_925_819_614_629_174_706_176.0;

/// [`solve`] where every input is [`narrow`] and `delta` and `e` are not [`TINY`] together,
/// [`solve_wide`] otherwise: the kernel `cast_ray_segment` uses.
#[inline]
pub(crate) fn solve_any(origin: Vec2, delta: Vec2, a: Vec2, e: Vec2) -> Option<(f32, f32)> {
    let scale = delta.abs().max_element() * e.abs().max_element();
    if narrow(origin) && narrow(delta) && narrow(a) && narrow(e) && scale >= TINY {
        solve(origin, delta, a, e)
    } else {
        solve_wide(origin, delta, a, e)
    }
}

/// [`solve`]'s rule in `f64`, for inputs whose `f32` products could overflow. The products
/// of two `f32` values are exact in `f64` (48 bits of 53) and at most about 10⁷⁷, so
/// nothing overflows; `t` and `s` are the `f64` quotients rounded to `f32`, which keeps
/// them in `[0, 1]`.
#[inline(never)]
pub(crate) fn solve_wide(origin: Vec2, delta: Vec2, a: Vec2, e: Vec2) -> Option<(f32, f32)> {
    if !(origin.is_finite() && delta.is_finite() && a.is_finite() && e.is_finite()) {
        return None;
    }
    let (origin, delta, a, e) = (
        origin.as_dvec2(),
        delta.as_dvec2(),
        a.as_dvec2(),
        e.as_dvec2(),
    );
    let den = delta.perp_dot(e);
    let w = a - origin;
    let sign = 1.0f64.copysign(den);
    let (den, tn, sn) = (den * sign, w.perp_dot(e) * sign, w.perp_dot(delta) * sign);
    let crossing = den > f64::from(PARALLEL_TOLERANCE) * e.length_squared();
    let inside = crossing && tn >= 0.0 && tn <= den && sn >= 0.0 && sn <= den;
    inside.then(|| ((tn / den) as f32, (sn / den) as f32))
}

/// The shared kernel of every ray–segment test in the crate (the grid walk calls it with
/// precomputed `e = b − a`), so that all ray queries agree bit for bit.
#[inline(always)]
pub(crate) fn solve(origin: Vec2, delta: Vec2, a: Vec2, e: Vec2) -> Option<(f32, f32)> {
    let (inside, tn, sn, den) = solve_parts(origin, delta, a, e);
    if inside {
        Some((tn / den, sn / den))
    } else {
        None
    }
}

/// A ray counts as parallel to a segment when, over its whole length, it moves less than
/// this many segment lengths across the segment's line.
///
/// In exact arithmetic "parallel" means not crossing the line at all. Coordinates rounded
/// to `f32` (a map origin of 0.1, say) turn a ray that runs exactly along a slope into one
/// that crosses it by a hair, and Cramer's rule then puts `t` anywhere. Measuring how far
/// the ray moves across the line, rather than the angle, keeps long shallow rays honest: a
/// ray that really crosses a floor, however long and flat, moves across it by far more
/// than this and hits it.
pub const PARALLEL_TOLERANCE: f32 = 1e-5;

/// Cramer's rule without branches: returns whether the ray hits and the numerators of `t`
/// and `s` over a positive denominator (`t = tn / den`). Branch-free because which way the
/// test goes is a coin toss for the branch predictor on random rays, and a misprediction
/// costs more than the few extra instructions.
#[inline(always)]
pub(crate) fn solve_parts(origin: Vec2, delta: Vec2, a: Vec2, e: Vec2) -> (bool, f32, f32, f32) {
    let den = delta.perp_dot(e);
    let w = a - origin;
    // Make the denominator positive; negating is exact, so t and s are unchanged.
    let sign = 1.0f32.copysign(den);
    let (den, tn, sn) = (den * sign, w.perp_dot(e) * sign, w.perp_dot(delta) * sign);
    // `den / |e| = |delta| sin θ` is how far the ray moves across the segment's line:
    // within `PARALLEL_TOLERANCE` segment lengths it is parallel, and a zero-length ray or
    // segment gives 0: no hit. NaN fails every comparison. (No squares of `den`: a ray of
    // length 1e20 must not overflow to infinity.)
    let crossing = den > PARALLEL_TOLERANCE * e.length_squared();
    let inside = crossing & (tn >= 0.0) & (tn <= den) & (sn >= 0.0) & (sn <= den);
    (inside, tn, sn, den)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f32, y: f32) -> Vec2 {
        Vec2::new(x, y)
    }

    #[test]
    fn crossing_ray_hits_at_exact_fraction() {
        let hit = cast_ray_segment(
            &Ray::between(v(0.0, 0.0), v(4.0, 4.0)),
            &Segment::new(v(0.0, 2.0), v(4.0, 2.0)),
        )
        .unwrap();
        assert_eq!(hit.t, 0.5);
        assert_eq!(hit.s, 0.5);
    }

    #[test]
    fn ray_ending_exactly_on_segment_hits_at_t_one() {
        let hit = cast_ray_segment(
            &Ray::between(v(0.0, 0.0), v(2.0, 0.0)),
            &Segment::new(v(2.0, -1.0), v(2.0, 1.0)),
        )
        .unwrap();
        assert_eq!(hit.t, 1.0);
    }

    #[test]
    fn ray_stopping_short_misses() {
        let hit = cast_ray_segment(
            &Ray::between(v(0.0, 0.0), v(1.999, 0.0)),
            &Segment::new(v(2.0, -1.0), v(2.0, 1.0)),
        );
        assert!(hit.is_none());
    }

    #[test]
    fn ray_through_segment_end_point_hits() {
        let hit = cast_ray_segment(
            &Ray::between(v(0.0, 1.0), v(4.0, 1.0)),
            &Segment::new(v(2.0, -1.0), v(2.0, 1.0)),
        )
        .unwrap();
        assert_eq!(hit.t, 0.5);
        assert_eq!(hit.s, 1.0);
    }

    #[test]
    fn parallel_and_collinear_rays_never_hit() {
        let seg = Segment::new(v(0.0, 0.0), v(2.0, 0.0));
        assert!(cast_ray_segment(&Ray::between(v(-1.0, 1.0), v(3.0, 1.0)), &seg).is_none());
        assert!(cast_ray_segment(&Ray::between(v(-1.0, 0.0), v(3.0, 0.0)), &seg).is_none());
        assert!(cast_ray_segment(&Ray::between(v(0.5, 0.0), v(1.5, 0.0)), &seg).is_none());
    }

    #[test]
    fn ray_along_a_slope_with_rounded_coordinates_does_not_hit_it() {
        // In exact arithmetic the ray runs along the slope x + y = 4.2; rounded to f32 it
        // crosses it at a tiny angle, where Cramer's rule gave t = 0.25 (far from the slope).
        let slope = Segment::new(v(1.1, 3.1), v(2.1, 2.1));
        let ray = Ray {
            origin: v(7.1, -2.9),
            delta: v(-12.0, 12.0),
        };
        assert!(cast_ray_segment(&ray, &slope).is_none());
    }

    #[test]
    fn long_shallow_ray_still_hits_the_floor_it_crosses() {
        // 4000 cells long, crossing y = 1 by 0.02 over that length: sin θ = 5e-6.
        let floor = Segment::new(v(2000.0, 1.0), v(2001.0, 1.0));
        let hit = cast_ray_segment(&Ray::between(v(0.5, 0.99), v(4000.5, 1.01)), &floor).unwrap();
        assert!((hit.t - 0.5).abs() < 1e-3, "{hit:?}");
    }

    #[test]
    fn very_long_ray_still_hits() {
        let wall = Segment::new(v(4.0, 0.0), v(4.0, 3.0));
        for length in [1e19f32, 1e20, 1e30, f32::MAX / 4.0] {
            let ray = Ray {
                origin: v(1.5, 1.5),
                delta: v(length, 0.0),
            };
            let hit = cast_ray_segment(&ray, &wall);
            assert!(hit.is_some(), "length {length}");
        }
    }

    #[test]
    fn far_out_ray_never_reports_nan() {
        // Around 1e27 the f32 products overflowed to infinity, and `tn = den = inf` passed
        // the range test as a hit at t = NaN.
        let wall = Segment::new(v(2.0, 0.0), v(2.0, 3.0));
        for scale in [1e19f32, 1e25, 1e27, 1e30, f32::MAX / 2.0] {
            for (origin, delta) in [
                (v(-scale, 1.0), v(2.0 * scale, 0.0)),
                (v(-scale, -scale), v(2.0 * scale, 2.0 * scale + 3.0)),
                (v(1.0, 1.0), v(scale, scale * 1e-20)),
            ] {
                let hit = cast_ray_segment(&Ray { origin, delta }, &wall);
                if let Some(h) = hit {
                    assert!((0.0..=1.0).contains(&h.t), "{scale}: {h:?}");
                    assert!((0.0..=1.0).contains(&h.s), "{scale}: {h:?}");
                }
            }
            let hit = cast_ray_segment(
                &Ray {
                    origin: v(-scale, 1.0),
                    delta: v(2.0 * scale, 0.0),
                },
                &wall,
            )
            .unwrap();
            assert_eq!(hit.t, 0.5, "{scale}");
        }
        // Past `NARROW` in the segment too (a short ray would be parallel to it: it moves
        // across its line by less than 1e-5 of its length).
        let huge = Segment::new(v(2e30, -1e30), v(2e30, 1e30));
        let hit = cast_ray_segment(&Ray::between(v(0.0, 0.0), v(4e30, 0.0)), &huge).unwrap();
        assert_eq!((hit.t, hit.s), (0.5, 0.5));
    }

    #[test]
    fn wide_kernel_agrees_with_the_narrow_one_where_both_are_exact() {
        // Dyadic inputs whose products are exact in f32 too: both kernels give the same bits.
        for (o, d, a, e) in [
            (v(0.0, 0.0), v(4.0, 4.0), v(0.0, 2.0), v(4.0, 0.0)),
            (v(0.5, 1.0), v(8.0, 0.0), v(2.0, -1.0), v(0.0, 2.0)),
            (v(1.0, 1.0), v(-3.0, 5.0), v(-4.0, 3.0), v(6.0, 1.0)),
        ] {
            assert_eq!(solve(o, d, a, e), solve_wide(o, d, a, e));
        }
    }

    #[test]
    fn grazing_but_not_parallel_ray_still_hits() {
        // sin θ ≈ 1e-3, far above the parallel threshold.
        let floor = Segment::new(v(0.0, 0.0), v(10.0, 0.0));
        let hit = cast_ray_segment(&Ray::between(v(0.0, 0.001), v(10.0, -0.009)), &floor).unwrap();
        assert!((hit.t - 0.1).abs() < 1e-4, "{hit:?}");
    }

    #[test]
    fn zero_length_ray_or_segment_never_hits() {
        let seg = Segment::new(v(0.0, -1.0), v(0.0, 1.0));
        assert!(cast_ray_segment(&Ray::between(v(0.0, 0.0), v(0.0, 0.0)), &seg).is_none());
        let point = Segment::new(v(1.0, 0.0), v(1.0, 0.0));
        assert!(cast_ray_segment(&Ray::between(v(0.0, 0.0), v(2.0, 0.0)), &point).is_none());
    }

    #[test]
    fn nan_input_never_hits() {
        let seg = Segment::new(v(0.0, -1.0), v(0.0, 1.0));
        assert!(cast_ray_segment(&Ray::between(v(f32::NAN, 0.0), v(1.0, 0.0)), &seg).is_none());
    }
}
