//! The messages systems send each other: each system reads the queue and appends to it;
//! none calls another.

use hecs::Entity;
use tileslide::Cell;

use crate::components::{Kind, Team};

/// Something that happened this step.
#[derive(Clone, Debug)]
pub enum Event {
    /// The keeper dug a square (the map is edited; the navigation grid and flow fields
    /// catch up by themselves, see `Level::catch_up`).
    Dug {
        /// The square.
        cell: Cell,
    },
    /// The keeper summoned a creature.
    Summoned {
        /// What it is.
        kind: Kind,
    },
    /// A hero party arrived.
    WaveArrived {
        /// Heroes in it.
        heroes: u32,
    },
    /// `target` takes `amount` damage.
    Damage {
        /// Who is hit.
        target: Entity,
        /// Hit points lost.
        amount: i32,
    },
    /// An entity died (and is gone).
    Died {
        /// Its team.
        team: Team,
        /// Whether it carried a piece of the treasure (now back on the pile).
        carried: bool,
    },
    /// A hero picked up a piece of the treasure.
    TreasureTaken {
        /// The hero.
        by: Entity,
    },
    /// A hero left by the exit (with the treasure if `carried`).
    Escaped {
        /// The hero.
        hero: Entity,
        /// Whether it took a piece of the treasure away.
        carried: bool,
    },
}
