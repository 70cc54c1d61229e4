// Bodies from JavaScript: adding, proposing, stepping against a map, handles, positions as
// a copy and as a view, errors and memory.
import { test } from "node:test";
import assert from "node:assert/strict";

import { Bodies, TileMap } from "../pkg/tileslide.js";
import { growth, wasm } from "./support.mjs";

const ROOM = "########\n#......#\n#......#\n########";

test("a body stopped by a wall slides along it, as in the Rust example", () => {
  const map = TileMap.fromAscii(ROOM);
  const bodies = new Bodies();
  const hero = bodies.addCircle(1.5, 1.5, 0.4);
  bodies.propose(hero, 10, 0.2);
  const report = bodies.step(map);
  assert.deepEqual(report, { moving: 1, contactCount: report.contactCount, cutShort: 0 });
  assert.ok(report.contactCount >= 1);
  const [x, y] = bodies.position(hero);
  assert.ok(x <= 6.6 && x > 6.59, `x ${x}`);
  assert.ok(y > 1.7, `y ${y}`);
  assert.equal(bodies.count, 1);
  bodies.free();
  map.free();
});

test("resolve leaves the move to integrate; two bodies never overlap", () => {
  const map = TileMap.fromAscii(ROOM);
  const bodies = new Bodies({ slide: "stop", passes: 2, broadphase: "sweepAndPrune", gap: 0.001 });
  const a = bodies.addCircle(2, 1.5, 0.4);
  const b = bodies.addCircle(4, 1.5, 0.4);
  bodies.propose(a, 3, 0);
  bodies.resolve(map);
  const [dx] = bodies.resolvedMove(a);
  assert.ok(dx < 1.2 && dx > 1.1, `stopped short of b: ${dx}`);
  assert.deepEqual(bodies.position(a), [2, 1.5], "not moved before integrate");
  bodies.integrate();
  const [ax] = bodies.position(a);
  const [bx] = bodies.position(b);
  assert.ok(bx - ax >= 0.8, `${bx - ax}`);
  bodies.free();
  map.free();
});

test("filters and owners: a ghost passes through walls and heroes", () => {
  const map = TileMap.fromAscii(ROOM);
  const bodies = new Bodies();
  const hero = bodies.addCircle(3, 1.5, 0.4, { owner: 7 });
  const ghost = bodies.addCircle(1.5, 1.5, 0.4, { owner: 2 ** 40, filter: { groups: 2, collidesWith: 2, walls: 0 } });
  assert.equal(bodies.owner(hero), 7);
  assert.equal(bodies.owner(ghost), 2 ** 40);
  bodies.propose(ghost, 8, 0);
  bodies.step(map);
  assert.deepEqual(bodies.position(ghost), [9.5, 1.5]);
  bodies.setFilter(ghost, {});
  bodies.setOwner(ghost, 3);
  assert.equal(bodies.owner(ghost), 3);
  bodies.free();
  map.free();
});

test("a compound body collides with every circle", () => {
  const map = TileMap.fromAscii(ROOM);
  const bodies = new Bodies();
  const cart = bodies.addCompound(3, 1.5, new Float64Array([-0.5, 0, 0.25, 0.5, 0, 0.25]));
  bodies.propose(cart, 10, 0);
  bodies.step(map);
  const [x] = bodies.position(cart);
  assert.ok(x > 6.2 && x <= 6.25, `the front wheel stops at the wall: ${x}`);
  assert.throws(() => bodies.addCompound(3, 1.5, [0, 0]), /2 numbers is not a whole number of circles/);
  assert.throws(() => bodies.addCompound(3, 1.5, []), /at least one circle/);
  assert.throws(() => bodies.addCompound(3, 1.5, [0, NaN, 0.2]), /circle 0 offset\.y is NaN/);
  bodies.free();
  map.free();
});

test("a removed body's handle is an Error, even after its slot is reused", () => {
  const bodies = new Bodies();
  const a = bodies.addCircle(1.5, 1.5, 0.25);
  const b = bodies.addCircle(3.5, 1.5, 0.25);
  bodies.remove(a);
  assert.equal(bodies.contains(a), false);
  const c = bodies.addCircle(5.5, 1.5, 0.25);
  assert.notEqual(c, a);
  for (const call of [
    () => bodies.propose(a, 1, 0),
    () => bodies.position(a),
    () => bodies.remove(a),
    () => bodies.setPosition(a, 2, 2),
    () => bodies.owner(a),
  ]) {
    assert.throws(call, /stale body handle/);
  }
  assert.throws(() => bodies.propose(12345, 1, 0), /stale body handle/);
  assert.throws(() => bodies.propose(-1, 1, 0), /not a body handle/);
  assert.throws(() => bodies.propose(0.5, 1, 0), /not a body handle/);
  assert.deepEqual(bodies.position(c), [5.5, 1.5]);
  assert.deepEqual(Array.from(bodies.handles()), [c, b], "slot order: c took a's slot");
  bodies.free();
});

test("numbers are checked: NaN and infinities are Errors naming the argument", () => {
  const bodies = new Bodies();
  const a = bodies.addCircle(1.5, 1.5, 0.25);
  assert.throws(() => bodies.addCircle(NaN, 1, 0.25), /position\.x is NaN/);
  assert.throws(() => bodies.addCircle(1, 1, Infinity), /radius is inf/);
  assert.throws(() => bodies.addCircle(1, 1, -1), /radius -1/);
  assert.throws(() => bodies.addCircle(1, 1, 0.2, { owner: -3 }), /owner/);
  assert.throws(() => bodies.addCircle(1, 1, 0.2, { ownr: 3 }), /unknown option `ownr`/);
  assert.throws(() => bodies.addCircle(1, 1, 0.2, { filter: { groups: 1.5 } }), /groups/);
  assert.throws(() => bodies.propose(a, 1, NaN), /move\.y is NaN/);
  assert.throws(() => bodies.propose(a, 1e30, 0), /out of range/);
  assert.throws(() => bodies.setPosition(a, Infinity, 0), /position\.x is inf/);
  assert.throws(() => bodies.proposeMany(new Float64Array([a]), new Float32Array([1])), /2 move floats/);
  assert.throws(() => bodies.proposeMany(new Float64Array([a]), new Float32Array([NaN, 0])), /entry 0/);
  assert.deepEqual(bodies.position(a), [1.5, 1.5], "nothing moved");
  bodies.free();
});

test("a bad config is an Error naming the field", () => {
  assert.throws(() => new Bodies({ gap: -1 }), /gap = -1/);
  assert.throws(() => new Bodies({ gap: NaN }), /gap/);
  assert.throws(() => new Bodies({ passes: 1000 }), /passes = 1000/);
  assert.throws(() => new Bodies({ slide: "bounce" }), /slide/);
  assert.throws(() => new Bodies({ broadphase: "tree" }), /broadphase/);
  assert.throws(() => new Bodies({ gaps: 1 }), /unknown option `gaps`/);
  assert.throws(() => new Bodies(5), /must be an object/);
  const bodies = new Bodies();
  assert.throws(() => bodies.setConfig({ passes: -1 }), /passes/);
  bodies.setConfig({ slide: "tangential" });
  bodies.free();
});

test("positions: a copy to keep, or a view of wasm memory refreshed by each call", () => {
  const map = TileMap.fromAscii(ROOM);
  const bodies = new Bodies();
  const a = bodies.addCircle(1.5, 1.5, 0.25);
  const b = bodies.addCircle(4.5, 2.5, 0.25);
  const copy = bodies.positions();
  const view = bodies.positionsView();
  assert.deepEqual(Array.from(copy), [1.5, 1.5, 4.5, 2.5]);
  assert.deepEqual(Array.from(view), Array.from(copy));
  bodies.proposeMany(new Float64Array([a, b]), new Float32Array([1, 0, -1, 0]));
  bodies.step(map);
  assert.deepEqual(Array.from(copy), [1.5, 1.5, 4.5, 2.5], "the copy keeps its values");
  const fresh = bodies.positionsView();
  assert.deepEqual(Array.from(fresh), [2.5, 1.5, 3.5, 2.5]);
  assert.deepEqual(Array.from(bodies.positions()), Array.from(fresh));
  assert.equal(fresh.buffer, wasm.memory.buffer, "a view of the package's memory");
  assert.notEqual(copy.buffer, wasm.memory.buffer);
  bodies.free();
  map.free();
});

test("10,000 Bodies made, stepped and freed do not grow the wasm memory", () => {
  const map = TileMap.fromAscii(ROOM);
  const grew = growth(10_000, () => {
    const bodies = new Bodies();
    const h = bodies.addCircle(1.5, 1.5, 0.25);
    bodies.propose(h, 0.5, 0);
    bodies.step(map);
    bodies.positionsView();
    bodies.free();
  });
  assert.equal(grew, 0);
  map.free();
});
