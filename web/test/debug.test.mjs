// Debug lines as a canvas draws them: typed arrays of segments, circles, points and boxes
// with their kinds, from a small ASCII map. Run with `npm test` after `npm run build`.
import { test } from "node:test";
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import { fileURLToPath } from "node:url";

import {
  initSync,
  Bodies,
  Character,
  DebugKind,
  DebugLines,
  FlowField,
  HitType,
  HitWorld,
  NavGrid,
  TileMap,
} from "../pkg/tileslide.js";

initSync({ module: readFileSync(fileURLToPath(new URL("../pkg/tileslide_bg.wasm", import.meta.url))) });

/** The segments of `lines` of `kind`, as [x0, y0, x1, y1] arrays. */
function segmentsOf(lines, kind) {
  const coords = lines.segments;
  const kinds = lines.segmentKinds;
  const out = [];
  for (let i = 0; i < kinds.length; i++) {
    if (kinds[i] === kind) out.push(Array.from(coords.subarray(4 * i, 4 * i + 4)));
  }
  return out;
}

test("the kinds are exported as constants with the core's numbers", () => {
  assert.equal(DebugKind.ActiveSegment, 0);
  assert.equal(DebugKind.OneWaySegment, 1);
  assert.equal(DebugKind.Normal, 2);
  assert.equal(DebugKind.HiddenSegment, 3);
  assert.equal(DebugKind.TemporarySegment, 4);
  assert.equal(DebugKind.Body, 5);
  assert.equal(DebugKind.BroadphaseBox, 16);
  assert.equal(DebugKind[3], "HiddenSegment");
});

test("the seam between two squares is hidden, not active", () => {
  const map = TileMap.fromAscii("##\n..");
  const lines = map.debugLines();
  assert.ok(lines.segments instanceof Float32Array);
  assert.ok(lines.segmentKinds instanceof Uint8Array);
  assert.equal(lines.segments.length, 4 * lines.segmentKinds.length);
  // Six active edges, each followed by its normal; the seam's two halves hidden.
  const active = segmentsOf(lines, DebugKind.ActiveSegment);
  const hidden = segmentsOf(lines, DebugKind.HiddenSegment);
  assert.equal(active.length, 6);
  assert.equal(segmentsOf(lines, DebugKind.Normal).length, 6);
  assert.equal(hidden.length, 2);
  for (const [x0, y0, x1, y1] of hidden) {
    assert.deepEqual([x0, x1], [1, 1]);
    assert.deepEqual([Math.min(y0, y1), Math.max(y0, y1)], [0, 1]);
  }
  assert.ok(active.every(([x0, , x1]) => !(x0 === 1 && x1 === 1)));
  // The top edge of the pair runs along y = 0, the bottom along y = 1, each two cells.
  const length = (s) => Math.hypot(s[2] - s[0], s[3] - s[1]);
  assert.equal(active.filter((s) => s[1] === 0 && s[3] === 0).map(length).reduce((a, b) => a + b), 2);
  assert.equal(lines.length, 14);
  assert.equal(lines.circles.length, 0);
  assert.equal(lines.points.length, 0);
  assert.equal(lines.boxes.length, 0);
  lines.free();
  map.free();
});

test("a normal starts at the middle of its segment and points out of the solid", () => {
  const map = TileMap.fromAscii("...\n.#.\n...", 2);
  const lines = map.debugLines();
  const coords = lines.segments;
  const kinds = lines.segmentKinds;
  let normals = 0;
  for (let i = 0; i < kinds.length; i++) {
    if (kinds[i] !== DebugKind.Normal) continue;
    normals++;
    // The segment before a normal is its wall.
    assert.equal(kinds[i - 1], DebugKind.ActiveSegment);
    const [ax, ay, bx, by] = coords.subarray(4 * (i - 1), 4 * i);
    const [nx0, ny0, nx1, ny1] = coords.subarray(4 * i, 4 * i + 4);
    assert.deepEqual([nx0, ny0], [(ax + bx) / 2, (ay + by) / 2]);
    assert.equal(Math.hypot(nx1 - nx0, ny1 - ny0), 0.5);
    // The tip is outside the block [2, 4]².
    assert.ok(nx1 < 2 || nx1 > 4 || ny1 < 2 || ny1 > 4);
  }
  assert.equal(normals, 4);
  lines.free();
  map.free();
});

test("a one-way platform is its own kind, and a block above hides it", () => {
  const map = TileMap.fromAscii("...\n.=.\n...");
  let lines = map.debugLines();
  assert.deepEqual(segmentsOf(lines, DebugKind.OneWaySegment), [[1, 1, 2, 1]]);
  lines.free();
  map.setTile(1, 0, 1); // A solid square above the platform.
  lines = map.debugLines();
  assert.equal(segmentsOf(lines, DebugKind.OneWaySegment).length, 0);
  assert.deepEqual(segmentsOf(lines, DebugKind.HiddenSegment), [[1, 1, 2, 1]]);
  lines.free();
  map.free();
});

test("a view limits the lines to what touches it", () => {
  const wide = "#.".repeat(100);
  const map = TileMap.fromAscii(wide);
  const all = map.debugLines();
  const some = map.debugLines([9.5, 0.25, 11.5, 0.75]);
  assert.ok(all.segmentKinds.length > 100);
  // The square in cell 10: its left and right edges cross the view.
  assert.deepEqual(segmentsOf(some, DebugKind.ActiveSegment).sort(), [[10, 1, 10, 0], [11, 0, 11, 1]].sort());
  assert.throws(() => map.debugLines([0, 0, 1]), /a view is 4 finite numbers/);
  assert.throws(() => map.debugLines([0, NaN, 1, 1]), /a view is 4 finite numbers/);
  all.free();
  some.free();
  map.free();
});

test("one buffer is cleared and refilled each frame, with its own view and kinds", () => {
  const map = TileMap.fromAscii("##\n..");
  const out = new DebugLines();
  out.setKinds([DebugKind.ActiveSegment]);
  for (let frame = 0; frame < 3; frame++) {
    out.clear();
    assert.equal(out.length, 0);
    map.fillDebugLines(out);
    assert.equal(out.length, 6);
    assert.ok(Array.from(out.segmentKinds).every((k) => k === DebugKind.ActiveSegment));
    assert.ok(Array.from(out.segmentOwners).every((o) => o === 0));
  }
  // Filling twice without clearing appends.
  map.fillDebugLines(out);
  assert.equal(out.length, 12);
  out.setKinds(null);
  out.setView([0, 0, 0.5, 0.5]);
  out.clear();
  map.fillDebugLines(out);
  assert.deepEqual(segmentsOf(out, DebugKind.ActiveSegment).length, 2);
  assert.throws(() => out.setKinds([200]), /200 is not a DebugKind/);
  out.free();
  map.free();
});

/** The shapes of `lines` of `kind` among `coords` (`n` floats a shape) and `kinds`. */
function shapesOf(coords, kinds, n, kind) {
  const out = [];
  for (let i = 0; i < kinds.length; i++) {
    if (kinds[i] === kind) out.push(Array.from(coords.subarray(n * i, n * i + n)));
  }
  return out;
}

test("bodies draw their circles, and after a step the broadphase boxes that hold them", () => {
  const map = TileMap.fromAscii("#######\n#.....#\n#.....#\n#######");
  const bodies = new Bodies();
  bodies.addCircle(2, 1.5, 0.3, { owner: 7 });
  bodies.addCircle(4, 2.5, 0.4);
  const lines = new DebugLines();
  bodies.fillDebugLines(lines);
  assert.deepEqual(shapesOf(lines.circles, lines.circleKinds, 3, DebugKind.Body), [
    [2, 1.5, Math.fround(0.3)],
    [4, 2.5, Math.fround(0.4)],
  ]);
  assert.deepEqual(Array.from(lines.circleOwners), [7, 0]);
  assert.equal(lines.boxes.length, 0, "no broadphase before a step");
  bodies.step(map);
  lines.clear();
  bodies.fillDebugLines(lines);
  const boxes = shapesOf(lines.boxes, lines.boxKinds, 4, DebugKind.BroadphaseBox);
  assert.equal(boxes.length, 2);
  const circles = shapesOf(lines.circles, lines.circleKinds, 3, DebugKind.Body);
  circles.forEach(([x, y, r], i) => {
    const [x0, y0, x1, y1] = boxes[i];
    assert.ok(x0 <= x - r && y0 <= y - r && x1 >= x + r && y1 >= y + r, `box ${boxes[i]} holds ${circles[i]}`);
  });
  // Only the kinds asked for.
  lines.clear();
  lines.setKinds([DebugKind.BroadphaseBox]);
  bodies.fillDebugLines(lines);
  assert.equal(lines.circles.length, 0);
  assert.equal(lines.boxes.length, 8);
  lines.free();
  bodies.free();
  map.free();
});

test("a character draws its shape and what its last move touched", () => {
  const map = TileMap.fromAscii("#######\n#.....#\n#.....#\n#######");
  const hero = new Character({ halfWidth: 0.25, halfHeight: 0.4 }, 2, 1.5);
  const lines = new DebugLines();
  hero.fillDebugLines(lines, 3);
  assert.deepEqual(shapesOf(lines.boxes, lines.boxKinds, 4, DebugKind.Character), [[1.75, 1.1, 2.25, 1.9]].map((b) => b.map(Math.fround)));
  assert.deepEqual(Array.from(lines.boxOwners), [3]);
  assert.equal(lines.segments.length, 0, "no move yet, no contact");
  hero.moveBy(map, 0, 2);
  lines.clear();
  hero.fillDebugLines(lines);
  const contacts = shapesOf(lines.segments, lines.segmentKinds, 4, DebugKind.Contact);
  assert.equal(contacts.length, 1, "the floor");
  const [x0, y0, x1, y1] = contacts[0];
  assert.ok(Math.abs(y0 - 3) < 0.01 && y1 < y0 && x0 === x1, `a contact up from the floor: ${contacts[0]}`);
  assert.deepEqual(Array.from(lines.segmentOwners), [0]);
  assert.throws(() => hero.fillDebugLines(lines, -1), /fillDebugLines: owner/);
  lines.free();
  hero.free();
  map.free();
});

test("a hit world draws its volumes, their broadphase boxes and the hits", () => {
  const world = new HitWorld();
  world.beginFrame();
  const body = { x: 0.5, y: 1, halfWidth: 0.5, halfHeight: 1, hit: 0xffffffff };
  world.register({ owner: 1, x: 0, y: 0, size: [1, 2], team: 1 }, [{ x: 1.3, y: 1, radius: 0.3, hit: HitType.Hit }], [body]);
  world.register({ owner: 2, x: 1.5, y: 0, size: [1, 1] }, [], [body]);
  assert.equal(world.detect().length, 1);
  const lines = new DebugLines();
  world.fillDebugLines(lines);
  assert.deepEqual(shapesOf(lines.circles, lines.circleKinds, 3, DebugKind.AttackVolume), [[1.3, 1, 0.3].map(Math.fround)]);
  assert.equal(shapesOf(lines.boxes, lines.boxKinds, 4, DebugKind.VulnerabilityVolume).length, 2);
  assert.equal(shapesOf(lines.boxes, lines.boxKinds, 4, DebugKind.BroadphaseBox).length, 2);
  const hits = shapesOf(lines.points, lines.pointKinds, 2, DebugKind.Hit);
  assert.equal(hits.length, 1);
  assert.deepEqual(Array.from(lines.pointOwners), [2], "the victim's");
  lines.free();
  world.free();
});

const HALL = "########\n#......#\n########";

test("a path found by a NavGrid is drawn leg by leg", () => {
  const map = TileMap.fromAscii("#####\n#...#\n#.#.#\n#...#\n#####");
  const nav = new NavGrid(map);
  const path = nav.findPath(map, 1.5, 1.5, 3.5, 3.5, 0.3);
  const lines = new DebugLines();
  NavGrid.fillPathDebugLines(path, lines, 4);
  const legs = shapesOf(lines.segments, lines.segmentKinds, 4, DebugKind.Path);
  assert.equal(legs.length, path.length / 2 - 1);
  legs.forEach((leg, i) => assert.deepEqual(leg, Array.from(path.subarray(2 * i, 2 * i + 4))));
  assert.ok(Array.from(lines.segmentOwners).every((o) => o === 4));
  assert.throws(() => NavGrid.fillPathDebugLines(new Float32Array([1, 2, 3]), lines), /3 floats/);
  assert.throws(() => NavGrid.fillPathDebugLines(new Float32Array([1, 2, 3, NaN]), lines), /point 1\.y is NaN/);
  lines.free();
  nav.free();
  map.free();
});

test("a flow field draws its arrows towards the goal, only in the view", () => {
  const map = TileMap.fromAscii(HALL);
  const nav = new NavGrid(map);
  const field = new FlowField(nav, map, 6.5, 1.5, 0.3);
  const lines = new DebugLines();
  field.fillDebugLines(nav, lines);
  const arrows = shapesOf(lines.segments, lines.segmentKinds, 4, DebugKind.FlowArrow);
  assert.ok(arrows.length > 5, `${arrows.length} arrows`);
  assert.ok(arrows.every(([x0, , x1]) => x1 >= x0), "every arrow points right, towards the goal");
  lines.clear();
  lines.setView([0, 0, 3, 3]);
  field.fillDebugLines(nav, lines);
  const seen = shapesOf(lines.segments, lines.segmentKinds, 4, DebugKind.FlowArrow);
  assert.ok(seen.length > 0 && seen.length < arrows.length);
  assert.ok(seen.every(([x0]) => x0 <= 3));
  lines.free();
  field.free();
  nav.free();
  map.free();
});

