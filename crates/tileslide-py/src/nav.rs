//! `NavGrid`, `NavPath` and `FlowField`: paths for circles of a radius on a map, and flow
//! fields that lead many agents to one goal. Values are converted here; the searches are
//! the core's.

use numpy::{PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray2};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use tileslide::{NavConfig, NavError, SegmentFlags, Vec2};

use crate::bodies::pairs;
use crate::errors::{finite, finite_point, whole_or};
use crate::map::TileMap;

fn nav_error(e: &NavError) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// `points` (a flat list of pairs) as a `float32` array of shape `(N, 2)`.
fn array<'py>(py: Python<'py>, points: Vec<f32>) -> PyResult<Bound<'py, PyArray2<f32>>> {
    let n = points.len() / 2;
    PyArray1::from_vec(py, points).reshape([n, 2])
}

/// Navigation data for one map: move clearances on a half-cell lattice, for circles of a
/// radius up to `max_radius`.
#[pyclass(module = "tileslide", frozen)]
pub struct NavGrid {
    pub(crate) nav: tileslide::NavGrid,
    pub(crate) map: Py<TileMap>,
}

#[pymethods]
impl NavGrid {
    /// The navigation grid of `map` for circles up to `max_radius` (map units, at most 31
    /// cells); segments with one of the `mask` flags block (default solid and one-way).
    #[new]
    #[pyo3(signature = (map, *, max_radius = 1.0, mask = None))]
    fn new(
        map: Bound<'_, TileMap>,
        max_radius: f32,
        mask: Option<Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let d = NavConfig::default();
        let config = NavConfig {
            max_radius: finite("max_radius", max_radius)?,
            mask: SegmentFlags(
                whole_or("mask", mask.as_ref(), u32::MAX.into(), d.mask.0.into())? as u32,
            ),
        };
        let nav =
            tileslide::NavGrid::new(&map.try_borrow()?.map, config).map_err(|e| nav_error(&e))?;
        Ok(NavGrid {
            nav,
            map: map.unbind(),
        })
    }

    /// The widest circle the grid serves.
    #[getter]
    fn max_radius(&self) -> f32 {
        self.nav.max_radius()
    }

    /// The map the grid was built for.
    #[getter]
    fn map(&self, py: Python<'_>) -> Py<TileMap> {
        self.map.clone_ref(py)
    }

    /// The shortest path for a circle of `radius` from (`x0`, `y0`) to (`x1`, `y1`),
    /// smoothed into straight runs each clear of walls; None when the circle does not fit
    /// at an end or cannot get from one to the other.
    fn find_path(
        &self,
        py: Python<'_>,
        x0: f32,
        y0: f32,
        x1: f32,
        y1: f32,
        radius: f32,
    ) -> PyResult<Option<NavPath>> {
        let from = finite_point(["x0", "y0"], x0, y0)?;
        let to = finite_point(["x1", "y1"], x1, y1)?;
        let radius = finite("radius", radius)?;
        let map = self.map.try_borrow(py)?;
        let path = self
            .nav
            .find_path(&map.map, from, to, radius)
            .map_err(|e| nav_error(&e))?;
        Ok(path.map(|path| NavPath { path }))
    }

    /// Whether a circle of `radius` fits at (`x`, `y`), clear of walls.
    fn fits(&self, py: Python<'_>, x: f32, y: f32, radius: f32) -> PyResult<bool> {
        let p = finite_point(["x", "y"], x, y)?;
        let radius = finite("radius", radius)?;
        self.nav
            .fits(&self.map.try_borrow(py)?.map, p, radius)
            .map_err(|e| nav_error(&e))
    }

    fn __repr__(&self) -> String {
        let (nx, ny) = self.nav.nodes();
        format!(
            "NavGrid(max_radius={}, nodes={nx}x{ny})",
            self.nav.max_radius()
        )
    }
}

/// A path found for a circle: its points from the start to the goal, each run between
/// them clear of walls for the circle.
#[pyclass(module = "tileslide", frozen)]
pub struct NavPath {
    pub(crate) path: tileslide::NavPath,
}

#[pymethods]
impl NavPath {
    /// The points, start to goal, as a `float32` array of shape `(N, 2)`.
    #[getter]
    fn points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f32>>> {
        array(
            py,
            self.path.points().iter().flat_map(|p| [p.x, p.y]).collect(),
        )
    }

    /// The path's length (map units).
    #[getter]
    fn length(&self) -> f32 {
        self.path.length()
    }

    /// The radius of the circle it is for.
    #[getter]
    fn radius(&self) -> f32 {
        self.path.radius()
    }

    fn __len__(&self) -> usize {
        self.path.points().len()
    }

    fn __repr__(&self) -> String {
        format!(
            "NavPath(points={}, length={}, radius={})",
            self.path.points().len(),
            self.path.length(),
            self.path.radius()
        )
    }
}

/// Distances to one goal for circles of one radius over a whole map: every agent asks it
/// which way to go.
#[pyclass(module = "tileslide", frozen)]
pub struct FlowField {
    pub(crate) field: tileslide::FlowField,
    pub(crate) nav: Py<NavGrid>,
}

impl FlowField {
    /// `direction` at (`x`, `y`), as `(dx, dy)` or None.
    fn at_point(
        &self,
        py: Python<'_>,
        x: f32,
        y: f32,
        direction: impl Fn(
            &tileslide::NavGrid,
            &tileslide::TileMap,
            Vec2,
        ) -> Result<Option<Vec2>, NavError>,
    ) -> PyResult<Option<(f32, f32)>> {
        let p = finite_point(["x", "y"], x, y)?;
        let nav = self.nav.get();
        let d = direction(&nav.nav, &nav.map.try_borrow(py)?.map, p).map_err(|e| nav_error(&e))?;
        Ok(d.map(|d| (d.x, d.y)))
    }

    /// `direction` at each row of `points` (shape `(N, 2)`), as rows `dx, dy`, NaN for
    /// None; an error names the row.
    fn each_point<'py>(
        &self,
        py: Python<'py>,
        points: &PyReadonlyArray2<'py, f32>,
        direction: impl Fn(
            &tileslide::NavGrid,
            &tileslide::TileMap,
            Vec2,
        ) -> Result<Option<Vec2>, NavError>,
    ) -> PyResult<Bound<'py, PyArray2<f32>>> {
        let points = pairs(points, "points")?;
        let nav = self.nav.get();
        let map = nav.map.try_borrow(py)?;
        let mut out = Vec::with_capacity(points.len() * 2);
        for (k, p) in points.iter().enumerate() {
            if !p.is_finite() {
                return Err(PyValueError::new_err(format!(
                    "points[{k}] = ({}, {}) is not finite",
                    p.x, p.y
                )));
            }
            let d = direction(&nav.nav, &map.map, *p)
                .map_err(|e| PyValueError::new_err(format!("points[{k}]: {e}")))?
                .unwrap_or(Vec2::NAN);
            out.extend([d.x, d.y]);
        }
        array(py, out)
    }
}

#[pymethods]
impl FlowField {
    /// The field of the goal (`x`, `y`) for circles of `radius` on `nav`'s map.
    #[new]
    fn new(py: Python<'_>, nav: Bound<'_, NavGrid>, x: f32, y: f32, radius: f32) -> PyResult<Self> {
        let goal = finite_point(["x", "y"], x, y)?;
        let radius = finite("radius", radius)?;
        let grid = nav.get();
        let field =
            tileslide::FlowField::new(&grid.nav, &grid.map.try_borrow(py)?.map, goal, radius)
                .map_err(|e| nav_error(&e))?;
        Ok(FlowField {
            field,
            nav: nav.unbind(),
        })
    }

    /// The goal `(x, y)`.
    #[getter]
    fn goal(&self) -> (f32, f32) {
        let g = self.field.goal();
        (g.x, g.y)
    }

    /// The radius of the circles it leads.
    #[getter]
    fn radius(&self) -> f32 {
        self.field.radius()
    }

    /// The unit direction `(dx, dy)` a circle at (`x`, `y`) should move in to reach the
    /// goal, or None when it cannot reach it or is on it.
    fn direction(&self, py: Python<'_>, x: f32, y: f32) -> PyResult<Option<(f32, f32)>> {
        self.at_point(py, x, y, |nav, map, p| self.field.direction(nav, map, p))
    }

    /// `direction` at each row of `points` (`float32`, shape `(N, 2)`): shape `(N, 2)`,
    /// both NaN where it is None.
    fn directions<'py>(
        &self,
        py: Python<'py>,
        points: PyReadonlyArray2<'py, f32>,
    ) -> PyResult<Bound<'py, PyArray2<f32>>> {
        self.each_point(py, &points, |nav, map, p| self.field.direction(nav, map, p))
    }

    /// A cheap direction for a circle at (`x`, `y`), along the field's lattice moves with
    /// no straight-line checks: for crowds that ask every step (a resolver slides them
    /// round corners). None when no node around the point reaches the goal, or on it.
    fn lattice_direction(&self, py: Python<'_>, x: f32, y: f32) -> PyResult<Option<(f32, f32)>> {
        self.at_point(py, x, y, |nav, map, p| {
            self.field.lattice_direction(nav, map, p)
        })
    }

    /// `lattice_direction` at each row of `points`, as `directions`.
    fn lattice_directions<'py>(
        &self,
        py: Python<'py>,
        points: PyReadonlyArray2<'py, f32>,
    ) -> PyResult<Bound<'py, PyArray2<f32>>> {
        self.each_point(py, &points, |nav, map, p| {
            self.field.lattice_direction(nav, map, p)
        })
    }

    /// The length of the way from (`x`, `y`) to the goal along the field (map units), or
    /// None if a circle there cannot reach it.
    fn distance(&self, py: Python<'_>, x: f32, y: f32) -> PyResult<Option<f32>> {
        let p = finite_point(["x", "y"], x, y)?;
        let nav = self.nav.get();
        self.field
            .distance(&nav.nav, &nav.map.try_borrow(py)?.map, p)
            .map_err(|e| nav_error(&e))
    }

    fn __repr__(&self) -> String {
        let g = self.field.goal();
        format!(
            "FlowField(goal=({}, {}), radius={})",
            g.x,
            g.y,
            self.field.radius()
        )
    }
}
