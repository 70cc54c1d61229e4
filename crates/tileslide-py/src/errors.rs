//! Rust errors as Python exceptions: a missing file is `FileNotFoundError`, an unreadable
//! one `OSError`, a bad argument `ValueError`, a map that does not load `LoadError` (a
//! `ValueError`) with the file, the position and the cause as attributes.

use pyo3::IntoPyObjectExt;
use pyo3::create_exception;
use pyo3::exceptions::{
    PyFileNotFoundError, PyOSError, PyOverflowError, PyTypeError, PyValueError,
};
use pyo3::prelude::*;
use tileslide::io::{LoadError as CoreLoadError, LoadErrorKind, Location};

create_exception!(
    tileslide,
    LoadError,
    PyValueError,
    "A map file (or text) that is not a map tileslide can load. Attributes: `file` (str), \
     `position` (None for the whole file, `(line, column)` from 1 in a text file, or a byte \
     offset in a binary one) and `cause` (str)."
);

/// The Python exception for a load error.
pub(crate) fn load_error(py: Python<'_>, e: &CoreLoadError) -> PyErr {
    let message = e.to_string();
    match e.io_error_kind() {
        Some(std::io::ErrorKind::NotFound) => return PyFileNotFoundError::new_err(message),
        Some(_) => return PyOSError::new_err(message),
        None => {}
    }
    if matches!(e.kind, LoadErrorKind::Parameter(_)) {
        return PyValueError::new_err(message);
    }
    let err = LoadError::new_err(message);
    let value = err.value(py);
    let position = match e.location {
        Location::LineColumn { line, column } => (line, column).into_bound_py_any(py),
        Location::Byte(offset) => offset.into_bound_py_any(py),
        _ => Ok(py.None().into_bound(py)),
    };
    // Setting attributes on a fresh exception object only fails when memory runs out; the
    // message says it all anyway.
    let _ = value.setattr("file", e.path.display().to_string());
    if let Ok(position) = position {
        let _ = value.setattr("position", position);
    }
    let _ = value.setattr("cause", e.kind.to_string());
    err
}

/// A `ValueError` unless `value` is finite.
pub(crate) fn finite(name: &str, value: f32) -> PyResult<f32> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(PyValueError::new_err(format!(
            "{name} is {value}: it must be a finite number"
        )))
    }
}

/// The point (`x`, `y`), named `names`, or a `ValueError` naming the coordinate that is
/// not finite.
pub(crate) fn finite_point(names: [&str; 2], x: f32, y: f32) -> PyResult<tileslide::Vec2> {
    Ok(tileslide::Vec2::new(
        finite(names[0], x)?,
        finite(names[1], y)?,
    ))
}

/// A Python int (or anything with `__index__`) from 0 to `max`, or an error naming `name`:
/// `TypeError` for what is not an int, `ValueError` for an int out of that range (where
/// pyo3 alone would raise an `OverflowError` that does not say which argument).
pub(crate) fn whole(name: &str, value: &Bound<'_, PyAny>, max: u64) -> PyResult<u64> {
    match value.extract::<u64>() {
        Ok(v) if v <= max => Ok(v),
        Ok(_) => Err(out_of_range(name, value, max)),
        Err(e) if e.is_instance_of::<PyOverflowError>(value.py()) => {
            Err(out_of_range(name, value, max))
        }
        Err(_) => Err(PyTypeError::new_err(format!(
            "{name} is {}: it must be an int",
            value
                .get_type()
                .name()
                .map_or_else(|_| "not an int".to_owned(), |n| format!("a {n}"))
        ))),
    }
}

fn out_of_range(name: &str, value: &Bound<'_, PyAny>, max: u64) -> PyErr {
    PyValueError::new_err(format!(
        "{name} is {value}: it must be a whole number from 0 to {max}"
    ))
}

/// `whole` for an argument that may be left out (`None`: `default`).
pub(crate) fn whole_or(
    name: &str,
    value: Option<&Bound<'_, PyAny>>,
    max: u64,
    default: u64,
) -> PyResult<u64> {
    value.map_or(Ok(default), |v| whole(name, v, max))
}
