//! The keeper's purse and, for the scripted keeper, its script: it earns gold, digs its
//! plan square by square from the treasure room towards the entrance, and summons
//! skeletons and imps when their rooms are ready. A player's keeper only earns; the
//! player's orders spend (see `orders`).

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
/// What the script pays for a square (5 gold: its plan is long).
pub(crate) const SCRIPT_DIG_COST: u32 = 5 * STEPS_PER_SECOND;
/// Gold a player pays to dig a square (the write-up's price).
pub const DIG_COST: u32 = 50;
/// Steps between extra summons once the plan is dug.
const SUMMON_EVERY: u64 = 20 * STEPS_PER_SECOND as u64;
/// The most creatures a keeper keeps: the script stops summoning there, and a player's
/// summons are refused.
pub const MAX_CREATURES: u32 = 8;

fn summon_cost(kind: Kind) -> u32 {
    match kind {
        Kind::Imp => 50 * STEPS_PER_SECOND,
        _ => 35 * STEPS_PER_SECOND,
    }
}

/// Gold a creature of `kind` costs to summon (imps 50, skeletons 35); `None` for a hero,
/// which the keeper cannot summon.
#[must_use]
pub fn creature_cost(kind: Kind) -> Option<u32> {
    (kind != Kind::Hero).then(|| summon_cost(kind) / STEPS_PER_SECOND)
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

    /// A player's keeper: no plan, no summons of its own, `gold` to start with.
    #[must_use]
    pub fn for_player(gold: u32) -> Self {
        Self {
            gold: gold.saturating_mul(STEPS_PER_SECOND),
            ..Self::new(Vec::new(), false)
        }
    }

    /// Gold left (whole coins).
    #[must_use]
    pub fn gold(&self) -> u32 {
        self.gold / STEPS_PER_SECOND
    }

    /// Pays `cost` whole coins, or returns the gold held (whole coins) when it is short.
    pub fn spend(&mut self, cost: u32) -> Result<(), u32> {
        let units = cost.saturating_mul(STEPS_PER_SECOND);
        if self.gold < units {
            return Err(self.gold());
        }
        self.gold -= units;
        Ok(())
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
        self.gold = self.gold.saturating_add(INCOME);
        if self.defends && self.dug == self.plan.len() && step.is_multiple_of(SUMMON_EVERY) {
            let creatures = world
                .query_mut::<&Kind>()
                .into_iter()
                .filter(|k| **k != Kind::Hero)
                .count();
            if creatures + self.summons.len() < MAX_CREATURES as usize {
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
        while self.dug < self.plan.len() && self.gold >= SCRIPT_DIG_COST {
            let cell = self.plan[self.dug];
            self.dug += 1;
            self.gold -= SCRIPT_DIG_COST;
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
pub(crate) fn free_spot(level: &Level, bodies: &Bodies, near: Vec2, radius: f32) -> Option<Vec2> {
    (0..12)
        .map(|k| {
            let angle = k as f32 * 2.4;
            near + Vec2::from_angle(angle) * (k as f32 * 0.25)
        })
        .find(|&p| level.is_free(bodies, p, radius))
}
