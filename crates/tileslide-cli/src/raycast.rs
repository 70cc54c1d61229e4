//! `tileslide raycast`.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, anyhow, bail};
use serde_json::json;
use tileslide::{QueryFilter, Ray, RayHit, SegmentFlags, Vec2};

use crate::json::number;
use crate::map_file::{self, MapArgs};
use crate::point_arg::parse_point;

pub fn run(
    args: &MapArgs,
    points: Option<(String, String)>,
    rays_file: Option<PathBuf>,
    both_sides: bool,
    as_json: bool,
) -> Result<()> {
    // Read the rays before the map, so a bad ray file fails fast.
    let rays = match (points, rays_file) {
        (Some((from, to)), _) => vec![(parse_point(&from, "--from")?, parse_point(&to, "--to")?)],
        (None, Some(path)) => read_rays(&path)?,
        (None, None) => bail!("give --from X,Y --to X,Y or --rays FILE"),
    };
    let (map, _) = map_file::load(args)?;
    let filter = if both_sides {
        QueryFilter::both_sides()
    } else {
        QueryFilter::default()
    };
    // All at once: `cast_rays` walks them side by side, with each answer `cast_ray`'s.
    let segments: Vec<Ray> = rays.iter().map(|(p0, p1)| Ray::between(*p0, *p1)).collect();
    // Finite end points can be too far apart for an f32 (from -3e38 to 3e38): such a ray
    // has no motion to cast, and answering "no hit" would be wrong.
    if let Some(i) = segments.iter().position(|r| !r.delta.is_finite()) {
        let (p0, p1) = rays[i];
        bail!(
            "ray {} ({}, {}) → ({}, {}): its end points are too far apart for a 32-bit float",
            i + 1,
            p0.x,
            p0.y,
            p1.x,
            p1.y
        );
    }
    let hits = map.cast_rays(&segments, &filter);
    for (i, ((p0, p1), hit)) in rays.iter().zip(&hits).enumerate() {
        if as_json {
            println!("{}", hit_json(hit.as_ref()));
        } else {
            println!(
                "ray {} ({}, {}) → ({}, {}): {}",
                i + 1,
                p0.x,
                p0.y,
                p1.x,
                p1.y,
                describe(hit.as_ref())
            );
        }
    }
    Ok(())
}

fn hit_json(hit: Option<&RayHit>) -> serde_json::Value {
    match hit {
        None => json!({ "hit": false }),
        Some(h) => {
            let mut v = json!({
                "hit": true, "t": number(h.t), "x": number(h.point.x), "y": number(h.point.y),
                "nx": number(h.normal.x), "ny": number(h.normal.y),
                "one_way": h.flags.contains(SegmentFlags::ONE_WAY),
            });
            if let (Some(cell), Some(tile)) = (h.cell(), h.tile()) {
                v["cell"] = json!([cell.col, cell.row]);
                v["tile"] = json!(tile.0);
            }
            v
        }
    }
}

fn describe(hit: Option<&RayHit>) -> String {
    match hit {
        None => "no hit".to_string(),
        Some(h) => {
            let mut s = format!(
                "hit at t = {} ({}, {}), normal ({}, {})",
                h.t, h.point.x, h.point.y, h.normal.x, h.normal.y
            );
            if let (Some(cell), Some(tile)) = (h.cell(), h.tile()) {
                s += &format!(", cell {cell}, tile {tile}");
            }
            if h.flags.contains(SegmentFlags::ONE_WAY) {
                s += ", one-way";
            }
            s
        }
    }
}

/// Reads a CSV ray file: `x0,y0,x1,y1` per line; blank lines and lines starting with `#`
/// are skipped. Errors name the file, line and column.
fn read_rays(path: &Path) -> Result<Vec<(Vec2, Vec2)>> {
    let bytes = tileslide::io::read_limited(path)
        .with_context(|| format!("{}: cannot read the ray file", path.display()))?;
    let text = String::from_utf8(bytes)
        .with_context(|| format!("{}: the ray file is not UTF-8 text", path.display()))?;
    let mut rays = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let trimmed = line.trim();
        if trimmed.is_empty() || trimmed.starts_with('#') {
            continue;
        }
        let mut values = [0f32; 4];
        let mut column = 1;
        let fields: Vec<&str> = line.split(',').collect();
        if fields.len() != 4 {
            bail!(
                "{}:{}:1: expected 4 comma-separated numbers x0,y0,x1,y1, found {} fields",
                path.display(),
                n + 1,
                fields.len()
            );
        }
        for (i, field) in fields.iter().enumerate() {
            let v: f32 = field.trim().parse().map_err(|_| {
                anyhow!(
                    "{}:{}:{}: {:?} is not a number",
                    path.display(),
                    n + 1,
                    column,
                    field.trim()
                )
            })?;
            if !v.is_finite() {
                bail!(
                    "{}:{}:{}: {:?} is not finite",
                    path.display(),
                    n + 1,
                    column,
                    field.trim()
                );
            }
            values[i] = v;
            column += field.chars().count() + 1;
        }
        rays.push((
            Vec2::new(values[0], values[1]),
            Vec2::new(values[2], values[3]),
        ));
    }
    Ok(rays)
}
