//! The Box2D peer: every circle moved by Box2D v3's character mover (`b2World_CollideMover`,
//! `b2SolvePlanes`, `b2World_CastMover`), the walls chain loops, the other circles shapes on
//! kinematic bodies.

use boxdd::{
    BodyId, BodyType, Circle, CollisionPlane, Filter, MoverQueryBuffer, QueryFilter, ShapeDef,
    ShapeId, Vec2, World, solve_planes,
};
use tileslide_scenes::{CrowdBody, SolidGrid};

use super::CrowdContender;
use crate::box2d_map::{box2d_world, create_wall_chains, to_box2d, to_position};

/// Collision category of the walls (Box2D's mover sample calls it `StaticBit`).
const WALL: u64 = 0x1;
/// Collision category of the circles (the sample's `MoverBit`).
const MOVER: u64 = 0x2;

/// Passes of collide, solve and cast per circle per step at most: the sample's 5.
const PASSES: usize = 5;

/// A pass that moves a circle less than this (cells) ends its step: the sample's tolerance.
const TOLERANCE: f32 = 0.01;

/// A crowd moved by Box2D v3's character mover (through `boxdd`), in a world holding the walls
/// and the circles.
///
/// The world: the walls as chain loops on one static body, as for
/// [`Box2dChains`](crate::rays::Box2dChains); each circle a circle shape on a kinematic body
/// of its own. Each circle is also a mover: a capsule of zero length (both centres at the
/// circle's centre) and the circle's radius, kept by this peer, whose body follows it.
///
/// Each step moves the circles one after the other (in index order, each seeing the others'
/// latest positions), each with the loop of Box2D's mover sample (`GeometricMover::Solve` in
/// its `samples/geometric_mover.cpp`), the target being the position plus the circle's
/// velocity:
///
/// 1. `b2World_CollideMover` at the current position gathers a collision plane from every
///    wall segment and every other circle the mover touches or overlaps (its own shape is
///    left out);
/// 2. `b2SolvePlanes` finds the move towards the target that best satisfies those planes
///    (pushing out of overlaps, sliding along contacts);
/// 3. `b2World_CastMover` sweeps the mover along that move against the walls and the other
///    circles and stops it at the first new contact;
/// 4. the circle advances by the fraction allowed; up to 5 passes, ending early when a pass
///    moves it less than 0.01;
///
/// then its body is moved there with `b2Body_SetTransform`, which updates Box2D's broad phase
/// at once, so the next circle's queries see it. The world is never stepped: the mover API is
/// queries only, and a step would find no contacts to make (Box2D's broad phase pairs only
/// dynamic bodies with others).
///
/// Two differences from the sample. The sample treats other movers as soft: their planes have
/// a push limit (0.025 m) and do not clip the velocity, and its cast ignores them, so a
/// character can lean into a friendly one and slowly pass it. Here every circle is an obstacle
/// as solid as a wall: every plane is rigid (`FLT_MAX` push limit), and the cast sees the
/// circles as well as the walls. (With the sample's soft planes, 10,000 circles end 100 steps
/// with some passed right through each other, the deepest overlap a full 0.6.) And the sample
/// ends each move with `b2ClipVector`, removing from the character's velocity what pushes into
/// the planes, so that speed does not build up against a wall; here the velocity is the
/// scene's constant proposal, the same every step for every contender, so nothing is clipped.
///
/// Box2D keeps contacts slightly overlapping on purpose: `b2SolvePlanes` lets a mover sink
/// into each plane by its linear slop (0.005 cells at Box2D's default scale of one unit per
/// meter) to avoid jitter, and `b2World_CastMover` stops a mover at that depth too. So a
/// circle resting against a wall or another circle overlaps it by about 0.005, five times the
/// audit's tolerance of 1e-3: the audit counts those circles, although Box2D regards them as
/// touching. Read the audit's maximum depths beside its counts. Deeper penetrations come from
/// jams: a circle squeezed between a wall and a neighbour with no room between them gets
/// planes that cannot all be met, `b2SolvePlanes` stops at its 20 iterations with a move that
/// breaks some of them, and `b2World_CastMover` ignores the shapes the mover already overlaps,
/// so it does not stop that move at the wall (at 10,000 circles after 100 steps, about 25
/// circles are more than 0.01 deep in a wall, the deepest about 0.09).
pub struct Box2dMoverCrowd {
    world: World,
    /// Circle `i`'s body and shape.
    bodies: Vec<BodyId>,
    shapes: Vec<ShapeId>,
    /// The movers' positions (their bodies follow them).
    positions: Vec<glam::Vec2>,
    velocities: Vec<glam::Vec2>,
    radius: f32,
    /// Scratch: the plane results of one collide, and the planes given to the solver.
    results: MoverQueryBuffer,
    planes: Vec<CollisionPlane>,
    /// The first error boxdd reported during a step, if any (see [`error`](Self::error)).
    error: Option<boxdd::Error>,
}

impl Box2dMoverCrowd {
    /// The name this peer is reported under.
    pub const NAME: &'static str = "box2d-mover";

    /// Builds the world: the wall chains from `grid`, one kinematic body with a circle of
    /// `radius` per body.
    ///
    /// # Errors
    /// When Box2D refuses the world or one of its objects (e.g. a radius not above Box2D's
    /// minimum mover radius of 0.01).
    pub fn new(grid: &SolidGrid, bodies: &[CrowdBody], radius: f32) -> Result<Self, boxdd::Error> {
        let mut world = box2d_world()?;
        let walls = Filter {
            category_bits: WALL,
            ..Filter::default()
        };
        create_wall_chains(&mut world, grid, walls)?;
        let shape_def = ShapeDef::builder()
            .filter(Filter {
                category_bits: MOVER,
                ..Filter::default()
            })
            .build()?;
        let circle = Circle::new(Vec2::ZERO, radius)?;
        let mut ids = Vec::with_capacity(bodies.len());
        let mut shapes = Vec::with_capacity(bodies.len());
        for b in bodies {
            let def = world
                .body_builder()
                .body_type(BodyType::Kinematic)
                .position(to_position(b.position))
                .build()?;
            let id = world.create_body(def)?;
            shapes.push(world.body(id)?.create_circle(&shape_def, &circle)?);
            ids.push(id);
        }
        Ok(Self {
            world,
            bodies: ids,
            shapes,
            positions: bodies.iter().map(|b| b.position).collect(),
            velocities: bodies.iter().map(|b| b.velocity).collect(),
            radius,
            results: MoverQueryBuffer::new(),
            planes: Vec::new(),
            error: None,
        })
    }

    /// The first error boxdd reported while stepping, if any. Stepping cannot fail in the
    /// [`CrowdContender`] contract; a circle whose move fails stays where it was, and the error
    /// is kept here (none is expected: boxdd reports errors for non-finite input, calls from
    /// inside Box2D callbacks and exhausted memory).
    pub fn error(&self) -> Option<boxdd::Error> {
        self.error
    }

    /// Moves circle `i` towards its position plus its velocity with the mover loop; returns
    /// where it ends.
    fn solve_move(&mut self, i: usize) -> Result<glam::Vec2, boxdd::Error> {
        let own = self.shapes[i];
        let filter = QueryFilter::new().category(MOVER).mask(WALL | MOVER);
        let mut at = self.positions[i];
        let target = at + self.velocities[i];
        let query = self.world.query()?;
        for _ in 0..PASSES {
            // The capsule is given relative to the query origin, the mover's position.
            let origin = to_position(at);
            query.collide_mover_into(
                origin,
                Vec2::ZERO,
                Vec2::ZERO,
                self.radius,
                filter,
                &mut self.results,
            )?;
            self.planes.clear();
            for result in self.results.iter() {
                if result.shape_id != own
                    && let Some(plane) = result.into_rigid_collision_plane()?
                {
                    self.planes.push(plane);
                }
            }
            let solved = solve_planes(to_box2d(target - at), &mut self.planes)?;
            let translation = solved.translation();
            let fraction = query.cast_mover(
                origin,
                Vec2::ZERO,
                Vec2::ZERO,
                self.radius,
                translation,
                filter,
            )?;
            let delta = glam::Vec2::new(translation.x, translation.y) * fraction;
            at += delta;
            if delta.length_squared() < TOLERANCE * TOLERANCE {
                break;
            }
        }
        Ok(at)
    }
}

impl CrowdContender for Box2dMoverCrowd {
    fn name(&self) -> &'static str {
        Self::NAME
    }

    fn step(&mut self) {
        for i in 0..self.positions.len() {
            let moved = self.solve_move(i).and_then(|at| {
                self.world
                    .body(self.bodies[i])?
                    .set_position_and_rotation(to_position(at), 0.0)?;
                Ok(at)
            });
            match moved {
                Ok(at) => self.positions[i] = at,
                Err(e) => {
                    self.error.get_or_insert(e);
                }
            }
        }
    }

    fn positions(&self) -> Vec<glam::Vec2> {
        self.positions.clone()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::crowd::{test_body as body, test_room as room};
    use glam::Vec2;
    use tileslide_scenes::{CROWD_RADIUS, audit_crowd};

    /// Box2D's linear slop at its default scale: the depth at which it leaves contacts.
    const SLOP: f32 = 0.005;

    fn run(bodies: &[CrowdBody], steps: usize) -> Vec<Vec2> {
        let mut crowd = Box2dMoverCrowd::new(&room(), bodies, CROWD_RADIUS).unwrap();
        for _ in 0..steps {
            crowd.step();
        }
        assert_eq!(crowd.error(), None);
        crowd.positions()
    }

    #[test]
    fn a_free_circle_moves_by_its_whole_velocity() {
        let p = run(&[body((3.5, 3.5), (0.05, 0.0))], 10);
        assert!((p[0] - Vec2::new(4.0, 3.5)).length() < 1e-5, "{}", p[0]);
    }

    #[test]
    fn a_circle_driven_into_a_wall_stops_in_it_by_the_slop() {
        // Heading for the wall x = 7: it stops inside it by Box2D's linear slop, and stays
        // there; the audit counts that as a wall penetration.
        let p = run(&[body((6.0, 3.5), (0.05, 0.0))], 40);
        let depth = p[0].x - (7.0 - CROWD_RADIUS);
        assert!((depth - SLOP).abs() < 1e-4, "{}: depth {depth}", p[0]);
        assert!((p[0].y - 3.5).abs() < 1e-5, "{}", p[0]);
        let audit = audit_crowd(&room(), &p, CROWD_RADIUS);
        assert_eq!(audit.wall_penetrations, 1, "{audit:?}");
    }

    #[test]
    fn a_circle_slides_along_a_wall_it_meets_at_an_angle() {
        // 45° into the wall x = 7: once in contact it keeps only its +y component.
        let v = 0.05 / 2.0_f32.sqrt();
        let p = run(&[body((6.0, 2.0), (v, v))], 60)[0];
        assert!((p.x - (7.0 - CROWD_RADIUS)).abs() < 2.0 * SLOP, "{p}");
        // Contact after about 20 steps at y ≈ 2.7, where it would stop without the slide;
        // then 40 steps up the wall at up to v per step (y ≈ 4.12 at most).
        assert!(p.y > 3.9 && p.y < 2.0 + 60.0 * v + 1e-3, "{p}");
    }

    #[test]
    fn two_circles_heading_for_each_other_stop_overlapping_by_the_slop() {
        let bodies = [
            body((2.5, 3.5), (0.05, 0.0)),
            body((5.5, 3.5), (-0.05, 0.0)),
        ];
        let p = run(&bodies, 60);
        let overlap = 2.0 * CROWD_RADIUS - p[0].distance(p[1]);
        assert!((overlap - SLOP).abs() < 1e-4, "overlap {overlap}");
        let audit = audit_crowd(&room(), &p, CROWD_RADIUS);
        assert_eq!(audit.overlapping_pairs, 1, "{audit:?}");
        assert_eq!(audit.wall_penetrations, 0, "{audit:?}");
    }
}
