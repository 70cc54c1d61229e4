//! The crowd benchmark: the "crowd" scene of BENCHMARKS.md (circles sliding through dungeon256,
//! each proposing its constant velocity as its move every step) run by each contender, timed
//! step by step, then audited for overlaps and wall penetrations.
//!
//! A contender implements [`CrowdContender`]; [`run_crowd`] steps it, times every step and
//! measures how far the circles travelled, and [`audit_crowd`] checks the end state.
//! [`TileslideCrowd`] is tileslide's resolver; the peers:
//!
//! - [`ParryVoxelsCrowd`] and [`ParrySegmentsCrowd`]: parry2d shape casts in a hand-rolled
//!   slide loop, the walls as `Voxels` or as segments;
//! - [`RapierCrowd`]: rapier2d's `KinematicCharacterController` on kinematic bodies;
//! - [`Box2dMoverCrowd`]: Box2D v3's character mover (collide, solve planes, cast), the walls
//!   as chain loops and the circles on kinematic bodies.
//!
//! Speed alone means nothing here: a contender that lets circles sink into walls or into each
//! other does less work. Read `ms_per_step` together with the audit and with `mean_travel` (a
//! contender that stops every circle at the first contact travels less).
//!
//! ```no_run
//! use tileslide_bench::crowd::{ParryVoxelsCrowd, run_crowd};
//! use tileslide_scenes::{CROWD_RADIUS, dungeon256, scene_crowd};
//!
//! let grid = dungeon256();
//! let bodies = scene_crowd(&grid, 1_000);
//! let mut peer = ParryVoxelsCrowd::new(&grid, &bodies, CROWD_RADIUS);
//! let result = run_crowd(&mut peer, &grid, 100, CROWD_RADIUS);
//! println!("{}: {:.2} ms/step, {:?}", result.name, result.ms_per_step, result.audit);
//! ```

mod box2d_mover;
mod neighbour_grid;
mod parry_slide;
mod rapier_kcc;
mod tileslide_crowd;

pub use box2d_mover::Box2dMoverCrowd;
pub use parry_slide::{ParryCrowd, ParrySegmentsCrowd, ParryVoxelsCrowd};
pub use rapier_kcc::RapierCrowd;
pub use tileslide_crowd::{TileslideCrowd, TileslideCrowdError};

use std::time::Instant;

use glam::Vec2;
use tileslide_scenes::{CrowdAudit, SolidGrid, audit_crowd};

/// An 8×8 room for the contenders' tests: solid border ring, open inside ([1, 7] × [1, 7]).
#[cfg(test)]
pub(crate) fn test_room() -> SolidGrid {
    SolidGrid::from_rows(&[
        "########", "#......#", "#......#", "#......#", "#......#", "#......#", "#......#",
        "########",
    ])
}

/// A body for the contenders' tests: its start `position` and constant `velocity`.
#[cfg(test)]
pub(crate) fn test_body(position: (f32, f32), velocity: (f32, f32)) -> tileslide_scenes::CrowdBody {
    tileslide_scenes::CrowdBody {
        position: Vec2::new(position.0, position.1),
        velocity: Vec2::new(velocity.0, velocity.1),
    }
}

/// Something that moves a crowd of circles through a map: tileslide or one of its peers.
///
/// A contender is built from the map, the [`CrowdBody`](tileslide_scenes::CrowdBody)s (start
/// positions and constant velocities) and the radius, by a constructor of its own (building its
/// structures is not timed). Every [`step`](Self::step) it proposes each body's velocity as
/// that body's move and resolves the moves against the walls and the other bodies.
pub trait CrowdContender {
    /// The name the contender is reported under (e.g. `"parry2d-voxels"`).
    fn name(&self) -> &'static str;

    /// Advances the crowd by one step: every body tries to move by its velocity.
    fn step(&mut self);

    /// The bodies' centres, in the order of the bodies the contender was built from.
    fn positions(&self) -> Vec<Vec2>;
}

/// One contender's figures on one crowd.
#[derive(Clone, Debug, PartialEq)]
pub struct CrowdResult {
    /// The contender's [`name`](CrowdContender::name).
    pub name: &'static str,
    /// Median wall time of one step, in milliseconds (0 for a run of no steps).
    pub ms_per_step: f64,
    /// Fastest and slowest step, in milliseconds.
    pub spread_ms: (f64, f64),
    /// The audit of the positions after the last step.
    pub audit: CrowdAudit,
    /// Mean over the bodies of the path length travelled: the sum of the per-step
    /// displacement lengths, in cells. A body never blocked travels `steps × 0.05`.
    pub mean_travel: f64,
}

/// Runs `steps` steps of `contender`, timing each [`step`](CrowdContender::step) alone, then
/// audits the final positions with [`audit_crowd`] (`radius` on `grid`).
///
/// The positions are read between steps, outside the timed part, to measure how far the bodies
/// travel.
pub fn run_crowd(
    contender: &mut dyn CrowdContender,
    grid: &SolidGrid,
    steps: usize,
    radius: f32,
) -> CrowdResult {
    let mut before = contender.positions();
    let mut travel = 0.0_f64;
    let mut times_ms = Vec::with_capacity(steps);
    for _ in 0..steps {
        let start = Instant::now();
        contender.step();
        times_ms.push(start.elapsed().as_secs_f64() * 1e3);
        let after = contender.positions();
        travel += before
            .iter()
            .zip(&after)
            .map(|(a, b)| f64::from(a.distance(*b)))
            .sum::<f64>();
        before = after;
    }
    times_ms.sort_by(f64::total_cmp);
    let ms_per_step = times_ms.get(steps / 2).copied().unwrap_or(0.0);
    let spread_ms = (
        times_ms.first().copied().unwrap_or(0.0),
        times_ms.last().copied().unwrap_or(0.0),
    );
    let mean_travel = if before.is_empty() {
        0.0
    } else {
        travel / before.len() as f64
    };
    CrowdResult {
        name: contender.name(),
        ms_per_step,
        spread_ms,
        audit: audit_crowd(grid, &before, radius),
        mean_travel,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use tileslide_scenes::{CROWD_RADIUS, CrowdBody, dungeon256, scene_crowd};

    /// A contender that moves every body by its velocity, ignoring everything: the harness's
    /// own check (known travel, known end positions).
    struct Ghosts {
        bodies: Vec<CrowdBody>,
    }

    impl CrowdContender for Ghosts {
        fn name(&self) -> &'static str {
            "ghosts"
        }
        fn step(&mut self) {
            for b in &mut self.bodies {
                b.position += b.velocity;
            }
        }
        fn positions(&self) -> Vec<Vec2> {
            self.bodies.iter().map(|b| b.position).collect()
        }
    }

    #[test]
    fn the_harness_measures_travel_and_audits_the_end_state() {
        let grid = dungeon256();
        let bodies = scene_crowd(&grid, 200);
        let mut ghosts = Ghosts {
            bodies: bodies.clone(),
        };
        let result = run_crowd(&mut ghosts, &grid, 40, CROWD_RADIUS);
        assert_eq!(result.name, "ghosts");
        assert!((result.mean_travel - 40.0 * 0.05).abs() < 1e-4);
        // Ghosts walk into walls: after 2 cells of travel, many are inside one.
        assert_eq!(
            result.audit,
            audit_crowd(&grid, &ghosts.positions(), CROWD_RADIUS)
        );
        assert!(result.audit.wall_penetrations > 0);
        for (b, end) in bodies.iter().zip(ghosts.positions()) {
            // 40 f32 additions at coordinates up to 256 drift by a few 1e-4.
            assert!((b.position + b.velocity * 40.0).distance(end) < 1e-3);
        }
        assert!(
            result.spread_ms.0 <= result.ms_per_step && result.ms_per_step <= result.spread_ms.1
        );
    }

    #[test]
    fn no_steps_means_no_travel_and_the_start_audit() {
        let grid = dungeon256();
        let mut ghosts = Ghosts {
            bodies: scene_crowd(&grid, 50),
        };
        let result = run_crowd(&mut ghosts, &grid, 0, CROWD_RADIUS);
        assert_eq!((result.ms_per_step, result.mean_travel), (0.0, 0.0));
        assert!(result.audit.is_clean());
    }

    /// Runs a peer for a few steps of a 200-body crowd on dungeon256.
    fn run_peer(make: impl Fn(&SolidGrid, &[CrowdBody]) -> Box<dyn CrowdContender>) -> CrowdResult {
        let grid = dungeon256();
        let bodies = scene_crowd(&grid, 200);
        let mut peer = make(&grid, &bodies);
        run_crowd(peer.as_mut(), &grid, 10, CROWD_RADIUS)
    }

    #[test]
    fn parry_voxels_moves_the_crowd() {
        let result = run_peer(|g, b| Box::new(ParryVoxelsCrowd::new(g, b, CROWD_RADIUS)));
        assert_eq!(result.name, "parry2d-voxels");
        assert!(result.mean_travel > 0.0, "{result:?}");
        assert!(result.mean_travel <= 10.0 * 0.05 + 1e-4, "{result:?}");
    }

    #[test]
    fn parry_segments_moves_the_crowd() {
        let result = run_peer(|g, b| Box::new(ParrySegmentsCrowd::new(g, b, CROWD_RADIUS)));
        assert_eq!(result.name, "parry2d-segments");
        assert!(result.mean_travel > 0.0, "{result:?}");
        assert!(result.mean_travel <= 10.0 * 0.05 + 1e-4, "{result:?}");
    }

    #[test]
    fn rapier_kcc_moves_the_crowd() {
        let result = run_peer(|g, b| Box::new(RapierCrowd::new(g, b, CROWD_RADIUS)));
        assert_eq!(result.name, "rapier2d-kcc");
        assert!(result.mean_travel > 0.0, "{result:?}");
        assert!(result.mean_travel <= 10.0 * 0.05 + 1e-3, "{result:?}");
    }

    #[test]
    fn box2d_mover_moves_the_crowd() {
        let result = run_peer(|g, b| Box::new(Box2dMoverCrowd::new(g, b, CROWD_RADIUS).unwrap()));
        assert_eq!(result.name, "box2d-mover");
        assert!(result.mean_travel > 0.0, "{result:?}");
        assert!(result.mean_travel <= 10.0 * 0.05 + 1e-3, "{result:?}");
        // Whatever it counts, nothing sinks deeper than Box2D's slop of 0.005, give or take.
        assert!(result.audit.max_overlap < 0.02, "{result:?}");
        assert!(result.audit.max_penetration < 0.02, "{result:?}");
    }
}
