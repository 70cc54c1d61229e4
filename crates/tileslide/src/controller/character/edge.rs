//! Where a walk leaves the ground: the places along a leg where whether there is ground
//! below can change, and the search between them.

use glam::Vec2;

use super::{Character, MoveOptions, end_point, nearest_end};
use crate::controller::CharacterShape;
use crate::controller::trace::{Log, MoveEvent, SweepPurpose};
use crate::geometry::Aabb;
use crate::query::{QueryFilter, Wall};
use crate::tiles::TileMap;

/// How many halvings [`Character::edge`] makes of a walk's leg to find where the ground
/// ends: to 2⁻²⁰ of the leg, far below the skin for any step a game makes.
const EDGE_STEPS: u32 = 20;

/// The ground just before a walk leaves it (see [`Character::edge`]): how far the character
/// drops onto it there, and the corner it stands on, for a circle on a rounded corner.
#[derive(Clone, Copy, Debug)]
pub(super) struct Footing {
    pub(super) drop: f32,
    pub(super) corner: Option<Vec2>,
}

impl Character {
    /// Where a walk along the straight `leg` from `from` (swept clear) leaves the ground:
    /// the first fraction of the leg at which the character has no walkable ground within
    /// the snap distance below it, and how far below the ground was just before it (the
    /// drop that puts the character on it there). `None` when it has ground all along the
    /// leg; a fraction of 0 (and no drop) when it has none at `from`. `grounded` says
    /// whether it has ground at the leg's end. The character is left where it was.
    ///
    /// Whether there is ground changes only at the leg's [`ground_events`]: where the
    /// shape's side passes a segment's capped end, where a circle's contact normal with a
    /// corner reaches the slope limit, where a walkable line takes over from a corner below
    /// a circle, where a walkable segment's line is the snap distance below. Each stretch
    /// between two of them is tested at its middle, in order along the leg, so a gap the
    /// leg crosses is not stepped over however long the step. The first stretch without
    /// ground is then bisected to 2⁻²⁰ of the leg, and the fraction is returned on the side
    /// past the edge, so that a fall from there does not catch the edge it left.
    ///
    /// [`ground_events`]: Self::ground_events
    pub(super) fn edge(
        &mut self,
        map: &TileMap,
        from: Vec2,
        leg: Vec2,
        grounded: bool,
        options: MoveOptions,
    ) -> Option<(f32, Footing)> {
        let end = self.position;
        self.ground_events(map, from, leg, options);
        let found = 'search: {
            if grounded && self.events.is_empty() {
                break 'search None;
            }
            let Some(mut footing) = self.ground_below(map, from, options) else {
                let none = Footing {
                    drop: 0.0,
                    corner: None,
                };
                break 'search Some((0.0, none));
            };
            let (mut lo, mut hi) = (0.0f32, None);
            let mut before = 0.0f32;
            for i in 0..=self.events.len() {
                let after = self.events.get(i).copied().unwrap_or(1.0);
                let middle = 0.5 * (before + after);
                before = after;
                match self.ground_below(map, from + leg * middle, options) {
                    Some(below) => (lo, footing) = (middle, below),
                    None => {
                        hi = Some(middle);
                        break;
                    }
                }
            }
            let mut hi = match hi {
                Some(hi) => hi,
                None if grounded => break 'search None,
                None => 1.0,
            };
            for _ in 0..EDGE_STEPS {
                let middle = 0.5 * (lo + hi);
                if !(lo < middle && middle < hi) {
                    break;
                }
                match self.ground_below(map, from + leg * middle, options) {
                    Some(below) => (lo, footing) = (middle, below),
                    None => hi = middle,
                }
            }
            Some((hi, footing))
        };
        self.position = end;
        found
    }

    /// Collects in `self.events`, sorted, the fractions of the walk along `leg` from
    /// `from` (strictly between 0 and 1) at which whether the character has walkable
    /// ground within the snap distance below it can change: where its side passes a
    /// capped segment end (the surface ends there), where a circle's contact normal with
    /// such an end reaches the slope limit (`|offset| = radius · sin max_slope` along the
    /// side), where a walkable line takes over from such an end below a circle (see
    /// [`takeovers`]), and where the line of a walkable segment not parallel to the leg is
    /// the snap distance below it.
    pub(super) fn ground_events(
        &mut self,
        map: &TileMap,
        from: Vec2,
        leg: Vec2,
        options: MoveOptions,
    ) {
        self.events.clear();
        let across = leg.dot(self.side);
        let reach = self.config.snap_distance;
        let to = from + leg;
        let down = -self.up * reach;
        let (a, b) = (self.shape.bounds(from), self.shape.bounds(to));
        let (c, d) = (self.shape.bounds(from + down), self.shape.bounds(to + down));
        let region = Aabb::from_corners(
            a.min.min(b.min).min(c.min.min(d.min)),
            a.max.max(b.max).max(c.max.max(d.max)),
        )
        .expand(self.config.skin);
        let filter = QueryFilter::default().with_mask(self.config.mask);
        self.walls.clear();
        map.walls_in(&region, &filter, &mut self.walls);
        let width = self.shape.support(self.side);
        let steepest = match self.shape {
            CharacterShape::Circle { radius } => {
                Some(radius * (1.0 - self.walkable * self.walkable).max(0.0).sqrt())
            }
            CharacterShape::Rect { .. } => None,
        };
        let along = from.dot(self.side);
        for wall in &self.walls {
            let capsule = &wall.capsule;
            if !self.held_by(wall.flags, capsule.segment.a, capsule.normal, options) {
                continue;
            }
            for (end, &cap) in capsule.caps.iter().enumerate() {
                if !cap || across == 0.0 {
                    continue;
                }
                let corner = end_point(&capsule.segment, end);
                let at = corner.dot(self.side) - along;
                let offsets = [Some(width), Some(-width), steepest, steepest.map(|s| -s)];
                for offset in offsets.into_iter().flatten() {
                    self.events.push((at + offset) / across);
                }
                // Where a walkable line takes over from the corner below a circle, and
                // where it comes within two skins below the corner, from where a circle
                // over a corner too steep to stand on stands on the line instead (see
                // `ground_hit`).
                if let CharacterShape::Circle { radius } = self.shape {
                    for line in &self.walls {
                        for lift in [0.0, 2.0 * self.config.skin] {
                            let found = takeovers(
                                corner,
                                radius,
                                line,
                                lift,
                                self.up,
                                self.side,
                                self.walkable,
                            );
                            for offset in found.into_iter().flatten() {
                                self.events.push((at + offset) / across);
                            }
                        }
                    }
                }
            }
            let rise = capsule.normal.dot(self.up);
            let closing = leg.dot(capsule.normal);
            if rise >= self.walkable && closing != 0.0 {
                // The gap below along `up` is the height above the line over `rise`.
                let height = (from - capsule.segment.a).dot(capsule.normal)
                    - self.shape.support(capsule.normal);
                self.events.push((reach * rise - height) / closing);
            }
        }
        self.events.retain(|f| *f > 0.0 && *f < 1.0);
        self.events.sort_by(f32::total_cmp);
        self.events.dedup();
    }

    /// The walkable ground within the snap distance below the character at `at`: how far
    /// it would drop onto it (see [`ground_hit`](Self::ground_hit)) and, for a circle
    /// standing on a rounded corner, the corner. `None` when there is none. Moves the
    /// character to `at`.
    pub(super) fn ground_below(
        &mut self,
        map: &TileMap,
        at: Vec2,
        options: MoveOptions,
    ) -> Option<Footing> {
        self.position = at;
        let (hit, wall, drop) = self.ground_hit(map, self.config.snap_distance, options)?;
        let corner = self
            .at_rounded_corner(&hit, &wall)
            .then(|| nearest_end(&wall.capsule.segment, at - self.up * drop));
        Some(Footing { drop, corner })
    }

    /// Puts the character where a walk leaves the ground: at `at` on the walk, down onto the
    /// ground as it was just before (`footing`).
    pub(super) fn step_off(
        &mut self,
        map: &TileMap,
        at: Vec2,
        footing: &Footing,
        options: MoveOptions,
        log: &mut Log<'_>,
    ) {
        log.push(MoveEvent::LeftGround { at });
        self.position = at;
        log.purpose(SweepPurpose::StepOff);
        self.go(map, -self.up * footing.drop, options, None, log);
    }
}

/// The sideways offsets from `corner` at which a circle of `radius` lowered onto both
/// touches `corner` `lift` higher than it touches the line of `wall` (when that is walkable
/// for `up` and `walkable`): with no lift, where one takes over from the other below it.
/// The circle's centre over `corner + offset·side` touches the corner at height
/// `√(r² − offset²)` above it and the line at `α + β·offset`, `α` including the lift, which
/// are equal at the roots of `(1 + β²)·offset² + 2αβ·offset + α² − r² = 0`.
fn takeovers(
    corner: Vec2,
    radius: f32,
    wall: &Wall,
    lift: f32,
    up: Vec2,
    side: Vec2,
    walkable: f32,
) -> [Option<f32>; 2] {
    let normal = wall.capsule.normal;
    let rise = normal.dot(up);
    if rise < walkable {
        return [None; 2];
    }
    let alpha = (radius - (corner - wall.capsule.segment.a).dot(normal)) / rise + lift;
    let beta = -normal.dot(side) / rise;
    let (a, b, c) = (
        1.0 + beta * beta,
        alpha * beta,
        alpha * alpha - radius * radius,
    );
    let discriminant = b * b - a * c;
    if discriminant < 0.0 {
        return [None; 2];
    }
    let root = discriminant.sqrt();
    [(-b - root) / a, (-b + root) / a]
        .map(|offset| (offset.abs() <= radius && alpha + beta * offset >= 0.0).then_some(offset))
}
