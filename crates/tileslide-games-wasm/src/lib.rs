//! The demo games for JavaScript: Dungeon Builder and the platformer through wasm-bindgen,
//! built by `web/build.sh` into the ES module `web/games-pkg/tileslide_games.js` (beside,
//! not inside, the `tileslide` npm package in `web/pkg/`), for the playground's pages.
//!
//! # Starting
//!
//! ```js
//! import init, { DungeonGame, PlatformerGame, Keys } from "./games-pkg/tileslide_games.js";
//! await init(); // or initSync({ module: bytes })
//! ```
//!
//! # `DungeonGame`
//!
//! ```js
//! const game = new DungeonGame(1);                       // a player keeps the dungeon
//! const demo = new DungeonGame(1, { scripted: true });   // the CLI demo's game
//! game.dig(31, 20);              // throws an Error saying why not (rock, gold, …)
//! game.summon("imp", 32.5, 20.5); // or "skeleton"
//! game.step(30);                 // 30 steps of 1/30 s
//! const { gold, wave, time, heroesAlive, creaturesAlive, treasureLeft, over } = game.state;
//! const fighters = game.creatures(); // Float32Array, 7 floats a fighter
//! game.free();
//! ```
//!
//! Coordinates are map units, one unit a square, y down; square (`col`, `row`) covers
//! `[col, col + 1) × [row, row + 1)`. The drawing arrays:
//!
//! - `creatures()`: `x, y, radius, kind` (0 hero, 1 skeleton, 2 imp), `team` (0 heroes,
//!   1 keeper), `hp` (fraction left), `carrying` (1 with a piece of the treasure);
//! - `fireballs()`: `x, y, radius`;
//! - `squares()`: a `Uint8Array` of `width × height` codes, row by row: 0 open and seen by
//!   the heroes, 1 open and unseen (yellow), 2 earth diggable now (mark the 50), 3 other
//!   earth, 4 rock;
//! - `diggable()`, `dug()`: `Uint32Array`s of `col, row` pairs;
//! - `segments()`: the map's active segments, `x0, y0, x1, y1, nx, ny, flags`;
//! - `treasure`, `exit`: `[x, y]`; `costs`: `{dig, imp, skeleton, maxCreatures}`;
//! - `stateHash()`: 16 hexadecimal digits, as `tileslide demo dungeon` prints it.
//!
//! `game.traceCreatures(true)` records the fighters' steps from then on (off by default);
//! `game.creatureAt(x, y)` gives the id of the fighter there (or `null`) and
//! `game.storyOf(id)` its last step in words, as `tileslide explain --body` tells a body's
//! (the walls met by cell and tile, the other fighters by kind and id), or `null`.
//!
//! # `PlatformerGame`
//!
//! ```js
//! const game = new PlatformerGame();   // or PlatformerGame.fromReplicaIsland(level, collision)
//! game.step(Keys.Right | Keys.Jump);   // or game.step({ right: true, jump: true }, n)
//! const [x, y, hw, hh] = game.player();
//! const { coins, coinsTotal, enemiesDefeated, hitsTaken, over } = game.state;
//! ```
//!
//! Steps are 1/60 s. Jump with down drops through a one-way platform. `coins()` gives
//! `x, y, radius`, `enemies()` `x, y, halfWidth, halfHeight`, `platform()` the moving
//! platform's top `x0, y0, x1, y1` (empty without one), `goal()` and `bounds()` boxes
//! `minX, minY, maxX, maxY`, `segments()` as the dungeon's. `up` is −1 when y grows
//! downwards (ASCII levels) and 1 for Replica Island levels (y up, 32 units a cell:
//! `cellSize`).
//!
//! `game.tracePlayer(true)` records the player's moves from then on (off by default);
//! `game.playerStory()` tells the last one in words, as `tileslide explain --character`
//! does (each sweep, the surfaces met by cell and tile, the landing), or `null`.
//!
//! # Errors and memory
//!
//! Every refusal is thrown as an `Error` whose message is the Rust error's; no input
//! panics (numbers that must be whole are checked, never wrapped). Objects hold wasm
//! memory until `.free()`, or until the garbage collector runs a `FinalizationRegistry`
//! callback (the build enables it).
#![forbid(unsafe_code)]

pub mod args;
pub mod draw;
pub mod dungeon;
pub mod platformer;
pub mod story;

use wasm_bindgen::prelude::*;

#[wasm_bindgen]
extern "C" {
    /// `new DungeonGame`'s options: `{scripted?: boolean}`.
    #[wasm_bindgen(typescript_type = "DungeonOptions")]
    pub type DungeonOptions;

    /// The keys held for a platformer step: a number of `Keys` bits or `PlatformerKeys`.
    #[wasm_bindgen(typescript_type = "number | PlatformerKeys")]
    pub type PlatformerInput;
}

#[wasm_bindgen(typescript_custom_section)]
const TS_TYPES: &str = r#"
/** How a Dungeon Builder game is kept: `scripted: true` for the keeper's script (the CLI
 * demo's game), else by the player's orders. */
export interface DungeonOptions {
    scripted?: boolean;
}

/** What a Dungeon Builder HUD shows. Times are in seconds of game time. */
export interface DungeonState {
    steps: number;
    time: number;
    /** Hero parties arrived so far. */
    wave: number;
    /** Seconds until the next party, or `null` when no more will come. */
    nextWaveIn: number | null;
    gold: number;
    /** Heroes in the dungeon or waiting at the entrance. */
    heroesAlive: number;
    creaturesAlive: number;
    heroesLost: number;
    heroesEscaped: number;
    creaturesSummoned: number;
    creaturesLost: number;
    /** Pieces of treasure on the pile. */
    treasureLeft: number;
    treasureTaken: number;
    /** Pieces carried out of the dungeon: all five and the game is lost. */
    treasureStolen: number;
    squaresDug: number;
    scripted: boolean;
    outcome: "playing" | "won" | "lost";
    over: boolean;
}

/** The keeper's prices in gold, and how many creatures it keeps at most. */
export interface DungeonCosts {
    dig: number;
    imp: number;
    skeleton: number;
    maxCreatures: number;
}

/** Keys held for a platformer step. */
export interface PlatformerKeys {
    left?: boolean;
    right?: boolean;
    jump?: boolean;
    down?: boolean;
}

/** What a platformer HUD shows. */
export interface PlatformerState {
    steps: number;
    time: number;
    coins: number;
    coinsTotal: number;
    enemiesDefeated: number;
    enemiesTotal: number;
    hitsTaken: number;
    jumps: number;
    grounded: boolean;
    invulnerable: boolean;
    reachedGoal: boolean;
    /** The goal reached or the player fell out of the map. */
    over: boolean;
}
"#;
