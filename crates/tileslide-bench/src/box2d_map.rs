//! The map in a Box2D v3 world, through the `boxdd` crate: the world every Box2D peer starts
//! from, the walls as chain loops, and vectors across.
//!
//! Box2D is used with its default length scale, one unit per meter, so a cell is 1 m and the
//! scenes' circles (radius 0.3) are the size of the character in Box2D's own mover sample.
//! Its tolerances are in those units: the linear slop (the overlap its solvers leave in
//! contacts) is 0.005 cells.
//!
//! `boxdd` wraps Box2D's C API in a safe, checked layer (world-bound ids, argument validation,
//! callback guards); the peers use only that layer, as this crate forbids `unsafe`, so what
//! they measure is Box2D through `boxdd`, checks included.

use boxdd::{BodyId, BodyType, ChainDef, Filter, Foundation, Position, Vec2, World};
use tileslide_scenes::SolidGrid;

use crate::wall_loops::wall_loops;

/// Box2D's process-wide state, which every `boxdd` call but the pure ones needs first,
/// initialized with the defaults (one unit per meter). Every peer makes the same call, so they
/// can share a process.
///
/// # Errors
/// When Box2D cannot be initialized (another part of the process chose another scale).
pub fn box2d_foundation() -> Result<&'static Foundation, boxdd::Error> {
    Foundation::initialize_default()
}

/// A Box2D world for a peer: no gravity, one thread.
///
/// # Errors
/// When Box2D cannot be initialized or refuses another world (it has room for 128 at a time).
pub fn box2d_world() -> Result<World, boxdd::Error> {
    let foundation = box2d_foundation()?;
    foundation.create_world(foundation.world_builder().gravity(Vec2::ZERO).build()?)
}

/// Adds `grid`'s walls to `world` as one static body at the origin carrying one chain loop per
/// [`WallLoop`](crate::wall_loops::WallLoop) (cells outside the grid count as empty), each
/// chain with `filter`; returns the body.
///
/// Box2D's chain segments are one-sided, colliding on their right: the loops are wound so that
/// the right side of every segment is the empty side, which is where rays and movers come from.
/// (Box2D's mover queries, `b2World_CollideMover`, treat them as two-sided segments; nothing
/// reaches their back sides, which are inside the walls.)
///
/// # Errors
/// When Box2D refuses the body or a chain.
pub fn create_wall_chains(
    world: &mut World,
    grid: &SolidGrid,
    filter: Filter,
) -> Result<BodyId, boxdd::Error> {
    let body = world.create_body(world.body_builder().body_type(BodyType::Static).build()?)?;
    let mut walls = world.body(body)?;
    for wall in wall_loops(grid) {
        let chain = ChainDef::builder()
            .points(wall.corners.iter().map(|&c| to_box2d(c)))
            .is_loop(true)
            .filter(filter)
            .build()?;
        walls.create_chain(&chain)?;
    }
    Ok(body)
}

/// Converts a workspace (glam 0.34) vector into Box2D's vector type (boxdd's own `Vec2`; its
/// optional glam conversions are for glam 0.33).
#[inline]
pub fn to_box2d(v: glam::Vec2) -> Vec2 {
    Vec2::new(v.x, v.y)
}

/// Converts a workspace point into a Box2D world position.
#[inline]
pub fn to_position(p: glam::Vec2) -> Position {
    Position::new(p.x, p.y)
}

/// Converts a Box2D world position into a workspace point.
#[inline]
pub fn from_position(p: Position) -> glam::Vec2 {
    glam::Vec2::new(p.x, p.y)
}
