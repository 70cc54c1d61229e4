// The playground's build of the package (web/playground-pkg/: the `explain` feature): a
// body's last step and a cell's segments in words, the words `tileslide explain` prints;
// and the npm package (web/pkg/) without them.
import { readFileSync } from "node:fs";
import { test } from "node:test";
import assert from "node:assert/strict";

import { Bodies, TileMap, initSync } from "../playground-pkg/tileslide.js";
import { Bodies as PackageBodies, TileMap as PackageMap } from "../pkg/tileslide.js";
import { here } from "./support.mjs";

initSync({ module: readFileSync(here("../playground-pkg/tileslide_bg.wasm")) });

const ROOM = "#####\n#...#\n#####";

test("a body stopped by a wall: its story names the wall's cell and tile", () => {
  const map = TileMap.fromAscii(ROOM);
  const bodies = new Bodies();
  const ball = bodies.addCircle(1.5, 1.5, 0.4);
  bodies.propose(ball, -1, 0);
  bodies.step(map);
  assert.equal(bodies.storyOf(ball), null, "steps are not traced until asked");
  bodies.traceNextSteps(true);
  bodies.propose(ball, -1, 0);
  bodies.step(map);
  const story = bodies.storyOf(ball);
  assert.ok(story.startsWith(`body ${ball}, last step: at (1.401, 1.500), proposed (-1.000, 0.000)\n`), story);
  assert.match(story, /\[1\] cell \(0, 1\) tile 1 segment \d \(face\): t 0\.000, at \(1\.000, 1\.500\), normal \(1\.000, 0\.000\)  <- first\n/);
  assert.match(story, /stopped: met straight on, no side to slide to/);
  assert.match(story, /resolved \(0\.000, 0\.000\): ends at \(1\.401, 1\.500\)\n$/);
  bodies.traceNextSteps(false);
  assert.equal(bodies.storyOf(ball), null, "stopping drops the trace");
  bodies.remove(ball);
  assert.throws(() => bodies.storyOf(ball), /stale|no body/);
  bodies.free();
  map.free();
});

test("a body met by another names it by its handle", () => {
  const map = TileMap.fromAscii("#######\n#.....#\n#######");
  const bodies = new Bodies();
  const still = bodies.addCircle(3.5, 1.5, 0.4);
  const mover = bodies.addCircle(1.5, 1.5, 0.4);
  bodies.traceNextSteps(true);
  bodies.propose(mover, 2, 0);
  bodies.step(map);
  assert.match(bodies.storyOf(mover), new RegExp(`body ${still} circle 0`));
  assert.match(bodies.storyOf(still), /still: no move proposed/);
  bodies.free();
  map.free();
});

test("a seam segment is hidden by its neighbour, and says which", () => {
  const map = TileMap.fromAscii(ROOM);
  const e = map.explainCell(1, 0);
  assert.deepEqual(e.cell, [1, 0]);
  assert.equal(e.tile, 1);
  assert.ok(e.words.startsWith("cell (1, 0): tile 1, 4 segments\n"), e.words);
  const seam = e.segments.find((s) => s.from[0] === 2 && s.to[0] === 2);
  assert.equal(seam.hidden, true);
  assert.match(seam.state, /^hidden by cell \(2, 0\) tile 1 segment \d$/);
  assert.match(seam.words, /wholly hidden/);
  assert.deepEqual(seam.ends, []);
  // The side facing the open row below: the room's ceiling.
  const face = e.segments.find((s) => s.from[1] === 1 && s.to[1] === 1);
  assert.equal(face.hidden, false);
  assert.equal(face.state, "active");
  assert.equal(face.ends.length, 2);
  assert.ok(face.ends.every((end) => end.cap === false), "the ceiling continues flat or concave both ways");
  assert.throws(() => map.explainCell(9, 0), /explainCell/);
  assert.throws(() => map.explainCell(0.5, 0), /explainCell: col/);
  map.free();
});

test("the npm package leaves the explanations out", () => {
  assert.equal(PackageBodies.prototype.storyOf, undefined);
  assert.equal(PackageBodies.prototype.traceNextSteps, undefined);
  assert.equal(PackageMap.prototype.explainCell, undefined);
});
