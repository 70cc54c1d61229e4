// The platformer in Chromium: it starts on the bundled level without a console error, the
// arrow keys run the player, and a jump made with the keyboard lands it on the one-way
// platform two cells above the floor (row 8 of examples/maps/platformer.txt); a Replica
// Island level chosen with the file pickers runs with the same keys.
import { test } from "node:test";
import assert from "node:assert/strict";
import { existsSync } from "node:fs";
import { fileURLToPath } from "node:url";

import { clientAt, colorAt, rgba, screenshot, stateOf, waitFrames, usePage } from "./harness.mjs";

const session = usePage("platformer");

/** Waits until the player (its state through the hook) satisfies `condition`, a function
 * of the state run in the page. */
function waitForPlayer(condition, timeout = 10_000) {
  return session.page.waitForFunction(
    (source) => new Function("s", `return (${source})(s)`)(window.__tileslide.state()),
    String(condition),
    { timeout },
  );
}

test("the bundled level starts with the player standing at its start", async () => {
  // The player's contacts are known once it has moved: the first frames may run no step.
  await waitForPlayer((s) => s.steps > 0);
  const s = await stateOf(session.page);
  assert.equal(s.name, "platformer.txt");
  assert.equal(s.grounded, true);
  assert.equal(s.coinsTotal, 10);
  assert.equal(s.enemiesTotal, 2);
  const [x, y] = s.player;
  assert.ok(Math.abs(x - 2.5) < 1e-6, `x = ${x}`);
  // Feet on the floor (the top of row 10).
  assert.ok(Math.abs(y + s.player[3] - 10) < 0.01, `feet at ${y + s.player[3]}`);
  assert.deepEqual(await colorAt(session.page, x, y), rgba("#35e0e0"), "the player is drawn cyan");
  assert.deepEqual(session.errors, []);
});

test("a click on the player tells its last move: on the ground, the floor's cell", async () => {
  const s = await stateOf(session.page);
  const [x, y] = s.player;
  const at = await clientAt(session.page, x, y);
  await session.page.mouse.click(at.x, at.y);
  const story = (await stateOf(session.page)).story;
  assert.match(story, /^player, step \d+: at \(/);
  assert.match(story, /on the ground: cell \(2, 10\) tile 1 segment \d/);
  assert.equal(await session.page.textContent("#story"), story);
  assert.deepEqual(session.errors, []);
});

test("the right arrow runs the player, and a jump lands it on the one-way platform", async () => {
  await session.page.keyboard.down("ArrowRight");
  await waitForPlayer((s) => s.player[0] >= 14);
  await session.page.keyboard.down("Space");
  await waitForPlayer((s) => !s.grounded);
  await session.page.keyboard.up("Space");
  await waitForPlayer((s) => s.grounded);
  await session.page.keyboard.up("ArrowRight");
  await waitFrames(session.page, 10);
  const s = await stateOf(session.page);
  const [x, y, , hh] = s.player;
  assert.equal(s.grounded, true);
  assert.ok(Math.abs(y + hh - 8) < 0.01, `feet at ${y + hh}, not on the platform's top (8)`);
  assert.ok(x > 16 && x < 22, `x = ${x} is not over the platform (16..22)`);
  assert.ok(s.jumps >= 1);
  assert.deepEqual(await colorAt(session.page, x, y), rgba("#35e0e0"));
  await screenshot(session.page, "playground-platformer.png");
  assert.deepEqual(session.errors, []);
});

test("down and jump drop the player through the one-way platform", async () => {
  await session.page.keyboard.down("ArrowDown");
  await session.page.keyboard.down("Space");
  await waitForPlayer((s) => !s.grounded);
  await session.page.keyboard.up("Space");
  await session.page.keyboard.up("ArrowDown");
  await waitForPlayer((s) => s.grounded);
  const s = await stateOf(session.page);
  const [, y, , hh] = s.player;
  assert.ok(Math.abs(y + hh - 10) < 0.01, `feet at ${y + hh}, not on the floor (10)`);
  assert.deepEqual(session.errors, []);
});

/** Replica Island's files, beside the checkout (`../shared/data/replica-island/`). */
const REPLICA = fileURLToPath(new URL("../../../../shared/data/replica-island/", import.meta.url));
const replicaMissing = !existsSync(`${REPLICA}collision.bin`);

test(
  "a Replica Island level chosen with the file pickers runs with the same keys",
  // As the Rust tests do: without the data they skip, unless CI is set.
  { skip: replicaMissing && !process.env.CI && `no Replica Island data at ${REPLICA}` },
  async () => {
    // A file that is not a level is refused with a message naming it, not a page error.
    await session.page.setInputFiles("#tile-set", `${REPLICA}collision.bin`);
    await session.page.setInputFiles("#level", `${REPLICA}collision.bin`);
    await session.page.waitForFunction(() => /level\.bin/.test(window.__tileslide.state().message));
    assert.equal((await stateOf(session.page)).name, "platformer.txt");
    await session.page.setInputFiles("#level", `${REPLICA}level_1_1_island.bin`);
    await session.page.waitForFunction(() => window.__tileslide.state().name !== "platformer.txt");
    let s = await stateOf(session.page);
    assert.equal(s.up, 1, "Replica Island's y axis points up");
    assert.equal(s.cellSize, 32);
    await session.page.locator("#canvas").focus();
    await waitForPlayer((s) => s.grounded);
    const startX = (await stateOf(session.page)).player[0];
    await session.page.keyboard.down("ArrowRight");
    await waitForPlayer(`(s) => s.player[0] > ${startX + 64}`);
    await session.page.keyboard.up("ArrowRight");
    s = await stateOf(session.page);
    assert.ok(s.player[0] > startX + 64, `ran from ${startX} to ${s.player[0]}`);
    assert.deepEqual(await colorAt(session.page, s.player[0], s.player[1]), rgba("#35e0e0"));
    assert.deepEqual(session.errors, []);
  },
);
