"""tileslide: collision detection and response for tile-based 2D games.

Maps load from ASCII text, Tiled (.tmx, .tmj), LDtk (.ldtk), baked (.tsm) and Replica
Island (.bin) files; rays are cast one at a time or as a NumPy batch; bodies (circles and
compounds of circles) slide round each other and along walls without overlap or tunnelling.
Coordinates are map units, y down; every number is a 32-bit float, as in the Rust core, so
answers are bit-identical to it.
"""

from os import PathLike
from typing import Optional, Sequence, Tuple, Union

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
        ValueError for a wrong shape or a coordinate that is not finite (naming the row),
        TypeError for an array that is not float32 and 2-dimensional."""

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
        """Proposes `moves[k]` (shape (N, 2)) for `ids[k]`. Every entry is checked first:
        a stale id (KeyError) or a move that is not finite (ValueError) names its entry and
        proposes nothing."""
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
