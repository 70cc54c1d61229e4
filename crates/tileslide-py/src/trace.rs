//! Tile shapes traced from images, as pymunk's `autogeometry` traces bitmaps: `trace` turns
//! a mask into segments; `TileSet.from_image` cuts a PNG tile sheet into traced tiles;
//! `TileMap.from_tiles` lays a tile set out on a grid.

use std::path::PathBuf;
use std::sync::Arc;

use numpy::{PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::exceptions::{PyKeyError, PyValueError};
use pyo3::prelude::*;
use tileslide::io::bitmap::{BitmapOptions, load_tile_set};
use tileslide::limits::MAX_CELLS;
use tileslide::{TileId, TileShape, Vec2};

use crate::errors::load_error;
use crate::map::TileMap;

/// Tile shapes by id, all of one tile size.
#[pyclass(module = "tileslide", frozen)]
pub struct TileSet {
    pub(crate) set: Arc<tileslide::TileSet>,
}

/// Segments `(N, 4)` and their normals `(N, 2)`.
type Segments<'py> = (Bound<'py, PyArray2<f32>>, Bound<'py, PyArray2<f32>>);

/// A shape's segments as `(N, 4)` rows `ax, ay, bx, by` and its normals as `(N, 2)`.
fn segment_arrays<'py>(py: Python<'py>, shape: &TileShape) -> PyResult<Segments<'py>> {
    let segments = shape.segments();
    let ends: Vec<f32> = segments
        .iter()
        .flat_map(|s| [s.a.x, s.a.y, s.b.x, s.b.y])
        .collect();
    let normals: Vec<f32> = segments
        .iter()
        .flat_map(|s| [s.normal.x, s.normal.y])
        .collect();
    Ok((
        PyArray1::from_vec(py, ends).reshape([segments.len(), 4])?,
        PyArray1::from_vec(py, normals).reshape([segments.len(), 2])?,
    ))
}

/// The outline of the solid pixels of `mask` (a 2-D boolean array, row 0 at the top),
/// simplified to within `tolerance` pixels so staircases become slopes: `(segments,
/// normals)`, `(N, 4)` rows `ax, ay, bx, by` in pixels (y down) and `(N, 2)` outward unit
/// normals, solid on the segment's right.
#[pyfunction]
#[pyo3(signature = (mask, tolerance = 1.0))]
pub fn trace<'py>(
    py: Python<'py>,
    mask: PyReadonlyArray2<'py, bool>,
    tolerance: f32,
) -> PyResult<Segments<'py>> {
    let shape = mask.shape();
    let (Ok(height), Ok(width)) = (u32::try_from(shape[0]), u32::try_from(shape[1])) else {
        return Err(PyValueError::new_err(format!(
            "mask has shape ({}, {}): too large",
            shape[0], shape[1]
        )));
    };
    let pixels: Vec<bool> = mask.as_array().iter().copied().collect();
    let traced = TileShape::trace(&pixels, width, height, tolerance)
        .map_err(|e| PyValueError::new_err(format!("mask: {e}")))?;
    segment_arrays(py, &traced)
}

#[pymethods]
impl TileSet {
    /// Cuts the PNG tile sheet at `path` into `tile_width × tile_height` pixel tiles, row
    /// by row (tile k gets id k), each traced: a pixel is solid when its alpha is at least
    /// `threshold` (or, in an image without transparency, when it is darker than
    /// `threshold`); outlines are simplified to within `tolerance` pixels.
    #[staticmethod]
    #[pyo3(signature = (path, tile_width, tile_height, threshold = 128, tolerance = 1.0))]
    fn from_image(
        py: Python<'_>,
        path: PathBuf,
        tile_width: u32,
        tile_height: u32,
        threshold: u8,
        tolerance: f32,
    ) -> PyResult<Self> {
        let options = BitmapOptions {
            threshold,
            tolerance,
            ..BitmapOptions::new(tile_width, tile_height)
        };
        let set = load_tile_set(&path, &options).map_err(|e| load_error(py, &e))?;
        Ok(TileSet { set: Arc::new(set) })
    }

    /// A tile's size `(width, height)`.
    #[getter]
    fn tile_size(&self) -> (f32, f32) {
        let s = self.set.tile_size();
        (s.x, s.y)
    }

    fn __len__(&self) -> usize {
        self.set.len()
    }

    /// The ids of the tiles, in increasing order.
    fn ids(&self) -> Vec<u32> {
        self.set.iter().map(|(id, _)| id.0).collect()
    }

    /// Tile `id`'s segments and normals, as `trace` returns them (tile-local coordinates).
    /// Raises KeyError for an id the set lacks.
    fn segments<'py>(&self, py: Python<'py>, id: u32) -> PyResult<Segments<'py>> {
        let shape = self
            .set
            .shape(TileId(id))
            .ok_or_else(|| PyKeyError::new_err(format!("tile {id} is not in the tile set")))?;
        segment_arrays(py, shape)
    }

    fn __repr__(&self) -> String {
        let s = self.set.tile_size();
        format!(
            "TileSet(len={}, tile_size=({}, {}))",
            self.set.len(),
            s.x,
            s.y
        )
    }
}

/// `TileMap.from_tiles`: `tiles` (2-D integers, row 0 at the top; negative for an empty
/// cell) laid out with `tileset`'s shapes, the map's corner at `origin`.
pub(crate) fn map_from_tiles(
    tiles: &PyReadonlyArray2<'_, i64>,
    tileset: &TileSet,
    origin: (f32, f32),
) -> PyResult<TileMap> {
    let shape = tiles.shape();
    let (Ok(height), Ok(width)) = (u32::try_from(shape[0]), u32::try_from(shape[1])) else {
        return Err(PyValueError::new_err(format!(
            "tiles has shape ({}, {}): too large",
            shape[0], shape[1]
        )));
    };
    // Refused before the cells are copied, as the core refuses such a map.
    if u64::from(width) * u64::from(height) > MAX_CELLS {
        return Err(PyValueError::new_err(format!(
            "tiles has shape ({height}, {width}): a map has at most {MAX_CELLS} cells"
        )));
    }
    let view = tiles.as_array();
    let mut cells = Vec::with_capacity(view.len());
    for ((row, col), &id) in view.indexed_iter() {
        if id < 0 {
            cells.push(None);
            continue;
        }
        let known = u32::try_from(id)
            .ok()
            .filter(|id| tileset.set.shape(TileId(*id)).is_some());
        let Some(id) = known else {
            return Err(PyValueError::new_err(format!(
                "tiles[{row}, {col}] is {id}: the tile set has no such tile (use a negative \
                 number for an empty cell)"
            )));
        };
        cells.push(Some(TileId(id)));
    }
    let origin = Vec2::new(origin.0, origin.1);
    let map =
        tileslide::TileMap::from_tiles(Arc::clone(&tileset.set), width, height, origin, &cells)
            .map_err(|e| PyValueError::new_err(e.to_string()))?;
    Ok(TileMap { map })
}
