//! `tileslide render MAP`: a PNG picture of a map. Also the canvas `simulate --gif` draws
//! its frames on.

use std::path::{Path, PathBuf};

use anyhow::{Result, anyhow, bail};
use tileslide::TileMap;
use tileslide_render::{Canvas, Picture, RenderOptions, YAxis};

use crate::map_file::{self, MapArgs, MapFormat};
use crate::output;

/// The `--scale` of `render` and `simulate --gif`, checked: pixels per cell.
pub fn check_scale(scale: f32) -> Result<f32> {
    if !(scale > 0.0 && scale.is_finite()) {
        bail!("--scale {scale}: pixels per cell must be a positive number");
    }
    Ok(scale)
}

/// `map` (read from `path` in `format`) drawn at `scale` pixels per cell, y up for Replica
/// Island levels (or when `y_up` says so), y down otherwise.
pub fn canvas(
    map: &TileMap,
    format: MapFormat,
    path: &Path,
    scale: f32,
    y_up: bool,
) -> Result<Canvas> {
    let y_axis = if y_up || format == MapFormat::ReplicaIsland {
        YAxis::Up
    } else {
        YAxis::Down
    };
    let options = RenderOptions::default()
        .with_pixels_per_cell(scale)
        .with_y_axis(y_axis);
    Canvas::new(map, &options).map_err(|e| anyhow!("{}: --scale {scale}: {e}", path.display()))
}

pub fn run(args: &MapArgs, scale: f32, output: Option<PathBuf>, y_up: bool) -> Result<()> {
    let scale = check_scale(scale)?;
    let output = output.unwrap_or_else(|| default_output(&args.map));
    output::check(&output, "-o", output::PNG)?;
    let (map, format) = map_file::load(args)?;
    let canvas = canvas(&map, format, &args.map, scale, y_up)?;
    let mut picture = Picture::new();
    picture.temporaries(&map);
    let image = canvas.render(&picture);
    image.save_png(&output)?;
    println!(
        "{}: {} × {} pixels ({} × {} cells at {scale} pixels per cell)",
        output.display(),
        image.width(),
        image.height(),
        map.width(),
        map.height()
    );
    Ok(())
}

/// `MAP`'s file stem with `.png`, in the current directory.
fn default_output(map: &Path) -> PathBuf {
    let mut name = map
        .file_stem()
        .unwrap_or_else(|| "map".as_ref())
        .to_os_string();
    name.push(".png");
    PathBuf::from(name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_output_is_the_stem_in_the_current_directory() {
        assert_eq!(
            default_output(Path::new("examples/maps/cave.tmx")),
            PathBuf::from("cave.png")
        );
        assert_eq!(
            default_output(Path::new("level.1.bin")),
            PathBuf::from("level.1.png")
        );
        assert_eq!(default_output(Path::new("/")), PathBuf::from("map.png"));
    }
}
