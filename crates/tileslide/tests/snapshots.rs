//! Snapshots (the `serde` feature): a run restored from a snapshot at step k goes on bit for
//! bit as the run that was never interrupted, and bad snapshots are refused with what is
//! wrong, never a panic or a half-restored state.
//!
//! The run is the BENCHMARKS.md crowd on dungeon256 with a game around it: cells dug next to
//! the crowd and walls built, bodies removed and added (their slots reused, their
//! generations moving on), a moving platform submitted as a temporary segment most steps,
//! and every body registered with hit volumes, a third of them swinging an attack that lasts
//! six frames. Snapshots are taken between steps, between proposing the moves and
//! resolving them, and between resolving and moving. After every step the whole state is
//! hashed: every body's position and moves and handle, the resolve's report, the hits, the
//! map's edits, the swing memory and the game's own state. A platformer character, run
//! through a scripted level, is restored the same way.
//!
//! These run in the debug build with every `cargo test`; the release build is checked with
//! `cargo test --release -p tileslide --features serde --test snapshots`.
#![cfg(feature = "serde")]
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use serde::{Deserialize, Serialize};
use tileslide::io::ascii;
use tileslide::limits::MAX_TEMPORARIES;
use tileslide::{
    Bodies, BodyDesc, BodyHandle, BodyShape, Cell, HitObject, HitTypes, HitWorld, MapEdits, Owner,
    ResolveReport, Segment, SegmentFlags, SnapshotError, TeamRule, TemporarySegment, TileMap, Vec2,
    Volume,
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
    /// Hits taken so far.
    hits_taken: u64,
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
        World::new(self.level.clone(), bodies, crowd)
    }
}

impl World {
    /// The run at step 0 with `bodies`, the game driving `crowd` (ids from 0 up).
    fn new(map: TileMap, bodies: Bodies, crowd: Vec<(u64, BodyHandle, Vec2)>) -> Self {
        let next_id = crowd.len() as u64;
        World {
            map,
            bodies,
            hits: HitWorld::new(),
            game: Game {
                step: 0,
                prepared: false,
                resolved: None,
                crowd,
                next_id,
                hits_taken: 0,
            },
        }
    }

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
        let hits = self.hits.detect(&mut TeamRule).to_vec();
        self.game.hits_taken += hits.iter().filter(|h| h.accepted).count() as u64;
        hits
    }

    /// The whole state after a step, as FNV-1a.
    fn hash(&self, report: &ResolveReport, hits: &[tileslide::HitEvent]) -> u64 {
        let mut h = Fnv1a::new();
        for (handle, b) in self.bodies.iter() {
            h.write_bytes(&cbor(&handle));
            for v in [b.position(), b.proposed_move(), b.resolved_move()] {
                h.write_f32(v.x);
                h.write_f32(v.y);
            }
        }
        for n in [report.moving, report.contact_count, report.cut_short] {
            h.write_u64(n as u64);
        }
        h.write_bytes(&cbor(hits));
        h.write_bytes(&cbor(&self.map.edits()));
        h.write_u64(self.map.active_segment_count() as u64);
        h.write_bytes(&cbor(&self.hits));
        h.write_bytes(&cbor(&self.game));
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

/// `value` in CBOR.
fn cbor<T: Serialize + ?Sized>(value: &T) -> Vec<u8> {
    let mut bytes = Vec::new();
    ciborium::into_writer(value, &mut bytes).unwrap();
    bytes
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
    // At every twentieth step: the snapshot in CBOR, and the world kept in memory
    // (clones keep the resolver's memories, which catch up with the map's journal).
    let mut saved = Vec::new();
    let mut swinging = 0;
    for s in 0..STEPS {
        if s % 20 == 0 {
            let bytes = cbor(&world.snapshot());
            saved.push((s, bytes, world.clone()));
        }
        hashes.push(world.step(&scene));
        let memory = serde_json::to_value(&world.hits).unwrap();
        swinging += usize::from(!memory["swung"].as_array().unwrap().is_empty());
    }
    // The run exercises what it should: hits, and swings remembered over frames; bodies
    // removed and slots reused; cells dug and built.
    assert!(
        world.game.hits_taken > 100,
        "{} hits",
        world.game.hits_taken
    );
    assert!(
        swinging > STEPS as usize / 2,
        "swing memory held at {swinging} steps"
    );
    let generations = serde_json::to_value(&world.bodies).unwrap()["slots"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|slot| slot["generation"].as_u64() > Some(0))
        .count();
    assert!(generations > 10, "{generations} slots reused or free");
    let edited = world.map.edits().tiles().to_vec();
    let dug = edited.iter().filter(|(_, t)| t.is_none()).count();
    assert!(
        dug >= 10 && edited.len() > dug,
        "{} cells edited, {dug} dug",
        edited.len()
    );
    let end = world.map;
    for (k, bytes, kept) in saved {
        let read: Snapshot = ciborium::from_reader(bytes.as_slice()).unwrap();
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

// Bad data: truncated, inconsistent, NaN, out of range, of another map.

const ROOM: &str = "\
##########
#........#
#...##...#
#..#.....#
##########";

/// A small world with something in every part of its state: bodies (one a compound, one
/// removed so its slot is free), proposed moves, swings remembered, a cell dug, a platform.
fn small_world() -> World {
    let mut map = ascii::parse(ROOM, "room.txt", 1.0).unwrap();
    map.clear_tile(Cell::new(4, 2)).unwrap();
    map.add_temporary(TemporarySegment {
        segment: Segment::new(Vec2::new(6.0, 3.0), Vec2::new(8.0, 3.0)),
        normal: Vec2::new(0.0, -1.0),
        flags: SegmentFlags::ONE_WAY,
        owner: Owner(9),
        velocity: Vec2::new(0.5, 0.0),
    })
    .unwrap();
    let mut bodies = Bodies::new();
    let circle = BodyShape::circle(0.3).unwrap();
    let cart = BodyShape::compound([
        tileslide::Circle::new(Vec2::new(-0.3, 0.0), 0.2),
        tileslide::Circle::new(Vec2::new(0.3, 0.0), 0.2),
    ])
    .unwrap();
    let mut crowd = Vec::new();
    for (id, (at, shape)) in [
        (Vec2::new(1.5, 1.5), &circle),
        (Vec2::new(3.25, 1.5), &circle),
        (Vec2::new(6.5, 2.5), &cart),
        (Vec2::new(8.5, 1.5), &circle),
        (Vec2::new(7.0, 1.3), &circle),
    ]
    .into_iter()
    .enumerate()
    {
        let handle = bodies.add(BodyDesc::new(at, shape.clone())).unwrap();
        crowd.push((id as u64, handle, Vec2::new(0.1, 0.05)));
    }
    let (_, removed, _) = crowd.remove(0);
    bodies.remove(removed).unwrap();
    let mut world = World::new(map, bodies, crowd);
    world.game.next_id = 5;
    world.detect_hits();
    for &(_, handle, velocity) in &world.game.crowd {
        world.bodies.propose(handle, velocity).unwrap();
    }
    world
}

/// `value` as JSON, changed by `edit`, read back as a `T`: the error's message.
fn refused<T: for<'de> Deserialize<'de> + std::fmt::Debug>(
    value: &impl Serialize,
    edit: impl FnOnce(&mut serde_json::Value),
) -> String {
    let mut json = serde_json::to_value(value).unwrap();
    edit(&mut json);
    match serde_json::from_value::<T>(json) {
        Ok(read) => panic!("read: {read:?}"),
        Err(e) => e.to_string(),
    }
}

/// A change to a snapshot's JSON.
type Edit = fn(&mut serde_json::Value);

/// `message` names everything in `parts`.
fn names(message: &str, parts: &[&str]) {
    for part in parts {
        assert!(message.contains(part), "{message:?} does not say {part:?}");
    }
}

#[test]
fn every_truncated_snapshot_is_refused_in_json_and_cbor() {
    let world = small_world();
    let snapshot = world.snapshot();
    let json = serde_json::to_string(&snapshot).unwrap();
    let bytes = cbor(&snapshot);
    assert!(serde_json::from_str::<Snapshot>(&json).is_ok());
    assert!(ciborium::from_reader::<Snapshot, _>(bytes.as_slice()).is_ok());
    for n in 0..json.len() {
        assert!(serde_json::from_str::<Snapshot>(&json[..n]).is_err(), "{n}");
    }
    for n in 0..bytes.len() {
        let read = ciborium::from_reader::<Snapshot, _>(&bytes[..n]);
        assert!(read.is_err(), "{n} of {} bytes", bytes.len());
    }
}

#[test]
fn nan_and_infinite_values_are_refused_naming_the_body() {
    let world = small_world();
    let bytes = cbor(&world.bodies);
    // The body in slot 1 stands at x = 3.25, which CBOR writes once, as a half-precision
    // float (0xf9, then 0x4280).
    let found: Vec<usize> = (0..bytes.len() - 2)
        .filter(|&at| bytes[at..at + 3] == [0xf9, 0x42, 0x80])
        .collect();
    assert_eq!(found.len(), 1, "{bytes:x?}");
    // NaN, infinity and minus infinity as half-precision floats.
    for bad in [[0x7e, 0x00], [0x7c, 0x00], [0xfc, 0x00]] {
        let mut patched = bytes.clone();
        patched[found[0] + 1..found[0] + 3].copy_from_slice(&bad);
        let message = match ciborium::from_reader::<Bodies, _>(patched.as_slice()) {
            Ok(read) => panic!("read: {read:?}"),
            Err(e) => e.to_string(),
        };
        names(&message, &["slot 1", "position", "not finite"]);
    }
}

#[test]
fn values_beyond_the_limits_are_refused_with_what_is_wrong() {
    let world = small_world();
    let bodies = &world.bodies;
    let body = |json: &mut serde_json::Value| json["slots"][2]["body"].take();
    // Positions, moves and their end points beyond MAX_COORD.
    let message = refused::<Bodies>(bodies, |json| {
        json["slots"][1]["body"]["position"][0] = 1e30.into();
    });
    names(&message, &["slot 1", "position", "out of range"]);
    let message = refused::<Bodies>(bodies, |json| {
        json["slots"][3]["body"]["proposed"][1] = 2e7.into();
    });
    names(
        &message,
        &["slot 3", "proposed move's end point", "out of range"],
    );
    let message = refused::<Bodies>(bodies, |json| {
        json["slots"][3]["body"]["resolved"][0] = (-3e7).into();
    });
    names(&message, &["slot 3", "resolved move's end point"]);
    // Shapes: a radius beyond MAX_COORD, a negative one, no circles.
    let message = refused::<Bodies>(bodies, |json| {
        let mut cart = body(json);
        cart["shape"][1]["radius"] = 1e9.into();
        json["slots"][2]["body"] = cart;
    });
    names(&message, &["slot 2", "circle 1", "radius 1000000000"]);
    let message = refused::<Bodies>(bodies, |json| {
        json["slots"][1]["body"]["shape"][0]["radius"] = (-0.5).into();
    });
    names(&message, &["slot 1", "circle 0", "radius -0.5"]);
    let message = refused::<Bodies>(bodies, |json| {
        json["slots"][1]["body"]["shape"] = serde_json::json!([]);
    });
    names(&message, &["slot 1", "at least one circle"]);
    // Settings out of their range.
    let message = refused::<Bodies>(bodies, |json| json["config"]["gap"] = (-1.0).into());
    names(&message, &["resolve settings", "gap = -1"]);
    let message = refused::<Bodies>(bodies, |json| json["config"]["passes"] = 1000.into());
    names(&message, &["resolve settings", "passes = 1000"]);
    // A map larger than MAX_CELLS, empty, a cell outside it.
    let edits = world.map.edits();
    let message = refused::<MapEdits>(&edits, |json| {
        json["width"] = 100_000.into();
        json["height"] = 100_000.into();
    });
    names(&message, &["100000×100000", "too large"]);
    let message = refused::<MapEdits>(&edits, |json| json["height"] = 0.into());
    names(&message, &["10×0", "empty"]);
    let message = refused::<MapEdits>(&edits, |json| {
        json["tiles"][0][0]["col"] = 10.into();
    });
    names(
        &message,
        &["tile edit 0", "(10, 2)", "outside the 10×5 map"],
    );
    // Temporary segments: beyond MAX_COORD, of zero length, with a normal not normalised.
    let message = refused::<MapEdits>(&edits, |json| {
        json["temporaries"][0]["segment"]["b"][0] = 1e30.into();
    });
    names(&message, &["temporary segment 0", "MAX_COORD"]);
    let message = refused::<MapEdits>(&edits, |json| {
        let a = json["temporaries"][0]["segment"]["a"].clone();
        json["temporaries"][0]["segment"]["b"] = a;
    });
    names(&message, &["temporary segment 0", "zero length"]);
    let message = refused::<MapEdits>(&edits, |json| {
        json["temporaries"][0]["normal"] = serde_json::json!([0.0, -2.0]);
    });
    names(
        &message,
        &["temporary segment 0", "(0, -2)", "not of unit length"],
    );
    // More temporary segments than a map holds.
    let message = refused::<MapEdits>(&edits, |json| {
        let one = json["temporaries"][0].clone();
        json["temporaries"] = serde_json::Value::Array(vec![one; MAX_TEMPORARIES + 1]);
    });
    names(&message, &["temporary segment", "65536", "MAX_TEMPORARIES"]);
}

#[test]
fn slots_and_free_lists_no_calls_could_leave_are_refused() {
    let world = small_world();
    let bodies = &world.bodies;
    // As saved: slot 0 free (generation 1), slots 1 to 4 hold bodies.
    let json = serde_json::to_value(bodies).unwrap();
    assert_eq!(json["free"], serde_json::json!([0]));
    assert_eq!(json["slots"][0]["generation"], 1);
    let cases: [(Edit, &[&str]); 6] = [
        (
            |json| json["slots"][0]["generation"] = 0.into(),
            &["slot 0", "empty at generation 0"],
        ),
        (
            |json| json["free"] = serde_json::json!([0, 2]),
            &["entry 1", "slot 2", "holding a body"],
        ),
        (
            |json| json["free"] = serde_json::json!([0, 0]),
            &["entry 1", "slot 0", "listed before"],
        ),
        (
            |json| json["free"] = serde_json::json!([0, 7]),
            &["entry 1", "slot 7", "past the last slot"],
        ),
        (
            |json| json["slots"][0]["generation"] = u32::MAX.into(),
            &["entry 0", "slot 0", "retired"],
        ),
        (
            |json| json["free"] = serde_json::json!([]),
            &["slot 0", "not in the free list"],
        ),
    ];
    for (edit, parts) in cases {
        names(&refused::<Bodies>(bodies, edit), parts);
    }
    // A retired slot (its generation spent) is empty and in no free list.
    let mut retired = serde_json::to_value(bodies).unwrap();
    retired["slots"][0]["generation"] = u32::MAX.into();
    retired["free"] = serde_json::json!([]);
    let read: Bodies = serde_json::from_value(retired).unwrap();
    assert_eq!(read.len(), 4);
    // The swing memory's lists are sorted and hold each entry once.
    let hits = &world.hits;
    let memory = serde_json::to_value(hits).unwrap();
    assert!(memory["swung"].as_array().unwrap().len() >= 2, "{memory}");
    let message = refused::<HitWorld>(hits, |json| {
        json["swung"].as_array_mut().unwrap().reverse();
    });
    names(
        &message,
        &["swing hits", "out of order or repeated at entry 1"],
    );
    let message = refused::<HitWorld>(hits, |json| {
        let first = json["swings"][0].clone();
        json["swings"].as_array_mut().unwrap().insert(0, first);
    });
    names(&message, &["swings", "entry 1"]);
    // The kept events' times lie in [0, 1] and their points are finite.
    assert!(!memory["events"].as_array().unwrap().is_empty(), "{memory}");
    let message = refused::<HitWorld>(hits, |json| json["events"][0]["t"] = 1.5.into());
    names(&message, &["hit event 0", "t = 1.5", "t must be in [0, 1]"]);
    let message = refused::<HitWorld>(hits, |json| {
        json["events"][0]["point"][1] = serde_json::json!(f64::MAX);
    });
    names(&message, &["hit event 0", "inf", "the point finite"]);
    // A missing field is named by serde.
    let message = refused::<Bodies>(bodies, |json| {
        json.as_object_mut().unwrap().remove("free");
    });
    names(&message, &["missing field `free`"]);
}

#[test]
fn handles_of_other_generations_are_stale_in_a_restored_set() {
    let world = small_world();
    let json = serde_json::to_string(&world.bodies).unwrap();
    let bodies: Bodies = serde_json::from_str(&json).unwrap();
    let (_, handle, _) = world.game.crowd[0];
    assert!(bodies.contains(handle));
    // The game's own saved handle, with a generation the slot never had or no longer has.
    for generation in [1, u32::MAX] {
        let mut saved = serde_json::to_value(handle).unwrap();
        saved["generation"] = generation.into();
        let stale: BodyHandle = serde_json::from_value(saved).unwrap();
        let mut bodies: Bodies = serde_json::from_str(&json).unwrap();
        assert_eq!(
            bodies.get(stale).unwrap_err(),
            tileslide::BodyError::StaleHandle(stale)
        );
        assert!(bodies.propose(stale, Vec2::X).is_err() && bodies.remove(stale).is_err());
        assert!(bodies.contains(handle), "the body is untouched");
    }
    // The freed slot is taken by the next body, at its next generation, as it would have
    // been: slot 0, generation 1.
    let mut bodies: Bodies = serde_json::from_str(&json).unwrap();
    let added = bodies
        .add(BodyDesc::new(
            Vec2::new(1.5, 3.5),
            BodyShape::circle(0.3).unwrap(),
        ))
        .unwrap();
    let saved = serde_json::to_value(added).unwrap();
    assert_eq!(saved, serde_json::json!({"index": 0, "generation": 1}));
}

#[test]
fn edits_of_another_map_or_with_unknown_tiles_are_refused_and_change_nothing() {
    let world = small_world();
    let edits = world.map.edits();
    let level = || ascii::parse(ROOM, "room.txt", 1.0).unwrap();
    let mut map = level();
    map.set_tile(Cell::new(1, 3), Some(ascii::SOLID)).unwrap();
    let before = map.edits();
    let revision = map.revision();
    // Another level of the same size.
    let mut other = ascii::parse(&ROOM.replace("##...", "#...."), "other.txt", 1.0).unwrap();
    let e = other.restore_edits(&edits).unwrap_err();
    assert!(matches!(e, SnapshotError::OtherBase { .. }), "{e}");
    names(&e.to_string(), &["another map", "checksum"]);
    // Another size.
    let mut wide = ascii::parse(&ROOM.replace("#\n", "##\n"), "wide.txt", 1.0).unwrap();
    let e = wide.restore_edits(&edits).unwrap_err();
    names(&e.to_string(), &["10×5 map", "this map is 11×5"]);
    // The edits read from a file with one more cell, at tile `tile`.
    let with_cell = |tile: u32| -> MapEdits {
        let mut json = serde_json::to_value(&edits).unwrap();
        let cell = serde_json::json!([{"col": 9, "row": 4}, tile]);
        json["tiles"].as_array_mut().unwrap().push(cell);
        serde_json::from_value(json).unwrap()
    };
    // A tile the set lacks; an edit that is none (the cell as the map was built).
    let cell = Cell::new(9, 4);
    let id = tileslide::TileId(99);
    let e = map.restore_edits(&with_cell(99)).unwrap_err();
    assert_eq!(e, SnapshotError::UnknownTile { cell, id });
    let e = map.restore_edits(&with_cell(1)).unwrap_err();
    assert_eq!(e, SnapshotError::NoChange { cell });
    // Refused, the map is as it was, revision and all.
    assert_eq!(map.edits(), before);
    assert!(map.revision() == revision);
    // The right edits on the right level: restored.
    map.restore_edits(&edits).unwrap();
    assert_eq!(map.edits(), edits);
    assert_eq!(map.tile(Cell::new(1, 3)), None);
    assert_eq!(map.tile(Cell::new(4, 2)), None);
    assert_eq!(map.temporaries(), world.map.temporaries());
}

proptest::proptest! {
    /// Bytes of a CBOR snapshot changed at random are read or refused, never a panic; what
    /// is read is a state the calls could have left: a set whose handles, free slots and
    /// steps work, edits that restore onto the level or are refused leaving it as it was, a
    /// world that detects.
    #[test]
    fn mutated_snapshots_are_read_or_refused_and_what_is_read_works(
        changes in proptest::collection::vec((0.0f64..1.0, proptest::num::u8::ANY), 0..3),
        numbers in proptest::collection::vec((0.0f64..1.0, 0usize..NUMBERS.len()), 0..4),
    ) {
        // Numbers of the snapshot replaced (generations, free slots, coordinates, cells,
        // tiles, swings), then bytes of its CBOR.
        let world = small_world();
        let mut json = serde_json::to_value(world.snapshot()).unwrap();
        let count = number_count(&json);
        for &(at, k) in &numbers {
            let at = ((count as f64 * at) as usize).min(count - 1);
            replace_number(&mut json, &mut { at }, &NUMBERS[k]);
        }
        let mut bytes = cbor(&json);
        for &(at, byte) in &changes {
            let at = ((bytes.len() as f64 * at) as usize).min(bytes.len() - 1);
            bytes[at] = byte;
        }
        let Ok(read) = ciborium::from_reader::<Snapshot, _>(bytes.as_slice()) else {
            return Ok(());
        };
        let Snapshot { map, mut bodies, mut hits, .. } = read;
        // The set: as many bodies as it says, every handle it lists valid, new bodies into
        // valid slots, and a step.
        let handles: Vec<BodyHandle> = bodies.iter().map(|(h, _)| h).collect();
        proptest::prop_assert_eq!(handles.len(), bodies.len());
        let mut level = ascii::parse(ROOM, "room.txt", 1.0).unwrap();
        for k in 0..3 {
            let at = Vec2::new(1.5 + k as f32, 3.5);
            let added = bodies.add(BodyDesc::new(at, BodyShape::circle(0.2).unwrap())).unwrap();
            proptest::prop_assert!(bodies.contains(added) && !handles.contains(&added));
        }
        for &h in &handles {
            bodies.propose(h, Vec2::new(0.3, -0.2)).unwrap();
        }
        bodies.step(&level);
        for h in handles {
            bodies.remove(h).unwrap();
        }
        proptest::prop_assert_eq!(bodies.len(), 3);
        // The edits: restored, or refused with the level as it was.
        match level.restore_edits(&map) {
            Ok(()) => proptest::prop_assert_eq!(level.edits(), map),
            Err(_) => proptest::prop_assert_eq!(level.edits(), ascii::parse(ROOM, "room.txt", 1.0).unwrap().edits()),
        }
        // The hit world: a frame.
        hits.begin_frame();
        let body = [Volume::rect(Vec2::ONE, Vec2::ONE, HitTypes::ANY).unwrap()];
        hits.register(HitObject::new(Owner(1), Vec2::ONE, Vec2::ONE), &body, &body).unwrap();
        hits.register(HitObject::new(Owner(2), Vec2::ONE, Vec2::ONE), &body, &body).unwrap();
        let events = hits.detect(&mut TeamRule);
        proptest::prop_assert!(events.len() == 2 && events.iter().all(|e| !e.accepted), "{events:?}");
    }
}

/// What numbers of a snapshot are replaced with: edges of every range it checks.
const NUMBERS: [f64; 10] = [0.0, 1.0, 2.0, 3.0, 9.0, -1.0, 0.5, 4294967295.0, 1e30, -2e7];

/// How many numbers `json` holds.
fn number_count(json: &serde_json::Value) -> usize {
    match json {
        serde_json::Value::Number(_) => 1,
        serde_json::Value::Array(items) => items.iter().map(number_count).sum(),
        serde_json::Value::Object(fields) => fields.values().map(number_count).sum(),
        _ => 0,
    }
}

/// Replaces the number at position `at` (counted as [`number_count`] counts) with `value`,
/// an integer where it is one.
fn replace_number(json: &mut serde_json::Value, at: &mut usize, value: &f64) {
    match json {
        serde_json::Value::Number(n) => {
            if *at == 0 {
                *json = match (n.is_f64(), *value) {
                    (false, v) if v >= 0.0 && v.fract() == 0.0 => (v as u64).into(),
                    (false, v) if v.fract() == 0.0 && v > -1e9 => (v as i64).into(),
                    (_, v) => v.into(),
                };
            }
            *at = at.wrapping_sub(1);
        }
        serde_json::Value::Array(items) => {
            for item in items {
                replace_number(item, at, value);
            }
        }
        serde_json::Value::Object(fields) => {
            for field in fields.values_mut() {
                replace_number(field, at, value);
            }
        }
        _ => {}
    }
}

// The character.

/// A platformer level (y down): a floor with one-way platforms, a ramp up a step, and a pit a
/// platform glides across.
const LEVEL: &str = "\
##############################
#............................#
#............................#
#............................#
#............................#
#............................#
#............................#
#............................#
#............................#
#...====..../##.........==...#
#################......#######
##############################";

/// The character's game: its velocity and the step, saved beside it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
struct Runner {
    step: u32,
    velocity: Vec2,
}

impl Runner {
    /// One step: the platform moves, then the character runs (turning every 90 steps),
    /// jumps every 40th step when on the ground, drops through one-way platforms from the
    /// 100th step on, and falls. The hash of its state and contacts after.
    fn step(&mut self, map: &mut TileMap, hero: &mut tileslide::Character) -> u64 {
        let s = self.step;
        let dt = 1.0 / 30.0;
        let phase = (s % 120) as f32 / 120.0 * std::f32::consts::TAU;
        let at = Vec2::new(20.0 + 2.0 * phase.sin(), 10.0);
        map.clear_temporaries();
        map.add_temporary(TemporarySegment {
            segment: Segment::new(at - Vec2::X, at + Vec2::X),
            normal: Vec2::new(0.0, -1.0),
            flags: SegmentFlags::SOLID,
            owner: Owner(7),
            velocity: Vec2::new(2.0 * phase.cos() * std::f32::consts::TAU / 4.0, 0.0),
        })
        .unwrap();
        let run = if (s / 90).is_multiple_of(2) {
            6.0
        } else {
            -6.0
        };
        self.velocity.x = run;
        if s.is_multiple_of(40) && hero.ground().is_some() {
            self.velocity.y = -9.0;
        }
        self.velocity.y += 25.0 * dt;
        let options = tileslide::MoveOptions {
            drop_through: s >= 100 && s.is_multiple_of(7),
        };
        let contacts = hero
            .move_and_slide(map, &mut self.velocity, dt, options)
            .unwrap();
        self.step += 1;
        let mut h = Fnv1a::new();
        h.write_bytes(&cbor(&*hero));
        h.write_bytes(&cbor(&contacts));
        h.write_bytes(&cbor(self));
        h.write_bytes(&cbor(&map.edits()));
        h.finish()
    }
}

#[test]
fn a_character_restored_at_every_step_moves_on_bit_for_bit() {
    let level = ascii::parse(LEVEL, "level.txt", 1.0).unwrap();
    let box_shape = tileslide::CharacterShape::rect(Vec2::new(0.3, 0.45)).unwrap();
    let ball = tileslide::CharacterShape::circle(0.45).unwrap();
    let mut corners = Vec::new();
    for shape in [box_shape, ball] {
        let start = || {
            let config = tileslide::ControllerConfig::default();
            let at = Vec2::new(2.5, 9.5);
            let hero = tileslide::Character::new(shape, at, Vec2::NEG_Y, config).unwrap();
            let runner = Runner {
                step: 0,
                velocity: Vec2::ZERO,
            };
            (hero, runner)
        };
        let (mut hero, mut runner) = start();
        let mut map = level.clone();
        let mut hashes = Vec::new();
        let (mut riding, mut on_corner) = (0, 0);
        for _ in 0..STEPS {
            hashes.push(runner.step(&mut map, &mut hero));
            let source = hero.ground().map(|g| g.source);
            riding += usize::from(matches!(
                source,
                Some(tileslide::SegmentSource::Temporary { .. })
            ));
            let saved = serde_json::to_value(&hero).unwrap();
            on_corner += usize::from(saved["ground_corner"] == true);
        }
        assert!(riding > 5, "{shape:?} rode {riding} steps");
        // Restored from JSON before every step, onto the level as loaded.
        let (mut hero, mut runner) = start();
        let mut map = level.clone();
        for (s, &expected) in hashes.iter().enumerate() {
            let json = serde_json::to_string(&(&hero, &runner, map.edits())).unwrap();
            let (read, again, edits): (tileslide::Character, Runner, MapEdits) =
                serde_json::from_str(&json).unwrap();
            (hero, runner, map) = (read, again, level.clone());
            map.restore_edits(&edits).unwrap();
            assert_eq!(
                runner.step(&mut map, &mut hero),
                expected,
                "{shape:?}: step {s}"
            );
        }
        corners.push(on_corner);
    }
    // The ball stood on rounded corners (at ledges), so that memory was restored too.
    assert!(corners[0] == 0 && corners[1] > 5, "{corners:?}");
}

#[test]
fn a_character_that_no_moves_could_leave_is_refused() {
    let mut map = ascii::parse(LEVEL, "level.txt", 1.0).unwrap();
    let shape = tileslide::CharacterShape::circle(0.4).unwrap();
    let config = tileslide::ControllerConfig::default();
    let mut hero = tileslide::Character::new(shape, Vec2::new(2.5, 9.4), Vec2::NEG_Y, config);
    let hero = hero.as_mut().unwrap();
    hero.move_by(&map, Vec2::new(0.0, 0.5), Default::default())
        .unwrap();
    assert!(hero.ground().is_some());
    map.clear_temporaries();
    let message =
        refused::<tileslide::Character>(&*hero, |json| json["up"] = serde_json::json!([0.0, -2.0]));
    names(&message, &["up", "(0, -2)", "unit length"]);
    let message =
        refused::<tileslide::Character>(&*hero, |json| json["up"] = serde_json::json!([0.0, 0.0]));
    names(&message, &["the character", "up"]);
    let message = refused::<tileslide::Character>(&*hero, |json| json["position"][0] = 1e30.into());
    names(&message, &["position", "beyond the coordinate range"]);
    let message = refused::<tileslide::Character>(&*hero, |json| {
        json["ground"]["normal"] = serde_json::json!([3.0, 0.0]);
    });
    names(&message, &["ground normal", "(3, 0)"]);
    let message = refused::<tileslide::Character>(&*hero, |json| {
        json["ground"] = serde_json::Value::Null;
        json["riding"] =
            serde_json::json!({"owner": 7, "middle": [1.0, 2.0], "normal": [0.0, -1.0]});
    });
    names(&message, &["platform", "on the ground"]);
    let message = refused::<tileslide::Character>(&*hero, |json| {
        json["config"]["max_slope_degrees"] = 95.0.into();
    });
    names(&message, &["max_slope_degrees"]);
    // As saved, it reads back and writes the same, its up direction bit for bit.
    let json = serde_json::to_string(&*hero).unwrap();
    let read: tileslide::Character = serde_json::from_str(&json).unwrap();
    assert_eq!(serde_json::to_string(&read).unwrap(), json);
    let tilted =
        tileslide::Character::new(shape, Vec2::new(2.5, 5.0), Vec2::new(1.0, -3.0), config);
    let tilted = tilted.unwrap();
    let json = serde_json::to_string(&tilted).unwrap();
    let read: tileslide::Character = serde_json::from_str(&json).unwrap();
    assert_eq!(
        read.up().to_array().map(f32::to_bits),
        tilted.up().to_array().map(f32::to_bits)
    );
}
