// The standard scenes of BENCHMARKS.md through the package, and through its build for speed
// (tileslide/speed), give the native answers bit for bit. The scenes are written by the native crate tileslide-web-bench (their generators use
// the platform's cos and sin, so they are made in one place and handed over as bytes); the
// checksums are the ones its native tests assert.
import { test } from "node:test";
import assert from "node:assert/strict";
import { execFileSync } from "node:child_process";
import { mkdtempSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";

import * as plain from "../pkg/tileslide.js";
import * as speed from "../pkg/speed/tileslide.js";
import { fnv1a, here } from "./support.mjs";

speed.initSync({ module: readFileSync(here("../pkg/speed/tileslide_bg.wasm")) });

/** crates/tileslide-web-bench/src/lib.rs's RAYS_CHECKSUM. */
const RAYS_CHECKSUM = "2d2187acd2742f7e";
/** The golden hash of crates/tileslide/tests/resolver_golden.rs: 2,000 circles, 40 steps. */
const GOLDEN = "527eda9698ab4a5d";

const dir = mkdtempSync(join(tmpdir(), "tileslide-scenes-"));
// Through `cargo run`, or the program built in TILESLIDE_PROGRAMS (a cargo profile's folder:
// test.sh sets it to the one its Rust tests built the program in).
const programs = process.env.TILESLIDE_PROGRAMS;
const [command, args] = programs
  ? [join(programs, "tileslide-web-bench"), []]
  : ["cargo", ["run", "--quiet", "-p", "tileslide-web-bench", "--"]];
execFileSync(command, [...args, "export", dir], {
  cwd: here("../.."),
  stdio: ["ignore", "ignore", "inherit"],
});
const floats = (name) => {
  const bytes = readFileSync(join(dir, name));
  return new Float32Array(bytes.buffer, bytes.byteOffset, bytes.byteLength / 4);
};
const tsm = readFileSync(join(dir, "dungeon256.tsm"));
const rays = floats("rays.f32");
const crowd = floats("crowd.f32");
rmSync(dir, { recursive: true });

for (const [name, { Bodies, TileMap }] of [["tileslide", plain], ["tileslide/speed", speed]]) {
  const map = TileMap.fromBaked(tsm);

  test(`${name}: the rays scene (dungeon256, 1,000,000 rays) gives the native checksum`, () => {
    assert.equal(rays.length, 4_000_000);
    const out = map.castRays(rays);
    let hits = 0;
    for (let i = 0; i < out.length; i += 5) if (!Number.isNaN(out[i])) hits++;
    assert.equal(hits, 943_906, "BENCHMARKS.md's hits");
    assert.equal(fnv1a(out), RAYS_CHECKSUM);
  });

  test(`${name}: the crowd scene's golden run (2,000 circles, 40 steps) gives the native golden hash`, () => {
    const bodies = new Bodies();
    const n = 2000;
    const handles = new Float64Array(n);
    const moves = new Float32Array(2 * n);
    for (let i = 0; i < n; i++) {
      handles[i] = bodies.addCircle(crowd[4 * i], crowd[4 * i + 1], Math.fround(0.3));
      moves.set(crowd.subarray(4 * i + 2, 4 * i + 4), 2 * i);
    }
    for (let step = 0; step < 40; step++) {
      bodies.proposeMany(handles, moves);
      bodies.step(map);
    }
    assert.equal(fnv1a(bodies.positions()), GOLDEN);
    bodies.free();
  });
}
