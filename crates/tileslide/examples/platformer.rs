//! Platformer: a box runs up a ramp, jumps onto a moving platform over a pit, rides it
//! across, hops off and jumps up through a one-way platform to the goal.
//!
//! `cargo run -p tileslide --example platformer [OUT.gif]` writes the run as an animated GIF
//! and a PNG of the character's trail (default `target/examples-out/`).
//!
//! The library moves the box ([`Character::move_and_slide`]): slopes, landing, walls, the
//! platform carrying its rider, and the velocity clipped against what it hit. Gravity, the
//! jump, coyote time and variable jump height are the game's rules, written here.

use std::error::Error;
use std::path::{Path, PathBuf};

use tileslide::io::ascii;
use tileslide::{
    Aabb, Character, CharacterShape, ControllerConfig, MoveOptions, Owner, Segment, SegmentFlags,
    SegmentSource, TemporarySegment, TileMap, Vec2,
};
use tileslide_render::{Animation, Canvas, Picture, RenderOptions, Rgba};

/// y down: `#` solid, `/` a ramp, `=` a one-way platform (the goal stands on it).
const LEVEL: &str = "\
################################
#..............................#
#..............................#
#..............................#
#.........................===..#
#..............................#
#........../###........#########
#........./####........#########
###############........#########
###############........#########
################################";

const HALF: Vec2 = Vec2::new(0.3, 0.45); // the box's half width and height
const DT: f32 = 1.0 / 60.0;
const GRAVITY: f32 = 40.0; // cells/s², down (+y)
const RUN: f32 = 6.0;
const JUMP: f32 = 13.0;
const MAX_FALL: f32 = 20.0;
const COYOTE_FRAMES: u32 = 6; // a jump still counts this long after leaving the ground
const PLATFORM: Owner = Owner(1);
const PLATFORM_Y: f32 = 7.0; // one cell below the plateaus on both sides of the pit
const PLATFORM_WIDTH: f32 = 2.0;

/// What the player presses this frame (here a script, in a game the keyboard): how fast
/// to run, and whether the jump button is held.
struct Input(f32, bool);

#[derive(Default)]
struct Run {
    frames: u32,
    jumps: u32,
    frames_riding: u32,
    reached_goal: bool,
    trail: Vec<Vec2>,
}

/// The moving platform: its left end slides between x = 15 and x = 21 and back.
fn platform_at(frame: u32) -> f32 {
    let phase = (frame as f32 * DT * 0.5) % 2.0; // one way in 2 s, back in 2 s
    15.0 + 6.0 * if phase < 1.0 { phase } else { 2.0 - phase }
}

/// The script: run to the pit, wait for the platform, hop on, ride, jump off, climb.
fn script(hero: &Character, riding: bool, platform: f32) -> Input {
    let (x, on_ground) = (hero.position.x, hero.ground().is_some());
    let far_side = platform >= 20.8;
    match x {
        _ if riding => Input(if far_side { RUN } else { 0.0 }, far_side),
        x if x < 14.3 => Input(RUN, false),
        // At the edge: wait for the platform, then a short hop (jump tapped, not held).
        x if x < 15.0 && on_ground => {
            let near = platform <= 15.4;
            Input(if near { RUN } else { 0.0 }, near)
        }
        x if x < 21.0 => Input(RUN * 0.6, false),
        // Off the platform and up through the one-way platform: full jumps (held).
        x => Input(if x < 27.5 { RUN } else { 0.0 }, x > 26.0 || !on_ground),
    }
}

fn play(mut animation: Option<&mut Animation<'_>>) -> Result<Run, Box<dyn Error>> {
    let mut map: TileMap = ascii::parse(LEVEL, "platformer.txt", 1.0)?;
    let shape = CharacterShape::rect(HALF)?;
    let (start, up) = (Vec2::new(2.0, 7.5), Vec2::NEG_Y);
    let mut hero = Character::new(shape, start, up, ControllerConfig::default())?;
    let mut velocity = Vec2::ZERO;
    let mut since_ground = 0;
    let mut carried = 0.0; // a moving platform's speed, kept from a jump off it to landing
    let mut run = Run::default();
    let mut picture = Picture::new();
    let mut was = platform_at(0);
    for frame in 0..480 {
        // 1. Platforms move first: submit the platform's segment at its new place.
        let x = platform_at(frame);
        map.clear_temporaries_of(PLATFORM);
        map.add_temporary(TemporarySegment {
            segment: Segment::new(
                Vec2::new(x, PLATFORM_Y),
                Vec2::new(x + PLATFORM_WIDTH, PLATFORM_Y),
            ),
            normal: Vec2::NEG_Y,
            flags: SegmentFlags::ONE_WAY,
            owner: PLATFORM,
            velocity: Vec2::new((x - was) / DT, 0.0),
        })?;
        was = x;
        // 2. The game's rules: input, coyote time, jump, variable jump height, gravity.
        let riding = hero
            .ground()
            .is_some_and(|g| matches!(g.source, SegmentSource::Temporary { .. }));
        let Input(run_speed, jump) = script(&hero, riding, x);
        if hero.ground().is_some() {
            (since_ground, carried) = (0, 0.0);
        } else {
            since_ground += 1;
        }
        if jump && since_ground <= COYOTE_FRAMES && velocity.y >= 0.0 {
            // Jumping off a moving platform keeps its speed.
            carried = hero.ground().map_or(0.0, |g| g.platform_velocity().x);
            velocity.y = -JUMP;
            since_ground = COYOTE_FRAMES + 1;
            run.jumps += 1;
        }
        velocity.x = run_speed + carried;
        if !jump && velocity.y < 0.0 {
            velocity.y *= 0.5; // released early: a lower jump
        }
        velocity.y = (velocity.y + GRAVITY * DT).min(MAX_FALL);
        // 3. The library: move, collide and slide, and keep what is left of the velocity.
        let contacts = hero.move_and_slide(&map, &mut velocity, DT, MoveOptions::default())?;
        run.frames_riding += u32::from(riding);
        run.frames += 1;
        if frame.is_multiple_of(3) {
            run.trail.push(hero.position);
        }
        let goal = contacts
            .ground
            .is_some_and(|g| g.flags.contains(SegmentFlags::ONE_WAY) && hero.position.x > 26.0);
        run.reached_goal |= goal;
        // 4. The picture: the platform, the hero's box and its trail.
        if let Some(animation) = animation.as_deref_mut()
            && frame.is_multiple_of(3)
        {
            picture.clear();
            picture.temporaries(&map).polyline(&run.trail);
            picture.area(Aabb::from_center(hero.position, HALF), HERO);
            animation.push(&picture)?;
        }
        if goal {
            break;
        }
    }
    Ok(run)
}

const HERO: Rgba = Rgba::opaque(40, 120, 220);

fn main() -> Result<(), Box<dyn Error>> {
    let gif = output_path("platformer.gif")?;
    let map = ascii::parse(LEVEL, "platformer.txt", 1.0)?;
    let canvas = Canvas::new(&map, &RenderOptions::default().with_pixels_per_cell(20.0))?;
    let mut animation = Animation::new(&canvas)?;
    let run = play(Some(&mut animation))?;
    animation.save_gif(&gif)?;
    // The still picture: the platform's track, the trail, the box every 24 frames.
    let mut picture = Picture::new();
    let track = Aabb::from_corners(
        Vec2::new(15.0, PLATFORM_Y),
        Vec2::new(23.0, PLATFORM_Y + 0.1),
    );
    picture.area(track, Rgba::opaque(150, 90, 200));
    picture.polyline(&run.trail);
    for at in run.trail.iter().step_by(8) {
        picture.area(Aabb::from_center(*at, HALF), HERO.with_alpha(90));
    }
    let png = gif.with_extension("png");
    canvas.render(&picture).save_png(&png)?;
    println!(
        "platformer: {} frames, {} jumps, {} frames riding the platform, goal {}",
        run.frames,
        run.jumps,
        run.frames_riding,
        if run.reached_goal {
            "reached"
        } else {
            "missed"
        }
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
    fn the_box_lands_on_the_moving_platform_rides_it_and_reaches_the_goal()
    -> Result<(), Box<dyn Error>> {
        let run = play(None)?;
        assert!(run.frames_riding > 30, "rode {} frames", run.frames_riding);
        assert!(run.reached_goal, "after {} frames", run.frames);
        Ok(())
    }
}
