//! Snapshots (the `serde` feature): a run restored from a snapshot at step k goes on bit for
//! bit as the run that was never interrupted, and bad snapshots are refused with what is
//! wrong, never a panic or a half-restored state.
//!
//! The run is the BENCHMARKS.md crowd on dungeon256 with a game around it: cells dug next to
//! the crowd and walls built, bodies removed and added (their slots reused, their
//! generations moving on), a moving platform submitted as a temporary segment most steps,
//! and every body registered with hit volumes, a third of them swinging an attack that lasts
//! six frames. Snapshots are taken between steps, between proposing the moves and
//! resolving them, and between resolving and moving. After every step the whole state is hashed: every body's position and moves
//! and handle, the resolve's report, the hits, the map's edits, the swing memory and the
//! game's own state.
//!
//! These run in the debug build with every `cargo test`; the release build is checked with
//! `cargo test --release -p tileslide --features serde --test snapshots`.
#![cfg(feature = "serde")]
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use serde::{Deserialize, Serialize};
use tileslide::io::ascii;
use tileslide::{
    Bodies, BodyDesc, BodyHandle, BodyShape, Cell, HitObject, HitTypes, HitWorld, MapEdits, Owner,
    ResolveReport, Segment, SegmentFlags, TeamRule, TemporarySegment, TileMap, Vec2, Volume,
};
use tileslide_scenes::{
    CROWD_RADIUS, Fnv1a, SplitMix64, crowd_candidates, dungeon256, scene_crowd,
};

/// Steps of the run.
const STEPS: u32 = 200;

/// Bodies of the crowd at the start.
const CROWD: usize = 500;

/// The game's own state, saved beside tileslide's: the step and the bodies it drives.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
struct Game {
    step: u32,
    /// Whether the step's first half ran: its edits made, its moves proposed.
    prepared: bool,
    /// The step's resolve ran, and reported this: the bodies are yet to make their moves.
    resolved: Option<ResolveReport>,
    /// The crowd's bodies alive: an id (the owner of their hit volumes), the handle and the
    /// constant move.
    crowd: Vec<(u64, BodyHandle, Vec2)>,
    next_id: u64,
}

/// The state of a run.
#[derive(Clone, Debug)]
struct World {
    map: TileMap,
    bodies: Bodies,
    hits: HitWorld,
    game: Game,
}

/// A snapshot as written.
#[derive(Serialize)]
struct SnapshotOut<'a> {
    map: MapEdits,
    bodies: &'a Bodies,
    hits: &'a HitWorld,
    game: &'a Game,
}

/// A snapshot as read.
#[derive(Deserialize)]
struct Snapshot {
    map: MapEdits,
    bodies: Bodies,
    hits: HitWorld,
    game: Game,
}

/// The scene's fixed parts: the level, the free spots new bodies are placed on, the crowd
/// at the start and where the platform starts (just below the first body).
struct Scene {
    level: TileMap,
    spots: Vec<Vec2>,
    crowd: Vec<tileslide_scenes::CrowdBody>,
    platform: Vec2,
}

impl Scene {
    fn new() -> Self {
        let grid = dungeon256();
        let crowd = scene_crowd(&grid, CROWD);
        Self {
            level: grid.to_tile_map().unwrap(),
            spots: crowd_candidates(&grid),
            platform: crowd[0].position + Vec2::new(-1.0, 0.6),
            crowd,
        }
    }

    /// The run at step 0.
    fn start(&self) -> World {
        let mut bodies = Bodies::new();
        let shape = BodyShape::circle(CROWD_RADIUS).unwrap();
        let crowd: Vec<_> = self
            .crowd
            .iter()
            .zip(0..)
            .map(|(b, id)| {
                let desc = BodyDesc::new(b.position, shape.clone()).with_owner(Owner(id));
                (id, bodies.add(desc).unwrap(), b.velocity)
            })
            .collect();
        let next_id = crowd.len() as u64;
        World {
            map: self.level.clone(),
            bodies,
            hits: HitWorld::new(),
            game: Game {
                step: 0,
                prepared: false,
                resolved: None,
                crowd,
                next_id,
            },
        }
    }
}

impl World {
    /// One step of the game (edits, bodies, platform, moves, resolve, hits); the hash of
    /// the whole state after it.
    fn step(&mut self, scene: &Scene) -> u64 {
        if !self.game.prepared {
            self.prepare(scene);
        }
        let report = match self.game.resolved.take() {
            Some(report) => report,
            None => self.bodies.resolve(&self.map),
        };
        self.bodies.integrate();
        let hits = self.detect_hits();
        self.game.step += 1;
        self.game.prepared = false;
        self.hash(&report, &hits)
    }

    /// The first half of a step and the resolve, short of moving the bodies.
    fn resolve(&mut self, scene: &Scene) {
        if !self.game.prepared {
            self.prepare(scene);
        }
        self.game.resolved = Some(self.bodies.resolve(&self.map));
    }

    /// The first half of a step: the game's edits and the bodies' proposed moves.
    fn prepare(&mut self, scene: &Scene) {
        let s = self.game.step;
        let mut rng = SplitMix64::new(0x5AA9_5407_0000_0000 + u64::from(s));
        // The map: a cell next to a body dug every third step, a wall built every seventh.
        if s.is_multiple_of(3)
            && let Some(cell) = self.cell_near_a_body(&mut rng)
            && self.map.tile(cell).is_some()
        {
            self.map.clear_tile(cell).unwrap();
        }
        if s.is_multiple_of(7)
            && let Some(cell) = self.cell_near_a_body(&mut rng)
            && self.map.tile(cell).is_none()
            && self.clear_of_bodies(cell)
        {
            self.map.set_tile(cell, Some(ascii::SOLID)).unwrap();
        }
        // Bodies: two removed every fifth step, one added every fourth (into the slot
        // freed last, when there is one).
        let crowd = &mut self.game.crowd;
        for _ in 0..if s % 5 == 2 { 2 } else { 0 } {
            let k = rng.below(crowd.len() as u64) as usize;
            let (_, handle, _) = crowd.remove(k);
            self.bodies.remove(handle).unwrap();
            assert!(self.bodies.get(handle).is_err());
        }
        if s % 4 == 1 {
            for _ in 0..50 {
                let at = rng.pick(&scene.spots).unwrap();
                if self.spot_is_free(at) {
                    let id = self.game.next_id;
                    let shape = BodyShape::circle(CROWD_RADIUS).unwrap();
                    let desc = BodyDesc::new(at, shape).with_owner(Owner(id));
                    let handle = self.bodies.add(desc).unwrap();
                    let angle = rng.f32() * std::f32::consts::TAU;
                    let velocity = Vec2::new(angle.cos(), angle.sin()) * 0.05;
                    self.game.crowd.push((id, handle, velocity));
                    self.game.next_id += 1;
                    break;
                }
            }
        }
        // A platform gliding back and forth over the first body's start, gone every
        // eleventh step.
        self.map.clear_temporaries();
        if !s.is_multiple_of(11) {
            let x = 0.05 * (s % 40) as f32;
            let from = scene.platform + Vec2::new(x, 0.0);
            let platform = TemporarySegment {
                segment: Segment::new(from, from + Vec2::new(2.0, 0.0)),
                normal: Vec2::new(0.0, -1.0),
                flags: SegmentFlags::SOLID,
                owner: Owner(u64::MAX),
                velocity: Vec2::new(0.05, 0.0),
            };
            self.map.add_temporary(platform).unwrap();
        }
        for &(_, handle, velocity) in &self.game.crowd {
            self.bodies.propose(handle, velocity).unwrap();
        }
        self.game.prepared = true;
    }

    /// A cell within a cell and a half of a body drawn at random.
    fn cell_near_a_body(&self, rng: &mut SplitMix64) -> Option<Cell> {
        let (_, handle, _) = rng.pick(&self.game.crowd)?;
        let at = self.bodies.get(handle).unwrap().position();
        let offset = Vec2::new(rng.range(-1.5, 1.5), rng.range(-1.5, 1.5));
        self.map.cell_at(at + offset)
    }

    /// Whether no body touches `cell` (with room to spare).
    fn clear_of_bodies(&self, cell: Cell) -> bool {
        let rect = self.map.cell_rect(cell);
        let centre = (rect.min + rect.max) * 0.5;
        self.bodies
            .iter()
            .all(|(_, b)| b.position().distance(centre) > 0.75 + CROWD_RADIUS)
    }

    /// Whether a new body fits at `at`: no tile in the cells its box touches, no body
    /// closer than two radii and a gap.
    fn spot_is_free(&self, at: Vec2) -> bool {
        let r = Vec2::splat(CROWD_RADIUS + 0.05);
        let area = tileslide::Aabb::from_corners(at - r, at + r);
        self.map
            .cells_overlapping(&area)
            .all(|c| self.map.tile(c).is_none())
            && self
                .bodies
                .iter()
                .all(|(_, b)| b.position().distance(at) > 2.0 * CROWD_RADIUS + 0.05)
    }

    /// The frame's hits: every body is vulnerable, every third attacks all around it with
    /// a swing that lasts six frames.
    fn detect_hits(&mut self) -> Vec<tileslide::HitEvent> {
        let s = self.game.step;
        self.hits.begin_frame();
        let size = Vec2::splat(2.0 * CROWD_RADIUS);
        let half = Vec2::splat(CROWD_RADIUS);
        let body = [Volume::rect(half, half, HitTypes::ANY).unwrap()];
        let sword = [Volume::circle(half, 2.5, HitTypes::HIT).unwrap()];
        for &(id, handle, velocity) in &self.game.crowd {
            let at = self.bodies.get(handle).unwrap().position();
            let swings = id % 3 == 0;
            let object = HitObject {
                motion: velocity,
                team: (id % 2) as u32,
                swing: swings.then(|| (id << 16) + u64::from(s / 6)),
                ..HitObject::new(Owner(id), at - half, size)
            };
            let attack: &[Volume] = if swings { &sword } else { &[] };
            self.hits.register(object, attack, &body).unwrap();
        }
        self.hits.detect(&mut TeamRule).to_vec()
    }

    /// The whole state after a step, as FNV-1a.
    fn hash(&self, report: &ResolveReport, hits: &[tileslide::HitEvent]) -> u64 {
        let mut h = Fnv1a::new();
        for (handle, b) in self.bodies.iter() {
            h.write_bytes(&postcard::to_stdvec(&handle).unwrap());
            for v in [b.position(), b.proposed_move(), b.resolved_move()] {
                h.write_f32(v.x);
                h.write_f32(v.y);
            }
        }
        for n in [report.moving, report.contact_count, report.cut_short] {
            h.write_u64(n as u64);
        }
        h.write_bytes(&postcard::to_stdvec(hits).unwrap());
        h.write_bytes(&postcard::to_stdvec(&self.map.edits()).unwrap());
        h.write_u64(self.map.active_segment_count() as u64);
        h.write_bytes(&postcard::to_stdvec(&self.hits).unwrap());
        h.write_bytes(&postcard::to_stdvec(&self.game).unwrap());
        h.finish()
    }

    fn snapshot(&self) -> SnapshotOut<'_> {
        SnapshotOut {
            map: self.map.edits(),
            bodies: &self.bodies,
            hits: &self.hits,
            game: &self.game,
        }
    }

    /// The run `saved` holds, on `map` (another map of the same level, in any state).
    fn restored(mut map: TileMap, saved: Snapshot) -> Self {
        map.restore_edits(&saved.map).unwrap();
        Self {
            map,
            bodies: saved.bodies,
            hits: saved.hits,
            game: saved.game,
        }
    }
}

/// The uninterrupted run: the hash after each step, and the map's edits before each.
fn reference(scene: &Scene) -> (Vec<u64>, Vec<MapEdits>) {
    let mut world = scene.start();
    let mut hashes = Vec::new();
    let mut edits = Vec::new();
    for _ in 0..STEPS {
        edits.push(world.map.edits());
        hashes.push(world.step(scene));
    }
    (hashes, edits)
}

#[test]
fn a_run_restored_from_json_at_every_step_goes_on_bit_for_bit() {
    let scene = Scene::new();
    let (hashes, edits) = reference(&scene);
    let mut world = scene.start();
    for s in 0..STEPS as usize {
        // Saved between steps, between proposing the moves and resolving them, and between
        // resolving and moving, in turn.
        match s % 3 {
            1 => world.prepare(&scene),
            2 => world.resolve(&scene),
            _ => {}
        }
        let json = serde_json::to_string(&world.snapshot()).unwrap();
        let saved: Snapshot = serde_json::from_str(&json).unwrap();
        // Onto the level as loaded at even steps; at odd steps onto the run's own map,
        // moved ten steps ahead first (a rollback).
        let map = if s % 2 == 0 {
            scene.level.clone()
        } else {
            let mut map = world.map.clone();
            let ahead = &edits[(s + 10).min(edits.len() - 1)];
            map.restore_edits(ahead).unwrap();
            map
        };
        world = World::restored(map, saved);
        // Read back, it writes the same JSON: nothing lost, nothing reordered.
        let again = serde_json::to_string(&world.snapshot()).unwrap();
        assert!(
            again == json,
            "step {s}: read back, the snapshot writes other JSON"
        );
        assert_eq!(world.step(&scene), hashes[s], "step {s}");
    }
}

#[test]
fn a_run_restored_at_step_k_goes_on_to_the_end_bit_for_bit() {
    let scene = Scene::new();
    let mut world = scene.start();
    let mut hashes = Vec::new();
    // At every twentieth step: the snapshot in postcard's bytes, and the world kept in memory
    // (clones keep the resolver's memories, which catch up with the map's journal).
    let mut saved = Vec::new();
    for s in 0..STEPS {
        if s % 20 == 0 {
            let bytes = postcard::to_stdvec(&world.snapshot()).unwrap();
            saved.push((s, bytes, world.clone()));
        }
        hashes.push(world.step(&scene));
    }
    let end = world.map;
    for (k, bytes, kept) in saved {
        let read: Snapshot = postcard::from_bytes(&bytes).unwrap();
        let mut from_bytes = World::restored(end.clone(), read);
        // Every other one also from the world kept in memory, its map rolled back.
        let mut in_memory = (k % 40 == 20).then(|| {
            let mut map = end.clone();
            map.restore_edits(&from_bytes.map.edits()).unwrap();
            World { map, ..kept }
        });
        for s in k..STEPS {
            let expected = hashes[s as usize];
            assert_eq!(from_bytes.step(&scene), expected, "from step {k}: step {s}");
            if let Some(world) = &mut in_memory {
                assert_eq!(world.step(&scene), expected, "kept at {k}: step {s}");
            }
        }
    }
}
