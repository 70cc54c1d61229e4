//! Top-down crowd: twelve circles follow a flow field to an exit, sliding around each
//! other and along the walls, and leave the level there.
//!
//! `cargo run -p tileslide --example top_down_flow [OUT.gif]` writes the run as an animated
//! GIF and a PNG of every circle's trail (default `target/examples-out/`).
//!
//! The pieces: a [`NavGrid`] over the map, one [`FlowField`] for the exit (shared by every
//! circle of that radius: one lookup per circle per frame, no search), and [`Bodies`], the
//! resolver that turns each circle's wish into a move that overlaps nothing.

use std::error::Error;
use std::path::{Path, PathBuf};

use tileslide::io::ascii;
use tileslide::{
    Aabb, Bodies, BodyDesc, BodyHandle, BodyShape, Circle, FlowField, NavConfig, NavGrid, Vec2,
};
use tileslide_render::{Animation, Canvas, Picture, RenderOptions, Rgba};

/// The level, y down: `#` walls, `/` and `\` slanted walls. The crowd starts on the left,
/// the exit is the gap in the right-hand wall.
const LEVEL: &str = "\
########################
#......#...............#
#......#......##.......#
#......#......##...\\...#
#..............#....\\..#
#......#.......#........
#......#........\\.......
#......#..##.....\\......
#.........##...........#
#......#...............#
########################";

/// Where the crowd goes: the exit's cell, so circles walk out through the gap.
const EXIT: Vec2 = Vec2::new(23.5, 6.5);
const RADIUS: f32 = 0.35;
const SPEED: f32 = 4.0; // cells per second
const DT: f32 = 1.0 / 60.0; // a fixed step: the same run on every machine
const MAX_FRAMES: u32 = 900;

/// What a run did.
struct Run {
    frames: u32,
    escaped: usize,
    /// The smallest gap seen between two circles (negative would be an overlap).
    closest_gap: f32,
    /// Each circle's positions, every few frames.
    trails: Vec<Vec<Vec2>>,
    /// Where the circles were at frame [`SNAPSHOT`], squeezing through the doors.
    snapshot: Vec<Vec2>,
}

const SNAPSHOT: u32 = 100;

/// Plays the level; pushes a frame to `animation` every third step when given one.
fn play(mut animation: Option<&mut Animation<'_>>) -> Result<Run, Box<dyn Error>> {
    let map = ascii::parse(LEVEL, "crowd.txt", 1.0)?;
    let nav = NavGrid::new(&map, NavConfig::default())?;
    let field = FlowField::new(&nav, &map, EXIT, RADIUS)?;

    // Twelve circles in a block on the left; `Bodies` keeps them from ever overlapping.
    let mut bodies = Bodies::new();
    let mut crowd: Vec<Option<BodyHandle>> = Vec::new();
    for i in 0..12 {
        let at = Vec2::new(1.8 + (i % 3) as f32 * 1.6, 1.8 + (i / 3) as f32 * 2.1);
        crowd.push(Some(
            bodies.add(BodyDesc::new(at, BodyShape::circle(RADIUS)?))?,
        ));
    }
    let mut run = Run {
        frames: 0,
        escaped: 0,
        closest_gap: f32::INFINITY,
        trails: vec![Vec::new(); crowd.len()],
        snapshot: Vec::new(),
    };
    let mut picture = Picture::new();
    while run.escaped < crowd.len() && run.frames < MAX_FRAMES {
        // 1. Each circle asks the field which way to go and proposes a step that way.
        for handle in crowd.iter().flatten() {
            let at = bodies.get(*handle)?.position();
            if let Some(dir) = field.direction(&nav, &map, at)? {
                bodies.propose(*handle, dir * SPEED * DT)?;
            }
        }
        // 2. The resolver moves them all: blocked moves slide along walls and each other.
        bodies.step(&map);
        run.frames += 1;
        // 3. Game logic: a circle through the exit leaves the level.
        for (k, slot) in crowd.iter_mut().enumerate() {
            let Some(handle) = *slot else { continue };
            let at = bodies.get(handle)?.position();
            if run.frames.is_multiple_of(4) {
                run.trails[k].push(at);
            }
            if at.x > 23.0 {
                bodies.remove(handle)?;
                *slot = None;
                run.escaped += 1;
            }
        }
        run.closest_gap = run.closest_gap.min(closest_gap(&bodies));
        if run.frames == SNAPSHOT {
            run.snapshot = bodies.iter().map(|(_, b)| b.position()).collect();
        }
        // 4. The picture of every third frame: the exit and the circles.
        if let Some(animation) = animation.as_deref_mut()
            && run.frames.is_multiple_of(3)
        {
            picture.clear();
            picture.area(Aabb::from_center(EXIT, Vec2::splat(0.5)), EXIT_COLOR);
            for (_, body) in bodies.iter() {
                picture.body(Circle::new(body.position(), RADIUS));
            }
            animation.push(&picture)?;
        }
    }
    Ok(run)
}

/// The smallest distance between the edges of two circles (brute force: every pair).
fn closest_gap(bodies: &Bodies) -> f32 {
    let at: Vec<Vec2> = bodies.iter().map(|(_, b)| b.position()).collect();
    let mut gap = f32::INFINITY;
    for (i, a) in at.iter().enumerate() {
        for b in &at[i + 1..] {
            gap = gap.min(a.distance(*b) - 2.0 * RADIUS);
        }
    }
    gap
}

const EXIT_COLOR: Rgba = Rgba::opaque(120, 200, 120);

fn main() -> Result<(), Box<dyn Error>> {
    let gif = output_path("top_down_flow.gif")?;
    let map = ascii::parse(LEVEL, "crowd.txt", 1.0)?;
    let canvas = Canvas::new(&map, &RenderOptions::default().with_pixels_per_cell(20.0))?;
    let mut animation = Animation::new(&canvas)?;
    let run = play(Some(&mut animation))?;
    animation.save_gif(&gif)?;

    // A still picture: the crowd at the doors, over every circle's whole trail.
    let mut picture = Picture::new();
    picture.area(Aabb::from_center(EXIT, Vec2::splat(0.5)), EXIT_COLOR);
    for trail in &run.trails {
        picture.polyline(trail);
    }
    for &at in &run.snapshot {
        picture.body(Circle::new(at, RADIUS));
    }
    let png = gif.with_extension("png");
    canvas.render(&picture).save_png(&png)?;

    println!(
        "top_down_flow: {} of 12 circles reached the exit in {} frames ({:.1} s)",
        run.escaped,
        run.frames,
        run.frames as f32 * DT
    );
    println!(
        "  closest gap between two circles: {:.4} cells (never overlapping)",
        run.closest_gap
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
    fn every_circle_reaches_the_exit_and_no_two_ever_overlap() -> Result<(), Box<dyn Error>> {
        let run = play(None)?;
        assert_eq!(run.escaped, 12, "stuck after {} frames", run.frames);
        assert!(run.closest_gap >= 0.0, "overlap: gap {}", run.closest_gap);
        Ok(())
    }
}
