//! Fights: melee between touching enemies, imps' fireballs (circles swept along their
//! flight each step, stopped by the first wall a ray cast meets), damage and death.
//! Hits are distance checks, not tileslide's volumes (see docs/dungeon.md).

use hecs::{Entity, World};
use tileslide::{Bodies, Ray, RayFilter, Vec2};

use crate::brains::{IMP_RANGE, Sightings};
use crate::components::{Body, Carrying, Cooldown, FIREBALL_RADIUS, Fireball, Health, Kind, Team};
use crate::events::Event;
use crate::level::Level;
use crate::{DT, STEPS_PER_SECOND};

const FIREBALL_SPEED: f32 = 8.0;
const FIREBALL_DAMAGE: i32 = 6;
const FIREBALL_TTL: u32 = 2 * STEPS_PER_SECOND;

fn melee(kind: Kind) -> (i32, u32) {
    match kind {
        Kind::Hero => (5, 24),
        Kind::Skeleton => (4, 30),
        Kind::Imp => (1, 30),
    }
}

/// Melee blows between touching enemies and new fireballs from imps that see a hero.
pub fn attack(world: &mut World, level: &Level, seen: &Sightings, events: &mut Vec<Event>) {
    let mut shots = Vec::new();
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
        let touching = seen
            .all
            .iter()
            .find(|o| o.2 != team && o.4.distance(p) <= kind.radius() + o.3.radius() + 0.1);
        if let Some(&(_, target, ..)) = touching {
            let (amount, wait) = melee(kind);
            events.push(Event::Damage { target, amount });
            cooldown.0 = wait;
        }
    }
    for (position, velocity) in shots {
        world.spawn((
            Fireball {
                position,
                velocity,
                ttl: FIREBALL_TTL,
            },
            Team::Keeper,
        ));
    }
}

/// Moves fireballs: each sweeps its step, stops at the first wall or hero it meets.
pub fn fly(world: &mut World, level: &Level, seen: &Sightings, events: &mut Vec<Event>) {
    let mut spent = Vec::new();
    let mut flying: Vec<_> = world
        .query_mut::<(Entity, &mut Fireball)>()
        .into_iter()
        .collect();
    flying.sort_by(|a, b| {
        a.1.position
            .x
            .total_cmp(&b.1.position.x)
            .then(a.1.position.y.total_cmp(&b.1.position.y))
    });
    for (entity, ball) in flying {
        let from = ball.position;
        let mut to = from + ball.velocity * DT;
        let wall = level
            .map
            .cast_ray(Ray::between(from, to), &RayFilter::default());
        if let Some(hit) = &wall {
            to = hit.point;
        }
        let victim = seen
            .all
            .iter()
            .filter(|s| s.2 == Team::Heroes)
            .map(|s| (s, t_of_closest(from, to, s.4)))
            .filter(|(s, t)| from.lerp(to, *t).distance(s.4) <= s.3.radius() + FIREBALL_RADIUS)
            .min_by(|a, b| a.1.total_cmp(&b.1));
        ball.ttl = ball.ttl.saturating_sub(1);
        ball.position = to;
        if let Some((s, _)) = victim {
            events.push(Event::Damage {
                target: s.1,
                amount: FIREBALL_DAMAGE,
            });
            spent.push(entity);
        } else if wall.is_some() || ball.ttl == 0 {
            spent.push(entity);
        }
    }
    for entity in spent {
        let _ = world.despawn(entity);
    }
}

/// The `t` in [0, 1] of the point of segment `a`–`b` closest to `p`.
fn t_of_closest(a: Vec2, b: Vec2, p: Vec2) -> f32 {
    let d = b - a;
    let len2 = d.length_squared();
    if len2 <= f32::EPSILON {
        0.0
    } else {
        ((p - a).dot(d) / len2).clamp(0.0, 1.0)
    }
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
