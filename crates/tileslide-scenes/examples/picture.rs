//! Draws the crowd scene after its 40 steps, with the first 64 rays of the rays scene, as
//! tileslide-render draws them: the picture other languages' renderers must equal byte for
//! byte (the Python package's tests compare `tileslide.render` with it).
//!
//! `cargo run -p tileslide-scenes --example picture -- FILE.png` draws dungeon256 at 4
//! pixels per cell with the 2,000 bodies (from `Bodies`, as `Picture::bodies` draws them)
//! and the rays with their hits.

use std::process::ExitCode;

use tileslide::io::ascii;
use tileslide::{QueryFilter, Ray};
use tileslide_render::{Canvas, Picture, RenderOptions};
use tileslide_scenes::{dungeon256, run_crowd, scene_crowd, scene_rays};

fn run() -> Result<(), String> {
    let out = std::env::args().nth(1).ok_or("usage: picture FILE.png")?;
    let grid = dungeon256();
    let map = ascii::parse(&grid.to_ascii(), "dungeon256", 1.0).map_err(|e| e.to_string())?;
    let crowd = scene_crowd(&grid, 2_000);
    let (bodies, _) = run_crowd(&map, &crowd, 40).map_err(|e| e.to_string())?;
    let mut picture = Picture::new();
    picture.bodies(&bodies);
    for r in scene_rays(&grid, 64) {
        let ray = Ray::between(r.origin, r.end());
        picture.ray(ray, map.cast_ray(ray, &QueryFilter::default()).as_ref());
    }
    let canvas = Canvas::new(&map, &RenderOptions::default().with_pixels_per_cell(4.0))
        .map_err(|e| e.to_string())?;
    canvas
        .render(&picture)
        .save_png(&out)
        .map_err(|e| format!("{out}: {e}"))
}

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("picture: {e}");
            ExitCode::FAILURE
        }
    }
}
