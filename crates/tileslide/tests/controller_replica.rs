//! A scripted run across real Replica Island levels (`../shared/data/replica-island/`): a
//! box the size of the game's hero starts at each level's player spawn and runs right,
//! jumping at walls and gaps, for a minute of game time at 60 steps per second. Every step
//! it must end outside solid, and its centre must not have crossed a solid face since the
//! last step (it never falls through a floor or passes a wall). Three levels that run left
//! to right it must cross from the spawn to the right wall.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use crate::replica_support;

use std::sync::Arc;

use replica_support::{TILE, data_dir, level_names, raw_level, read};
use tileslide::io::replica;
use tileslide::{
    Aabb, Character, CharacterShape, Contacts, ControllerConfig, MoveOptions, QueryFilter, Ray,
    SegmentFlags, TileMap, Vec2,
};

/// The hero's box, in pixels: 24 × 48.
const HALF: Vec2 = Vec2::new(12.0, 24.0);
/// Levels that run left to right with nothing a runner cannot jump: the run must cross
/// them, from the spawn to within three tiles of the right wall.
const CROSSED: [&str; 3] = [
    "level_0_1_sewer_kyle.bin",
    "level_2_4_grass.bin",
    "level_3_6_sewer.bin",
];

/// Steps per second, and how long each run lasts.
const RATE: f32 = 60.0;
const SECONDS: f32 = 60.0;
/// Run speed, jump speed and gravity, in pixels per second (per second).
const RUN: f32 = 180.0;
const JUMP: f32 = 520.0;
const GRAVITY: f32 = 1200.0;

/// The player spawn of a level (object layer value 0) as the hero's centre (y up, pixels):
/// standing a pixel above the bottom of the spawn cell, where the game puts its objects'
/// feet. `None` for a level without one (cut scenes).
fn spawn(bytes: &[u8]) -> Option<Vec2> {
    let level = raw_level(bytes);
    let layer = level.layers.iter().find(|l| l.kind == 2)?;
    let (w, h) = (layer.width as usize, layer.height as usize);
    let cells = bytes.get(layer.cells_at..layer.cells_at + w * h)?;
    let at = cells.iter().position(|&b| b == 0)?;
    let (col, file_row) = (at % w, at / w);
    let row = h - 1 - file_row;
    Some(Vec2::new(
        (col as f32 + 0.5) * TILE,
        row as f32 * TILE + HALF.y + 1.0,
    ))
}

/// Whether the hero at `p` overlaps a solid segment by more than a twentieth of a pixel.
fn in_solid(map: &TileMap, p: Vec2) -> bool {
    let probe = Aabb::from_center(p, HALF - Vec2::splat(0.05));
    map.segments_overlapping_aabb(&probe)
        .iter()
        .any(|s| s.flags.contains(SegmentFlags::SOLID))
}

/// What one run did.
#[derive(Debug)]
struct Run {
    /// Steps on the ground, jumps, and the furthest right the hero got (pixels from the
    /// spawn).
    grounded_steps: usize,
    jumps: usize,
    progress: f32,
    /// Whether it fell out of the bottom of the level (a pit).
    fell_out: bool,
}

/// Runs the hero right from `start` through `map`, checking the invariants every step.
fn run(name: &str, map: &TileMap, start: Vec2) -> Run {
    let config = ControllerConfig {
        snap_distance: 10.0,
        skin: 0.03,
        ..ControllerConfig::default()
    };
    let shape = CharacterShape::rect(HALF).unwrap();
    let mut hero = Character::new(shape, start, Vec2::Y, config).unwrap();
    assert!(!in_solid(map, start), "{name}: the spawn is inside solid");
    let dt = 1.0 / RATE;
    let mut vy = 0.0f32;
    let mut contacts = Contacts::default();
    let solid = QueryFilter::default().with_mask(SegmentFlags::SOLID);
    let mut result = Run {
        grounded_steps: 0,
        jumps: 0,
        progress: 0.0,
        fell_out: false,
    };
    for k in 0..(SECONDS * RATE) as usize {
        let p = hero.position;
        if contacts.is_grounded() {
            // Jump at a wall, or where the ground ends a little ahead.
            let ahead = p + Vec2::new(HALF.x + 10.0, 0.0);
            let gap = map
                .cast_ray(
                    Ray::between(ahead, ahead - Vec2::new(0.0, HALF.y + 40.0)),
                    &QueryFilter::default(),
                )
                .is_none();
            if contacts.right.is_some() || gap {
                vy = JUMP;
                result.jumps += 1;
            }
        }
        vy -= GRAVITY * dt;
        contacts = hero
            .move_by(map, Vec2::new(RUN * dt, vy * dt), MoveOptions::default())
            .unwrap();
        if contacts.is_grounded() {
            result.grounded_steps += 1;
            vy = vy.max(0.0);
        }
        if contacts.ceiling.is_some() {
            vy = vy.min(0.0);
        }
        let now = hero.position;
        assert!(
            !in_solid(map, now),
            "{name} step {k}: inside solid at {now:?}"
        );
        assert!(
            map.cast_ray(Ray::between(p, now), &solid).is_none(),
            "{name} step {k}: the centre crossed a wall from {p:?} to {now:?}"
        );
        result.progress = result.progress.max(now.x - start.x);
        if now.y < -4.0 * TILE {
            result.fell_out = true;
            break;
        }
    }
    result
}

#[test]
fn a_hero_runs_and_jumps_across_every_level_without_passing_a_wall() {
    let Some(dir) = data_dir() else {
        return;
    };
    let set = Arc::new(replica::load_tile_set(dir.join("collision.bin")).unwrap());
    let mut levels = 0;
    let mut crossed = 0;
    let mut report = Vec::new();
    for name in level_names(&dir) {
        let bytes = read(&dir, &name);
        let Some(start) = spawn(&bytes) else {
            continue;
        };
        // A level the loader refuses (a truncated file) has no world to run in.
        let Ok(map) = replica::load_level(dir.join(&name), set.clone()) else {
            continue;
        };
        let result = run(&name, &map, start);
        report.push(format!("{name}: {result:?}"));
        levels += 1;
        // It stood on the ground, and got somewhere; across the levels it can cross.
        assert!(result.grounded_steps > 60, "{name}: {result:?}");
        assert!(result.progress > 2.0 * TILE, "{name}: {result:?}");
        if CROSSED.contains(&name.as_str()) {
            let to_the_end = map.width() as f32 * TILE - start.x;
            assert!(
                result.progress >= to_the_end - 3.0 * TILE,
                "{name}: {result:?}, {to_the_end} px to the right wall"
            );
            crossed += 1;
        }
    }
    assert_eq!(crossed, CROSSED.len());
    eprintln!("{}", report.join("\n"));
    assert!(levels >= 20, "only {levels} levels with a player spawn");
}
