//! Sword swing: a knight swings a sword through three slimes, to the right and then to the
//! left. The blade overlaps each slime for several frames of a swing, but each slime it
//! reaches is hit once per swing; the slime out of reach is never hit.
//!
//! `cargo run -p tileslide --example sword_swing [OUT.gif]` writes the run as an animated
//! GIF and a PNG of one frame (default `target/examples-out/`).
//!
//! Each frame the game registers every object in a [`HitWorld`] with the attack and
//! vulnerability volumes of its animation frame, in its own coordinates; the world mirrors
//! them for objects facing left, finds the pairs, and reports the hits. Giving the attack a
//! `swing` id makes each victim take it once until the swing ends.

use std::collections::HashMap;
use std::error::Error;
use std::path::{Path, PathBuf};

use tileslide::io::ascii;
use tileslide::{
    Circle, Facing, HitObject, HitTypes, HitWorld, Owner, TeamRule, Vec2, Volume, VolumeShape,
};
use tileslide_render::{Animation, Canvas, Picture, RenderOptions, VolumeKind};

const LEVEL: &str = "\
####################
#..................#
#..................#
#..................#
#..................#
#..................#
#..................#
####################";

const SIZE: Vec2 = Vec2::new(1.0, 1.0); // every object's box: volumes mirror about it
const KNIGHT: Vec2 = Vec2::new(9.5, 3.5); // top-left corners (an object's local origin)
const SLIMES: [Vec2; 4] = [
    Vec2::new(11.3, 3.2),
    Vec2::new(10.8, 4.8),
    Vec2::new(7.5, 3.8),
    Vec2::new(15.0, 3.5), // out of reach
];
const SWING_FRAMES: u32 = 16;
const SWING_EVERY: u32 = 30;
const FRAMES: u32 = 240;

/// The sword's volumes in the knight's coordinates, `k` frames into a swing: three
/// circles along the blade, sweeping from overhead (−100°) to the feet (+70°) in front.
fn blade(k: u32) -> Result<[Volume; 3], Box<dyn Error>> {
    let angle = (-100.0 + 170.0 * k as f32 / (SWING_FRAMES - 1) as f32).to_radians();
    let dir = Vec2::from_angle(angle);
    let hilt = SIZE * 0.5;
    let circle = |along: f32, r: f32| Volume::circle(hilt + dir * along, r, HitTypes::HIT);
    Ok([circle(0.7, 0.25)?, circle(1.1, 0.25)?, circle(1.5, 0.25)?])
}

/// Where a volume of an object is in the world: placed at its position, mirrored if it
/// faces left (what the hit world does with it too), for the picture.
fn placed(volume: &Volume, at: Vec2, facing: Facing) -> VolumeShape {
    match volume.shape {
        VolumeShape::Circle(c) => {
            let x = if facing.flip_x {
                SIZE.x - c.center.x
            } else {
                c.center.x
            };
            VolumeShape::Circle(Circle::new(at + Vec2::new(x, c.center.y), c.radius))
        }
        other => other,
    }
}

#[derive(Default)]
struct Run {
    swings: u64,
    /// Accepted hits per (swing, slime's key).
    hits: HashMap<(u64, u64), u32>,
    /// The hits the same swings would have made without a swing id: one for every frame
    /// the blade touches a slime.
    hits_without_swing: u32,
}

fn play(mut animation: Option<&mut Animation<'_>>) -> Result<(Run, Picture), Box<dyn Error>> {
    let mut world = HitWorld::new();
    let mut plain = HitWorld::new(); // the same objects, but the knight's swing has no id
    let body = [Volume::circle(SIZE * 0.5, 0.45, HitTypes::ANY)?];
    let mut run = Run::default();
    let mut picture = Picture::new();
    let mut still = None;
    let mut events = Vec::new();
    for frame in 0..FRAMES {
        world.begin_frame();
        plain.begin_frame();
        picture.clear();
        // The knight: swinging for SWING_FRAMES out of every SWING_EVERY, facing right for
        // the first half of the run and left for the second.
        let (swing, k) = (u64::from(frame / SWING_EVERY), frame % SWING_EVERY);
        let facing = Facing {
            flip_x: frame >= FRAMES / 2,
            flip_y: false,
        };
        let knight = HitObject {
            team: 1,
            facing,
            swing: (k < SWING_FRAMES).then_some(swing),
            ..HitObject::new(Owner(0), KNIGHT, SIZE)
        };
        let swinging = blade(k)?;
        let sword: &[Volume] = if k < SWING_FRAMES { &swinging } else { &[] };
        world.register(knight, sword, &body)?;
        plain.register(
            HitObject {
                swing: None,
                ..knight
            },
            sword,
            &body,
        )?;
        for v in sword {
            picture.volume(placed(v, KNIGHT, facing), VolumeKind::Attack);
        }
        picture.body(Circle::new(KNIGHT + SIZE * 0.5, 0.45));
        // The slimes: team 2, a body that takes any hit, no attack.
        for (i, &at) in SLIMES.iter().enumerate() {
            let slime = HitObject {
                team: 2,
                ..HitObject::new(Owner(1 + i as u64), at, SIZE)
            };
            world.register(slime, &[], &body)?;
            plain.register(slime, &[], &body)?;
            picture.volume(
                placed(&body[0], at, Facing::default()),
                VolumeKind::Vulnerability,
            );
        }
        run.swings = swing + 1;
        let plain_hits = plain
            .detect(&mut TeamRule)
            .iter()
            .filter(|e| e.accepted)
            .count();
        run.hits_without_swing += plain_hits as u32;
        // The hits, by the built-in rule: other teams only.
        events.clear();
        events.extend_from_slice(world.detect(&mut TeamRule));
        for event in &events {
            // (Only the knight attacks; a slime's key is 1 + its index.)
            if let Some(victim) = world.object(event.victim)
                && event.accepted
            {
                *run.hits.entry((swing, victim.owner.0)).or_default() += 1;
            }
            picture.hit_event(&world, event);
        }
        // The still picture: the first frame with a hit.
        if still.is_none() && events.iter().any(|e| e.accepted) {
            still = Some(picture.clone());
        }
        if let Some(animation) = animation.as_deref_mut() {
            animation.push(&picture)?;
        }
    }
    Ok((run, still.unwrap_or_default()))
}

fn main() -> Result<(), Box<dyn Error>> {
    let gif = output_path("sword_swing.gif")?;
    let map = ascii::parse(LEVEL, "arena.txt", 1.0)?;
    let canvas = Canvas::new(&map, &RenderOptions::default().with_pixels_per_cell(24.0))?;
    let mut animation = Animation::new(&canvas)?.with_frame_delay(4);
    let (run, still) = play(Some(&mut animation))?;
    animation.save_gif(&gif)?;
    let png = gif.with_extension("png");
    canvas.render(&still).save_png(&png)?;
    println!("sword_swing: {} swings over {FRAMES} frames", run.swings);
    for key in 1..=SLIMES.len() as u64 {
        let swings_hit = run.hits.keys().filter(|(_, k)| *k == key).count();
        let total: u32 = run
            .hits
            .iter()
            .filter(|((_, k), _)| *k == key)
            .map(|(_, n)| n)
            .sum();
        println!("  slime {key}: hit by {swings_hit} swings, {total} hits in all");
    }
    let hits: u32 = run.hits.values().sum();
    println!(
        "  {hits} hits; without a swing id the same blade would hit {} times",
        run.hits_without_swing
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
    fn each_swing_hits_each_slime_in_reach_once_and_the_far_one_never() -> Result<(), Box<dyn Error>>
    {
        let (run, _) = play(None)?;
        for (&(swing, slime), &n) in &run.hits {
            assert_eq!(n, 1, "swing {swing} hit slime {slime} {n} times");
        }
        let hit_by = |key: u64| run.hits.keys().filter(|(_, k)| *k == key).count();
        // Facing right the first four swings reach slimes 1 and 2; facing left, slime 3.
        assert_eq!((hit_by(1), hit_by(2), hit_by(3), hit_by(4)), (4, 4, 4, 0));
        // The rule does some work: the blade touches the slimes for several frames.
        assert!(run.hits_without_swing > 12, "{}", run.hits_without_swing);
        Ok(())
    }
}
