// The package as a web game uses it: loading maps, editing them, casting rays, errors and
// memory. Run with `npm test` after `npm run build`.
import { test } from "node:test";
import assert from "node:assert/strict";
import { existsSync, readFileSync } from "node:fs";
import { fileURLToPath } from "node:url";
import { gzipSync } from "node:zlib";

import { initSync, TileMap } from "../pkg/tileslide.js";

const here = (path) => fileURLToPath(new URL(path, import.meta.url));
const wasm = initSync({ module: readFileSync(here("../pkg/tileslide_bg.wasm")) });
const cave = readFileSync(here("../../examples/maps/cave.txt"), "utf8");

const ROOM = "#####\n#...#\n#...#\n#####";

test("the package's wasm stays under 400 KB gzipped", () => {
  // The budget a web game pays to download; `npm run build` prints the size too.
  const gzipped = gzipSync(readFileSync(here("../pkg/tileslide_bg.wasm")), { level: 9 }).length;
  assert.ok(gzipped < 400_000, `tileslide_bg.wasm is ${gzipped} bytes gzipped`);
});

test("tileslide/speed is the same package built for speed", async () => {
  // The same exports and types, a larger .wasm, and the same answers (test/scenes.test.mjs
  // checks the standard scenes' checksums through both).
  const speed = await import("../pkg/speed/tileslide.js");
  const plain = await import("../pkg/tileslide.js");
  assert.deepEqual(Object.keys(speed).sort(), Object.keys(plain).sort());
  assert.equal(
    readFileSync(here("../pkg/speed/tileslide.d.ts"), "utf8"),
    readFileSync(here("../pkg/tileslide.d.ts"), "utf8"),
  );
  const bytes = (dir) => gzipSync(readFileSync(here(`../pkg/${dir}tileslide_bg.wasm`)), { level: 9 }).length;
  assert.ok(bytes("speed/") > bytes(""), "the speed build is the larger");
  const manifest = JSON.parse(readFileSync(here("../package.json"), "utf8"));
  assert.equal(manifest.exports["./speed"].default, "./pkg/speed/tileslide.js");
  for (const file of manifest.files) assert.ok(existsSync(here(`../${file}`)), `${file} is built`);
});

test("a map drawn in ASCII answers a ray with the CLI's fields", () => {
  const map = TileMap.fromAscii(ROOM);
  assert.equal(map.width, 5);
  assert.equal(map.height, 4);
  const hit = map.castRay(1.5, 1.5, 10, 1.5);
  assert.deepEqual(hit, { t: Math.fround(2.5 / 8.5), x: 4, y: 1.5, nx: -1, ny: 0, cell: [4, 1], tile: hit.tile });
  assert.equal(typeof hit.tile, "number");
  assert.equal(map.castRay(1.5, 1.5, 2.5, 2.5), null);
  map.free();
});

test("the cell size scales the map", () => {
  const map = TileMap.fromAscii(ROOM, 16);
  const hit = map.castRay(24, 24, 200, 24);
  assert.equal(hit.x, 64);
  map.free();
});

test("a ray from inside a wall sees its back face only with bothSides", () => {
  const map = TileMap.fromAscii(ROOM);
  assert.equal(map.castRay(4.5, 1.5, 2.5, 1.5), null);
  const back = map.castRay(4.5, 1.5, 2.5, 1.5, { bothSides: true });
  assert.equal(back.x, 4);
  // `against`: only faces opposing the direction count (floors, on a y-down map).
  const floors = map.castRay(2.5, 1.5, 2.5, 10, { against: [0, 1] });
  assert.equal(floors.y, 3);
  assert.equal(map.castRay(1.5, 1.5, 10, 1.5, { against: [0, 1] }), null);
  map.free();
});

test("digging a wall opens the way", () => {
  const map = TileMap.fromAscii(ROOM);
  map.setTile(4, 1, null);
  assert.equal(map.castRay(1.5, 1.5, 4.9, 1.5), null);
  map.setTile(4, 1, 1);
  assert.equal(map.castRay(1.5, 1.5, 4.9, 1.5).x, 4);
  map.free();
});

/** The rays of crates/tileslide-wasm/src/rays.rs's checksum test, built the same way. */
function checksumRays() {
  const out = new Float32Array(2000 * 4);
  for (let i = 0; i < 2000; i++) {
    const x0 = 1.5 + (i % 37) * 0.25;
    const y0 = 1.5 + (i % 11) * 0.5;
    const dx = ((i * 7919) % 41) * 0.5 - 10;
    const dy = (Number((BigInt(i) * 104729n) % 37n)) * 0.5 - 9;
    out.set([x0, y0, x0 + dx, y0 + dy], i * 4);
  }
  return out;
}

/** FNV-1a over the floats' bytes, little-endian, as the Rust test computes it. */
function fnv1a(floats) {
  const bytes = new Uint8Array(floats.buffer, floats.byteOffset, floats.byteLength);
  let h = 0xcbf29ce484222325n;
  for (const b of bytes) {
    h ^= BigInt(b);
    h = (h * 0x100000001b3n) & 0xffffffffffffffffn;
  }
  return h;
}

test("castRays gives the native answers bit for bit", () => {
  const map = TileMap.fromAscii(cave);
  const rays = checksumRays();
  const out = map.castRays(rays);
  assert.ok(out instanceof Float32Array);
  assert.equal(out.length, 2000 * 5);
  // The checksum the native test in crates/tileslide-wasm/src/rays.rs asserts.
  assert.equal(fnv1a(out).toString(16), "ab275c4c94610d89");
  // Each answer is castRay's; a miss is five NaNs.
  for (let i = 0; i < 2000; i += 97) {
    const hit = map.castRay(rays[4 * i], rays[4 * i + 1], rays[4 * i + 2], rays[4 * i + 3]);
    const got = Array.from(out.subarray(5 * i, 5 * i + 5));
    if (hit === null) {
      assert.ok(got.every(Number.isNaN), `ray ${i}: ${got}`);
    } else {
      assert.deepEqual(got, [hit.t, hit.x, hit.y, hit.nx, hit.ny].map(Math.fround));
    }
  }
  map.free();
});

test("bad input is an Error that names what and where", () => {
  assert.throws(() => TileMap.fromAscii("#####\n#.?.#\n#####"), (e) => {
    assert.ok(e instanceof Error);
    assert.match(e.message, /map\.txt:2:3/);
    assert.match(e.message, /'\?'/);
    return true;
  });
  const map = TileMap.fromAscii(ROOM);
  assert.throws(() => map.castRay(NaN, 1, 2, 2), /x0 is NaN/);
  assert.throws(() => map.castRay(1, 1, 2, Infinity), /y1 is inf/);
  assert.throws(() => map.castRays(new Float32Array([1, 1, 2])), /3 floats/);
  assert.throws(() => map.castRays(new Float32Array([1, 1, 2, 2, 1, NaN, 2, 2])), /ray 1: y0 is NaN/);
  assert.throws(() => map.castRay(1, 1, 2, 2, { bothSides: true, against: [0, 1] }), /not both/);
  assert.throws(() => map.castRay(1, 1, 2, 2, { against: [0] }), /against/);
  assert.throws(() => map.castRay(1, 1, 2, 2, { bothSides: "yes" }), /bothSides/);
  assert.throws(() => map.setTile(-1, 0, 1), /col is -1/);
  assert.throws(() => map.setTile(1.5, 0, 1), /col is 1\.5/);
  assert.throws(() => map.setTile(99, 0, 1), /99/);
  assert.throws(() => TileMap.fromBaked(new Uint8Array([1, 2, 3, 4])), Error);
  assert.throws(() => TileMap.fromTiled("{", "broken.tmj"), /broken\.tmj/);
  map.free();
});

test("a baked map reads back bit for bit", () => {
  const map = TileMap.fromAscii(cave);
  const again = TileMap.fromBaked(map.toBaked());
  const rays = checksumRays();
  assert.deepEqual(again.castRays(rays), map.castRays(rays));
  map.free();
  again.free();
});

test("a Tiled map with an embedded tile set loads from its text", () => {
  const tmj = JSON.stringify({
    orientation: "orthogonal", width: 2, height: 1, tilewidth: 8, tileheight: 8,
    tilesets: [{ firstgid: 1, name: "t", tilewidth: 8, tileheight: 8, tilecount: 1,
      tiles: [{ id: 0, objectgroup: { objects: [{ id: 1, x: 0, y: 0, width: 8, height: 8 }] } }] }],
    layers: [{ type: "tilelayer", name: "walls", width: 2, height: 1, data: [0, 1] }],
  });
  const map = TileMap.fromTiled(tmj, "level.tmj");
  assert.equal(map.width, 2);
  assert.equal(map.castRay(2, 4, 20, 4).x, 8);
  map.free();
});

test("a Tiled map's external tile set is given by name, as text or bytes", () => {
  const example = (name) => here("../../examples/maps/" + name);
  const tmj = readFileSync(example("cave.tmj"), "utf8");
  const tmx = readFileSync(example("cave.tmx"), "utf8");
  const fromText = TileMap.fromTiled(tmj, "cave.tmj", { "tiles.tsj": readFileSync(example("tiles.tsj"), "utf8") });
  const fromBytes = TileMap.fromTiled(tmx, "cave.tmx", new Map([["tiles.tsx", new Uint8Array(readFileSync(example("tiles.tsx")))]]));
  assert.equal(fromText.width, 30);
  const rays = checksumRays().map((v) => v * 16);
  assert.deepEqual(fromText.castRays(rays), fromBytes.castRays(rays));
  assert.ok(Array.from(fromText.castRays(rays)).some((v) => !Number.isNaN(v)));
  // Without it, the error names the file the map asks for.
  assert.throws(() => TileMap.fromTiled(tmj, "cave.tmj", { "walls.tsj": "{}" }), /tiles\.tsj/);
  assert.throws(() => TileMap.fromTiled(tmj, "cave.tmj", { "tiles.tsj": 5 }), /files\["tiles\.tsj"\]/);
  assert.throws(() => TileMap.fromTiled(tmj, "cave.tmj", 7), /files/);
  fromText.free();
  fromBytes.free();
});

const replica = here("../../../shared/data/replica-island/");
test("a Replica Island level loads from its bytes", { skip: !existsSync(replica) && !process.env.CI && "no ../shared/data/replica-island" }, () => {
  const map = TileMap.fromReplicaIsland(
    readFileSync(replica + "level_0_1_sewer.bin"),
    readFileSync(replica + "collision.bin"),
  );
  assert.ok(map.width > 10 && map.height > 5);
  const rays = new Float32Array(400);
  for (let i = 0; i < 100; i++) rays.set([32 * (i % 10) + 40, 32 * (i % 7) + 40, 32 * (i % 10) + 40, 2000], 4 * i);
  assert.ok(Array.from(map.castRays(rays)).some((v) => !Number.isNaN(v)));
  map.free();
});

test("10,000 maps made and freed do not grow the wasm memory", () => {
  const churn = (n) => {
    for (let i = 0; i < n; i++) {
      const map = TileMap.fromAscii(cave);
      map.castRay(1.5, 1.5, 30, 10);
      map.free();
    }
  };
  churn(200);
  const before = wasm.memory.buffer.byteLength;
  churn(10_000);
  assert.equal(wasm.memory.buffer.byteLength, before);
});
