// Debug lines as a canvas draws them: typed arrays of segments, circles, points and boxes
// with their kinds, from a small ASCII map. Run with `npm test` after `npm run build`.
import { test } from "node:test";
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import { fileURLToPath } from "node:url";

import { initSync, DebugKind, DebugLines, TileMap } from "../pkg/tileslide.js";

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
