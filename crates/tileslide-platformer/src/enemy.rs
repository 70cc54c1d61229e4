//! An enemy: a box that patrols back and forth, turning at walls, edges and its range; or
//! one that flies back and forth, turning at walls and its range.

use tileslide::{
    Character, CharacterShape, ControllerConfig, ControllerError, MoveOptions, QueryFilter, Ray,
    TileMap, Vec2,
};

use crate::fall;
use crate::hits::ENEMY_HALF;
use crate::replica_objects::EnemyStart;

/// Enemies' patrol speed (cells per second) and range either side of their start (cells).
const ENEMY_SPEED: f32 = 1.5;
const ENEMY_RANGE: f32 = 3.0;

/// An enemy: a box that patrols back and forth, turning at walls, edges and its range; or
/// one that flies back and forth along its row, without gravity, turning at walls and its
/// range.
#[derive(Clone, Debug)]
pub struct Enemy {
    /// The controller's character.
    pub body: Character,
    /// Still in the game (not stomped).
    pub alive: bool,
    /// It flies instead of walking.
    pub flies: bool,
    /// −1 or 1: which way it walks.
    dir: f32,
    home: f32,
    rise: f32,
    speed: f32,
    half: Vec2,
    up: Vec2,
}

impl Enemy {
    /// An enemy standing on `start`'s feet (or flying there, its bottom at them), moving
    /// left first, on a map whose up is `up` and whose cells are `scale` wide, moved with
    /// `config`.
    pub(crate) fn new(
        start: EnemyStart,
        up: Vec2,
        scale: f32,
        config: ControllerConfig,
    ) -> Result<Self, ControllerError> {
        let s = scale;
        let half = ENEMY_HALF * s;
        let body = Character::new(
            CharacterShape::rect(half)?,
            start.feet + up * (half.y + 1e-3 * s),
            up,
            config,
        )?;
        Ok(Self {
            body,
            alive: true,
            flies: start.flies,
            dir: -1.0,
            home: start.feet.x,
            rise: 0.0,
            speed: ENEMY_SPEED * s,
            half,
            up,
        })
    }

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

    /// Walks it for `dt` seconds, falling under gravity; on the ground it turns at an edge
    /// ahead or beyond its range, and it turns at a wall it walks into. A flyer keeps its
    /// height and turns beyond its range and at walls.
    pub(crate) fn patrol(
        &mut self,
        map: &TileMap,
        dt: f32,
        scale: f32,
    ) -> Result<(), ControllerError> {
        let s = scale;
        let up = self.up;
        let ahead = self.feet() + Vec2::X * self.dir * (self.half.x + 0.1 * s) + up * 0.6 * s;
        let edge = || {
            map.cast_ray(
                Ray::between(ahead, ahead - up * 1.5 * s),
                &QueryFilter::default(),
            )
            .is_none()
        };
        let out = (self.body.position.x - self.home) * self.dir > ENEMY_RANGE * s;
        let grounded = self.body.ground().is_some();
        let turn = if self.flies {
            out
        } else {
            grounded && (out || edge())
        };
        if turn {
            self.dir = -self.dir;
        }
        if !self.flies {
            self.rise = fall::fall(self.rise, dt, s);
        }
        let motion = Vec2::X * self.dir * self.speed * dt + up * self.rise * dt;
        let contacts = self.body.move_by(map, motion, MoveOptions::default())?;
        if contacts.is_grounded() {
            self.rise = 0.0;
        }
        if (self.dir > 0.0 && contacts.right.is_some())
            || (self.dir < 0.0 && contacts.left.is_some())
        {
            self.dir = -self.dir;
        }
        Ok(())
    }
}
