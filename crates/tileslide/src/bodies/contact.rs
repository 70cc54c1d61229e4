//! One contact of a moving circle: the sweeps against a wall and against another circle,
//! with the gap band and the graze rule, and the slide of the blocked remainder off it.
//!
//! The sweeps are the exact pair sweeps (`circle_circle`, `Capsule::sweep_ordinary`) of a
//! circle grown to its contact radius; the rules here are what the resolver adds to them so
//! that rounding never snags a body (see `resolver` and `docs/resolver.md`).

use glam::Vec2;

use super::config::SlideMode;
use crate::geometry::{SweepHit, circle_circle};
use crate::query::Capsule;

/// Relative size below which the remainder's projection on the tangent counts as zero (the
/// write-up's `EPS`, relative to the remainder's length for `f32`).
const TIE_EPSILON: f32 = 1e-5;

/// Largest lean into a round obstacle (another circle, a wall's rounded end) that a move
/// starting within its contact radius may have and still count as running along the
/// contact tangent, as a fraction of the move's length (see `grazes`). The slide off such a
/// contact leans by rounding, about 1e-7 of its length; and a move leaning in by `ε` brings
/// the centres at most `ε²/2` of their distance closer, far below a float's spacing.
const TANGENT_EPSILON: f32 = 1e-5;

/// How far a slide along a wall that leans into it by rounding is lifted off it, as a
/// fraction of the slide's length (see `slide`): ten times the rounding noise.
const SLIDE_LIFT: f32 = 1e-6;

/// What a sweep stopped at.
#[derive(Clone, Copy, Debug)]
pub(super) enum Obstacle {
    /// A wall: met on its flat side, or at a rounded end; by the body's circle `circle`
    /// (from its first), and found at `wall` in that circle's list of near walls.
    Wall { flat: bool, circle: u32, wall: u32 },
    /// Another body, by work index.
    Body(u32),
}

/// The contact radius for a circle whose centre is at squared distance `distance2` from an
/// obstacle it touches at `radius`: `radius + gap` from outside that band, `radius + gap / 2`
/// from inside it (so a body in the band may still close in a little: no snag on rounding).
pub(super) fn band(distance2: f32, radius: f32, gap: f32) -> f32 {
    if distance2 > (radius + gap) * (radius + gap) {
        radius + gap
    } else {
        radius + 0.5 * gap
    }
}

/// Whether `hit` is the start of a move by `motion` from within the contact radius of a
/// round obstacle that only runs along it: the contact normal, which is then the direction
/// between the centres, and the move are perpendicular to within [`TANGENT_EPSILON`].
///
/// The slide off a contact met at `t = 0` is perpendicular to its normal, but only to
/// within rounding (the normal is rounded when normalized): the exact sweep
/// (`sweep_circle_circle`) counts any move with a negative projection on the centres'
/// direction as an approach, and for about half the slides the projection rounds negative.
/// Such a slide would be blocked at `t = 0` by the very contact it slides off, on every pass,
/// and the body would not move at all. A move this close to the tangent cannot come closer
/// than `1 − TANGENT_EPSILON²/2` of the centres' distance anywhere along it, so it is not a
/// contact. Only for round obstacles: along a flat side a lean adds up with the length of
/// the move, so the same tolerance would let a body creep into the wall.
pub(super) fn grazes(hit: SweepHit, motion: Vec2) -> bool {
    hit.t == 0.0 && hit.normal.dot(motion) >= -TANGENT_EPSILON * motion.length()
}

/// The first contact of a circle of contact radius `radius` at `center` moving by `motion`
/// with `wall`: the exact sweep, without the rounded ends the move only grazes.
pub(super) fn sweep_wall(
    wall: &Capsule,
    center: Vec2,
    radius: f32,
    motion: Vec2,
) -> Option<SweepHit> {
    let hit = wall.sweep_ordinary(center, radius, motion)?;
    // The flat side reports the wall's own normal; any other comes from a rounded end (a
    // shortcut only: the sweep below would return the flat hit unchanged).
    if hit.normal == wall.normal || !grazes(hit, motion) {
        return Some(hit);
    }
    // A rounded end only grazed from within its radius is not a contact, but the flat side
    // or the other end may still be met further on: sweep again without the ends the move
    // only grazes.
    let mut caps = wall.caps;
    for (cap, end) in caps.iter_mut().zip([wall.segment.a, wall.segment.b]) {
        *cap &= !circle_circle(center - end, motion, radius)
            .is_some_and(|end_hit| grazes(end_hit, motion));
    }
    Capsule { caps, ..*wall }.sweep_ordinary(center, radius, motion)
}

/// The first contact of a circle at `center` moving by `motion` with a still circle at
/// `other`, their contact radius (the radii's sum, and the band) `radius`: the exact sweep,
/// unless the move only grazes it.
pub(super) fn sweep_circle(
    center: Vec2,
    motion: Vec2,
    other: Vec2,
    radius: f32,
) -> Option<SweepHit> {
    circle_circle(center - other, motion, radius).filter(|&hit| !grazes(hit, motion))
}

/// The write-up's response: the blocked remainder redirected along the contact tangent, to
/// the side its projection points. For two bodies meeting exactly head-on (projection
/// zero) the one with the lower slot turns one way and the other the opposite way; a body
/// running straight into a wall stops.
pub(super) fn slide(
    blocked: Vec2,
    normal: Vec2,
    obstacle: Obstacle,
    me: u32,
    mode: SlideMode,
) -> Vec2 {
    let length = blocked.length();
    // The tangent of the write-up: `perp(d)` with `d` from the higher slot's centre to the
    // lower's, so both bodies of a pair use the same tangent.
    let perp = Vec2::new(normal.y, -normal.x);
    let eps = TIE_EPSILON * length;
    let (tangent, along) = match obstacle {
        Obstacle::Wall { .. } => {
            let u = blocked.dot(perp);
            if u.abs() <= eps {
                return Vec2::ZERO;
            }
            (if u < 0.0 { -perp } else { perp }, u.abs())
        }
        Obstacle::Body(other) => {
            // Which way is a coin toss (slot order, and the side of the centre line the
            // remainder points to): negated by flipping the sign bit, without a branch
            // (the same bits as `-perp`, `eps`, `-t`).
            let lower = flip_if(me >= other);
            let t = Vec2::new(lower(perp.x), lower(perp.y));
            let u = blocked.dot(t);
            let threshold = lower(-eps);
            let away = flip_if(u < threshold);
            (Vec2::new(away(t.x), away(t.y)), u.abs())
        }
    };
    let slid = match mode {
        SlideMode::FullLength => tangent * length,
        SlideMode::Tangential => tangent * along,
        SlideMode::Stop => return Vec2::ZERO,
    };
    // Along a wall the tangent is perpendicular to the normal, but the slide's components
    // are rounded one by one, so its projection on the normal is rounding noise, about 1e-7
    // of its length (exactly zero only for axis-aligned and 45° walls). From inside the gap
    // band a slide that leans in by that noise is an approach at `t = 0`: it would be
    // blocked by the wall it slides along, on every pass. Lifted off the wall by
    // `SLIDE_LIFT` of its length instead, it slides; the lift only ever moves the body away
    // from the wall, so unlike a tolerance in the sweep it cannot add up into it. (Only on
    // the flat side: a slide off a rounded end is a round obstacle's, which `grazes` lets
    // through.)
    let lean = slid.dot(normal);
    if matches!(obstacle, Obstacle::Wall { flat: true, .. }) && lean < 0.0 {
        slid + normal * (SLIDE_LIFT * slid.length())
    } else {
        slid
    }
}

/// Whether a remainder `blocked` meets a contact with `normal` head-on: its projection on the
/// tangent is within [`TIE_EPSILON`] of its length, the test `slide` makes (a wall then
/// stops the body; two bodies take the tie-break).
pub(super) fn is_head_on(blocked: Vec2, normal: Vec2) -> bool {
    let perp = Vec2::new(normal.y, -normal.x);
    blocked.dot(perp).abs() <= TIE_EPSILON * blocked.length()
}

/// Negation when `yes`, by flipping the sign bit with an integer mask: the same bits as
/// `-x`, with no branch for a condition the predictor cannot guess.
fn flip_if(yes: bool) -> impl Fn(f32) -> f32 {
    let mask = u32::from(yes) << 31;
    move |x| f32::from_bits(x.to_bits() ^ mask)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn head_on_bodies_turn_opposite_ways() {
        // Body 0 moving +x meets body 1 moving −x: normals are opposite, remainders too.
        let n0 = Vec2::new(-1.0, 0.0); // from body 1 towards body 0
        let s0 = slide(
            Vec2::new(1.0, 0.0),
            n0,
            Obstacle::Body(1),
            0,
            SlideMode::FullLength,
        );
        let s1 = slide(
            Vec2::new(-1.0, 0.0),
            -n0,
            Obstacle::Body(0),
            1,
            SlideMode::FullLength,
        );
        assert_eq!(s0.length(), 1.0);
        assert_eq!(s0, -s1, "the two bodies must slide in opposite directions");
        assert_eq!(s0.x, 0.0);
    }

    #[test]
    fn slides_follow_the_projection_and_walls_stop_head_on_moves() {
        let up = Vec2::new(0.0, 1.0);
        // Leaning right against a floor: slides right, full length or tangential part.
        let blocked = Vec2::new(0.6, -0.8);
        assert_eq!(
            slide(
                blocked,
                up,
                Obstacle::Wall {
                    flat: true,
                    circle: 0,
                    wall: 0,
                },
                0,
                SlideMode::FullLength
            ),
            Vec2::new(1.0, 0.0)
        );
        let t = slide(
            blocked,
            up,
            Obstacle::Wall {
                flat: true,
                circle: 0,
                wall: 0,
            },
            0,
            SlideMode::Tangential,
        );
        assert!((t - Vec2::new(0.6, 0.0)).length() < 1e-6);
        assert_eq!(
            slide(
                blocked,
                up,
                Obstacle::Wall {
                    flat: true,
                    circle: 0,
                    wall: 0,
                },
                0,
                SlideMode::Stop
            ),
            Vec2::ZERO
        );
        assert_eq!(
            slide(
                Vec2::new(0.0, -1.0),
                up,
                Obstacle::Wall {
                    flat: true,
                    circle: 0,
                    wall: 0,
                },
                0,
                SlideMode::FullLength
            ),
            Vec2::ZERO
        );
    }

    #[test]
    fn the_contact_band_lets_bodies_close_in_but_never_touch() {
        assert_eq!(band(1.0, 0.5, 0.01), 0.51);
        assert_eq!(band(0.505 * 0.505, 0.5, 0.01), 0.505);
        assert!(band(0.09, 0.5, 0.01) > 0.5);
    }
}
