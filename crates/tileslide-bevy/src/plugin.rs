//! The plugin: its settings, its system sets and the order of a step.

use bevy::app::PostUpdate;
use bevy::ecs::intern::Interned;
use bevy::ecs::schedule::ScheduleLabel;
use bevy::prelude::*;
use bevy::transform::TransformSystems;
use tileslide::{NavConfig, ResolveConfig};

use crate::bodies::{self, TileslideBodies};
use crate::character;
use crate::hits::{self, TileslideHits};
use crate::loader::TileMapLoader;
use crate::map::{self, TileMapAsset};
use crate::messages::{BodyContact, Crushed, Hit, NavArrived, SurfaceContact, TileslideError};
use crate::nav::{self, Navigation};
use crate::platform;
use crate::position;
use crate::units::{InvalidScale, MapUnits};

/// tileslide in a Bevy app: the map asset and its loader, and each step (in
/// [`FixedUpdate`] by default) the moving platforms, navigation, characters, bodies and hit
/// volumes, with `Transform`s written back and contacts, crushes, hits and arrivals sent.
///
/// ```
/// use bevy::prelude::*;
/// use tileslide_bevy::{Body, CollisionMap, TileslidePlugin, Velocity};
///
/// let map = tileslide::io::ascii::parse("#####\n#...#\n#####", "hall.txt", 1.0)?;
/// let mut app = App::new();
/// app.add_plugins((MinimalPlugins, TileslidePlugin::default()))
///     .insert_resource(CollisionMap::new(map))
///     .insert_resource(Time::<Fixed>::from_hz(60.0))
///     .insert_resource(bevy::time::TimeUpdateStrategy::FixedTimesteps(1));
/// // A ball rolling right into the wall at x = 4 (world y is the map's, negated).
/// let ball = app
///     .world_mut()
///     .spawn((Body::circle(0.4), Velocity(Vec2::new(60.0, 0.0)), Transform::from_xyz(1.5, -1.5, 0.0)))
///     .id();
/// for _ in 0..10 {
///     app.update();
/// }
/// let x = app.world().get::<Transform>(ball).unwrap().translation.x;
/// assert!(x > 3.59 && x < 3.6);
/// # Ok::<(), tileslide::io::LoadError>(())
/// ```
#[derive(Clone, Debug)]
pub struct TileslidePlugin {
    schedule: Interned<dyn ScheduleLabel>,
    units: Result<MapUnits, InvalidScale>,
    resolve: ResolveConfig,
    nav: Option<NavConfig>,
}

impl Default for TileslidePlugin {
    fn default() -> Self {
        Self {
            schedule: FixedUpdate.intern(),
            units: Ok(MapUnits::default()),
            resolve: ResolveConfig::default(),
            nav: None,
        }
    }
}

impl TileslidePlugin {
    /// The plugin stepping in `schedule` instead of [`FixedUpdate`] (a schedule of the
    /// game's own, stepped as it likes; interpolation assumes a fixed one).
    #[must_use]
    pub fn in_schedule(self, schedule: impl ScheduleLabel) -> Self {
        Self {
            schedule: schedule.intern(),
            ..self
        }
    }

    /// The plugin with `scale` world units per map unit (see [`MapUnits`]). A scale
    /// [`MapUnits::new`] refuses leaves 1 in place and is reported when the app is built.
    #[must_use]
    pub fn with_scale(self, scale: f32) -> Self {
        Self {
            units: MapUnits::new(scale),
            ..self
        }
    }

    /// The plugin resolving bodies with `config` (map units; a config the core refuses
    /// leaves the default in place and is reported when the app is built).
    #[must_use]
    pub fn with_resolve_config(self, config: ResolveConfig) -> Self {
        Self {
            resolve: config,
            ..self
        }
    }

    /// The plugin building its navigation grid with `config` (map units). Without it, the
    /// core's default serves circles up to one cell of the map wide (`max_radius` the
    /// map's shorter cell side, so 16 for a map of 16-pixel tiles).
    #[must_use]
    pub fn with_nav_config(self, config: NavConfig) -> Self {
        Self {
            nav: Some(config),
            ..self
        }
    }
}

/// The parts of a step, in order, in the plugin's schedule. Game systems that move
/// platforms, set velocities and proposed moves or edit the map run before
/// [`SyncIn`](Self::SyncIn); those that read where things went and what they hit run
/// after [`Writeback`](Self::Writeback).
#[derive(SystemSet, Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TileslideSet {
    /// Takes the game's state in: the map asset, new and removed bodies, teleports,
    /// platforms' segments, agents' steering, proposed moves.
    SyncIn,
    /// Moves characters, then resolves and moves bodies.
    Step,
    /// Writes positions into `Transform`s, tests hit volumes, sends the messages.
    Writeback,
}

/// How many steps the plugin has run.
#[derive(Resource, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct StepCount(pub u64);

fn count_step(mut count: ResMut<StepCount>) {
    count.0 += 1;
}

impl Plugin for TileslidePlugin {
    fn build(&self, app: &mut App) {
        let mut bodies = TileslideBodies::default();
        let refused = bodies.set_config(self.resolve).err();
        let units = self.units.unwrap_or_default();
        app.insert_resource(units)
            .insert_resource(bodies)
            .insert_resource(self.nav.map_or_else(Navigation::default, Navigation::new))
            .init_resource::<TileslideHits>()
            .init_resource::<StepCount>()
            .add_message::<SurfaceContact>()
            .add_message::<BodyContact>()
            .add_message::<Crushed>()
            .add_message::<Hit>()
            .add_message::<NavArrived>()
            .add_message::<TileslideError>();
        let schedule = self.schedule;
        app.configure_sets(
            schedule,
            (
                TileslideSet::SyncIn,
                TileslideSet::Step,
                TileslideSet::Writeback,
            )
                .chain()
                .run_if(map::has_map),
        );
        app.add_systems(
            schedule,
            (
                (
                    platform::submit_platforms,
                    bodies::add_and_remove_bodies,
                    nav::steer_agents,
                    bodies::propose_moves,
                )
                    .chain()
                    .in_set(TileslideSet::SyncIn),
                (character::move_characters, bodies::step_bodies)
                    .chain()
                    .in_set(TileslideSet::Step),
                (
                    (bodies::write_back_bodies, character::write_back_characters),
                    hits::detect_hits,
                    count_step,
                )
                    .chain()
                    .in_set(TileslideSet::Writeback),
            ),
        );
        #[cfg(feature = "ecs_tilemap")]
        app.add_systems(
            schedule,
            crate::ecs_tilemap::follow_tilemap_layer.before(TileslideSet::SyncIn),
        );
        app.add_systems(
            PostUpdate,
            position::interpolate.before(TransformSystems::Propagate),
        );
        if let Some(e) = refused {
            app.world_mut().write_message(TileslideError {
                entity: Entity::PLACEHOLDER,
                message: format!("TileslidePlugin: {e}; the default resolve settings are used"),
            });
        }
        if let Err(e) = self.units {
            app.world_mut().write_message(TileslideError {
                entity: Entity::PLACEHOLDER,
                message: format!("TileslidePlugin: {e}; a scale of 1 is used"),
            });
        }
    }

    fn finish(&self, app: &mut App) {
        // The map asset needs Bevy's asset server (`AssetPlugin`, in `DefaultPlugins`);
        // without it maps are built in code.
        if app.world().contains_resource::<AssetServer>()
            && !app.world().contains_resource::<Assets<TileMapAsset>>()
        {
            app.init_asset::<TileMapAsset>()
                .register_asset_loader(TileMapLoader)
                // Every frame, so no reload is missed in frames without a fixed step.
                .add_systems(PreUpdate, map::follow_map_asset);
        }
    }
}
