// The demo games as the playground plays them (web/games-pkg, built by build.sh): the
// scripted keeper's game is the native one bit for bit, a person digs and summons, the
// platformer runs and jumps, a Replica Island level loads from its bytes, and bad input is
// an Error, never a crash.
import { test } from "node:test";
import assert from "node:assert/strict";
import { existsSync, readFileSync } from "node:fs";
import { fileURLToPath } from "node:url";

import { initSync, DungeonGame, PlatformerGame, Keys } from "../games-pkg/tileslide_games.js";

const here = (path) => fileURLToPath(new URL(path, import.meta.url));
initSync({ module: readFileSync(here("../games-pkg/tileslide_games_bg.wasm")) });

// The same constants as crates/tileslide-games-wasm/tests/native.rs.
const SCRIPTED_SEED_3_900_STEPS = "8205ccf86cfaa4a0";
const PLAYED_SEED_1_600_STEPS = "9bf34ef5bf9a5aea";

test("the scripted keeper's game has the native state hash", () => {
  const game = new DungeonGame(3, { scripted: true });
  game.step(900);
  assert.equal(game.stateHash(), SCRIPTED_SEED_3_900_STEPS);
  assert.equal(game.state.steps, 900);
  assert.equal(game.state.scripted, true);
  assert.ok(game.state.squaresDug > 0);
  // A BigInt seed is the same seed.
  const again = new DungeonGame(3n, { scripted: true });
  for (let i = 0; i < 900; i++) again.step();
  assert.equal(again.stateHash(), SCRIPTED_SEED_3_900_STEPS);
  assert.throws(() => game.dig(32, 28), /the scripted keeper plays this game/);
  game.free();
  again.free();
});

test("a person digs a diggable square: gold drops by 50 and the square opens", () => {
  const game = new DungeonGame(1);
  const { width, height } = game;
  assert.deepEqual([width, height], [64, 64]);
  assert.equal(game.costs.dig, 50);
  const before = game.state.gold;
  const squares = game.squares();
  assert.equal(squares.length, width * height);
  const diggable = game.diggable();
  assert.ok(diggable.length > 0 && diggable.length % 2 === 0);
  // Every listed square is marked diggable (2) in squares().
  for (let i = 0; i < diggable.length; i += 2) {
    assert.equal(squares[diggable[i + 1] * width + diggable[i]], 2);
  }
  const [col, row] = [31, 20];
  assert.equal(game.isDiggable(col, row), true);
  const segmentsBefore = game.segments().length;
  game.dig(col, row);
  assert.equal(game.state.gold, before - 50);
  assert.equal(game.state.squaresDug, 1);
  assert.equal(game.squares()[row * width + col], 1, "open and not yet seen");
  assert.equal(game.isDiggable(col, row), false);
  assert.equal(game.isDiggable(col - 1, row), true);
  assert.notEqual(game.segments().length, segmentsBefore);
  assert.deepEqual([...game.dug()], [col, row]);
  game.free();
});

test("a person summons creatures at their costs and sees them drawn", () => {
  const game = new DungeonGame(1);
  const gold = game.state.gold;
  const { imp, skeleton } = game.costs;
  game.summon("skeleton", 32.5, 12.5);
  game.summon("imp", 32.5, 16.5);
  assert.equal(game.state.gold, gold - imp - skeleton);
  assert.equal(game.state.creaturesAlive, 2);
  const fighters = game.creatures();
  assert.equal(fighters.length, 14);
  // x, y, radius, kind (1 skeleton), team (1 keeper), hp fraction, carrying.
  assert.deepEqual([...fighters.slice(0, 7)], [32.5, 12.5, Math.fround(0.35), 1, 1, 1, 0]);
  assert.equal(fighters[7 + 3], 2, "an imp");
  assert.throws(() => game.summon("hero", 32.5, 12.5), /summons "imp" or "skeleton"/);
  assert.throws(() => game.summon("imp", 20.5, 20.5), /not in an open square/);
  assert.throws(() => game.summon("imp", NaN, 20.5), /must be finite/);
  game.free();
});

test("orders given in the browser replay the native game", () => {
  const game = new DungeonGame(1);
  game.dig(31, 20);
  game.summon("imp", 32.5, 20.5);
  game.step(600);
  assert.equal(game.stateHash(), PLAYED_SEED_1_600_STEPS);
  const s = game.state;
  assert.equal(s.wave, 1);
  assert.ok(s.time === 20 && s.nextWaveIn > 0, JSON.stringify(s));
  assert.equal(s.outcome, "playing");
  game.free();
});

test("refused orders and bad arguments are Errors naming why", () => {
  const game = new DungeonGame(1);
  assert.throws(() => game.dig(0, 0), /\(0, 0\): the square is rock/);
  assert.throws(() => game.dig(32, 20), /open already/);
  assert.throws(() => game.dig(20, 20), /not beside an open square/);
  assert.throws(() => game.dig(-1, 3), /dig: col is -1, not a whole number/);
  assert.throws(() => game.dig(2.5, 3), /dig: col is 2.5/);
  assert.throws(() => game.dig(NaN, 3), /dig: col is NaN/);
  assert.throws(() => game.dig(1e12, 3), /dig: col is 1000000000000/);
  assert.equal(game.isDiggable(NaN, 3), false);
  assert.throws(() => game.step(-1), /step: n is -1/);
  assert.throws(() => game.step(1e9), /step: n is 1000000000/);
  assert.throws(() => new DungeonGame(-1), /the seed is/);
  assert.throws(() => new DungeonGame(1.5), /the seed is/);
  assert.throws(() => new DungeonGame("1"), /the seed is/);
  assert.throws(() => new DungeonGame(1, { scripted: "yes" }), /options.scripted must be true or false/);
  // Spend everything, then one more square.
  for (let row = 15; row < 21; row++) game.dig(31, row);
  assert.equal(game.state.gold, 0);
  assert.throws(() => game.dig(30, 20), /costs 50 gold and the keeper has 0/);
  // Still usable after every refusal.
  game.step(30);
  assert.equal(game.state.gold, 20);
  game.free();
});

test("the HUD reports the end of an undefended game", () => {
  const game = new DungeonGame(1);
  for (let i = 0; i < 12 && !game.state.over; i++) game.step(900);
  const s = game.state;
  assert.equal(s.outcome, "lost", JSON.stringify(s));
  assert.equal(s.over, true);
  assert.equal(s.treasureStolen, 5);
  assert.throws(() => game.dig(31, 20), /the game is over/);
  game.free();
});

test("the platformer: hold right, then jump, and the player rises and lands", () => {
  const game = new PlatformerGame();
  const [x0, y0] = game.player();
  game.step(Keys.Right, 20);
  const [x1, y1] = game.player();
  assert.ok(x1 > x0 + 1, `${x0} → ${x1}`);
  assert.equal(game.state.grounded, true);
  game.step({ right: true, jump: true });
  assert.equal(game.state.jumps, 1);
  let highest = y1;
  let landed = false;
  for (let i = 0; i < 120 && !landed; i++) {
    game.step(Keys.Right);
    highest = Math.min(highest, game.player()[1]);
    landed = game.state.grounded;
  }
  assert.ok(highest < y1 - 1, `rose to ${highest} from ${y1}`);
  assert.ok(landed, "never landed");
  assert.ok(game.player()[0] > x1);
  assert.equal(game.up, -1);
  assert.equal(game.coins().length, 3 * game.state.coinsTotal - 3 * game.state.coins);
  assert.equal(game.enemies().length, 8);
  assert.equal(game.platform().length, 4);
  assert.equal(game.segments().length % 7, 0);
  assert.ok(y0 > 0);
  game.free();
});

test("the platformer refuses bad input with Errors", () => {
  const game = new PlatformerGame();
  assert.throws(() => game.step(16), /input bits is 16/);
  assert.throws(() => game.step(-1), /input bits is -1/);
  assert.throws(() => game.step("right"), /must be a number of Keys bits/);
  assert.throws(() => game.step(0, 1.5), /step: n is 1.5/);
  assert.throws(() => PlatformerGame.fromAscii("#...\n####"), /no player start/);
  assert.throws(() => PlatformerGame.fromReplicaIsland(new Uint8Array([96, 1]), new Uint8Array([1, 2, 3])), /collision.bin/);
  game.step();
  assert.equal(game.state.steps, 1);
  game.free();
});

const replica = here("../../../shared/data/replica-island/");
test("a Replica Island level loads from its bytes and is played", { skip: !existsSync(replica) && !process.env.CI && "no ../shared/data/replica-island" }, () => {
  const game = PlatformerGame.fromReplicaIsland(
    readFileSync(replica + "level_1_1_island.bin"),
    readFileSync(replica + "collision.bin"),
  );
  assert.equal(game.up, 1);
  assert.equal(game.cellSize, 32);
  assert.equal(game.name, "level.bin");
  const [x0] = game.player();
  game.step(Keys.Right, 120);
  const [x1] = game.player();
  assert.ok(x1 > x0, `${x0} → ${x1}`);
  assert.equal(game.state.steps, 120);
  assert.ok(game.segments().length > 0);
  const [minX, , maxX] = game.bounds();
  assert.ok(minX <= x1 && x1 <= maxX);
  game.free();
});

test("mutated Replica Island bytes load or throw an Error, never crash the module", { skip: !existsSync(replica) && !process.env.CI && "no ../shared/data/replica-island" }, () => {
  const level = readFileSync(replica + "level_1_1_island.bin");
  const tiles = readFileSync(replica + "collision.bin");
  // A fixed linear congruential sequence: the same mutations every run.
  let seed = 12345;
  const next = (n) => {
    seed = (Math.imul(seed, 1103515245) + 12345) >>> 0;
    return seed % n;
  };
  let loaded = 0;
  for (let round = 0; round < 150; round++) {
    const [bytes, other] = round % 3 === 0 ? [Uint8Array.from(tiles), level] : [Uint8Array.from(level), tiles];
    const cut = next(4) === 0 ? next(bytes.length) : bytes.length;
    for (let k = 0; k < 1 + next(8); k++) bytes[next(bytes.length)] = next(256);
    const mutated = bytes.subarray(0, cut);
    try {
      const game = round % 3 === 0
        ? PlatformerGame.fromReplicaIsland(other, mutated)
        : PlatformerGame.fromReplicaIsland(mutated, other);
      game.step(Keys.Right | Keys.Jump, 30);
      game.free();
      loaded++;
    } catch (e) {
      assert.ok(!(e instanceof WebAssembly.RuntimeError), `round ${round}: ${e}`);
      assert.ok(e instanceof Error && e.message.length > 0, `round ${round}: ${e}`);
    }
  }
  // The module is still sound.
  const game = new PlatformerGame();
  game.step(Keys.Right, 10);
  assert.equal(game.state.steps, 10);
  game.free();
  assert.ok(loaded > 0, "no mutation loaded");
});

test("random orders are carried out or refused with an Error, never crash the module", () => {
  const game = new DungeonGame(9);
  let seed = 777;
  const next = (n) => {
    seed = (Math.imul(seed, 1103515245) + 12345) >>> 0;
    return seed % n;
  };
  const values = [NaN, Infinity, -Infinity, -1, 1e30, -0, 0.5];
  const number = (n) => (next(10) === 0 ? values[next(values.length)] : next(n) + (next(2) ? 0.5 : 0));
  let accepted = 0;
  for (let i = 0; i < 400; i++) {
    try {
      if (next(2)) game.dig(number(70), number(70));
      else game.summon(next(2) ? "imp" : "skeleton", number(70), number(70));
      accepted++;
    } catch (e) {
      assert.ok(!(e instanceof WebAssembly.RuntimeError), `order ${i}: ${e}`);
      assert.ok(e instanceof Error && e.message.length > 0);
    }
    if (i % 10 === 0) game.step(15);
  }
  assert.ok(accepted > 0);
  const s = game.state;
  assert.equal(s.squaresDug + s.creaturesSummoned, accepted);
  game.free();
});
