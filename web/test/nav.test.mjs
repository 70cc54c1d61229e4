// NavGrid and FlowField from JavaScript: paths, map edits and sync, flow fields, errors and
// memory.
import { test } from "node:test";
import assert from "node:assert/strict";

import { FlowField, NavGrid, TileMap } from "../pkg/tileslide.js";
import { growth } from "./support.mjs";

// A wall with a gap at the bottom: the way from left to right goes round it.
const MAZE = [
  "##########",
  "#...#....#",
  "#...#....#",
  "#...#....#",
  "#........#",
  "##########",
].join("\n");

test("findPath goes round the wall; a walled-in goal has no path", () => {
  const map = TileMap.fromAscii(MAZE);
  const nav = new NavGrid(map, { maxRadius: 0.5 });
  assert.equal(nav.maxRadius, 0.5);
  const path = nav.findPath(map, 2, 2, 7, 2, 0.3);
  assert.ok(path instanceof Float32Array);
  assert.deepEqual(Array.from(path.slice(0, 2)), [2, 2]);
  assert.deepEqual(Array.from(path.slice(-2)), [7, 2]);
  const ys = path.filter((_, i) => i % 2 === 1);
  assert.ok(Math.max(...ys) > 4, "it dips under the wall");
  assert.equal(nav.fits(map, 2, 2, 0.3), true);
  assert.equal(nav.fits(map, 4.5, 2, 0.3), false);
  // Close the gap: the grid is behind the map until synced.
  map.setTile(4, 4, 1);
  assert.throws(() => nav.findPath(map, 2, 2, 7, 2, 0.3), /findPath: .*behind the map/);
  const change = nav.sync(map);
  assert.ok(change.changedMoves > 0 && change.rebuilt === false);
  assert.equal(change.region.length, 4);
  assert.equal(nav.findPath(map, 2, 2, 7, 2, 0.3), null);
  assert.deepEqual(nav.sync(map), { changedMoves: 0, rebuilt: false, region: null });
  nav.free();
  map.free();
});

test("a flow field points the way, and catches up after an edit", () => {
  const map = TileMap.fromAscii(MAZE);
  const nav = new NavGrid(map);
  const field = new FlowField(nav, map, 7, 2, 0.3);
  assert.deepEqual(field.goal, [7, 2]);
  assert.ok(Math.abs(field.radius - 0.3) < 1e-7);
  const [dx, dy] = field.direction(nav, map, 2, 2);
  assert.ok(dy > 0, "down towards the gap first");
  assert.ok(Math.abs(Math.hypot(dx, dy) - 1) < 1e-5);
  const far = field.distance(nav, map, 2, 2);
  assert.ok(far > 5 + 2, `round the wall: ${far}`);
  const many = field.directions(nav, map, new Float32Array([2, 2, 4.5, 2]));
  assert.deepEqual(Array.from(many.slice(0, 2)), [dx, dy].map(Math.fround));
  assert.ok(Number.isNaN(many[2]) && Number.isNaN(many[3]), "inside the wall: no direction");
  assert.equal(field.direction(nav, map, 7, 2), null, "on the goal");
  map.setTile(4, 4, 1);
  nav.sync(map);
  assert.equal(field.sync(nav, map), true);
  assert.equal(field.direction(nav, map, 2, 2), null);
  assert.equal(field.distance(nav, map, 2, 2), null);
  field.free();
  nav.free();
  map.free();
});

test("bad input is an Error naming it", () => {
  const map = TileMap.fromAscii(MAZE);
  assert.throws(() => new NavGrid(map, { maxRadius: -1 }), /max_radius -1/);
  assert.throws(() => new NavGrid(map, { maxRadius: NaN }), /maxRadius/);
  assert.throws(() => new NavGrid(map, { radius: 1 }), /unknown option `radius`/);
  const nav = new NavGrid(map);
  assert.throws(() => nav.findPath(map, NaN, 2, 7, 2, 0.3), /from\.x is NaN/);
  assert.throws(() => nav.findPath(map, 2, 2, 7, 2, 5), /radius 5/);
  assert.throws(() => nav.findPath(map, 2, 2, 7, Infinity, 0.3), /to\.y is inf/);
  assert.throws(() => new FlowField(nav, map, 7, 2, 0), /radius 0/);
  const other = TileMap.fromAscii(MAZE);
  assert.throws(() => nav.findPath(other, 2, 2, 7, 2, 0.3), /findPath/);
  const field = new FlowField(nav, map, 7, 2, 0.3);
  assert.throws(() => field.directions(nav, map, new Float32Array([1])), /1 floats/);
  assert.throws(() => field.directions(nav, map, new Float32Array([1, NaN])), /point 0\.y is NaN/);
  field.free();
  other.free();
  nav.free();
  map.free();
});

test("lattice directions steer along the field's moves, in one call or many", () => {
  const map = TileMap.fromAscii(MAZE);
  const nav = new NavGrid(map);
  const field = new FlowField(nav, map, 7, 2, 0.3);
  // Down the left room towards the gap under the wall, as the full direction goes.
  const [dx, dy] = field.latticeDirection(nav, map, 2, 2);
  assert.ok(dy > 0 && Math.abs(Math.hypot(dx, dy) - 1) < 1e-6, `${dx}, ${dy}`);
  assert.deepEqual(field.latticeDirection(nav, map, 7, 2), null, "on the goal");
  const many = field.latticeDirections(nav, map, new Float32Array([2, 2, 4.5, 2, 7, 2]));
  assert.deepEqual(Array.from(many.slice(0, 2)), [dx, dy].map(Math.fround));
  assert.ok(many.slice(2).every(Number.isNaN), "inside the wall and on the goal: none");
  // Under the wall's end, the way goes right.
  assert.ok(field.latticeDirection(nav, map, 3, 4.5)[0] > 0);
  assert.throws(() => field.latticeDirections(nav, map, new Float32Array([1])), /latticeDirections: 1 floats/);
  assert.throws(() => field.latticeDirections(nav, map, new Float32Array([1, 1, 1, NaN])), /point 1\.y is NaN/);
  assert.throws(() => field.latticeDirection(nav, map, NaN, 1), /latticeDirection: point\.x is NaN/);
  field.free();
  nav.free();
  map.free();
});

// 2,000 rounds, each building a clearance table of 273 lattice nodes (a few milliseconds in
// the package's size-optimised build): a grid or a field left behind would grow the memory by
// megabytes, a path by a few hundred kilobytes.
test("2,000 NavGrids and FlowFields made and freed do not grow the wasm memory", () => {
  const map = TileMap.fromAscii(MAZE);
  const grew = growth(2_000, () => {
    const nav = new NavGrid(map);
    const field = new FlowField(nav, map, 7, 2, 0.3);
    nav.findPath(map, 2, 2, 7, 2, 0.3);
    field.free();
    nav.free();
  });
  assert.equal(grew, 0);
  map.free();
});
