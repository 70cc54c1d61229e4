//! The seeded standard scenes of BENCHMARKS.md, shared by tests, benchmarks and the CLI.
//!
//! Every figure tileslide publishes comes from these scenes, so they are
//! generated bit-for-bit from the seeds in BENCHMARKS.md with [`SplitMix64`]:
//!
//! - the maps [`dungeon256`] and [`open256`] (also by name through [`Scene`]),
//!   as a plain [`SolidGrid`] of solid/empty cells;
//! - the "rays" scene, [`scene_rays`], with [`reference_hit_distance`] as the
//!   plain grid walk that defines what counts as a hit;
//! - the "crowd" scene, [`scene_crowd`] (circles of [`CROWD_RADIUS`] on the
//!   free spots of [`crowd_candidates`], each with a constant velocity), with
//!   [`audit_crowd`] as the end-of-run check for overlaps and wall penetrations;
//! - the "broad" scene, [`scene_broad`] (circles of [`BROAD_RADIUS`] bouncing around the
//!   square `[1, 255]²` under [`update_broad`]), with [`broad_pairs_reference`] as the exact
//!   set of overlapping [boxes](broad_box) every broad phase must report;
//! - the checks of determinism: [`Fnv1a`], the one hash behind the maps' fingerprints, the
//!   crowd's golden [`positions_hash`] and the demos' state hashes.
//!
//! Conventions: cell `(x, y)` covers `[x, x+1] × [y, y+1]`, cells are stored
//! row-major (`y * width + x`), and cells outside a grid are empty.
//! [`SolidGrid::to_tile_map`] turns a grid into a `tileslide` map of solid squares.
//!
//! ```
//! use tileslide_scenes::{Scene, reference_hit_distance, scene_rays};
//!
//! let grid = Scene::Dungeon256.grid();
//! assert_eq!(grid.fingerprint_hex(), "a36c9fd56f2ba422");
//! let hits = scene_rays(&grid, 1_000)
//!     .iter()
//!     .filter(|ray| reference_hit_distance(&grid, ray).is_some())
//!     .count();
//! assert!(hits > 900);
//! ```
#![forbid(unsafe_code)]

mod audit;
mod broad;
mod crowd;
mod dungeon;
mod edges;
mod fnv;
mod grid;
mod rays;
mod reference_walk;
mod rng;
mod scene;
mod tile_map;
pub use tile_map::TileMapError;

pub use audit::{AUDIT_TOLERANCE, CrowdAudit, audit_crowd};
pub use broad::{
    BROAD_RADIUS, BroadCircle, boxes_overlap, broad_box, broad_boxes, broad_pairs_reference,
    scene_broad, update_broad,
};
pub use crowd::{CROWD_RADIUS, CrowdBody, crowd_candidates, run_crowd, scene_crowd};
pub use dungeon::{dungeon256, open256};
pub use edges::ExposedEdge;
pub use fnv::{Fnv1a, positions_hash};
pub use grid::SolidGrid;
pub use rays::{SceneRay, scene_rays};
pub use reference_walk::reference_hit_distance;
pub use rng::SplitMix64;
pub use scene::Scene;
