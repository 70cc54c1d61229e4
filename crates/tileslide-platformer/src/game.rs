//! The game: a fixed step that moves the platform, the enemies and the player with
//! tileslide's controller, exchanges hits through a `HitWorld`, and audits the result.

use thiserror::Error;
use tileslide::{
    Character, CharacterShape, Contacts, ControllerConfig, ControllerError, HitEvent, HitWorld,
    MapError, MoveOptions, Owner, QueryFilter, Ray, Segment, SegmentFlags, SegmentSource,
    TemporarySegment, Vec2, VolumeError,
};

use crate::hits::{self, Boxed, ENEMY_HALF, PLAYER_HALF, Who};
use crate::level::{Level, PlatformTrack};
use crate::script::{self, Input};
use crate::summary::Summary;

/// Steps per second (the step is fixed: no wall clock).
pub const STEPS_PER_SECOND: u32 = 60;
/// The player's run speed, in cells per second.
pub const RUN_SPEED: f32 = 5.0;
/// The player's take-off speed, in cells per second.
pub const JUMP_SPEED: f32 = 14.0;
/// Gravity, in cells per second per second.
pub const GRAVITY: f32 = 40.0;
/// The fastest fall, in cells per second.
const MAX_FALL: f32 = 20.0;
/// Take-off speed after a stomp, and after being hit, in cells per second.
const BOUNCE_SPEED: f32 = 9.0;
const KNOCK_SPEED: f32 = 6.0;
/// Steps the player cannot be hit after a hit.
const INVULNERABLE_STEPS: u32 = 60;
/// Steps a drop through a one-way platform is held.
const DROP_STEPS: u32 = 8;
/// Enemies' patrol speed (cells per second) and range either side of their start (cells).
const ENEMY_SPEED: f32 = 1.5;
const ENEMY_RANGE: f32 = 3.0;
/// The moving platform's speed, in cells per second.
const PLATFORM_SPEED: f32 = 2.0;
/// The owner of the moving platform's temporary segment.
pub const PLATFORM_OWNER: Owner = Owner(1);

/// Why a step failed (the library's own errors: bad input never panics).
#[derive(Debug, Error)]
pub enum GameError {
    /// The controller refused a move or a shape.
    #[error("controller: {0}")]
    Controller(#[from] ControllerError),
    /// The map refused the platform's segment.
    #[error("moving platform: {0}")]
    Map(#[from] MapError),
    /// The hit volumes refused an object (a position beyond `MAX_COORD`).
    #[error("hit volumes: {0}")]
    Volume(#[from] VolumeError),
}

/// The player: a box moved by the controller.
#[derive(Clone, Debug)]
pub struct Player {
    /// The controller's character.
    pub body: Character,
    /// What it touched in its last move.
    pub contacts: Contacts,
    /// Speed along up, in world units per second.
    rise: f32,
    /// Steps left of invulnerability after a hit.
    pub invulnerable: u32,
    /// Steps left of a drop through a one-way platform.
    drop: u32,
    half: Vec2,
    up: Vec2,
}

impl Player {
    /// Half its size, in world units.
    #[must_use]
    pub fn half(&self) -> Vec2 {
        self.half
    }

    /// The middle of its bottom side.
    #[must_use]
    pub fn feet(&self) -> Vec2 {
        self.body.position - self.up * self.half.y
    }
}

/// An enemy: a box that patrols back and forth, turning at walls, edges and its range.
#[derive(Clone, Debug)]
pub struct Enemy {
    /// The controller's character.
    pub body: Character,
    /// Still in the game (not stomped).
    pub alive: bool,
    /// −1 or 1: which way it walks.
    dir: f32,
    home: f32,
    rise: f32,
    speed: f32,
    half: Vec2,
    up: Vec2,
}

impl Enemy {
    /// The middle of its bottom side.
    #[must_use]
    pub fn feet(&self) -> Vec2 {
        self.body.position - self.up * self.half.y
    }

    /// Its walking velocity along x, in world units per second.
    #[must_use]
    pub fn velocity_x(&self) -> f32 {
        if self.alive {
            self.dir * self.speed
        } else {
            0.0
        }
    }

    /// Half its size, in world units.
    #[must_use]
    pub fn half(&self) -> Vec2 {
        self.half
    }
}

/// A coin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Coin {
    /// Its centre.
    pub center: Vec2,
    /// Collected.
    pub taken: bool,
}

/// A running game on one level.
#[derive(Debug)]
pub struct Game {
    /// The level (its map holds the platform's temporary segment).
    pub level: Level,
    /// The player.
    pub player: Player,
    /// The enemies.
    pub enemies: Vec<Enemy>,
    /// The coins.
    pub coins: Vec<Coin>,
    /// Where the platform is along its track (0 to its travel) and which way it goes.
    platform_at: f32,
    platform_dir: f32,
    hits: HitWorld,
    who: Vec<Who>,
    events: Vec<HitEvent>,
    /// The player's centre every few steps, for pictures.
    trail: Vec<Vec2>,
    summary: Summary,
}

impl Game {
    /// A game at the start of `level`.
    pub fn new(level: Level) -> Result<Self, GameError> {
        let s = level.scale;
        let config = ControllerConfig {
            snap_distance: 0.3 * s,
            skin: 1e-3 * s,
            ..ControllerConfig::default()
        };
        let up = level.up;
        let half = PLAYER_HALF * s;
        let body = Character::new(
            CharacterShape::rect(half)?,
            level.start + up * (half.y + 1e-3 * s),
            up,
            config,
        )?;
        let player = Player {
            body,
            contacts: Contacts::default(),
            rise: 0.0,
            invulnerable: 0,
            drop: 0,
            half,
            up,
        };
        let enemy_half = ENEMY_HALF * s;
        let enemies = level
            .enemies
            .iter()
            .map(|&feet| {
                let body = Character::new(
                    CharacterShape::rect(enemy_half)?,
                    feet + up * (enemy_half.y + 1e-3 * s),
                    up,
                    config,
                )?;
                Ok(Enemy {
                    body,
                    alive: true,
                    dir: -1.0,
                    home: feet.x,
                    rise: 0.0,
                    speed: ENEMY_SPEED * s,
                    half: enemy_half,
                    up,
                })
            })
            .collect::<Result<Vec<_>, GameError>>()?;
        let coins = level
            .coins
            .iter()
            .map(|&center| Coin {
                center,
                taken: false,
            })
            .collect::<Vec<_>>();
        let summary = Summary {
            level: level.name.clone(),
            goal: level.goal_kind,
            coins_total: coins.len(),
            enemies_total: enemies.len(),
            end: player.body.position,
            ..Summary::default()
        };
        let mut game = Self {
            trail: vec![player.body.position],
            level,
            player,
            enemies,
            coins,
            platform_at: 0.0,
            platform_dir: 1.0,
            hits: HitWorld::new(),
            who: Vec::new(),
            events: Vec::new(),
            summary,
        };
        game.submit_platform(Vec2::ZERO)?;
        Ok(game)
    }

    /// Gravity in world units per second per second.
    #[must_use]
    pub fn gravity(&self) -> f32 {
        GRAVITY * self.level.scale
    }

    /// The run so far.
    #[must_use]
    pub fn summary(&self) -> &Summary {
        &self.summary
    }

    /// Whether the run is over: the goal reached, or the player fell out of the map.
    #[must_use]
    pub fn is_over(&self) -> bool {
        self.summary.reached_goal || self.fell_out()
    }

    fn fell_out(&self) -> bool {
        let b = self.level.map.bounds();
        let p = self.player.body.position;
        let margin = 4.0 * self.level.scale;
        p.y < b.min.y - margin || p.y > b.max.y + margin
    }

    /// The last step's hit events.
    #[must_use]
    pub fn events(&self) -> &[HitEvent] {
        &self.events
    }

    /// The hit world of the last step (for drawing its events).
    #[must_use]
    pub fn hit_world(&self) -> &HitWorld {
        &self.hits
    }

    /// The player's centre every few steps so far.
    #[must_use]
    pub fn trail(&self) -> &[Vec2] {
        &self.trail
    }

    /// Runs steps until the run is over or `max_steps` have run.
    pub fn run(&mut self, max_steps: u64) -> Result<&Summary, GameError> {
        while !self.is_over() && self.summary.steps < max_steps {
            self.step()?;
        }
        Ok(&self.summary)
    }

    /// One fixed step: the platform, the enemies, the player (by the script), the hits,
    /// the audit.
    pub fn step(&mut self) -> Result<(), GameError> {
        let dt = 1.0 / STEPS_PER_SECOND as f32;
        self.move_platform(dt)?;
        for i in 0..self.enemies.len() {
            self.move_enemy(i, dt)?;
        }
        let input = script::next_input(self);
        let from = self.player.body.position;
        self.move_player(input, dt)?;
        let to = self.player.body.position;
        self.exchange_hits(to - from)?;
        let s = self.level.scale;
        let summary = &mut self.summary;
        summary
            .audit
            .check(&self.level.map, from, to, self.player.half, s);
        summary.steps += 1;
        summary.end = to;
        let player_box = tileslide::Aabb::from_center(to, self.player.half);
        summary.reached_goal |= player_box.overlaps(&self.level.goal);
        if summary.steps.is_multiple_of(4) {
            self.trail.push(to);
        }
        Ok(())
    }

    fn submit_platform(&mut self, velocity: Vec2) -> Result<(), GameError> {
        let Some(PlatformTrack { start, width, .. }) = self.level.platform else {
            return Ok(());
        };
        let s = self.level.scale;
        let a = start * s + Vec2::X * self.platform_at;
        let map = &mut self.level.map;
        map.clear_temporaries_of(PLATFORM_OWNER);
        map.add_temporary(TemporarySegment {
            segment: Segment::new(a, a + Vec2::X * width * s),
            normal: self.level.up,
            flags: SegmentFlags::ONE_WAY,
            owner: PLATFORM_OWNER,
            velocity,
        })?;
        Ok(())
    }

    /// Slides the platform along its track and back, re-submitting its segment.
    fn move_platform(&mut self, dt: f32) -> Result<(), GameError> {
        let Some(track) = self.level.platform else {
            return Ok(());
        };
        let s = self.level.scale;
        let travel = track.travel * s;
        let before = self.platform_at;
        let mut at = before + self.platform_dir * PLATFORM_SPEED * s * dt;
        if !(0.0..=travel).contains(&at) {
            self.platform_dir = -self.platform_dir;
            at = at.clamp(0.0, travel);
        }
        self.platform_at = at;
        self.submit_platform(Vec2::X * (at - before) / dt)
    }

    fn move_enemy(&mut self, i: usize, dt: f32) -> Result<(), GameError> {
        let s = self.level.scale;
        let g = self.gravity();
        let map = &self.level.map;
        let Some(enemy) = self.enemies.get_mut(i).filter(|e| e.alive) else {
            return Ok(());
        };
        let up = enemy.up;
        let ahead = enemy.feet() + Vec2::X * enemy.dir * (enemy.half.x + 0.1 * s) + up * 0.6 * s;
        let edge = map
            .cast_ray(
                Ray::between(ahead, ahead - up * 1.5 * s),
                &QueryFilter::default(),
            )
            .is_none();
        let out = (enemy.body.position.x - enemy.home) * enemy.dir > ENEMY_RANGE * s;
        let grounded = enemy.body.ground().is_some();
        if grounded && (edge || out) {
            enemy.dir = -enemy.dir;
        }
        enemy.rise = (enemy.rise - g * dt).max(-MAX_FALL * s);
        let motion = Vec2::X * enemy.dir * enemy.speed * dt + up * enemy.rise * dt;
        let from = enemy.body.position;
        let contacts = enemy.body.move_by(map, motion, MoveOptions::default())?;
        if contacts.is_grounded() {
            enemy.rise = 0.0;
        }
        if (enemy.dir > 0.0 && contacts.right.is_some())
            || (enemy.dir < 0.0 && contacts.left.is_some())
        {
            enemy.dir = -enemy.dir;
        }
        let to = enemy.body.position;
        let half = enemy.half;
        self.summary.audit.check(map, from, to, half, s);
        Ok(())
    }

    fn move_player(&mut self, input: Input, dt: f32) -> Result<(), GameError> {
        let s = self.level.scale;
        let g = self.gravity();
        let player = &mut self.player;
        let up = player.up;
        if player.contacts.is_grounded() {
            // (A stomp's bounce or a hit's knock set a rise: keep it.)
            player.rise = player.rise.max(0.0);
            if input.jump {
                player.rise = JUMP_SPEED * s;
                self.summary.jumps += 1;
            }
            if input.drop {
                player.drop = DROP_STEPS;
            }
        }
        player.rise = (player.rise - g * dt).max(-MAX_FALL * s);
        let motion = Vec2::X * input.run * RUN_SPEED * s * dt + up * player.rise * dt;
        let options = MoveOptions {
            drop_through: player.drop > 0,
        };
        player.drop = player.drop.saturating_sub(1);
        player.invulnerable = player.invulnerable.saturating_sub(1);
        let contacts = player.body.move_by(&self.level.map, motion, options)?;
        if contacts.ceiling.is_some() {
            player.rise = player.rise.min(0.0);
        }
        let riding = contacts
            .ground
            .is_some_and(|g| matches!(g.source, SegmentSource::Temporary { .. }));
        self.summary.steps_riding += u64::from(riding);
        player.contacts = contacts;
        Ok(())
    }

    fn exchange_hits(&mut self, motion: Vec2) -> Result<(), GameError> {
        let s = self.level.scale;
        let up = self.level.up;
        let player = &self.player;
        let me = Boxed {
            center: player.body.position,
            half: player.half,
            motion,
        };
        let falling = player.rise < 0.0 && !player.contacts.is_grounded();
        let enemies: Vec<(usize, Boxed)> = (self.enemies.iter().enumerate())
            .filter(|(_, e)| e.alive)
            .map(|(i, e)| {
                let b = Boxed {
                    center: e.body.position,
                    half: e.half,
                    motion: Vec2::X * e.velocity_x() / STEPS_PER_SECOND as f32,
                };
                (i, b)
            })
            .collect();
        let coins: Vec<(usize, Vec2)> = (self.coins.iter().enumerate())
            .filter(|(_, c)| !c.taken)
            .map(|(i, c)| (i, c.center))
            .collect();
        let outcome = hits::exchange(
            &mut self.hits,
            &mut self.who,
            up,
            s,
            (&me, falling, player.invulnerable > 0),
            &enemies,
            &coins,
        )?;
        for i in outcome.collected {
            if let Some(c) = self.coins.get_mut(i) {
                c.taken = true;
                self.summary.coins_collected += 1;
            }
        }
        for &i in &outcome.stomped {
            if let Some(e) = self.enemies.get_mut(i).filter(|e| e.alive) {
                e.alive = false;
                self.summary.enemies_defeated += 1;
            }
        }
        let player = &mut self.player;
        if !outcome.stomped.is_empty() {
            player.rise = BOUNCE_SPEED * s;
        } else if outcome.player_hit {
            self.summary.hits_taken += 1;
            player.invulnerable = INVULNERABLE_STEPS;
            player.rise = KNOCK_SPEED * s;
        }
        self.events = outcome.events;
        Ok(())
    }
}
