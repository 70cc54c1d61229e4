//! A circle rolling around a rounded corner, exactly, whatever the frame rate.

use std::f32::consts::{FRAC_PI_2, PI, TAU};

use glam::Vec2;

use super::{Character, MIN_MOVE, Met, MoveOptions, nearest_end};
use crate::controller::CharacterShape;
use crate::controller::trace::{Log, SweepPurpose};
use crate::geometry::{Aabb, SweepHit};
use crate::query::{QueryFilter, Wall};
use crate::tiles::TileMap;

/// A circle whose contact normal with a corner rises more than this (its sine) is above
/// the corner: sideways motion towards the corner does not roll it (see
/// `Character::roll`). Not zero,
/// so that a circle rolled to exactly level is not taken for above it through rounding.
const ROLL_LEVEL: f32 = 1e-5;

/// The most a circle's contact normal turns on one swept leg of a roll around a corner
/// (radians): the legs run along the arc's tangents, at most `1/cos(ROLL_STEP/2) − 1`
/// (0.9 %) of the distance outside it.
const ROLL_STEP: f32 = 0.27;

impl Character {
    /// Whether `hit` is a circle meeting `wall`'s rounded end (its normal is not the face's).
    pub(super) fn at_rounded_corner(&self, hit: &SweepHit, wall: &Wall) -> bool {
        matches!(self.shape, CharacterShape::Circle { .. }) && hit.normal != wall.capsule.normal
    }

    /// Rolls the circle, touching `corner`, around it by as much of `rest` as presses it
    /// there, and returns what is left of `rest` once it leaves the corner, or once another
    /// surface stops it on the way (with that surface, which the rest meets first).
    ///
    /// Sliding by the projection of each step's motion on the tangent (as on a flat face)
    /// would follow the arc by chords, one a step, and end in a different place at each
    /// frame rate. Rolling is exact instead: pressed by a constant displacement `d` (length
    /// `L`) at distance `R`, the angle `ψ` from `d` to the contact normal obeys
    /// `dψ/ds = −(L/R)·sin ψ` over the fraction `s` of the move, so
    /// `tan(ψ/2) = tan(ψ₀/2)·e^(−L·s/R)`, and the circle leaves the corner when `|ψ| = 90°`.
    /// Steps compose exactly, so any frame rate ends in the same place. As on a steep slope,
    /// sideways motion towards a corner the circle is above does not lift it over: there
    /// only the move's rise or fall rolls it (until it is level with the corner, where the
    /// whole move presses again). The arc is travelled a skin from the corner by swept legs
    /// along its tangents (at most [`ROLL_STEP`] of turn each), so nothing on the way is
    /// passed through; a leg stopped by another surface puts the circle where the arc meets
    /// that surface (see [`arc_meets`](Self::arc_meets)). The corner is rounded only
    /// between the faces that meet there: a roll that would turn the normal past one of
    /// them ends where the normal is that face's, the rest of the move meeting the face flat
    /// (see [`face_reached`](Self::face_reached)).
    pub(super) fn roll(
        &mut self,
        map: &TileMap,
        corner: Vec2,
        rest: Vec2,
        options: MoveOptions,
        log: &mut Log<'_>,
    ) -> (Vec2, Option<Met>) {
        log.purpose(SweepPurpose::Roll);
        let offset = self.position - corner;
        // Rolled a skin from the corner, however close the move that met it came (a move
        // that grazes the corner ends closer than a skin, by how much depends on the rate).
        let radius = self.shape.support(offset) + self.config.skin;
        if rest.dot(offset) >= 0.0 {
            // Moving off the corner: free.
            return (rest, None);
        }
        // Above the corner, sideways motion towards it does not lift the circle over it
        // (as on a steep slope): only the rise or fall rolls it. Sideways motion away from
        // it carries the circle off its far side, so the whole move rolls it there, and it
        // leaves the corner where a straight move from the corner's skin would graze it.
        let above = offset.dot(self.up) > ROLL_LEVEL * radius;
        let towards = rest.dot(self.side) * offset.dot(self.side) < 0.0;
        let driver = if above && towards {
            self.up * rest.dot(self.up)
        } else {
            rest
        };
        let length = driver.length();
        if radius <= 0.0 || length <= MIN_MOVE || driver.dot(offset) >= 0.0 {
            return (Vec2::ZERO, None);
        }
        let start = driver.angle_to(offset);
        let k = (0.5 * start).tan();
        // The fraction of the move at which the normal turns square to the motion.
        let leave = radius / length * k.abs().ln();
        let mut done = leave.clamp(0.0, 1.0);
        let mut end = 2.0 * (k * (-length * done / radius).exp()).atan();
        let dir = driver / length;
        let mut flat = None;
        if let Some((angle, face)) = self.face_reached(map, corner, dir, (start, end)) {
            // The part of the move that turns the normal to the face's.
            let rolled = radius / length * (k / (0.5 * angle).tan()).ln();
            done = if rolled.is_nan() {
                0.0
            } else {
                rolled.clamp(0.0, done)
            };
            end = angle;
            flat = Some(face);
        }
        let pieces = ((end - start).abs() / ROLL_STEP).ceil().max(1.0);
        let mut from = start;
        for i in 1..=pieces as u32 {
            let to = start + (end - start) * (i as f32 / pieces);
            let middle = dir.rotate(Vec2::from_angle(0.5 * (from + to)));
            let apex = corner + middle * (radius / (0.5 * (to - from)).cos());
            let arrival = corner + dir.rotate(Vec2::from_angle(to)) * radius;
            let stopped = self
                .go(map, apex - self.position, options, None, log)
                .or_else(|| self.go(map, arrival - self.position, options, None, log));
            if let Some((hit, wall, _)) = stopped {
                // Stopped on a leg: a skin from the surface where the arc itself reaches it,
                // not where the leg (outside the arc, by an amount that depends on how the
                // roll was cut into legs, and so on the rate) does.
                if let Some(angle) = self.arc_meets(corner, radius, dir, (from, to), (&hit, &wall))
                {
                    let on_arc = corner + dir.rotate(Vec2::from_angle(angle)) * radius;
                    self.go(map, on_arc - self.position, options, None, log);
                }
                // The part of the move rolled so far, from the angle reached.
                let now = driver.angle_to(self.position - corner);
                // (A ratio that rounding made negative gives NaN: taken as nothing rolled.)
                let rolled = radius / length * (k / (0.5 * now).tan()).ln();
                let rolled = if rolled.is_nan() {
                    0.0
                } else {
                    rolled.clamp(0.0, 1.0)
                };
                return (rest * (1.0 - rolled), Some((hit, wall)));
            }
            from = to;
        }
        (rest * (1.0 - done), flat)
    }

    /// Where a roll around `corner` whose contact normal turns from angle `span.0` to
    /// `span.1` (from `dir`) first turns it out of the rounded cap of a face that ends at
    /// the corner (the face met, or one that goes on from it there): the angle, at which the
    /// normal is that face's, and the face as met there, flat. A cap rounds its segment's
    /// end only on the far side of the end (where the normal leans out along the segment);
    /// past that, the face's flat side is the surface.
    fn face_reached(
        &mut self,
        map: &TileMap,
        corner: Vec2,
        dir: Vec2,
        (start, end): (f32, f32),
    ) -> Option<(f32, Met)> {
        let turn = end - start;
        if turn == 0.0 {
            return None;
        }
        // Ends this close are the corner (the map's own tolerance for joined ends).
        let near = 1e-4 * map.cell_size().max_element();
        let region = Aabb::from_center(corner, Vec2::splat(near));
        // (The sweeps' buffer, which holds nothing the move still needs.)
        let mut walls = std::mem::take(&mut self.walls);
        walls.clear();
        map.walls_in(
            &region,
            &QueryFilter::default().with_mask(self.config.mask),
            &mut walls,
        );
        let mut best: Option<(f32, f32, Wall)> = None;
        for &wall in &walls {
            let segment = &wall.capsule.segment;
            // Its direction out of the corner (only its sign along `perp(n)` counts).
            let out = if segment.a.distance_squared(corner) <= near * near {
                segment.a - segment.b
            } else if segment.b.distance_squared(corner) <= near * near {
                segment.b - segment.a
            } else {
                continue;
            };
            // The cap is where the normal `u` leans along `out` (`u·out ≥ 0`); the roll
            // crosses its edge where `u` is the face's normal `n`, and leaves the cap there
            // if `u·out` falls as it turns (`du` is `turn · perp(u)`).
            let normal = wall.capsule.normal;
            if turn * normal.perp().dot(out) >= 0.0 {
                continue;
            }
            let angle = dir.angle_to(normal);
            // The turn from `start` to `angle`, in (−π, π].
            let mut to = angle - start;
            if to > PI {
                to -= TAU;
            } else if to <= -PI {
                to += TAU;
            }
            let mut progress = to / turn;
            // A normal already just past the face's at the start (a sweep that met the cap
            // where the face begins, a hair below the corner by rounding): the face at once.
            if progress < 0.0 && to.abs() < FRAC_PI_2 {
                progress = 0.0;
            }
            if (0.0..=1.0).contains(&progress) && best.as_ref().is_none_or(|(p, ..)| progress < *p)
            {
                best = Some((progress, start + turn * progress, wall));
            }
        }
        self.walls = walls;
        best.map(|(_, angle, wall)| {
            let hit = SweepHit {
                t: 0.0,
                normal: wall.capsule.normal,
            };
            (angle, (hit, wall))
        })
    }

    /// The angle (from `dir`, between the ends of `span`) at which the centre of a circle
    /// rolling around `corner` at `radius` comes a skin from `wall`, which `hit` met: from
    /// its face, where `(corner + radius·u − a)·n` is the shape's reach plus the skin (`u`
    /// the unit vector at that angle); from its rounded end `e`, where
    /// `|corner + radius·u − e|` is. Either is `u·v = cosine` for a unit `v`.
    pub(super) fn arc_meets(
        &self,
        corner: Vec2,
        radius: f32,
        dir: Vec2,
        span: (f32, f32),
        (hit, wall): (&SweepHit, &Wall),
    ) -> Option<f32> {
        let capsule = &wall.capsule;
        let reach = self.shape.support(hit.normal) + self.config.skin;
        let (towards, cosine) = if hit.normal == capsule.normal {
            let cosine = (reach - (corner - capsule.segment.a).dot(capsule.normal)) / radius;
            (capsule.normal, cosine)
        } else {
            let apart = nearest_end(&capsule.segment, self.position) - corner;
            let distance = apart.length();
            let cosine =
                (radius * radius + distance * distance - reach * reach) / (2.0 * radius * distance);
            (apart / distance, cosine)
        };
        if cosine.is_nan() || cosine.abs() > 1.0 {
            return None;
        }
        let towards = dir.angle_to(towards);
        let (low, high) = (span.0.min(span.1), span.0.max(span.1));
        let turn = cosine.acos();
        [towards - turn, towards + turn]
            .map(|angle| (angle + PI).rem_euclid(TAU) - PI)
            .into_iter()
            .find(|angle| (low..=high).contains(angle))
    }
}
