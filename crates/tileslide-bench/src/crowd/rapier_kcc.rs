//! The rapier2d peer: every circle a kinematic body moved by rapier's
//! `KinematicCharacterController`, the walls fixed cuboid colliders.

use parry2d::shape::Ball;
use rapier2d::control::KinematicCharacterController;
use rapier2d::prelude::{
    ColliderBuilder, PhysicsWorld, QueryFilter, RigidBodyBuilder, RigidBodyHandle, Vector,
};
use tileslide_scenes::{CrowdBody, SolidGrid};

use super::CrowdContender;
use crate::parry_vectors::to_parry;

/// A crowd in a rapier2d [`PhysicsWorld`] (zero gravity, default integration parameters):
/// each circle a position-based kinematic body with a ball collider, each solid cell that has an
/// empty side neighbour in the grid a fixed 1×1 cuboid collider (the cells buried in the walls
/// cannot be touched and would only weigh down the broad phase).
///
/// A step is what a rapier user writes for kinematic characters:
///
/// 1. for each circle, `KinematicCharacterController::move_shape` with its velocity as the
///    desired translation, against a query pipeline that excludes the circle's own body (so it
///    sees the walls and the other circles where the last step left them);
/// 2. `set_next_kinematic_translation` to the position it allows, for every circle;
/// 3. one `PhysicsWorld::step`, which moves the bodies and updates the broad phase.
///
/// Every circle plans its move against the others' positions of the previous step, so two
/// circles can both take the same gap in one step: the overlaps this leaves are part of what
/// the benchmark measures.
///
/// The controller is set up for a top-down game: no ground snapping, and every contact treated
/// as a wall to slide along (its slope logic is written for side views: with the default
/// `up = +y`, a circle moving up along a wall facing −x would stop instead of sliding, because
/// that wall reads as a slope too steep to climb).
pub struct RapierCrowd {
    world: PhysicsWorld,
    controller: KinematicCharacterController,
    ball: Ball,
    handles: Vec<RigidBodyHandle>,
    velocities: Vec<Vector>,
    /// Scratch: the translations planned in step 1, applied in step 2.
    planned: Vec<Vector>,
}

impl RapierCrowd {
    /// The name this peer is reported under.
    pub const NAME: &'static str = "rapier2d-kcc";

    /// Builds the world: wall colliders from `grid`, one kinematic ball of `radius` per body;
    /// then steps it once so that the broad phase knows every collider before the first query.
    pub fn new(grid: &SolidGrid, bodies: &[CrowdBody], radius: f32) -> Self {
        let mut world = PhysicsWorld {
            gravity: Vector::ZERO,
            ..PhysicsWorld::default()
        };
        for y in 0..grid.height {
            for x in 0..grid.width {
                let (xi, yi) = (x as i64, y as i64);
                // Only neighbours inside the grid count: nothing moves outside it, so the outer
                // sides of the border ring are never touched (the same reading as
                // `SolidGrid::merged_exposed_edges`).
                let exposed = [(1, 0), (-1, 0), (0, 1), (0, -1)]
                    .iter()
                    .map(|&(dx, dy)| (xi + dx, yi + dy))
                    .filter(|&(nx, ny)| {
                        (0..grid.width as i64).contains(&nx)
                            && (0..grid.height as i64).contains(&ny)
                    })
                    .any(|(nx, ny)| !grid.is_solid(nx, ny));
                if grid.is_solid(xi, yi) && exposed {
                    let centre = Vector::new(x as f32 + 0.5, y as f32 + 0.5);
                    world.insert_collider(
                        ColliderBuilder::cuboid(0.5, 0.5).translation(centre),
                        None,
                    );
                }
            }
        }
        let handles = bodies
            .iter()
            .map(|b| {
                let body =
                    RigidBodyBuilder::kinematic_position_based().translation(to_parry(b.position));
                world.insert(body, ColliderBuilder::ball(radius)).0
            })
            .collect();
        world.step();
        let controller = KinematicCharacterController {
            snap_to_ground: None,
            // Never a wall too steep to climb, never a slope to stick to: always slide.
            max_slope_climb_angle: f32::INFINITY,
            min_slope_slide_angle: f32::NEG_INFINITY,
            ..KinematicCharacterController::default()
        };
        Self {
            world,
            controller,
            ball: Ball::new(radius),
            handles,
            velocities: bodies.iter().map(|b| to_parry(b.velocity)).collect(),
            planned: Vec::with_capacity(bodies.len()),
        }
    }

    /// The number of wall colliders (solid cells with an empty side neighbour in the grid).
    pub fn wall_colliders(&self) -> usize {
        self.world.colliders.len() - self.handles.len()
    }
}

impl CrowdContender for RapierCrowd {
    fn name(&self) -> &'static str {
        Self::NAME
    }

    fn step(&mut self) {
        let dt = self.world.integration_parameters.dt;
        self.planned.clear();
        for (&handle, &velocity) in self.handles.iter().zip(&self.velocities) {
            let body = &self.world.bodies[handle];
            let queries = self
                .world
                .query_pipeline_with_filter(QueryFilter::default().exclude_rigid_body(handle));
            let movement = self.controller.move_shape(
                dt,
                &queries,
                &self.ball,
                body.position(),
                velocity,
                |_| {},
            );
            self.planned.push(body.translation() + movement.translation);
        }
        for (&handle, &target) in self.handles.iter().zip(&self.planned) {
            self.world.bodies[handle].set_next_kinematic_translation(target);
        }
        self.world.step();
    }

    fn positions(&self) -> Vec<glam::Vec2> {
        self.handles
            .iter()
            .map(|&h| {
                let p = self.world.bodies[h].translation();
                glam::Vec2::new(p.x, p.y)
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::crowd::test_room as room;
    use glam::Vec2;
    use tileslide_scenes::CROWD_RADIUS;

    #[test]
    fn only_solid_cells_next_to_empty_ones_become_colliders() {
        // The ring's 28 cells all face the room except the 4 corners.
        let crowd = RapierCrowd::new(&room(), &[], CROWD_RADIUS);
        assert_eq!(crowd.wall_colliders(), 24);
    }

    #[test]
    fn a_free_circle_moves_by_its_whole_velocity_and_a_wall_stops_it() {
        let bodies = [
            CrowdBody {
                position: Vec2::new(3.5, 2.5),
                velocity: Vec2::new(0.05, 0.0),
            },
            CrowdBody {
                position: Vec2::new(6.0, 4.5),
                velocity: Vec2::new(0.05, 0.0),
            },
        ];
        let mut crowd = RapierCrowd::new(&room(), &bodies, CROWD_RADIUS);
        for _ in 0..20 {
            crowd.step();
        }
        let p = crowd.positions();
        assert!((p[0] - Vec2::new(4.5, 2.5)).length() < 1e-4, "{}", p[0]);
        // Against the wall x = 7, short of it by the controller's offset (1 % of the ball's
        // 0.6 height by default).
        assert!(
            (p[1].x - (7.0 - CROWD_RADIUS - 0.006)).abs() < 1e-3,
            "{}",
            p[1]
        );
    }

    #[test]
    fn a_circle_slides_up_along_a_wall_facing_minus_x() {
        // The case the default slope settings get wrong in a top-down game.
        let v = 0.05 / 2.0_f32.sqrt();
        let bodies = [CrowdBody {
            position: Vec2::new(6.0, 2.0),
            velocity: Vec2::new(v, v),
        }];
        let mut crowd = RapierCrowd::new(&room(), &bodies, CROWD_RADIUS);
        for _ in 0..60 {
            crowd.step();
        }
        // Contact after about 20 steps at y ≈ 2.7, where it would stop without the slide;
        // sliding, it ends near y = 2 + 60 v ≈ 4.1.
        let p = crowd.positions()[0];
        assert!(p.y > 3.5, "{p}");
    }
}
