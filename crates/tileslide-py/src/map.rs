//! `TileMap` and `RayHit`: a collision map loaded from a file or ASCII text, and its ray
//! casts, one at a time or a NumPy batch.

use std::path::PathBuf;
use std::sync::Arc;

use numpy::{PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::exceptions::{PyIndexError, PyValueError};
use pyo3::prelude::*;
use tileslide::io::ascii;
use tileslide::{
    Cell, Faces, Owner, QueryFilter, Ray, Segment, SegmentFlags, TemporarySegment, TileId, Vec2,
};

use crate::errors::{finite, finite_point, load_error, whole_or};
use crate::trace::{TileSet, map_from_tiles};

/// Rays cast a chunk at a time, so the batch's own buffers stay small whatever its size.
const CHUNK: usize = 4096;

/// A collision map: tiles on a grid, each a set of solid segments with seams culled, and
/// the temporary segments (moving platforms, doors) submitted until cleared.
#[pyclass(module = "tileslide")]
pub struct TileMap {
    pub(crate) map: tileslide::TileMap,
}

/// The first face a ray hit.
#[pyclass(module = "tileslide", frozen, get_all)]
#[derive(Clone, Debug)]
pub struct RayHit {
    /// Fraction of the way from the start to the end, in [0, 1].
    t: f32,
    /// The point hit.
    x: f32,
    y: f32,
    /// The face's outward unit normal.
    nx: f32,
    ny: f32,
    /// The tile's cell `(col, row)`, or None for a face that is not a tile's.
    cell: Option<(u32, u32)>,
    /// The tile's id, or None.
    tile: Option<u32>,
}

#[pymethods]
impl RayHit {
    fn __repr__(&self) -> String {
        let cell = self
            .cell
            .map_or_else(|| "None".to_owned(), |(c, r)| format!("({c}, {r})"));
        let tile = self
            .tile
            .map_or_else(|| "None".to_owned(), |t| t.to_string());
        format!(
            "RayHit(t={}, x={}, y={}, nx={}, ny={}, cell={cell}, tile={tile})",
            self.t, self.x, self.y, self.nx, self.ny
        )
    }
}

fn filter(both_sides: bool) -> QueryFilter {
    let mut filter = QueryFilter::default();
    if both_sides {
        filter.faces = Faces::Both;
    }
    filter
}

fn hit_of(hit: &tileslide::RayHit) -> RayHit {
    RayHit {
        t: hit.t,
        x: hit.point.x,
        y: hit.point.y,
        nx: hit.normal.x,
        ny: hit.normal.y,
        cell: hit.cell().map(|c| (c.col, c.row)),
        tile: hit.tile().map(|t| t.0),
    }
}

impl TileMap {
    fn check_cell(&self, col: u32, row: u32) -> PyResult<()> {
        if col < self.map.width() && row < self.map.height() {
            Ok(())
        } else {
            Err(PyIndexError::new_err(format!(
                "cell ({col}, {row}) is outside the {} × {} map",
                self.map.width(),
                self.map.height()
            )))
        }
    }
}

#[pymethods]
impl TileMap {
    /// Loads the map at `path`, its format told by its extension (`.txt` ASCII, `.tmx`,
    /// `.tmj`, `.json` Tiled, `.ldtk` LDtk, `.tsm` baked, `.bin` Replica Island with
    /// `tileset`, its `collision.bin`).
    #[staticmethod]
    #[pyo3(signature = (path, tileset = None))]
    fn from_file(py: Python<'_>, path: PathBuf, tileset: Option<PathBuf>) -> PyResult<Self> {
        let map =
            tileslide::io::load_file(&path, tileset.as_deref()).map_err(|e| load_error(py, &e))?;
        Ok(TileMap { map })
    }

    /// Builds a map from ASCII text (`#` solid, `.` empty, `/` `\` ramps, `=` one-way; rows
    /// top to bottom) with square cells of side `cell`.
    #[staticmethod]
    #[pyo3(signature = (text, cell = 1.0))]
    fn from_ascii(py: Python<'_>, text: &str, cell: f32) -> PyResult<Self> {
        if !(cell.is_finite() && cell > 0.0) {
            return Err(PyValueError::new_err(format!(
                "cell is {cell}: it must be a finite positive number"
            )));
        }
        let map = ascii::parse(text, "<ascii>", cell).map_err(|e| load_error(py, &e))?;
        Ok(TileMap { map })
    }

    /// Saves the map as a baked map (`.tsm`): the segments seam-culled once, loaded back
    /// without a tile set by `TileMap.from_file`.
    fn save(&self, path: PathBuf) -> PyResult<()> {
        // An OSError subclass by the error's kind: FileNotFoundError for a missing folder.
        tileslide::io::baked::save(&self.map, &path).map_err(|e| {
            PyErr::from(std::io::Error::new(
                e.kind(),
                format!("{}: {e}", path.display()),
            ))
        })
    }

    /// A map laid out from `tiles` (a 2-D integer array, row 0 at the top: the id of each
    /// cell's tile in `tileset`, negative for an empty cell), its corner at `origin`.
    #[staticmethod]
    #[pyo3(signature = (tiles, tileset, origin = (0.0, 0.0)))]
    fn from_tiles(
        tiles: PyReadonlyArray2<'_, i64>,
        tileset: &TileSet,
        origin: (f32, f32),
    ) -> PyResult<Self> {
        map_from_tiles(&tiles, tileset, origin)
    }

    /// The map's tile set (for ASCII maps, the ids of `tileslide::io::ascii`).
    #[getter]
    fn tileset(&self) -> TileSet {
        TileSet {
            set: Arc::clone(self.map.tile_set()),
        }
    }

    /// The id of the tile in cell (`col`, `row`), or None for an empty cell. Raises
    /// IndexError for a cell outside the map.
    fn tile(&self, col: u32, row: u32) -> PyResult<Option<u32>> {
        self.check_cell(col, row)?;
        Ok(self.map.tile(Cell::new(col, row)).map(|t| t.0))
    }

    /// Puts tile `id` of the map's tile set in cell (`col`, `row`), or empties it (None):
    /// only the segments around the cell change, and bodies and characters stepped on the
    /// map next see the new wall. Raises IndexError for a cell outside the map, ValueError
    /// for an id the tile set lacks.
    fn set_tile(&mut self, col: u32, row: u32, id: Option<u32>) -> PyResult<()> {
        self.check_cell(col, row)?;
        self.map
            .set_tile(Cell::new(col, row), id.map(TileId))
            .map_err(|e| PyValueError::new_err(e.to_string()))
    }

    /// The map's width in cells.
    #[getter]
    fn width(&self) -> u32 {
        self.map.width()
    }

    /// The map's height in cells.
    #[getter]
    fn height(&self) -> u32 {
        self.map.height()
    }

    /// A cell's size `(width, height)`.
    #[getter]
    fn cell_size(&self) -> (f32, f32) {
        let c = self.map.cell_size();
        (c.x, c.y)
    }

    /// The first face the ray from (`x0`, `y0`) to (`x1`, `y1`) hits, or None. By default
    /// only faces the ray meets head-on count; `both_sides` counts back faces too.
    #[pyo3(signature = (x0, y0, x1, y1, both_sides = false))]
    fn cast_ray(
        &self,
        x0: f32,
        y0: f32,
        x1: f32,
        y1: f32,
        both_sides: bool,
    ) -> PyResult<Option<RayHit>> {
        let start = Vec2::new(finite("x0", x0)?, finite("y0", y0)?);
        let end = Vec2::new(finite("x1", x1)?, finite("y1", y1)?);
        let ray = Ray::between(start, end);
        if !ray.is_finite() {
            return Err(PyValueError::new_err(format!(
                "the ray ({x0}, {y0}) to ({x1}, {y1}) is too long to cast"
            )));
        }
        Ok(self
            .map
            .cast_ray(ray, &filter(both_sides))
            .map(|h| hit_of(&h)))
    }

    /// Casts a batch of rays: `rays` is a `float32` array of shape `(N, 4)`, each row
    /// `x0, y0, x1, y1`. Returns a `float32` array of shape `(N, 5)`, each row
    /// `t, x, y, nx, ny` of the ray's first hit, every value NaN for a miss.
    #[pyo3(signature = (rays, both_sides = false))]
    fn cast_rays<'py>(
        &self,
        py: Python<'py>,
        rays: PyReadonlyArray2<'py, f32>,
        both_sides: bool,
    ) -> PyResult<Bound<'py, PyArray2<f32>>> {
        let shape = rays.shape();
        if shape[1] != 4 {
            return Err(PyValueError::new_err(format!(
                "rays has shape ({}, {}): it must be (N, 4), rows x0, y0, x1, y1",
                shape[0], shape[1]
            )));
        }
        let n = shape[0];
        // A C-contiguous array is read in place; any other layout is copied once.
        let copied;
        // (`as_slice` also takes a Fortran-ordered array, whose memory is column by column.)
        let input: &[f32] = if let (true, Ok(slice)) = (rays.is_c_contiguous(), rays.as_slice()) {
            slice
        } else {
            copied = rays.as_array().iter().copied().collect::<Vec<f32>>();
            &copied
        };
        // Every ray checked before any is cast: coordinates that are not finite, or ends so
        // far apart that the ray's length overflows (which would cast as a silent miss).
        let bad = input
            .chunks_exact(4)
            .position(|r| !Ray::between(Vec2::new(r[0], r[1]), Vec2::new(r[2], r[3])).is_finite());
        if let Some(k) = bad {
            let r = &input[k * 4..k * 4 + 4];
            let why = if r.iter().all(|v| v.is_finite()) {
                "is too long to cast"
            } else {
                "is not finite"
            };
            return Err(PyValueError::new_err(format!(
                "rays[{k}] = ({}, {}, {}, {}) {why}",
                r[0], r[1], r[2], r[3]
            )));
        }
        let filter = filter(both_sides);
        let mut out = vec![f32::NAN; n * 5];
        let mut batch = Vec::with_capacity(CHUNK.min(n));
        let mut hits = Vec::with_capacity(CHUNK.min(n));
        for (coords, rows) in input.chunks(CHUNK * 4).zip(out.chunks_mut(CHUNK * 5)) {
            batch.clear();
            batch.extend(
                coords
                    .chunks_exact(4)
                    .map(|r| Ray::between(Vec2::new(r[0], r[1]), Vec2::new(r[2], r[3]))),
            );
            self.map.cast_rays_into(&batch, &filter, &mut hits);
            for (row, hit) in rows.chunks_exact_mut(5).zip(&hits) {
                if let Some(h) = hit {
                    row.copy_from_slice(&[h.t, h.point.x, h.point.y, h.normal.x, h.normal.y]);
                }
            }
        }
        PyArray1::from_vec(py, out).reshape([n, 5])
    }

    /// Adds a temporary segment from (`x0`, `y0`) to (`x1`, `y1`) facing (`nx`, `ny`)
    /// (normalised): a door or a moving platform, which every query, body and character
    /// meets until it is cleared. `flags` 1 solid, 2 one-way; `owner` who submitted it
    /// (`clear_temporaries(owner)` clears its segments); (`vx`, `vy`) how fast it moves (a
    /// character standing on it rides it).
    #[pyo3(signature = (x0, y0, x1, y1, nx, ny, *, flags = None, owner = None, vx = 0.0, vy = 0.0))]
    #[allow(clippy::too_many_arguments)]
    fn add_temporary(
        &mut self,
        x0: f32,
        y0: f32,
        x1: f32,
        y1: f32,
        nx: f32,
        ny: f32,
        flags: Option<Bound<'_, PyAny>>,
        owner: Option<Bound<'_, PyAny>>,
        vx: f32,
        vy: f32,
    ) -> PyResult<()> {
        let a = finite_point(["x0", "y0"], x0, y0)?;
        let b = finite_point(["x1", "y1"], x1, y1)?;
        let normal = finite_point(["nx", "ny"], nx, ny)?;
        let velocity = finite_point(["vx", "vy"], vx, vy)?;
        let flags = whole_or("flags", flags.as_ref(), u32::MAX.into(), 1)? as u32;
        let owner = whole_or("owner", owner.as_ref(), u64::MAX, 0)?;
        self.map
            .add_temporary(TemporarySegment {
                segment: Segment::new(a, b),
                normal,
                flags: SegmentFlags(flags),
                owner: Owner(owner),
                velocity,
            })
            .map_err(|e| PyValueError::new_err(e.to_string()))
    }

    /// Removes the temporary segments of `owner`, or every one when None.
    #[pyo3(signature = (owner = None))]
    fn clear_temporaries(&mut self, owner: Option<Bound<'_, PyAny>>) -> PyResult<()> {
        match owner {
            None => self.map.clear_temporaries(),
            Some(o) => {
                self.map
                    .clear_temporaries_of(Owner(whole_or("owner", Some(&o), u64::MAX, 0)?))
            }
        }
        Ok(())
    }

    /// How many temporary segments the map holds.
    #[getter]
    fn temporary_count(&self) -> usize {
        self.map.temporaries().len()
    }

    fn __repr__(&self) -> String {
        let c = self.map.cell_size();
        format!(
            "TileMap(width={}, height={}, cell_size=({}, {}))",
            self.map.width(),
            self.map.height(),
            c.x,
            c.y
        )
    }
}
