//! How a game is set up: the seed, who keeps the dungeon (the script or a player), whether
//! the scripted keeper defends, and what the hero parties are like.

use crate::components::Kind;

/// Who gives the keeper's orders.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum KeeperMode {
    /// The keeper's script digs its plan and summons on its own (`tileslide demo dungeon`);
    /// the game takes no orders.
    #[default]
    Scripted,
    /// A player gives every order ([`crate::Game::dig`], [`crate::Game::summon`]); the
    /// dungeon starts with a corridor from the entrance to the treasure room and the keeper
    /// with [`PLAYER_START_GOLD`].
    Player,
}

/// Gold a player's keeper starts with.
pub const PLAYER_START_GOLD: u32 = 300;
/// Hero parties a player must see off to win (the default of [`GameConfig::player`]).
pub const PLAYER_WAVES: u32 = 5;

/// How a game is set up.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GameConfig {
    /// The seed of the game's random numbers.
    pub seed: u64,
    /// Who gives the keeper's orders.
    pub keeper: KeeperMode,
    /// Whether the scripted keeper summons creatures (false: an undefended dungeon). A
    /// player's keeper summons what the player orders.
    pub defenders: bool,
    /// What the hero parties are like.
    pub party: Party,
    /// The parties that come: after this many no more arrive, and the keeper wins once the
    /// last hero is dead or gone with treasure still in the dungeon. `None`: parties come
    /// for ever, and the game can only be lost.
    pub waves_to_win: Option<u32>,
}

impl GameConfig {
    /// A game of the scripted, defending keeper from `seed` with the usual parties, for
    /// ever (the game of `tileslide demo dungeon`).
    #[must_use]
    pub fn new(seed: u64) -> Self {
        Self {
            seed,
            keeper: KeeperMode::Scripted,
            defenders: true,
            party: Party::default(),
            waves_to_win: None,
        }
    }

    /// A game a player keeps, from `seed`, with the usual parties: won after
    /// [`PLAYER_WAVES`] of them.
    #[must_use]
    pub fn player(seed: u64) -> Self {
        Self {
            keeper: KeeperMode::Player,
            waves_to_win: Some(PLAYER_WAVES),
            ..Self::new(seed)
        }
    }
}

/// The hero parties: how many heroes each brings and how tough they are.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Party {
    /// Fewest heroes in a party.
    pub min_heroes: u32,
    /// Most heroes in a party (at least `min_heroes`).
    pub max_heroes: u32,
    /// Each hero's hit points.
    pub hero_hp: i32,
}

impl Default for Party {
    /// Three to five heroes of [`Kind::Hero`]'s hit points.
    fn default() -> Self {
        Self {
            min_heroes: 3,
            max_heroes: 5,
            hero_hp: Kind::Hero.max_hp(),
        }
    }
}
