//! Hero parties: one arrives at the entrance every 30 seconds of game time (12 s in for the
//! first), up to a last one if the game has one.

use hecs::World;
use tileslide::Bodies;

use crate::components::Kind;
use crate::config::Party;
use crate::error::GameError;
use crate::events::Event;
use crate::layout::Layout;
use crate::level::Level;
use crate::spawn::{self, Ids};
use crate::step::STEPS_PER_SECOND;
use tileslide_scenes::SplitMix64;

/// Steps between parties.
const WAVE_EVERY: u64 = 30 * STEPS_PER_SECOND as u64;
/// Steps before the first party.
const FIRST_WAVE: u64 = 12 * STEPS_PER_SECOND as u64;

/// Steps from `step` until the next party arrives (0: it arrives at this step).
pub(crate) fn steps_to_next_wave(step: u64) -> u64 {
    if step <= FIRST_WAVE {
        FIRST_WAVE - step
    } else {
        (WAVE_EVERY - (step - FIRST_WAVE) % WAVE_EVERY) % WAVE_EVERY
    }
}

/// Heroes still to come in (the entrance may be crowded).
#[derive(Clone, Debug)]
pub struct Arrivals {
    waiting: u32,
    rng: SplitMix64,
    party: Party,
    /// Parties that will come (`None`: no end).
    waves: Option<u32>,
    /// Parties arrived so far.
    arrived: u32,
}

impl Arrivals {
    /// Arrivals of `waves` `party`s (`None`: no end) whose sizes come from `rng`.
    #[must_use]
    pub fn new(rng: SplitMix64, party: Party, waves: Option<u32>) -> Self {
        Self {
            waiting: 0,
            rng,
            party,
            waves,
            arrived: 0,
        }
    }

    /// Heroes of arrived parties still waiting for room at the entrance.
    #[must_use]
    pub fn waiting(&self) -> u32 {
        self.waiting
    }

    /// Whether every party that will come has arrived.
    #[must_use]
    pub fn all_arrived(&self) -> bool {
        self.waves.is_some_and(|w| self.arrived >= w)
    }

    /// Steps from `step` until the next party arrives (0: it arrives in the step numbered
    /// `step`), or `None` when no more will come.
    #[must_use]
    pub fn next_wave_in(&self, step: u64) -> Option<u64> {
        if self.all_arrived() {
            return None;
        }
        if step <= FIRST_WAVE {
            return Some(FIRST_WAVE - step);
        }
        let since = (step - FIRST_WAVE) % WAVE_EVERY;
        Some(if since == 0 { 0 } else { WAVE_EVERY - since })
    }

    /// One step: a new party when it is time; waiting heroes step in where there is room.
    ///
    /// # Errors
    /// A body error (a bug).
    pub fn run(
        &mut self,
        step: u64,
        level: &Level,
        world: &mut World,
        bodies: &mut Bodies,
        ids: &mut Ids,
        events: &mut Vec<Event>,
    ) -> Result<(), GameError> {
        if step >= FIRST_WAVE
            && (step - FIRST_WAVE).is_multiple_of(WAVE_EVERY)
            && !self.all_arrived()
        {
            self.arrived += 1;
            let Party {
                min_heroes,
                max_heroes,
                ..
            } = self.party;
            let spread = u64::from(max_heroes.saturating_sub(min_heroes)) + 1;
            // below(spread) < spread ≤ 2³², so the cast keeps every value.
            let heroes = min_heroes + self.rng.below(spread) as u32;
            self.waiting = self.waiting.saturating_add(heroes);
            events.push(Event::WaveArrived { heroes });
        }
        let radius = Kind::Hero.radius();
        for p in Layout::arrival_points() {
            if self.waiting == 0 {
                break;
            }
            if level.is_free(bodies, p, radius) {
                spawn::fighter(world, bodies, ids, Kind::Hero, p, self.party.hero_hp)?;
                self.waiting -= 1;
            }
        }
        Ok(())
    }
}
