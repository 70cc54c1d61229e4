//! `DungeonGame` for JavaScript: Dungeon Builder kept by a person (`dig`, `summon`) or by
//! the script (`{scripted: true}`, the game of `tileslide demo dungeon`), with what a
//! canvas and a HUD draw.

use js_sys::{Float32Array, Object, Reflect, Uint8Array, Uint32Array};
use tileslide::{Cell, Vec2};
use tileslide_dungeon::{
    DIG_COST, FIREBALL_RADIUS, Game, GameConfig, Kind, MAX_CREATURES, Outcome, STEPS_PER_SECOND,
    creature_cost,
};
use wasm_bindgen::prelude::*;

use crate::args::{self, error};
use crate::{DungeonOptions, draw};

/// A game of Dungeon Builder.
#[wasm_bindgen]
pub struct DungeonGame {
    game: Game,
}

/// `{key: value, …}` as a JavaScript object.
pub(crate) fn object(entries: &[(&str, JsValue)]) -> Result<Object, JsError> {
    let out = Object::new();
    for (key, value) in entries {
        Reflect::set(&out, &JsValue::from_str(key), value)
            .map_err(|_| error(format!("setting `{key}` of a result object failed")))?;
    }
    Ok(out)
}

/// The creature `name` names: `"imp"` or `"skeleton"`.
fn creature(name: &str) -> Result<Kind, JsError> {
    match name {
        "imp" => Ok(Kind::Imp),
        "skeleton" => Ok(Kind::Skeleton),
        _ => Err(error(format!(
            "summon: the kind is {name:?}; the keeper summons \"imp\" or \"skeleton\""
        ))),
    }
}

/// Whether `options` (`undefined`, `null` or an object) says `{scripted: true}`.
fn scripted(options: &JsValue) -> Result<bool, JsError> {
    if options.is_undefined() || options.is_null() {
        return Ok(false);
    }
    if !options.is_object() {
        return Err(error(
            "new DungeonGame: the options must be an object, {scripted?: boolean}",
        ));
    }
    let value = Reflect::get(options, &JsValue::from_str("scripted"))
        .map_err(|_| error("new DungeonGame: reading options.scripted failed"))?;
    if value.is_undefined() {
        return Ok(false);
    }
    value
        .as_bool()
        .ok_or_else(|| error("new DungeonGame: options.scripted must be true or false"))
}

#[wasm_bindgen]
impl DungeonGame {
    /// A new game from `seed` (a whole number or a `BigInt`). With `{scripted: true}` the
    /// keeper's script plays (the game of `tileslide demo dungeon --seed`, state hash for
    /// state hash); otherwise the player gives the orders, starting with a corridor from the
    /// entrance to the treasure room, 300 gold, and parties until the fifth is seen off.
    #[wasm_bindgen(constructor)]
    pub fn new(
        #[wasm_bindgen(unchecked_param_type = "number | bigint")] seed: JsValue,
        options: Option<DungeonOptions>,
    ) -> Result<DungeonGame, JsError> {
        let seed = args::seed(&seed)?;
        let options = options.map_or(JsValue::UNDEFINED, JsValue::from);
        let config = if scripted(&options)? {
            GameConfig::new(seed)
        } else {
            GameConfig::player(seed)
        };
        let game = Game::with_config(config).map_err(error)?;
        Ok(Self { game })
    }

    /// Runs `n` fixed steps of 1/30 s (1 by default; at most 108,000, an hour).
    pub fn step(&mut self, n: Option<f64>) -> Result<(), JsError> {
        for _ in 0..args::step_count("step: n", n)? {
            self.game.step().map_err(error)?;
        }
        Ok(())
    }

    /// Digs out square (`col`, `row`) for 50 gold: earth beside an open square. Throws an
    /// `Error` saying why not (rock, open already, not beside an open square, not enough
    /// gold, the scripted keeper plays, the game is over).
    pub fn dig(&mut self, col: f64, row: f64) -> Result<(), JsError> {
        let cell = Cell::new(
            args::whole("dig: col", col, u32::MAX)?,
            args::whole("dig: row", row, u32::MAX)?,
        );
        self.game.dig(cell).map_err(error)
    }

    /// Whether square (`col`, `row`) can be dug now (gold aside); `false` for anything
    /// that is not a square of the map.
    #[wasm_bindgen(js_name = isDiggable)]
    pub fn is_diggable(&self, col: f64, row: f64) -> bool {
        match (
            args::whole_number(col, u32::MAX),
            args::whole_number(row, u32::MAX),
        ) {
            (Some(col), Some(row)) => self.game.is_diggable(Cell::new(col, row)),
            _ => false,
        }
    }

    /// Summons a creature, `"imp"` (50 gold) or `"skeleton"` (35 gold), at (`x`, `y`) or
    /// the first free place near it; the point must be in an open square. Throws an
    /// `Error` saying why not.
    pub fn summon(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "\"imp\" | \"skeleton\"")] kind: &str,
        x: f32,
        y: f32,
    ) -> Result<(), JsError> {
        let kind = creature(kind)?;
        self.game.summon(kind, Vec2::new(x, y)).map_err(error)
    }

    /// The HUD's numbers (see `DungeonState`).
    #[wasm_bindgen(getter, unchecked_return_type = "DungeonState")]
    pub fn state(&self) -> Result<Object, JsError> {
        let g = &self.game;
        let s = g.summary();
        let outcome = match g.outcome() {
            Outcome::Won => "won",
            Outcome::Lost => "lost",
            _ => "playing",
        };
        let number = |n: u64| JsValue::from_f64(n as f64);
        let next_wave = g.next_wave_in().map_or(JsValue::NULL, |n| {
            JsValue::from_f64(n as f64 / f64::from(STEPS_PER_SECOND))
        });
        object(&[
            ("steps", number(s.steps)),
            (
                "time",
                JsValue::from_f64(s.steps as f64 / f64::from(STEPS_PER_SECOND)),
            ),
            ("wave", number(s.waves.into())),
            ("nextWaveIn", next_wave),
            ("gold", number(g.gold().into())),
            ("heroesAlive", number(g.heroes_alive().into())),
            ("creaturesAlive", number(g.creatures_alive().into())),
            ("heroesLost", number(s.heroes_lost.into())),
            ("heroesEscaped", number(s.heroes_escaped.into())),
            ("creaturesSummoned", number(s.creatures_summoned.into())),
            ("creaturesLost", number(s.creatures_lost.into())),
            ("treasureLeft", number(s.treasure_left.into())),
            ("treasureTaken", number(s.treasure_taken.into())),
            ("treasureStolen", number(s.treasure_stolen.into())),
            ("squaresDug", number(s.squares_dug.into())),
            ("scripted", JsValue::from_bool(is_scripted(g))),
            ("outcome", JsValue::from_str(outcome)),
            ("over", JsValue::from_bool(g.outcome().is_over())),
        ])
    }

    /// The prices and the limit: `{dig: 50, imp: 50, skeleton: 35, maxCreatures: 8}`.
    #[wasm_bindgen(getter, unchecked_return_type = "DungeonCosts")]
    pub fn costs(&self) -> Result<Object, JsError> {
        let price = |kind| JsValue::from(creature_cost(kind).unwrap_or(0));
        object(&[
            ("dig", JsValue::from(DIG_COST)),
            ("imp", price(Kind::Imp)),
            ("skeleton", price(Kind::Skeleton)),
            ("maxCreatures", JsValue::from(MAX_CREATURES)),
        ])
    }

    /// Every fighter alive in spawn order, 7 floats each: x, y, radius, kind (0 hero,
    /// 1 skeleton, 2 imp), team (0 heroes, 1 keeper), hit points left as a fraction, and
    /// 1 when it carries a piece of the treasure (else 0).
    pub fn creatures(&self) -> Float32Array {
        Float32Array::from(draw::fighters(&self.game.fighters()).as_slice())
    }

    /// Starts (`true`) or stops tracing the fighters' steps, for `storyOf` (off by
    /// default).
    #[wasm_bindgen(js_name = traceCreatures)]
    pub fn trace_creatures(&mut self, on: bool) {
        self.game.trace_bodies(on);
    }

    /// The id of the fighter whose circle holds (`x`, `y`), or `null`.
    #[wasm_bindgen(js_name = creatureAt, unchecked_return_type = "number | null")]
    pub fn creature_at(&self, x: f32, y: f32) -> JsValue {
        crate::story::fighter_at(&self.game, x, y)
            .map_or(JsValue::NULL, |id| JsValue::from_f64(id as f64))
    }

    /// Fighter `id`'s last step in words (each pass, what it met: a wall's cell and tile
    /// or another fighter, what the resolver did), or `null` when steps are not traced or
    /// no such fighter is alive.
    #[wasm_bindgen(js_name = storyOf, unchecked_return_type = "string | null")]
    pub fn story_of(&self, id: f64) -> Result<JsValue, JsError> {
        let id = args::whole("storyOf: id", id, u32::MAX)?;
        Ok(crate::story::fighter_story(&self.game, u64::from(id))
            .map_or(JsValue::NULL, JsValue::from))
    }

    /// The fireballs in flight, 3 floats each: `x, y, radius`.
    pub fn fireballs(&self) -> Float32Array {
        let balls: Vec<f32> = self
            .game
            .fireballs()
            .iter()
            .flat_map(|p| [p.x, p.y, FIREBALL_RADIUS])
            .collect();
        Float32Array::from(balls.as_slice())
    }

    /// One code per square, row by row (`width × height`): 0 open and seen by the
    /// heroes, 1 open and not seen yet, 2 earth that can be dug now, 3 other earth, 4 rock.
    pub fn squares(&self) -> Uint8Array {
        Uint8Array::from(draw::squares(&self.game).as_slice())
    }

    /// The squares that can be dug now, as `col, row` pairs.
    pub fn diggable(&self) -> Uint32Array {
        Uint32Array::from(draw::cell_pairs(&self.game.diggable()).as_slice())
    }

    /// The squares dug so far, in order, as `col, row` pairs.
    pub fn dug(&self) -> Uint32Array {
        Uint32Array::from(draw::cell_pairs(self.game.dug()).as_slice())
    }

    /// The map's active segments, 7 floats each: `x0, y0, x1, y1, nx, ny, flags` (the
    /// outward unit normal; flags 1 solid, 2 one-way). They change only when a square is
    /// dug (`state.squaresDug`).
    pub fn segments(&self) -> Float32Array {
        Float32Array::from(draw::segments(self.game.map()).as_slice())
    }

    /// Columns of the map (one unit a square).
    #[wasm_bindgen(getter)]
    pub fn width(&self) -> u32 {
        self.game.map().width()
    }

    /// Rows of the map.
    #[wasm_bindgen(getter)]
    pub fn height(&self) -> u32 {
        self.game.map().height()
    }

    /// Where the treasure pile lies: `[x, y]`.
    #[wasm_bindgen(getter)]
    pub fn treasure(&self) -> Float32Array {
        let p = self.game.level().treasure;
        Float32Array::from([p.x, p.y].as_slice())
    }

    /// Where heroes come in and leave: `[x, y]`.
    #[wasm_bindgen(getter)]
    pub fn exit(&self) -> Float32Array {
        let p = self.game.level().exit;
        Float32Array::from([p.x, p.y].as_slice())
    }

    /// The game's state hash as 16 hexadecimal digits (what `tileslide demo dungeon`
    /// prints): equal hashes mean equal games.
    #[wasm_bindgen(js_name = stateHash)]
    pub fn state_hash(&self) -> String {
        format!("{:016x}", self.game.state_hash())
    }
}

/// Whether the script keeps `game`.
fn is_scripted(game: &Game) -> bool {
    game.mode() == tileslide_dungeon::KeeperMode::Scripted
}
