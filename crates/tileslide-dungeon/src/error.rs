//! The game's error: a refusal from the library, which here is always a bug in the game.

/// What can go wrong (all of these are bugs in the game, not bad input).
#[derive(Debug, thiserror::Error)]
pub enum GameError {
    /// The built-in map did not parse.
    #[error("dungeon map: {0}")]
    Load(#[from] tileslide::io::LoadError),
    /// A map edit was refused.
    #[error("digging: {0}")]
    Map(#[from] tileslide::MapError),
    /// Navigation refused.
    #[error("navigation: {0}")]
    Nav(#[from] tileslide::NavError),
    /// The resolver refused a body.
    #[error("bodies: {0}")]
    Body(#[from] tileslide::BodyError),
    /// A hit volume was refused.
    #[error("hit volumes: {0}")]
    Volume(#[from] tileslide::VolumeError),
}
