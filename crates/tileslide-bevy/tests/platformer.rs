//! A character runs up a ramp, jumps onto a moving platform over a pit, rides it, hops off
//! and jumps up through a one-way platform to the goal: through the plugin, and through the
//! core's API with the same rules, bit for bit.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod support;

use bevy::prelude::*;
use tileslide::io::ascii;
use tileslide::{
    Character, CharacterShape, ControllerConfig, MoveOptions, Owner, Segment, SegmentFlags,
    SegmentSource, TemporarySegment,
};
use tileslide_bevy::{
    CharacterContacts, CharacterController, CharacterInput, CollisionMap, Crushed, Platform, Side,
    StepCount, SurfaceContact, TileslidePlugin, TileslideSet,
};

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

/// World units per map cell: a power of two, so the plugin's conversions are exact.
const SCALE: f32 = 16.0;
const HALF: tileslide::Vec2 = tileslide::Vec2::new(0.3, 0.45);
const START: tileslide::Vec2 = tileslide::Vec2::new(2.0, 7.5);
const GRAVITY: f32 = 40.0;
const RUN: f32 = 6.0;
const JUMP: f32 = 13.0;
const MAX_FALL: f32 = 20.0;
const COYOTE_FRAMES: u32 = 6;
const PLATFORM_Y: f32 = 7.0;
const PLATFORM_WIDTH: f32 = 2.0;
const FRAMES: u32 = 480;

/// The moving platform's left end in frame `frame`: from x = 15 to 21 and back, 2 s each way.
fn platform_at(frame: u32, dt: f32) -> f32 {
    let phase = (frame as f32 * dt * 0.5) % 2.0;
    15.0 + 6.0 * if phase < 1.0 { phase } else { 2.0 - phase }
}

/// What the game's rules see of the character before it moves (map units).
#[derive(Clone, Copy)]
struct Seen {
    x: f32,
    on_ground: bool,
    riding: bool,
    /// The x velocity of the ground's platform (0 on a tile or in the air).
    ground_platform_vx: f32,
}

/// The game's rules, in map units: a script for the player, coyote time, jumps that keep a
/// platform's speed, variable jump height, gravity.
#[derive(Default, Resource)]
struct Rules {
    since_ground: u32,
    carried: f32,
    jumps: u32,
}

impl Rules {
    fn velocity(
        &mut self,
        seen: Seen,
        mut velocity: tileslide::Vec2,
        platform: f32,
    ) -> tileslide::Vec2 {
        let dt = support::dt();
        let far_side = platform >= 20.8;
        let (run, jump) = match seen.x {
            _ if seen.riding => (if far_side { RUN } else { 0.0 }, far_side),
            x if x < 14.3 => (RUN, false),
            x if x < 15.0 && seen.on_ground => {
                let near = platform <= 15.4;
                (if near { RUN } else { 0.0 }, near)
            }
            x if x < 21.0 => (RUN * 0.6, false),
            x => (
                if x < 27.5 { RUN } else { 0.0 },
                x > 26.0 || !seen.on_ground,
            ),
        };
        if seen.on_ground {
            (self.since_ground, self.carried) = (0, 0.0);
        } else {
            self.since_ground += 1;
        }
        if jump && self.since_ground <= COYOTE_FRAMES && velocity.y >= 0.0 {
            self.carried = seen.ground_platform_vx;
            velocity.y = -JUMP;
            self.since_ground = COYOTE_FRAMES + 1;
            self.jumps += 1;
        }
        velocity.x = run + self.carried;
        if !jump && velocity.y < 0.0 {
            velocity.y *= 0.5;
        }
        velocity.y = (velocity.y + GRAVITY * dt).min(MAX_FALL);
        velocity
    }
}

/// What a run did, frame by frame.
#[derive(Default, Resource)]
struct Run {
    positions: Vec<tileslide::Vec2>,
    frames_riding: u32,
    jumps: u32,
    goal_frame: Option<u32>,
}

/// The scene on the core's API alone.
fn core_run() -> Run {
    let dt = support::dt();
    let mut map = ascii::parse(LEVEL, "platformer.txt", 1.0).unwrap();
    let shape = CharacterShape::rect(HALF).unwrap();
    let up = tileslide::Vec2::NEG_Y;
    let mut hero = Character::new(shape, START, up, ControllerConfig::default()).unwrap();
    let mut velocity = tileslide::Vec2::ZERO;
    let mut rules = Rules::default();
    let mut run = Run::default();
    let platform = Owner(1);
    let mut was = platform_at(0, dt);
    for frame in 0..FRAMES {
        let x = platform_at(frame, dt);
        map.clear_temporaries_of(platform);
        map.add_temporary(TemporarySegment {
            segment: Segment::new(
                tileslide::Vec2::new(x, PLATFORM_Y),
                tileslide::Vec2::new(x + PLATFORM_WIDTH, PLATFORM_Y),
            ),
            normal: tileslide::Vec2::NEG_Y,
            flags: SegmentFlags::ONE_WAY,
            owner: platform,
            velocity: tileslide::Vec2::new((x - was) / dt, 0.0),
        })
        .unwrap();
        was = x;
        let ground = hero.ground().copied();
        let seen = Seen {
            x: hero.position.x,
            on_ground: ground.is_some(),
            riding: ground.is_some_and(|g| matches!(g.source, SegmentSource::Temporary { .. })),
            ground_platform_vx: ground.map_or(0.0, |g| g.platform_velocity().x),
        };
        velocity = rules.velocity(seen, velocity, x);
        let contacts = hero
            .move_and_slide(&map, &mut velocity, dt, MoveOptions::default())
            .unwrap();
        run.frames_riding += u32::from(seen.riding);
        run.positions.push(hero.position);
        let goal = contacts
            .ground
            .is_some_and(|g| g.flags.contains(SegmentFlags::ONE_WAY) && hero.position.x > 26.0);
        if goal && run.goal_frame.is_none() {
            run.goal_frame = Some(frame);
        }
    }
    run.jumps = rules.jumps;
    run
}

/// The game's system in the plugin's app: moves the platform and sets the character's
/// velocity by the same rules, before the plugin's step.
fn play(
    step: Res<StepCount>,
    mut rules: ResMut<Rules>,
    mut run: ResMut<Run>,
    mut platforms: Query<&mut Transform, With<Platform>>,
    mut heroes: Query<(&Transform, &CharacterContacts, &mut CharacterInput), Without<Platform>>,
) {
    let frame = step.0 as u32;
    let x = platform_at(frame, support::dt());
    for mut transform in &mut platforms {
        transform.translation = Vec3::new(x * SCALE, -PLATFORM_Y * SCALE, 0.0);
    }
    for (transform, contacts, mut input) in &mut heroes {
        let seen = Seen {
            x: transform.translation.x / SCALE,
            on_ground: contacts.is_grounded(),
            riding: contacts.is_riding(),
            ground_platform_vx: contacts.ground.map_or(0.0, |g| g.velocity.x / SCALE),
        };
        run.frames_riding += u32::from(seen.riding);
        let v = input.velocity;
        let velocity = rules.velocity(seen, tileslide::Vec2::new(v.x / SCALE, -v.y / SCALE), x);
        input.velocity = Vec2::new(velocity.x * SCALE, -velocity.y * SCALE);
    }
}

/// Keeps where the character is after each step (map units) and when it reached the goal.
fn record(
    step: Res<StepCount>,
    mut run: ResMut<Run>,
    heroes: Query<(&Transform, &CharacterContacts)>,
) {
    for (transform, contacts) in &heroes {
        let at = transform.translation;
        run.positions
            .push(tileslide::Vec2::new(at.x / SCALE, -at.y / SCALE));
        let on_goal = contacts
            .ground
            .is_some_and(|g| g.flags.contains(SegmentFlags::ONE_WAY) && at.x / SCALE > 26.0);
        if on_goal && run.goal_frame.is_none() {
            run.goal_frame = Some(step.0 as u32 - 1);
        }
    }
}

/// The scene through the plugin, in world units 16 to a cell, y up.
fn plugin_app() -> App {
    let map = ascii::parse(LEVEL, "platformer.txt", 1.0).unwrap();
    let mut app = support::headless(TileslidePlugin::default().with_scale(SCALE));
    app.insert_resource(CollisionMap::new(map))
        .init_resource::<Rules>()
        .init_resource::<Run>()
        .add_systems(FixedUpdate, play.before(TileslideSet::SyncIn))
        .add_systems(FixedUpdate, record.after(TileslideSet::Writeback));
    support::collect::<SurfaceContact>(&mut app);
    support::collect::<Crushed>(&mut app);
    let core = ControllerConfig::default();
    let config = ControllerConfig {
        snap_distance: core.snap_distance * SCALE,
        skin: core.skin * SCALE,
        step_height: core.step_height * SCALE,
        ..core
    };
    app.world_mut().spawn((
        CharacterController::rect(Vec2::new(HALF.x, HALF.y) * SCALE).with_config(config),
        Transform::from_xyz(START.x * SCALE, -START.y * SCALE, 0.0),
    ));
    let x = platform_at(0, support::dt());
    app.world_mut().spawn((
        Platform::one_way(Vec2::ZERO, Vec2::new(PLATFORM_WIDTH * SCALE, 0.0)),
        Transform::from_xyz(x * SCALE, -PLATFORM_Y * SCALE, 0.0),
    ));
    app
}

#[test]
fn a_character_walks_jumps_and_lands_on_the_moving_platform_then_reaches_the_goal() {
    let mut app = plugin_app();
    support::run_steps(&mut app, u64::from(FRAMES));
    let rules = app.world().resource::<Rules>();
    let run = app.world().resource::<Run>();
    assert!(run.frames_riding > 30, "rode {} frames", run.frames_riding);
    assert!(rules.jumps >= 2, "{} jumps", rules.jumps);
    assert!(run.goal_frame.is_some(), "the goal was not reached");
    // The character landed on the platform: its ground was the platform's entity, its
    // normal up, and every step reported the ground it stood on.
    let contacts = support::collected::<SurfaceContact>(&app);
    let platform = app
        .world_mut()
        .query_filtered::<Entity, With<Platform>>()
        .single(app.world())
        .unwrap();
    let on_platform = contacts
        .iter()
        .filter(|c| c.side == Side::Ground && c.touch.platform == Some(platform))
        .count();
    assert!(
        on_platform > 30,
        "{on_platform} ground contacts on the platform"
    );
    assert!(
        contacts
            .iter()
            .filter(|c| c.touch.platform == Some(platform))
            .all(|c| c.touch.normal == Vec2::Y && c.touch.tile.is_none())
    );
    assert!(support::collected::<Crushed>(&app).is_empty());
}

#[test]
fn the_plugin_moves_the_character_as_the_core_does_bit_for_bit() {
    let core = core_run();
    let mut app = plugin_app();
    support::run_steps(&mut app, u64::from(FRAMES));
    let plugin = app.world().resource::<Run>();
    assert_eq!(plugin.positions.len(), core.positions.len());
    for (frame, (p, c)) in plugin.positions.iter().zip(&core.positions).enumerate() {
        assert_eq!(
            (p.x.to_bits(), p.y.to_bits()),
            (c.x.to_bits(), c.y.to_bits()),
            "frame {frame}: plugin {p}, core {c}"
        );
    }
    assert_eq!(plugin.goal_frame, core.goal_frame);
    assert_eq!(plugin.frames_riding, core.frames_riding);
    assert_eq!(app.world().resource::<Rules>().jumps, core.jumps);
}
