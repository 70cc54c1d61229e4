//! The scripted keeper: earns gold, digs its plan square by square from the treasure room
//! towards the entrance, and summons skeletons and imps when their rooms are ready.

use hecs::World;
use tileslide::{Bodies, Cell, Vec2};

use crate::components::Kind;
use crate::error::GameError;
use crate::events::Event;
use crate::layout::{LAIR, ROOST};
use crate::level::Level;
use crate::spawn::{self, Ids};
use crate::step::STEPS_PER_SECOND;

/// Gold is counted in steps' worth: 20 gold a second.
const INCOME: u32 = 20;
/// What a square costs to dig, in steps' worth of gold.
pub(crate) const DIG_COST: u32 = 5 * STEPS_PER_SECOND;
/// Steps between extra summons once the plan is dug.
const SUMMON_EVERY: u64 = 20 * STEPS_PER_SECOND as u64;
/// The keeper stops summoning at this many creatures.
const MAX_CREATURES: usize = 8;

fn summon_cost(kind: Kind) -> u32 {
    match kind {
        Kind::Imp => 50 * STEPS_PER_SECOND,
        _ => 35 * STEPS_PER_SECOND,
    }
}

/// The keeper's purse and to-do list.
#[derive(Clone, Debug)]
pub struct Keeper {
    gold: u32,
    plan: Vec<Cell>,
    dug: usize,
    summons: Vec<(Kind, Vec2)>,
    defends: bool,
}

impl Keeper {
    /// A keeper with this plan; with `defends` false it never summons.
    #[must_use]
    pub fn new(plan: Vec<Cell>, defends: bool) -> Self {
        Self {
            gold: 40 * STEPS_PER_SECOND,
            plan,
            dug: 0,
            summons: Vec::new(),
            defends,
        }
    }

    /// Gold left (whole coins).
    #[must_use]
    pub fn gold(&self) -> u32 {
        self.gold / STEPS_PER_SECOND
    }

    /// One step: earn, summon what is due and affordable, then dig what gold allows.
    ///
    /// # Errors
    /// A map, navigation or body error (bugs).
    pub fn run(
        &mut self,
        step: u64,
        level: &mut Level,
        world: &mut World,
        bodies: &mut Bodies,
        ids: &mut Ids,
        events: &mut Vec<Event>,
    ) -> Result<(), GameError> {
        self.gold += INCOME;
        if self.defends && self.dug == self.plan.len() && step.is_multiple_of(SUMMON_EVERY) {
            let creatures = world
                .query_mut::<&Kind>()
                .into_iter()
                .filter(|k| **k != Kind::Hero)
                .count();
            if creatures + self.summons.len() < MAX_CREATURES {
                let kind = if (step / SUMMON_EVERY).is_multiple_of(2) {
                    Kind::Skeleton
                } else {
                    Kind::Imp
                };
                self.summons
                    .push((kind, if kind == Kind::Imp { ROOST } else { LAIR }));
            }
        }
        if let Some(&(kind, post)) = self.summons.first() {
            if self.gold < summon_cost(kind) {
                return Ok(());
            }
            let Some(at) = free_spot(level, bodies, post, kind.radius()) else {
                return Ok(());
            };
            self.gold -= summon_cost(kind);
            self.summons.remove(0);
            spawn::fighter(world, bodies, ids, kind, at, kind.max_hp())?;
            events.push(Event::Summoned { kind });
            return Ok(());
        }
        while self.dug < self.plan.len() && self.gold >= DIG_COST {
            let cell = self.plan[self.dug];
            self.dug += 1;
            self.gold -= DIG_COST;
            level.map.clear_tile(cell)?;
            for (post, kind) in [(LAIR, Kind::Skeleton), (ROOST, Kind::Imp)] {
                if self.defends && level.map.cell_at(post) == Some(cell) {
                    self.summons.extend([(kind, post), (kind, post)]);
                }
            }
            events.push(Event::Dug { cell });
        }
        Ok(())
    }
}

/// The first free place for a circle of `radius` on a small spiral around `near`.
fn free_spot(level: &Level, bodies: &Bodies, near: Vec2, radius: f32) -> Option<Vec2> {
    (0..12)
        .map(|k| {
            let angle = k as f32 * 2.4;
            near + Vec2::from_angle(angle) * (k as f32 * 0.25)
        })
        .find(|&p| level.is_free(bodies, p, radius))
}
