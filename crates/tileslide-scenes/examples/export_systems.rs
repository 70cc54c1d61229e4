//! Writes fixed runs of the core's character, paths and hit volumes, and the core's answers
//! on them, to files other languages read: the Python package's tests replay the inputs
//! and check their answers against these, bit for bit.
//!
//! `cargo run -p tileslide-scenes --example export_systems -- DIR` writes, in DIR (every
//! number a little-endian `float32`; whole numbers are exact in it):
//! - `character_map.txt`: the character's room (ASCII, unit cells);
//! - `character_{box,circle}_in.f32`: for each step of a run of `move_and_slide`, rows
//!   `vx, vy, dt, drop_through, x0, y0, x1, y1, pvx, pvy`: the velocity passed in, the
//!   time step, whether it drops through one-way platforms, and the moving platform
//!   (owner 7, a solid segment facing up, submitted anew each step) with its velocity;
//! - `character_{box,circle}_out.f32`: after each step, rows `x, y, vx, vy, grounded,
//!   col, row, owner`: the position, the velocity kept, and the ground's cell (or -1) or
//!   platform owner (or -1);
//! - `path_queries.f32`: rows `x0, y0, x1, y1, radius` on the dungeon256 map of `export`
//!   (a grid of `max_radius` 1); `path_counts.f32` each path's point count (-1: no path),
//!   `path_lengths.f32` its length (NaN: none), `path_points.f32` the points in order,
//!   rows `x, y`;
//! - `flow_points.f32`: rows `x, y` where the flow field of `flow.json`'s goal and radius
//!   is asked; `flow_directions.f32`, `flow_lattice.f32` rows `dx, dy` (NaN: none),
//!   `flow_distances.f32` (NaN: unreachable);
//! - `hits_objects.f32`: the hit volumes scene, rows `frame, owner, x, y, w, h, mx, my,
//!   team, flip_x, flip_y, invulnerable, swing (-1: none), aim_x, aim_y (NaN: none)`, then
//!   the attack and the vulnerability volume, each `kind (0 circle, 1 rect, 2 capsule,
//!   -1 none), p0..p4, hit` (circle `x, y, r`; rect `x, y, half_width, half_height`;
//!   capsule `x0, y0, x1, y1, r`), registered in row order, frame by frame;
//! - `hits_events.f32`: each frame's `detect` (the team rule), rows `frame, attacker,
//!   victim, attacker_owner, victim_owner, hit_type, accepted, t, x, y`;
//! - `debug_map_segments.f32`: the character map's debug segments, rows `x0, y0, x1, y1,
//!   kind`;
//! - `systems.json`: the runs' settings.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use tileslide::io::ascii;
use tileslide::{
    Character, CharacterShape, ControllerConfig, DebugLines, FlowField, HitObject, HitTypes,
    HitWorld, MoveOptions, NavConfig, NavGrid, Owner, Segment, SegmentFlags, SegmentSource,
    TeamRule, TemporarySegment, TileMap, Vec2, Volume,
};
use tileslide_scenes::{SplitMix64, crowd_candidates, dungeon256};

/// The character's room: ramps, a one-way platform, a step; the moving platform runs
/// above the right half.
const CHARACTER_MAP: &str = "\
####################
#..................#
#..................#
#..................#
#.......====.......#
#..................#
#..............#...#
#....../#\\.....##..#
####################
";
const CHARACTER_STEPS: usize = 300;
const GRAVITY: f32 = 30.0;
const JUMP: f32 = -16.0;
const PLATFORM_OWNER: u64 = 7;
const PLATFORM_Y: f32 = 6.0;
const BOX_HALF: Vec2 = Vec2::new(0.3, 0.45);
const BOX_STEP_HEIGHT: f32 = 0.25;
const CIRCLE_RADIUS: f32 = 0.35;

const PATH_QUERIES: usize = 40;
const PATH_RADII: [f32; 4] = [0.25, 0.3, 0.45, 0.6];
const FLOW_POINTS: usize = 2_000;
const FLOW_RADIUS: f32 = 0.3;

const HIT_FRAMES: usize = 8;
const HIT_OBJECTS: usize = 120;
const HIT_AREA: f32 = 24.0;

fn floats_bytes(values: impl IntoIterator<Item = f32>) -> Vec<u8> {
    values.into_iter().flat_map(f32::to_le_bytes).collect()
}

fn write(dir: &Path, name: &str, bytes: &[u8]) -> Result<(), String> {
    let path = dir.join(name);
    std::fs::write(&path, bytes).map_err(|e| format!("{}: {e}", path.display()))
}

/// The moving platform's left end at `step`.
fn platform_x(step: usize) -> f32 {
    9.0 + 2.0 * (step as f32 * 0.05).sin()
}

/// One run of `move_and_slide`: its inputs and outputs, rows as the module says.
fn character_run(shape: CharacterShape, config: ControllerConfig) -> Result<[Vec<f32>; 2], String> {
    let mut map =
        ascii::parse(CHARACTER_MAP, "character_map.txt", 1.0).map_err(|e| e.to_string())?;
    let mut hero = Character::new(shape, Vec2::new(2.5, 5.0), Vec2::NEG_Y, config)
        .map_err(|e| e.to_string())?;
    let dt = 1.0 / 60.0;
    let (mut inputs, mut outputs) = (Vec::new(), Vec::new());
    let mut velocity = Vec2::ZERO;
    for step in 0..CHARACTER_STEPS {
        let x0 = platform_x(step);
        let platform_velocity = Vec2::new((x0 - platform_x(step.saturating_sub(1))) / dt, 0.0);
        map.clear_temporaries();
        map.add_temporary(TemporarySegment {
            segment: Segment::new(Vec2::new(x0, PLATFORM_Y), Vec2::new(x0 + 2.0, PLATFORM_Y)),
            normal: Vec2::NEG_Y,
            flags: SegmentFlags::SOLID,
            owner: Owner(PLATFORM_OWNER),
            velocity: platform_velocity,
        })
        .map_err(|e| e.to_string())?;
        velocity.x = match step {
            0..150 => 4.0,
            150..230 => -4.0,
            _ => 2.0,
        };
        velocity.y += GRAVITY * dt;
        // Hops: a jump every 20 steps when on the ground.
        if step % 20 == 0 && hero.ground().is_some() {
            velocity.y = JUMP;
        }
        let drop_through = (170..185).contains(&step);
        inputs.extend([
            velocity.x,
            velocity.y,
            dt,
            f32::from(u8::from(drop_through)),
            x0,
            PLATFORM_Y,
            x0 + 2.0,
            PLATFORM_Y,
            platform_velocity.x,
            platform_velocity.y,
        ]);
        let contacts = hero
            .move_and_slide(&map, &mut velocity, dt, MoveOptions { drop_through })
            .map_err(|e| e.to_string())?;
        let (col, row, owner) = match contacts.ground.map(|g| g.source) {
            Some(SegmentSource::Tile { segment, .. }) => {
                (segment.cell.col as f32, segment.cell.row as f32, -1.0)
            }
            Some(SegmentSource::Temporary { owner, .. }) => (-1.0, -1.0, owner.0 as f32),
            _ => (-1.0, -1.0, -1.0),
        };
        let p = hero.position;
        let grounded = f32::from(u8::from(contacts.is_grounded()));
        outputs.extend([p.x, p.y, velocity.x, velocity.y, grounded, col, row, owner]);
    }
    Ok([inputs, outputs])
}

fn export_characters(dir: &Path) -> Result<(), String> {
    write(dir, "character_map.txt", CHARACTER_MAP.as_bytes())?;
    let map = ascii::parse(CHARACTER_MAP, "character_map.txt", 1.0).map_err(|e| e.to_string())?;
    let mut lines = DebugLines::new();
    map.debug_lines(&mut lines);
    write(
        dir,
        "debug_map_segments.f32",
        &floats_bytes(lines.segments().iter().flat_map(|s| {
            let (a, b) = (s.segment.a, s.segment.b);
            [a.x, a.y, b.x, b.y, f32::from(s.kind as u8)]
        })),
    )?;
    let boxed = CharacterShape::rect(BOX_HALF).map_err(|e| e.to_string())?;
    let box_config = ControllerConfig {
        step_height: BOX_STEP_HEIGHT,
        ..ControllerConfig::default()
    };
    let circle = CharacterShape::circle(CIRCLE_RADIUS).map_err(|e| e.to_string())?;
    for (name, shape, config) in [
        ("box", boxed, box_config),
        ("circle", circle, ControllerConfig::default()),
    ] {
        let [inputs, outputs] = character_run(shape, config)?;
        write(
            dir,
            &format!("character_{name}_in.f32"),
            &floats_bytes(inputs),
        )?;
        write(
            dir,
            &format!("character_{name}_out.f32"),
            &floats_bytes(outputs),
        )?;
    }
    Ok(())
}

fn export_paths(dir: &Path, map: &TileMap, open: &[Vec2]) -> Result<(), String> {
    let nav = NavGrid::new(map, NavConfig::default()).map_err(|e| e.to_string())?;
    let mut rng = SplitMix64::new(0x9A7B);
    let (mut queries, mut counts, mut lengths, mut points) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for k in 0..PATH_QUERIES {
        // The first starts in the border wall: no path.
        let from = if k == 0 {
            Vec2::new(0.5, 0.5)
        } else {
            rng.pick(open).ok_or("no open cell")?
        };
        let to = rng.pick(open).ok_or("no open cell")?;
        let radius = PATH_RADII[k % PATH_RADII.len()];
        queries.extend([from.x, from.y, to.x, to.y, radius]);
        match nav
            .find_path(map, from, to, radius)
            .map_err(|e| e.to_string())?
        {
            None => {
                counts.push(-1.0);
                lengths.push(f32::NAN);
            }
            Some(path) => {
                counts.push(path.points().len() as f32);
                lengths.push(path.length());
                points.extend(path.points().iter().flat_map(|p| [p.x, p.y]));
            }
        }
    }
    write(dir, "path_queries.f32", &floats_bytes(queries))?;
    write(dir, "path_counts.f32", &floats_bytes(counts))?;
    write(dir, "path_lengths.f32", &floats_bytes(lengths))?;
    write(dir, "path_points.f32", &floats_bytes(points))?;

    let goal = rng.pick(open).ok_or("no open cell")?;
    let field = FlowField::new(&nav, map, goal, FLOW_RADIUS).map_err(|e| e.to_string())?;
    let (mut at, mut directions, mut lattice, mut distances) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for _ in 0..FLOW_POINTS {
        let p = rng.pick(open).ok_or("no open cell")?
            + Vec2::new(rng.range(-0.5, 0.5), rng.range(-0.5, 0.5));
        at.extend([p.x, p.y]);
        let d = field.direction(&nav, map, p).map_err(|e| e.to_string())?;
        directions.extend(d.map_or([f32::NAN; 2], |d| [d.x, d.y]));
        let d = field
            .lattice_direction(&nav, map, p)
            .map_err(|e| e.to_string())?;
        lattice.extend(d.map_or([f32::NAN; 2], |d| [d.x, d.y]));
        let d = field.distance(&nav, map, p).map_err(|e| e.to_string())?;
        distances.push(d.unwrap_or(f32::NAN));
    }
    write(dir, "flow_points.f32", &floats_bytes(at))?;
    write(dir, "flow_directions.f32", &floats_bytes(directions))?;
    write(dir, "flow_lattice.f32", &floats_bytes(lattice))?;
    write(dir, "flow_distances.f32", &floats_bytes(distances))?;
    write(
        dir,
        "flow.json",
        format!(
            "{{\"goal\": [{}, {}], \"radius\": {FLOW_RADIUS}}}\n",
            goal.x, goal.y
        )
        .as_bytes(),
    )
}

/// A random volume: its row (`kind, p0..p4, hit`) and the volume.
fn random_volume(rng: &mut SplitMix64, hit: HitTypes) -> Result<([f32; 7], Volume), String> {
    let (x, y) = (rng.range(0.0, 1.5), rng.range(0.0, 1.5));
    let bits = hit.bits() as f32;
    let volume = match rng.below(3) {
        0 => {
            let r = rng.range(0.2, 0.8);
            (
                [0.0, x, y, r, 0.0, 0.0, bits],
                Volume::circle(Vec2::new(x, y), r, hit),
            )
        }
        1 => {
            let (w, h) = (rng.range(0.2, 0.8), rng.range(0.2, 0.8));
            (
                [1.0, x, y, w, h, 0.0, bits],
                Volume::rect(Vec2::new(x, y), Vec2::new(w, h), hit),
            )
        }
        _ => {
            let (x1, y1, r) = (
                rng.range(0.0, 2.0),
                rng.range(0.0, 2.0),
                rng.range(0.05, 0.3),
            );
            (
                [2.0, x, y, x1, y1, r, bits],
                Volume::capsule(Vec2::new(x, y), Vec2::new(x1, y1), r, hit),
            )
        }
    };
    Ok((volume.0, volume.1.map_err(|e| e.to_string())?))
}

fn export_hits(dir: &Path) -> Result<(), String> {
    let mut rng = SplitMix64::new(0x417);
    // Each object keeps its start, motion and look; its volumes change every frame.
    let objects: Vec<(Vec2, Vec2, u32, bool, bool, Option<Vec2>)> = (0..HIT_OBJECTS)
        .map(|k| {
            let start = Vec2::new(rng.range(0.0, HIT_AREA), rng.range(0.0, HIT_AREA));
            let motion = if k % 3 == 0 {
                Vec2::ZERO
            } else {
                Vec2::new(rng.range(-1.5, 1.5), rng.range(-1.5, 1.5))
            };
            let aim = (k % 5 == 0).then(|| Vec2::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0)));
            (start, motion, (k % 3) as u32, k % 2 == 0, k % 7 == 3, aim)
        })
        .collect();
    let mut world = HitWorld::new();
    let (mut rows, mut events) = (Vec::new(), Vec::new());
    for frame in 0..HIT_FRAMES {
        world.begin_frame();
        for (k, &(start, motion, team, flip_x, flip_y, aim)) in objects.iter().enumerate() {
            let position = start + motion * (frame as f32 + 1.0);
            let size = Vec2::new(1.0, 1.5);
            let invulnerable = k % 11 == 5 && frame % 2 == 0;
            let swing = (k % 4 == 0 && frame < 5).then_some(k as u64);
            let object = HitObject {
                motion,
                facing: tileslide::Facing { flip_x, flip_y },
                aim,
                team,
                invulnerable,
                swing,
                ..HitObject::new(Owner(k as u64), position, size)
            };
            let attack_types = if k % 6 == 1 {
                HitTypes::COLLECT
            } else {
                HitTypes::HIT
            };
            let vulnerable_types = HitTypes::HIT | HitTypes::COLLECT;
            let no_attack = k % 9 == 2;
            let (attack_row, attack) = random_volume(&mut rng, attack_types)?;
            let (vulnerable_row, vulnerable) = random_volume(&mut rng, vulnerable_types)?;
            let attack_row = if no_attack { [-1.0; 7] } else { attack_row };
            let attack: &[Volume] = if no_attack { &[] } else { &[attack] };
            world
                .register(object, attack, &[vulnerable])
                .map_err(|e| e.to_string())?;
            let aim = aim.unwrap_or(Vec2::NAN);
            rows.extend([
                frame as f32,
                k as f32,
                position.x,
                position.y,
                size.x,
                size.y,
                motion.x,
                motion.y,
                team as f32,
                f32::from(u8::from(flip_x)),
                f32::from(u8::from(flip_y)),
                f32::from(u8::from(invulnerable)),
                swing.map_or(-1.0, |s| s as f32),
                aim.x,
                aim.y,
            ]);
            rows.extend(attack_row);
            rows.extend(vulnerable_row);
        }
        for e in world.detect(&mut TeamRule) {
            events.extend([
                frame as f32,
                e.attacker.0 as f32,
                e.victim.0 as f32,
                e.attacker_owner.0 as f32,
                e.victim_owner.0 as f32,
                e.hit_type.bits() as f32,
                f32::from(u8::from(e.accepted)),
                e.t,
                e.point.x,
                e.point.y,
            ]);
        }
    }
    write(dir, "hits_objects.f32", &floats_bytes(rows))?;
    write(dir, "hits_events.f32", &floats_bytes(events))
}

fn run() -> Result<(), String> {
    let dir = PathBuf::from(std::env::args().nth(1).ok_or("usage: export_systems DIR")?);
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    export_characters(&dir)?;
    let grid = dungeon256();
    let map = ascii::parse(&grid.to_ascii(), "dungeon256.txt", 1.0).map_err(|e| e.to_string())?;
    export_paths(&dir, &map, &crowd_candidates(&grid))?;
    export_hits(&dir)?;
    write(
        &dir,
        "systems.json",
        format!(
            "{{\"character_steps\": {CHARACTER_STEPS}, \"platform_owner\": {PLATFORM_OWNER}, \
             \"box_half\": [{}, {}], \"box_step_height\": {BOX_STEP_HEIGHT}, \
             \"circle_radius\": {CIRCLE_RADIUS}, \"hit_frames\": {HIT_FRAMES}, \
             \"hit_objects\": {HIT_OBJECTS}}}\n",
            BOX_HALF.x, BOX_HALF.y
        )
        .as_bytes(),
    )
}

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("export_systems: {e}");
            ExitCode::FAILURE
        }
    }
}
