//! The second loop of a step: moves checked against each other and the walls at the exact
//! time of impact, the blocked remainder slid along the contact tangent.
//!
//! Bodies are resolved one after another, in slot order (Gauss–Seidel). Each one moves by
//! *collide and slide* against a still picture of everything else: the walls, the bodies
//! already resolved at their new positions, and the others where they stand. It sweeps its
//! move to the first contact (exact time of impact), keeps that part, redirects the blocked
//! remainder along the contact tangent (the write-up's slide and tie-break), and sweeps
//! again, up to `passes` times; a remainder still blocked after that is cut at its first
//! contact. Every sweep is exact against obstacles that do not move while it runs, so:
//!
//! - no pair overlaps afterwards: a pair's later-resolved body checked its whole path
//!   against the other's final position, and the earlier one against the later one's start;
//! - nothing crosses a wall front at any speed, whatever the passes;
//! - a body without a move never moves; the result depends only on the inputs and the slot
//!   order, so identical inputs give bit-identical positions.
//!
//! Moving bodies keep a small gap (see [`ResolveConfig::gap`]) from what they touch: a sweep
//! stops at the radius plus the gap, and a body already inside that band may still close in
//! to half the gap. So rounding never leaves anything overlapping, and a circle sliding along
//! a wall with a remainder that leans into it by a rounding error is not stopped ("snag").
//! Against a round obstacle (another body, a wall's rounded end) a body already inside the
//! band is still free to move along the contact tangent, to within rounding: that is where
//! its slide goes, and taking rounding for an approach would block the slide at `t = 0` on
//! every pass (see `grazes`).

use glam::Vec2;

use super::body::BodyFilter;
use super::config::{ResolveConfig, SlideMode, TimeOfImpact};
use super::map_watch::{MapChange, MapWatch};
use super::near_walls::NearWalls;
use super::neighbours::Neighbours;
use super::set::Body;
use super::settled::Settled;
use crate::geometry::{Aabb, Circle, SweepHit, bisect, circle_circle, in_range};
use crate::query::Capsule;
use crate::tiles::TileMap;

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

/// Shortest safe part of a move that is taken, as a fraction of the gap (see
/// `collide_and_slide`).
const MIN_STEP: f32 = 0.125;

/// What a `resolve` did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ResolveReport {
    /// Bodies with a non-zero proposed move.
    pub moving: usize,
    /// Contacts met (each sweep that stopped at something counts once).
    pub contacts: usize,
    /// Bodies whose remainder was still blocked after the last pass, and was cut at its
    /// first contact.
    pub cut_short: usize,
}

/// A circle of a body, for the duration of a resolve.
#[derive(Clone, Copy, Debug)]
struct WorkCircle {
    body: u32,
    offset: Vec2,
    radius: f32,
}

/// What a sweep stopped at.
#[derive(Clone, Copy, Debug)]
enum Obstacle {
    /// A wall: met on its flat side, or at a rounded end.
    Wall { flat: bool },
    /// Another body, by work index.
    Body(u32),
}

/// Buffers kept between resolves, so a step allocates nothing once warm.
#[derive(Clone, Debug, Default)]
pub(crate) struct Scratch {
    circles: Vec<WorkCircle>,
    /// Per body, its first circle; one more entry at the end.
    first_circle: Vec<u32>,
    position: Vec<Vec2>,
    motion: Vec<Vec2>,
    filter: Vec<BodyFilter>,
    /// Per body, how far its circles reach past their radius this step: its move and the
    /// gap.
    reach: Vec<f32>,
    /// Per circle, its reach disc (where it starts, its radius grown by its body's reach:
    /// everywhere it can be this step) and the disc's box.
    reach_discs: Vec<Circle>,
    boxes: Vec<Aabb>,
    /// Whether `circles` and `first_circle` still describe the bodies (see `load`).
    shapes_known: bool,
    /// Per circle, the circles it may meet.
    neighbours: Neighbours,
    /// The walls near each circle, kept between steps (statements about the map, so they
    /// stay true whichever circle they end up with).
    near: NearWalls,
    /// The map as the last resolve saw it, to tell the memories what changed since.
    watch: MapWatch,
    /// Per circle of the body being resolved, its range of `near`'s walls.
    wall_ranges: Vec<(u32, u32)>,
    /// The last resolve, to skip bodies blocked in place again.
    pub(super) settled: Settled,
}

impl Scratch {
    /// Resolves the proposed moves of `bodies` (in slot order) on `map`, writing each
    /// body's resolved move.
    pub fn resolve(
        &mut self,
        bodies: &mut [&mut Body],
        config: &ResolveConfig,
        map: &TileMap,
    ) -> ResolveReport {
        let gap = config.gap * map.cell_size().min_element();
        self.load(bodies, gap);
        self.find_neighbours(config, map.cell_size().min_element());
        let change = self.watch.update(map);
        self.near.begin(self.circles.len(), change, &self.watch);
        self.settled
            .begin(&self.position, change != MapChange::Everything, config);
        if change == MapChange::Local {
            for (c, area) in self.boxes.iter().enumerate() {
                if self.watch.touches(area) {
                    self.settled.wake(self.circles[c].body as usize);
                }
            }
        }
        let mut report = ResolveReport::default();
        for (b, body) in bodies.iter_mut().enumerate() {
            let (start, motion) = (self.position[b], self.motion[b]);
            if motion == Vec2::ZERO {
                self.settled.remember_still(b, start);
                continue;
            }
            if self.settled.stays(b, start, motion, &mut report) {
                body.resolved = Vec2::ZERO;
                continue;
            }
            let before = report;
            self.collide_and_slide(b as u32, config, gap, map, &mut report);
            let end = self.position[b];
            body.resolved = end - start;
            report.moving += 1;
            let contacts = report.contacts - before.contacts;
            let cut_short = report.cut_short > before.cut_short;
            self.settled
                .remember(b, start, motion, end, contacts, cut_short);
            if end != start {
                self.disturb_neighbours(b);
            }
        }
        report
    }

    /// Forgets the last resolve: the bodies changed in a way their positions do not show.
    pub fn forget(&mut self) {
        self.settled.forget();
        self.neighbours.forget();
        self.shapes_known = false;
    }

    /// Body `b` moved: flags the bodies whose reach discs touch its own as disturbed.
    fn disturb_neighbours(&mut self, b: usize) {
        let circles = self.first_circle[b] as usize..self.first_circle[b + 1] as usize;
        for c in circles {
            for &n in self.neighbours.row(c) {
                let other = self.circles[n as usize].body as usize;
                self.settled.disturb(b, other);
            }
        }
    }

    /// Copies the bodies into flat arrays.
    fn load(&mut self, bodies: &[&mut Body], gap: f32) {
        // The circles change only when bodies are added or removed, which calls `forget`:
        // otherwise they are kept, and the bodies' shapes (each a list of its own, on the
        // heap) are not read again.
        if !self.shapes_known || self.first_circle.len() != bodies.len() + 1 {
            self.circles.clear();
            self.first_circle.clear();
            for (b, body) in bodies.iter().enumerate() {
                self.first_circle.push(self.circles.len() as u32);
                self.circles
                    .extend(body.shape.circles().iter().map(|c| WorkCircle {
                        body: b as u32,
                        offset: c.center,
                        radius: c.radius,
                    }));
            }
            self.first_circle.push(self.circles.len() as u32);
            self.shapes_known = true;
        }
        self.position.clear();
        self.motion.clear();
        self.filter.clear();
        self.reach.clear();
        for body in bodies {
            self.position.push(body.position);
            self.motion.push(body.proposed);
            self.filter.push(body.filter);
            // Everywhere a circle can be during the step: its whole move, grown by the
            // radius and the gap.
            self.reach.push(body.proposed.length() + gap);
        }
        self.reach_discs.clear();
        let (position, reach) = (&self.position, &self.reach);
        self.reach_discs.extend(self.circles.iter().map(|c| {
            let b = c.body as usize;
            Circle::new(position[b] + c.offset, c.radius + reach[b])
        }));
        self.boxes.clear();
        self.boxes.extend(self.reach_discs.iter().map(Circle::aabb));
    }

    /// The circles each circle may meet: pairs of different bodies that collide by filter
    /// and whose reach discs overlap. A row is read only for a moving body, so the rows may
    /// also pair bodies that both stay.
    fn find_neighbours(&mut self, config: &ResolveConfig, cell: f32) {
        let (circles, filter) = (&self.circles, &self.filter);
        self.neighbours.update(
            config.broadphase,
            &self.reach_discs,
            &self.boxes,
            cell,
            |i| circles[i as usize].body as usize,
            |a, b| filter[a].collides(&filter[b]),
        );
    }

    /// Moves body `b` by its proposed move with collide and slide, updating its position.
    fn collide_and_slide(
        &mut self,
        b: u32,
        config: &ResolveConfig,
        gap: f32,
        map: &TileMap,
        report: &mut ResolveReport,
    ) {
        let bi = b as usize;
        let circles = self.first_circle[bi] as usize..self.first_circle[bi + 1] as usize;
        // The walls near each circle, once: the reach disc holds every position the body
        // can take this step (slides never lengthen the remainder).
        self.wall_ranges.clear();
        let mask = self.filter[bi].walls;
        for c in circles.clone() {
            let range = self.near.around(c, &self.reach_discs[c], mask, gap, map);
            self.wall_ranges.push(range);
        }
        let mut remaining = self.motion[bi];
        for pass in 0..=config.passes {
            if remaining == Vec2::ZERO {
                break;
            }
            let Some((hit, obstacle)) = self.first_contact(b, remaining, gap, config.toi) else {
                self.position[bi] += remaining;
                return;
            };
            report.contacts += 1;
            // A safe part shorter than a fraction of the gap is not taken: rounding the
            // position can lose one coordinate of so small a step (at x = 232 the float
            // spacing is 1.5e-5) and keep the other, and a body pressed into a wall and a
            // neighbour would creep into the neighbour a few ulps per pass.
            let step = remaining * hit.t;
            let taken = step.length() >= gap * MIN_STEP;
            self.position[bi] += Vec2::new(keep_if(taken, step.x), keep_if(taken, step.y));
            if pass == config.passes {
                report.cut_short += 1;
                return;
            }
            let blocked = remaining * (1.0 - hit.t);
            remaining = slide(blocked, hit.normal, obstacle, b, config.slide);
            // A slide that would end past MAX_COORD is not taken, so every body stays in
            // range: a move ends within it (checked by `propose`), and every later position
            // lies on a straight path between two points within it (the square is convex,
            // and rounding is monotone).
            if !in_range(self.position[bi] + remaining) {
                remaining = Vec2::ZERO;
            }
        }
    }

    /// The first contact of body `b` moving by `motion` from where it is now, against the
    /// walls near it and its neighbours where they are now.
    fn first_contact(
        &self,
        b: u32,
        motion: Vec2,
        gap: f32,
        toi: TimeOfImpact,
    ) -> Option<(SweepHit, Obstacle)> {
        let bi = b as usize;
        let origin = self.position[bi];
        // Obstacles farther than the move's length plus the contact radius are out of reach:
        // the cheap test that lets a free body skip almost every sweep.
        let reach = motion.length();
        let mut best: Option<(SweepHit, Obstacle)> = None;
        let mut keep = |hit: SweepHit, obstacle: Obstacle| {
            if best.is_none_or(|(b, _)| hit.t < b.t) {
                best = Some((hit, obstacle));
            }
        };
        let first = self.first_circle[bi] as usize;
        for (k, c) in self.circles[first..self.first_circle[bi + 1] as usize]
            .iter()
            .enumerate()
        {
            let center = origin + c.offset;
            for wall in self.near.walls(self.wall_ranges[k]) {
                let distance2 = wall.segment.distance_squared_to(center);
                let radius = band(distance2, c.radius, gap);
                if distance2 > (radius + reach) * (radius + reach) {
                    continue;
                }
                if let Some(hit) = sweep_wall(wall, center, radius, motion, toi) {
                    keep(
                        hit,
                        Obstacle::Wall {
                            flat: hit.normal == wall.normal,
                        },
                    );
                }
            }
            let ci = first + k;
            let neighbours = self.neighbours.row(ci);
            // The nearest neighbour contact, lowest circle index first on equal `t` (the
            // row is in broadphase order).
            let mut nearest: Option<(SweepHit, u32)> = None;
            for &n in neighbours {
                let other = &self.circles[n as usize];
                let at = self.position[other.body as usize] + other.offset;
                let distance2 = center.distance_squared(at);
                let radius = band(distance2, c.radius + other.radius, gap);
                if distance2 > (radius + reach) * (radius + reach) {
                    continue;
                }
                if let Some(hit) = sweep_circle(center, motion, at, radius, toi)
                    && nearest.is_none_or(|(h, m)| hit.t < h.t || (hit.t == h.t && n < m))
                {
                    nearest = Some((hit, n));
                }
            }
            if let Some((hit, n)) = nearest {
                keep(hit, Obstacle::Body(self.circles[n as usize].body));
            }
        }
        best
    }
}

/// The contact radius for a circle whose centre is at squared distance `distance2` from an
/// obstacle it touches at `radius`: `radius + gap` from outside that band, `radius + gap / 2`
/// from inside it (so a body in the band may still close in a little: no snag on rounding).
fn band(distance2: f32, radius: f32, gap: f32) -> f32 {
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
fn grazes(hit: SweepHit, motion: Vec2) -> bool {
    hit.t == 0.0 && hit.normal.dot(motion) >= -TANGENT_EPSILON * motion.length()
}

fn sweep_wall(
    wall: &Capsule,
    center: Vec2,
    radius: f32,
    motion: Vec2,
    toi: TimeOfImpact,
) -> Option<SweepHit> {
    match toi {
        TimeOfImpact::Exact => {
            let hit = wall.sweep_ordinary(center, radius, motion)?;
            // The flat side reports the wall's own normal; any other comes from a rounded
            // end (a shortcut only: the sweep below would return the flat hit unchanged).
            if hit.normal == wall.normal || !grazes(hit, motion) {
                return Some(hit);
            }
            // A rounded end only grazed from within its radius is not a contact, but the
            // flat side or the other end may still be met further on: sweep again without
            // the ends the move only grazes.
            let mut caps = wall.caps;
            for (cap, end) in caps.iter_mut().zip([wall.segment.a, wall.segment.b]) {
                *cap &= !circle_circle(center - end, motion, radius)
                    .is_some_and(|end_hit| grazes(end_hit, motion));
            }
            Capsule { caps, ..*wall }.sweep_ordinary(center, radius, motion)
        }
        TimeOfImpact::Bisection { halvings } => {
            // The write-up's check at sampled positions: inside the capsule, on the front.
            let at = |t: f32| center + motion * t;
            let inside = |t: f32| {
                let p = at(t);
                (p - wall.segment.a).dot(wall.normal) >= 0.0
                    && wall.segment.distance_squared_to(p) < radius * radius
            };
            let t = bisect(halvings, inside)?;
            let p = at(t);
            let normal = (p - wall.segment.closest_point(p))
                .try_normalize()
                .unwrap_or(wall.normal);
            Some(SweepHit { t, normal })
        }
    }
}

fn sweep_circle(
    center: Vec2,
    motion: Vec2,
    other: Vec2,
    radius: f32,
    toi: TimeOfImpact,
) -> Option<SweepHit> {
    match toi {
        TimeOfImpact::Exact => {
            circle_circle(center - other, motion, radius).filter(|&hit| !grazes(hit, motion))
        }
        TimeOfImpact::Bisection { halvings } => {
            let at = |t: f32| center + motion * t;
            let t = bisect(halvings, |t| {
                at(t).distance_squared(other) < radius * radius
            })?;
            let normal = (at(t) - other)
                .try_normalize()
                .unwrap_or(-motion.normalize_or_zero());
            Some(SweepHit { t, normal })
        }
    }
}

/// The write-up's response: the blocked remainder redirected along the contact tangent, to
/// the side its projection points. For two bodies meeting exactly head-on (projection
/// zero) the one with the lower slot turns one way and the other the opposite way; a body
/// running straight into a wall stops.
fn slide(blocked: Vec2, normal: Vec2, obstacle: Obstacle, me: u32, mode: SlideMode) -> Vec2 {
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
    if matches!(obstacle, Obstacle::Wall { flat: true }) && lean < 0.0 {
        slid + normal * (SLIDE_LIFT * slid.length())
    } else {
        slid
    }
}

/// Negation when `yes`, by flipping the sign bit with an integer mask: the same bits as
/// `-x`, with no branch for a condition the predictor cannot guess.
fn flip_if(yes: bool) -> impl Fn(f32) -> f32 {
    let mask = u32::from(yes) << 31;
    move |x| f32::from_bits(x.to_bits() ^ mask)
}

/// `x` when `yes`, else `-0.0` (which added to anything leaves it bit for bit as it was,
/// `-0.0` included), by masking bits: no branch for a condition the predictor cannot guess.
fn keep_if(yes: bool, x: f32) -> f32 {
    let keep = u32::from(yes).wrapping_neg();
    f32::from_bits((x.to_bits() & keep) | (!keep & (-0.0f32).to_bits()))
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
                Obstacle::Wall { flat: true },
                0,
                SlideMode::FullLength
            ),
            Vec2::new(1.0, 0.0)
        );
        let t = slide(
            blocked,
            up,
            Obstacle::Wall { flat: true },
            0,
            SlideMode::Tangential,
        );
        assert!((t - Vec2::new(0.6, 0.0)).length() < 1e-6);
        assert_eq!(
            slide(
                blocked,
                up,
                Obstacle::Wall { flat: true },
                0,
                SlideMode::Stop
            ),
            Vec2::ZERO
        );
        assert_eq!(
            slide(
                Vec2::new(0.0, -1.0),
                up,
                Obstacle::Wall { flat: true },
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
