//! The game's hit volumes and what their hits do: the player collects coins (`COLLECT`)
//! and stomps enemies (its feet deal `STOMP`, which only an enemy's top accepts); an
//! enemy's body deals `HIT` to the player's body.

use tileslide::{
    Aabb, Circle, HitEvent, HitObject, HitTypes, HitWorld, Owner, TeamRule, Vec2, Volume,
    VolumeError, VolumeShape,
};

/// The game's own hit type: a stomp, dealt by the player's feet while falling.
pub const STOMP: HitTypes = HitTypes::from_bits(1 << 6);
/// The player's half size, in cells.
pub const PLAYER_HALF: Vec2 = Vec2::new(0.3, 0.45);
/// An enemy's half size, in cells.
pub const ENEMY_HALF: Vec2 = Vec2::new(0.35, 0.3);
/// A coin's radius, in cells.
pub const COIN_RADIUS: f32 = 0.3;
/// How deep the feet and the top strips are, in cells.
const STRIP: f32 = 0.2;

/// Teams: volumes hit only across teams ([`TeamRule`]).
const PLAYER_TEAM: u32 = 0;
const ENEMY_TEAM: u32 = 1;
const COIN_TEAM: u32 = 2;

/// Who an object registered this frame is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Who {
    /// The player.
    Player,
    /// Enemy `i`.
    Enemy(usize),
    /// Coin `i`.
    Coin(usize),
}

/// What this frame's hits did.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Outcome {
    /// Coins collected.
    pub collected: Vec<usize>,
    /// Enemies stomped.
    pub stomped: Vec<usize>,
    /// The player was hit (and stomped nothing this frame).
    pub player_hit: bool,
    /// Every hit event of the frame, accepted or not.
    pub events: Vec<HitEvent>,
}

/// A character-sized object for the hit world: its box, and the strip at its feet (`top:
/// false`) or head (`top: true`) in object-local coordinates, for a world whose up is `up`.
pub struct Boxed {
    /// The object's centre.
    pub center: Vec2,
    /// Its half size, in world units.
    pub half: Vec2,
    /// Its move this frame.
    pub motion: Vec2,
}

impl Boxed {
    fn object(&self, owner: u64, team: u32) -> HitObject {
        let mut object = HitObject::new(Owner(owner), self.center - self.half, self.half * 2.0);
        object.motion = self.motion;
        object.team = team;
        object
    }

    /// The whole box, local: centred at its half size.
    fn body(&self, hit: HitTypes) -> Option<Volume> {
        Volume::rect(self.half, self.half, hit).ok()
    }

    /// The strip at the feet or the head (towards `up` when `top`), local.
    fn strip(&self, up: Vec2, top: bool, depth: f32, hit: HitTypes) -> Option<Volume> {
        let size = self.half * 2.0;
        let high_y = (up.y > 0.0) == top; // the strip is at the large-y side
        let (y0, y1) = if high_y {
            (size.y - depth, size.y)
        } else {
            (0.0, depth)
        };
        // From its corners: the strip's edge must be exactly the box's.
        let strip = Volume {
            shape: VolumeShape::Rect(Aabb {
                min: Vec2::new(0.0, y0),
                max: Vec2::new(size.x, y1),
            }),
            hit,
        };
        strip.check().ok().map(|()| strip)
    }

    /// The strip in world coordinates, for pictures.
    #[must_use]
    pub fn world_strip(&self, up: Vec2, top: bool, scale: f32) -> Option<VolumeShape> {
        let local = self.strip(up, top, STRIP * scale, HitTypes::NONE)?;
        let corner = self.center - self.half;
        match local.shape {
            VolumeShape::Rect(b) => Some(VolumeShape::Rect(Aabb {
                min: b.min + corner,
                max: b.max + corner,
            })),
            // The strip is built as a rect; any other shape has no picture here.
            _ => None,
        }
    }
}

/// Registers the player, the enemies and the coins for this frame, finds the hits and says
/// what they did. `falling`: the player's feet deal stomps.
pub fn exchange(
    world: &mut HitWorld,
    who: &mut Vec<Who>,
    up: Vec2,
    scale: f32,
    player: (&Boxed, bool, bool),
    enemies: &[(usize, Boxed)],
    coins: &[(usize, Vec2)],
) -> Result<Outcome, VolumeError> {
    let (me, falling, invulnerable) = player;
    world.begin_frame();
    who.clear();
    let strip = STRIP * scale;
    let mut object = me.object(0, PLAYER_TEAM);
    object.invulnerable = invulnerable;
    let mut attack: Vec<Volume> = me.body(HitTypes::COLLECT).into_iter().collect();
    if falling {
        attack.extend(me.strip(up, false, strip, STOMP));
    }
    let vulnerable: Vec<Volume> = me.body(HitTypes::HIT).into_iter().collect();
    world.register(object, &attack, &vulnerable)?;
    who.push(Who::Player);
    for (i, enemy) in enemies {
        let attack: Vec<Volume> = enemy.body(HitTypes::HIT).into_iter().collect();
        let top: Vec<Volume> = enemy.strip(up, true, strip, STOMP).into_iter().collect();
        world.register(enemy.object(1 + *i as u64, ENEMY_TEAM), &attack, &top)?;
        who.push(Who::Enemy(*i));
    }
    let radius = COIN_RADIUS * scale;
    for (i, center) in coins {
        let coin = Volume::circle(Vec2::splat(radius), radius, HitTypes::COLLECT).ok();
        let mut object = HitObject::new(
            Owner(1_000_000 + *i as u64),
            *center - Vec2::splat(radius),
            Vec2::splat(2.0 * radius),
        );
        object.team = COIN_TEAM;
        world.register(object, &[], coin.as_slice())?;
        who.push(Who::Coin(*i));
    }
    let events = world.detect(&mut TeamRule).to_vec();
    Ok(outcome(events, who))
}

fn outcome(events: Vec<HitEvent>, who: &[Who]) -> Outcome {
    let mut out = Outcome::default();
    let mut hit = false;
    for e in events.iter().filter(|e| e.accepted) {
        let attacker = who.get(e.attacker.0 as usize);
        let victim = who.get(e.victim.0 as usize);
        match (attacker, victim) {
            (Some(Who::Player), Some(Who::Coin(i))) => out.collected.push(*i),
            (Some(Who::Player), Some(Who::Enemy(i))) if e.hit_type.matches(STOMP) => {
                out.stomped.push(*i);
            }
            (Some(Who::Enemy(_)), Some(Who::Player)) => hit = true,
            _ => {}
        }
    }
    // A stomp lands before the stomped enemy's body can hurt.
    out.player_hit = hit && out.stomped.is_empty();
    out.events = events;
    out
}

/// The circle of a coin, for pictures.
#[must_use]
pub fn coin_circle(center: Vec2, scale: f32) -> Circle {
    Circle::new(center, COIN_RADIUS * scale)
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    fn boxed(center: Vec2, half: Vec2, motion: Vec2) -> Boxed {
        Boxed {
            center,
            half,
            motion,
        }
    }

    #[test]
    fn falling_feet_stomp_and_the_stomp_spares_the_player() {
        let mut world = HitWorld::new();
        let mut who = Vec::new();
        let up = Vec2::NEG_Y;
        // The player falls onto the enemy's top (y down): feet strip meets the top strip.
        let player = boxed(Vec2::new(0.0, 0.0), PLAYER_HALF, Vec2::new(0.0, 0.2));
        let enemy = boxed(Vec2::new(0.0, 0.7), ENEMY_HALF, Vec2::ZERO);
        let out = exchange(
            &mut world,
            &mut who,
            up,
            1.0,
            (&player, true, false),
            &[(0, enemy)],
            &[(0, Vec2::new(0.2, 0.0))],
        )
        .unwrap();
        assert_eq!(out.stomped, vec![0]);
        assert_eq!(out.collected, vec![0]);
        assert!(!out.player_hit);
    }

    #[test]
    fn walking_into_an_enemy_is_a_hit_unless_invulnerable() {
        let mut world = HitWorld::new();
        let mut who = Vec::new();
        let player = boxed(Vec2::new(0.0, 0.0), PLAYER_HALF, Vec2::X * 0.1);
        let enemy = || (0, boxed(Vec2::new(0.6, 0.15), ENEMY_HALF, Vec2::ZERO));
        let hit = |invulnerable, world: &mut HitWorld, who: &mut Vec<Who>| {
            exchange(
                world,
                who,
                Vec2::NEG_Y,
                1.0,
                (&player, false, invulnerable),
                &[enemy()],
                &[],
            )
            .unwrap()
        };
        let out = hit(false, &mut world, &mut who);
        assert!(out.player_hit && out.stomped.is_empty());
        assert!(!hit(true, &mut world, &mut who).player_hit);
    }
}
