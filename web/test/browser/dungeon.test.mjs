// Dungeon Builder in Chromium: it starts without a console error; with the game paused, a
// click on a square marked 50 digs it (gold drops by 50 and the square opens, on the
// canvas too); a creature is summoned with the keyboard and the mouse; sped up, the first
// hero party arrives and is drawn cyan; the scripted keeper digs on its own, and its game
// is the games package's in Node from the same seed, state hash for state hash.
import { test } from "node:test";
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import { fileURLToPath } from "node:url";

import { DungeonGame, initSync } from "../../games-pkg/tileslide_games.js";

import { clientAt, colorAt, rgba, screenshot, stateOf, waitFrames, usePage } from "./harness.mjs";

const session = usePage("dungeon");

const EARTH = rgba("#6b4a2b");
const OPEN = [rgba("#b08a5e"), rgba("#e6d84a")]; // seen floor, not explored yet

/** How many canvas pixels have exactly `color`. */
function countPixels(color) {
  return session.page.evaluate((color) => {
    const canvas = document.getElementById("canvas");
    const data = canvas.getContext("2d").getImageData(0, 0, canvas.width, canvas.height).data;
    let n = 0;
    for (let i = 0; i < data.length; i += 4) {
      if (data[i] === color[0] && data[i + 1] === color[1] && data[i + 2] === color[2]) n++;
    }
    return n;
  }, color);
}

test("the game starts for the player, with gold and nothing dug", async () => {
  const s = await stateOf(session.page);
  assert.equal(s.scripted, false);
  assert.equal(s.squaresDug, 0);
  assert.ok(s.gold >= 100, `gold ${s.gold}`);
  assert.equal(s.outcome, "playing");
  assert.deepEqual(session.errors, []);
});

test("a click on a square marked 50 digs it: gold drops by 50 and the square opens", async () => {
  await session.page.keyboard.press("Space"); // pause: no income or wave while we look
  assert.equal((await stateOf(session.page)).paused, true);
  await session.page.keyboard.press("d");
  const [col, row] = await session.page.evaluate(() => window.__tileslide.diggable().slice(0, 2));
  assert.equal(await session.page.evaluate(([c, r]) => window.__tileslide.square(c, r), [col, row]), 2);
  // A corner of the square, away from its "50".
  const corner = [col + 0.12, row + 0.12];
  assert.deepEqual(await colorAt(session.page, ...corner), EARTH);
  const before = await stateOf(session.page);
  const at = await clientAt(session.page, col + 0.5, row + 0.5);
  await session.page.mouse.click(at.x, at.y);
  await waitFrames(session.page, 2);
  const after = await stateOf(session.page);
  assert.equal(after.gold, before.gold - 50);
  assert.equal(after.squaresDug, before.squaresDug + 1);
  assert.equal(after.steps, before.steps, "paused: no step ran");
  const code = await session.page.evaluate(([c, r]) => window.__tileslide.square(c, r), [col, row]);
  assert.ok(code === 0 || code === 1, `square code ${code} is not open`);
  const color = await colorAt(session.page, ...corner);
  assert.ok(OPEN.some((c) => c.every((v, i) => v === color[i])), `corner drawn ${color}`);
  assert.match(after.message, /dug square/);
  assert.deepEqual(session.errors, []);
});

test("a click on earth away from the dungeon is refused with a message, not an error", async () => {
  const before = await stateOf(session.page);
  // A square of earth (code 3: not beside an open square) that the canvas shows.
  const at = await session.page.evaluate(() => {
    const hook = window.__tileslide;
    const { width, height } = hook.state();
    const r = document.getElementById("canvas").getBoundingClientRect();
    for (let row = 0; row < height; row++) {
      for (let col = 0; col < width; col++) {
        if (hook.square(col, row) !== 3) continue;
        const p = hook.clientAt(col + 0.5, row + 0.5);
        if (p.x > r.left + 40 && p.x < r.right - 10 && p.y > r.top + 40 && p.y < r.bottom - 10) return p;
      }
    }
    return null;
  });
  assert.ok(at, "the canvas shows earth that cannot be dug");
  await session.page.mouse.click(at.x, at.y);
  const after = await stateOf(session.page);
  assert.equal(after.gold, before.gold);
  assert.notEqual(after.message, before.message);
  assert.deepEqual(session.errors, []);
});

test("an imp summoned with I and a click stands where it was put", async () => {
  const before = await stateOf(session.page);
  await session.page.keyboard.press("i");
  // The treasure room is open floor.
  const [tx, ty] = await session.page.evaluate(() => Array.from(window.__tileslide.treasure()));
  const at = await clientAt(session.page, tx + 1, ty);
  await session.page.mouse.click(at.x, at.y);
  await waitFrames(session.page, 2);
  const after = await stateOf(session.page);
  assert.equal(after.creaturesSummoned, before.creaturesSummoned + 1, after.message);
  assert.equal(after.creaturesAlive, before.creaturesAlive + 1);
  assert.ok(after.gold < before.gold);
  assert.ok((await countPixels(rgba("#ff6fb5"))) > 0, "an imp is drawn pink");
  assert.deepEqual(session.errors, []);
});

test("the explain tool: a click on the imp tells its last step", async () => {
  assert.equal((await stateOf(session.page)).paused, true);
  await session.page.keyboard.press("e");
  // A few steps traced (however many frames they take), then paused again.
  const { steps } = await stateOf(session.page);
  await session.page.keyboard.press("Space");
  await session.page.waitForFunction((n) => window.__tileslide.state().steps >= n + 3, steps);
  await session.page.keyboard.press("Space");
  const fighters = await session.page.evaluate(() => window.__tileslide.fighters());
  const imp = fighters.findIndex((v, i) => i % 7 === 3 && v === 2) - 3;
  assert.ok(imp >= 0, "the imp is there");
  const at = await clientAt(session.page, fighters[imp], fighters[imp + 1]);
  await session.page.mouse.click(at.x, at.y);
  await waitFrames(session.page, 1);
  const s = await stateOf(session.page);
  assert.match(s.story, /^imp \d+, step \d+: at \(\d+\.\d{3}, \d+\.\d{3}\), proposed \(/);
  assert.match(s.story, /\n  resolved \(-?\d+\.\d{3}, -?\d+\.\d{3}\): ends at \(/);
  assert.equal(await session.page.textContent("#story"), s.story);
  await session.page.keyboard.press("d");
  assert.deepEqual(session.errors, []);
});

test("sped up, the first party of heroes arrives and is drawn cyan", async () => {
  await session.page.keyboard.press("Space"); // resume
  for (let i = 0; i < 3; i++) await session.page.keyboard.press("+");
  assert.equal((await stateOf(session.page)).speed, 8);
  await session.page.waitForFunction(() => window.__tileslide.state().heroesAlive > 0, null, { timeout: 20_000 });
  await session.page.waitForFunction(() => window.__tileslide.state().time > 16, null, { timeout: 20_000 });
  const s = await stateOf(session.page);
  assert.ok(s.wave >= 1);
  assert.ok((await countPixels(rgba("#35e0e0"))) > 0, "heroes are drawn cyan");
  await session.page.keyboard.press("Space");
  await waitFrames(session.page, 2);
  await screenshot(session.page, "playground-dungeon.png");
  await session.page.keyboard.press("Space");
  assert.deepEqual(session.errors, []);
});

test("the scripted keeper digs on its own and plays the game Node plays from the same seed", async () => {
  await session.page.click("#scripted");
  const s = await stateOf(session.page);
  assert.equal(s.scripted, true);
  await session.page.waitForFunction(() => window.__tileslide.state().squaresDug > 0, null, { timeout: 20_000 });
  // Paused, the page's game is the one the games package plays in Node from the same seed
  // for as many steps (whose hash the Rust tests hold equal to native).
  await session.page.keyboard.press("Space");
  const played = await stateOf(session.page);
  assert.equal(played.paused, true);
  initSync({ module: readFileSync(fileURLToPath(new URL("../../games-pkg/tileslide_games_bg.wasm", import.meta.url))) });
  const game = new DungeonGame(1, { scripted: true });
  game.step(played.steps);
  assert.equal(played.hash, game.stateHash(), `after ${played.steps} steps`);
  game.free();
  assert.deepEqual(session.errors, []);
});
