//! tileslide for Python: the extension module `tileslide`, built by maturin
//! (`pyproject.toml`). Maps and their ray casts (one at a time, or a NumPy batch without a
//! Python loop), bodies (positions and proposed moves as NumPy arrays), with errors as
//! Python's own exceptions and `tileslide.LoadError` for a map that does not load. The
//! stubs editors read are `tileslide.pyi`; the tests are `tests/` (pytest).
#![forbid(unsafe_code)]

use pyo3::prelude::*;

mod bodies;
mod character;
mod debug;
mod errors;
mod map;
mod nav;
mod render;
mod trace;
mod volumes;

/// The module: its classes, its exception and its version.
#[pymodule]
#[pyo3(name = "tileslide")]
fn tileslide_module(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add("LoadError", m.py().get_type::<errors::LoadError>())?;
    m.add_class::<map::TileMap>()?;
    m.add_class::<map::RayHit>()?;
    m.add_class::<bodies::Bodies>()?;
    m.add_class::<bodies::BodyId>()?;
    m.add_class::<bodies::StepReport>()?;
    m.add_class::<trace::TileSet>()?;
    m.add_function(wrap_pyfunction!(render::render, m)?)?;
    m.add_function(wrap_pyfunction!(trace::trace, m)?)?;
    m.add_class::<character::Character>()?;
    m.add_class::<character::Contact>()?;
    m.add_class::<character::MoveResult>()?;
    m.add_class::<volumes::HitWorld>()?;
    m.add_class::<volumes::HitType>()?;
    m.add_class::<volumes::Volume>()?;
    m.add_class::<volumes::ObjectId>()?;
    m.add_class::<volumes::HitEvent>()?;
    m.add_class::<nav::NavGrid>()?;
    m.add_class::<nav::NavPath>()?;
    m.add_class::<nav::FlowField>()?;
    m.add_class::<debug::DebugLines>()?;
    m.add("DebugKind", debug::kind_enum(m.py())?)?;
    Ok(())
}
