//! Deciding moves: every fighter proposes one to the resolver each step. Heroes follow the
//! flow field to their goal unless an enemy is close; skeletons charge heroes they see;
//! imps stand and shoot; idle creatures walk the path back to their post.

use hecs::{Entity, World};
use tileslide::{Bodies, Vec2};

use crate::components::{Body, CreatureBrain, Goal, HeroBrain, Id, Kind, Team};
use crate::explore::centre_of;
use crate::level::Level;
use crate::step::DT;

/// How far heroes notice enemies.
const HERO_SIGHT: f32 = 3.5;
/// How far skeletons notice heroes.
const SKELETON_SIGHT: f32 = 8.0;
/// How far imps shoot.
pub const IMP_RANGE: f32 = 9.0;

/// Where every fighter is, sorted by id: what brains look at.
pub struct Sightings {
    /// (id, entity, team, kind, position, radius), by id.
    pub all: Vec<(Id, Entity, Team, Kind, Vec2)>,
}

impl Sightings {
    /// Everyone's current place.
    #[must_use]
    pub fn take(world: &World, bodies: &Bodies) -> Self {
        let mut all: Vec<_> = world
            .query::<(Entity, &Id, &Body, &Team, &Kind)>()
            .iter()
            .filter_map(|(e, id, body, team, kind)| {
                bodies
                    .get(body.0)
                    .ok()
                    .map(|b| (*id, e, *team, *kind, b.position()))
            })
            .collect();
        all.sort_by_key(|s| s.0);
        Self { all }
    }

    /// The nearest enemy of `team` within `range` of `p` that `p` sees (ties: lower id).
    #[must_use]
    pub fn nearest_enemy(
        &self,
        level: &Level,
        team: Team,
        p: Vec2,
        range: f32,
    ) -> Option<(Entity, Vec2, Kind)> {
        self.all
            .iter()
            .filter(|s| s.2 != team && s.4.distance(p) <= range)
            .filter(|s| level.sees(p, s.4))
            .min_by(|a, b| a.4.distance(p).total_cmp(&b.4.distance(p)))
            .map(|s| (s.1, s.4, s.3))
    }
}

/// A move of `speed` for one step towards `target`, stopping `short` before it.
fn towards(p: Vec2, target: Vec2, speed: f32, short: f32) -> Vec2 {
    let d = target - p;
    let len = d.length();
    let step = (len - short).clamp(0.0, speed * DT);
    if len > 1e-6 {
        d / len * step
    } else {
        Vec2::ZERO
    }
}

/// Steps between a hero's looks around (spread over heroes by id).
const LOOK_EVERY: u64 = 5;

/// Proposes every hero's move: fight an enemy in sight; else, once a hero has seen the
/// treasure (or when carrying it out), follow the flow field to the goal; else explore
/// towards the nearest frontier square (see [`crate::explore`]).
pub fn heroes(
    world: &mut World,
    bodies: &mut Bodies,
    level: &mut Level,
    seen: &Sightings,
    step: u64,
) {
    for (body, brain, kind, id) in world.query_mut::<(&Body, &mut HeroBrain, &Kind, &Id)>() {
        let Ok(p) = bodies.get(body.0).map(|b| b.position()) else {
            continue;
        };
        if (step + id.0).is_multiple_of(LOOK_EVERY) {
            let Level {
                map,
                explored,
                treasure,
                ..
            } = &mut *level;
            let sees = |a: Vec2, b: Vec2| {
                map.cast_ray(
                    tileslide::Ray::between(a, b),
                    &tileslide::QueryFilter::default(),
                )
                .is_none()
            };
            explored.look(map, p, *treasure, sees);
        }
        let motion = match seen.nearest_enemy(level, Team::Heroes, p, HERO_SIGHT) {
            Some((_, q, other)) => {
                towards(p, q, kind.speed(), kind.radius() + other.radius() + 0.05)
            }
            None if brain.goal == Goal::Treasure && !level.explored.treasure_seen() => {
                explore(brain, level, p, kind.radius(), kind.speed())
            }
            None => {
                brain.exploring = None;
                let field = match brain.goal {
                    Goal::Treasure => &level.to_treasure,
                    Goal::Exit => &level.to_exit,
                };
                field
                    .direction(&level.nav, &level.map, p)
                    .ok()
                    .flatten()
                    .map_or(Vec2::ZERO, |d| d * kind.speed() * DT)
            }
        };
        let _ = bodies.propose(body.0, motion);
    }
}

/// The next step of a hero exploring: along its path to its frontier square while that is
/// still one, else to the nearest frontier square it finds a path to (none: it waits).
fn explore(brain: &mut HeroBrain, level: &mut Level, p: Vec2, radius: f32, speed: f32) -> Vec2 {
    let current = brain.exploring.as_ref().is_some_and(|(cell, path, next)| {
        *next < path.points().len() && level.explored.is_frontier(&level.map, *cell)
    });
    if !current {
        brain.exploring = None;
        let Some(cell) = level.explored.nearest_frontier(&level.map, p) else {
            return Vec2::ZERO;
        };
        let target = centre_of(&level.map, cell);
        match level.nav.find_path(&level.map, p, target, radius) {
            Ok(Some(path)) => brain.exploring = Some((cell, path, 1)),
            _ => {
                level.explored.dead_end(cell);
                return Vec2::ZERO;
            }
        }
    }
    let Some((_, path, next)) = &mut brain.exploring else {
        return Vec2::ZERO;
    };
    follow(path, next, p, speed)
}

/// The next step along `path` from `p`, `next` being the next point to reach.
fn follow(path: &tileslide::NavPath, next: &mut usize, p: Vec2, speed: f32) -> Vec2 {
    while *next < path.points().len() && path.points()[*next].distance(p) < 0.05 {
        *next += 1;
    }
    match path.points().get(*next) {
        Some(&target) => towards(p, target, speed, 0.0),
        None => Vec2::ZERO,
    }
}

/// Proposes every creature's move.
pub fn creatures(world: &mut World, bodies: &mut Bodies, level: &mut Level, seen: &Sightings) {
    for (body, brain, kind) in world.query_mut::<(&Body, &mut CreatureBrain, &Kind)>() {
        let Ok(p) = bodies.get(body.0).map(|b| b.position()) else {
            continue;
        };
        let sight = if *kind == Kind::Imp {
            IMP_RANGE
        } else {
            SKELETON_SIGHT
        };
        let motion = match seen.nearest_enemy(level, Team::Keeper, p, sight) {
            Some((_, q, other)) if *kind == Kind::Skeleton => {
                brain.way_home = None;
                towards(p, q, kind.speed(), kind.radius() + other.radius() + 0.05)
            }
            Some(_) => Vec2::ZERO,
            None => walk_home(brain, level, p, kind.radius(), kind.speed()),
        };
        let _ = bodies.propose(body.0, motion);
    }
}

/// The next step along the creature's path home, finding the path first if needed.
fn walk_home(
    brain: &mut CreatureBrain,
    level: &mut Level,
    p: Vec2,
    radius: f32,
    speed: f32,
) -> Vec2 {
    if p.distance(brain.post) < 0.3 {
        brain.way_home = None;
        return Vec2::ZERO;
    }
    if brain.way_home.is_none() {
        brain.way_home = level
            .nav
            .find_path(&level.map, p, brain.post, radius)
            .ok()
            .flatten()
            .map(|path| (path, 1));
    }
    let Some((path, next)) = &mut brain.way_home else {
        return Vec2::ZERO;
    };
    follow(path, next, p, speed)
}
