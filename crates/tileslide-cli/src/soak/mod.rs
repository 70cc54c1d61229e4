//! `tileslide soak`: a long randomized session with every promise audited every step.
//!
//! A cave is dug out and built up cell by cell while bodies wander, dash up to 60 cells in a
//! step and follow a flow field, platformer characters run, jump and drop through moving
//! one-way platforms, every body and character registers hit volumes in a world of each
//! broadphase, rays, circle casts and paths are asked of the map, and bad values and stale
//! handles are handed to the entry points. Every so often the world is saved (serde, CBOR),
//! restored into a second world, and both run on side by side, compared bit for bit. The
//! report gives steps per second and, per kind of check, how many ran and how many failed,
//! with the first failures in words; the command fails if any did. See docs/soak.md.

mod audit;
mod checks;
mod world;

use std::time::Instant;

use anyhow::{Context, bail};
use serde::{Serialize, de::DeserializeOwned};
use serde_json::json;
use tileslide::{Bodies, FlowField, HitWorld, MapEdits, NavGrid};

pub use audit::{Audit, Kind};
pub use world::{Settings, Sim};

/// The most bodies a soak takes (the map grows with them: about six cells a body).
pub const MAX_BODIES: u32 = 200_000;
/// The most characters a soak takes.
pub const MAX_CHARACTERS: u32 = 10_000;
/// The most rays a step casts.
pub const MAX_RAYS: u32 = 10_000;
/// The most moving platforms.
pub const MAX_PLATFORMS: u32 = 1_000;

/// `tileslide soak`'s arguments.
#[derive(clap::Args, Debug)]
pub struct SoakArgs {
    /// Steps to run.
    #[arg(long, default_value_t = 10_000)]
    pub steps: u64,
    /// The seed of every random choice: the same seed and sizes give the same run.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Bodies (circles, and pairs of circles) alive at a time.
    #[arg(long, default_value_t = 1_000)]
    pub bodies: u32,
    /// Platformer characters (circles and boxes).
    #[arg(long, default_value_t = 16)]
    pub characters: u32,
    /// Moving one-way platforms.
    #[arg(long, default_value_t = 8)]
    pub platforms: u32,
    /// Rays cast a step.
    #[arg(long, default_value_t = 16)]
    pub rays: u32,
    /// Steps between snapshots restored into a second world, which then runs beside the
    /// first for 30 steps (0: never).
    #[arg(long, default_value_t = 1_000)]
    pub snapshot_every: u64,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// Runs the soak and prints its report; an error if any check failed.
pub fn run(args: &SoakArgs) -> anyhow::Result<()> {
    for (name, value, max) in [
        ("--bodies", args.bodies, MAX_BODIES),
        ("--characters", args.characters, MAX_CHARACTERS),
        ("--rays", args.rays, MAX_RAYS),
        ("--platforms", args.platforms, MAX_PLATFORMS),
    ] {
        if value > max {
            bail!("{name} {value}: at most {max}");
        }
    }
    let settings = Settings {
        seed: args.seed,
        bodies: args.bodies,
        characters: args.characters,
        platforms: args.platforms,
        rays: args.rays,
        dig_every: 4,
        // A path after map edits first brings its radius class's landmarks up to date (a
        // search over the whole lattice): at every eighth step that was half the soak's time.
        path_every: 32,
        snapshot_every: args.snapshot_every,
        twin_steps: 30,
    };
    let started = Instant::now();
    let mut sim = Sim::new(settings).context("building the soak's world")?;
    let mut audit = Audit {
        live: true,
        ..Audit::default()
    };
    let mut twin: Option<(Sim, u64)> = None;
    let progress = !args.json && args.steps >= 10_000;
    for step in 1..=args.steps {
        if settings.snapshot_every > 0 && step % settings.snapshot_every == 0 && twin.is_none() {
            twin = Some((restored(&sim)?, settings.twin_steps));
        }
        sim.step(&mut audit)?;
        if let Some((other, left)) = &mut twin {
            other.step(&mut Audit::default())?;
            *left -= 1;
            let (mine, theirs) = (digest(&sim), digest(other));
            if mine != theirs {
                audit.count(Kind::Snapshot);
                audit.violation(
                    Kind::Snapshot,
                    step,
                    format!(
                        "restored at step {}, differs {} steps later",
                        step + *left + 1 - settings.twin_steps,
                        settings.twin_steps - *left
                    ),
                );
                twin = None;
            } else if *left == 0 {
                audit.count(Kind::Snapshot);
                twin = None;
            }
        }
        if progress && step % (args.steps / 10) == 0 {
            eprintln!(
                "soak: step {step} of {}, {:.0} steps/s, {} violations",
                args.steps,
                step as f64 / started.elapsed().as_secs_f64(),
                audit.violations()
            );
        }
    }
    let seconds = started.elapsed().as_secs_f64();
    report(args, &sim, &audit, seconds);
    let violations = audit.violations();
    if violations > 0 {
        bail!("the soak found {violations} violations");
    }
    Ok(())
}

/// `value` written to CBOR and read back, as a game saves and loads it.
fn round_trip<T: Serialize + DeserializeOwned>(value: &T, what: &str) -> anyhow::Result<T> {
    let mut bytes = Vec::new();
    ciborium::into_writer(value, &mut bytes).with_context(|| format!("saving {what}"))?;
    ciborium::from_reader(bytes.as_slice()).with_context(|| format!("restoring {what}"))
}

/// A second world restored from `sim`'s snapshot: the bodies, characters and hit worlds
/// through CBOR, the map as built with the edits restored, the navigation grid and flow
/// field built anew, the game's own state cloned.
fn restored(sim: &Sim) -> anyhow::Result<Sim> {
    let bodies: Bodies = round_trip(&sim.bodies, "the bodies")?;
    let hits: [HitWorld; 2] = [
        round_trip(&sim.hits[0], "a hit world")?,
        round_trip(&sim.hits[1], "a hit world")?,
    ];
    let edits: MapEdits = round_trip(&sim.map.edits(), "the map's edits")?;
    let mut map = sim.base.clone();
    map.restore_edits(&edits)?;
    let nav = NavGrid::new(&map, world::nav_config())?;
    let flow = FlowField::new(&nav, &map, sim.game.goal, world::MAX_BODY_RADIUS)?;
    let mut game = sim.game.clone();
    for r in &mut game.runners {
        r.character = round_trip(&r.character, "a character")?;
    }
    Ok(Sim {
        base: sim.base.clone(),
        map,
        nav,
        flow,
        bodies,
        hits,
        game,
    })
}

/// FNV-1a 64 of every body's and character's position, the characters' velocities and the
/// last frame's hit events, in the game's order.
fn digest(sim: &Sim) -> u64 {
    let mut hash = 0xcbf2_9ce4_8422_2325u64;
    let mut eat = |bits: u32| {
        for byte in bits.to_le_bytes() {
            hash = (hash ^ u64::from(byte)).wrapping_mul(0x0100_0000_01b3);
        }
    };
    for b in &sim.game.placed {
        let p = sim.position(b.handle);
        eat(p.x.to_bits());
        eat(p.y.to_bits());
    }
    for r in &sim.game.runners {
        for v in [r.character.position, r.velocity] {
            eat(v.x.to_bits());
            eat(v.y.to_bits());
        }
    }
    for e in sim.hits[0].events() {
        eat(e.attacker.0);
        eat(e.victim.0);
        eat(e.t.to_bits());
    }
    hash
}

fn report(args: &SoakArgs, sim: &Sim, audit: &Audit, seconds: f64) {
    let rate = args.steps as f64 / seconds.max(1e-9);
    let (w, h) = (sim.map.width(), sim.map.height());
    let hash = format!("{:#018x}", digest(sim));
    if args.json {
        let kinds: serde_json::Map<String, serde_json::Value> = audit
            .kinds
            .iter()
            .map(|(kind, t)| {
                let first: Vec<_> = t
                    .first
                    .iter()
                    .map(|(step, what)| json!({"step": step, "what": what}))
                    .collect();
                (
                    kind.name().to_owned(),
                    json!({"checks": t.checks, "violations": t.violations, "first": first}),
                )
            })
            .collect();
        let out = json!({
            "steps": args.steps,
            "seed": args.seed,
            "seconds": seconds,
            "steps_per_second": rate,
            "map": [w, h],
            "bodies": sim.game.placed.len(),
            "characters": sim.game.runners.len(),
            "platforms": sim.game.platforms.len(),
            "checks": kinds,
            "violations": audit.violations(),
            "hash": hash,
        });
        println!("{out}");
        return;
    }
    println!(
        "soak: {} steps in {seconds:.1} s ({rate:.0} steps/s), seed {}",
        args.steps, args.seed
    );
    println!(
        "world: {w} × {h} cells, {} bodies, {} characters, {} moving platforms",
        sim.game.placed.len(),
        sim.game.runners.len(),
        sim.game.platforms.len()
    );
    println!("{:<24} {:>14} {:>11}", "check", "runs", "violations");
    for (kind, t) in &audit.kinds {
        println!("{:<24} {:>14} {:>11}", kind.name(), t.checks, t.violations);
        for (step, what) in &t.first {
            println!("    step {step}: {what}");
        }
    }
    println!("final state: {hash}");
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

    use glam::Vec2;
    use tileslide::{Cell, CharacterShape, Circle, io::ascii};

    use super::world::{room_of, rooms};
    use super::*;

    fn small() -> Sim {
        Sim::new(Settings {
            seed: 3,
            bodies: 60,
            characters: 4,
            platforms: 2,
            rays: 4,
            dig_every: 4,
            path_every: 8,
            snapshot_every: 0,
            twin_steps: 0,
        })
        .unwrap()
    }

    /// The centre of the first interior cell for which `pick` holds.
    fn cell_where(sim: &Sim, pick: impl Fn(Cell) -> bool) -> Vec2 {
        let (w, h) = (sim.map.width(), sim.map.height());
        (1..h - 1)
            .flat_map(|r| (1..w - 1).map(move |c| Cell::new(c, r)))
            .find(|&cell| pick(cell))
            .map(|cell| Vec2::new(cell.col as f32 + 0.5, cell.row as f32 + 0.5))
            .expect("no such cell")
    }

    fn violations(audit: &Audit, kind: Kind) -> u64 {
        audit.kinds.get(&kind).map_or(0, |t| t.violations)
    }

    #[test]
    fn a_clean_step_finds_nothing() {
        let mut sim = small();
        let mut audit = Audit::default();
        for _ in 0..20 {
            sim.step(&mut audit).unwrap();
        }
        assert_eq!(audit.violations(), 0, "{audit:?}");
    }

    #[test]
    fn a_body_put_in_a_wall_is_found() {
        let mut sim = small();
        let wall = cell_where(&sim, |c| sim.map.tile(c) == Some(ascii::SOLID));
        let h = sim.game.placed[0].handle;
        sim.bodies.set_position(h, wall).unwrap();
        let mut audit = Audit::default();
        checks::bodies(&mut sim, &mut audit);
        assert!(violations(&audit, Kind::BodyPlace) >= 1, "{audit:?}");
    }

    #[test]
    fn a_body_put_on_another_is_found() {
        let mut sim = small();
        let (a, b) = (sim.game.placed[0].handle, sim.game.placed[1].handle);
        let at = sim.position(b) + Vec2::new(0.01, 0.0);
        sim.bodies.set_position(a, at).unwrap();
        let mut audit = Audit::default();
        checks::bodies(&mut sim, &mut audit);
        assert!(violations(&audit, Kind::BodyPair) >= 1, "{audit:?}");
    }

    #[test]
    fn a_body_that_gets_into_another_room_is_found() {
        let mut sim = small();
        let b = sim
            .game
            .placed
            .iter()
            .find(|b| b.circles.len() == 1)
            .unwrap()
            .clone();
        // A cell walled in on its four sides: a room of its own.
        let open = |sim: &Sim, c: Cell| sim.map.tile(c).is_none();
        let cell = cell_where(&sim, |c| {
            c.col > 2
                && c.row > 2
                && c.col + 3 < sim.map.width()
                && c.row + 3 < sim.map.height()
                && open(&sim, c)
                && sim.clear_for(
                    Vec2::new(c.col as f32 + 0.5, c.row as f32 + 0.5),
                    &[Circle::new(Vec2::ZERO, 2.0)],
                    0.0,
                )
        });
        let at = Cell::new(cell.x as u32, cell.y as u32);
        for n in [
            Cell::new(at.col - 1, at.row),
            Cell::new(at.col + 1, at.row),
            Cell::new(at.col, at.row - 1),
            Cell::new(at.col, at.row + 1),
        ] {
            sim.map.set_tile(n, Some(ascii::SOLID)).unwrap();
        }
        sim.game.rooms = rooms(&sim.map);
        assert_ne!(
            room_of(&sim.map, &sim.game.rooms, cell),
            room_of(&sim.map, &sim.game.rooms, b.last)
        );
        sim.bodies.set_position(b.handle, cell).unwrap();
        let mut audit = Audit::default();
        checks::bodies(&mut sim, &mut audit);
        assert_eq!(violations(&audit, Kind::BodyPlace), 1, "{audit:?}");
        assert!(audit.kinds[&Kind::BodyPlace].first[0].1.contains("room"));
    }

    #[test]
    fn a_character_in_a_wall_is_found() {
        let sim = small();
        let wall = cell_where(&sim, |c| {
            sim.map.tile(c) == Some(ascii::SOLID)
                && sim.map.tile(Cell::new(c.col + 1, c.row)).is_none()
        });
        // Half a cell into the wall from the open cell beside it.
        let p = wall + Vec2::new(0.6, 0.0);
        for shape in [
            CharacterShape::circle(0.3).unwrap(),
            CharacterShape::rect(Vec2::new(0.3, 0.3)).unwrap(),
        ] {
            assert!(checks::character_in_wall(&sim.map, shape, p).is_some());
            assert!(checks::character_in_wall(&sim.map, shape, p + Vec2::new(0.3, 0.0)).is_none());
        }
    }

    #[test]
    fn a_restored_world_runs_as_the_original_and_a_difference_shows() {
        let mut sim = small();
        let mut audit = Audit::default();
        for _ in 0..10 {
            sim.step(&mut audit).unwrap();
        }
        let mut twin = restored(&sim).unwrap();
        for _ in 0..10 {
            sim.step(&mut audit).unwrap();
            twin.step(&mut Audit::default()).unwrap();
            assert_eq!(digest(&sim), digest(&twin));
        }
        let h = twin.game.placed[0].handle;
        let p = twin.position(h);
        twin.bodies
            .set_position(h, p + Vec2::new(1e-4, 0.0))
            .unwrap();
        assert_ne!(digest(&sim), digest(&twin));
    }

    #[test]
    fn rooms_split_where_a_wall_is_built() {
        let map = ascii::parse("#####\n#.#.#\n#####\n", "t.txt", 1.0).unwrap();
        let r = rooms(&map);
        let (a, b) = (
            room_of(&map, &r, Vec2::new(1.5, 1.5)),
            room_of(&map, &r, Vec2::new(3.5, 1.5)),
        );
        assert!(a.is_some() && b.is_some() && a != b);
        assert_eq!(room_of(&map, &r, Vec2::new(2.5, 1.5)), None);
        assert_eq!(room_of(&map, &r, Vec2::new(-1.0, 1.5)), None);
    }
}
