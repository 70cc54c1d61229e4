//! `render`: a picture of a map and what is in it, as PNG bytes (and a file), drawn by
//! tileslide-render: solid material, active segments with their normals, bodies, circles,
//! rays with their hits, paths.

use std::path::PathBuf;

use numpy::{PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyBytes;
use tileslide::{Circle, QueryFilter, Ray, Vec2};
use tileslide_render::{Canvas, Picture, RenderError, RenderOptions, YAxis};

use crate::bodies::Bodies;
use crate::map::TileMap;

/// The rows of `array`, which must have `width` columns: read in logical order whatever
/// its layout.
fn rows(
    array: &PyReadonlyArray2<'_, f32>,
    name: &str,
    width: usize,
    what: &str,
) -> PyResult<Vec<Vec<f32>>> {
    let shape = array.shape();
    if shape[1] != width {
        return Err(PyValueError::new_err(format!(
            "{name} has shape ({}, {}): it must be (N, {width}), rows {what}",
            shape[0], shape[1]
        )));
    }
    Ok(array
        .as_array()
        .rows()
        .into_iter()
        .map(|r| r.to_vec())
        .collect())
}

fn render_error(e: &RenderError) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// Draws `map` with, over it, `bodies` (a `Bodies`), `circles` (`(N, 3)` rows x, y,
/// radius), `rays` (`(N, 4)` rows x0, y0, x1, y1, each drawn with what it hits on the map)
/// and `paths` (a sequence of `(N, 2)` arrays of points). `scale` is pixels per cell;
/// `y_up` draws row 0 at the bottom (for maps whose up is +y). Returns the PNG's bytes,
/// and writes them to `path` when given. Shapes with coordinates that are not finite are
/// left out.
#[pyfunction]
#[pyo3(signature = (map, path = None, *, bodies = None, circles = None, rays = None, paths = None, scale = 16.0, y_up = false))]
#[allow(clippy::too_many_arguments)]
pub fn render<'py>(
    py: Python<'py>,
    map: &TileMap,
    path: Option<PathBuf>,
    bodies: Option<PyRef<'py, Bodies>>,
    circles: Option<PyReadonlyArray2<'py, f32>>,
    rays: Option<PyReadonlyArray2<'py, f32>>,
    paths: Option<Vec<PyReadonlyArray2<'py, f32>>>,
    scale: f32,
    y_up: bool,
) -> PyResult<Bound<'py, PyBytes>> {
    let options = RenderOptions::default()
        .with_pixels_per_cell(scale)
        .with_y_axis(if y_up { YAxis::Up } else { YAxis::Down });
    let canvas = Canvas::new(&map.map, &options).map_err(|e| render_error(&e))?;
    let mut picture = Picture::new();
    if let Some(bodies) = &bodies {
        picture.bodies(&bodies.bodies);
    }
    if let Some(circles) = &circles {
        for c in rows(circles, "circles", 3, "x, y, radius")? {
            picture.body(Circle::new(Vec2::new(c[0], c[1]), c[2]));
        }
    }
    if let Some(rays) = &rays {
        let filter = QueryFilter::default();
        for r in rows(rays, "rays", 4, "x0, y0, x1, y1")? {
            let ray = Ray::between(Vec2::new(r[0], r[1]), Vec2::new(r[2], r[3]));
            let hit = if ray.is_finite() {
                map.map.cast_ray(ray, &filter)
            } else {
                None
            };
            picture.ray(ray, hit.as_ref());
        }
    }
    for (k, points) in paths.iter().flatten().enumerate() {
        let points: Vec<Vec2> = rows(points, &format!("paths[{k}]"), 2, "x, y")?
            .into_iter()
            .map(|p| Vec2::new(p[0], p[1]))
            .collect();
        picture.polyline(&points);
    }
    let png = canvas
        .render(&picture)
        .to_png()
        .map_err(|e| render_error(&e))?;
    if let Some(path) = path {
        std::fs::write(&path, &png).map_err(|e| {
            PyErr::from(std::io::Error::new(
                e.kind(),
                format!("{}: {e}", path.display()),
            ))
        })?;
    }
    Ok(PyBytes::new(py, &png))
}
