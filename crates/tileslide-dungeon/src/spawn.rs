//! Putting fighters into the world: an entity with its components and a body.

use hecs::{Entity, World};
use tileslide::{Bodies, BodyDesc, BodyShape, Vec2};

use crate::components::{Body, Cooldown, CreatureBrain, Goal, Health, HeroBrain, Id, Kind};
use crate::error::GameError;

/// Hands out [`Id`]s in spawn order.
#[derive(Clone, Debug, Default)]
pub struct Ids {
    next: u64,
}

impl Ids {
    /// The next id.
    pub fn next(&mut self) -> Id {
        self.next += 1;
        Id(self.next)
    }
}

/// Spawns a fighter of `kind` with `max_hp` hit points at `at` (the caller checked the
/// place is free).
///
/// # Errors
/// A body error (a bad radius or position: a bug).
pub fn fighter(
    world: &mut World,
    bodies: &mut Bodies,
    ids: &mut Ids,
    kind: Kind,
    at: Vec2,
    max_hp: i32,
) -> Result<Entity, GameError> {
    let handle = bodies.add(BodyDesc::new(at, BodyShape::circle(kind.radius())?))?;
    let max = max_hp;
    let common = (
        ids.next(),
        Body(handle),
        Health { hp: max, max },
        kind.team(),
        kind,
        Cooldown(0),
    );
    let entity = world.spawn(common);
    // The brain goes in after: hecs moves the entity to its final archetype once.
    let _ = match kind {
        Kind::Hero => world.insert_one(
            entity,
            HeroBrain {
                goal: Goal::Treasure,
                exploring: None,
            },
        ),
        Kind::Skeleton | Kind::Imp => world.insert_one(
            entity,
            CreatureBrain {
                post: at,
                way_home: None,
            },
        ),
    };
    Ok(entity)
}
