//! # tileslide-dungeon
//!
//! Dungeon Builder as a deterministic fixed-step simulation built only on tileslide's
//! public API. A keeper digs a dungeon out of a disc of earth inside rock, paying gold per
//! square, and summons skeletons (melee) and imps (fireballs); hero parties arrive every 30
//! seconds, explore, fight their way to the treasure along a flow field and carry it out.
//!
//! The keeper is either a script ([`GameConfig::new`], the game of `tileslide demo
//! dungeon`: it digs from the treasure room towards the entrance and summons when its rooms
//! are ready) or a player ([`GameConfig::player`]): the dungeon starts with a corridor from
//! the entrance to the treasure room, and the player's orders ([`Game::dig`] a square of
//! earth beside an open one for [`DIG_COST`] gold, [`Game::summon`] an imp or a skeleton
//! for its [`creature_cost`]) take effect at once or are refused with an [`OrderError`]
//! saying why. The game is lost when the heroes carry every piece of the treasure out and
//! won when the last party is seen off ([`Game::outcome`]).
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
//! use tileslide_dungeon::{Game, GameConfig, Kind, OrderError};
//! use tileslide::{Cell, Vec2};
//!
//! let mut game = Game::with_config(GameConfig::player(1))?;
//! game.dig(Cell::new(31, 20))?; // earth beside the corridor
//! game.summon(Kind::Imp, Vec2::new(32.5, 20.5))?;
//! assert!(matches!(game.dig(Cell::new(0, 0)), Err(OrderError::Rock { .. })));
//! game.step()?;
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
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
#![forbid(unsafe_code)]

// The modules import each other in one direction only. At the bottom, plain types:
// `step` (the fixed step), `error`, `components`, `events`, `config`, `audit`, `explore`,
// `layout`, `outcome`. Above them the shared world: `level` (map and navigation), `spawn`,
// `hits`. Then the systems, each using only those: `keeper`, `arrivals`, `brains`,
// `combat` (which reads `brains`' sightings), `treasure`, `summary`. `game` runs the
// systems in order; on top of it, `orders` carries out a player's orders, `view` gives
// renderers plain values, `render` draws a `Game` and `screen` frames it with the HUD
// and the legend.

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
mod orders;
mod outcome;
mod render;
mod screen;
mod spawn;
mod step;
mod summary;
mod treasure;
mod view;

pub use audit::Audit;
pub use components::{FIREBALL_RADIUS, Goal, Kind, Team};
pub use config::{GameConfig, KeeperMode, PLAYER_START_GOLD, PLAYER_WAVES, Party};
pub use error::GameError;
pub use events::Event;
pub use explore::Explored;
pub use game::Game;
pub use keeper::{DIG_COST, MAX_CREATURES, creature_cost};
pub use layout::Ground;
pub use level::Level;
pub use orders::{LoggedOrder, Order, OrderError};
pub use outcome::Outcome;
pub use render::{colour, style};
pub use screen::{HEIGHT, Screen, WIDTH};
pub use step::{DT, STEPS_PER_SECOND};
pub use summary::Summary;
pub use tileslide_scenes::SplitMix64;
pub use view::Fighter;
