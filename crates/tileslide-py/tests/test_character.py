"""The character: runs of move_and_slide through Python end where the Rust core puts them,
bit for bit, moving platform and one-way platform included; contacts name their tile or
platform; bad input raises, naming the argument."""

import math

import numpy as np
import pytest

import tileslide
from conftest import named, same_bits

ROOM = "########\n#......#\n#......#\n#......#\n########\n"


def replay(systems, name, character):
    m = tileslide.TileMap.from_ascii(systems.character_map)
    owner = systems.settings["platform_owner"]
    rows = []
    for vx, vy, dt, drop, x0, y0, x1, y1, pvx, pvy in systems.floats(f"character_{name}_in", 10):
        m.clear_temporaries()
        m.add_temporary(x0, y0, x1, y1, 0.0, -1.0, owner=owner, vx=pvx, vy=pvy)
        r = character.move_and_slide(m, vx, vy, dt, drop_through=bool(drop))
        g = r.ground
        col, row = g.cell if g is not None and g.cell is not None else (-1, -1)
        platform = g.owner if g is not None and g.owner is not None else -1
        rows.append([r.x, r.y, r.vx, r.vy, float(r.grounded), col, row, platform])
        assert r.grounded == (g is not None) == (character.ground is not None)
        assert (r.x, r.y) == (character.x, character.y)
    return np.array(rows, dtype=np.float32)


def test_a_box_run_ends_where_the_core_puts_it_bit_for_bit(systems):
    s = systems.settings
    hx, hy = s["box_half"]
    hero = tileslide.Character(
        2.5, 5.0, half_width=hx, half_height=hy, step_height=s["box_step_height"]
    )
    out = replay(systems, "box", hero)
    expected = systems.floats("character_box_out", 8)
    assert len(out) == s["character_steps"]
    assert same_bits(out, expected)
    # The run stands on the floor, the one-way platform and the moving platform.
    assert (expected[:, 7] == s["platform_owner"]).any()
    assert (expected[:, 6] == 4).any() and (expected[:, 6] == 8).any()


def test_a_circle_run_ends_where_the_core_puts_it_bit_for_bit(systems):
    hero = tileslide.Character(2.5, 5.0, radius=systems.settings["circle_radius"])
    out = replay(systems, "circle", hero)
    assert same_bits(out, systems.floats("character_circle_out", 8))


def test_a_box_lands_and_walks_into_a_wall():
    m = tileslide.TileMap.from_ascii(ROOM)
    hero = tileslide.Character(2.0, 1.5, half_width=0.25, half_height=0.4)
    r = hero.move_by(m, 0.0, 3.0)
    assert r.grounded and r.vx is None and r.vy is None
    assert r.y == pytest.approx(4.0 - 0.4 - 0.001, abs=1e-5)
    assert r.ground.cell[1] == 4 and r.ground.tile is not None and r.ground.owner is None
    assert (r.ground.nx, r.ground.ny) == (0.0, -1.0) and r.ground.flags == 1
    r = hero.move_by(m, 10.0, 0.5)
    assert r.right is not None and r.left is None and r.grounded
    assert r.right.cell == (7, 3) and r.right.nx == -1.0
    assert hero.x == pytest.approx(7.0 - 0.25 - 0.001, abs=1e-4)
    # The speed into the wall is clipped, the speed away from it kept.
    assert hero.clip_velocity(5.0, 0.0) == (0.0, 0.0)
    assert hero.clip_velocity(-5.0, 0.0) == (-5.0, 0.0)
    assert "MoveResult(" in repr(r) and "right" in repr(r) and "Contact(" in repr(r.right)


def test_move_and_slide_lands_and_zeroes_the_fall():
    m = tileslide.TileMap.from_ascii(ROOM)
    hero = tileslide.Character(2.0, 1.5, radius=0.3)
    vx, vy = 3.0, 0.0
    for _ in range(60):
        r = hero.move_and_slide(m, vx, vy + 0.5, 1 / 60)
        vx, vy = r.vx, r.vy
    assert r.grounded and vy == 0.0 and r.ground.cell[1] == 4


def test_a_character_rides_a_moving_platform_and_reports_its_owner():
    m = tileslide.TileMap.from_ascii("..........\n" * 6)
    hero = tileslide.Character(2.0, 2.5, half_width=0.25, half_height=0.5)
    m.add_temporary(1.0, 3.0, 4.0, 3.0, 0.0, -1.0, owner=9, vx=6.0)
    assert m.temporary_count == 1
    r = hero.move_by(m, 0.0, 0.1)
    assert r.ground is not None and r.ground.owner == 9 and r.ground.cell is None
    assert (r.ground.vx, r.ground.vy) == (6.0, 0.0)
    x = hero.x
    m.clear_temporaries(owner=9)
    m.add_temporary(1.5, 3.0, 4.5, 3.0, 0.0, -1.0, owner=9, vx=6.0)
    hero.move_by(m, 0.0, 0.1)
    assert hero.x == pytest.approx(x + 0.5, abs=1e-5), "carried by the platform's move"
    m.clear_temporaries()
    assert m.temporary_count == 0


def test_drop_through_falls_through_a_one_way_platform():
    m = tileslide.TileMap.from_ascii("......\n......\n.====.\n......\n......\n######\n")
    hero = tileslide.Character(2.5, 1.4, half_width=0.25, half_height=0.5)
    assert hero.move_by(m, 0.0, 0.5).ground.cell[1] == 2
    r = hero.move_by(m, 0.0, 1.0, drop_through=True)
    assert hero.y > 2.0 and not (r.ground is not None and r.ground.cell[1] == 2)


def test_teleport_moves_without_a_sweep_and_forgets_the_ground():
    m = tileslide.TileMap.from_ascii(ROOM)
    hero = tileslide.Character(2.0, 1.5, radius=0.3, up=(0.0, -2.0))
    assert hero.up == (0.0, -1.0) and hero.radius == np.float32(0.3)
    assert hero.half_extents is None
    hero.move_by(m, 0.0, 3.0)
    assert hero.ground is not None
    hero.teleport(5.0, 2.0)
    assert (hero.x, hero.y) == (5.0, 2.0) and hero.ground is None
    assert "Character(x=5, y=2, radius=0.3)" == repr(hero)


@pytest.mark.parametrize(
    "kwargs, match",
    [
        ({}, "radius="),
        ({"radius": 0.3, "half_width": 0.2, "half_height": 0.2}, "one of the two"),
        ({"half_width": 0.2}, "half_height"),
        ({"radius": -1.0}, "radius"),
        ({"radius": math.nan}, "radius is NaN"),
        ({"half_width": math.inf, "half_height": 1.0}, "half_width is inf"),
        ({"radius": 0.3, "up": (0.0, 0.0)}, "up"),
        ({"radius": 0.3, "up": (math.nan, 1.0)}, r"up\[0\]"),
        ({"radius": 0.3, "max_slope_degrees": 90.0}, "max_slope_degrees"),
        ({"radius": 0.3, "skin": -1.0}, "skin"),
        ({"radius": 0.3, "snap_distance": math.nan}, "snap_distance"),
        ({"radius": 0.3, "step_height": 1e30}, "step_height"),
        ({"radius": 0.3, "max_slides": 0}, "max_slides"),
        ({"radius": 0.3, "max_slides": -1}, "max_slides is -1"),
        ({"radius": 0.3, "mask": 2**40}, "mask is"),
    ],
)
def test_a_bad_character_is_refused_naming_the_argument(kwargs, match):
    with pytest.raises(ValueError, match=match):
        tileslide.Character(1.0, 1.0, **kwargs)


def test_wrong_types_raise_type_error_naming_the_argument():
    with pytest.raises(TypeError, match="max_slides"):
        tileslide.Character(1.0, 1.0, radius=0.3, max_slides="four")
    with pytest.raises(TypeError, match="mask"):
        tileslide.Character(1.0, 1.0, radius=0.3, mask=1.5)
    with pytest.raises(TypeError, match=named("x")):
        tileslide.Character("1", 1.0, radius=0.3)
    with pytest.raises(TypeError):
        tileslide.Character(1.0, 1.0, radius=0.3).move_by(None, 1.0, 0.0)


def test_bad_moves_raise_and_leave_the_character_where_it_was():
    m = tileslide.TileMap.from_ascii(ROOM)
    hero = tileslide.Character(2.0, 2.0, radius=0.3)
    for call, match in [
        (lambda: hero.move_by(m, math.nan, 0.0), "dx is NaN"),
        (lambda: hero.move_by(m, 0.0, math.inf), "dy is inf"),
        (lambda: hero.move_by(m, 1e30, 0.0), "displacement"),
        (lambda: hero.move_and_slide(m, math.nan, 0.0, 0.1), "vx is NaN"),
        (lambda: hero.move_and_slide(m, 0.0, 1.0, -0.1), "dt is -0.1"),
        (lambda: hero.move_and_slide(m, 0.0, 1.0, math.inf), "dt is inf"),
        (lambda: hero.clip_velocity(0.0, math.nan), "vy is NaN"),
        (lambda: hero.teleport(math.nan, 0.0), "x is NaN"),
        (lambda: hero.teleport(1e30, 0.0), "position"),
        (lambda: tileslide.Character(1e30, 0.0, radius=0.3), "position"),
    ]:
        with pytest.raises(ValueError, match=match):
            call()
    assert (hero.x, hero.y) == (2.0, 2.0)


def test_bad_temporary_segments_are_refused_naming_the_argument():
    m = tileslide.TileMap.from_ascii(ROOM)
    for kwargs, error, match in [
        ({"x0": math.nan}, ValueError, "x0 is NaN"),
        ({"ny": math.inf}, ValueError, "ny is inf"),
        ({"vx": math.nan}, ValueError, "vx is NaN"),
        ({"x1": 1.0, "y1": 1.0}, ValueError, "zero length"),
        ({"nx": 0.0, "ny": 0.0}, ValueError, "zero normal"),
        ({"owner": -1}, ValueError, "owner is -1"),
        ({"flags": 2**33}, ValueError, "flags is"),
        ({"owner": "a"}, TypeError, "owner"),
    ]:
        args = {"x0": 1.0, "y0": 1.0, "x1": 2.0, "y1": 1.0, "nx": 0.0, "ny": -1.0}
        args.update(kwargs)
        with pytest.raises(error, match=match):
            m.add_temporary(**args)
    with pytest.raises(ValueError, match="owner"):
        m.clear_temporaries(owner=-3)
    assert m.temporary_count == 0


def test_a_map_holds_at_most_max_temporaries():
    m = tileslide.TileMap.from_ascii(ROOM)
    for i in range(65536):
        m.add_temporary(1.0, 1.0 + (i % 3), 2.0, 1.0 + (i % 3), 0.0, -1.0, owner=i % 7)
    with pytest.raises(ValueError, match="owner 9 refused.*65536.*MAX_TEMPORARIES"):
        m.add_temporary(1.0, 1.0, 2.0, 1.0, 0.0, -1.0, owner=9)
    assert m.temporary_count == 65536
    m.clear_temporaries(owner=3)
    m.add_temporary(1.0, 1.0, 2.0, 1.0, 0.0, -1.0, owner=9)
