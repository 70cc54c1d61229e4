//! `DebugLines` and `DebugKind`: what maps, bodies, characters, hit worlds, paths and flow
//! fields look like, as the core draws them (kinded segments, circles, points and boxes),
//! in NumPy arrays ready for pygame. The shapes are the core's; only the arrays are made
//! here.

use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use tileslide::debug::DebugKinds;
use tileslide::{Aabb, DebugKind, Owner, Vec2};

use crate::bodies::Bodies;
use crate::character::Character;
use crate::errors::whole;
use crate::map::TileMap;
use crate::nav::{FlowField, NavPath};
use crate::volumes::HitWorld;

/// The IntEnum `DebugKind`: the core's kinds by their numbers, named in upper snake case.
pub(crate) fn kind_enum(py: Python<'_>) -> PyResult<Bound<'_, PyAny>> {
    let members: Vec<(String, u8)> = DebugKind::ALL
        .iter()
        .map(|&k| (k.name().to_uppercase(), k as u8))
        .collect();
    let kwargs = PyDict::new(py);
    kwargs.set_item("module", "tileslide")?;
    let kind = py
        .import("enum")?
        .getattr("IntEnum")?
        .call(("DebugKind", members), Some(&kwargs))?;
    kind.setattr(
        "__doc__",
        "What a debug shape shows (the numbers of the Rust core's DebugKind): a front end \
         picks its colour and layer by it.",
    )?;
    Ok(kind)
}

/// `N` floats a row, as a `float32` array of shape `(N, width)`.
fn rows<'py, T, const W: usize>(
    py: Python<'py>,
    items: &[T],
    row: impl Fn(&T) -> [f32; W],
) -> PyResult<Bound<'py, PyArray2<f32>>> {
    let flat: Vec<f32> = items.iter().flat_map(row).collect();
    PyArray1::from_vec(py, flat).reshape([items.len(), W])
}

/// Each item's kind, as a `uint8` array.
fn kinds<'py, T>(
    py: Python<'py>,
    items: &[T],
    kind: impl Fn(&T) -> DebugKind,
) -> Bound<'py, PyArray1<u8>> {
    PyArray1::from_vec(py, items.iter().map(|i| kind(i) as u8).collect())
}

/// A buffer of debug shapes, each with a kind: keep one, `clear()` it each frame, `add`
/// what is to be drawn, and draw the arrays.
#[pyclass(module = "tileslide")]
pub struct DebugLines {
    lines: tileslide::DebugLines,
}

#[pymethods]
impl DebugLines {
    /// An empty buffer taking the `kinds` given (`DebugKind`s or their numbers; every
    /// kind when None), only shapes touching `view` `(min_x, min_y, max_x, max_y)` when
    /// given.
    #[new]
    #[pyo3(signature = (kinds = None, view = None))]
    fn new(
        kinds: Option<Vec<Bound<'_, PyAny>>>,
        view: Option<(f32, f32, f32, f32)>,
    ) -> PyResult<Self> {
        let mut lines = tileslide::DebugLines::new();
        if let Some(kinds) = kinds {
            let mut set = DebugKinds::NONE;
            for (k, kind) in kinds.iter().enumerate() {
                let n = whole(&format!("kinds[{k}]"), kind, u64::from(u8::MAX))?;
                let kind = DebugKind::from_u8(n as u8).ok_or_else(|| {
                    PyValueError::new_err(format!("kinds[{k}] is {n}: no DebugKind has it"))
                })?;
                set = set.with(kind);
            }
            lines.set_kinds(set);
        }
        if let Some((x0, y0, x1, y1)) = view {
            let ok = [x0, y0, x1, y1].iter().all(|v| v.is_finite()) && x0 <= x1 && y0 <= y1;
            if !ok {
                return Err(PyValueError::new_err(format!(
                    "view is ({x0}, {y0}, {x1}, {y1}): it must be finite (min_x, min_y, \
                     max_x, max_y) with min <= max"
                )));
            }
            lines.set_view(Some(Aabb::from_corners(
                Vec2::new(x0, y0),
                Vec2::new(x1, y1),
            )));
        }
        Ok(DebugLines { lines })
    }

    /// Adds what `what` looks like: a `TileMap` (its active and hidden segments, normals,
    /// temporary segments), `Bodies` (their circles), a `Character` (its shape and what
    /// its last move touched, with `owner`), a `HitWorld` (this frame's volumes and the
    /// last `detect`'s hits), a `NavPath` (its legs, with `owner`) or a `FlowField` (its
    /// arrows).
    #[pyo3(signature = (what, owner = None))]
    fn add(&mut self, what: &Bound<'_, PyAny>, owner: Option<Bound<'_, PyAny>>) -> PyResult<()> {
        let owner = Owner(match owner {
            None => 0,
            Some(o) => whole("owner", &o, u64::MAX)?,
        });
        let out = &mut self.lines;
        if let Ok(map) = what.cast::<TileMap>() {
            map.try_borrow()?.map.debug_lines(out);
        } else if let Ok(bodies) = what.cast::<Bodies>() {
            bodies.try_borrow()?.bodies.debug_lines(out);
        } else if let Ok(character) = what.cast::<Character>() {
            let c = character.try_borrow()?;
            c.character.debug_lines(Some(&c.last), owner, out);
        } else if let Ok(world) = what.cast::<HitWorld>() {
            world.try_borrow()?.world.debug_lines(out);
        } else if let Ok(path) = what.cast::<NavPath>() {
            path.get().path.debug_lines(owner, out);
        } else if let Ok(field) = what.cast::<FlowField>() {
            let field = field.get();
            field.flow().debug_lines(&field.nav.get().grid(), out);
        } else {
            return Err(PyTypeError::new_err(format!(
                "what is a {}: it must be a TileMap, Bodies, Character, HitWorld, NavPath or \
                 FlowField",
                what.get_type().name()?
            )));
        }
        Ok(())
    }

    /// Empties the buffer (its kinds and view stay).
    fn clear(&mut self) {
        self.lines.clear();
    }

    /// The segments, rows `x0, y0, x1, y1` (`float32`, shape `(N, 4)`).
    #[getter]
    fn segments<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f32>>> {
        rows(py, self.lines.segments(), |s| {
            [s.segment.a.x, s.segment.a.y, s.segment.b.x, s.segment.b.y]
        })
    }

    /// Each segment's kind (`uint8`, shape `(N,)`; `DebugKind(k)` names it).
    #[getter]
    fn segment_kinds<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<u8>> {
        kinds(py, self.lines.segments(), |s| s.kind)
    }

    /// The circles, rows `x, y, radius` (`float32`, shape `(N, 3)`).
    #[getter]
    fn circles<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f32>>> {
        rows(py, self.lines.circles(), |c| {
            [c.circle.center.x, c.circle.center.y, c.circle.radius]
        })
    }

    /// Each circle's kind.
    #[getter]
    fn circle_kinds<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<u8>> {
        kinds(py, self.lines.circles(), |c| c.kind)
    }

    /// The points, rows `x, y` (`float32`, shape `(N, 2)`).
    #[getter]
    fn points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f32>>> {
        rows(py, self.lines.points(), |p| [p.point.x, p.point.y])
    }

    /// Each point's kind.
    #[getter]
    fn point_kinds<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<u8>> {
        kinds(py, self.lines.points(), |p| p.kind)
    }

    /// The boxes, rows `min_x, min_y, max_x, max_y` (`float32`, shape `(N, 4)`).
    #[getter]
    fn boxes<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f32>>> {
        rows(py, self.lines.boxes(), |b| {
            [b.aabb.min.x, b.aabb.min.y, b.aabb.max.x, b.aabb.max.y]
        })
    }

    /// Each box's kind.
    #[getter]
    fn box_kinds<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<u8>> {
        kinds(py, self.lines.boxes(), |b| b.kind)
    }

    /// Shapes in the buffer, of every sort.
    fn __len__(&self) -> usize {
        self.lines.len()
    }

    fn __repr__(&self) -> String {
        format!(
            "DebugLines(segments={}, circles={}, points={}, boxes={})",
            self.lines.segments().len(),
            self.lines.circles().len(),
            self.lines.points().len(),
            self.lines.boxes().len()
        )
    }
}
