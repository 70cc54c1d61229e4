//! How a game is set up: the seed, whether the keeper defends, and what the hero parties
//! are like.

use crate::components::Kind;

/// How a game is set up.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GameConfig {
    /// The seed of the game's random numbers.
    pub seed: u64,
    /// Whether the keeper summons creatures (false: an undefended dungeon).
    pub defenders: bool,
    /// What the hero parties are like.
    pub party: Party,
}

impl GameConfig {
    /// A defended game from `seed` with the usual parties.
    #[must_use]
    pub fn new(seed: u64) -> Self {
        Self {
            seed,
            defenders: true,
            party: Party::default(),
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
