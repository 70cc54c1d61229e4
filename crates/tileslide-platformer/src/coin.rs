//! A coin the player collects.

use tileslide::Vec2;

/// A coin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Coin {
    /// Its centre.
    pub center: Vec2,
    /// Collected.
    pub taken: bool,
}
