"""Debug lines: the map's segments are the core's bit for bit; bodies, characters, hit
worlds, paths and flow fields add their shapes with the core's kinds; bad input raises,
naming the argument."""

import math

import numpy as np
import pytest

import tileslide
from conftest import same_bits
from tileslide import DebugKind, DebugLines

ROOM = "######\n#....#\n#.=..#\n#../##\n######\n"


def test_the_maps_segments_are_the_cores_bit_for_bit(systems):
    lines = DebugLines()
    lines.add(tileslide.TileMap.from_ascii(systems.character_map))
    expected = systems.floats("debug_map_segments", 5)
    assert lines.segments.dtype == np.float32 and lines.segments.shape == (len(expected), 4)
    assert same_bits(lines.segments, expected[:, :4])
    assert lines.segment_kinds.dtype == np.uint8
    np.testing.assert_array_equal(lines.segment_kinds, expected[:, 4].astype(np.uint8))


def test_debug_kind_is_an_int_enum_of_the_cores_kinds():
    assert issubclass(DebugKind, int) and len(DebugKind) == 17
    assert DebugKind.ACTIVE_SEGMENT == 0 and DebugKind(3) is DebugKind.HIDDEN_SEGMENT
    assert DebugKind.BROADPHASE_BOX == 16 and DebugKind.__module__ == "tileslide"


def test_every_part_adds_its_shapes_with_its_kinds():
    m = tileslide.TileMap.from_ascii(ROOM)
    m.add_temporary(1.0, 1.0, 2.0, 1.0, 0.0, -1.0)
    lines = DebugLines()
    lines.add(m)
    kinds = set(map(DebugKind, lines.segment_kinds))
    assert {DebugKind.ACTIVE_SEGMENT, DebugKind.ONE_WAY_SEGMENT, DebugKind.NORMAL,
            DebugKind.TEMPORARY_SEGMENT} <= kinds
    lines.clear()
    assert len(lines) == 0 and lines.segments.shape == (0, 4)

    bodies = tileslide.Bodies()
    bodies.add(1.5, 1.5, 0.25)
    lines.add(bodies)
    assert same_bits(lines.circles, np.array([[1.5, 1.5, 0.25]], np.float32))
    assert list(lines.circle_kinds) == [DebugKind.BODY]

    lines = DebugLines(kinds=[DebugKind.CHARACTER, DebugKind.CONTACT])
    hero = tileslide.Character(3.5, 1.5, half_width=0.25, half_height=0.4)
    assert hero.move_by(m, 0.0, 2.0).grounded
    lines.add(hero, owner=4)
    assert list(lines.box_kinds) == [DebugKind.CHARACTER]
    assert same_bits(lines.boxes, np.array([[3.25, hero.y - 0.4, 3.75, hero.y + 0.4]], np.float32))
    assert DebugKind.CONTACT in set(lines.segment_kinds), "its ground"
    assert "DebugLines(" in repr(lines)

    world = tileslide.HitWorld()
    world.register(1, 1.0, 1.0, 1.0, 1.0, attack=[tileslide.Volume.circle(0.5, 0.5, 0.5)])
    world.register(2, 1.5, 1.0, 1.0, 1.0, team=1,
                   vulnerable=[tileslide.Volume.rect(0.5, 0.5, 0.5, 0.5)])
    world.detect()
    lines = DebugLines()
    lines.add(world)
    assert DebugKind.ATTACK_VOLUME in set(lines.circle_kinds)
    assert DebugKind.VULNERABILITY_VOLUME in set(lines.box_kinds)
    assert list(lines.point_kinds) == [DebugKind.HIT] and lines.points.shape == (1, 2)

    nav = tileslide.NavGrid(m)
    path = nav.find_path(1.5, 1.5, 3.5, 1.5, 0.3)
    lines = DebugLines(view=(0.0, 0.0, 10.0, 10.0))
    lines.add(path, owner=2)
    assert set(lines.segment_kinds) == {DebugKind.PATH}
    assert len(lines.segments) == len(path) - 1
    lines.add(tileslide.FlowField(nav, 3.5, 1.5, 0.3))
    assert DebugKind.FLOW_ARROW in set(lines.segment_kinds)


def test_a_view_keeps_only_what_touches_it():
    m = tileslide.TileMap.from_ascii(ROOM)
    everything, window = DebugLines(), DebugLines(view=(0.0, 0.0, 1.0, 1.0))
    everything.add(m)
    window.add(m)
    assert 0 < len(window) < len(everything)


def test_bad_input_raises_naming_the_argument():
    for call, error, match in [
        (lambda: DebugLines(kinds=[99]), ValueError, r"kinds\[0\] is 99"),
        (lambda: DebugLines(kinds=[0, -1]), ValueError, r"kinds\[1\] is -1"),
        (lambda: DebugLines(kinds=["body"]), TypeError, r"kinds\[0\]"),
        (lambda: DebugLines(view=(0.0, 0.0, math.nan, 1.0)), ValueError, "view"),
        (lambda: DebugLines(view=(2.0, 0.0, 1.0, 1.0)), ValueError, "view"),
        (lambda: DebugLines().add("map"), TypeError, "what is a str"),
        (lambda: DebugLines().add(tileslide.Bodies(), owner=-1), ValueError, "owner is -1"),
    ]:
        with pytest.raises(error, match=match):
            call()


def test_drawing_a_world_from_inside_its_own_rule_raises_instead_of_panicking():
    world = tileslide.HitWorld()
    world.register(1, 0.0, 0.0, 1.0, 1.0, attack=[tileslide.Volume.circle(0.5, 0.5, 1.0)])
    world.register(2, 0.5, 0.0, 1.0, 1.0, team=1, vulnerable=[tileslide.Volume.circle(0.5, 0.5, 1.0)])

    def rule(attacker, victim, hit_type):
        DebugLines().add(world)
        return True

    with pytest.raises(RuntimeError, match="borrowed"):
        world.detect(rule)
