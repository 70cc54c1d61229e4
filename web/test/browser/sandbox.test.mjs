// The Sandbox in Chromium: it starts without a console error, a square painted with the
// mouse is in the map (the canvas shows it, and a ray dragged across it stops on its face
// with the face's normal, cell and tile), and the ray filters change what the ray meets.
import { test } from "node:test";
import assert from "node:assert/strict";

import { clientAt, colorAt, rgba, screenshot, stateOf, waitFrames, usePage } from "./harness.mjs";

const session = usePage("sandbox");

/** Presses the mouse at world point `from`, drags to `to` in `steps` moves, releases. */
async function drag(from, to, steps = 8) {
  const a = await clientAt(session.page, ...from);
  const b = await clientAt(session.page, ...to);
  await session.page.mouse.move(a.x, a.y);
  await session.page.mouse.down();
  await session.page.mouse.move(b.x, b.y, { steps });
  await session.page.mouse.up();
}

test("the sandbox starts with the cave and no console error", async () => {
  const state = await stateOf(session.page);
  assert.deepEqual([state.width, state.height], [40, 16]);
  assert.deepEqual(session.errors, []);
});

test("a square painted with the mouse is in the map and on the canvas", async () => {
  const cell = [10, 8];
  const centre = [cell[0] + 0.5, cell[1] + 0.5];
  assert.equal(await session.page.evaluate(([c, r]) => window.__tileslide.tileAt(c, r), cell), null);
  const empty = await colorAt(session.page, ...centre);
  await session.page.keyboard.press("1");
  const at = await clientAt(session.page, ...centre);
  await session.page.mouse.click(at.x, at.y);
  await waitFrames(session.page, 2);
  assert.equal(await session.page.evaluate(([c, r]) => window.__tileslide.tileAt(c, r), cell), 1);
  const painted = await colorAt(session.page, ...centre);
  assert.notDeepEqual(painted, empty, `painted ${painted}, before ${empty}`);
  assert.deepEqual(painted, rgba("#4a3b2c"), "the square is filled with the solid colour");
  assert.deepEqual(session.errors, []);
});

test("a canvas resized by the page is drawn again before the browser shows it", async () => {
  // The square painted above, read once more in the moment after the canvas changed size:
  // its ResizeObserver runs after the frame's drawing, and setting a canvas's size clears
  // it, so the page draws it again there, not a frame later.
  const centre = [10.5, 8.5];
  const readAfterResize = (width) =>
    session.page.evaluate(
      ([x, y, width]) =>
        new Promise((resolve) => {
          const canvas = document.getElementById("canvas");
          canvas.style.width = width;
          requestAnimationFrame(() =>
            setTimeout(() => {
              const { x: px, y: py } = window.__tileslide.pixelAt(x, y);
              resolve({
                size: [canvas.width, canvas.height],
                color: Array.from(canvas.getContext("2d").getImageData(px, py, 1, 1).data),
              });
            }, 0),
          );
        }),
      [...centre, width],
    );
  const before = await stateOf(session.page);
  const narrow = await readAfterResize("80%");
  const wide = await readAfterResize("");
  assert.ok(narrow.size[0] < wide.size[0], `the canvas narrowed: ${narrow.size} then ${wide.size}`);
  assert.deepEqual(narrow.color, rgba("#4a3b2c"), "drawn at once when narrowed");
  assert.deepEqual(wide.color, rgba("#4a3b2c"), "drawn at once when widened again");
  assert.equal((await stateOf(session.page)).width, before.width);
  assert.deepEqual(session.errors, []);
});

test("a square painted beside another hides the seam between them", async () => {
  const HIDDEN = 3; // DebugKind.HiddenSegment
  const ACTIVE = 0; // DebugKind.ActiveSegment
  const onSeam = ([x0, y0, x1, y1]) => x0 === 11 && x1 === 11 && Math.min(y0, y1) >= 8 && Math.max(y0, y1) <= 9;
  const seam = (kind) => session.page.evaluate((k) => window.__tileslide.segments(k), kind);
  assert.equal((await seam(ACTIVE)).filter(onSeam).length, 1, "the square's right face is active");
  assert.equal((await seam(HIDDEN)).filter(onSeam).length, 0);
  const at = await clientAt(session.page, 11.5, 8.5);
  await session.page.mouse.click(at.x, at.y);
  await waitFrames(session.page, 2);
  assert.equal((await seam(ACTIVE)).filter(onSeam).length, 0, "no active segment on the seam");
  assert.equal((await seam(HIDDEN)).filter(onSeam).length, 2, "both faces of the seam hidden");
  // Erased again (5): the face is active once more.
  await session.page.keyboard.press("5");
  await session.page.mouse.click(at.x, at.y);
  await waitFrames(session.page, 2);
  assert.equal(await session.page.evaluate(() => window.__tileslide.tileAt(11, 8)), null);
  assert.equal((await seam(ACTIVE)).filter(onSeam).length, 1);
  assert.equal((await seam(HIDDEN)).filter(onSeam).length, 0);
  assert.deepEqual(session.errors, []);
});

test("a ray dragged across the painted square stops on its left face", async () => {
  await session.page.keyboard.press("r");
  await drag([5.5, 8.5], [15.5, 8.5]);
  await waitFrames(session.page, 2);
  const { ray } = await stateOf(session.page);
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
  assert.deepEqual(await colorAt(session.page, ray.hit.x, ray.hit.y), rgba("#ff4d4d"));
  const readout = await session.page.textContent("#ray-readout");
  assert.match(readout, /cell \[10, 8\]/);
  assert.deepEqual(session.errors, []);
});

test("the ray filters choose the faces the ray meets", async () => {
  // Floors only: a level ray meets no floor.
  await session.page.selectOption("#filter", "down");
  let { ray } = await stateOf(session.page);
  assert.equal(ray.hit, null);
  // Only faces that oppose a move to the right: the square's left face again.
  await session.page.selectOption("#filter", "right");
  ({ ray } = await stateOf(session.page));
  assert.equal(ray.hit?.x, 10);
  // From inside the square, front faces see nothing until the cave's right wall; both
  // sides see the square's own right face from behind.
  await session.page.selectOption("#filter", "front");
  await drag([10.5, 8.5], [39.5, 8.5]);
  ({ ray } = await stateOf(session.page));
  assert.equal(ray.hit?.x, 39);
  await session.page.keyboard.press("f"); // front → both sides
  ({ ray } = await stateOf(session.page));
  assert.equal((await stateOf(session.page)).filter, "both");
  assert.equal(ray.hit?.x, 11);
  assert.deepEqual(ray.hit?.cell, [10, 8]);
  assert.deepEqual(session.errors, []);
});

/** The closest two circles come, as the gap between their edges (negative: overlap), over
 * every pair of the page's bodies. */
function closestGap() {
  return session.page.evaluate(() => {
    const c = window.__tileslide.circles();
    let gap = Infinity;
    for (let i = 0; i < c.length; i += 3) {
      for (let j = i + 3; j < c.length; j += 3) {
        const d = Math.hypot(c[i] - c[j], c[i + 1] - c[j + 1]) - c[i + 2] - c[j + 2];
        if (d < gap) gap = d;
      }
    }
    return gap;
  });
}

test("circles dropped with the mouse flow to it and slide around each other", async () => {
  await session.page.keyboard.press("c");
  const drops = [[3.5, 3.5], [4.5, 4.5], [3.5, 6.5], [5.5, 2.5]];
  for (const [x, y] of drops) {
    const at = await clientAt(session.page, x, y);
    await session.page.mouse.click(at.x, at.y);
  }
  let s = await stateOf(session.page);
  assert.equal(s.bodies, drops.length, s.message);
  // The mouse rests at the goal, far to the right, past the ceiling's pillar.
  const goal = [30.5, 6.5];
  const at = await clientAt(session.page, ...goal);
  await session.page.mouse.move(at.x, at.y, { steps: 4 });
  await session.page.waitForFunction(() => {
    const c = window.__tileslide.circles();
    return c.length > 0 && c.every((v, i) => i % 3 !== 0 || v > 20);
  }, null, { timeout: 20_000 });
  s = await stateOf(session.page);
  assert.deepEqual(s.goal, goal);
  const circles = await session.page.evaluate(() => window.__tileslide.circles());
  for (let i = 0; i < circles.length; i += 3) {
    assert.ok(circles[i] > 20, `circle ${i / 3} at x = ${circles[i]} did not flow`);
  }
  assert.ok((await closestGap()) > -1e-3, "no two circles overlap");
  assert.deepEqual(session.errors, []);
});

test("the broadphase and flow-arrow layers draw the bodies' boxes and the field's arrows", async () => {
  const counts = () => session.page.evaluate(() => window.__tileslide.crowdLineCounts());
  const pixels = () => session.page.evaluate(() => {
    const c = document.getElementById("canvas");
    const data = c.getContext("2d").getImageData(0, 0, c.width, c.height).data;
    let sum = 0;
    for (let i = 0; i < data.length; i += 4) sum = (sum * 31 + data[i] + 7 * data[i + 1] + 13 * data[i + 2]) % 1e9;
    return sum;
  });
  await session.page.click("#pause");
  await waitFrames(session.page, 2);
  const before = await pixels();
  for (const layer of ["broadphase", "flow"]) await session.page.check(`#layers input[data-layer="${layer}"]`);
  await waitFrames(session.page, 2);
  const { bodies } = await stateOf(session.page);
  const { boxes, arrows } = await counts();
  assert.equal(boxes, bodies, "a broadphase box for each circle");
  assert.ok(arrows > 100, `${arrows} flow arrows`);
  assert.notEqual(await pixels(), before, "the canvas shows them");
  for (const layer of ["broadphase", "flow"]) await session.page.uncheck(`#layers input[data-layer="${layer}"]`);
  await session.page.click("#pause");
  await waitFrames(session.page, 2);
  assert.deepEqual(session.errors, []);
});

test("10,000 bodies: the frame time is measured and shown", async (t) => {
  await session.page.click("#ten-thousand");
  let s = await stateOf(session.page);
  assert.equal(s.bodies, 10_000, s.message);
  await session.page.waitForFunction(() => window.__tileslide.state().frame.frames > 0, null, { timeout: 20_000 });
  // 120 frames of the crowd flowing to the mouse.
  const start = (await stateOf(session.page)).frame.frames;
  await session.page.waitForFunction((n) => window.__tileslide.state().frame.frames >= n, start + 120, {
    timeout: 120_000,
  });
  s = await stateOf(session.page);
  assert.ok(Number.isFinite(s.frame.mean) && s.frame.mean > 0);
  const readout = await session.page.textContent("#body-readout");
  assert.match(readout, /bodies 10,000/);
  assert.match(readout, /frame +\d+\.\d+ ms/);
  assert.ok((await closestGap()) > -1e-3, "no two of the 10,000 overlap");
  const figures =
    `${s.frame.mean.toFixed(2)} ms a frame (mean of the last 60), ` +
    `${s.frame.step.toFixed(2)} ms a step, ${s.frame.draw.toFixed(2)} ms drawing`;
  t.diagnostic(`sandbox with 10,000 bodies: ${figures}`);
  console.log(`# sandbox with 10,000 bodies: ${figures}`);
  await session.page.click("#clear-bodies");
  assert.deepEqual(session.errors, []);
});

test("the explain tool: a circle clicked tells how its last step stopped at the wall", async () => {
  const hook = (f, ...args) => session.page.evaluate(([f, args]) => window.__tileslide[f](...args), [f, args]);
  // The square painted at (10, 8) is the wall; the circle is dropped in the open cell left
  // of it, and moved into it with the steps paused.
  assert.equal(await hook("tileAt", 10, 8), 1);
  assert.equal(await hook("tileAt", 9, 8), null);
  if (!(await stateOf(session.page)).paused) await session.page.click("#pause");
  // The click on the button may have scrolled the canvas's top out of the window.
  await session.page.evaluate(() => window.scrollTo(0, 0));
  await session.page.keyboard.press("c");
  const drop = await clientAt(session.page, 9.5, 8.5);
  await session.page.mouse.click(drop.x, drop.y);
  const [handle] = await hook("bodyHandles");
  await session.page.keyboard.press("e");
  await hook("moveBody", handle, 1, 0);
  const circles = await hook("circles");
  const [x, y] = circles;
  assert.ok(x > 9.6 && x < 9.7, `the circle stopped at x = ${x}: ${circles}, ${JSON.stringify(await stateOf(session.page))}`);
  const at = await clientAt(session.page, x, y);
  await session.page.mouse.click(at.x, at.y);
  await waitFrames(session.page, 1);
  const shown = await hook("explain");
  assert.equal(shown.body, handle);
  assert.match(shown.story, new RegExp(`^body ${handle}, last step: at \\(9\\.\\d{3}, 8\\.\\d{3}\\), proposed \\(1\\.000, 0\\.000\\)`));
  assert.match(shown.readout, /cell \(10, 8\) tile 1 segment \d \(face\): t 0\.\d+, at \(10\.000, 8\.500\), normal \(-1\.000, 0\.000\)  <- first/);
  assert.match(shown.readout, /stopped: met straight on/);
  assert.deepEqual(session.errors, []);
});

test("the explain tool: hovering a hidden seam says which neighbour hides it", async () => {
  // A square beside the one at (10, 8): the seam between them is hidden on both sides.
  await session.page.keyboard.press("1");
  const square = await clientAt(session.page, 11.5, 8.5);
  await session.page.mouse.click(square.x, square.y);
  await session.page.keyboard.press("e");
  const seam = await clientAt(session.page, 10.95, 8.5);
  await session.page.mouse.move(seam.x, seam.y, { steps: 2 });
  await waitFrames(session.page, 1);
  const shown = await session.page.evaluate(() => window.__tileslide.explain());
  assert.deepEqual(shown.cell, [10, 8]);
  assert.equal(shown.segment.hidden, true);
  assert.match(shown.segment.state, /^hidden by cell \(11, 8\) tile 1 segment \d$/);
  assert.match(shown.readout, /segment \d hidden by cell \(11, 8\) tile 1 segment \d/);
  assert.match(shown.readout, /wholly hidden: no query, body or character ever meets it/);
  // Back as it was: the square erased, the circle gone, the steps running.
  await session.page.keyboard.press("5");
  await session.page.mouse.click(square.x, square.y);
  await session.page.click("#clear-bodies");
  await session.page.click("#pause");
  assert.deepEqual(session.errors, []);
});

test("a screenshot of the sandbox", async () => {
  // Circles of three sizes, flowing to the ray's end past the hill.
  await session.page.keyboard.press("c");
  for (const [i, radius] of [0.2, 0.35, 0.5].entries()) {
    await session.page.evaluate((r) => {
      const slider = document.getElementById("radius");
      slider.value = String(r);
      slider.dispatchEvent(new Event("input"));
    }, radius);
    for (let k = 0; k < 5; k++) {
      const at = await clientAt(session.page, 2 + 1.2 * k, 2 + 2 * i);
      await session.page.mouse.click(at.x, at.y);
    }
  }
  assert.equal((await stateOf(session.page)).bodies, 15);
  await session.page.keyboard.press("r");
  await session.page.selectOption("#filter", "front");
  await drag([33.5, 12.5], [9.5, 9.5]);
  await session.page.waitForTimeout(2500);
  await screenshot(session.page, "playground-sandbox.png");
  assert.deepEqual(session.errors, []);
});
