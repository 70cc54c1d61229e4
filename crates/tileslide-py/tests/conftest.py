"""Shared fixtures: the standard scenes and the Rust core's answers on them.

The scenes are written by tileslide-scenes' example `export` (once per test session, into
the cargo target directory, always anew), so every agreement test compares with the core's
own answers from the same checkout; the character runs, path queries and hit volumes scene
likewise by its example `export_systems`. Each example runs through `cargo run`, or, when
TILESLIDE_PROGRAMS names a folder of built programs (test.sh sets it to the one its Rust
tests built them in), from there.
"""

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[3]
MAPS = ROOT / "examples" / "maps"
# The rays the tests compare (the benchmark takes a million).
TEST_RAYS = 100_000


def target_dir() -> Path:
    return Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))


class Scenes:
    """The exported scenes: arrays, the map's text and the expected numbers."""

    def __init__(self, folder: Path):
        self.folder = folder
        self.expected = json.loads((folder / "expected.json").read_text())
        self.map_text = (folder / "dungeon256.txt").read_text()
        self.rays = np.fromfile(folder / "rays.f32", dtype="<f4").reshape(-1, 4)
        self.ray_hits = np.fromfile(folder / "rays_hits.f32", dtype="<f4").reshape(-1, 5)
        self.crowd = np.fromfile(folder / "crowd.f32", dtype="<f4").reshape(-1, 4)
        self.crowd_end = np.fromfile(folder / "crowd_end.f32", dtype="<f4").reshape(-1, 2)


def run_example(name: str, *args: str) -> None:
    """Runs tileslide-scenes' example `name` with `args`: the one built in TILESLIDE_PROGRAMS
    (a cargo profile's folder, which holds the examples in `examples/`) when that is set,
    else through `cargo run`."""
    programs = os.environ.get("TILESLIDE_PROGRAMS")
    if programs:
        command = [str(Path(programs) / "examples" / name)]
    else:
        command = ["cargo", "run", "--quiet", "-p", "tileslide-scenes", "--example", name, "--"]
    subprocess.run(command + list(args), cwd=ROOT, check=True)


def export_scenes(rays: int) -> Scenes:
    folder = target_dir() / "scenes" / str(rays)
    run_example("export", str(folder), str(rays))
    return Scenes(folder)


@pytest.fixture(scope="session")
def scenes() -> Scenes:
    return export_scenes(TEST_RAYS)


def run_crowd(scenes: Scenes, m):
    """The crowd scene run through Python as the golden test runs it: the bodies and ids."""
    import tileslide

    bodies = tileslide.Bodies()
    radius = scenes.expected["crowd_radius"]
    ids = [bodies.add(float(x), float(y), radius) for x, y in scenes.crowd[:, :2]]
    moves = np.ascontiguousarray(scenes.crowd[:, 2:])
    for _ in range(scenes.expected["crowd_steps"]):
        bodies.propose_many(ids, moves)
        bodies.step(m)
    return bodies, ids

class Systems:
    """The exported runs of the character, paths and hit volumes (see export_systems.rs)."""

    def __init__(self, folder: Path):
        self.folder = folder
        self.settings = json.loads((folder / "systems.json").read_text())
        self.flow = json.loads((folder / "flow.json").read_text())
        self.character_map = (folder / "character_map.txt").read_text()

    def floats(self, name: str, columns: int = 0) -> np.ndarray:
        values = np.fromfile(self.folder / f"{name}.f32", dtype="<f4")
        return values.reshape(-1, columns) if columns else values


@pytest.fixture(scope="session")
def systems() -> Systems:
    folder = target_dir() / "scenes" / "systems"
    run_example("export_systems", str(folder))
    return Systems(folder)


def same_bits(a, b) -> bool:
    """Whether two float32 arrays hold the same bits (NaNs included)."""
    a = np.ascontiguousarray(a, dtype=np.float32)
    b = np.ascontiguousarray(b, dtype=np.float32)
    return a.shape == b.shape and np.array_equal(a.view(np.uint32), b.view(np.uint32))


def named(argument: str):
    """The pattern a TypeError of pyo3's own argument conversion matches: pyo3 names the
    argument in the exception's note (PEP 678), which Python 3.11 and newer have (pytest
    matches notes too); on 3.9 and 3.10 the message alone says what was wrong."""
    return argument if sys.version_info >= (3, 11) else None


def fnv1a64(data: bytes) -> int:
    """FNV-1a 64, as tileslide_scenes::Fnv1a."""
    h = 0xCBF29CE484222325
    for byte in data:
        h ^= byte
        h = (h * 0x100000001B3) & 0xFFFFFFFFFFFFFFFF
    return h
