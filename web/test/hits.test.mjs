// HitWorld from JavaScript: a frame's volumes, hits in a fixed order with when and where,
// kept until the next detect, teams, swings, a JavaScript rule, errors and memory.
import { test } from "node:test";
import assert from "node:assert/strict";

import { HitType, HitWorld } from "../pkg/tileslide.js";
import { growth } from "./support.mjs";

/** The Rust example's frame: a hero's fist and a slime's body. */
function frame(world, heroExtra = {}) {
  world.beginFrame();
  const body = { x: 0.5, y: 1, halfWidth: 0.5, halfHeight: 1, hit: 0xffffffff };
  const hero = world.register(
    { owner: 1, x: 0, y: 0, size: [1, 2], team: 1, ...heroExtra },
    [{ x: 1.3, y: 1, radius: 0.3, hit: HitType.Hit }],
    [body],
  );
  const slime = world.register({ owner: 2, x: 1.5, y: 0, size: [1, 1] }, [], [body]);
  return [hero, slime];
}

test("a fist meets a slime: one hit, as in the Rust example", () => {
  const world = new HitWorld();
  const [hero, slime] = frame(world);
  assert.deepEqual([hero, slime], [0, 1]);
  // Still where the frame starts, they touch at t = 0, at the slime's point nearest the fist.
  const hit = {
    attacker: hero, victim: slime, attackerOwner: 1, victimOwner: 2,
    hitType: HitType.Hit, accepted: true, t: 0, x: 1.5, y: 1,
  };
  assert.deepEqual(world.detect(), [hit]);
  // The events stay readable until the next detect, with the owners to say who they were.
  world.beginFrame();
  assert.deepEqual(world.events(), [hit]);
  assert.deepEqual(world.detect(), []);
  assert.deepEqual(world.events(), []);
  frame(world);
  assert.equal(world.owner(slime), 2);
  assert.equal(world.owner(7), null);
  const [x, y, r] = world.boundingCircle(hero);
  assert.ok(r > 1 && Number.isFinite(x + y));
  world.free();
});

test("teams, invulnerability, facing and swings decide the hits", () => {
  const world = new HitWorld("uniformGrid");
  frame(world, { team: 0 });
  assert.equal(world.detect()[0].accepted, false, "same team");
  frame(world, { flipX: true });
  assert.deepEqual(world.detect(), [], "the fist is mirrored behind the hero");
  // A swing hits each victim once until no object registers it.
  frame(world, { swing: 5 });
  assert.equal(world.detect().length, 1);
  frame(world, { swing: 5 });
  assert.equal(world.detect().length, 0, "same swing");
  world.beginFrame();
  frame(world, { swing: 5 });
  assert.equal(world.detect().length, 1, "the swing ended in the empty frame");
  // A fast fist swept along its move hits what it passed.
  world.beginFrame();
  const bullet = world.register({ owner: 3, x: 10, y: 0.5, size: [0.1, 0.1], motion: [10, 0], team: 1 },
    [{ radius: 0.05, hit: HitType.Hit | HitType.Death }], []);
  const wall = world.register({ owner: 4, x: 4, y: 0, size: [1, 1] }, [], [{ x: 0.5, y: 0.5, halfWidth: 0.1, halfHeight: 0.5, hit: HitType.Death }]);
  // It left x = 0 and meets the wall's face at x = 4.4 when its centre is at 4.35.
  const [shot] = world.detect();
  assert.deepEqual({ ...shot, t: 0, x: 0 }, {
    attacker: bullet, victim: wall, attackerOwner: 3, victimOwner: 4,
    hitType: HitType.Death, accepted: true, t: 0, x: 0, y: 0.5,
  });
  assert.ok(Math.abs(shot.t - 0.435) < 1e-6 && Math.abs(shot.x - 4.4) < 1e-6, JSON.stringify(shot));
  world.free();
});

test("a JavaScript rule decides; an exception it throws becomes the Error", () => {
  const world = new HitWorld();
  const [hero, slime] = frame(world);
  const asked = [];
  const events = world.detect((a, v, type) => {
    asked.push([a, v, type]);
    return false;
  });
  assert.deepEqual(asked, [[hero, slime, HitType.Hit]]);
  assert.equal(events[0].accepted, false);
  frame(world);
  assert.throws(() => world.detect(() => { throw new Error("no hits today"); }), /the rule threw: no hits today/);
  world.free();
});

test("bad objects and volumes are Errors naming them", () => {
  const world = new HitWorld();
  world.beginFrame();
  const ok = { owner: 1, x: 0, y: 0, size: [1, 1] };
  assert.throws(() => new HitWorld("tree"), /broadphase/);
  assert.throws(() => world.register({ ...ok, x: NaN }, [], []), /position\.x is NaN/);
  assert.throws(() => world.register({ ...ok, owner: undefined }, [], []), /owner/);
  assert.throws(() => world.register({ ...ok, size: [1] }, [], []), /size/);
  assert.throws(() => world.register({ ...ok, motion: [Infinity, 0] }, [], []), /motion.*inf/);
  assert.throws(() => world.register({ ...ok, teams: 1 }, [], []), /unknown option `teams`/);
  assert.throws(() => world.register(ok, [{ radius: -1 }], []), /attack\[0\]/);
  assert.throws(() => world.register(ok, [], [{ radius: 1 }, { halfWidth: 1 }]), /vulnerable\[1\]/);
  assert.throws(() => world.register(ok, {}, []), /array/);
  assert.throws(() => world.owner(-1), /id is -1/);
  assert.equal(world.detect().length, 0, "nothing was registered");
  world.free();
});

test("10,000 HitWorlds made, used and freed do not grow the wasm memory", () => {
  const grew = growth(10_000, () => {
    const world = new HitWorld();
    frame(world);
    world.detect();
    world.free();
  });
  assert.equal(grew, 0);
});
