//! The exact time of impact the resolver uses against the write-up's bisection, which this
//! file keeps for the comparison: the exact method is never worse.
//!
//! The write-up ("Simple sphere-based collision detection and response") finds a move's time
//! of impact by sampling: it checks the end of the move and, if the circle overlaps
//! something there, halves towards the contact a few times (4 in the write-up), keeping the
//! last clear sample. So it only sees sampled positions: a move whose end is clear passes
//! through anything on the way, and where it does stop it stops up to `2^-halvings` of the
//! move short of the contact. The exact sweeps (`sweep_circle_circle`,
//! `sweep_circle_segment`) solve for the contact in closed form.
//!
//! For random moves of a circle against a circle and against a wall (a segment's capsule,
//! front side only, as the resolver's walls), each checked against a brute-force walk of the
//! path: the exact sweep stops wherever the path first enters the obstacle, never later and
//! never inside it, and never before the bisection's stop; the bisection misses contacts the
//! exact sweep finds.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use proptest::prelude::*;
use tileslide::{
    Segment, Vec2, geometry::EndCaps, geometry::SweepHit, geometry::sweep_circle_circle,
    geometry::sweep_circle_segment,
};

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

/// The write-up's time of impact by bisection: the last of `halvings` probes at which
/// `overlaps(t)` is false, after first checking `t = 1`; `None` when the end of the move is
/// clear.
fn bisect(halvings: u32, overlaps: impl Fn(f32) -> bool) -> Option<f32> {
    let mut hit = overlaps(1.0);
    if !hit {
        return None;
    }
    let (mut t, mut best) = (1.0f32, 0.0f32);
    let mut piece = 1.0f32;
    for _ in 0..halvings {
        piece *= 0.5;
        t += if hit { -piece } else { piece };
        hit = overlaps(t);
        if !hit {
            best = t;
        }
    }
    Some(best)
}

/// How deep (as a fraction of the radius) a sample must be inside an obstacle to count as
/// overlapping it, and how far (in map units) the exact contact may be off: rounding.
const DEPTH: f32 = 1e-3;
const SLACK: f32 = 1e-3;

/// Samples of the brute-force walk along a move.
const SAMPLES: usize = 4096;

/// Checks one move against one obstacle: `depth(p)` is how far a circle centred at `p` is
/// inside the obstacle (negative when clear), `exact` the exact sweep's answer.
fn compare(
    start: Vec2,
    motion: Vec2,
    radius: f32,
    halvings: u32,
    depth: impl Fn(Vec2) -> f32,
    exact: Option<SweepHit>,
) -> Result<(), TestCaseError> {
    let at = |t: f32| start + motion * t;
    let length = motion.length();
    // The brute force: where the walk first goes clearly inside.
    let first = (0..=SAMPLES)
        .map(|i| i as f32 / SAMPLES as f32)
        .find(|&t| depth(at(t)) > DEPTH * radius);
    if let Some(t) = first {
        let hit = exact.ok_or_else(|| TestCaseError::fail(format!("missed; inside at t = {t}")))?;
        prop_assert!(hit.t <= t, "exact t = {} after the overlap at {}", hit.t, t);
    }
    if let Some(hit) = exact {
        // At its contact the circle touches the obstacle: not inside, not short of it.
        let d = depth(at(hit.t));
        prop_assert!(d.abs() <= SLACK, "depth {} at the exact t = {}", d, hit.t);
    }
    let bisection = bisect(halvings, |t| depth(at(t)) > 0.0);
    if let Some(t) = bisection {
        // Bisection stops where the exact sweep stops or short of it, never past it.
        let hit = exact.ok_or_else(|| TestCaseError::fail(format!("bisection hit at {t}")))?;
        prop_assert!(
            length * (t - hit.t) <= SLACK,
            "bisection {} past the exact t = {}",
            t,
            hit.t
        );
    }
    Ok(())
}

fn point() -> impl Strategy<Value = Vec2> {
    (-10.0f32..10.0, -10.0f32..10.0).prop_map(|(x, y)| v(x, y))
}

/// A point near the path from `start` by `motion`, or near where it ends: from `t` along it
/// (to 1.25), off it by `off` (up to 2.5 each way).
fn near_path(start: Vec2, motion: Vec2, t: f32, off: Vec2) -> Vec2 {
    start + motion * t + off * 0.25
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn against_a_circle_the_exact_sweep_is_never_worse_than_bisection(
        start in point(),
        motion in point(),
        (t, off) in (0.0f32..1.25, point()),
        radius in 0.05f32..2.0,
        halvings in 0u32..12,
    ) {
        let other = near_path(start, motion, t, off);
        // Moves that start clear, as the write-up's do.
        prop_assume!(start.distance(other) > radius + SLACK);
        let depth = |p: Vec2| radius - p.distance(other);
        let exact = sweep_circle_circle(start, motion, other, radius);
        compare(start, motion, radius, halvings, depth, exact)?;
    }

    #[test]
    fn against_a_wall_the_exact_sweep_is_never_worse_than_bisection(
        start in point(),
        motion in point(),
        (t, off) in (0.0f32..1.25, point()),
        b in point(),
        radius in 0.05f32..2.0,
        halvings in 0u32..12,
    ) {
        let a = near_path(start, motion, t, off);
        prop_assume!(a.distance(b) > 0.1);
        let wall = Segment::new(a, b);
        // The wall faces the start: moves come from its front (from behind, it lets them by).
        let across = (b - a).perp().normalize();
        let normal = if (start - a).dot(across) >= 0.0 { across } else { -across };
        // Inside means within the radius of the segment and on its front side, where the
        // write-up's bisection looks too.
        let depth = |p: Vec2| {
            let front = (p - a).dot(normal);
            (radius - wall.distance_squared_to(p).sqrt()).min(front)
        };
        prop_assume!(depth(start) < -SLACK);
        let exact = sweep_circle_segment(start, radius, motion, &wall, normal, EndCaps::BOTH);
        compare(start, motion, radius, halvings, depth, exact)?;
    }
}

/// The write-up's bisection passes through a one-cell wall when the move ends beyond it;
/// the exact sweep stops at the wall. Where bisection does stop, it stops short.
#[test]
fn bisection_passes_through_a_thin_wall_that_the_exact_sweep_stops_at() {
    // The wall's left face, x = 4 facing left; its right face is at x = 5.
    let face = Segment::new(v(4.0, 0.0), v(4.0, 3.0));
    let (normal, radius) = (v(-1.0, 0.0), 0.3);
    let inside = |p: Vec2| {
        (p.x <= 4.0 && face.distance_squared_to(p) < radius * radius) || (p.x > 4.0 && p.x < 5.3)
    };
    let start = v(2.0, 1.5);
    // A move to x = 6: clear at its end, so the bisection sees nothing.
    let through = v(4.0, 0.0);
    assert_eq!(bisect(4, |t| inside(start + through * t)), None);
    let hit = sweep_circle_segment(start, radius, through, &face, normal, EndCaps::BOTH).unwrap();
    assert!((start + through * hit.t).x <= 4.0 - radius + 1e-6);
    // A move to x = 4, into the wall: the bisection stops up to 1/16 of the move short.
    let into = v(2.0, 0.0);
    let t = bisect(4, |t| inside(start + into * t)).unwrap();
    let hit = sweep_circle_segment(start, radius, into, &face, normal, EndCaps::BOTH).unwrap();
    assert!(
        t <= hit.t && hit.t - t <= 1.0 / 16.0,
        "bisection {t}, exact {}",
        hit.t
    );
    assert!(hit.t - t > 0.01, "the bisection stopped at the contact");
}
