"""A crowd that flows to the mouse, in a pygame-ce window: 200 circles on a cave map slide
round each other and along the walls, ramps and ledges, never overlapping and never
snagging on the seams between tiles.

    pip install pygame-ce            # the optional dependency (tileslide[examples])
    python crates/tileslide-py/examples/crowd.py [MAP]

Move the mouse to lead the crowd; Esc or closing the window quits. `--frames N` stops after
N frames with the crowd led round a fixed loop instead of by the mouse, and `--screenshot
FILE` saves the last frame (with SDL_VIDEODRIVER=dummy it runs without a display).
"""

import argparse
import math
import os
from pathlib import Path

import numpy as np

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
import pygame  # noqa: E402 (after the environment it reads)

import tileslide

HERE = Path(__file__).resolve().parent
DEFAULT_MAP = HERE.parents[2] / "examples" / "maps" / "cave.txt"
RADIUS = 0.3
SPEED = 6.0  # cells per second
FPS = 60
PIXELS = 24  # per cell


def free_spots(m: tileslide.TileMap, count: int, seed: int = 7) -> list:
    """`count` cell centres of empty cells with empty neighbours, picked with a seeded RNG."""
    free = [
        (c + 0.5, r + 0.5)
        for r in range(1, m.height - 1)
        for c in range(1, m.width - 1)
        if all(m.tile(c + dc, r + dr) is None for dc in (-1, 0, 1) for dr in (-1, 0, 1))
    ]
    rng = np.random.default_rng(seed)
    picked = rng.choice(len(free), size=min(count, len(free)), replace=False)
    return [free[k] for k in picked]


def tile_outlines(m: tileslide.TileMap) -> list:
    """Each tile's outline in map coordinates, for drawing: its segments' start points in
    order (a polygon, filled) or, for a one-way platform, its one segment (a line)."""
    tiles = m.tileset
    shapes = {id: tiles.segments(id)[0] for id in tiles.ids()}
    w, h = m.cell_size
    outlines = []
    for r in range(m.height):
        for c in range(m.width):
            id = m.tile(c, r)
            if id is None:
                continue
            segments = shapes[id]
            points = [(c * w + float(ax), r * h + float(ay)) for ax, ay, _, _ in segments]
            if len(segments) == 1:
                points.append((c * w + float(segments[0][2]), r * h + float(segments[0][3])))
            outlines.append(points)
    return outlines


def scripted_target(frame: int, m: tileslide.TileMap) -> tuple:
    """A loop round the map's middle, for runs without a mouse."""
    angle = frame / 90.0
    return (
        m.width * (0.5 + 0.35 * math.cos(angle)),
        m.height * (0.5 + 0.3 * math.sin(angle)),
    )


def run(map_path: Path, frames: int = 0, screenshot: str = "", count: int = 200):
    m = tileslide.TileMap.from_file(map_path)
    cell = m.cell_size[0]
    scale = PIXELS / cell
    pygame.display.init()
    screen = pygame.display.set_mode((int(m.width * PIXELS), int(m.height * PIXELS)))
    pygame.display.set_caption("tileslide crowd")
    clock = pygame.time.Clock()
    bodies = tileslide.Bodies()
    ids = [bodies.add(x * cell, y * cell, RADIUS * cell) for x, y in free_spots(m, count)]
    outlines = [[(x * scale, y * scale) for x, y in points] for points in tile_outlines(m)]
    dt = 1.0 / FPS
    frame = 0
    running = True
    while running:
        for event in pygame.event.get():
            if event.type == pygame.QUIT or (event.type == pygame.KEYDOWN and event.key == pygame.K_ESCAPE):
                running = False
        if frames:
            target = np.array(scripted_target(frame, m), dtype=np.float32) * cell
        else:
            target = np.array(pygame.mouse.get_pos(), dtype=np.float32) / scale
        positions = bodies.positions(ids)
        delta = target - positions
        distance = np.hypot(delta[:, 0], delta[:, 1])[:, None]
        step = np.minimum(distance, SPEED * cell * dt)
        moves = np.where(distance > 1e-6, delta / np.maximum(distance, 1e-6) * step, 0.0)
        bodies.propose_many(ids, moves.astype(np.float32))
        bodies.step(m)

        screen.fill((246, 244, 238))
        for points in outlines:
            if len(points) > 2:
                pygame.draw.polygon(screen, (120, 124, 132), points)
            else:
                pygame.draw.line(screen, (214, 120, 40), points[0], points[1], 3)
        for x, y in bodies.positions(ids) * scale:
            pygame.draw.circle(screen, (46, 139, 87), (float(x), float(y)), RADIUS * PIXELS)
        pygame.draw.circle(screen, (200, 30, 90), (float(target[0] * scale), float(target[1] * scale)), 4)
        pygame.display.flip()
        frame += 1
        if frames and frame >= frames:
            running = False
        elif not frames:
            clock.tick(FPS)
    if screenshot:
        pygame.image.save(screen, screenshot)
    pygame.quit()
    return m, bodies, ids


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("map", nargs="?", default=str(DEFAULT_MAP))
    parser.add_argument("--frames", type=int, default=0, help="stop after N frames, led round a loop")
    parser.add_argument("--screenshot", default="", help="save the last frame to this PNG")
    args = parser.parse_args()
    run(Path(args.map), args.frames, args.screenshot)


if __name__ == "__main__":
    main()
