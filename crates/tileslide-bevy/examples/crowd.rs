//! A crowd of circles flowing to the cursor round each other and along the walls of a
//! Tiled map (`examples/maps/cave.tmj`), down one shared flow field.
//!
//! ```sh
//! cargo run -p tileslide-bevy --features examples --example crowd
//! ```
//!
//! Hold the left mouse button to call the crowd to the cursor; F1 shows or hides the debug
//! lines (the map's active segments, the bodies, their contacts), F2 shows every kind.

// Bevy systems take what they use as parameters, queries as tuples: that is how Bevy code
// reads.
#![allow(clippy::too_many_arguments, clippy::type_complexity)]

mod support;

use bevy::prelude::*;
use bevy::window::PrimaryWindow;
use tileslide::Cell;
use tileslide_bevy::{
    Body, CollisionMap, Interpolated, MapUnits, NavAgent, NavGoal, NavStatus, TileMapAsset,
    TileslideBodies, TileslidePlugin,
};

/// Tiled's cell, in pixels: the world unit is one cell.
const CELL: f32 = 16.0;
const RADIUS: f32 = 0.3;
const SPEED: f32 = 5.0;
/// How many circles, at most (one to a free cell).
const CROWD: usize = 600;

fn main() -> AppExit {
    let plugin = TileslidePlugin::default().with_scale(1.0 / CELL);
    let mut app = support::app("tileslide: a crowd flowing to the cursor (Tiled)", plugin);
    app.init_resource::<Crowd>()
        .add_systems(Startup, setup)
        .add_systems(Update, ((spawn_crowd, call_the_crowd).chain(), hud));
    app.run()
}

#[derive(Resource, Default)]
struct Crowd {
    map: Handle<TileMapAsset>,
    spawned: usize,
    goal: Option<Vec2>,
    /// The free cell farthest from where the crowd starts: its goal when it plays itself.
    far: Option<Vec2>,
}

fn setup(mut commands: Commands, assets: Res<AssetServer>, mut crowd: ResMut<Crowd>) {
    crowd.map = assets.load("cave.tmj");
    commands.insert_resource(CollisionMap::from_asset(crowd.map.clone()));
    // Framed on the map (30 × 16 cells) once it has loaded.
    commands.spawn(support::camera(Vec2::ZERO, 31.0, 17.0));
    commands.spawn(support::hud("loading the map…"));
}

/// Once the map has loaded: a circle at the centre of each free cell the crowd can stand
/// in, up to [`CROWD`], in the map's top-left quarter first.
fn spawn_crowd(
    mut commands: Commands,
    mut crowd: ResMut<Crowd>,
    map: Option<Res<CollisionMap>>,
    units: Res<MapUnits>,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<ColorMaterial>>,
    mut camera: Single<&mut Transform, With<Camera2d>>,
) {
    if crowd.spawned > 0 {
        return;
    }
    let Some(map) = map.as_ref().and_then(|m| m.map()) else {
        return;
    };
    let bounds = map.bounds();
    let centre = units.to_world((bounds.min + bounds.max) * 0.5);
    camera.translation = centre.extend(camera.translation.z);
    let mesh = meshes.add(Circle::new(RADIUS));
    let material = materials.add(Color::srgb(0.95, 0.55, 0.35));
    let mut free = Vec::new();
    for row in 0..map.height() {
        for col in 0..map.width() {
            let cell = Cell::new(col, row);
            let centre = map.cell_corner(cell) + map.cell_size() * 0.5;
            if map.tile(cell).is_none() && is_open(map, centre) {
                free.push(centre);
            }
        }
    }
    // Nearest the top-left first: the crowd starts in one place and spreads out from it.
    free.sort_by(|a, b| (a.x + a.y).total_cmp(&(b.x + b.y)));
    crowd.far = free.last().map(|&p| units.to_world(p));
    for centre in free.into_iter().take(CROWD) {
        commands.spawn((
            Body::circle(RADIUS),
            NavAgent::new(RADIUS, SPEED),
            Interpolated,
            Transform::from_translation(units.to_world(centre).extend(1.0)),
            Mesh2d(mesh.clone()),
            MeshMaterial2d(material.clone()),
        ));
        crowd.spawned += 1;
    }
}

/// True when a circle of the crowd's radius at `centre` (map units) touches no wall.
fn is_open(map: &tileslide::TileMap, centre: tileslide::Vec2) -> bool {
    let radius = RADIUS * CELL;
    let circle = tileslide::Circle::new(centre, radius * 1.05);
    map.segments_overlapping_circle(&circle).is_empty()
}

/// Holding the left button (or, taking a screenshot, from the start) calls the crowd to the
/// cell under the cursor.
fn call_the_crowd(
    buttons: Res<ButtonInput<MouseButton>>,
    window: Single<&Window, With<PrimaryWindow>>,
    camera: Single<(&Camera, &GlobalTransform)>,
    scripted: Option<Res<support::Screenshotting>>,
    map: Option<Res<CollisionMap>>,
    units: Res<MapUnits>,
    mut crowd: ResMut<Crowd>,
    mut agents: Query<&mut NavAgent>,
) {
    let target = if scripted.is_some() {
        crowd.far
    } else if buttons.pressed(MouseButton::Left) {
        support::cursor_world(&window, &camera)
    } else {
        None
    };
    let Some(target) = target else {
        return;
    };
    let Some(map) = map.as_ref().and_then(|m| m.map()) else {
        return;
    };
    // The centre of the free cell under it, so that the crowd shares one flow field.
    let Some(cell) = map.cell_at(units.to_map(target)) else {
        return;
    };
    if map.tile(cell).is_some() {
        return;
    }
    let goal = units.to_world(map.cell_corner(cell) + map.cell_size() * 0.5);
    if crowd.goal == Some(goal) {
        return;
    }
    crowd.goal = Some(goal);
    for mut agent in &mut agents {
        agent.set_goal(Some(NavGoal::Flow(goal)));
    }
}

fn hud(
    crowd: Res<Crowd>,
    bodies: Option<Res<TileslideBodies>>,
    agents: Query<&NavAgent>,
    mut text: Single<&mut Text, With<support::Hud>>,
) {
    let report = bodies.map(|b| b.last_report()).unwrap_or_default();
    let stuck = agents
        .iter()
        .filter(|a| a.status() == NavStatus::Unreachable)
        .count();
    let goal = match crowd.goal {
        Some(g) => format!("flowing to ({:.1}, {:.1})", g.x, -g.y),
        None => "waiting".to_owned(),
    };
    text.0 = format!(
        "{} circles  |  {goal}  |  {} moving, {} contacts last step, {stuck} with no way there\nhold the left button to call them, F1/F2 debug lines",
        crowd.spawned, report.moving, report.contact_count
    );
}
