//! The treasure: heroes who reach it pick up a piece and turn for the exit; heroes who
//! reach the exit leave the dungeon.

use hecs::{Entity, World};
use tileslide::Bodies;

use crate::components::{Body, Carrying, Goal, HeroBrain};
use crate::events::Event;
use crate::level::Level;

/// How near a hero must be to grab the treasure or leave.
const REACH: f32 = 1.2;

/// Pick-ups and escapes; `left` is the pile, decremented per piece taken.
pub fn run(
    world: &mut World,
    bodies: &mut Bodies,
    level: &Level,
    left: &mut u32,
    events: &mut Vec<Event>,
) {
    let mut taken: Vec<Entity> = Vec::new();
    let mut gone = Vec::new();
    let mut heroes: Vec<_> = world
        .query_mut::<(
            Entity,
            &crate::components::Id,
            &Body,
            &mut HeroBrain,
            Option<&Carrying>,
        )>()
        .into_iter()
        .map(|(e, id, body, brain, carrying)| (*id, e, body.0, brain, carrying.is_some()))
        .collect();
    heroes.sort_by_key(|h| h.0);
    for (_, entity, body, brain, carrying) in heroes {
        let Ok(p) = bodies.get(body).map(|b| b.position()) else {
            continue;
        };
        match brain.goal {
            Goal::Treasure if *left == 0 => brain.goal = Goal::Exit,
            Goal::Treasure if p.distance(level.treasure) <= REACH => {
                *left -= 1;
                brain.goal = Goal::Exit;
                taken.push(entity);
            }
            Goal::Exit if p.distance(level.exit) <= REACH => gone.push((entity, body, carrying)),
            _ => {}
        }
    }
    for entity in taken {
        let _ = world.insert_one(entity, Carrying);
        events.push(Event::TreasureTaken { by: entity });
    }
    for (hero, body, carried) in gone {
        let _ = bodies.remove(body);
        let _ = world.despawn(hero);
        events.push(Event::Escaped { hero, carried });
    }
}

/// Pieces carried by heroes who died go back on the pile.
pub fn recover(left: &mut u32, events: &[Event]) {
    for event in events {
        if let Event::Died { carried: true, .. } = event {
            *left += 1;
        }
    }
}
