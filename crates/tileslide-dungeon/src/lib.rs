//! # tileslide-dungeon
//!
//! Dungeon Builder, the demo game of issue 8, as a deterministic fixed-step simulation
//! built only on tileslide's public API. A keeper digs a dungeon out of a disc of earth
//! inside rock, from the treasure room towards the entrance, paying gold per square, and
//! summons skeletons (melee) and imps (fireballs); hero parties arrive every 30 seconds,
//! fight their way to the treasure along a flow field and carry it out.
//!
//! - Movement: every fighter is a circle in [`tileslide::Bodies`]; each step brains
//!   propose moves and the resolver steps them (no overlaps, no wall crossings).
//! - Navigation: a [`tileslide::NavGrid`] updated per dug square; heroes follow
//!   [`tileslide::FlowField`]s, creatures walk [`tileslide::NavPath`]s home; both are
//!   refreshed only when a dug square affects them.
//! - Hits: [`tileslide::HitWorld`] attack and vulnerability volumes with teams; melee
//!   swings hit each victim once, fireballs are swept along their step.
//! - Line of sight and fireball walls: [`tileslide::TileMap::cast_ray`].
//! - Entities live in a [`hecs::World`]; systems talk through [`Event`]s.
//!
//! ```
//! let mut game = tileslide_dungeon::Game::new(1)?;
//! for _ in 0..30 {
//!     game.step()?;
//! }
//! assert_eq!(game.summary().steps, 30);
//! assert_eq!(game.summary().audit.overlapping_pairs, 0);
//! # Ok::<(), tileslide_dungeon::GameError>(())
//! ```

// The modules import each other in one direction only. At the bottom, plain types:
// `step` (the fixed step), `error`, `components`, `events`, `config`, `audit`, `explore`,
// `layout`. Above them the shared world: `level` (map and navigation), `spawn`, `hits`.
// Then the systems, each using only those: `keeper`, `arrivals`, `brains`, `combat` (which
// reads `brains`' sightings), `treasure`, `summary`. `game` runs the systems in order;
// `render` draws a `Game`, and `screen` frames it with the HUD and the legend.

mod arrivals;
mod audit;
mod brains;
mod combat;
mod components;
mod config;
mod error;
mod events;
mod explore;
mod game;
mod hits;
mod keeper;
mod layout;
mod level;
mod render;
mod screen;
mod spawn;
mod step;
mod summary;
mod treasure;

pub use audit::Audit;
pub use components::{Goal, Kind, Team};
pub use config::{GameConfig, Party};
pub use error::GameError;
pub use events::Event;
pub use explore::Explored;
pub use game::Game;
pub use level::Level;
pub use render::{colour, style};
pub use screen::{HEIGHT, Screen, WIDTH};
pub use step::{DT, STEPS_PER_SECOND};
pub use summary::Summary;
pub use tileslide_scenes::SplitMix64;
