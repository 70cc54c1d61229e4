"""The pygame-ce example runs headless (SDL's dummy video driver): the crowd follows its
leader without a body overlapping another or a wall."""

import importlib.util
import math

import numpy as np
import pytest

from conftest import ROOT

EXAMPLE = ROOT / "crates" / "tileslide-py" / "examples" / "crowd.py"


def test_the_crowd_example_flows_without_overlap(tmp_path, monkeypatch):
    pytest.importorskip("pygame")
    monkeypatch.setenv("SDL_VIDEODRIVER", "dummy")
    spec = importlib.util.spec_from_file_location("crowd_example", EXAMPLE)
    crowd = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(crowd)
    shot = tmp_path / "crowd.png"
    m, bodies, ids = crowd.run(crowd.DEFAULT_MAP, frames=300, screenshot=str(shot))
    assert shot.read_bytes()[:4] == b"\x89PNG"
    start = np.array(crowd.free_spots(m, len(ids)), dtype=np.float32)
    end = bodies.positions(ids)
    assert len(ids) == 200
    assert float(np.abs(end - start).sum(axis=1).mean()) > 2.0, "the crowd moved"
    r = crowd.RADIUS
    gaps = end[:, None, :] - end[None, :, :]
    distance = np.hypot(gaps[..., 0], gaps[..., 1]) + np.eye(len(ids)) * 1e9
    assert float(distance.min()) >= 2 * r - 1e-3
    # No wall inside any circle: short rays from its centre meet no face from either side.
    for x, y in end.tolist():
        for k in range(16):
            a = k * math.pi / 8
            tip = (x + math.cos(a) * r * 0.999, y + math.sin(a) * r * 0.999)
            assert m.cast_ray(x, y, *tip, both_sides=True) is None, (x, y)
