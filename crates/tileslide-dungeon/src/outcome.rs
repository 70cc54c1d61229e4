//! How a game ends: the heroes carry every piece of the treasure out, or the keeper sees
//! off every party that comes.

/// Where the game stands.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Outcome {
    /// Neither side has won yet.
    #[default]
    Playing,
    /// Every party that comes has arrived and its last hero is dead or gone, with treasure
    /// still in the dungeon (only in a game with a last party,
    /// [`crate::GameConfig::waves_to_win`]).
    Won,
    /// The heroes carried every piece of the treasure out of the dungeon.
    Lost,
}

impl Outcome {
    /// Whether the game is decided.
    #[must_use]
    pub fn is_over(self) -> bool {
        self != Outcome::Playing
    }
}
