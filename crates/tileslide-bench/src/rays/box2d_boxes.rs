//! The Box2D box peer: one Box2D v3 box shape per solid cell in a world, queried with Box2D's
//! closest-hit world ray cast.

use boxdd::{BodyType, ShapeDef, Transform, World, shapes};
use tileslide_scenes::{SceneRay, SolidGrid};

use super::box2d_chains::cast_closest;
use crate::box2d_map::box2d_world;

/// The grid's solid cells as Box2D v3 boxes (through `boxdd`): one 1×1 polygon per solid cell,
/// centred on the cell, all on one static body at the origin, for reference against
/// [`Box2dChains`](super::Box2dChains): the shapes a tile map gives most directly, whose seams
/// Box2D's chains exist to smooth over (movers can catch on the seams between boxes; rays do
/// not care).
///
/// Each ray is one `b2World_CastRayClosest`, as for the chains, with the same first difference
/// from tileslide's answers (a ray starting exactly on a wall's face and moving into it is not
/// stopped there: 3 of dungeon256's million rays, none of open256's). Every solid cell is a shape,
/// the cells buried in the walls included, so the static tree holds 20,365 leaves on
/// dungeon256 (against 34,656 chain segments).
///
/// Box2D's static tree is built by inserting the shapes one by one as they are created (Box2D
/// then rotates nodes to keep it balanced). Box2D has a call that rebuilds it from scratch
/// (`b2World_RebuildStaticTree`), but it is documented as being for internal testing, and
/// `boxdd` leaves it to its raw FFI (`boxdd_sys`), which this crate, forbidding `unsafe`,
/// does not use: the tree is the one a Box2D user gets by creating the shapes. (Through the
/// raw FFI, outside this crate, a rebuilt tree cast dungeon256's rays about 1.3× faster, and
/// open256's about 1.1×; the chains' tree gained 1.1× and nothing.)
pub struct Box2dBoxes {
    world: World,
}

impl Box2dBoxes {
    /// The name this peer is reported under.
    pub const NAME: &'static str = "box2d-boxes";

    /// Builds the world: one static body with a box per solid cell, in row-major order.
    /// Entries of `grid.solid` beyond `width * height` are ignored.
    ///
    /// # Errors
    /// When Box2D refuses the world, the body or a shape.
    pub fn new(grid: &SolidGrid) -> Result<Self, boxdd::Error> {
        let mut world = box2d_world()?;
        let body = world.create_body(world.body_builder().body_type(BodyType::Static).build()?)?;
        let mut cells = world.body(body)?;
        let def = ShapeDef::default();
        for y in 0..grid.height {
            for x in 0..grid.width {
                if grid.is_solid(x as i64, y as i64) {
                    let centre = Transform::from_pos_angle([x as f32 + 0.5, y as f32 + 0.5], 0.0)?;
                    cells.create_polygon(&def, &shapes::offset_box_polygon(0.5, 0.5, centre)?)?;
                }
            }
        }
        Ok(Self { world })
    }

    /// Distance in cells along `ray` (whose `dir` must be unit length) to the first solid cell
    /// boundary it meets within `ray.length`, or `None` if there is none (an error from boxdd
    /// reads as a miss, as for [`Box2dChains::cast`](super::Box2dChains::cast)).
    #[inline]
    pub fn cast(&self, ray: &SceneRay) -> Option<f32> {
        cast_closest(&self.world, ray)
    }
}

#[cfg(test)]
super::test_grids::ray_peer_tests!(Box2dBoxes, |grid| Box2dBoxes::new(grid).unwrap());
