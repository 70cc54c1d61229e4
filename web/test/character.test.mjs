// Character from JavaScript: falling, walking into walls, one-way platforms, moving
// platforms, velocities, errors and memory.
import { test } from "node:test";
import assert from "node:assert/strict";

import { Character, TileMap } from "../pkg/tileslide.js";
import { growth } from "./support.mjs";

const ROOM = "#######\n#.....#\n#.....#\n#######";
const close = (a, b, what) => assert.ok(Math.abs(a - b) < 1e-4, `${what}: ${a} vs ${b}`);

test("a box falls onto the floor and walks into the wall, as in the Rust example", () => {
  const map = TileMap.fromAscii(ROOM);
  const hero = new Character({ halfWidth: 0.25, halfHeight: 0.4 }, 2, 1.5);
  const fall = hero.moveBy(map, 0, 2);
  assert.equal(fall.grounded, true);
  close(fall.y, 3 - 0.4 - 0.001, "on the floor");
  assert.equal(fall.ground.cell[1], 3, "a floor cell");
  assert.ok([1, 2].includes(fall.ground.cell[0]), `under the box: ${fall.ground.cell}`);
  assert.equal(typeof fall.ground.tile, "number");
  assert.deepEqual([fall.ground.nx, fall.ground.ny], [0, -1]);
  assert.equal(fall.ground.flags, 1);
  assert.equal(fall.ground.owner, null);
  assert.equal(fall.ceiling, null);
  const walk = hero.moveBy(map, 10, 0.5);
  assert.ok(walk.right !== null && walk.grounded);
  assert.deepEqual(walk.right.cell, [6, 2]);
  close(hero.x, 6 - 0.25 - 0.001, "at the wall");
  assert.equal(hero.x, walk.x);
  assert.deepEqual(hero.up, [0, -1]);
  assert.notEqual(hero.ground, null);
  hero.free();
  map.free();
});

test("one-way platforms: jump up through, land on, drop through on request", () => {
  const map = TileMap.fromAscii("#######\n#.....#\n#.....#\n#.===.#\n#.....#\n#.....#\n#######");
  const ball = new Character({ radius: 0.3 }, 3.5, 5.5);
  ball.moveBy(map, 0, 1);
  assert.equal(ball.moveBy(map, 0, -3).ceiling, null, "jumps up through the platform");
  assert.ok(ball.y < 3);
  const land = ball.moveBy(map, 0, 2);
  assert.equal(land.grounded, true);
  close(land.y, 3 - 0.3 - 0.001, "lands on the platform");
  assert.equal(land.ground.flags, 2);
  const drop = ball.moveBy(map, 0, 1, { dropThrough: true });
  assert.ok(drop.y > 3, `dropped through: ${drop.y}`);
  ball.free();
  map.free();
});

test("moveAndSlide keeps the velocity the surfaces leave; a moving platform carries the character", () => {
  const map = TileMap.fromAscii("########\n#......#\n#......#\n########");
  const hero = new Character({ halfWidth: 0.25, halfHeight: 0.4 }, 2, 1.5, [0, -1], { maxSlopeDegrees: 45, skin: 0.001 });
  let vx = 6, vy = 0;
  for (let i = 0; i < 60; i++) {
    vy += 30 / 60;
    const r = hero.moveAndSlide(map, vx, vy, 1 / 60);
    vx = r.vx;
    vy = r.vy;
  }
  assert.notEqual(hero.ground, null);
  assert.deepEqual([vx, vy], [0, 0], "landed and ran into the right wall");
  // clipVelocity uses the last move's contacts: push into the wall once more.
  const push = hero.moveBy(map, 0.5, 0.1);
  assert.ok(push.right !== null && push.grounded);
  assert.deepEqual(hero.clipVelocity(5, 3), [0, 0]);
  assert.deepEqual(hero.clipVelocity(-5, -3), [-5, -3], "away from both is free");
  // A platform under a second character, moving right: it rides along.
  const rider = new Character({ halfWidth: 0.25, halfHeight: 0.25 }, 3, 1.7);
  map.addTemporary(2, 2, 4, 2, 0, -1, { flags: 2, owner: 9, velocity: [0.5, 0] });
  assert.equal(map.temporaryCount, 1);
  const on = rider.moveBy(map, 0, 0.5);
  assert.equal(on.ground.owner, 9);
  assert.deepEqual(on.ground.velocity, [0.5, 0]);
  assert.equal(on.ground.cell, null);
  map.clearTemporariesOf(9);
  map.addTemporary(2.5, 2, 4.5, 2, 0, -1, { flags: 2, owner: 9, velocity: [0.5, 0] });
  const carried = rider.moveBy(map, 0, 0.1);
  close(carried.x, 3.5, "carried by the platform's move");
  map.clearTemporaries();
  assert.equal(map.temporaryCount, 0);
  hero.free();
  rider.free();
  map.free();
});

test("bad shapes, configs and numbers are Errors naming them", () => {
  const map = TileMap.fromAscii(ROOM);
  assert.throws(() => new Character({ radius: -1 }, 2, 2), /radius/);
  assert.throws(() => new Character({ radius: NaN }, 2, 2), /radius is NaN/);
  assert.throws(() => new Character({ halfWidth: 1 }, 2, 2), /shape must be/);
  assert.throws(() => new Character({ radius: 0.3 }, NaN, 2), /position\.x is NaN/);
  assert.throws(() => new Character({ radius: 0.3 }, 2, 2, [0, 0]), /up/);
  assert.throws(() => new Character({ radius: 0.3 }, 2, 2, [0, -1], { skin: -1 }), /skin/);
  assert.throws(() => new Character({ radius: 0.3 }, 2, 2, [0, -1], { maxSlope: 5 }), /unknown option `maxSlope`/);
  assert.throws(() => new Character({ radius: 0.3 }, 2, 2, [0, -1], { maxSlopeDegrees: 90 }), /max_slope_degrees/);
  const c = new Character({ radius: 0.3 }, 2, 2);
  assert.throws(() => c.moveBy(map, Infinity, 0), /displacement\.x is inf/);
  assert.throws(() => c.moveBy(map, 0, 0, { dropThrough: 1 }), /dropThrough/);
  assert.throws(() => c.moveAndSlide(map, 1, 1, -1), /dt/);
  assert.throws(() => c.moveAndSlide(map, 1, 1, NaN), /dt is NaN/);
  assert.throws(() => c.teleport(1e39, 0), /too large/);
  assert.throws(() => map.addTemporary(1, 1, 1, 1, 0, 1), /zero length/);
  assert.throws(() => map.addTemporary(1, 1, 2, 1, 0, NaN), /normal\.y is NaN/);
  assert.throws(() => map.addTemporary(1, 1, 2, 1, 0, 1, { velocity: [1] }), /velocity/);
  c.teleport(3, 2);
  assert.deepEqual([c.x, c.y], [3, 2]);
  c.free();
  map.free();
});

test("a map holds at most 65,536 temporary segments", () => {
  const map = TileMap.fromAscii(ROOM);
  for (let i = 0; i < 65_536; i++) {
    map.addTemporary(1, 1 + (i % 3), 2, 1 + (i % 3), 0, -1, { owner: i % 7 });
  }
  assert.throws(() => map.addTemporary(1, 1, 2, 1, 0, -1, { owner: 9 }), /owner 9 refused.*65536.*MAX_TEMPORARIES/);
  assert.equal(map.temporaryCount, 65_536);
  map.clearTemporariesOf(3);
  map.addTemporary(1, 1, 2, 1, 0, -1, { owner: 9 });
  map.free();
});

test("10,000 Characters made, moved and freed do not grow the wasm memory", () => {
  const map = TileMap.fromAscii(ROOM);
  const grew = growth(10_000, () => {
    const c = new Character({ radius: 0.3 }, 2, 1.5);
    c.moveBy(map, 1, 1);
    c.free();
  });
  assert.equal(grew, 0);
  map.free();
});
