// What the package's tests share: starting the package synchronously, and the paths of the
// bundled maps.
import { readFileSync } from "node:fs";
import { fileURLToPath } from "node:url";

import { initSync } from "../pkg/tileslide.js";

/** The absolute path of `path`, relative to web/test/. */
export const here = (path) => fileURLToPath(new URL(path, import.meta.url));

/** The package's wasm exports (its `memory` among them), started once. */
export const wasm = initSync({ module: readFileSync(here("../pkg/tileslide_bg.wasm")) });

/** FNV-1a over the floats' bytes, little-endian, as the Rust tests compute it. */
export function fnv1a(floats) {
  const bytes = new Uint8Array(floats.buffer, floats.byteOffset, floats.byteLength);
  let h = 0xcbf29ce484222325n;
  for (const b of bytes) {
    h ^= BigInt(b);
    h = (h * 0x100000001b3n) & 0xffffffffffffffffn;
  }
  return h.toString(16).padStart(16, "0");
}

/** Runs `make` 200 times, then `n` times, and returns the wasm memory's growth over the `n`. */
export function growth(n, make) {
  for (let i = 0; i < 200; i++) make();
  const before = wasm.memory.buffer.byteLength;
  for (let i = 0; i < n; i++) make();
  return wasm.memory.buffer.byteLength - before;
}
