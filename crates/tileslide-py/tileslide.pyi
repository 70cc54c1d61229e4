"""tileslide: collision detection and response for tile-based 2D games.

Maps load from ASCII text, Tiled (.tmx, .tmj), LDtk (.ldtk), baked (.tsm) and Replica
Island (.bin) files; rays are cast one at a time or as a NumPy batch; bodies (circles and
compounds of circles) slide round each other and along walls without overlap or tunnelling;
a platformer character walks slopes, stands on one-way and moving platforms (temporary
segments).
Coordinates are map units, y down; every number is a 32-bit float, as in the Rust core, so
answers are bit-identical to it.
"""

from enum import IntEnum
from os import PathLike
from typing import Callable, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str

_Path = Union[str, PathLike[str]]

class LoadError(ValueError):
    """A map file (or text) that is not a map tileslide can load."""

    file: str
    """The file, as given (`"<ascii>"` for `TileMap.from_ascii`)."""
    position: Union[None, Tuple[int, int], int]
    """None for the whole file, `(line, column)` from 1 in a text file, or a byte offset in
    a binary one."""
    cause: str
    """What is wrong."""

class RayHit:
    """The first face a ray hit."""

    @property
    def t(self) -> float:
        """Fraction of the way from the start to the end, in [0, 1]."""
    @property
    def x(self) -> float:
        """The point hit, x."""
    @property
    def y(self) -> float:
        """The point hit, y."""
    @property
    def nx(self) -> float:
        """The face's outward unit normal, x."""
    @property
    def ny(self) -> float:
        """The face's outward unit normal, y."""
    @property
    def cell(self) -> Optional[Tuple[int, int]]:
        """The tile's cell `(col, row)`, or None for a face that is not a tile's."""
    @property
    def tile(self) -> Optional[int]:
        """The tile's id, or None."""

class TileMap:
    """A collision map: tiles on a grid, each a set of solid segments, seams culled."""

    @staticmethod
    def from_file(path: _Path, tileset: Optional[_Path] = None) -> TileMap:
        """Loads the map at `path`, its format told by its extension: `.txt` ASCII, `.tmx`,
        `.tmj`, `.json` Tiled, `.ldtk` LDtk (its first level), `.tsm` baked, `.bin` Replica
        Island (with `tileset`, its `collision.bin`).

        Raises FileNotFoundError, OSError, LoadError (a ValueError naming the file, the
        position and the cause), or ValueError (an unknown format, a tile set the format
        does not take or lacks)."""
    @staticmethod
    def from_ascii(text: str, cell: float = 1.0) -> TileMap:
        """Builds a map from ASCII text: `#` solid, `.` or space empty, `/` and `\\`
        ramps, `=` one-way platform; rows top to bottom, lines starting with `;` are
        comments. Cells are squares of side `cell`."""
    @staticmethod
    def from_tiles(
        tiles: npt.NDArray[np.int64], tileset: TileSet, origin: Tuple[float, float] = (0.0, 0.0)
    ) -> TileMap:
        """A map laid out from `tiles` (2-D int64, row 0 at the top: each cell's tile id in
        `tileset`, negative for an empty cell), its corner at `origin`. Raises ValueError
        naming the first cell whose id the tile set lacks."""
    @property
    def tileset(self) -> TileSet:
        """The map's tile set."""
    def tile(self, col: int, row: int) -> Optional[int]:
        """The id of the tile in cell (col, row), or None for an empty cell. Raises
        IndexError for a cell outside the map."""
    def set_tile(self, col: int, row: int, id: Optional[int]) -> None:
        """Puts tile `id` of the map's tile set in cell (col, row), or empties it (None):
        only the segments around the cell change; bodies stepped on the map next meet the
        new wall. Raises IndexError outside the map, ValueError for an unknown id."""
    def save(self, path: _Path) -> None:
        """Saves the map as a baked map (`.tsm`), which loads without a tile set."""
    @property
    def width(self) -> int:
        """The map's width in cells."""
    @property
    def height(self) -> int:
        """The map's height in cells."""
    @property
    def cell_size(self) -> Tuple[float, float]:
        """A cell's size `(width, height)`."""
    def cast_ray(
        self, x0: float, y0: float, x1: float, y1: float, both_sides: bool = False
    ) -> Optional[RayHit]:
        """The first face the ray from (x0, y0) to (x1, y1) hits, or None. Only faces the
        ray meets head-on count, unless `both_sides`. Raises ValueError for a coordinate
        that is not finite."""
    def cast_rays(
        self, rays: npt.NDArray[np.float32], both_sides: bool = False
    ) -> npt.NDArray[np.float32]:
        """Casts a batch: `rays` has shape (N, 4), rows `x0, y0, x1, y1`. Returns shape
        (N, 5), rows `t, x, y, nx, ny` of each ray's first hit, all NaN for a miss. Raises
        ValueError for a wrong shape, a coordinate that is not finite or a ray too long to
        cast (naming the row),
        TypeError for an array that is not float32 and 2-dimensional."""
    def add_temporary(
        self,
        x0: float,
        y0: float,
        x1: float,
        y1: float,
        nx: float,
        ny: float,
        *,
        flags: int = 1,
        owner: int = 0,
        vx: float = 0.0,
        vy: float = 0.0,
    ) -> None:
        """Adds a temporary segment from (x0, y0) to (x1, y1) facing (nx, ny) (normalised):
        a door or a moving platform, which every query, body and character meets until it
        is cleared. `flags` 1 solid, 2 one-way; `owner` who submitted it; (vx, vy) how fast
        it moves (a character standing on it rides it). Submit moving platforms anew each
        frame, before the characters move. Raises ValueError for a coordinate that is not
        finite (naming it), a segment of zero length, a zero normal, an owner or flags out
        of range."""
    def clear_temporaries(self, owner: Optional[int] = None) -> None:
        """Removes the temporary segments of `owner`, or every one when None."""
    @property
    def temporary_count(self) -> int:
        """How many temporary segments the map holds."""

class BodyId:
    """A body's id. Once its body is removed the id is stale for good: using it raises
    KeyError, even after its slot holds another body."""

    @property
    def index(self) -> int:
        """The body's slot (bodies are resolved in slot order)."""
    @property
    def generation(self) -> int:
        """How many bodies had the slot before this one."""
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...

class StepReport:
    """What a step did."""

    @property
    def moving(self) -> int:
        """Bodies with a move to make."""
    @property
    def contacts(self) -> int:
        """Contacts met (each sweep stopped at something counts once)."""
    @property
    def cut_short(self) -> int:
        """Bodies whose move was still blocked after the last pass, cut at its first
        contact."""

class Bodies:
    """A set of bodies resolved together: each step, every proposed move is made as far as
    it goes without overlapping the map's walls or another body, sliding along what it
    meets."""

    def __init__(self) -> None: ...
    def add(
        self,
        x: float,
        y: float,
        radius: float = 0.5,
        *,
        circles: Optional[Sequence[Tuple[float, float, float]]] = None,
        groups: Optional[int] = None,
        collides_with: Optional[int] = None,
    ) -> BodyId:
        """Adds a body at (x, y): one circle of `radius`, or a compound of `circles` given
        as `(dx, dy, radius)` offsets from the position. `groups` (default 1) are the
        groups it belongs to, `collides_with` (default all) those it meets, as bits.
        Raises ValueError for a radius that is not positive, a position that is not finite
        or out of range."""
    def remove(self, id: BodyId) -> None:
        """Removes a body; its id is stale from now on."""
    def __contains__(self, id: BodyId) -> bool: ...
    def __len__(self) -> int: ...
    def ids(self) -> list[BodyId]:
        """Every body's id, in slot order."""
    def propose(self, id: BodyId, dx: float, dy: float) -> None:
        """Proposes the move (dx, dy) for the next step, replacing one proposed before."""
    def propose_many(self, ids: Sequence[BodyId], moves: npt.NDArray[np.float32]) -> None:
        """Proposes `moves[k]` (shape (N, 2)) for `ids[k]`. A stale id (KeyError), or a
        move that is not finite or would end out of range (ValueError), names its entry and
        leaves every proposal as it was."""
    def set_position(self, id: BodyId, x: float, y: float) -> None:
        """Moves a body to (x, y) at once (no sweep), dropping its proposed move."""
    def step(self, map: TileMap) -> StepReport:
        """One step: every proposed move resolved together against `map` and each other,
        then made."""
    def position(self, id: BodyId) -> Tuple[float, float]:
        """A body's position."""
    def positions(self, ids: Optional[Sequence[BodyId]] = None) -> npt.NDArray[np.float32]:
        """The positions of `ids` (every body's, in slot order, when None), shape (N, 2)."""

class TileSet:
    """Tile shapes by id, all of one tile size."""

    @staticmethod
    def from_image(
        path: _Path,
        tile_width: int,
        tile_height: int,
        threshold: int = 128,
        tolerance: float = 1.0,
    ) -> TileSet:
        """Cuts the PNG tile sheet at `path` into tile_width × tile_height pixel tiles, row
        by row (tile k gets id k), each traced (see `trace`): a pixel is solid when its
        alpha is at least `threshold`, or, without transparency, when it is darker.
        Raises FileNotFoundError, LoadError, or ValueError for a tile size of 0."""
    @property
    def tile_size(self) -> Tuple[float, float]:
        """A tile's size (width, height)."""
    def __len__(self) -> int: ...
    def ids(self) -> list[int]:
        """The ids of the tiles, in increasing order."""
    def segments(
        self, id: int
    ) -> Tuple[npt.NDArray[np.float32], npt.NDArray[np.float32]]:
        """Tile `id`'s segments (N, 4) and outward normals (N, 2), tile-local. Raises
        KeyError for an id the set lacks."""

def trace(
    mask: npt.NDArray[np.bool_], tolerance: float = 1.0
) -> Tuple[npt.NDArray[np.float32], npt.NDArray[np.float32]]:
    """The outline of the solid pixels of `mask` (2-D bool, row 0 at the top), simplified
    to within `tolerance` pixels so staircases become slopes: segments (N, 4) rows
    ax, ay, bx, by in pixels (y down) and outward unit normals (N, 2)."""

def render(
    map: TileMap,
    path: Optional[_Path] = None,
    *,
    bodies: Optional[Bodies] = None,
    circles: Optional[npt.NDArray[np.float32]] = None,
    rays: Optional[npt.NDArray[np.float32]] = None,
    paths: Optional[Sequence[npt.NDArray[np.float32]]] = None,
    scale: float = 16.0,
    y_up: bool = False,
) -> bytes:
    """A PNG picture of `map` (solid material, segments with their normals) with, over it,
    `bodies`, `circles` ((N, 3) rows x, y, radius), `rays` ((N, 4), each drawn with what
    it hits) and `paths` ((N, 2) arrays of points). `scale` is pixels per cell; `y_up`
    draws row 0 at the bottom. Returns the PNG's bytes and writes them to `path` when
    given. Raises ValueError for a scale that is not positive or an image too large."""

class Contact:
    """One surface a character touched: a tile's (`cell` and `tile`) or a temporary
    segment's (`owner`, and its velocity)."""

    @property
    def nx(self) -> float:
        """The surface's unit normal at the contact, pointing towards the character, x."""
    @property
    def ny(self) -> float:
        """The normal, y."""
    @property
    def flags(self) -> int:
        """The segment's flags (1 solid, 2 one-way)."""
    @property
    def cell(self) -> Optional[Tuple[int, int]]:
        """The tile's cell `(col, row)`, or None for a temporary segment."""
    @property
    def tile(self) -> Optional[int]:
        """The tile's id, or None for a temporary segment."""
    @property
    def owner(self) -> Optional[int]:
        """The temporary segment's owner, or None for a tile."""
    @property
    def vx(self) -> float:
        """How fast the surface moves, x (a moving platform's velocity; 0 for a tile)."""
    @property
    def vy(self) -> float:
        """How fast the surface moves, y."""

class MoveResult:
    """What a move did: where the character is and the surfaces it touched, by kind."""

    @property
    def x(self) -> float:
        """The character's position after the move, x."""
    @property
    def y(self) -> float:
        """The character's position after the move, y."""
    @property
    def grounded(self) -> bool:
        """Whether it stands on walkable ground."""
    @property
    def ground(self) -> Optional[Contact]:
        """The walkable ground under it at the end of the move, or None in the air."""
    @property
    def ceiling(self) -> Optional[Contact]:
        """The last ceiling that stopped it, or None."""
    @property
    def left(self) -> Optional[Contact]:
        """The last wall met on its left (lower x), or None."""
    @property
    def right(self) -> Optional[Contact]:
        """The last wall met on its right (higher x), or None."""
    @property
    def crush(self) -> Optional[Contact]:
        """A moving platform that pressed it into the world (crushed), or None."""
    @property
    def vx(self) -> Optional[float]:
        """`move_and_slide`: the velocity the surfaces leave, to keep, x; None for
        `move_by`."""
    @property
    def vy(self) -> Optional[float]:
        """`move_and_slide`: the velocity to keep, y; None for `move_by`."""

class Character:
    """A platformer character: a box or a circle with an up direction, moved by the
    displacement the game wants each step (velocity × dt, gravity included). It walks
    slopes up to the slope limit, snaps to the ground, jumps up through one-way platforms
    and drops through them on request, rides moving platforms; gravity, jumps and coyote
    time are the game's rules. Every move is an exact sweep: no speed passes a wall."""

    def __init__(
        self,
        x: float,
        y: float,
        *,
        radius: Optional[float] = None,
        half_width: Optional[float] = None,
        half_height: Optional[float] = None,
        up: Tuple[float, float] = (0.0, -1.0),
        max_slope_degrees: float = 50.0,
        snap_distance: float = 0.3,
        skin: float = 0.001,
        max_slides: int = 4,
        step_height: float = 0.0,
        mask: int = 3,
    ) -> None:
        """A character centred at (x, y): a circle of `radius`, or a box of half extents
        `half_width` × `half_height`. `up` is normalised (default (0, -1): y-down maps, as
        ASCII and Tiled maps are). The controller: the steepest walkable slope in degrees
        [0, 90); how far below its feet a grounded character looks for ground to stay on;
        the gap kept from surfaces; how many times a move may slide on; the highest ledge a
        walk steps up onto; the segment flags that block it. Distances in map units, the
        defaults for cells of size 1. Raises ValueError naming the argument out of range,
        TypeError for a wrong type."""
    @property
    def x(self) -> float:
        """The x of the shape's centre."""
    @property
    def y(self) -> float:
        """The y of the shape's centre."""
    @property
    def up(self) -> Tuple[float, float]:
        """The unit up direction."""
    @property
    def radius(self) -> Optional[float]:
        """The circle's radius, or None for a box."""
    @property
    def half_extents(self) -> Optional[Tuple[float, float]]:
        """The box's half extents `(half_width, half_height)`, or None for a circle."""
    @property
    def ground(self) -> Optional[Contact]:
        """The ground under the character after its last move, or None in the air."""
    def teleport(self, x: float, y: float) -> None:
        """Moves the character to (x, y) at once (no sweep), forgetting its ground."""
    def move_by(
        self, map: TileMap, dx: float, dy: float, *, drop_through: bool = False
    ) -> MoveResult:
        """Moves the character by (dx, dy) through `map` and its temporary segments as far
        as they let it. `drop_through` falls through one-way platforms during this move
        (hold it until the platform is cleared). Raises ValueError for a displacement that
        is not finite or ends out of range (the character does not move)."""
    def move_and_slide(
        self,
        map: TileMap,
        vx: float,
        vy: float,
        dt: float,
        *,
        drop_through: bool = False,
    ) -> MoveResult:
        """Moves the character by velocity (vx, vy) × dt, as `move_by`, then takes out of
        the velocity what the surfaces it touched stopped (landing zeroes the fall, a
        ceiling the rise, a wall the speed into it): the result's `vx`, `vy`, to keep for
        the next step. Raises ValueError for a velocity that is not finite or a negative
        or infinite `dt`."""
    def clip_velocity(self, vx: float, vy: float) -> Tuple[float, float]:
        """The velocity (vx, vy) without what the surfaces the last move touched stop, as
        `move_and_slide` clips it: for a displacement made with `move_by`."""

class HitType:
    """Hit types: the bits a volume deals (attack) or accepts (vulnerability); combine them
    with `|`. Bits 6 and up are the game's own."""

    NONE: int
    """No type: a volume with it never hits and is never hit."""
    ANY: int
    """Every type (0xFFFFFFFF): matches everything."""
    HIT: int
    """Damage (1)."""
    DEATH: int
    """Kills outright (2)."""
    COLLECT: int
    """Picks up a coin or a gem (4)."""
    POSSESS: int
    """Takes control of a robot (8)."""
    DEPRESS: int
    """Presses a button (16)."""
    LAUNCH: int
    """Throws the victim: a spring, a cannon (32)."""

class Volume:
    """An attack or vulnerability volume in object-local coordinates, with the hit types it
    deals or accepts (bits of HitType, default HIT). Raises ValueError naming a value that
    is not finite, a negative size, a coordinate out of range or hit bits out of range."""

    @staticmethod
    def circle(x: float, y: float, radius: float, hit: int = 1) -> Volume:
        """A disc centred at (x, y) of `radius` (>= 0)."""
    @staticmethod
    def rect(x: float, y: float, half_width: float, half_height: float, hit: int = 1) -> Volume:
        """The rectangle centred at (x, y) with half extents `half_width` × `half_height`
        (>= 0)."""
    @staticmethod
    def capsule(
        x0: float, y0: float, x1: float, y1: float, radius: float, hit: int = 1
    ) -> Volume:
        """The points within `radius` (>= 0) of the segment from (x0, y0) to (x1, y1): a
        blade, a beam."""
    @property
    def hit(self) -> int:
        """The hit types it deals or accepts."""

class ObjectId:
    """An object's id for one frame: its place in the frame's registrations. Once the next
    frame begins it is stale: using it raises KeyError."""

    @property
    def index(self) -> int:
        """0, 1, 2, … in registration order."""
    @property
    def frame(self) -> int:
        """The frame it was registered in (how many frames had begun before)."""
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...

class HitEvent:
    """One hit: an attack volume of `attacker` met a vulnerability volume of `victim` that
    accepts its type."""

    @property
    def attacker(self) -> ObjectId:
        """Who hit, as registered in the frame `detect` ran in."""
    @property
    def victim(self) -> ObjectId:
        """Who was hit."""
    @property
    def attacker_owner(self) -> int:
        """The attacker's owner: the game's key for it, stable across frames."""
    @property
    def victim_owner(self) -> int:
        """The victim's owner."""
    @property
    def hit_type(self) -> int:
        """The types dealt: the attack's types that the vulnerability accepts."""
    @property
    def accepted(self) -> bool:
        """Whether the victim (the rule) took the hit."""
    @property
    def t(self) -> float:
        """When the volumes first touched, as a fraction of the frame's move in [0, 1]:
        0 when they overlap where the frame starts."""
    @property
    def x(self) -> float:
        """Where they touched then, x."""
    @property
    def y(self) -> float:
        """Where they touched then, y."""

class HitWorld:
    """Attack and vulnerability volumes of the objects of one frame, and the hits between
    them. Each frame: `begin_frame()`, `register` every object with the volumes of its
    current animation frame, then `detect()`. Hits are exact, swept along each object's
    move (a fast projectile cannot pass through a target), in a fixed order."""

    def __init__(self, broadphase: str = "sweep_and_prune") -> None:
        """An empty world; `broadphase` is "sweep_and_prune" or "uniform_grid" (the
        results are the same either way)."""
    @property
    def frame(self) -> int:
        """Frames begun so far: the ids registered now carry it."""
    def begin_frame(self) -> None:
        """Starts a frame: forgets the last frame's objects (their ids go stale) and ends
        the swings nobody registered in it."""
    def register(
        self,
        owner: int,
        x: float,
        y: float,
        width: float,
        height: float,
        *,
        attack: Sequence[Volume] = (),
        vulnerable: Sequence[Volume] = (),
        motion: Tuple[float, float] = (0.0, 0.0),
        flip_x: bool = False,
        flip_y: bool = False,
        aim: Optional[Tuple[float, float]] = None,
        team: int = 0,
        invulnerable: bool = False,
        swing: Optional[int] = None,
    ) -> ObjectId:
        """Registers an object of `owner` for this frame: its volumes' local origin at
        (x, y) at the end of the frame, its size (volumes are mirrored about its middle),
        its attack and vulnerability volumes. `motion` is how far it moved this frame (its
        volumes are swept along it); `flip_x`, `flip_y` mirror it; `aim` turns its attack
        volumes to point along a direction; `team` and `invulnerable` feed the default
        rule; `swing` names the attack it makes (each victim is hit at most once per swing,
        until a frame registers no object with it). Returns its id for this frame. Raises
        ValueError naming a bad value (nothing is registered), TypeError for a volume that
        is not a Volume."""
    def detect(
        self, rule: Optional[Callable[[ObjectId, ObjectId, int], bool]] = None
    ) -> list[HitEvent]:
        """Finds this frame's hits. Without `rule`, a victim takes hits from other teams
        while it is not invulnerable; with it, `rule(attacker, victim, hit_type)` decides,
        and an exception it raises is raised again after the detection."""
    def events(self) -> list[HitEvent]:
        """The last `detect`'s events, kept until the next `detect`."""
    def owner(self, id: ObjectId) -> int:
        """The owner of the object `id` of this frame. Raises KeyError for a stale id."""
    def bounding_circle(self, id: ObjectId) -> Optional[Tuple[float, float, float]]:
        """`(x, y, radius)`: a circle holding every volume of `id` at the end of the frame,
        or None for an object without volumes. Raises KeyError for a stale id."""
    def __contains__(self, id: ObjectId) -> bool: ...
    def __len__(self) -> int: ...

class NavPath:
    """A path found for a circle: its points from the start to the goal, each run between
    them clear of walls for the circle."""

    @property
    def points(self) -> npt.NDArray[np.float32]:
        """The points, start to goal, shape (N, 2)."""
    @property
    def length(self) -> float:
        """The path's length (map units)."""
    @property
    def radius(self) -> float:
        """The radius of the circle it is for."""
    def __len__(self) -> int: ...

class NavGrid:
    """Navigation data for one map: move clearances on a half-cell lattice, for circles of
    a radius up to `max_radius`."""

    def __init__(self, map: TileMap, *, max_radius: float = 1.0, mask: int = 3) -> None:
        """The navigation grid of `map` for circles up to `max_radius` (map units, at most
        31 cells); segments with one of the `mask` flags block (default solid and
        one-way: a one-way platform is crossed only from behind). Raises ValueError naming
        `max_radius` or `mask`, or for a map too large."""
    def sync(self) -> bool:
        """Catches up with the map's tile edits (`TileMap.set_tile`) since the grid was
        built or last synced; until then its queries raise ValueError. Returns whether the
        grid changed."""
    @property
    def max_radius(self) -> float:
        """The widest circle the grid serves."""
    @property
    def map(self) -> TileMap:
        """The map the grid was built for."""
    def find_path(
        self, x0: float, y0: float, x1: float, y1: float, radius: float
    ) -> Optional[NavPath]:
        """The shortest path for a circle of `radius` from (x0, y0) to (x1, y1), smoothed
        into straight runs each clear of walls (by the map's own circle cast); None when
        the circle does not fit at an end or cannot get from one to the other. Raises
        ValueError naming a coordinate that is not finite or out of range, or a radius
        that is not positive or above `max_radius`."""
    def fits(self, x: float, y: float, radius: float) -> bool:
        """Whether a circle of `radius` fits at (x, y), clear of walls."""

class FlowField:
    """Distances to one goal for circles of one radius over the whole map: every agent
    asks it which way to go."""

    def __init__(self, nav: NavGrid, x: float, y: float, radius: float) -> None:
        """The field of the goal (x, y) for circles of `radius` on `nav`'s map."""
    def sync(self) -> bool:
        """Catches up with the map's tile edits once the field's NavGrid has (sync that
        first, or this raises ValueError): recomputes the field when an edit changed a way
        it reaches. Returns whether it did."""
    @property
    def goal(self) -> Tuple[float, float]:
        """The goal."""
    @property
    def radius(self) -> float:
        """The radius of the circles it leads."""
    def direction(self, x: float, y: float) -> Optional[Tuple[float, float]]:
        """The unit direction a circle at (x, y) should move in to reach the goal, or None
        when it cannot reach it or is on it."""
    def directions(self, points: npt.NDArray[np.float32]) -> npt.NDArray[np.float32]:
        """`direction` at each row of `points` (shape (N, 2)): shape (N, 2), NaN where it
        is None. Raises ValueError naming the row that is not finite, TypeError for an
        array that is not float32 and 2-dimensional."""
    def lattice_direction(self, x: float, y: float) -> Optional[Tuple[float, float]]:
        """A cheap direction along the field's lattice moves, with no straight-line checks:
        for crowds of thousands that ask every step (a resolver such as Bodies slides them
        round corners). None when no node around the point reaches the goal, or on it."""
    def lattice_directions(self, points: npt.NDArray[np.float32]) -> npt.NDArray[np.float32]:
        """`lattice_direction` at each row of `points`, as `directions`."""
    def distance(self, x: float, y: float) -> Optional[float]:
        """The length of the way from (x, y) to the goal along the field (map units), or
        None if a circle there cannot reach it."""

class DebugKind(IntEnum):
    """What a debug shape shows (the numbers of the Rust core's DebugKind): a front end
    picks its colour and layer by it."""

    ACTIVE_SEGMENT = 0
    """An active solid segment of the map (a segment)."""
    ONE_WAY_SEGMENT = 1
    """An active one-way platform segment (a segment)."""
    NORMAL = 2
    """A segment's outward normal, from its middle (a segment)."""
    HIDDEN_SEGMENT = 3
    """A piece of a tile segment hidden by seam culling (a segment)."""
    TEMPORARY_SEGMENT = 4
    """A temporary segment: a moving platform, a door (a segment)."""
    BODY = 5
    """A body's circle (a circle)."""
    CHARACTER = 6
    """A character's shape (a circle or a box)."""
    CONTACT = 7
    """A surface a character touched, along its normal (a segment)."""
    RAY = 8
    """A ray (a segment)."""
    RAY_HIT = 9
    """Where a ray hit (a point)."""
    ATTACK_VOLUME = 10
    """An attack volume (a circle or a box)."""
    VULNERABILITY_VOLUME = 11
    """A vulnerability volume (a circle or a box)."""
    HIT = 12
    """An accepted hit event (a point)."""
    REFUSED_HIT = 13
    """A refused hit event (a point)."""
    PATH = 14
    """A leg of a navigation path (a segment)."""
    FLOW_ARROW = 15
    """A flow field's next move out of a node (a segment)."""
    BROADPHASE_BOX = 16
    """A box the broadphase files something under (a box)."""

class DebugLines:
    """A buffer of debug shapes (segments, circles, points, boxes), each with a kind: keep
    one, `clear()` it each frame, `add` what is to be drawn, and draw the arrays (a kind
    array beside each, `DebugKind(k)` naming its entries)."""

    def __init__(
        self,
        kinds: Optional[Sequence[int]] = None,
        view: Optional[Tuple[float, float, float, float]] = None,
    ) -> None:
        """An empty buffer taking the `kinds` given (DebugKinds or their numbers; every
        kind when None), only shapes touching `view` `(min_x, min_y, max_x, max_y)` when
        given. Raises ValueError naming a number no kind has or a bad view."""
    def add(
        self,
        what: Union[TileMap, Bodies, Character, HitWorld, NavPath, FlowField],
        owner: int = 0,
    ) -> None:
        """Adds what `what` looks like: a TileMap (active and hidden segments, normals,
        temporary segments), Bodies (their circles), a Character (its shape and what its
        last move touched, with `owner`), a HitWorld (this frame's volumes and the last
        `detect`'s hits), a NavPath (its legs, with `owner`) or a FlowField (its arrows).
        Raises TypeError for anything else."""
    def clear(self) -> None:
        """Empties the buffer (its kinds and view stay)."""
    @property
    def segments(self) -> npt.NDArray[np.float32]:
        """The segments, shape (N, 4), rows `x0, y0, x1, y1`."""
    @property
    def segment_kinds(self) -> npt.NDArray[np.uint8]:
        """Each segment's kind, shape (N,)."""
    @property
    def circles(self) -> npt.NDArray[np.float32]:
        """The circles, shape (N, 3), rows `x, y, radius`."""
    @property
    def circle_kinds(self) -> npt.NDArray[np.uint8]:
        """Each circle's kind."""
    @property
    def points(self) -> npt.NDArray[np.float32]:
        """The points, shape (N, 2), rows `x, y`."""
    @property
    def point_kinds(self) -> npt.NDArray[np.uint8]:
        """Each point's kind."""
    @property
    def boxes(self) -> npt.NDArray[np.float32]:
        """The boxes, shape (N, 4), rows `min_x, min_y, max_x, max_y`."""
    @property
    def box_kinds(self) -> npt.NDArray[np.uint8]:
        """Each box's kind."""
    def __len__(self) -> int: ...
