//! `tileslide path`.

use anyhow::{Result, anyhow, bail};
use serde_json::{Value, json};
use tileslide::{NavConfig, NavError, NavGrid, NavPath, TileMap, Vec2};

use crate::json::number;
use crate::map_file::{self, MapArgs};
use crate::point_arg::parse_point;

pub fn run(args: &MapArgs, from: &str, to: &str, radius: &str, as_json: bool) -> Result<()> {
    // Check the arguments before loading the map, so a typo fails fast.
    let from = parse_point(from, "--from")?;
    let to = parse_point(to, "--to")?;
    let radius = parse_radius(radius)?;
    let (map, _) = map_file::load(args)?;
    // The grid serves exactly the one radius asked for: clearances are measured up to
    // `max_radius`, so a larger one would only cost building time.
    let config = NavConfig {
        max_radius: radius,
        ..NavConfig::default()
    };
    let nav = NavGrid::new(&map, config).map_err(|e| match e {
        NavError::BadMaxRadius { limit, .. } => anyhow!(
            "--radius {radius}: too wide for this map, whose cells allow at most {limit} (31 cells)"
        ),
        e => anyhow!("{}: {e}", args.map.display()),
    })?;
    let path = nav.find_path(&map, from, to, radius)?;
    if as_json {
        println!("{}", path_json(path.as_ref()));
        return Ok(());
    }
    match &path {
        Some(path) => {
            println!(
                "path from {} to {} for radius {radius}: length {}, {} points",
                point(from),
                point(to),
                path.length(),
                path.points().len()
            );
            for &p in path.points() {
                println!("{}", point(p));
            }
        }
        None => println!(
            "no path from {} to {} for radius {radius}: {}",
            point(from),
            point(to),
            why_not(&nav, &map, from, to, radius)?
        ),
    }
    Ok(())
}

/// `{"found":true,"length":L,"points":[[X,Y],...]}` or `{"found":false}`.
fn path_json(path: Option<&NavPath>) -> Value {
    match path {
        None => json!({ "found": false }),
        Some(path) => {
            let points: Vec<Value> = path
                .points()
                .iter()
                .map(|p| json!([number(p.x), number(p.y)]))
                .collect();
            json!({ "found": true, "length": number(path.length()), "points": points })
        }
    }
}

/// Why `find_path` found nothing: an end where the circle does not fit, or no way between.
fn why_not(nav: &NavGrid, map: &TileMap, from: Vec2, to: Vec2, radius: f32) -> Result<String> {
    Ok(if !nav.fits(map, from, radius)? {
        "the circle does not fit at the start (--from)".to_owned()
    } else if !nav.fits(map, to, radius)? {
        "the circle does not fit at the goal (--to)".to_owned()
    } else {
        "no way between them is wide enough".to_owned()
    })
}

fn point(p: Vec2) -> String {
    format!("({}, {})", p.x, p.y)
}

/// Parses `--radius` into a positive, finite radius; errors name the argument.
fn parse_radius(text: &str) -> Result<f32> {
    let r: f32 = text
        .trim()
        .parse()
        .map_err(|_| anyhow!("--radius {text:?}: not a number"))?;
    if !r.is_finite() {
        bail!("--radius {text:?}: not finite");
    }
    if r <= 0.0 {
        bail!("--radius {text:?}: must be positive (the circle's radius, in map units)");
    }
    Ok(r)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn radii_parse_and_errors_name_the_argument() {
        assert_eq!(parse_radius("0.4").unwrap(), 0.4);
        for (text, cause) in [
            ("-1", "positive"),
            ("0", "positive"),
            ("NaN", "not finite"),
            ("inf", "not finite"),
            ("wide", "not a number"),
        ] {
            let e = parse_radius(text).unwrap_err().to_string();
            assert!(e.contains("--radius") && e.contains(cause), "{text}: {e}");
        }
    }

    #[test]
    fn json_has_the_documented_fields_in_order() {
        assert_eq!(path_json(None).to_string(), r#"{"found":false}"#);
        let map = tileslide::io::ascii::parse("#####\n#...#\n#####", "t.txt", 1.0).unwrap();
        let nav = NavGrid::new(&map, NavConfig::default()).unwrap();
        let path = nav
            .find_path(&map, Vec2::new(1.5, 1.5), Vec2::new(3.5, 1.5), 0.4)
            .unwrap();
        assert_eq!(
            path_json(path.as_ref()).to_string(),
            r#"{"found":true,"length":2.0,"points":[[1.5,1.5],[3.5,1.5]]}"#
        );
    }
}
