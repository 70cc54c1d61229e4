//! A platformer on an LDtk level (`examples/maps/ldtk/platformer.ldtk`): ramps, one-way
//! platforms, two moving platforms from the level's entities, coins and a goal.
//!
//! ```sh
//! cargo run -p tileslide-bevy --features examples --example platformer
//! ```
//!
//! Arrows or A/D run, Space, W or Up jumps, Down or S drops through a one-way platform; F1
//! shows or hides the debug lines (active segments and normals, contacts), F2 shows every
//! kind. The level is loaded through Bevy's asset server and reloads when the file changes
//! (with the `hot_reload` feature).

// Bevy systems take what they use as parameters, queries as tuples: that is how Bevy code
// reads.
#![allow(clippy::too_many_arguments, clippy::type_complexity)]

mod support;

use bevy::prelude::*;
use bevy::transform::TransformSystems;
use tileslide::ControllerConfig;
use tileslide::io::ldtk::LdtkEntity;
use tileslide_bevy::{
    CharacterContacts, CharacterController, CharacterInput, CollisionMap, Interpolated, MapUnits,
    Platform, TileMapAsset, TileslidePlugin, TileslideSet,
};

/// LDtk's cell, in pixels: the world unit is one cell.
const CELL: f32 = 16.0;
const GRAVITY: f32 = 45.0;
const RUN: f32 = 8.0;
const JUMP: f32 = 15.5;
const MAX_FALL: f32 = 22.0;
/// Steps after leaving the ground in which a jump still works.
const COYOTE_STEPS: u32 = 6;

fn main() -> AppExit {
    let plugin = TileslidePlugin::default().with_scale(1.0 / CELL);
    let mut app = support::app("tileslide: platformer (LDtk)", plugin);
    app.init_resource::<Game>()
        .add_systems(Startup, setup)
        .add_systems(Update, (spawn_level, read_keys, collect, hud))
        .add_systems(
            FixedUpdate,
            (move_platforms, drive_player).before(TileslideSet::SyncIn),
        )
        .add_systems(PostUpdate, follow.before(TransformSystems::Propagate));
    app.run()
}

/// The level's handle, what was spawned from it, and the score.
#[derive(Resource, Default)]
struct Game {
    level: Handle<TileMapAsset>,
    spawned: bool,
    coins: u32,
    goal: Option<Vec2>,
    reached: bool,
    jump_asked: bool,
    steps: u32,
}

#[derive(Component)]
struct Player {
    since_ground: u32,
    /// The speed of the platform it jumped off, kept until it lands.
    carried: f32,
}

#[derive(Component)]
struct Coin(u32);

/// A platform moving along `path` (world points of its centre) at `speed`, back and forth
/// or round and round.
#[derive(Component)]
struct Mover {
    path: Vec<Vec2>,
    speed: f32,
    looped: bool,
    /// The leg it is on and how far along it.
    leg: usize,
    along: f32,
    forward: bool,
}

fn setup(mut commands: Commands, assets: Res<AssetServer>, mut game: ResMut<Game>) {
    game.level = assets.load("ldtk/platformer.ldtk");
    commands.insert_resource(CollisionMap::from_asset(game.level.clone()));
    commands.spawn(support::camera(Vec2::new(15.0, -10.0), 32.0, 18.0));
    commands.spawn(support::hud("loading the level…"));
}

/// Spawns the player, the platforms, the coins and the goal from the level's entities once
/// it has loaded.
fn spawn_level(
    mut commands: Commands,
    mut game: ResMut<Game>,
    levels: Res<Assets<TileMapAsset>>,
    units: Res<MapUnits>,
) {
    if game.spawned {
        return;
    }
    let Some(level) = levels.get(&game.level) else {
        return;
    };
    game.spawned = true;
    let world = |p: tileslide::Vec2| units.to_world(p);
    let size = |e: &LdtkEntity| Vec2::new(e.size.x, e.size.y) / CELL;
    for entity in level.entity_layers.iter().flat_map(|l| &l.entities) {
        let at = world(entity.center());
        match entity.identifier.as_str() {
            "PlayerStart" => {
                let half = Vec2::new(0.35, 0.65);
                let config = ControllerConfig {
                    step_height: 0.3,
                    ..ControllerConfig::default()
                };
                commands.spawn((
                    Player {
                        since_ground: 0,
                        carried: 0.0,
                    },
                    CharacterController::rect(half).with_config(config),
                    Interpolated,
                    Transform::from_translation(at.extend(1.0)),
                    Sprite::from_color(Color::srgb(0.35, 0.75, 0.95), half * 2.0),
                ));
            }
            "MovingPlatform" => {
                let half = size(entity) * 0.5;
                let points = entity
                    .field("path")
                    .and_then(|f| f.as_points())
                    .unwrap_or_default();
                // The path's first point is the platform's own cell: the path moves its centre.
                let offset = points.first().map_or(Vec2::ZERO, |&p| at - world(p));
                let mut path: Vec<Vec2> = points.iter().map(|&p| world(p) + offset).collect();
                if path.is_empty() {
                    path.push(at);
                }
                let speed = entity
                    .field("speed")
                    .and_then(|f| f.as_float())
                    .unwrap_or(32.0) as f32
                    / CELL;
                let looped = entity
                    .field("loop")
                    .and_then(|f| f.as_bool())
                    .unwrap_or(false);
                commands.spawn((
                    Platform::one_way(Vec2::new(-half.x, half.y), Vec2::new(half.x, half.y)),
                    Mover {
                        path,
                        speed,
                        looped,
                        leg: 0,
                        along: 0.0,
                        forward: true,
                    },
                    Transform::from_translation(at.extend(0.5)),
                    Sprite::from_color(Color::srgb(0.85, 0.6, 0.3), half * 2.0),
                ));
            }
            "Coin" => {
                let value = entity.field("value").and_then(|f| f.as_int()).unwrap_or(1);
                commands.spawn((
                    Coin(u32::try_from(value).unwrap_or(1)),
                    Transform::from_translation(at.extend(0.4)),
                    Sprite::from_color(Color::srgb(1.0, 0.85, 0.2), Vec2::splat(0.45)),
                ));
            }
            "Goal" => {
                game.goal = Some(at);
                commands.spawn((
                    Transform::from_translation(at.extend(0.3)),
                    Sprite::from_color(Color::srgba(0.3, 1.0, 0.5, 0.6), size(entity)),
                ));
            }
            _ => {}
        }
    }
}

/// A jump asked for between fixed steps is kept for the next one.
fn read_keys(keys: Res<ButtonInput<KeyCode>>, mut game: ResMut<Game>) {
    if keys.any_just_pressed([KeyCode::Space, KeyCode::KeyW, KeyCode::ArrowUp]) {
        game.jump_asked = true;
    }
}

/// Moves each platform along its path by its speed × the step.
fn move_platforms(time: Res<Time>, mut platforms: Query<(&mut Mover, &mut Transform)>) {
    for (mut mover, mut transform) in &mut platforms {
        let mover = &mut *mover;
        if mover.path.len() < 2 {
            continue;
        }
        let mut left = mover.speed * time.delta_secs();
        let at = loop {
            let (from, to) = leg(mover);
            let length = from.distance(to);
            if mover.along + left < length {
                mover.along += left;
                break from.lerp(to, mover.along / length.max(f32::MIN_POSITIVE));
            }
            left -= length - mover.along;
            mover.along = 0.0;
            next_leg(mover);
            if left <= 0.0 {
                break leg(mover).0;
            }
        };
        transform.translation = at.extend(transform.translation.z);
    }
}

/// The ends of the leg a platform is on, in the direction it goes.
fn leg(mover: &Mover) -> (Vec2, Vec2) {
    let n = mover.path.len();
    let (a, b) = (mover.leg, (mover.leg + 1) % n);
    if mover.forward {
        (mover.path[a], mover.path[b])
    } else {
        (mover.path[b], mover.path[a])
    }
}

/// On to the next leg: round the path when it loops, back along it at its ends when not.
fn next_leg(mover: &mut Mover) {
    let n = mover.path.len();
    if mover.looped {
        mover.leg = (mover.leg + 1) % n;
    } else if mover.forward {
        if mover.leg + 2 < n {
            mover.leg += 1;
        } else {
            mover.forward = false;
        }
    } else if mover.leg > 0 {
        mover.leg -= 1;
    } else {
        mover.forward = true;
    }
}

/// The player's velocity from the keys (or, taking a screenshot, a script): running,
/// jumping with coyote time and a platform's speed, gravity.
fn drive_player(
    time: Res<Time>,
    keys: Res<ButtonInput<KeyCode>>,
    scripted: Option<Res<support::Screenshotting>>,
    mut game: ResMut<Game>,
    mut player: Query<(&mut Player, &mut CharacterInput, &CharacterContacts)>,
) {
    let Ok((mut player, mut input, contacts)) = player.single_mut() else {
        return;
    };
    let dt = time.delta_secs();
    game.steps += 1;
    let (run, jump, drop) = if scripted.is_some() {
        // Run right and jump now and then (and at every wall).
        let wall = contacts.right.is_some();
        (1.0, wall || game.steps.is_multiple_of(50), false)
    } else {
        let pressed = |codes: [KeyCode; 2]| keys.any_pressed(codes);
        let run = f32::from(u8::from(pressed([KeyCode::ArrowRight, KeyCode::KeyD])))
            - f32::from(u8::from(pressed([KeyCode::ArrowLeft, KeyCode::KeyA])));
        let jump = std::mem::take(&mut game.jump_asked);
        (run, jump, pressed([KeyCode::ArrowDown, KeyCode::KeyS]))
    };
    if contacts.is_grounded() {
        (player.since_ground, player.carried) = (0, 0.0);
    } else {
        player.since_ground = player.since_ground.saturating_add(1);
    }
    let mut velocity = input.velocity;
    if jump && player.since_ground <= COYOTE_STEPS {
        velocity.y = JUMP;
        player.since_ground = COYOTE_STEPS + 1;
        // A jump off a moving platform keeps its speed until the landing.
        player.carried = contacts.ground.map_or(0.0, |ground| ground.velocity.x);
    }
    velocity.x = run * RUN + player.carried;
    velocity.y = (velocity.y - GRAVITY * dt).max(-MAX_FALL);
    input.velocity = velocity;
    input.drop_through = drop;
}

/// Picks up the coins the player touches, and notices the goal.
fn collect(
    mut commands: Commands,
    mut game: ResMut<Game>,
    player: Query<&Transform, With<Player>>,
    coins: Query<(Entity, &Coin, &Transform)>,
) {
    let Ok(player) = player.single() else {
        return;
    };
    let at = player.translation.truncate();
    for (entity, coin, transform) in &coins {
        if transform.translation.truncate().distance(at) < 0.8 {
            game.coins += coin.0;
            commands.entity(entity).despawn();
        }
    }
    if game.goal.is_some_and(|goal| goal.distance(at) < 1.2) {
        game.reached = true;
    }
}

fn hud(
    game: Res<Game>,
    player: Query<&CharacterContacts, With<Player>>,
    mut text: Single<&mut Text, With<support::Hud>>,
) {
    let Ok(contacts) = player.single() else {
        return;
    };
    let ground = match contacts.ground {
        Some(g) if g.platform.is_some() => "riding a platform".to_owned(),
        Some(g) => match g.tile {
            Some(t) => format!("on tile {} at ({}, {})", t.tile.0, t.cell.col, t.cell.row),
            None => "on the ground".to_owned(),
        },
        None => "in the air".to_owned(),
    };
    let goal = if game.reached { "  GOAL!" } else { "" };
    text.0 = format!(
        "coins {}  |  {ground}{goal}  |  arrows run, space jumps, down drops, F1/F2 debug lines",
        game.coins
    );
}

/// The camera follows the player, inside the level.
fn follow(
    player: Query<&Transform, (With<Player>, Without<Camera2d>)>,
    mut camera: Query<&mut Transform, With<Camera2d>>,
    map: Option<Res<CollisionMap>>,
    units: Res<MapUnits>,
) {
    let (Ok(player), Ok(mut camera)) = (player.single(), camera.single_mut()) else {
        return;
    };
    let mut at = player.translation.truncate();
    if let Some(bounds) = map.as_ref().and_then(|m| m.map()).map(|m| m.bounds()) {
        let (a, b) = (units.to_world(bounds.min), units.to_world(bounds.max));
        let (low, high) = (a.min(b), a.max(b));
        let half = Vec2::new(16.0, 9.0);
        at = at.clamp(low + half, (high - half).max(low + half));
    }
    camera.translation = at.extend(camera.translation.z);
}
