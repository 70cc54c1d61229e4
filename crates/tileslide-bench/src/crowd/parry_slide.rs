//! The parry2d peers: every circle moved in turn by a hand-rolled "cast, move, slide" loop built
//! on parry2d's shape casts, against the walls (as `Voxels` or as segments) and the circles near
//! it.

use parry2d::math::{Pose, Vector};
use parry2d::query::{ShapeCastOptions, cast_shapes};
use parry2d::shape::{Ball, Polyline, Shape, Voxels};
use tileslide_scenes::{CrowdBody, SolidGrid};

use super::CrowdContender;
use super::neighbour_grid::NeighbourGrid;
use crate::parry_vectors::to_parry;
use crate::rays::{ParryPolyline, ParryVoxels};

/// Gap the slide keeps between a circle and whatever it hits (parry's `target_distance`): a
/// contact stops the circle this far away, so that the next cast along the wall does not start
/// in contact. Well inside the audit's 1e-3 tolerance in the other direction: it only ever
/// leaves circles apart, never overlapping.
const SKIN: f32 = 1e-3;

/// Casts per circle per step at most: the first move, then up to three slides along the
/// contacts met on the way (a circle wedged in a corner or between neighbours stops there).
const MAX_CASTS: usize = 4;

/// Moves shorter than this (cells) are dropped: nothing is left to slide.
const MIN_MOVE: f32 = 1e-6;

/// A crowd moved with parry2d shape casts, the walls being the parry shape `W` (one shape for
/// the whole map, identity pose).
///
/// Each step moves the circles one after the other (in index order, each seeing the others'
/// latest positions, so two circles never claim the same gap), each with this loop:
///
/// 1. cast the ball along the remaining move (parry's [`cast_shapes`], `target_distance` 1e-3,
///    `stop_at_penetration = false` so that a contact being left is ignored) against the walls
///    and against every circle in the 3×3 neighbouring buckets of a uniform grid of buckets
///    rebuilt at the start of the step;
/// 2. move to the earliest time of impact (all of the move if nothing is hit);
/// 3. remove from what is left of the move its component into the contact normal, and start
///    again with the rest (the slide along the contact tangent), at most 4 casts.
///
/// This is the loop a parry user writes for kinematic circles; parry has no character
/// controller of its own (rapier's is measured by [`RapierCrowd`](super::RapierCrowd)).
///
/// Circles do end up in walls with both wall shapes, because some of parry's casts miss (the
/// loop trusts them, as a user would). Replaying the offending moves on dungeon256 showed:
/// with `Voxels`, diagonal moves that return no hit although a wall cell of the circle's
/// starting row or column is in the way (parry's voxel cast shifts a window of the ball's
/// size one row or column at a time instead of growing it, so once the window has moved to
/// the next row, the cells of the starting row are never tested: e.g. the ball at
/// (246.675, 117.325) moving (0.0311, −0.0392) misses cell (247, 117), which the same cast
/// against that cell's cuboid alone hits at t = 0.77); with segments, casts that return no
/// hit, or a hit a few 1e-3 too late, when the circle starts resting against a long merged
/// edge (within the skin) and moves into it.
#[derive(Clone, Debug)]
pub struct ParryCrowd<W> {
    name: &'static str,
    walls: W,
    ball: Ball,
    positions: Vec<Vector>,
    velocities: Vec<Vector>,
    neighbours: NeighbourGrid,
}

/// The parry2d peer with the walls as one [`Voxels`] shape, one voxel per solid cell (as
/// [`ParryVoxels`] builds it for the rays).
pub type ParryVoxelsCrowd = ParryCrowd<Voxels>;

/// The parry2d peer with the walls as segments: the grid's merged exposed edges as one
/// [`Polyline`] (as [`ParryPolyline`] builds it for the rays), whose shape cast walks its
/// internal BVH of segments.
pub type ParrySegmentsCrowd = ParryCrowd<Polyline>;

impl ParryVoxelsCrowd {
    /// The name this peer is reported under.
    pub const NAME: &'static str = "parry2d-voxels";

    /// Builds the voxel walls from `grid` and places `bodies` as circles of `radius`.
    pub fn new(grid: &SolidGrid, bodies: &[CrowdBody], radius: f32) -> Self {
        let walls = ParryVoxels::new(grid).shape().clone();
        ParryCrowd::with_walls(Self::NAME, walls, grid, bodies, radius)
    }
}

impl ParrySegmentsCrowd {
    /// The name this peer is reported under.
    pub const NAME: &'static str = "parry2d-segments";

    /// Builds the segment walls from `grid` and places `bodies` as circles of `radius`.
    pub fn new(grid: &SolidGrid, bodies: &[CrowdBody], radius: f32) -> Self {
        let walls = ParryPolyline::new(grid).shape().clone();
        ParryCrowd::with_walls(Self::NAME, walls, grid, bodies, radius)
    }
}

impl<W: Shape> ParryCrowd<W> {
    /// A crowd of `bodies` (circles of `radius`) among the `walls`, reported as `name`.
    pub fn with_walls(
        name: &'static str,
        walls: W,
        grid: &SolidGrid,
        bodies: &[CrowdBody],
        radius: f32,
    ) -> Self {
        let positions: Vec<Vector> = bodies.iter().map(|b| to_parry(b.position)).collect();
        let velocities: Vec<Vector> = bodies.iter().map(|b| to_parry(b.velocity)).collect();
        // Two circles can meet during a step if their centres are within 2r, plus both moves,
        // plus the skin; a circle's bucket can also be one move stale (see NeighbourGrid).
        let fastest = velocities.iter().map(|v| v.length()).fold(0.0, f32::max);
        let reach = 2.0 * radius + 4.0 * fastest + SKIN;
        Self {
            name,
            walls,
            ball: Ball::new(radius),
            positions,
            velocities,
            neighbours: NeighbourGrid::new(grid.width, grid.height, reach),
        }
    }

    /// The earliest hit along `motion` from `at` for circle `i`: time of impact in `[0, 1]`
    /// (a fraction of `motion`) and the unit contact normal pointing from the circle towards
    /// what it hits, or `None` if the way is free.
    fn first_hit(&self, i: usize, at: Vector, motion: Vector) -> Option<(f32, Vector)> {
        let start = Pose::from_translation(at);
        let mut options = ShapeCastOptions {
            max_time_of_impact: 1.0,
            target_distance: SKIN,
            stop_at_penetration: false,
            compute_impact_geometry_on_penetration: true,
        };
        let mut best = None;
        // `Err(Unsupported)` cannot happen for a ball against voxels, a polyline or a ball.
        if let Ok(Some(hit)) = cast_shapes(
            &start,
            motion,
            &self.ball,
            &Pose::IDENTITY,
            Vector::ZERO,
            &self.walls,
            options,
        ) {
            options.max_time_of_impact = hit.time_of_impact;
            best = Some((hit.time_of_impact, hit.normal1));
        }
        self.neighbours.for_each_near(at, |j| {
            if j == i {
                return;
            }
            let other = Pose::from_translation(self.positions[j]);
            if let Ok(Some(hit)) = cast_shapes(
                &start,
                motion,
                &self.ball,
                &other,
                Vector::ZERO,
                &self.ball,
                options,
            ) && best.is_none_or(|(t, _)| hit.time_of_impact < t)
            {
                options.max_time_of_impact = hit.time_of_impact;
                best = Some((hit.time_of_impact, hit.normal1));
            }
        });
        best
    }

    /// Moves circle `i` by its velocity, sliding along what it hits.
    fn slide(&mut self, i: usize) {
        let mut at = self.positions[i];
        let mut motion = self.velocities[i];
        for _ in 0..MAX_CASTS {
            if motion.length_squared() < MIN_MOVE * MIN_MOVE {
                break;
            }
            match self.first_hit(i, at, motion) {
                None => {
                    at += motion;
                    break;
                }
                Some((t, normal)) => {
                    at += motion * t;
                    let rest = motion * (1.0 - t);
                    // `normal1` is the ball's outward normal at the contact: it points into
                    // the obstacle. Drop the part of the rest that pushes into it; what is
                    // left runs along the contact tangent (or away from the obstacle).
                    let into = rest.dot(normal);
                    motion = if into > 0.0 {
                        rest - normal * into
                    } else {
                        rest
                    };
                }
            }
        }
        self.positions[i] = at;
    }
}

impl<W: Shape> CrowdContender for ParryCrowd<W> {
    fn name(&self) -> &'static str {
        self.name
    }

    fn step(&mut self) {
        self.neighbours.rebuild(&self.positions);
        for i in 0..self.positions.len() {
            self.slide(i);
        }
    }

    fn positions(&self) -> Vec<glam::Vec2> {
        self.positions
            .iter()
            .map(|p| glam::Vec2::new(p.x, p.y))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::crowd::{test_body as body, test_room as room};
    use glam::Vec2;
    use tileslide_scenes::{CROWD_RADIUS, audit_crowd};

    /// Runs both wall variants on the same bodies for `steps` steps.
    fn run_both(bodies: &[CrowdBody], steps: usize) -> Vec<Vec<Vec2>> {
        let grid = room();
        let mut voxels = ParryVoxelsCrowd::new(&grid, bodies, CROWD_RADIUS);
        let mut segments = ParrySegmentsCrowd::new(&grid, bodies, CROWD_RADIUS);
        for _ in 0..steps {
            voxels.step();
            segments.step();
        }
        vec![voxels.positions(), segments.positions()]
    }

    #[test]
    fn a_free_circle_moves_by_its_whole_velocity() {
        for positions in run_both(&[body((3.5, 3.5), (0.05, 0.0))], 10) {
            assert!((positions[0] - Vec2::new(4.0, 3.5)).length() < 1e-5);
        }
    }

    #[test]
    fn a_circle_driven_into_a_wall_stops_at_the_skin() {
        // Heading for the wall x = 7 at 0.05 a step: it stops at x = 7 − 0.3 − SKIN, within
        // the precision of parry's iterative casts, and stays there.
        for positions in run_both(&[body((6.0, 3.5), (0.05, 0.0))], 40) {
            let x = positions[0].x;
            assert!((x - (7.0 - CROWD_RADIUS - SKIN)).abs() < 5e-4, "x = {x}");
        }
    }

    #[test]
    fn a_circle_slides_along_a_wall_it_meets_at_an_angle() {
        // 45° into the wall x = 7: once in contact it keeps only its +y component.
        let v = 0.05 / 2.0_f32.sqrt();
        for positions in run_both(&[body((6.0, 2.0), (v, v))], 60) {
            let p = positions[0];
            assert!((p.x - (7.0 - CROWD_RADIUS - SKIN)).abs() < 5e-4, "{p}");
            // Contact after about 20 steps at y ≈ 2.7, where it would stop without the slide;
            // then 40 steps up the wall at up to v per step (y ≈ 4.12 at most).
            assert!(p.y > 3.9 && p.y < 2.0 + 60.0 * v + 1e-3, "{p}");
        }
    }

    #[test]
    fn two_circles_heading_for_each_other_stop_apart() {
        let bodies = [
            body((2.5, 3.5), (0.05, 0.0)),
            body((5.5, 3.5), (-0.05, 0.0)),
        ];
        for positions in run_both(&bodies, 60) {
            let gap = positions[0].distance(positions[1]) - 2.0 * CROWD_RADIUS;
            assert!((0.0..2.0 * SKIN).contains(&gap), "gap {gap}");
            let audit = audit_crowd(&room(), &positions, CROWD_RADIUS);
            assert!(audit.is_clean(), "{audit:?}");
        }
    }
}
