//! Fights: melee swings and imps' fireballs, aimed here and landed through tileslide's
//! hit volumes ([`Hits`]): a swing is an attack volume in front of the fighter for a few
//! steps, a fireball an attack volume swept along its step (stopped by the first wall a
//! ray cast meets). Then damage and death.

use hecs::{Entity, World};
use tileslide::{Bodies, QueryFilter, Ray};

use crate::brains::{IMP_RANGE, Sightings};
use crate::components::{
    Body, Carrying, Cooldown, FIREBALL_RADIUS, Fireball, Health, Kind, Swing, Team,
};
use crate::error::GameError;
use crate::events::Event;
use crate::hits::{Blow, Hits, Target};
use crate::level::Level;
use crate::spawn::Ids;
use crate::step::{DT, STEPS_PER_SECOND};

const FIREBALL_SPEED: f32 = 8.0;
const FIREBALL_DAMAGE: i32 = 6;
const FIREBALL_TTL: u32 = 2 * STEPS_PER_SECOND;
/// Steps a swing's attack volume lasts.
const SWING_STEPS: u32 = 6;
/// How far beyond touching an enemy may be for a fighter to swing at it (cells).
const SWING_REACH: f32 = 0.15;

fn melee(kind: Kind) -> (i32, u32) {
    match kind {
        Kind::Hero => (5, 24),
        Kind::Skeleton => (4, 30),
        Kind::Imp => (1, 30),
    }
}

/// Starts swings at enemies within reach and shoots fireballs from imps that see a hero.
/// Whether a swing lands is for the volumes to say ([`strike`]).
pub fn attack(
    world: &mut World,
    level: &Level,
    ids: &mut Ids,
    seen: &Sightings,
) -> Result<(), GameError> {
    let mut shots = Vec::new();
    let mut swings = Vec::new();
    for &(_, entity, team, kind, p) in &seen.all {
        let Ok(mut cooldown) = world.get::<&mut Cooldown>(entity) else {
            continue;
        };
        if cooldown.0 > 0 {
            cooldown.0 -= 1;
            continue;
        }
        if kind == Kind::Imp {
            if let Some((_, q, _)) = seen.nearest_enemy(level, team, p, IMP_RANGE) {
                let dir = (q - p).normalize_or_zero();
                shots.push((
                    p + dir * (kind.radius() + FIREBALL_RADIUS + 0.02),
                    dir * FIREBALL_SPEED,
                ));
                cooldown.0 = 45;
            }
            continue;
        }
        let within = seen
            .all
            .iter()
            .find(|o| o.2 != team && o.4.distance(p) <= kind.radius() + o.3.radius() + SWING_REACH);
        if let Some(&(.., q)) = within {
            let (damage, wait) = melee(kind);
            cooldown.0 = wait;
            swings.push((
                entity,
                Swing {
                    id: ids.next().0,
                    direction: (q - p).normalize_or_zero(),
                    damage,
                    steps_left: SWING_STEPS,
                },
            ));
        }
    }
    for (entity, swing) in swings {
        let _ = world.insert_one(entity, swing);
    }
    for (position, velocity) in shots {
        world.spawn((
            Fireball {
                key: ids.next().0,
                position,
                velocity,
                ttl: FIREBALL_TTL,
            },
            Team::Keeper,
        ));
    }
    Ok(())
}

/// After the resolver's step: moves fireballs (each stops at the first wall its step
/// meets), registers every fighter's circle, swing and every fireball's swept circle in
/// `hits`, and turns the hits into [`Event::Damage`]. Fireballs that hit, hit a wall or
/// burn out are gone.
///
/// # Errors
/// A bad swing volume, or a fighter or fireball the hit volumes refuse (bugs).
pub fn strike(
    world: &mut World,
    level: &Level,
    hits: &mut Hits,
    seen: &Sightings,
    events: &mut Vec<Event>,
) -> Result<(), GameError> {
    hits.begin();
    let mut ended = Vec::new();
    for &(id, entity, team, kind, position) in &seen.all {
        let blow = match world.get::<&mut Swing>(entity) {
            Ok(mut swing) => {
                swing.steps_left = swing.steps_left.saturating_sub(1);
                if swing.steps_left == 0 {
                    ended.push(entity);
                }
                Some(Blow {
                    swing: swing.id,
                    direction: swing.direction,
                    damage: swing.damage,
                })
            }
            Err(_) => None,
        };
        let target = Target {
            key: id.0,
            entity,
            team,
            kind,
            position,
        };
        hits.fighter(target, blow)?;
    }
    for entity in ended {
        let _ = world.remove_one::<Swing>(entity);
    }
    let mut flying: Vec<_> = world
        .query_mut::<(Entity, &mut Fireball, &Team)>()
        .into_iter()
        .collect();
    flying.sort_by_key(|(_, ball, _)| ball.key);
    let mut spent = Vec::new();
    for (entity, ball, team) in flying {
        let from = ball.position;
        let mut to = from + ball.velocity * DT;
        let wall = level
            .map
            .cast_ray(Ray::between(from, to), &QueryFilter::default());
        if let Some(hit) = &wall {
            to = hit.point;
        }
        ball.ttl = ball.ttl.saturating_sub(1);
        ball.position = to;
        hits.fireball(ball.key, entity, *team, from, to, FIREBALL_DAMAGE)?;
        if wall.is_some() || ball.ttl == 0 {
            spent.push(entity);
        }
    }
    hits.detect(events);
    spent.extend_from_slice(hits.spent());
    for entity in spent {
        let _ = world.despawn(entity);
    }
    Ok(())
}

/// Applies this step's damage; the dead leave the world and the resolver.
pub fn bury(world: &mut World, bodies: &mut Bodies, events: &mut Vec<Event>) {
    let mut dead: Vec<Entity> = Vec::new();
    for event in events.iter() {
        if let Event::Damage { target, amount } = event
            && let Ok(mut health) = world.get::<&mut Health>(*target)
        {
            health.hp -= amount;
            if health.hp <= 0 && !dead.contains(target) {
                dead.push(*target);
            }
        }
    }
    for entity in dead {
        let team = world
            .get::<&Team>(entity)
            .map(|t| *t)
            .unwrap_or(Team::Keeper);
        let carried = world.get::<&Carrying>(entity).is_ok();
        if let Ok(body) = world.get::<&Body>(entity).map(|b| b.0) {
            let _ = bodies.remove(body);
        }
        let _ = world.despawn(entity);
        events.push(Event::Died { team, carried });
    }
}
