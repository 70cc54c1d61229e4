//! tileslide in Bevy: collision against tile maps loaded from files, bodies that slide round
//! each other, platformer characters, hit volumes and navigation agents, stepped in a fixed
//! schedule.
//!
//! **Supported Bevy version: 0.19** (0.19.1; Rust 1.95). The plugin uses Bevy without
//! rendering (`default-features = false`, with `std` and `bevy_asset`), so it builds into
//! headless servers and tests; a game brings the rest of Bevy.
//!
//! # The parts
//!
//! - [`TileslidePlugin`] adds everything; its systems run in `FixedUpdate` (or the
//!   schedule you give) in three public sets, [`TileslideSet::SyncIn`], `Step` and
//!   `Writeback`, in that order.
//! - [`CollisionMap`] (a resource) is the map every step collides against: built in code
//!   from a `tileslide::TileMap`, or kept in step with a [`TileMapAsset`] that
//!   [`TileMapLoader`] reads from `.txt`, `.tmx`, `.tmj`, `.ldtk` or `.tsm` files (reloaded when the
//!   file changes, with the `hot_reload` feature).
//! - [`Body`] with [`ProposedMove`] and [`Velocity`]: circles and compounds, resolved
//!   together by the core's `Bodies` each step; with [`ReportContacts`], each contact that
//!   stopped or turned one is sent as a [`BodyContact`].
//! - [`CharacterController`] with [`CharacterInput`] and [`CharacterContacts`]: the core's
//!   platformer character.
//! - [`Platform`]: segments that move with an entity (moving platforms, doors), submitted
//!   to the map as temporary segments each step.
//! - [`HitVolumes`]: attack and vulnerability volumes with hit types and teams.
//! - [`NavAgent`]: bodies that follow a path or a flow field to a goal.
//! - [`TilemapCollision`]: with the `ecs_tilemap` feature, a bevy_ecs_tilemap layer as the
//!   collision map, kept in step with its tiles.
//! - [`Interpolated`]: shows a body or a character between fixed steps.
//! - With the `debug` feature, `TileslideDebugPlugin` draws the core's debug lines (active
//!   segments, normals, hidden seams, temporaries, bodies, contacts, volumes, paths) with
//!   Bevy's gizmos.
//! - Messages and entity events: [`SurfaceContact`], [`BodyContact`], [`Crushed`], [`Hit`]
//!   (each with the tile's cell and id where a tile is involved), [`NavArrived`], and
//!   [`TileslideError`]
//!   for components the core refused.
//!
//! # Units and axes
//!
//! Components are in world units, y up. The map is y down (as editors draw it): a map
//! point `(x, y)` is the world point `(x · scale, −y · scale)` ([`MapUnits`]). Bevy 0.19
//! uses glam 0.32 and tileslide glam 0.34; [`MapUnits`] converts between their `Vec2`s.
//!
//! # Determinism
//!
//! With a power-of-two scale the plugin gives the core's results bit for bit: bodies are
//! added to the core in entity order, positions are kept in the core and only written to
//! `Transform`s, and a `Transform` moved by the game is a teleport.
#![forbid(unsafe_code)]
// Bevy systems take what they use as parameters, queries as tuples: that is how Bevy code
// reads, not a design to factor.
#![allow(clippy::too_many_arguments, clippy::type_complexity)]

mod bodies;
mod character;
#[cfg(feature = "debug")]
mod debug;
#[cfg(feature = "ecs_tilemap")]
mod ecs_tilemap;
mod hits;
mod loader;
mod map;
mod messages;
mod nav;
mod platform;
mod plugin;
mod position;
// Without the `ecs_tilemap` feature nothing reads a layer: the module's logic is still built
// and tested, free of the renderer the feature brings.
#[cfg_attr(not(feature = "ecs_tilemap"), allow(dead_code))]
mod tilemap;
mod units;

pub use bodies::{Body, BodyLink, ProposedMove, ReportContacts, TileslideBodies, Velocity};
pub use character::{CharacterContacts, CharacterController, CharacterInput};
#[cfg(feature = "debug")]
pub use debug::{DebugDraw, TileslideDebugPlugin, color_of};
pub use hits::{HitLink, HitShape, HitVolume, HitVolumes, TileslideHits};
pub use loader::{MAX_EXTERNAL_FILES, MapLoadError, TileMapLoader, TileMapSettings};
pub use map::{CollisionMap, TileMapAsset};
pub use messages::{
    BodyContact, Crushed, Hit, NavArrived, Side, SurfaceContact, SurfaceTouch, TileRef,
    TileslideError,
};
pub use nav::{NavAgent, NavGoal, NavStatus, Navigation};
pub use platform::{Platform, PlatformLink, PlatformSegment};
pub use plugin::{StepCount, TileslidePlugin, TileslideSet};
pub use position::{Interpolated, StepPosition};
pub use tilemap::TilemapCollision;
pub use units::{InvalidScale, MapUnits};

/// The crate's README, its quick start compiled and run as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
