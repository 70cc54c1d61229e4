//! What a run did.

use tileslide::Vec2;

use crate::audit::Audit;
use crate::level::Goal;

/// What a run did: progress, pickups, fights and the collision audit.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Summary {
    /// The level's name.
    pub level: String,
    /// Steps run.
    pub steps: u64,
    /// Coins collected, of `coins_total`.
    pub coins_collected: usize,
    /// Coins in the level.
    pub coins_total: usize,
    /// Enemies stomped, of `enemies_total`.
    pub enemies_defeated: usize,
    /// Enemies in the level.
    pub enemies_total: usize,
    /// Hits the player took.
    pub hits_taken: u32,
    /// Jumps the player made.
    pub jumps: u32,
    /// Steps the player rode the moving platform.
    pub steps_riding: u64,
    /// What ends the run: the level's goal, or its right end when it has none.
    pub goal: Goal,
    /// Whether the player reached it (`goal`).
    pub reached_goal: bool,
    /// The player's centre at the end.
    pub end: Vec2,
    /// The collision audit of the player and the enemies.
    pub audit: Audit,
}
