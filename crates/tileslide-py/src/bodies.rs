//! `Bodies`: circles and compounds of circles that slide round each other and along a map's
//! walls, named by `BodyId`s; positions and proposed moves in NumPy arrays for crowds.

use numpy::{PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::exceptions::{PyKeyError, PyValueError};
use pyo3::prelude::*;
use tileslide::{BodyDesc, BodyError, BodyFilter, BodyHandle, BodyShape, Circle, Vec2};

use crate::map::TileMap;

/// A body's id. Once its body is removed the id is stale for good: using it raises
/// `KeyError`, even after its slot holds another body.
#[pyclass(module = "tileslide", frozen, eq, hash, from_py_object)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct BodyId {
    /// The body's slot (bodies are resolved in slot order).
    #[pyo3(get)]
    index: u32,
    /// How many bodies had the slot before this one.
    #[pyo3(get)]
    generation: u32,
}

impl BodyId {
    fn handle(self) -> BodyHandle {
        BodyHandle::from_parts(self.index, self.generation)
    }

    fn of(handle: BodyHandle) -> Self {
        BodyId {
            index: handle.index(),
            generation: handle.generation(),
        }
    }
}

#[pymethods]
impl BodyId {
    fn __repr__(&self) -> String {
        format!(
            "BodyId(index={}, generation={})",
            self.index, self.generation
        )
    }
}

/// What a step did.
#[pyclass(module = "tileslide", frozen, get_all)]
#[derive(Clone, Copy, Debug)]
pub struct StepReport {
    /// Bodies with a move to make.
    moving: usize,
    /// Contacts met (each sweep stopped at something counts once).
    contacts: usize,
    /// Bodies whose move was still blocked after the last pass, and cut at its first
    /// contact.
    cut_short: usize,
}

#[pymethods]
impl StepReport {
    fn __repr__(&self) -> String {
        format!(
            "StepReport(moving={}, contacts={}, cut_short={})",
            self.moving, self.contacts, self.cut_short
        )
    }
}

/// A set of bodies resolved together: each step, every proposed move is made as far as it
/// goes without overlapping the map's walls or another body, sliding along what it meets.
#[pyclass(module = "tileslide")]
pub struct Bodies {
    pub(crate) bodies: tileslide::Bodies,
}

fn body_error(e: &BodyError) -> PyErr {
    match e {
        BodyError::StaleHandle(_) => PyKeyError::new_err(e.to_string()),
        _ => PyValueError::new_err(e.to_string()),
    }
}

/// `error` with "entry k: " in front of its message.
fn at_entry(k: usize, e: &BodyError) -> PyErr {
    match e {
        BodyError::StaleHandle(_) => PyKeyError::new_err(format!("entry {k}: {e}")),
        _ => PyValueError::new_err(format!("entry {k}: {e}")),
    }
}

/// The rows of an `(N, 2)` array, as pairs: read in place when C-contiguous.
pub(crate) fn pairs(array: &PyReadonlyArray2<'_, f32>, name: &str) -> PyResult<Vec<Vec2>> {
    let shape = array.shape();
    if shape[1] != 2 {
        return Err(PyValueError::new_err(format!(
            "{name} has shape ({}, {}): it must be (N, 2)",
            shape[0], shape[1]
        )));
    }
    let view = array.as_array();
    Ok(view
        .rows()
        .into_iter()
        .map(|r| Vec2::new(r[0], r[1]))
        .collect())
}

#[pymethods]
impl Bodies {
    /// An empty set with the resolver's default settings.
    #[new]
    fn new() -> Self {
        Bodies {
            bodies: tileslide::Bodies::new(),
        }
    }

    /// Adds a body at (`x`, `y`): one circle of `radius`, or, with `circles`, a compound of
    /// circles given as `(dx, dy, radius)` offsets from the position. `groups` are the
    /// groups it belongs to and `collides_with` those it meets (bits). Returns its id.
    #[pyo3(signature = (x, y, radius = 0.5, *, circles = None, groups = None, collides_with = None))]
    fn add(
        &mut self,
        x: f32,
        y: f32,
        radius: f32,
        circles: Option<Vec<(f32, f32, f32)>>,
        groups: Option<u32>,
        collides_with: Option<u32>,
    ) -> PyResult<BodyId> {
        let shape = match circles {
            None => BodyShape::circle(radius),
            Some(circles) => BodyShape::compound(
                circles
                    .into_iter()
                    .map(|(dx, dy, r)| Circle::new(Vec2::new(dx, dy), r)),
            ),
        }
        .map_err(|e| body_error(&e))?;
        let defaults = BodyFilter::default();
        let filter = BodyFilter {
            groups: groups.unwrap_or(defaults.groups),
            collides_with: collides_with.unwrap_or(defaults.collides_with),
            ..defaults
        };
        let handle = self
            .bodies
            .add(BodyDesc::new(Vec2::new(x, y), shape).with_filter(filter))
            .map_err(|e| body_error(&e))?;
        Ok(BodyId::of(handle))
    }

    /// Removes a body; its id is stale from now on.
    fn remove(&mut self, id: BodyId) -> PyResult<()> {
        self.bodies
            .remove(id.handle())
            .map(|_| ())
            .map_err(|e| body_error(&e))
    }

    /// Whether `id` names a body of this set.
    fn __contains__(&self, id: BodyId) -> bool {
        self.bodies.contains(id.handle())
    }

    fn __len__(&self) -> usize {
        self.bodies.len()
    }

    /// Every body's id, in slot order (the order bodies are resolved in).
    fn ids(&self) -> Vec<BodyId> {
        self.bodies.iter().map(|(h, _)| BodyId::of(h)).collect()
    }

    /// Proposes the move (`dx`, `dy`) for the next step, replacing one proposed before.
    fn propose(&mut self, id: BodyId, dx: f32, dy: f32) -> PyResult<()> {
        self.bodies
            .propose(id.handle(), Vec2::new(dx, dy))
            .map_err(|e| body_error(&e))
    }

    /// Proposes `moves[k]` (a `float32` array of shape `(N, 2)`) for `ids[k]`. A stale id,
    /// or a move that is not finite or would end out of range, raises, naming the entry,
    /// and leaves every proposal as it was.
    fn propose_many(&mut self, ids: Vec<BodyId>, moves: PyReadonlyArray2<'_, f32>) -> PyResult<()> {
        let moves = pairs(&moves, "moves")?;
        if moves.len() != ids.len() {
            return Err(PyValueError::new_err(format!(
                "{} ids but {} moves: there must be one move for each id",
                ids.len(),
                moves.len()
            )));
        }
        // Proposed one by one with the core's own checks; on a refusal the entries already
        // proposed get their moves from before back (in reverse, for an id given twice),
        // so a bad entry leaves every proposal as it was.
        let mut before = Vec::with_capacity(ids.len());
        for (k, (id, m)) in ids.iter().zip(moves).enumerate() {
            let refused = match self.bodies.get(id.handle()) {
                Ok(body) => {
                    before.push((id.handle(), body.proposed_move()));
                    self.bodies.propose(id.handle(), m).err()
                }
                Err(e) => Some(e),
            };
            if let Some(e) = refused {
                for (handle, previous) in before.into_iter().rev() {
                    // Moves the set accepted from these positions before: accepted again.
                    let _ = self.bodies.propose(handle, previous);
                }
                return Err(at_entry(k, &e));
            }
        }
        Ok(())
    }

    /// Moves a body to (`x`, `y`) at once (a teleport: no sweep), dropping its proposed move.
    fn set_position(&mut self, id: BodyId, x: f32, y: f32) -> PyResult<()> {
        self.bodies
            .set_position(id.handle(), Vec2::new(x, y))
            .map_err(|e| body_error(&e))
    }

    /// One step: every proposed move resolved together against `map` and each other (no
    /// overlap, no tunnelling), then made.
    fn step(&mut self, map: &TileMap) -> StepReport {
        let done = self.bodies.step(&map.map);
        StepReport {
            moving: done.moving,
            contacts: done.contact_count,
            cut_short: done.cut_short,
        }
    }

    /// A body's position `(x, y)`.
    fn position(&self, id: BodyId) -> PyResult<(f32, f32)> {
        let p = self
            .bodies
            .get(id.handle())
            .map_err(|e| body_error(&e))?
            .position();
        Ok((p.x, p.y))
    }

    /// The positions of `ids` (every body's, in slot order, when None) as a `float32` array
    /// of shape `(N, 2)`.
    #[pyo3(signature = (ids = None))]
    fn positions<'py>(
        &self,
        py: Python<'py>,
        ids: Option<Vec<BodyId>>,
    ) -> PyResult<Bound<'py, PyArray2<f32>>> {
        let mut out = Vec::new();
        match ids {
            None => {
                out.reserve(self.bodies.len() * 2);
                for (_, body) in self.bodies.iter() {
                    let p = body.position();
                    out.extend([p.x, p.y]);
                }
            }
            Some(ids) => {
                out.reserve(ids.len() * 2);
                for (k, id) in ids.iter().enumerate() {
                    let p = self
                        .bodies
                        .get(id.handle())
                        .map_err(|e| at_entry(k, &e))?
                        .position();
                    out.extend([p.x, p.y]);
                }
            }
        }
        let n = out.len() / 2;
        PyArray1::from_vec(py, out).reshape([n, 2])
    }

    fn __repr__(&self) -> String {
        format!("Bodies(len={})", self.bodies.len())
    }
}
