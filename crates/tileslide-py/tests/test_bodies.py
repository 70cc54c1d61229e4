"""Bodies: the crowd scene through Python ends where the Rust core puts it, bit for bit;
ids go stale when their body is removed; bad input raises, naming what and where."""

import math

import numpy as np
import pytest

import tileslide
from conftest import fnv1a64, run_crowd

# The Rust core's golden hash of the crowd (crates/tileslide/tests/resolver_golden.rs).
GOLDEN = 0x527EDA9698AB4A5D

ROOM = "########\n#......#\n#......#\n#......#\n########\n"


def test_the_crowd_ends_on_the_cores_golden_hash(scenes):
    m = tileslide.TileMap.from_ascii(scenes.map_text)
    bodies, ids = run_crowd(scenes, m)
    end = bodies.positions(ids)
    assert end.dtype == np.float32 and end.shape == (len(ids), 2)
    assert np.array_equal(end.view(np.uint32), scenes.crowd_end.view(np.uint32))
    digest = fnv1a64(end.astype("<f4").tobytes())
    assert f"{digest:#018x}" == scenes.expected["crowd_hash"]
    assert digest == GOLDEN


def test_a_body_slides_along_a_wall_and_stops_touching_it():
    m = tileslide.TileMap.from_ascii(ROOM)
    bodies = tileslide.Bodies()
    b = bodies.add(2.0, 2.5, 0.4)
    bodies.propose(b, 10.0, 1.0)
    report = bodies.step(m)
    assert (report.moving, report.cut_short) == (1, 0) and report.contacts >= 1
    x, y = bodies.position(b)
    # Stopped by the right wall (x = 7) without overlapping it; slid down to the floor.
    assert 7.0 - 0.4 - 0.01 < x <= 7.0 - 0.4
    assert y <= 4.0 - 0.4


def test_two_bodies_meet_without_overlap():
    m = tileslide.TileMap.from_ascii(ROOM)
    bodies = tileslide.Bodies()
    a = bodies.add(2.0, 2.5, 0.5)
    b = bodies.add(5.0, 2.5, 0.5)
    bodies.propose(a, 2.0, 0.0)
    bodies.propose(b, -2.0, 0.0)
    bodies.step(m)
    (ax, ay), (bx, by) = bodies.position(a), bodies.position(b)
    assert math.hypot(bx - ax, by - ay) >= 1.0 - 1e-4


def test_positions_and_ids_follow_slot_order_and_membership():
    bodies = tileslide.Bodies()
    a = bodies.add(1.5, 1.5)
    b = bodies.add(3.5, 1.5, circles=[(0.0, 0.0, 0.3), (0.5, 0.0, 0.3)])
    assert len(bodies) == 2 and bodies.ids() == [a, b]
    assert a in bodies and hash(a) != hash(b)
    np.testing.assert_array_equal(bodies.positions(), [[1.5, 1.5], [3.5, 1.5]])
    bodies.set_position(b, 4.0, 2.0)
    assert bodies.position(b) == (4.0, 2.0)
    bodies.remove(a)
    assert a not in bodies and len(bodies) == 1
    c = bodies.add(2.0, 2.0)
    # The slot is reused under a new generation; the old id stays stale.
    assert c.index == a.index and c.generation != a.generation
    assert a not in bodies and c in bodies
    assert "BodyId(index=" in repr(c)


def test_a_stale_id_raises_key_error_everywhere():
    m = tileslide.TileMap.from_ascii(ROOM)
    bodies = tileslide.Bodies()
    a = bodies.add(1.5, 1.5)
    bodies.remove(a)
    for call in [
        lambda: bodies.position(a),
        lambda: bodies.propose(a, 1.0, 0.0),
        lambda: bodies.set_position(a, 1.0, 1.0),
        lambda: bodies.remove(a),
    ]:
        with pytest.raises(KeyError, match="stale body handle"):
            call()
    assert bodies.step(m).moving == 0


def test_propose_many_checks_every_entry_before_proposing_any():
    m = tileslide.TileMap.from_ascii(ROOM)
    bodies = tileslide.Bodies()
    a = bodies.add(2.0, 2.5, 0.3)
    gone = bodies.add(4.0, 2.5, 0.3)
    bodies.remove(gone)
    moves = np.array([[1.0, 0.0], [1.0, 0.0]], dtype=np.float32)
    with pytest.raises(KeyError, match="entry 1"):
        bodies.propose_many([a, gone], moves)
    bad = np.array([[1.0, 0.0], [math.nan, 0.0]], dtype=np.float32)
    c = bodies.add(5.0, 2.5, 0.3)
    with pytest.raises(ValueError, match="entry 1"):
        bodies.propose_many([a, c], bad)
    assert bodies.step(m).moving == 0, "nothing was proposed"
    with pytest.raises(ValueError, match="one move for each id"):
        bodies.propose_many([a], moves)
    with pytest.raises(ValueError, match=r"\(N, 2\)"):
        bodies.propose_many([a], np.zeros((1, 3), dtype=np.float32))
    with pytest.raises(KeyError, match="entry 0"):
        bodies.positions([gone])


def test_a_move_ending_out_of_range_leaves_every_proposal_as_it_was():
    m = tileslide.TileMap.from_ascii(ROOM)
    bodies = tileslide.Bodies()
    a = bodies.add(2.0, 2.5, 0.3)
    b = bodies.add(5.0, 2.5, 0.3)
    bodies.propose(a, 0.5, 0.0)
    # Entry 0 (a's new move) is valid, entry 2 ends beyond the coordinate range.
    moves = np.array([[-0.5, 0.0], [0.25, 0.0], [1e30, 0.0]], dtype=np.float32)
    with pytest.raises(ValueError, match="entry 2: .*out of range"):
        bodies.propose_many([a, b, a], moves)
    report = bodies.step(m)
    assert report.moving == 1, "only a's earlier move is proposed"
    assert bodies.position(a) == (2.5, 2.5) and bodies.position(b) == (5.0, 2.5)


@pytest.mark.parametrize("radius", [0.0, -1.0, math.nan, math.inf])
def test_a_radius_that_is_not_positive_and_finite_is_refused(radius):
    with pytest.raises(ValueError, match="radius"):
        tileslide.Bodies().add(1.0, 1.0, radius)


def test_positions_and_moves_that_are_not_finite_or_in_range_are_refused():
    bodies = tileslide.Bodies()
    with pytest.raises(ValueError, match="not finite"):
        bodies.add(math.nan, 1.0)
    with pytest.raises(ValueError, match="out of range"):
        bodies.add(1e30, 1.0)
    a = bodies.add(1.0, 1.0)
    with pytest.raises(ValueError, match="not finite"):
        bodies.propose(a, math.inf, 0.0)
    with pytest.raises(ValueError, match="circle"):
        bodies.add(1.0, 1.0, circles=[])
