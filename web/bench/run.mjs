// `npm run bench`: the standard rays scene (dungeon256, 1,000,000 rays) and crowd scene
// (10,000 circles, 100 steps a run) in wasm through the package, and natively in the same
// run through the same Rust code (the tileslide-web-bench crate, release build), with the
// medians, the wasm/native ratios, the answers' checksums (they must agree) and the CPU.
// The runs are interleaved (a native run, then a wasm run of each scene, N times), so that
// a machine whose load changes during the benchmark weighs on both sides alike. Both builds
// of the package are timed: tileslide (for size) and tileslide/speed (for speed).
//
// Options: --runs N (default 5), --no-build (use web/pkg as it is).
import { execFileSync } from "node:child_process";
import { mkdtempSync, readFileSync, rmSync, statSync } from "node:fs";
import { cpus, tmpdir } from "node:os";
import { join } from "node:path";
import { fileURLToPath } from "node:url";
import { gzipSync } from "node:zlib";

const here = (path) => fileURLToPath(new URL(path, import.meta.url));
const root = here("../..");
const args = process.argv.slice(2);
const runsAt = args.indexOf("--runs");
const runs = runsAt >= 0 ? Number(args[runsAt + 1]) : 5;
if (!Number.isInteger(runs) || runs < 1) throw new Error("--runs takes a positive whole number");

if (!args.includes("--no-build")) {
  execFileSync("sh", [here("../build.sh")], { stdio: "inherit" });
}
// The tests' support module starts the package and hashes answers as the native side does.
const { fnv1a } = await import("../test/support.mjs");
const plain = await import("../pkg/tileslide.js");
const speed = await import("../pkg/speed/tileslide.js");
speed.initSync({ module: readFileSync(here("../pkg/speed/tileslide_bg.wasm")) });
const builds = [
  { name: "tileslide", module: plain, dir: "../pkg/" },
  { name: "tileslide/speed", module: speed, dir: "../pkg/speed/" },
];

// The native side: builds, writes the scenes, times them, and prints one line of JSON.
execFileSync("cargo", ["build", "--quiet", "--release", "-p", "tileslide-web-bench"], { cwd: root, stdio: "inherit" });
const metadata = JSON.parse(execFileSync("cargo", ["metadata", "--format-version", "1", "--no-deps"], { cwd: root }));
const dir = mkdtempSync(join(tmpdir(), "tileslide-bench-"));
const bench = join(metadata.target_directory, "release", "tileslide-web-bench");
const nativeRun = () => JSON.parse(execFileSync(bench, ["time", dir, "1"], { cwd: root }));
// The first run writes the scenes the wasm side reads.
let native = nativeRun();

const floats = (name) => {
  const bytes = readFileSync(join(dir, name));
  return new Float32Array(bytes.buffer, bytes.byteOffset, bytes.byteLength / 4);
};
const tsm = readFileSync(join(dir, "dungeon256.tsm"));
for (const build of builds) build.map = build.module.TileMap.fromBaked(tsm);
const rays = floats("rays.f32");
const crowd = floats("crowd.f32");

const median = (times) => {
  const sorted = [...times].sort((a, b) => a - b);
  return sorted[Math.floor(sorted.length / 2)];
};
const seconds = (work) => {
  const start = process.hrtime.bigint();
  work();
  return Number(process.hrtime.bigint() - start) / 1e9;
};

const steps = native.crowdSteps;
const crowdOnce = (build) => {
  const bodies = new build.module.Bodies();
  const n = crowd.length / 4;
  const handles = new Float64Array(n);
  const moves = new Float32Array(2 * n);
  for (let i = 0; i < n; i++) {
    handles[i] = bodies.addCircle(crowd[4 * i], crowd[4 * i + 1], 0.3);
    moves.set(crowd.subarray(4 * i + 2, 4 * i + 4), 2 * i);
  }
  for (let s = 0; s < steps; s++) {
    bodies.proposeMany(handles, moves);
    bodies.step(build.map);
  }
  build.crowdHash = fnv1a(bodies.positions());
  bodies.free();
};
for (const build of builds) Object.assign(build, { rays: [], crowd: [] });
const times = { nativeRays: [], nativeRaysPortable: [], nativeCrowd: [] };
for (let i = 0; i < runs; i++) {
  if (i > 0) native = nativeRun();
  times.nativeRays.push(native.raysSeconds);
  times.nativeRaysPortable.push(native.raysPortableSeconds);
  times.nativeCrowd.push(native.crowdStepSeconds);
  for (const build of builds) {
    build.rays.push(seconds(() => (build.answers = build.map.castRays(rays))));
    build.crowd.push(seconds(() => crowdOnce(build)) / steps);
  }
}
rmSync(dir, { recursive: true });
native.raysSeconds = median(times.nativeRays);
native.raysPortableSeconds = median(times.nativeRaysPortable);
native.crowdStepSeconds = median(times.nativeCrowd);

const row = (name, wasm, nat, unit, scale, same) =>
  `${name.padEnd(26)} ${(wasm * scale).toFixed(2).padStart(9)} ${unit}  ${(nat * scale).toFixed(2).padStart(9)} ${unit}  ${(wasm / nat).toFixed(2).padStart(5)}×  ${same ? "same answers" : "ANSWERS DIFFER"}`;
console.log(`CPU: ${cpus()[0]?.model ?? "unknown"}; Node ${process.version}; median of ${runs} interleaved runs (crowd: ${steps} steps a run)`);
for (const build of builds) {
  const file = here(`${build.dir}tileslide_bg.wasm`);
  const raysSeconds = median(build.rays);
  const crowdStepSeconds = median(build.crowd);
  const raysChecksum = fnv1a(build.answers);
  console.log(`\n${build.name}: tileslide_bg.wasm ${statSync(file).size} bytes, ${gzipSync(readFileSync(file), { level: 9 }).length} gzipped`);
  console.log(`${"scene".padEnd(26)} ${"wasm".padStart(12)}  ${"native".padStart(12)}  ratio`);
  console.log(row("rays dungeon256, 1M rays", raysSeconds, native.raysSeconds, "ms", 1e3, raysChecksum === native.raysChecksum));
  // On x86-64 the native batch walk runs 256-bit AVX2 when it can; its portable walk is the
  // same eight lanes as two 128-bit halves, as in wasm's SIMD128: the same work at the
  // package's width (the native side checks that its answers are cast_rays').
  console.log(row("rays, native 128-bit walk", raysSeconds, native.raysPortableSeconds, "ms", 1e3, raysChecksum === native.raysChecksum));
  console.log(row("crowd 10,000, per step", crowdStepSeconds, native.crowdStepSeconds, "ms", 1e3, build.crowdHash === native.crowdHash));
  if (raysChecksum !== native.raysChecksum || build.crowdHash !== native.crowdHash) {
    console.error(`${build.name} checksums: rays wasm ${raysChecksum} native ${native.raysChecksum}; crowd wasm ${build.crowdHash} native ${native.crowdHash}`);
    process.exitCode = 1;
  }
}
