//! `NavGrid`, `NavPath` and `FlowField`: paths for circles of a radius on a map, and flow
//! fields that lead many agents to one goal. Values are converted here; the searches are
//! the core's.

use std::sync::{Mutex, MutexGuard};

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
    /// Behind a lock so that `sync` can catch it up with the map's edits.
    pub(crate) nav: Mutex<tileslide::NavGrid>,
    pub(crate) map: Py<TileMap>,
}

impl NavGrid {
    /// The grid. (Calls hold the GIL, so the lock is never contended; a panic while it was
    /// held leaves the grid as whole as the core left it.)
    pub(crate) fn grid(&self) -> MutexGuard<'_, tileslide::NavGrid> {
        self.nav
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
    }
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
            nav: Mutex::new(nav),
            map: map.unbind(),
        })
    }

    /// The widest circle the grid serves.
    #[getter]
    fn max_radius(&self) -> f32 {
        self.grid().max_radius()
    }

    /// Catches up with the map's tile edits (`TileMap.set_tile`) since the grid was built
    /// or last synced; until then its queries raise ValueError. Each edited cell costs the
    /// same on any map. Returns whether the grid changed.
    fn sync(&self, py: Python<'_>) -> PyResult<bool> {
        let map = self.map.try_borrow(py)?;
        let change = self.grid().sync(&map.map).map_err(|e| nav_error(&e))?;
        Ok(!change.is_empty())
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
            .grid()
            .find_path(&map.map, from, to, radius)
            .map_err(|e| nav_error(&e))?;
        Ok(path.map(|path| NavPath { path }))
    }

    /// Whether a circle of `radius` fits at (`x`, `y`), clear of walls.
    fn fits(&self, py: Python<'_>, x: f32, y: f32, radius: f32) -> PyResult<bool> {
        let p = finite_point(["x", "y"], x, y)?;
        let radius = finite("radius", radius)?;
        self.grid()
            .fits(&self.map.try_borrow(py)?.map, p, radius)
            .map_err(|e| nav_error(&e))
    }

    fn __repr__(&self) -> String {
        let (nx, ny) = self.grid().nodes();
        format!(
            "NavGrid(max_radius={}, nodes={nx}x{ny})",
            self.grid().max_radius()
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
    /// Behind a lock so that `sync` can catch it up with the map's edits.
    pub(crate) field: Mutex<tileslide::FlowField>,
    pub(crate) nav: Py<NavGrid>,
}

impl FlowField {
    /// The field (the lock as `NavGrid::grid`'s).
    pub(crate) fn flow(&self) -> MutexGuard<'_, tileslide::FlowField> {
        self.field
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
    }

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
        let d =
            direction(&nav.grid(), &nav.map.try_borrow(py)?.map, p).map_err(|e| nav_error(&e))?;
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
        let grid = nav.grid();
        let mut out = Vec::with_capacity(points.len() * 2);
        for (k, p) in points.iter().enumerate() {
            if !p.is_finite() {
                return Err(PyValueError::new_err(format!(
                    "points[{k}] = ({}, {}) is not finite",
                    p.x, p.y
                )));
            }
            let d = direction(&grid, &map.map, *p)
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
            tileslide::FlowField::new(&grid.grid(), &grid.map.try_borrow(py)?.map, goal, radius)
                .map_err(|e| nav_error(&e))?;
        Ok(FlowField {
            field: Mutex::new(field),
            nav: nav.unbind(),
        })
    }

    /// Catches up with the map's tile edits, once the field's `NavGrid` has (`sync` it
    /// first): recomputes the field when an edit changed a way it reaches. Returns whether
    /// it did (directions and distances may then differ).
    fn sync(&self, py: Python<'_>) -> PyResult<bool> {
        let nav = self.nav.get();
        let map = nav.map.try_borrow(py)?;
        let grid = nav.grid();
        self.flow().sync(&grid, &map.map).map_err(|e| nav_error(&e))
    }

    /// The goal `(x, y)`.
    #[getter]
    fn goal(&self) -> (f32, f32) {
        let g = self.flow().goal();
        (g.x, g.y)
    }

    /// The radius of the circles it leads.
    #[getter]
    fn radius(&self) -> f32 {
        self.flow().radius()
    }

    /// The unit direction `(dx, dy)` a circle at (`x`, `y`) should move in to reach the
    /// goal, or None when it cannot reach it or is on it.
    fn direction(&self, py: Python<'_>, x: f32, y: f32) -> PyResult<Option<(f32, f32)>> {
        self.at_point(py, x, y, |nav, map, p| self.flow().direction(nav, map, p))
    }

    /// `direction` at each row of `points` (`float32`, shape `(N, 2)`): shape `(N, 2)`,
    /// both NaN where it is None.
    fn directions<'py>(
        &self,
        py: Python<'py>,
        points: PyReadonlyArray2<'py, f32>,
    ) -> PyResult<Bound<'py, PyArray2<f32>>> {
        self.each_point(py, &points, |nav, map, p| {
            self.flow().direction(nav, map, p)
        })
    }

    /// A cheap direction for a circle at (`x`, `y`), along the field's lattice moves with
    /// no straight-line checks: for crowds that ask every step (a resolver slides them
    /// round corners). None when no node around the point reaches the goal, or on it.
    fn lattice_direction(&self, py: Python<'_>, x: f32, y: f32) -> PyResult<Option<(f32, f32)>> {
        self.at_point(py, x, y, |nav, map, p| {
            self.flow().lattice_direction(nav, map, p)
        })
    }

    /// `lattice_direction` at each row of `points`, as `directions`.
    fn lattice_directions<'py>(
        &self,
        py: Python<'py>,
        points: PyReadonlyArray2<'py, f32>,
    ) -> PyResult<Bound<'py, PyArray2<f32>>> {
        self.each_point(py, &points, |nav, map, p| {
            self.flow().lattice_direction(nav, map, p)
        })
    }

    /// The length of the way from (`x`, `y`) to the goal along the field (map units), or
    /// None if a circle there cannot reach it.
    fn distance(&self, py: Python<'_>, x: f32, y: f32) -> PyResult<Option<f32>> {
        let p = finite_point(["x", "y"], x, y)?;
        let nav = self.nav.get();
        self.flow()
            .distance(&nav.grid(), &nav.map.try_borrow(py)?.map, p)
            .map_err(|e| nav_error(&e))
    }

    fn __repr__(&self) -> String {
        let g = self.flow().goal();
        format!(
            "FlowField(goal=({}, {}), radius={})",
            g.x,
            g.y,
            self.flow().radius()
        )
    }
}
