use glam::Vec2;

use super::Segment;

/// A ray as a finite segment of motion: from `origin` to `origin + delta`.
///
/// Queries report positions along it as `t` in `[0, 1]`: `t = 0` is the origin, `t = 1`
/// the end point.
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
/// - a zero-length ray or a zero-length segment never hits (the denominator is zero).
///
/// ```
/// # use tileslide::{cast_ray_segment, Ray, Segment, Vec2};
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
    let (t, s) = solve(ray.origin, ray.delta, segment.a, e)?;
    Some(RaySegmentHit { t, s })
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
