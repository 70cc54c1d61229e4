//! The Box2D chain peer: the grid's walls as Box2D v3 chain loops in a world, queried with
//! Box2D's closest-hit world ray cast.

use boxdd::{Filter, QueryFilter, World};
use tileslide_scenes::{SceneRay, SolidGrid};

use crate::box2d_map::{box2d_world, create_wall_chains, to_box2d, to_position};

/// The grid's walls as chain loops on one static body of a Box2D v3 world (through `boxdd`):
/// every closed boundary loop of the solid cells one `b2ChainDef` loop, holes included, wound
/// so that the one-sided segments face the empty side (see [`create_wall_chains`]). This is
/// how Box2D's docs describe static level geometry: chains, whose segments carry their
/// neighbours as ghost vertices so that movers glide over the seams.
///
/// Each ray is one `b2World_CastRayClosest` (boxdd's `Query::cast_ray_closest`) with the
/// translation `dir · length`, which walks the world's static tree of segments; the distance is
/// the hit fraction times `ray.length`.
///
/// A chain segment stops a ray only from its right side (Box2D skips a segment when the ray's
/// origin is on its left), which is always the empty side here. Two differences from
/// tileslide's answers remain, a handful in a million rays:
///
/// - `b2World_CastRayClosest` ignores a hit at fraction 0 (its "initial overlap"), so a ray
///   that starts exactly on a wall's face and moves into the wall passes through it to the
///   next wall, where tileslide (and parry) report a hit at 0: 3 of dungeon256's million rays,
///   whose origins lie on a grid line (as for [`Box2dBoxes`](super::Box2dBoxes));
/// - Box2D's segment test keeps a hit at a segment's end point and computes it in f32, so a
///   ray that passes outside a wall's convex corner by less than about 1e-6 cells hits the
///   corner: 2 of dungeon256's million rays, 3 of open256's (Box2D's polygon test, clipping
///   the ray against the box's sides, does not).
pub struct Box2dChains {
    world: World,
}

impl Box2dChains {
    /// The name this peer is reported under.
    pub const NAME: &'static str = "box2d-chains";

    /// Builds the world: one static body with the grid's wall loops as chains.
    ///
    /// # Errors
    /// When Box2D refuses the world, the body or a chain.
    pub fn new(grid: &SolidGrid) -> Result<Self, boxdd::Error> {
        let mut world = box2d_world()?;
        create_wall_chains(&mut world, grid, Filter::default())?;
        Ok(Self { world })
    }

    /// Distance in cells along `ray` (whose `dir` must be unit length) to the first wall segment
    /// it meets from the empty side within `ray.length`, or `None` if there is none.
    ///
    /// boxdd reports an error only for non-finite input or a call from inside a Box2D callback;
    /// neither happens with scene rays, and an error would read as a miss (a disagreement in the
    /// benchmark's report, not a silent answer).
    #[inline]
    pub fn cast(&self, ray: &SceneRay) -> Option<f32> {
        cast_closest(&self.world, ray)
    }
}

/// Box2D's closest hit along `ray` in `world` (every shape, Box2D's default query filter), as
/// a distance in cells.
#[inline]
pub(super) fn cast_closest(world: &World, ray: &SceneRay) -> Option<f32> {
    let query = world.query().ok()?;
    let hit = query
        .cast_ray_closest(
            to_position(ray.origin),
            to_box2d(ray.dir * ray.length),
            QueryFilter::default(),
        )
        .ok()??;
    Some(hit.fraction * ray.length)
}

#[cfg(test)]
super::test_grids::ray_peer_tests!(Box2dChains, |grid| Box2dChains::new(grid).unwrap());
