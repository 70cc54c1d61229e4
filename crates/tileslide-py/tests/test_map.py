"""TileMap: loading every map format, ray casts one at a time and in NumPy batches, and
errors as Python exceptions."""

import math

import numpy as np
import pytest

import tileslide
from conftest import MAPS

ROOM = "#####\n#...#\n#.=.#\n#####\n"


def test_from_ascii_has_the_text_size_and_cell():
    m = tileslide.TileMap.from_ascii(ROOM, cell=2.0)
    assert (m.width, m.height) == (5, 4)
    assert m.cell_size == (2.0, 2.0)
    assert "width=5" in repr(m)


def test_a_ray_hits_the_first_face_with_its_cell_and_tile():
    m = tileslide.TileMap.from_ascii(ROOM)
    hit = m.cast_ray(2.5, 1.5, 2.5, -3.0)
    assert hit is not None
    # The ceiling's underside is the bottom of row 0, at y = 1.
    assert hit.y == 1.0 and hit.x == 2.5
    assert (hit.nx, hit.ny) == (0.0, 1.0)
    assert hit.t == pytest.approx(0.5 / 4.5)
    assert hit.cell == (2, 0)
    assert hit.tile is not None
    assert "RayHit(" in repr(hit)


def test_a_ray_that_hits_nothing_is_none_and_back_faces_need_both_sides():
    m = tileslide.TileMap.from_ascii(ROOM)
    assert m.cast_ray(1.5, 1.5, 3.5, 1.5) is None
    # From inside the left wall out into the room: the wall's face at x = 1 faces the
    # room, so the ray meets it from behind.
    assert m.cast_ray(0.5, 1.5, 2.5, 1.5) is None
    back = m.cast_ray(0.5, 1.5, 2.5, 1.5, both_sides=True)
    assert back is not None
    assert (back.x, back.nx, back.cell) == (1.0, 1.0, (0, 1))


def test_the_one_way_platform_stops_rays_from_above_only():
    m = tileslide.TileMap.from_ascii(ROOM)
    down = m.cast_ray(2.5, 1.2, 2.5, 2.8)
    assert down is not None and down.cell == (2, 2) and down.ny == -1.0
    up = m.cast_ray(2.5, 2.8, 2.5, 1.2)
    assert up is None or up.cell != (2, 2)


def test_every_map_format_loads(tmp_path):
    rays = np.array(
        [[1.5, 1.5, 30.0, 12.0], [3.2, 2.1, 3.2, 40.0], [10.0, 5.0, 0.0, 5.0]], dtype=np.float32
    )
    cave = tileslide.TileMap.from_file(MAPS / "cave.txt")
    baked = tmp_path / "cave.tsm"
    cave.save(baked)
    # A cave drawn in Tiled, with 16-pixel tiles, saved as XML and as JSON.
    tmx = tileslide.TileMap.from_file(MAPS / "cave.tmx")
    assert tmx.cell_size == (16.0, 16.0)
    for original, copies in [(cave, [baked, str(baked)]), (tmx, [MAPS / "cave.tmj"])]:
        expected = original.cast_rays(rays * original.cell_size[0])
        for path in copies:
            m = tileslide.TileMap.from_file(path)
            assert (m.width, m.height, m.cell_size) == (
                original.width,
                original.height,
                original.cell_size,
            )
            np.testing.assert_array_equal(m.cast_rays(rays * m.cell_size[0]), expected)
    ldtk = tileslide.TileMap.from_file(MAPS / "ldtk" / "dungeon.ldtk")
    assert ldtk.width > 0 and ldtk.height > 0


def test_a_replica_island_level_needs_its_tile_set():
    data = MAPS.parents[2] / "shared" / "data" / "replica-island"
    if not data.is_dir():
        pytest.skip("the Replica Island data is not beside the checkout")
    level = tileslide.TileMap.from_file(data / "level_0_1_sewer.bin", tileset=data / "collision.bin")
    assert level.width > 0
    with pytest.raises(ValueError, match="needs its tile set"):
        tileslide.TileMap.from_file(data / "level_0_1_sewer.bin")


def test_a_missing_file_is_file_not_found():
    with pytest.raises(FileNotFoundError, match="nowhere.tmx"):
        tileslide.TileMap.from_file(MAPS / "nowhere.tmx")


def test_a_broken_file_is_a_load_error_with_file_position_and_cause(tmp_path):
    broken = tmp_path / "broken.txt"
    broken.write_text("###\n#?#\n###\n")
    with pytest.raises(tileslide.LoadError) as caught:
        tileslide.TileMap.from_file(broken)
    e = caught.value
    assert isinstance(e, ValueError)
    assert e.file == str(broken)
    assert e.position == (2, 2)
    assert "'?'" in e.cause
    assert str(broken) in str(e) and ":2:2" in str(e)


def test_a_broken_binary_file_names_the_byte(tmp_path):
    bad = tmp_path / "bad.tsm"
    bad.write_bytes(b"not a baked map at all")
    with pytest.raises(tileslide.LoadError) as caught:
        tileslide.TileMap.from_file(bad)
    assert isinstance(caught.value.position, int)
    assert caught.value.file == str(bad)


def test_a_bad_ascii_map_is_a_load_error_naming_the_text():
    with pytest.raises(tileslide.LoadError) as caught:
        tileslide.TileMap.from_ascii("#x#\n")
    assert caught.value.file == "<ascii>"
    assert caught.value.position == (1, 2)


def test_unknown_formats_and_stray_tile_sets_are_value_errors():
    with pytest.raises(ValueError, match="unknown map format"):
        tileslide.TileMap.from_file(MAPS / "tiles.png")
    with pytest.raises(ValueError, match="carries its own tile set"):
        tileslide.TileMap.from_file(MAPS / "cave.txt", tileset=MAPS / "cave.txt")


@pytest.mark.parametrize("cell", [0.0, -1.0, math.nan, math.inf])
def test_a_cell_that_is_not_positive_and_finite_is_refused(cell):
    with pytest.raises(ValueError, match="cell is"):
        tileslide.TileMap.from_ascii(ROOM, cell=cell)


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf])
def test_coordinates_that_are_not_finite_are_refused(bad):
    m = tileslide.TileMap.from_ascii(ROOM)
    with pytest.raises(ValueError, match="x1 is"):
        m.cast_ray(1.5, 1.5, bad, 1.5)
    rays = np.array([[1.5, 1.5, 2.5, 1.5], [1.5, 1.5, bad, 1.5]], dtype=np.float32)
    with pytest.raises(ValueError, match=r"rays\[1\]"):
        m.cast_rays(rays)


def test_a_ray_too_long_to_cast_is_refused_alone_and_in_a_batch():
    m = tileslide.TileMap.from_ascii(ROOM)
    with pytest.raises(ValueError, match="too long"):
        m.cast_ray(-3e38, 0.0, 3e38, 0.0)
    # Finite ends whose difference overflows: refused, not cast as a silent miss.
    rays = np.array([[1.5, 1.5, 2.5, 1.5], [-3e38, 0.0, 3e38, 0.0]], dtype=np.float32)
    with pytest.raises(ValueError, match=r"rays\[1\] = .* is too long to cast"):
        m.cast_rays(rays)


def test_a_batch_of_the_wrong_shape_or_type_is_refused():
    m = tileslide.TileMap.from_ascii(ROOM)
    with pytest.raises(ValueError, match=r"\(N, 4\)"):
        m.cast_rays(np.zeros((3, 5), dtype=np.float32))
    with pytest.raises(TypeError):
        m.cast_rays(np.zeros((3, 4), dtype=np.float64))
    with pytest.raises(TypeError):
        m.cast_rays(np.zeros(4, dtype=np.float32))


def test_an_empty_batch_gives_an_empty_answer():
    m = tileslide.TileMap.from_ascii(ROOM)
    out = m.cast_rays(np.zeros((0, 4), dtype=np.float32))
    assert out.shape == (0, 5) and out.dtype == np.float32


def test_the_batch_equals_single_casts_and_reads_any_layout(scenes):
    m = tileslide.TileMap.from_ascii(scenes.map_text)
    rays = scenes.rays[:2000]
    batch = m.cast_rays(rays)
    for row, ray in zip(batch, rays):
        hit = m.cast_ray(*ray.tolist())
        if hit is None:
            assert np.isnan(row).all()
        else:
            assert row.tolist() == [hit.t, hit.x, hit.y, hit.nx, hit.ny]
    # Every other row of a bigger array, and a Fortran-ordered copy: not C-contiguous.
    strided = np.repeat(rays, 2, axis=0)[::2]
    assert not strided.flags.c_contiguous
    np.testing.assert_array_equal(m.cast_rays(strided), batch)
    np.testing.assert_array_equal(m.cast_rays(np.asfortranarray(rays)), batch)


def test_the_rays_scene_equals_the_rust_core_bit_for_bit(scenes):
    m = tileslide.TileMap.from_ascii(scenes.map_text)
    out = m.cast_rays(scenes.rays)
    assert out.shape == scenes.ray_hits.shape
    # Bit patterns: NaN rows compare equal, and -0.0 differs from 0.0.
    assert np.array_equal(out.view(np.uint32), scenes.ray_hits.view(np.uint32))
    assert int((~np.isnan(out[:, 0])).sum()) == scenes.expected["ray_hits"]
