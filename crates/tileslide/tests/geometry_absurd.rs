//! Proves that the public pair primitives answer every finite input, however absurd: the
//! problem (offsets, motion, radii, half extents, the segment) at any scale from 2⁻¹⁴⁰ to
//! 2¹²⁴ and shifted anywhere up to 2¹²⁵, and motions up to `f32::MAX`. For each of
//! `sweep_circle_circle`, `sweep_circle_segment`, `sweep_box_segment` and
//! `cast_ray_segment`: `t` is never NaN and lies in `[0, 1]`, and a motion that truly
//! crosses the obstacle's face (decided in `f64` on the very `f32` inputs, with a margin) is
//! reported as a hit at the `f64` reference's `t`; a circle that clearly misses a circle is
//! reported as a miss.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use glam::DVec2;
use proptest::prelude::*;
use tileslide::{
    Ray, Segment, Vec2, geometry::EndCaps, geometry::SweepHit, geometry::cast_ray_segment,
    geometry::sweep_box_segment, geometry::sweep_circle_circle, geometry::sweep_circle_segment,
};

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

fn pow2(k: i32) -> f32 {
    2f64.powi(k) as f32
}

/// The problem's scale: a power of two from 2⁻¹⁴⁰ to 2¹²⁴ (so a motion of 8 of it stays
/// finite).
fn scale() -> impl Strategy<Value = f32> {
    (-140i32..=124).prop_map(pow2)
}

/// Where the problem lies: at 0, near it (up to 2²⁴ times its scale away, so that its
/// offsets keep some bits), or anywhere up to 2¹²⁵ in each coordinate.
fn shift(scale: f32) -> impl Strategy<Value = Vec2> {
    let near = 2f64.powi(24).min(2f64.powi(125) / f64::from(scale));
    prop_oneof![
        Just(Vec2::ZERO),
        (-near..near, -near..near)
            .prop_map(move |(x, y)| (DVec2::new(x, y) * f64::from(scale)).as_vec2()),
        (-140i32..=125, -1.0f32..1.0, -1.0f32..1.0).prop_map(|(k, x, y)| v(x, y) * pow2(k)),
    ]
}

/// A segment direction: an axis (as tile faces are) or any angle.
fn direction() -> impl Strategy<Value = Vec2> {
    prop_oneof![
        prop_oneof![Just(Vec2::X), Just(Vec2::Y), Just(-Vec2::X), Just(-Vec2::Y)],
        (0.0f32..std::f32::consts::TAU).prop_map(|a| v(a.cos(), a.sin())),
    ]
}

/// A segment of length 1 to 4 times `scale` from `shift + scale·a0`, and its unit normal
/// (the left perpendicular, computed in `f64`: in `f32` its squared length may overflow).
fn segment(shift: Vec2, scale: f32, a0: Vec2, dir: Vec2, len: f32) -> (Segment, Vec2) {
    let a = shift + a0 * scale;
    let b = a + dir * (len * scale);
    let e = b.as_dvec2() - a.as_dvec2();
    let normal = e.perp().normalize().as_vec2();
    (Segment::new(a, b), normal)
}

/// The point `along` the direction `dir` and `height` along its left perpendicular (a
/// segment's normal): most centres start in front of the segment.
fn in_frame(dir: Vec2, (along, height): (f32, f32)) -> Vec2 {
    dir * along + dir.perp() * height
}

/// What holds for every answer: `t` in `[0, 1]`, a finite unit normal.
fn sane(hit: Option<SweepHit>) -> Result<(), TestCaseError> {
    if let Some(h) = hit {
        prop_assert!((0.0..=1.0).contains(&h.t), "t {:?}", h);
        prop_assert!(h.normal.is_finite(), "normal {:?}", h);
        prop_assert!((h.normal.length() - 1.0).abs() < 1e-5, "normal {:?}", h);
    }
    Ok(())
}

/// A hit expected at `t_ref`.
fn hit_at(hit: Option<SweepHit>, t_ref: f64, what: &str) -> Result<(), TestCaseError> {
    let Some(h) = hit else {
        return Err(TestCaseError::fail(format!(
            "{what}: no hit, reference t {t_ref}"
        )));
    };
    prop_assert!(
        (f64::from(h.t) - t_ref).abs() <= 1e-3,
        "{}: {:?}, reference t {}",
        what,
        h,
        t_ref
    );
    Ok(())
}

/// When a move by `m` from height `h0` above a line (along its unit normal `n`) first comes
/// within `reach` of it, and where along the segment from `p` (relative to its start, of
/// direction `e`) that happens, as a fraction of its length: `None` unless it approaches.
fn face_reference(p: DVec2, m: DVec2, e: DVec2, n: DVec2, reach: f64) -> Option<(f64, f64)> {
    let (h0, vn) = (p.dot(n), m.dot(n));
    if vn >= 0.0 {
        return None;
    }
    let t = (h0 - reach) / -vn;
    let s = (p + m * t).dot(e) / e.length_squared();
    Some((t, s))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// Two circles: a clear approach to within 0.9 of the radius sum, starting at least 1.1
    /// radius sums apart, is a hit at the `f64` time of contact; a path that stays beyond
    /// 1.1 radius sums, or reaches contact only after `t = 1.01`, is a miss.
    #[test]
    fn circle_sweep_of_any_finite_size_matches_the_f64_reference(
        (s, at) in scale().prop_flat_map(|s| (Just(s), shift(s))),
        d0 in (-4.0f32..4.0, -4.0f32..4.0), m0 in (-8.0f32..8.0, -8.0f32..8.0),
        r0 in 0.05f32..2.0,
    ) {
        let other = at;
        let center = at + v(d0.0, d0.1) * s;
        let (motion, radius) = (v(m0.0, m0.1) * s, r0 * s);
        let hit = sweep_circle_circle(center, motion, other, radius);
        sane(hit)?;
        let (d, m, r) = (center.as_dvec2() - other.as_dvec2(), motion.as_dvec2(), f64::from(radius));
        let (a, b, c) = (m.length_squared(), d.dot(m), d.length_squared() - r * r);
        prop_assume!(a > 0.0 && c > 0.21 * r * r);
        if b >= 0.0 {
            prop_assert!(hit.is_none(), "moving away: {:?}", hit);
            return Ok(());
        }
        let closest2 = d.length_squared() - b * b / a;
        let disc = b * b - a * c;
        let t_ref = if disc > 0.0 { c / (-b + disc.sqrt()) } else { f64::INFINITY };
        if closest2 < 0.81 * r * r && t_ref <= 0.99 {
            hit_at(hit, t_ref, "circle")?;
        } else if closest2 > 1.21 * r * r || t_ref > 1.01 {
            prop_assert!(hit.is_none(), "clear miss (t {}): {:?}", t_ref, hit);
        }
    }

    /// A circle against a segment: a move that reaches the line at `radius` over the
    /// segment's middle 90 %, from at least 1.2 radii in front, is a hit at that time.
    #[test]
    fn circle_segment_sweep_of_any_finite_size_crosses_no_face(
        (s, at) in scale().prop_flat_map(|s| (Just(s), shift(s))), dir in direction(), len in 1.0f32..4.0,
        c0 in (-2.0f32..6.0, -1.0f32..4.0), m0 in (-8.0f32..8.0, -8.0f32..8.0),
        r0 in 0.01f32..0.5, caps in any::<[bool; 2]>(),
    ) {
        let (seg, normal) = segment(at, s, Vec2::ZERO, dir, len);
        let center = seg.a + in_frame(dir, c0) * s;
        let (motion, radius) = (v(m0.0, m0.1) * s, r0 * s);
        let caps = EndCaps { a: caps[0], b: caps[1] };
        let hit = sweep_circle_segment(center, radius, motion, &seg, normal, caps);
        sane(hit)?;
        let p = center.as_dvec2() - seg.a.as_dvec2();
        let e = seg.b.as_dvec2() - seg.a.as_dvec2();
        let (n, r) = (normal.as_dvec2(), f64::from(radius));
        if p.dot(n) <= 1.2 * r {
            // Not clearly in front (a shift far beyond the scale rounds most centres
            // onto the line): only the sanity above applies.
            return Ok(());
        }
        if let Some((t_ref, along)) = face_reference(p, motion.as_dvec2(), e, n, r)
            && t_ref <= 0.99 && (0.05..=0.95).contains(&along)
        {
            hit_at(hit, t_ref, "circle on segment")?;
        }
    }

    /// A box against a segment: a move whose box reaches the line with the middle of its
    /// lowest feature (corner, or side for an axis-aligned face) over the segment's middle
    /// 90 %, from clearly in front, is a hit at that time.
    #[test]
    fn box_segment_sweep_of_any_finite_size_crosses_no_face(
        (s, at) in scale().prop_flat_map(|s| (Just(s), shift(s))), dir in direction(), len in 1.0f32..4.0,
        c0 in (-2.0f32..6.0, -1.0f32..4.0), m0 in (-8.0f32..8.0, -8.0f32..8.0),
        h0 in (0.01f32..0.5, 0.01f32..0.5), caps in any::<[bool; 2]>(),
    ) {
        let (seg, normal) = segment(at, s, Vec2::ZERO, dir, len);
        let center = seg.a + in_frame(dir, c0) * s;
        let (motion, half) = (v(m0.0, m0.1) * s, v(h0.0, h0.1) * s);
        let caps = EndCaps { a: caps[0], b: caps[1] };
        let hit = sweep_box_segment(center, half, motion, &seg, normal, caps);
        sane(hit)?;
        let p = center.as_dvec2() - seg.a.as_dvec2();
        let e = seg.b.as_dvec2() - seg.a.as_dvec2();
        let (n, h) = (normal.as_dvec2(), half.as_dvec2());
        let support = h.x * n.x.abs() + h.y * n.y.abs();
        if p.dot(n) <= support + 0.05 * f64::from(s) {
            return Ok(());
        }
        // The middle of the lowest feature, relative to the centre.
        let low = DVec2::new(
            if n.x == 0.0 { 0.0 } else { -h.x.copysign(n.x) },
            if n.y == 0.0 { 0.0 } else { -h.y.copysign(n.y) },
        );
        if let Some((t_ref, along)) = face_reference(p + low, motion.as_dvec2(), e, n, 0.0)
            && t_ref <= 0.99 && (0.05..=0.95).contains(&along)
        {
            hit_at(hit, t_ref, "box on segment")?;
        }
    }

    /// A ray against a segment: a crossing well inside both, at an angle, is a hit at the
    /// `f64` reference's `t` and `s`.
    #[test]
    fn ray_segment_test_of_any_finite_size_matches_the_f64_reference(
        (s, at) in scale().prop_flat_map(|s| (Just(s), shift(s))), dir in direction(), len in 1.0f32..4.0,
        o0 in (-4.0f32..4.0, -4.0f32..4.0), d0 in (-8.0f32..8.0, -8.0f32..8.0),
    ) {
        let (seg, _) = segment(at, s, Vec2::ZERO, dir, len);
        let ray = Ray { origin: seg.a + v(o0.0, o0.1) * s, delta: v(d0.0, d0.1) * s };
        let hit = cast_ray_segment(&ray, &seg);
        if let Some(h) = hit {
            prop_assert!((0.0..=1.0).contains(&h.t) && (0.0..=1.0).contains(&h.s), "{:?}", h);
        }
        let (d, e) = (ray.delta.as_dvec2(), seg.b.as_dvec2() - seg.a.as_dvec2());
        let w = seg.a.as_dvec2() - ray.origin.as_dvec2();
        let den = d.perp_dot(e);
        prop_assume!(den.abs() > 0.05 * d.length() * e.length());
        let (t_ref, s_ref) = (w.perp_dot(e) / den, w.perp_dot(d) / den);
        if (0.01..=0.99).contains(&t_ref) && (0.01..=0.99).contains(&s_ref) {
            let h = hit.ok_or_else(|| TestCaseError::fail(format!("no hit, t {t_ref}")))?;
            prop_assert!((f64::from(h.t) - t_ref).abs() <= 1e-3, "{:?}, t {}", h, t_ref);
            prop_assert!((f64::from(h.s) - s_ref).abs() <= 1e-3, "{:?}, s {}", h, s_ref);
        }
    }
}

#[test]
fn motions_up_to_f32_max_meet_what_they_cross() {
    // A motion of f32::MAX towards a floor 1e38 below: |motion|² overflowed to infinity
    // and the circle–circle quadratic returned NaN or a miss.
    let floor = Segment::new(v(-1e38, 0.0), v(1e38, 0.0));
    let center = v(0.0, 1e38);
    let motion = v(0.0, -f32::MAX);
    let hit = sweep_circle_segment(center, 1.0, motion, &floor, Vec2::Y, EndCaps::BOTH).unwrap();
    assert!((hit.t - 1e38 / f32::MAX).abs() < 1e-6, "{hit:?}");
    let hit =
        sweep_box_segment(center, v(1.0, 1.0), motion, &floor, Vec2::Y, EndCaps::BOTH).unwrap();
    assert!((hit.t - 1e38 / f32::MAX).abs() < 1e-6, "{hit:?}");
    // Circles f32::MAX apart, one moving the whole way to the other.
    let hit = sweep_circle_circle(
        v(-f32::MAX / 2.0, 0.0),
        v(f32::MAX, 0.0),
        v(f32::MAX / 2.0, 0.0),
        1e37,
    )
    .unwrap();
    assert!((hit.t - (1.0 - 1e37 / f32::MAX)).abs() < 1e-6, "{hit:?}");
    assert!((hit.normal - v(-1.0, 0.0)).length() < 1e-6, "{hit:?}");
    // A problem 1e-30 across: every square underflowed to 0, and the floor had no length.
    let tiny = Segment::new(v(-2e-30, 0.0), v(2e-30, 0.0));
    let hit = sweep_circle_segment(
        v(0.0, 3e-30),
        1e-30,
        v(0.0, -4e-30),
        &tiny,
        Vec2::Y,
        EndCaps::BOTH,
    )
    .unwrap();
    assert!((hit.t - 0.5).abs() < 1e-5, "{hit:?}");
    let hit = sweep_circle_circle(v(0.0, 3e-30), v(0.0, -4e-30), Vec2::ZERO, 1e-30).unwrap();
    assert!((hit.t - 0.5).abs() < 1e-5, "{hit:?}");
}
