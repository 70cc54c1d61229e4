//! The game: a fixed step that moves the platform, the enemies and the player with
//! tileslide's controller, exchanges hits through a `HitWorld`, and audits the result.

use tileslide::{ControllerConfig, HitEvent, HitWorld, Vec2};

use crate::coin::Coin;
use crate::enemy::Enemy;
use crate::error::GameError;
use crate::fall;
use crate::hits::{self, Boxed, Who};
use crate::input::Input;
use crate::level::Level;
use crate::platform::MovingPlatform;
use crate::player::Player;
use crate::script;
use crate::summary::Summary;

/// Steps per second (the step is fixed: no wall clock).
pub const STEPS_PER_SECOND: u32 = 60;

/// What the script makes the player do in `game`'s next step: the first of these rules
/// that applies. Only a player on the ground decides anything; in the air it keeps running
/// right.
///
/// 1. A coin below and a little ahead of the one-way platform it stands on: drop through.
/// 2. A wall ahead: jump.
/// 3. The ground ends ahead: jump if there is ground to land on within a jump (moving
///    platforms are not counted, they move), else wait for the moving platform if the
///    level has one (or jump anyway).
/// 4. A coin above and ahead within a jump's reach, not over solid ground it can walk to:
///    jump.
/// 5. An enemy ahead on the same level, close enough to land on: jump (a stomp).
/// 6. Otherwise run right.
#[must_use]
pub fn next_input(game: &Game) -> Input {
    script::decide(&game.level, &game.player, &game.enemies, &game.coins)
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
    /// Where the platform is along its track and which way it goes.
    platform: MovingPlatform,
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
        let player = Player::new(&level, config)?;
        let enemies = level
            .enemies
            .iter()
            .map(|&start| Enemy::new(start, level.up, s, config))
            .collect::<Result<Vec<_>, _>>()?;
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
            platform: MovingPlatform::new(),
            hits: HitWorld::new(),
            who: Vec::new(),
            events: Vec::new(),
            summary,
        };
        game.platform.submit(&mut game.level, Vec2::ZERO)?;
        Ok(game)
    }

    /// Gravity in world units per second per second.
    #[must_use]
    pub fn gravity(&self) -> f32 {
        fall::gravity(self.level.scale)
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
        self.step_as(None)
    }

    /// One fixed step with the player doing what `input` says instead of the script (a
    /// person playing). Its run is clamped to −1..1 (NaN counts as 0); the jump and the
    /// drop happen only on the ground, as the script's do.
    pub fn step_with(&mut self, input: Input) -> Result<(), GameError> {
        let run = if input.run.is_nan() {
            0.0
        } else {
            input.run.clamp(-1.0, 1.0)
        };
        self.step_as(Some(Input { run, ..input }))
    }

    /// One step, the player moved by `input` or, without one, by the script (asked after
    /// the platform and the enemies moved).
    fn step_as(&mut self, input: Option<Input>) -> Result<(), GameError> {
        let dt = 1.0 / STEPS_PER_SECOND as f32;
        self.platform.slide(&mut self.level, dt)?;
        for i in 0..self.enemies.len() {
            self.move_enemy(i, dt)?;
        }
        let input = input.unwrap_or_else(|| next_input(self));
        let from = self.player.body.position;
        self.move_player(input, dt)?;
        let to = self.player.body.position;
        self.exchange_hits(to - from)?;
        let s = self.level.scale;
        let summary = &mut self.summary;
        summary
            .audit
            .check(&self.level.map, from, to, self.player.half(), s);
        summary.steps += 1;
        summary.end = to;
        let player_box = tileslide::Aabb::from_center(to, self.player.half());
        summary.reached_goal |= player_box.overlaps(&self.level.goal);
        if summary.steps.is_multiple_of(4) {
            self.trail.push(to);
        }
        Ok(())
    }

    fn move_enemy(&mut self, i: usize, dt: f32) -> Result<(), GameError> {
        let s = self.level.scale;
        let map = &self.level.map;
        let Some(enemy) = self.enemies.get_mut(i).filter(|e| e.alive) else {
            return Ok(());
        };
        let from = enemy.body.position;
        enemy.patrol(map, dt, s)?;
        let to = enemy.body.position;
        self.summary.audit.check(map, from, to, enemy.half(), s);
        Ok(())
    }

    fn move_player(&mut self, input: Input, dt: f32) -> Result<(), GameError> {
        let s = self.level.scale;
        if self.player.take_off(input, s) {
            self.summary.jumps += 1;
        }
        let riding = self.player.run(&self.level.map, input, dt, s)?;
        self.summary.steps_riding += u64::from(riding);
        Ok(())
    }

    fn exchange_hits(&mut self, motion: Vec2) -> Result<(), GameError> {
        let s = self.level.scale;
        let up = self.level.up;
        let player = &self.player;
        let me = Boxed {
            center: player.body.position,
            half: player.half(),
            motion,
        };
        let falling = player.is_falling();
        let enemies: Vec<(usize, Boxed)> = (self.enemies.iter().enumerate())
            .filter(|(_, e)| e.alive)
            .map(|(i, e)| {
                let b = Boxed {
                    center: e.body.position,
                    half: e.half(),
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
            player.bounce(s);
        } else if outcome.player_hit {
            self.summary.hits_taken += 1;
            player.knock(s);
        }
        self.events = outcome.events;
        Ok(())
    }
}
