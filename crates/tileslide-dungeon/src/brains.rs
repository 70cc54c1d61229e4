//! Deciding moves: every fighter proposes one to the resolver each step. Heroes follow the
//! flow field to their goal unless an enemy is close; skeletons charge heroes they see;
//! imps stand and shoot; idle creatures walk the path back to their post.

use hecs::{Entity, World};
use tileslide::{Bodies, Vec2};

use crate::DT;
use crate::components::{Body, CreatureBrain, Goal, HeroBrain, Id, Kind, Team};
use crate::level::Level;

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

/// Proposes every hero's move.
pub fn heroes(world: &mut World, bodies: &mut Bodies, level: &Level, seen: &Sightings) {
    for (body, brain, kind) in world.query_mut::<(&Body, &HeroBrain, &Kind)>() {
        let Ok(p) = bodies.get(body.0).map(|b| b.position()) else {
            continue;
        };
        let motion = match seen.nearest_enemy(level, Team::Heroes, p, HERO_SIGHT) {
            Some((_, q, other)) => {
                towards(p, q, kind.speed(), kind.radius() + other.radius() + 0.05)
            }
            None => {
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
    while *next < path.points().len() && path.points()[*next].distance(p) < 0.05 {
        *next += 1;
    }
    match path.points().get(*next) {
        Some(&target) => towards(p, target, speed, 0.0),
        None => Vec2::ZERO,
    }
}
