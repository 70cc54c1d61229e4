"""The rays benchmark through Python: `TileMap.cast_rays` on the rays scene (1,000,000 rays
on dungeon256, NumPy in, NumPy out) beside the Rust core's batch on the same rays, timed in
the same run. Prints the CPU model, both medians and their ratio.

    crates/tileslide-py/bench/rays.py [RAYS] [PASSES] [ROUNDS]

ROUNDS (default 5) alternate PASSES (default 7) timed passes of each.

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
    passes = int(sys.argv[2]) if len(sys.argv) > 2 else 7
    rounds = int(sys.argv[3]) if len(sys.argv) > 3 else 5
    folder = ROOT / "target" / "scenes" / f"bench-{rays_n}"
    cargo_example("export", str(folder), str(rays_n))
    rays = np.fromfile(folder / "rays.f32", dtype="<f4").reshape(-1, 4)
    expected = np.fromfile(folder / "rays_hits.f32", dtype="<f4").reshape(-1, 5)
    m = tileslide.TileMap.from_ascii((folder / "dungeon256.txt").read_text())
    out = m.cast_rays(rays)
    if not np.array_equal(out.view(np.uint32), expected.view(np.uint32)):
        sys.exit("Python's answers differ from the core's: the timing would mean nothing")

    # Rounds alternate the two, so a slow spell of a shared machine hits both alike.
    rust_times, python_times = [], []
    for _ in range(rounds):
        rust = json.loads(cargo_example("time_rays", str(rays_n), str(passes)))
        rust_times += rust["times_ms"]
        for _ in range(passes):
            start = time.perf_counter()
            m.cast_rays(rays)
            python_times.append((time.perf_counter() - start) * 1e3)
    rust_times.sort()
    python_times.sort()
    rust_median = rust_times[len(rust_times) // 2]
    python_median = python_times[len(python_times) // 2]
    total = rounds * passes
    print(f"{cpu_model()}; {rays_n:,} rays on dungeon256, median of {total} passes ({rounds} rounds of {passes}, alternating)")
    print(f"  Rust batch (cast_rays_into):   {rust_median:8.1f} ms  ({rust_times[0]:.1f} to {rust_times[-1]:.1f})")
    print(f"  Python TileMap.cast_rays:      {python_median:8.1f} ms  ({python_times[0]:.1f} to {python_times[-1]:.1f})")
    print(f"  Python / Rust: {python_median / rust_median:.2f}x  (hits {int((~np.isnan(out[:, 0])).sum()):,}, Rust {rust['hits']:,})")


if __name__ == "__main__":
    main()
