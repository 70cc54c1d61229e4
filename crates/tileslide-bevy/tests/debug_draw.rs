//! The debug plugin fills its lines from the plugin's state (feature `debug`).

#![cfg(feature = "debug")]
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod support;

use bevy::gizmos::{AppGizmoBuilder, GizmoAsset};
use bevy::prelude::*;
use tileslide::DebugKind;
use tileslide::io::ascii;
use tileslide_bevy::{
    Body, CharacterController, CollisionMap, DebugDraw, TileslideDebugPlugin, TileslidePlugin,
};

#[test]
fn the_debug_lines_show_the_map_the_bodies_and_the_characters() {
    let map = ascii::parse("######\n#....#\n#.#..#\n######", "room.txt", 1.0).unwrap();
    let mut app = support::headless(TileslidePlugin::default());
    // What `Gizmos` needs without a renderer (a game gets it from `DefaultPlugins`).
    app.add_plugins((bevy::asset::AssetPlugin::default(), TileslideDebugPlugin))
        .init_asset::<GizmoAsset>()
        .init_gizmo_group::<DefaultGizmoConfigGroup>()
        .insert_resource(CollisionMap::new(map));
    app.finish();
    app.cleanup();
    app.world_mut()
        .spawn((Body::circle(0.3), Transform::from_xyz(1.5, -1.5, 0.0)));
    app.world_mut().spawn((
        CharacterController::circle(0.3),
        Transform::from_xyz(3.5, -1.5, 0.0),
    ));
    support::run_steps(&mut app, 3);
    let lines = app.world().resource::<DebugDraw>().lines();
    assert!(lines.count(DebugKind::ActiveSegment) > 0);
    assert!(lines.count(DebugKind::Normal) > 0);
    assert!(lines.count(DebugKind::HiddenSegment) > 0);
    assert_eq!(lines.count(DebugKind::Body), 1);
    assert_eq!(lines.count(DebugKind::Character), 1);
    // Switched off: nothing.
    app.world_mut().resource_mut::<DebugDraw>().enabled = false;
    app.update();
    assert!(app.world().resource::<DebugDraw>().lines().is_empty());
}
