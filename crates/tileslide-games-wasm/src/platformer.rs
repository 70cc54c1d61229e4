//! `PlatformerGame` for JavaScript: the platformer played by a person, on the bundled
//! level, an ASCII level or a Replica Island level, with what a canvas and a HUD draw.

use js_sys::{Float32Array, Object, Reflect};
use tileslide_platformer::{COIN_RADIUS, Game, Input, Level, PLATFORM_OWNER, STEPS_PER_SECOND};
use wasm_bindgen::prelude::*;

use crate::args::{self, error};
use crate::dungeon::object;
use crate::{PlatformerInput, draw};

/// The keys of `PlatformerGame.step`'s input as bits, to be or-ed together.
#[wasm_bindgen]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Keys {
    /// Run left.
    Left = 1,
    /// Run right.
    Right = 2,
    /// Jump (from the ground); with `Down`, drop through the one-way platform stood on.
    Jump = 4,
    /// With `Jump`: drop through a one-way platform.
    Down = 8,
}

/// The player's input from held keys: left and right together cancel out; jump with down
/// is a drop through a one-way platform, jump alone a jump.
#[must_use]
pub fn input_from_keys(left: bool, right: bool, jump: bool, down: bool) -> Input {
    Input {
        run: f32::from(i8::from(right) - i8::from(left)),
        jump: jump && !down,
        drop: jump && down,
    }
}

/// The input `value` says: a number of [`Keys`] bits, an object `{left, right, jump,
/// down}` of booleans, or `undefined` (no key held).
fn input(value: &JsValue) -> Result<Input, JsError> {
    if value.is_undefined() || value.is_null() {
        return Ok(Input::default());
    }
    if let Some(n) = value.as_f64() {
        let bits = args::whole("step: the input bits", n, 15)?;
        let held = |key: Keys| bits & key as u32 != 0;
        return Ok(input_from_keys(
            held(Keys::Left),
            held(Keys::Right),
            held(Keys::Jump),
            held(Keys::Down),
        ));
    }
    if !value.is_object() {
        return Err(error(
            "step: the input must be a number of Keys bits or {left, right, jump, down}",
        ));
    }
    let key = |name: &str| -> Result<bool, JsError> {
        let v = Reflect::get(value, &JsValue::from_str(name))
            .map_err(|_| error(format!("step: reading input.{name} failed")))?;
        Ok(v.is_truthy())
    };
    Ok(input_from_keys(
        key("left")?,
        key("right")?,
        key("jump")?,
        key("down")?,
    ))
}

/// A game of the platformer.
#[wasm_bindgen]
pub struct PlatformerGame {
    game: Game,
}

fn start(level: Level) -> Result<PlatformerGame, JsError> {
    Ok(PlatformerGame {
        game: Game::new(level).map_err(error)?,
    })
}

#[wasm_bindgen]
impl PlatformerGame {
    /// The bundled level (`examples/maps/platformer.txt`): ramps, one-way platforms, a
    /// moving platform, ten coins and two enemies.
    #[wasm_bindgen(constructor)]
    pub fn new() -> Result<PlatformerGame, JsError> {
        start(Level::bundled().map_err(error)?)
    }

    /// A level drawn in ASCII with the demo's markers (`P` start, `G` goal, `o` coin, `E`
    /// enemy, `M` moving platform; see the bundled level).
    #[wasm_bindgen(js_name = fromAscii)]
    pub fn from_ascii(text: &str) -> Result<PlatformerGame, JsError> {
        start(Level::parse_ascii(text, "level.txt").map_err(error)?)
    }

    /// A Replica Island level: the bytes of a level file (`level_*.bin`) and of the game's
    /// `collision.bin`, as the CLI's `demo platformer LEVEL --tileset collision.bin` loads
    /// them, with the coins and enemies of the level's object layer. Its y axis points up;
    /// its goal is its last three columns.
    #[wasm_bindgen(js_name = fromReplicaIsland)]
    pub fn from_replica_island(level: &[u8], tile_set: &[u8]) -> Result<PlatformerGame, JsError> {
        start(Level::parse_replica(level, "level.bin", tile_set, "collision.bin").map_err(error)?)
    }

    /// Runs `n` fixed steps of 1/60 s (1 by default, at most 108,000) with the keys of
    /// `input` held: a number of `Keys` bits or `{left, right, jump, down}` (none held when
    /// it is left out). A held jump
    /// jumps again on landing.
    pub fn step(&mut self, input: Option<PlatformerInput>, n: Option<f64>) -> Result<(), JsError> {
        let input = self::input(&input.map_or(JsValue::UNDEFINED, JsValue::from))?;
        for _ in 0..args::step_count("step: n", n)? {
            self.game.step_with(input).map_err(error)?;
        }
        Ok(())
    }

    /// Starts (`true`) or stops tracing the player's moves, for `playerStory` (off by
    /// default: an untraced move records nothing).
    #[wasm_bindgen(js_name = tracePlayer)]
    pub fn trace_player(&mut self, on: bool) {
        crate::story::trace_player(&mut self.game, on);
    }

    /// The player's last move in words (each sweep and what it met, by cell and tile, the
    /// slides, the landing), or `null` when moves are not traced or none was made yet.
    #[wasm_bindgen(js_name = playerStory, unchecked_return_type = "string | null")]
    pub fn player_story(&self) -> JsValue {
        crate::story::player_story(&self.game).map_or(JsValue::NULL, JsValue::from)
    }

    /// The HUD's numbers (see `PlatformerState`).
    #[wasm_bindgen(getter, unchecked_return_type = "PlatformerState")]
    pub fn state(&self) -> Result<Object, JsError> {
        let g = &self.game;
        let s = g.summary();
        let count = |n: usize| JsValue::from_f64(n as f64);
        object(&[
            ("steps", JsValue::from_f64(s.steps as f64)),
            (
                "time",
                JsValue::from_f64(s.steps as f64 / f64::from(STEPS_PER_SECOND)),
            ),
            ("coins", count(s.coins_collected)),
            ("coinsTotal", count(s.coins_total)),
            ("enemiesDefeated", count(s.enemies_defeated)),
            ("enemiesTotal", count(s.enemies_total)),
            ("hitsTaken", JsValue::from(s.hits_taken)),
            ("jumps", JsValue::from(s.jumps)),
            (
                "grounded",
                JsValue::from_bool(g.player.contacts.is_grounded()),
            ),
            (
                "invulnerable",
                JsValue::from_bool(g.player.invulnerable > 0),
            ),
            ("reachedGoal", JsValue::from_bool(s.reached_goal)),
            ("over", JsValue::from_bool(g.is_over())),
        ])
    }

    /// The player's box: `[x, y, halfWidth, halfHeight]` (centre and half size).
    pub fn player(&self) -> Float32Array {
        let p = &self.game.player;
        let (c, h) = (p.body.position, p.half());
        Float32Array::from([c.x, c.y, h.x, h.y].as_slice())
    }

    /// The coins not taken yet, 3 floats each: `x, y, radius`.
    pub fn coins(&self) -> Float32Array {
        let r = COIN_RADIUS * self.game.level.scale;
        let out: Vec<f32> = (self.game.coins.iter())
            .filter(|c| !c.taken)
            .flat_map(|c| [c.center.x, c.center.y, r])
            .collect();
        Float32Array::from(out.as_slice())
    }

    /// The enemies still standing, 4 floats each: `x, y, halfWidth, halfHeight`.
    pub fn enemies(&self) -> Float32Array {
        let out: Vec<f32> = (self.game.enemies.iter())
            .filter(|e| e.alive)
            .flat_map(|e| {
                let (c, h) = (e.body.position, e.half());
                [c.x, c.y, h.x, h.y]
            })
            .collect();
        Float32Array::from(out.as_slice())
    }

    /// The moving platform's top, `[x0, y0, x1, y1]`, or an empty array when the level has
    /// none.
    pub fn platform(&self) -> Float32Array {
        let out: Vec<f32> = (self.game.level.map.temporaries().iter())
            .filter(|t| t.owner == PLATFORM_OWNER)
            .flat_map(|t| [t.segment.a.x, t.segment.a.y, t.segment.b.x, t.segment.b.y])
            .collect();
        Float32Array::from(out.as_slice())
    }

    /// The goal's box, `[minX, minY, maxX, maxY]`.
    pub fn goal(&self) -> Float32Array {
        let g = self.game.level.goal;
        Float32Array::from([g.min.x, g.min.y, g.max.x, g.max.y].as_slice())
    }

    /// The map's active segments, 7 floats each: `x0, y0, x1, y1, nx, ny, flags` (the
    /// outward unit normal; flags 1 solid, 2 one-way). The moving platform is not among
    /// them (see `platform()`).
    pub fn segments(&self) -> Float32Array {
        Float32Array::from(draw::segments(&self.game.level.map).as_slice())
    }

    /// The map's bounds in world units, `[minX, minY, maxX, maxY]`.
    pub fn bounds(&self) -> Float32Array {
        let b = self.game.level.map.bounds();
        Float32Array::from([b.min.x, b.min.y, b.max.x, b.max.y].as_slice())
    }

    /// One cell's width in world units (1 for ASCII levels, 32 for Replica Island).
    #[wasm_bindgen(getter, js_name = cellSize)]
    pub fn cell_size(&self) -> f32 {
        self.game.level.scale
    }

    /// Which way is up along y: −1 for ASCII levels (y grows downwards), 1 for Replica
    /// Island levels.
    #[wasm_bindgen(getter)]
    pub fn up(&self) -> f32 {
        self.game.level.up.y
    }

    /// The level's name (its file name).
    #[wasm_bindgen(getter)]
    pub fn name(&self) -> String {
        self.game.level.name.clone()
    }
}
