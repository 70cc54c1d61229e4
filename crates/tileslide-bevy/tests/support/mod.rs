//! What the plugin's tests share: a headless app stepped one fixed step per update.

#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::time::Duration;

use bevy::asset::{AssetPlugin, LoadState};
use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use tileslide_bevy::{StepCount, TileMapAsset, TileslidePlugin};

/// The fixed step of every test: 60 a second.
pub const STEP: Duration = Duration::from_nanos(16_666_667);

/// The step as the plugin's systems see it (`Time::delta_secs`), for the same scene run
/// on the core.
pub fn dt() -> f32 {
    STEP.as_secs_f32()
}

/// A headless app (`MinimalPlugins`, no window, no GPU) with `plugin`, whose every
/// `update` runs exactly one fixed step of [`STEP`].
pub fn headless(plugin: TileslidePlugin) -> App {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, plugin))
        .insert_resource(Time::<Fixed>::from_duration(STEP))
        .insert_resource(TimeUpdateStrategy::FixedTimesteps(1));
    app
}

/// Updates `app` until the plugin has run `steps` more steps (at most `steps + 10`
/// updates: the first update of an app runs no fixed step).
pub fn run_steps(app: &mut App, steps: u64) {
    let until = app.world().resource::<StepCount>().0 + steps;
    for _ in 0..steps + 10 {
        if app.world().resource::<StepCount>().0 >= until {
            return;
        }
        app.update();
    }
    panic!("the plugin did not run {steps} steps");
}

/// The messages of type `M` the plugin sent, in order, kept by [`collect`].
#[derive(Resource)]
pub struct Collected<M>(pub Vec<M>);

/// Keeps every message of type `M` in [`Collected<M>`], from now on.
pub fn collect<M: Message + Clone>(app: &mut App) {
    app.insert_resource(Collected::<M>(Vec::new()));
    app.add_systems(
        Last,
        |mut reader: MessageReader<M>, mut kept: ResMut<Collected<M>>| {
            kept.0.extend(reader.read().cloned());
        },
    );
}

/// The messages of type `M` collected so far.
pub fn collected<M: Message + Clone>(app: &App) -> Vec<M> {
    app.world().resource::<Collected<M>>().0.clone()
}

/// The repository's bundled maps.
pub fn maps_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/maps")
}

/// A headless app whose assets are read from `root`.
pub fn app_reading(root: &Path) -> App {
    let mut app = headless(TileslidePlugin::default());
    app.add_plugins(AssetPlugin {
        file_path: root.to_string_lossy().into_owned(),
        ..default()
    });
    // `finish` registers the map asset: build the app as `run` would.
    app.finish();
    app.cleanup();
    app
}

/// Updates `app` until `handle` has loaded or failed.
pub fn wait_for(app: &mut App, handle: &Handle<TileMapAsset>) -> LoadState {
    for _ in 0..2000 {
        app.update();
        let state = app.world().resource::<AssetServer>().load_state(handle);
        if matches!(state, LoadState::Loaded | LoadState::Failed(_)) {
            return state;
        }
        std::thread::sleep(std::time::Duration::from_millis(1));
    }
    panic!("the map neither loaded nor failed");
}

/// Waits for `handle`, and fails with its error unless it loaded.
pub fn assert_loaded(app: &mut App, handle: &Handle<TileMapAsset>) {
    match wait_for(app, handle) {
        LoadState::Loaded => {}
        LoadState::Failed(e) => panic!("{e}"),
        other => panic!("{other:?}"),
    }
}

/// Loads the map at `path` (relative to the app's asset folder).
pub fn load(app: &mut App, path: &str) -> Handle<TileMapAsset> {
    app.world().resource::<AssetServer>().load(path.to_string())
}
