//! Hits through tileslide's volumes: every step each fighter registers its circle as a
//! vulnerability volume and, while it swings, an attack volume in front of it; every
//! fireball registers its circle as an attack volume moving along its step, so
//! [`HitWorld`]'s exact swept test catches a target the fireball passes through between
//! steps, and its time of impact says which target the fireball reached first. The hit
//! events become [`Event::Damage`].

use hecs::Entity;
use tileslide::{HitObject, HitTypes, HitWorld, Owner, TeamRule, Vec2, Volume};

use crate::components::{Kind, Team};
use crate::error::GameError;
use crate::events::Event;

/// How far ahead of the fighter's edge the middle of its swing is (cells).
const SWING_AHEAD: f32 = 0.2;
/// Radius of a swing's attack volume (cells).
const SWING_RADIUS: f32 = 0.25;

/// A fighter's body this step, for [`Hits::fighter`].
#[derive(Clone, Copy, Debug)]
pub struct Target {
    /// The game's stable id (the hit volumes' owner).
    pub key: u64,
    /// The entity.
    pub entity: Entity,
    /// Its side.
    pub team: Team,
    /// Its kind (its circle's radius).
    pub kind: Kind,
    /// Its centre.
    pub position: Vec2,
}

/// A swing under way, for [`Hits::fighter`].
#[derive(Clone, Copy, Debug)]
pub struct Blow {
    /// The swing's id: each victim is hit at most once while it lasts.
    pub swing: u64,
    /// Which way it swings (unit length).
    pub direction: Vec2,
    /// Damage per hit.
    pub damage: i32,
}

/// What a registered object is to the game.
#[derive(Clone, Copy, Debug)]
enum Registered {
    /// A fighter, swinging `damage` or not swinging (0).
    Fighter { entity: Entity, damage: i32 },
    /// A fireball, dealing `damage`.
    Fireball { entity: Entity, damage: i32 },
}

/// The step's hit volumes and the [`HitWorld`] that tests them (kept between steps for
/// its sweep-and-prune order and its swings).
pub struct Hits {
    world: HitWorld,
    registered: Vec<Registered>,
    /// Fireballs that hit someone this step.
    spent: Vec<Entity>,
    /// Body circles of heroes, skeletons and imps.
    bodies: [Volume; 3],
    fireball: Volume,
}

/// The team number [`TeamRule`] compares.
fn team_number(team: Team) -> u32 {
    match team {
        Team::Heroes => 1,
        Team::Keeper => 2,
    }
}

impl Hits {
    /// The body volume of every kind of fighter and a fireball's of `fireball_radius`.
    ///
    /// # Errors
    /// A bad radius (a bug).
    pub fn new(fireball_radius: f32) -> Result<Self, GameError> {
        let body = |kind: Kind| Volume::circle(Vec2::ZERO, kind.radius(), HitTypes::HIT);
        Ok(Self {
            world: HitWorld::new(),
            registered: Vec::new(),
            spent: Vec::new(),
            bodies: [body(Kind::Hero)?, body(Kind::Skeleton)?, body(Kind::Imp)?],
            fireball: Volume::circle(Vec2::ZERO, fireball_radius, HitTypes::HIT)?,
        })
    }

    /// Starts a step: last step's objects are forgotten, swings not registered again end.
    pub fn begin(&mut self) {
        self.world.begin_frame();
        self.registered.clear();
        self.spent.clear();
    }

    /// Registers a fighter's circle, and its swing's volume if it swings. Volumes are
    /// object-local about the centre (size zero, never mirrored: a swing is aimed by its
    /// direction instead).
    ///
    /// # Errors
    /// A non-finite swing direction (a bug).
    pub fn fighter(&mut self, target: Target, blow: Option<Blow>) -> Result<(), GameError> {
        let object = HitObject {
            team: team_number(target.team),
            swing: blow.map(|b| b.swing),
            ..HitObject::new(Owner(target.key), target.position, Vec2::ZERO)
        };
        let body = self.bodies[match target.kind {
            Kind::Hero => 0,
            Kind::Skeleton => 1,
            Kind::Imp => 2,
        }];
        let attack = match blow {
            Some(b) => Some(Volume::circle(
                b.direction * (target.kind.radius() + SWING_AHEAD),
                SWING_RADIUS,
                HitTypes::HIT,
            )?),
            None => None,
        };
        self.world
            .register(object, attack.as_slice(), std::slice::from_ref(&body))?;
        self.registered.push(Registered::Fighter {
            entity: target.entity,
            damage: blow.map_or(0, |b| b.damage),
        });
        Ok(())
    }

    /// Registers a fireball of `team` that moved from `from` to `to` this step.
    ///
    /// # Errors
    /// A position or move the hit volumes refuse (beyond `MAX_COORD`: a bug).
    pub fn fireball(
        &mut self,
        key: u64,
        entity: Entity,
        team: Team,
        from: Vec2,
        to: Vec2,
        damage: i32,
    ) -> Result<(), GameError> {
        let object = HitObject {
            team: team_number(team),
            motion: to - from,
            ..HitObject::new(Owner(key), to, Vec2::ZERO)
        };
        self.world
            .register(object, std::slice::from_ref(&self.fireball), &[])?;
        self.registered
            .push(Registered::Fireball { entity, damage });
        Ok(())
    }

    /// Tests the step's volumes (teams: heroes hit creatures and the other way round) and
    /// turns the accepted hits into [`Event::Damage`]. A fireball hits one fighter: of those
    /// its path meets, the first it reaches (the least time of impact along its step; on
    /// equal times, the first registered).
    pub fn detect(&mut self, events: &mut Vec<Event>) {
        // Per fireball (by its index in `registered`): the victim it reaches first, and when.
        let mut fireball_hits: Vec<(usize, Entity, f32)> = Vec::new();
        self.world.detect(&mut TeamRule);
        for hit in self.world.drain_events() {
            if !hit.accepted {
                continue;
            }
            let (a, v) = (hit.attacker.0 as usize, hit.victim.0 as usize);
            let (Some(attacker), Some(Registered::Fighter { entity: victim, .. })) =
                (self.registered.get(a), self.registered.get(v))
            else {
                continue;
            };
            match *attacker {
                Registered::Fighter { damage, .. } => events.push(Event::Damage {
                    target: *victim,
                    amount: damage,
                }),
                Registered::Fireball { .. } => match fireball_hits.iter_mut().find(|h| h.0 == a) {
                    Some(first) if hit.t < first.2 => *first = (a, *victim, hit.t),
                    Some(_) => {}
                    None => fireball_hits.push((a, *victim, hit.t)),
                },
            }
        }
        for (a, victim, _) in fireball_hits {
            if let Some(Registered::Fireball { entity, damage, .. }) = self.registered.get(a) {
                events.push(Event::Damage {
                    target: victim,
                    amount: *damage,
                });
                self.spent.push(*entity);
            }
        }
    }

    /// Fireballs that hit someone in the last [`detect`](Self::detect).
    #[must_use]
    pub fn spent(&self) -> &[Entity] {
        &self.spent
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hero(world: &mut hecs::World, key: u64, x: f32) -> Target {
        hero_at(world, key, Vec2::new(x, 0.0))
    }

    fn hero_at(world: &mut hecs::World, key: u64, position: Vec2) -> Target {
        Target {
            key,
            entity: world.spawn(()),
            team: Team::Heroes,
            kind: Kind::Hero,
            position,
        }
    }

    fn damage(events: &[Event]) -> Vec<(Entity, i32)> {
        events
            .iter()
            .filter_map(|e| match e {
                Event::Damage { target, amount } => Some((*target, *amount)),
                _ => None,
            })
            .collect()
    }

    /// What [`fire_across`] saw.
    struct Shot {
        heroes: Vec<Entity>,
        ball: Entity,
        dealt: Vec<(Entity, i32)>,
        spent: Vec<Entity>,
    }

    /// Heroes at `xs` on the x axis, a fireball from x = 2 to x = 8 in one step.
    fn fire_across(xs: &[f32]) -> Shot {
        let at: Vec<_> = xs.iter().map(|&x| Vec2::new(x, 0.0)).collect();
        fire_across_heroes_at(&at)
    }

    /// Heroes at `at`, a fireball from (2, 0) to (8, 0) in one step.
    fn fire_across_heroes_at(at: &[Vec2]) -> Shot {
        let mut world = hecs::World::new();
        let mut hits = Hits::new(0.12).unwrap();
        let heroes: Vec<_> = (1..)
            .zip(at)
            .map(|(k, &p)| hero_at(&mut world, k, p))
            .collect();
        let ball = world.spawn(());
        hits.begin();
        for &h in &heroes {
            hits.fighter(h, None).unwrap();
        }
        let (from, to) = (Vec2::new(2.0, 0.0), Vec2::new(8.0, 0.0));
        hits.fireball(99, ball, Team::Keeper, from, to, 6).unwrap();
        let mut events = Vec::new();
        hits.detect(&mut events);
        Shot {
            heroes: heroes.iter().map(|h| h.entity).collect(),
            ball,
            dealt: damage(&events),
            spent: hits.spent().to_vec(),
        }
    }

    #[test]
    fn a_fast_fireball_cannot_pass_through_a_hero_between_steps() {
        // Both ends of the step (3 cells either side of the hero) miss its circle.
        let shot = fire_across(&[5.0]);
        assert_eq!(shot.dealt, vec![(shot.heroes[0], 6)]);
        assert_eq!(shot.spent, vec![shot.ball]);
    }

    #[test]
    fn a_fireball_hits_only_the_first_hero_on_its_path() {
        let shot = fire_across(&[6.0, 4.0]);
        assert_eq!(shot.dealt, vec![(shot.heroes[1], 6)]);
    }

    #[test]
    fn a_fireball_hits_the_hero_it_reaches_first_not_the_nearest_centre() {
        // Hero 0 stands 0.35 off the path at x = 4.5: the ball (reach 0.3 + 0.12) touches
        // it when its centre is at 4.5 − √(0.42² − 0.35²) ≈ 4.27. Hero 1 stands on the path
        // at x = 4.6: touched at 4.6 − 0.42 = 4.18, first, though its centre is farther
        // from where the ball started (2.6 against 2.52).
        let shot = fire_across_heroes_at(&[Vec2::new(4.5, 0.35), Vec2::new(4.6, 0.0)]);
        assert_eq!(shot.dealt, vec![(shot.heroes[1], 6)]);
        assert_eq!(shot.spent, vec![shot.ball]);
    }

    #[test]
    fn a_swing_hits_each_enemy_once_and_never_its_own_side() {
        let mut world = hecs::World::new();
        let mut hits = Hits::new(0.12).unwrap();
        let swinger = hero(&mut world, 1, 0.0);
        let friend = hero(&mut world, 2, 0.6);
        let foe = Target {
            key: 3,
            entity: world.spawn(()),
            team: Team::Keeper,
            kind: Kind::Skeleton,
            position: Vec2::new(0.0, 0.65),
        };
        let mut landed = Vec::new();
        for step in 0..3 {
            let direction = if step == 0 { Vec2::X } else { Vec2::Y };
            let blow = Blow {
                swing: 10,
                direction,
                damage: 5,
            };
            hits.begin();
            hits.fighter(swinger, Some(blow)).unwrap();
            hits.fighter(friend, None).unwrap();
            hits.fighter(foe, None).unwrap();
            let mut events = Vec::new();
            hits.detect(&mut events);
            landed.extend(damage(&events));
        }
        assert_eq!(landed, vec![(foe.entity, 5)]);
    }
}
