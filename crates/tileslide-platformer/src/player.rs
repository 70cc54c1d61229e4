//! The player: a box moved by the controller, running, jumping, dropping through one-way
//! platforms, bouncing off stomps and knocked back by hits.

use tileslide::{
    Character, CharacterShape, Contacts, ControllerConfig, ControllerError, MoveOptions, MoveTrace,
    SegmentSource, TileMap, Vec2,
};

use crate::fall;
use crate::hits::PLAYER_HALF;
use crate::input::Input;
use crate::level::Level;

/// The player's run speed, in cells per second.
pub const RUN_SPEED: f32 = 5.0;
/// The player's take-off speed, in cells per second.
pub const JUMP_SPEED: f32 = 14.0;
/// Take-off speed after a stomp, and after being hit, in cells per second.
const BOUNCE_SPEED: f32 = 9.0;
const KNOCK_SPEED: f32 = 6.0;
/// Steps the player cannot be hit after a hit.
const INVULNERABLE_STEPS: u32 = 60;
/// Steps a drop through a one-way platform is held.
const DROP_STEPS: u32 = 8;

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
    /// `Some` while its moves are traced: the last move's trace (see
    /// [`Character::move_by_traced`]); `None` (the default) moves untraced.
    pub trace: Option<MoveTrace>,
    /// Steps left of a drop through a one-way platform.
    drop: u32,
    half: Vec2,
    up: Vec2,
}

impl Player {
    /// The player standing at `level`'s start, moved with `config`.
    pub(crate) fn new(level: &Level, config: ControllerConfig) -> Result<Self, ControllerError> {
        let s = level.scale;
        let up = level.up;
        let half = PLAYER_HALF * s;
        let body = Character::new(
            CharacterShape::rect(half)?,
            level.start + up * (half.y + 1e-3 * s),
            up,
            config,
        )?;
        Ok(Self {
            body,
            contacts: Contacts::default(),
            rise: 0.0,
            invulnerable: 0,
            trace: None,
            drop: 0,
            half,
            up,
        })
    }

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

    /// Whether it is in the air and coming down (its feet stomp).
    #[must_use]
    pub(crate) fn is_falling(&self) -> bool {
        self.rise < 0.0 && !self.contacts.is_grounded()
    }

    /// On the ground, starts the jump or the drop that `input` asks for. Returns whether it
    /// jumped.
    pub(crate) fn take_off(&mut self, input: Input, scale: f32) -> bool {
        if !self.contacts.is_grounded() {
            return false;
        }
        // (A stomp's bounce or a hit's knock set a rise: keep it.)
        self.rise = self.rise.max(0.0);
        if input.jump {
            self.rise = JUMP_SPEED * scale;
        }
        if input.drop {
            self.drop = DROP_STEPS;
        }
        input.jump
    }

    /// Moves it for `dt` seconds: `input`'s run sideways and its rise along up under
    /// gravity, through one-way platforms while a drop lasts. Counts down the drop and the
    /// invulnerability. Returns whether it stands on a moving platform after the move.
    pub(crate) fn run(
        &mut self,
        map: &TileMap,
        input: Input,
        dt: f32,
        scale: f32,
    ) -> Result<bool, ControllerError> {
        let s = scale;
        self.rise = fall::fall(self.rise, dt, s);
        let motion = Vec2::X * input.run * RUN_SPEED * s * dt + self.up * self.rise * dt;
        let options = MoveOptions {
            drop_through: self.drop > 0,
        };
        self.drop = self.drop.saturating_sub(1);
        self.invulnerable = self.invulnerable.saturating_sub(1);
        let contacts = match &mut self.trace {
            Some(trace) => self.body.move_by_traced(map, motion, options, trace)?,
            None => self.body.move_by(map, motion, options)?,
        };
        if contacts.ceiling.is_some() {
            self.rise = self.rise.min(0.0);
        }
        let riding = contacts
            .ground
            .is_some_and(|g| matches!(g.source, SegmentSource::Temporary { .. }));
        self.contacts = contacts;
        Ok(riding)
    }

    /// Bounces it up off a stomped enemy.
    pub(crate) fn bounce(&mut self, scale: f32) {
        self.rise = BOUNCE_SPEED * scale;
    }

    /// Knocks it up after an enemy's hit, and makes it invulnerable for a while.
    pub(crate) fn knock(&mut self, scale: f32) {
        self.invulnerable = INVULNERABLE_STEPS;
        self.rise = KNOCK_SPEED * scale;
    }
}
