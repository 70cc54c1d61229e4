"""Paths and flow fields: on the dungeon, Python's paths, directions and distances are the
Rust core's bit for bit; bad input raises, naming the argument."""

import math

import numpy as np
import pytest

import tileslide
from conftest import named, same_bits

# Two rooms joined by a gap one cell wide (column 5).
ROOM = "##########\n#........#\n#........#\n#####.####\n#........#\n#........#\n##########\n"


@pytest.fixture(scope="module")
def dungeon(scenes):
    m = tileslide.TileMap.from_ascii(scenes.map_text)
    return m, tileslide.NavGrid(m)


def test_paths_are_the_cores_bit_for_bit(systems, dungeon):
    _, nav = dungeon
    queries = systems.floats("path_queries", 5)
    counts = systems.floats("path_counts")
    lengths = systems.floats("path_lengths")
    points = systems.floats("path_points", 2)
    got_counts, got_lengths, got_points = [], [], []
    for x0, y0, x1, y1, r in queries:
        path = nav.find_path(x0, y0, x1, y1, r)
        if path is None:
            got_counts.append(-1)
            got_lengths.append(math.nan)
            continue
        assert path.points.dtype == np.float32 and path.points.shape == (len(path), 2)
        assert path.radius == r
        got_counts.append(len(path))
        got_lengths.append(path.length)
        got_points.append(path.points)
    assert same_bits(np.array(got_counts, dtype=np.float32), counts)
    assert same_bits(np.array(got_lengths, dtype=np.float32), lengths)
    assert same_bits(np.concatenate(got_points), points)
    assert (counts < 0).any() and (counts > 2).any(), "the queries find paths and miss some"


def test_flow_field_answers_are_the_cores_bit_for_bit(systems, dungeon):
    _, nav = dungeon
    gx, gy = systems.flow["goal"]
    field = tileslide.FlowField(nav, gx, gy, systems.flow["radius"])
    points = systems.floats("flow_points", 2)
    directions = field.directions(points)
    assert directions.dtype == np.float32 and directions.shape == points.shape
    assert same_bits(directions, systems.floats("flow_directions", 2))
    assert same_bits(field.lattice_directions(points), systems.floats("flow_lattice", 2))
    distances = [field.distance(x, y) for x, y in points[:200]]
    distances = np.array([math.nan if d is None else d for d in distances], dtype=np.float32)
    assert same_bits(distances, systems.floats("flow_distances")[:200])
    # One point at a time agrees with the batch.
    for (x, y), d, ld in zip(points[:50], directions[:50], field.lattice_directions(points[:50])):
        one = field.direction(x, y)
        assert (one is None and np.isnan(d).all()) or same_bits(np.array(one), d)
        one = field.lattice_direction(x, y)
        assert (one is None and np.isnan(ld).all()) or same_bits(np.array(one), ld)


def test_a_path_goes_round_a_wall_and_fits_the_circle():
    m = tileslide.TileMap.from_ascii(ROOM)
    nav = tileslide.NavGrid(m)
    assert nav.max_radius == 1.0 and nav.map is m and "NavGrid(" in repr(nav)
    path = nav.find_path(2.0, 2.0, 2.0, 5.0, 0.3)
    assert path is not None and len(path) >= 3 and "NavPath(" in repr(path)
    pts = path.points
    assert tuple(pts[0]) == (2.0, 2.0) and tuple(pts[-1]) == (2.0, 5.0)
    assert path.length > 6.0 and (pts[:, 0] > 5.0).any(), "through the gap"
    steps = np.diff(pts, axis=0)
    assert path.length == pytest.approx(np.hypot(steps[:, 0], steps[:, 1]).sum(), rel=1e-5)
    # Too wide for the gap: no path; from inside a wall: no path.
    assert nav.find_path(2.0, 2.0, 2.0, 5.0, 0.7) is None
    assert nav.find_path(3.5, 3.5, 2.0, 2.0, 0.3) is None
    assert nav.fits(2.0, 2.0, 0.7) and not nav.fits(3.5, 3.5, 0.1)


def test_a_flow_field_leads_to_its_goal():
    m = tileslide.TileMap.from_ascii(ROOM)
    nav = tileslide.NavGrid(m)
    field = tileslide.FlowField(nav, 2.0, 5.0, 0.3)
    assert field.goal == (2.0, 5.0) and field.radius == np.float32(0.3)
    dx, dy = field.direction(2.0, 2.0)
    assert dx > 0.0 and math.hypot(dx, dy) == pytest.approx(1.0)
    assert field.distance(2.0, 2.0) > 6.0 and field.distance(3.5, 3.5) is None
    assert field.direction(3.5, 3.5) is None
    assert "FlowField(goal=(2, 5)" in repr(field)


def test_bad_input_raises_naming_the_argument():
    m = tileslide.TileMap.from_ascii(ROOM)
    nav = tileslide.NavGrid(m)
    field = tileslide.FlowField(nav, 2.0, 5.0, 0.3)
    for call, error, match in [
        (lambda: tileslide.NavGrid(m, max_radius=math.nan), ValueError, "max_radius is NaN"),
        (lambda: tileslide.NavGrid(m, max_radius=0.0), ValueError, "max_radius"),
        (lambda: tileslide.NavGrid(m, max_radius=100.0), ValueError, "max_radius"),
        (lambda: tileslide.NavGrid(m, mask=-1), ValueError, "mask is -1"),
        (lambda: tileslide.NavGrid("map"), TypeError, named("map")),
        (lambda: nav.find_path(math.nan, 1.0, 2.0, 2.0, 0.3), ValueError, "x0 is NaN"),
        (lambda: nav.find_path(1.0, 1.0, 2.0, math.inf, 0.3), ValueError, "y1 is inf"),
        (lambda: nav.find_path(1.0, 1.0, 2.0, 2.0, math.nan), ValueError, "radius is NaN"),
        (lambda: nav.find_path(1.0, 1.0, 2.0, 2.0, 2.0), ValueError, "radius"),
        (lambda: nav.find_path(1e30, 1.0, 2.0, 2.0, 0.3), ValueError, "out of range|beyond"),
        (lambda: nav.fits(1.0, math.nan, 0.3), ValueError, "y is NaN"),
        (lambda: tileslide.FlowField(nav, math.nan, 1.0, 0.3), ValueError, "x is NaN"),
        (lambda: tileslide.FlowField(nav, 1.5, 1.5, -1.0), ValueError, "radius"),
        (lambda: field.direction(math.inf, 1.0), ValueError, "x is inf"),
        (lambda: field.lattice_direction(1.0, math.nan), ValueError, "y is NaN"),
        (lambda: field.distance(math.nan, 1.0), ValueError, "x is NaN"),
        (lambda: field.directions(np.zeros((3, 3), np.float32)), ValueError, r"\(N, 2\)"),
        (lambda: field.directions(np.zeros((3, 2), np.float64)), TypeError, named("points")),
        (lambda: field.directions(np.zeros(4, np.float32)), TypeError, named("points")),
        (
            lambda: field.lattice_directions(np.array([[1, 1], [np.nan, 1]], np.float32)),
            ValueError,
            r"points\[1\]",
        ),
        (
            lambda: field.directions(np.array([[1e30, 1]], np.float32)),
            ValueError,
            r"points\[0\]",
        ),
    ]:
        with pytest.raises(error, match=match):
            call()


def test_after_a_map_edit_paths_and_fields_refuse_until_synced_then_follow_it():
    m = tileslide.TileMap.from_ascii(ROOM)
    nav = tileslide.NavGrid(m)
    field = tileslide.FlowField(nav, 2.0, 5.0, 0.3)
    before = nav.find_path(2.0, 2.0, 2.0, 5.0, 0.3)
    assert before is not None and field.direction(2.0, 2.0) is not None
    assert not nav.sync() and not field.sync(), "nothing to catch up with"
    # Close the gap in the middle wall: the two halves are cut off.
    m.set_tile(5, 3, m.tile(0, 0))
    with pytest.raises(ValueError, match="behind the map"):
        nav.find_path(2.0, 2.0, 2.0, 5.0, 0.3)
    with pytest.raises(ValueError, match="behind the map"):
        field.direction(2.0, 2.0)
    with pytest.raises(ValueError, match="behind the map"):
        field.sync()
    assert nav.sync()
    assert nav.find_path(2.0, 2.0, 2.0, 5.0, 0.3) is None
    assert field.sync()
    assert field.direction(2.0, 2.0) is None and field.distance(2.0, 2.0) is None
    # Dig it out again: the way is back, the same as before.
    m.set_tile(5, 3, None)
    assert nav.sync() and field.sync()
    again = nav.find_path(2.0, 2.0, 2.0, 5.0, 0.3)
    assert again is not None and same_bits(again.points, before.points)
    assert field.direction(2.0, 2.0) is not None
