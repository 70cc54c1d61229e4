//! # tileslide
//!
//! Collision detection for tile-based 2D games: tiles hold line segments with outward
//! normals (slopes, bumps, one-way platforms), the map hides the seams between neighbouring
//! tiles, and ray casts walk the grid exactly and return the globally nearest hit.
//! [`Bodies`] moves circles (and compounds of circles) through the map: each tick every body
//! proposes a move, [`Bodies::resolve`] checks the moves against each other and the walls at
//! the exact time of impact and slides the blocked remainder along the contact tangent, so
//! crowds flow around each other and along walls without ever overlapping. [`HitWorld`]
//! finds the hits between objects' attack and vulnerability volumes each frame, with hit
//! types, teams and "hit once per swing", exactly and along fast moves. [`Character`] is a
//! platformer's box or circle: moved by velocity × dt, it walks slopes, snaps to the ground,
//! stands on one-way platforms and reports its ground, ceiling and wall contacts.
//!
//! ## Conventions
//!
//! - Vectors are [`glam::Vec2`] (`f32`), re-exported as [`Vec2`].
//! - A cell is a [`Cell`] `{ col, row }`; cell (c, r) covers `[c·w, (c+1)·w) × [r·h, (r+1)·h)`
//!   from the map's origin. The map does not assume which way is up.
//! - A position along a ray or move is `t` in `[0, 1]`.
//! - Normals point out of solid material; by default a ray hits only faces it meets
//!   head-on (`dot(normal, p1 − p0) < 0`).
//! - Coordinates are at most [`MAX_COORD`](limits::MAX_COORD) (2²⁴ map units) from the origin: maps reaching
//!   past it, and positions, moves' end points, radii and sizes past it, are refused with an
//!   error naming the value. Ray casts answer every finite ray; a circle cast every finite
//!   motion of a circle whose centre and radius are in the range.
//! - Bad input (files, shapes, cells) is an error naming what and where, never a panic.
//!
//! ## What is where
//!
//! The crate root holds what a game uses every frame: the map and its tiles and temporary
//! segments, the queries and their hits, bodies, the character, hit volumes, paths, their
//! errors, the shapes these take ([`Segment`], [`Ray`], [`Circle`], [`Aabb`]), the
//! caller's entity ([`Owner`]), [`Vec2`], and [`DebugLines`]: what the world looks like as
//! kinded segments, circles, points and boxes, which every part fills with a `debug_lines`
//! method and every front end draws. Four public modules hold the rest:
//! [`io`] (the loaders), [`geometry`] (the exact pair primitives the rest is built on),
//! [`broadphase`] (pairs of overlapping boxes) and [`limits`] (the largest coordinates,
//! maps and grids accepted).
//!
//! ## Features
//!
//! - `tiled` (default): Tiled maps, `.tmx` and `.tmj`, in [`io::tiled`].
//! - `png` (default): tile sets traced from PNG tile sheets, in [`io::bitmap`].
//! - `aim` (default): hit volumes that aim in any direction: [`HitObject::aim`] turns an
//!   object's attack volumes, and capsule volumes (`Volume::capsule`). Without it,
//!   [`HitWorld::register`] refuses an aim, and the hit volumes take less code (the web
//!   package leaves it out).
//! - `tiled-zstd`: zstd-compressed Tiled tile layers (builds the zstd C library).
//! - `serde`: `Serialize` and `Deserialize` for the value types a game saves or sends:
//!   shapes, configurations, filters, hits, contacts, reports, handles and ids (ids and
//!   flags as their numbers). A [`BodyShape`] is read through [`BodyShape::compound`], so a
//!   saved shape is checked as a built one is; other values are checked where they enter a
//!   system, as built ones are. Also snapshots: [`Bodies`], a [`HitWorld`]'s memory, a
//!   [`Character`] and [`MapEdits`], saved at a step and restored to go on bit for bit as the run that was
//!   never interrupted (rollback netcode, replays), and checked as they are read.
//! - `parallel`: large pieces of work split across the threads of a rayon pool (the global
//!   pool, or the one a call runs in): ray batches, [`Bodies::resolve`] (in waves of bodies
//!   that do not meet), the broadphase's scan, [`HitWorld::detect`]'s volume tests, flow
//!   fields ([`FlowField::new_many`] builds several at once). The answers are the same, bit
//!   for bit, on any number of threads and without the feature (`docs/parallel.md`).
//!
//! ## Quick start
//!
//! ```
//! use tileslide::{io::ascii, Ray, QueryFilter, Vec2};
//!
//! // '#' solid, '/' and '\' ramps, '=' one-way platform; row 0 is the top line.
//! let map = ascii::parse("\
//! ##########
//! #........#
//! #.=......#
//! #.../####
//! ##########", "quick.txt", 1.0)?;
//!
//! // Straight down from above the ramp: the nearest hit is on its slope.
//! let down = Ray::between(Vec2::new(4.75, 1.5), Vec2::new(4.75, 4.5));
//! let hit = map.cast_ray(down, &QueryFilter::default()).unwrap();
//! assert!((hit.point.y - 3.25).abs() < 1e-6);
//! assert_eq!(hit.cell().map(|c| (c.col, c.row)), Some((4, 3)));
//!
//! // Upward through the one-way platform: its back face does not block.
//! let up = Ray::between(Vec2::new(2.5, 2.5), Vec2::new(2.5, 1.5));
//! assert!(map.cast_ray(up, &QueryFilter::default()).is_none());
//! # Ok::<(), tileslide::io::LoadError>(())
//! ```

mod bodies;
pub mod broadphase;
mod controller;
pub mod debug;
pub mod geometry;
pub mod io;
pub mod limits;
mod owner;
mod path;
mod prefetch;
mod query;
mod snapshot;
mod tiles;
mod volumes;

pub use bodies::{
    Bodies, Body, BodyDesc, BodyError, BodyFate, BodyFilter, BodyHandle, BodyShape, BodyTrace,
    ContactPart, ContactSource, ContactTrace, PassTrace, ResolveConfig, ResolveReport,
    ResolveTrace, Response, SlideMode,
};
pub use controller::{
    Character, CharacterShape, Contact, Contacts, ControllerConfig, ControllerError, MoveEvent,
    MoveHit, MoveOptions, MoveTrace, OneWayPass, SlideResponse, Surface, SweepPurpose, SweepTrace,
};
pub use debug::{DebugKind, DebugLines};
pub use geometry::aabb::Aabb;
pub use geometry::circle::Circle;
pub use geometry::ray::Ray;
pub use geometry::segment::Segment;
pub use glam::Vec2;
pub use owner::Owner;
pub use path::{FlowField, NAV_MOVES, NavChange, NavConfig, NavError, NavGrid, NavPath};
pub use query::{CastError, CircleHit, Faces, QueryFilter, RayHit, SegmentOverlap, SegmentSource};
pub use snapshot::{MapEdits, SnapshotError};
pub use tiles::{
    ActivePiece, ActiveSegment, Cell, CellExplanation, CellSide, EndJoin, HiddenPart, JournalError,
    MapError, MapRevision, PieceEnd, PlacedSegment, SegmentExplanation, SegmentFlags, SegmentRef,
    ShapeError, TemporaryError, TemporarySegment, TileId, TileMap, TileSegment, TileSet,
    TileSetError, TileShape, WallSource,
};
pub use volumes::{
    DetectTrace, Facing, HitEvent, HitObject, HitRule, HitTypes, HitWorld, ObjectId, PairOutcome,
    PairTrace, Refusal, TeamRule, Volume, VolumeError, VolumeShape, VolumeTest,
};

/// The README's quick start, compiled and run as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../../../README.md")]
pub struct ReadmeDoctests;
