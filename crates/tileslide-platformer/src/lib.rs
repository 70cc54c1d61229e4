//! # tileslide-platformer
//!
//! The platformer demo (`tileslide demo platformer`): a character controlled by a script
//! runs through a level of ramps, one-way platforms, a moving platform, coins and enemies,
//! everything moved and hit by tileslide:
//!
//! - the player and the enemies are [`tileslide::Character`]s (walk ramps, land on and drop
//!   through one-way platforms, ride the moving platform);
//! - the moving platform is a temporary segment, re-submitted every step
//!   ([`tileslide::TileMap::add_temporary`] after
//!   [`tileslide::TileMap::clear_temporaries_of`]);
//! - coins, stomps and enemy hits are volumes in a [`tileslide::HitWorld`] with hit types
//!   (`COLLECT`, the game's own `STOMP`, `HIT`);
//! - every step an [`Audit`] checks with the map's own queries that no character is inside
//!   solid and no centre crossed a solid face.
//!
//! A Replica Island level ([`Level::load_replica`]) is played with its objects: the player
//! starts at the level's spawn, and its coins and simple enemies are placed where it puts
//! them ([`ReplicaRole`] lists which of the game's objects become what; the rest are counted
//! in [`Level::ignored_objects`]).
//!
//! The step is fixed ([`STEPS_PER_SECOND`]) and nothing reads a clock, so a run is
//! deterministic.
//!
//! ```
//! use tileslide_platformer::{Game, Level};
//! let mut game = Game::new(Level::bundled()?)?;
//! let summary = game.run(60 * 60)?;
//! assert!(summary.reached_goal && summary.audit.is_clean());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
#![forbid(unsafe_code)]

// The modules import each other in one direction only. At the bottom: `input`, `error`,
// `fall`, `coin`, `hits`, `audit`, `replica_objects`, `level`, `summary`. Above them
// the moving things, each on its own: `player`, `enemy`, `platform`. `script` reads the
// level and those things and returns an `Input`; `game` owns them all, asks the script
// for its input every step and moves everything; `picture` draws a `Game`.

mod audit;
mod coin;
mod enemy;
mod error;
mod fall;
mod game;
mod hits;
mod input;
mod level;
mod picture;
mod platform;
mod player;
mod replica_objects;
mod script;
mod summary;

pub use audit::{Audit, TOLERANCE, overlaps_solid};
pub use coin::Coin;
pub use enemy::Enemy;
pub use error::GameError;
pub use fall::GRAVITY;
pub use game::{Game, STEPS_PER_SECOND, next_input};
pub use hits::{COIN_RADIUS, ENEMY_HALF, PLAYER_HALF, STOMP};
pub use input::Input;
pub use level::{BUNDLED_LEVEL, Goal, Level, LevelError, MARKERS, PlatformTrack};
pub use picture::{COIN_COLOR, ENEMY_COLOR, PLAYER_COLOR, legend};
pub use platform::PLATFORM_OWNER;
pub use player::{JUMP_SPEED, Player, RUN_SPEED};
pub use replica_objects::{EnemyStart, IgnoredObjects, ReplicaRole};
pub use summary::Summary;

/// The longest run, in steps: a minute of game time.
pub const MAX_STEPS: u64 = 60 * STEPS_PER_SECOND as u64;
