// The Sandbox in Chromium: it starts without a console error, a square painted with the
// mouse is in the map (the canvas shows it, and a ray dragged across it stops on its face
// with the face's normal, cell and tile), and the ray filters change what the ray meets.
import { after, before, test } from "node:test";
import assert from "node:assert/strict";

import { clientAt, colorAt, openPage, rgba, screenshot, startPlayground, stateOf, waitFrames } from "./harness.mjs";

let site;
let page;
let errors;

before(async () => {
  site = await startPlayground();
  ({ page, errors } = await openPage(site, "sandbox"));
});

after(async () => {
  await site?.close();
});

/** Presses the mouse at world point `from`, drags to `to` in `steps` moves, releases. */
async function drag(from, to, steps = 8) {
  const a = await clientAt(page, ...from);
  const b = await clientAt(page, ...to);
  await page.mouse.move(a.x, a.y);
  await page.mouse.down();
  await page.mouse.move(b.x, b.y, { steps });
  await page.mouse.up();
}

test("the sandbox starts with the cave and no console error", async () => {
  const state = await stateOf(page);
  assert.deepEqual([state.width, state.height], [40, 16]);
  assert.deepEqual(errors, []);
});

test("a square painted with the mouse is in the map and on the canvas", async () => {
  const cell = [10, 8];
  const centre = [cell[0] + 0.5, cell[1] + 0.5];
  assert.equal(await page.evaluate(([c, r]) => window.__tileslide.tileAt(c, r), cell), null);
  const empty = await colorAt(page, ...centre);
  await page.keyboard.press("1");
  const at = await clientAt(page, ...centre);
  await page.mouse.click(at.x, at.y);
  await waitFrames(page, 2);
  assert.equal(await page.evaluate(([c, r]) => window.__tileslide.tileAt(c, r), cell), 1);
  const painted = await colorAt(page, ...centre);
  assert.notDeepEqual(painted, empty);
  assert.deepEqual(painted, rgba("#4a3b2c"), "the square is filled with the solid colour");
  assert.deepEqual(errors, []);
});

test("a square painted beside another hides the seam between them", async () => {
  const HIDDEN = 3; // DebugKind.HiddenSegment
  const ACTIVE = 0; // DebugKind.ActiveSegment
  const onSeam = ([x0, y0, x1, y1]) => x0 === 11 && x1 === 11 && Math.min(y0, y1) >= 8 && Math.max(y0, y1) <= 9;
  const seam = (kind) => page.evaluate((k) => window.__tileslide.segments(k), kind);
  assert.equal((await seam(ACTIVE)).filter(onSeam).length, 1, "the square's right face is active");
  assert.equal((await seam(HIDDEN)).filter(onSeam).length, 0);
  const at = await clientAt(page, 11.5, 8.5);
  await page.mouse.click(at.x, at.y);
  await waitFrames(page, 2);
  assert.equal((await seam(ACTIVE)).filter(onSeam).length, 0, "no active segment on the seam");
  assert.equal((await seam(HIDDEN)).filter(onSeam).length, 2, "both faces of the seam hidden");
  // Erased again (5): the face is active once more.
  await page.keyboard.press("5");
  await page.mouse.click(at.x, at.y);
  await waitFrames(page, 2);
  assert.equal(await page.evaluate(() => window.__tileslide.tileAt(11, 8)), null);
  assert.equal((await seam(ACTIVE)).filter(onSeam).length, 1);
  assert.equal((await seam(HIDDEN)).filter(onSeam).length, 0);
  assert.deepEqual(errors, []);
});

test("a ray dragged across the painted square stops on its left face", async () => {
  await page.keyboard.press("r");
  await drag([5.5, 8.5], [15.5, 8.5]);
  await waitFrames(page, 2);
  const { ray } = await stateOf(page);
  assert.ok(ray.hit, "the ray hits");
  assert.equal(ray.hit.x, 10);
  // The mouse lands on whole CSS pixels: the ray's ends are the world points under them.
  assert.ok(Math.abs(ray.y0 - 8.5) < 0.05 && Math.abs(ray.y1 - 8.5) < 0.05, `y ${ray.y0} ${ray.y1}`);
  const expectedT = (10 - ray.x0) / (ray.x1 - ray.x0);
  assert.ok(Math.abs(ray.hit.t - expectedT) < 1e-5, `t = ${ray.hit.t}, expected ${expectedT}`);
  assert.deepEqual([ray.hit.nx, ray.hit.ny], [-1, 0]);
  assert.deepEqual(ray.hit.cell, [10, 8]);
  assert.equal(ray.hit.tile, 1);
  // The hit point is marked in red on the canvas.
  assert.deepEqual(await colorAt(page, ray.hit.x, ray.hit.y), rgba("#ff4d4d"));
  const readout = await page.textContent("#ray-readout");
  assert.match(readout, /cell \[10, 8\]/);
  assert.deepEqual(errors, []);
});

test("the ray filters choose the faces the ray meets", async () => {
  // Floors only: a level ray meets no floor.
  await page.selectOption("#filter", "down");
  let { ray } = await stateOf(page);
  assert.equal(ray.hit, null);
  // Only faces that oppose a move to the right: the square's left face again.
  await page.selectOption("#filter", "right");
  ({ ray } = await stateOf(page));
  assert.equal(ray.hit?.x, 10);
  // From inside the square, front faces see nothing until the cave's right wall; both
  // sides see the square's own right face from behind.
  await page.selectOption("#filter", "front");
  await drag([10.5, 8.5], [39.5, 8.5]);
  ({ ray } = await stateOf(page));
  assert.equal(ray.hit?.x, 39);
  await page.keyboard.press("f"); // front → both sides
  ({ ray } = await stateOf(page));
  assert.equal((await stateOf(page)).filter, "both");
  assert.equal(ray.hit?.x, 11);
  assert.deepEqual(ray.hit?.cell, [10, 8]);
  assert.deepEqual(errors, []);
});

test("a screenshot of the sandbox", async () => {
  await page.selectOption("#filter", "front");
  await drag([3.5, 3.5], [20.5, 12.2]);
  await waitFrames(page, 2);
  await screenshot(page, "playground-sandbox.png");
  assert.deepEqual(errors, []);
});
