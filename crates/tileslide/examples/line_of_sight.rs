//! Line of sight: three guards watch a room; a thief walks round it. A guard sees the thief
//! when the thief is inside its view cone and a ray from the guard's eye to the thief hits
//! no wall on the way.
//!
//! `cargo run -p tileslide --example line_of_sight [OUT.gif]` writes the run as an animated
//! GIF and a PNG of one frame (default `target/examples-out/`).
//!
//! One [`TileMap::cast_ray`] per guard and frame: it returns the nearest wall hit between
//! the two points, exactly (corners and the crack between two diagonal blocks included), so
//! "no hit" means a clear line.

use std::error::Error;
use std::path::{Path, PathBuf};

use tileslide::io::ascii;
use tileslide::{Circle, QueryFilter, Ray, TileMap, Vec2};
use tileslide_render::{Animation, Canvas, Picture, RenderOptions, Rgba};

/// y down: `#` walls, `/` and `\` slanted walls.
const LEVEL: &str = "\
######################
#....................#
#..##.......#........#
#..##.......#...##...#
#...........#...##...#
#.....\\..............#
#......\\.......####..#
#....................#
#...####.............#
#....................#
######################";

struct Guard {
    eye: Vec2,
    /// The direction it looks in at time 0 (radians, y down), and how far it turns each
    /// way while it scans.
    facing: f32,
    scan: f32,
}

const GUARDS: [Guard; 3] = [
    guard(9.0, 6.0, -2.4, 0.5), // watches the top left, behind the pillar
    guard(14.5, 2.5, 3.0, 0.5), // looks left along the top, across the wall
    guard(10.0, 8.0, 0.5, 0.6), // watches the bottom right
];

const fn guard(x: f32, y: f32, facing: f32, scan: f32) -> Guard {
    Guard {
        eye: Vec2::new(x, y),
        facing,
        scan,
    }
}

const HALF_ANGLE: f32 = 0.6; // radians each side of the facing: a 69° cone
const RANGE: f32 = 12.0;
const DT: f32 = 1.0 / 30.0;
const FRAMES: u32 = 360;

/// The thief's round: along the walls, clockwise.
const ROUND: [Vec2; 5] = [
    Vec2::new(1.5, 1.5),
    Vec2::new(19.5, 1.5),
    Vec2::new(19.5, 9.5),
    Vec2::new(1.5, 9.5),
    Vec2::new(1.5, 1.5),
];
const SPEED: f32 = 4.5;

/// The guard's view direction at time `t` (s): it scans to and fro.
fn look(guard: &Guard, t: f32) -> Vec2 {
    let angle = guard.facing + guard.scan * (t * 0.8).sin();
    Vec2::new(angle.cos(), angle.sin())
}

/// Whether the thief at `target` is within the guard's cone and range (geometry only).
fn in_view(eye: Vec2, look: Vec2, target: Vec2) -> bool {
    let to = target - eye;
    to.length() <= RANGE && to.normalize_or_zero().dot(look) >= HALF_ANGLE.cos()
}

/// Whether the guard sees `target`: in view, and the ray between them hits no wall (on
/// either side: a wall hides what is behind it whichever way the ray meets it).
fn sees(map: &TileMap, eye: Vec2, look: Vec2, target: Vec2) -> bool {
    in_view(eye, look, target)
        && map
            .cast_ray(Ray::between(eye, target), &QueryFilter::both_sides())
            .is_none()
}

/// Where the thief is at time `t`: walking the round, again and again.
fn thief_at(t: f32) -> Vec2 {
    let mut left = (t * SPEED) % ROUND.windows(2).map(|w| w[0].distance(w[1])).sum::<f32>();
    for w in ROUND.windows(2) {
        let leg = w[0].distance(w[1]);
        if left <= leg {
            return w[0].lerp(w[1], left / leg);
        }
        left -= leg;
    }
    ROUND[0]
}

#[derive(Default)]
struct Run {
    seen: u32,
    /// Frames in which a guard had the thief in its cone but a wall hid it.
    hidden_by_walls: u32,
}

fn play(
    map: &TileMap,
    mut animation: Option<&mut Animation<'_>>,
) -> Result<(Run, Option<Picture>), Box<dyn Error>> {
    let mut run = Run::default();
    let mut picture = Picture::new();
    let mut still = None;
    for frame in 0..FRAMES {
        let t = frame as f32 * DT;
        let thief = thief_at(t);
        picture.clear();
        let (mut spotted, mut hidden) = (false, false);
        for guard in &GUARDS {
            let dir = look(guard, t);
            let seen = sees(map, guard.eye, dir, thief);
            spotted |= seen;
            if in_view(guard.eye, dir, thief) {
                // The guard's ray to the thief: clear, or stopped where the wall is.
                let ray = Ray::between(guard.eye, thief);
                picture.ray(ray, map.cast_ray(ray, &QueryFilter::both_sides()).as_ref());
                hidden |= !seen;
                run.hidden_by_walls += u32::from(!seen);
            }
            // The view cone's two edges.
            for side in [-HALF_ANGLE, HALF_ANGLE] {
                let edge = Vec2::from_angle(side).rotate(dir) * 2.0;
                picture.polyline(&[guard.eye + edge, guard.eye]);
            }
            picture.body_with_color(Circle::new(guard.eye, 0.35), GUARD);
        }
        run.seen += u32::from(spotted);
        picture.body_with_color(
            Circle::new(thief, 0.3),
            if spotted { SPOTTED } else { HIDDEN },
        );
        // The still picture: the first frame where one guard sees the thief and a wall
        // hides it from another.
        if spotted && hidden && still.is_none() {
            still = Some(picture.clone());
        }
        if let Some(animation) = animation.as_deref_mut()
            && frame.is_multiple_of(2)
        {
            animation.push(&picture)?;
        }
    }
    Ok((run, still))
}

const GUARD: Rgba = Rgba::opaque(60, 60, 160);
const SPOTTED: Rgba = Rgba::opaque(220, 40, 40);
const HIDDEN: Rgba = Rgba::opaque(60, 170, 80);

fn main() -> Result<(), Box<dyn Error>> {
    let gif = output_path("line_of_sight.gif")?;
    let map = ascii::parse(LEVEL, "guards.txt", 1.0)?;
    let canvas = Canvas::new(&map, &RenderOptions::default().with_pixels_per_cell(20.0))?;
    let mut animation = Animation::new(&canvas)?;
    let (run, still) = play(&map, Some(&mut animation))?;
    animation.save_gif(&gif)?;
    let png = gif.with_extension("png");
    canvas.render(&still.unwrap_or_default()).save_png(&png)?;
    println!(
        "line_of_sight: {FRAMES} frames, the thief seen in {} of them",
        run.seen
    );
    println!(
        "  {} times a guard looked straight at the thief and a wall hid it",
        run.hidden_by_walls
    );
    println!("  wrote {} and {}", gif.display(), png.display());
    Ok(())
}

/// Where to write: the first argument, or `target/examples-out/NAME`.
fn output_path(name: &str) -> std::io::Result<PathBuf> {
    if let Some(arg) = std::env::args().nth(1) {
        return Ok(arg.into());
    }
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../target/examples-out");
    std::fs::create_dir_all(&dir)?;
    Ok(dir.canonicalize()?.join(name))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_guard_sees_the_thief_only_in_its_cone_and_not_through_walls() -> Result<(), Box<dyn Error>>
    {
        let map = ascii::parse(LEVEL, "guards.txt", 1.0)?;
        let (eye, right) = (Vec2::new(1.5, 4.5), Vec2::X);
        assert!(
            sees(&map, eye, right, Vec2::new(10.0, 4.5)),
            "in the open, in the cone"
        );
        assert!(
            !sees(&map, eye, right, Vec2::new(15.0, 4.5)),
            "behind the wall at x = 12"
        );
        assert!(
            !sees(&map, eye, -right, Vec2::new(10.0, 4.5)),
            "behind the guard's back"
        );
        assert!(
            !sees(&map, eye, right, Vec2::new(2.0, 1.5)),
            "outside the cone"
        );
        let (run, _) = play(&map, None)?;
        assert!(
            run.seen > 0 && run.seen < FRAMES,
            "seen in {} frames",
            run.seen
        );
        assert!(run.hidden_by_walls > 0, "no wall ever hid the thief");
        Ok(())
    }
}
