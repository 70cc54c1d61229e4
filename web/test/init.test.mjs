// The asynchronous start a browser uses: `await init(...)` with the wasm's bytes (in a
// browser, with no argument: the module finds tileslide_bg.wasm beside itself).
import { test } from "node:test";
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import { fileURLToPath } from "node:url";

import init, { TileMap } from "../pkg/tileslide.js";

test("await init() starts the package as initSync does", async () => {
  const bytes = readFileSync(fileURLToPath(new URL("../pkg/tileslide_bg.wasm", import.meta.url)));
  const wasm = await init({ module_or_path: bytes });
  assert.ok(wasm.memory instanceof WebAssembly.Memory);
  const map = TileMap.fromAscii("###\n#.#\n###");
  assert.equal(map.castRay(1.5, 1.5, 5, 1.5).x, 2);
  map.free();
});
