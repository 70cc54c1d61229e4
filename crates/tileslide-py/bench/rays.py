"""The rays benchmark through Python: `TileMap.cast_rays` on the rays scene (1,000,000 rays
on dungeon256, NumPy in, NumPy out) beside the Rust core's batch on the same rays, timed in
the same run. Prints the CPU model, both medians and their ratio.

    crates/tileslide-py/bench/rays.py [RAYS] [PASSES]

Run it with the virtual environment's Python after installing a release wheel (the README's
"From Python" says how); it builds the scene exporter and the Rust timer with
`cargo run --release`.
"""

import json
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

import tileslide

ROOT = Path(__file__).resolve().parents[3]


def cpu_model() -> str:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "unknown CPU"


def cargo_example(name: str, *args: str) -> str:
    command = ["cargo", "run", "--quiet", "--release", "-p", "tileslide-scenes", "--example"]
    done = subprocess.run(command + [name, "--", *args], cwd=ROOT, check=True, capture_output=True, text=True)
    return done.stdout


def main() -> None:
    rays_n = int(sys.argv[1]) if len(sys.argv) > 1 else 1_000_000
    passes = int(sys.argv[2]) if len(sys.argv) > 2 else 11
    folder = ROOT / "target" / "scenes" / f"bench-{rays_n}"
    cargo_example("export", str(folder), str(rays_n))
    rays = np.fromfile(folder / "rays.f32", dtype="<f4").reshape(-1, 4)
    expected = np.fromfile(folder / "rays_hits.f32", dtype="<f4").reshape(-1, 5)
    m = tileslide.TileMap.from_ascii((folder / "dungeon256.txt").read_text())

    rust = json.loads(cargo_example("time_rays", str(rays_n), str(passes)))

    out = m.cast_rays(rays)
    if not np.array_equal(out.view(np.uint32), expected.view(np.uint32)):
        sys.exit("Python's answers differ from the core's: the timing would mean nothing")
    times = []
    for _ in range(passes):
        start = time.perf_counter()
        m.cast_rays(rays)
        times.append((time.perf_counter() - start) * 1e3)
    times.sort()
    median = times[passes // 2]
    print(f"{cpu_model()}; {rays_n:,} rays on dungeon256, median of {passes} passes")
    print(f"  Rust batch (cast_rays_into):   {rust['median_ms']:8.1f} ms  ({rust['min_ms']:.1f} to {rust['max_ms']:.1f})")
    print(f"  Python TileMap.cast_rays:      {median:8.1f} ms  ({times[0]:.1f} to {times[-1]:.1f})")
    print(f"  Python / Rust: {median / rust['median_ms']:.2f}x  (hits {int((~np.isnan(out[:, 0])).sum()):,}, Rust {rust['hits']:,})")


if __name__ == "__main__":
    main()
