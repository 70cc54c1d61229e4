//! What happened so far: the counts a game keeps from its events.

use tileslide::Cell;

use crate::audit::Audit;
use crate::components::Team;
use crate::events::Event;

/// What happened so far.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Summary {
    /// Hero parties arrived.
    pub waves: u32,
    /// Heroes killed.
    pub heroes_lost: u32,
    /// Heroes who left by the exit.
    pub heroes_escaped: u32,
    /// Creatures summoned.
    pub creatures_summoned: u32,
    /// Creatures killed.
    pub creatures_lost: u32,
    /// Pieces of treasure taken up (some may be dropped again).
    pub treasure_taken: u32,
    /// Pieces still on the pile.
    pub treasure_left: u32,
    /// Pieces carried out of the dungeon.
    pub treasure_stolen: u32,
    /// Squares the keeper dug.
    pub squares_dug: u32,
    /// Steps run.
    pub steps: u64,
    /// Collision audit, summed over every step.
    pub audit: Audit,
}

/// Counts an event into the summary.
pub(crate) fn chronicle(summary: &mut Summary, dug: &mut Vec<Cell>, event: &Event) {
    match event {
        Event::Dug { cell, .. } => {
            summary.squares_dug += 1;
            dug.push(*cell);
        }
        Event::Summoned { .. } => summary.creatures_summoned += 1,
        Event::WaveArrived { .. } => summary.waves += 1,
        Event::Died {
            team: Team::Heroes, ..
        } => summary.heroes_lost += 1,
        Event::Died {
            team: Team::Keeper, ..
        } => summary.creatures_lost += 1,
        Event::TreasureTaken { .. } => summary.treasure_taken += 1,
        Event::Escaped { carried, .. } => {
            summary.heroes_escaped += 1;
            summary.treasure_stolen += u32::from(*carried);
        }
        Event::Damage { .. } => {}
    }
}
