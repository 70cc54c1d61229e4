"""Pictures (`render`) equal tileslide-render's byte for byte; tile shapes traced from masks
and PNG tile sheets; maps laid out from tile arrays and edited cell by cell."""

import math
import struct

import numpy as np
import pytest

import tileslide
from conftest import MAPS, run_crowd, run_example, target_dir

ROOM = "#####\n#...#\n#...#\n#####\n"


def png_size(data: bytes):
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    return struct.unpack(">II", data[16:24])


def test_the_crowd_picture_equals_the_rust_renderers_byte_for_byte(scenes, tmp_path):
    reference = target_dir() / "scenes" / "crowd.png"
    run_example("picture", str(reference))
    m = tileslide.TileMap.from_ascii(scenes.map_text)
    bodies, ids = run_crowd(scenes, m)
    out = tmp_path / "crowd.png"
    data = tileslide.render(m, out, bodies=bodies, rays=scenes.rays[:64], scale=4.0)
    assert png_size(data) == (1024, 1024)
    assert out.read_bytes() == data
    assert data == reference.read_bytes()


def test_circles_rays_and_paths_change_the_picture():
    m = tileslide.TileMap.from_ascii(ROOM)
    plain = tileslide.render(m)
    assert png_size(plain) == (80, 64)
    # Off the room's middle line, so the picture drawn y-up differs.
    circles = np.array([[2.5, 1.6, 0.4]], dtype=np.float32)
    rays = np.array([[1.5, 1.5, 3.5, 2.5]], dtype=np.float32)
    path = np.array([[1.5, 1.5], [3.5, 1.5], [3.5, 2.5]], dtype=np.float32)
    drawn = {
        tileslide.render(m, circles=circles),
        tileslide.render(m, rays=rays),
        tileslide.render(m, paths=[path]),
        tileslide.render(m, y_up=True, circles=circles),
    }
    assert plain not in drawn and len(drawn) == 4
    assert png_size(tileslide.render(m, scale=2.5)) == (13, 10)
    # A circle that is not finite is left out, not drawn wrong.
    nan = np.array([[math.nan, 2.0, 0.4]], dtype=np.float32)
    assert tileslide.render(m, circles=nan) == plain


def test_bad_scales_sizes_shapes_and_folders_are_refused(tmp_path):
    m = tileslide.TileMap.from_ascii(ROOM)
    for scale in [0.0, -2.0, math.nan]:
        with pytest.raises(ValueError, match="pixels per cell"):
            tileslide.render(m, scale=scale)
    with pytest.raises(ValueError, match="too large"):
        tileslide.render(m, scale=100_000.0)
    with pytest.raises(ValueError, match=r"circles has shape \(1, 2\)"):
        tileslide.render(m, circles=np.zeros((1, 2), dtype=np.float32))
    with pytest.raises(ValueError, match=r"paths\[1\]"):
        good = np.zeros((2, 2), dtype=np.float32)
        tileslide.render(m, paths=[good, np.zeros((2, 3), dtype=np.float32)])
    with pytest.raises(FileNotFoundError, match="nowhere"):
        tileslide.render(m, tmp_path / "nowhere" / "map.png")


def test_a_staircase_mask_traces_to_one_slope():
    # A 4 × 4 ramp drawn in 1-pixel steps, rising to the right (y down).
    mask = np.array([[c + r >= 3 for c in range(4)] for r in range(4)])
    segments, normals = tileslide.trace(mask)
    assert segments.shape == (3, 4) and normals.shape == (3, 2)
    slopes = [n for n in normals if n[0] < 0 and n[1] < 0]
    assert len(slopes) == 1
    assert math.isclose(float(np.hypot(*slopes[0])), 1.0, rel_tol=1e-6)
    exact, _ = tileslide.trace(mask, tolerance=0.0)
    assert len(exact) > 3, "tolerance 0 keeps every step"
    empty, _ = tileslide.trace(np.zeros((3, 3), dtype=bool))
    assert empty.shape == (0, 4)


def test_bad_masks_are_refused():
    with pytest.raises(ValueError, match="tolerance"):
        tileslide.trace(np.ones((2, 2), dtype=bool), tolerance=-1.0)
    with pytest.raises(TypeError):
        tileslide.trace(np.ones((2, 2), dtype=np.uint8))


def test_a_png_tile_sheet_becomes_a_traced_tile_set_and_a_map():
    tiles = tileslide.TileSet.from_image(MAPS / "tiles.png", 16, 16)
    assert len(tiles) == 8 and tiles.ids() == list(range(8))
    assert tiles.tile_size == (16.0, 16.0)
    segments, normals = tiles.segments(0)
    assert segments.shape[1] == 4 and len(segments) == len(normals)
    with pytest.raises(KeyError, match="tile 99"):
        tiles.segments(99)
    layout = np.array([[0, -1, 1], [-1, -1, -1], [2, 2, 2]])
    m = tileslide.TileMap.from_tiles(layout, tiles, origin=(32.0, 0.0))
    assert (m.width, m.height, m.cell_size) == (3, 3, (16.0, 16.0))
    assert [m.tile(c, 0) for c in range(3)] == [0, None, 1]
    # A ray down the middle column meets the bottom row's tiles.
    hit = m.cast_ray(32.0 + 24.0, 17.0, 32.0 + 24.0, 47.0)
    assert hit is not None and hit.cell == (1, 2)
    # Past the map's cell limit (2^26): refused before the cells are read. (A broadcast
    # view: the array itself takes no memory.)
    huge = np.broadcast_to(np.int64(-1), (1 << 14, 1 << 13))
    with pytest.raises(ValueError, match=r"tiles has shape \(16384, 8192\): .* at most 67108864"):
        tileslide.TileMap.from_tiles(huge, tiles)
    with pytest.raises(ValueError, match=r"tiles\[0, 1\] is 42"):
        tileslide.TileMap.from_tiles(np.array([[0, 42]]), tiles)
    with pytest.raises(tileslide.LoadError) as caught:
        tileslide.TileSet.from_image(MAPS / "cave.txt", 16, 16)
    assert caught.value.file.endswith("cave.txt")
    with pytest.raises(ValueError, match="at least one pixel"):
        tileslide.TileSet.from_image(MAPS / "tiles.png", 0, 16)


def test_set_tile_digs_and_builds_walls_bodies_then_meet():
    m = tileslide.TileMap.from_ascii(ROOM)
    solid = m.tile(0, 0)
    assert solid is not None and m.tile(1, 1) is None
    assert solid in m.tileset.ids()
    # Wall off the room's middle column; a ray across now stops there.
    m.set_tile(2, 1, solid)
    hit = m.cast_ray(1.5, 1.5, 3.5, 1.5)
    assert hit is not None and hit.x == 2.0
    bodies = tileslide.Bodies()
    b = bodies.add(1.5, 1.5, 0.3)
    bodies.propose(b, 2.0, 0.0)
    bodies.step(m)
    assert bodies.position(b)[0] <= 2.0 - 0.3
    # Dig it out again: the ray goes through.
    m.set_tile(2, 1, None)
    assert m.cast_ray(1.5, 1.5, 3.5, 1.5) is None
    with pytest.raises(IndexError, match=r"cell \(5, 1\) is outside"):
        m.set_tile(5, 1, None)
    with pytest.raises(IndexError):
        m.tile(0, 4)
    with pytest.raises(ValueError):
        m.set_tile(1, 1, 123456)
