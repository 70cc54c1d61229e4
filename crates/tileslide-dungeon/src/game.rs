//! The game loop: a fixed 1/30 s step running the systems in a fixed order over the hecs
//! world, talking through the event queue.

use hecs::World;
use tileslide::{Bodies, Cell, ResolveTrace, TileMap};

use crate::arrivals::Arrivals;
use crate::audit::Audit;
use crate::brains::{self, Sightings};
use crate::components::{Body, Carrying, CreatureBrain, FIREBALL_RADIUS, Health, Id, Team};
use crate::config::{GameConfig, KeeperMode, PLAYER_START_GOLD};
use crate::error::GameError;
use crate::events::Event;
use crate::hits::Hits;
use crate::keeper::{DIG_COST, Keeper, SCRIPT_DIG_COST};
use crate::layout::Layout;
use crate::level::Level;
use crate::orders::LoggedOrder;
use crate::outcome::Outcome;
use crate::spawn::Ids;
use crate::step::STEPS_PER_SECOND;
use crate::summary::{Summary, chronicle};
use crate::{combat, treasure};
use tileslide_scenes::{Fnv1a, SplitMix64};

/// Pieces of treasure at the start.
const TREASURE: u32 = 5;

/// The Dungeon Builder game.
pub struct Game {
    pub(crate) world: World,
    pub(crate) bodies: Bodies,
    pub(crate) level: Level,
    initial_map: TileMap,
    pub(crate) dug: Vec<Cell>,
    pub(crate) keeper: Keeper,
    mode: KeeperMode,
    arrivals: Arrivals,
    pub(crate) ids: Ids,
    hits: Hits,
    events: Vec<Event>,
    pub(crate) summary: Summary,
    outcome: Outcome,
    pub(crate) orders: Vec<LoggedOrder>,
    /// The bodies' last step, while traced ([`Game::trace_bodies`]).
    pub(crate) trace: Option<ResolveTrace>,
}

impl Game {
    /// A game of the scripted, defending keeper from `seed` (`tileslide demo dungeon`'s).
    ///
    /// # Errors
    /// Only on a bug in the built-in dungeon.
    pub fn new(seed: u64) -> Result<Self, GameError> {
        Self::with_config(GameConfig::new(seed))
    }

    /// A game set up by `config`.
    ///
    /// # Errors
    /// Only on a bug in the built-in dungeon.
    pub fn with_config(config: GameConfig) -> Result<Self, GameError> {
        let (layout, keeper) = match config.keeper {
            KeeperMode::Scripted => {
                let layout = Layout::build()?;
                let keeper = Keeper::new(layout.plan.clone(), config.defenders);
                (layout, keeper)
            }
            KeeperMode::Player => (
                Layout::build_for_player()?,
                Keeper::for_player(PLAYER_START_GOLD),
            ),
        };
        let initial_map = layout.map.clone();
        Ok(Self {
            world: World::new(),
            bodies: Bodies::new(),
            level: Level::new(layout)?,
            initial_map,
            dug: Vec::new(),
            keeper,
            mode: config.keeper,
            arrivals: Arrivals::new(
                SplitMix64::new(config.seed),
                config.party,
                config.waves_to_win,
            ),
            ids: Ids::default(),
            hits: Hits::new(FIREBALL_RADIUS)?,
            events: Vec::new(),
            summary: Summary {
                treasure_left: TREASURE,
                ..Summary::default()
            },
            outcome: Outcome::Playing,
            orders: Vec::new(),
            trace: None,
        })
    }

    /// One fixed step (1/30 s). The game goes on after it is decided (see
    /// [`Game::outcome`]); only a player's orders stop.
    ///
    /// # Errors
    /// A map, navigation or body error (bugs).
    pub fn step(&mut self) -> Result<(), GameError> {
        let step = self.summary.steps;
        let events = &mut self.events;
        self.keeper.run(
            step,
            &mut self.level,
            &mut self.world,
            &mut self.bodies,
            &mut self.ids,
            events,
        )?;
        refresh_ways(&mut self.level, &mut self.world, events)?;
        self.arrivals.run(
            step,
            &self.level,
            &mut self.world,
            &mut self.bodies,
            &mut self.ids,
            events,
        )?;
        let seen = Sightings::take(&self.world, &self.bodies);
        brains::heroes(
            &mut self.world,
            &mut self.bodies,
            &mut self.level,
            &seen,
            step,
        );
        brains::creatures(&mut self.world, &mut self.bodies, &mut self.level, &seen);
        combat::attack(&mut self.world, &self.level, &mut self.ids, &seen)?;
        match &mut self.trace {
            Some(trace) => self.bodies.step_traced(&self.level.map, trace),
            None => self.bodies.step(&self.level.map),
        };
        let seen = Sightings::take(&self.world, &self.bodies);
        combat::strike(&mut self.world, &self.level, &mut self.hits, &seen, events)?;
        combat::bury(&mut self.world, &mut self.bodies, events);
        treasure::recover(&mut self.summary.treasure_left, events);
        treasure::run(
            &mut self.world,
            &mut self.bodies,
            &self.level,
            &mut self.summary.treasure_left,
            events,
        );
        for event in events.drain(..) {
            chronicle(&mut self.summary, &mut self.dug, &event);
        }
        self.summary.steps += 1;
        self.summary
            .audit
            .add(Audit::of(&self.bodies, &self.level.map));
        if self.outcome == Outcome::Playing {
            self.outcome = self.decide();
        }
        Ok(())
    }

    /// Lost when every piece is carried out; won when every party has come and its last
    /// hero is dead or gone, with treasure still in the dungeon.
    fn decide(&self) -> Outcome {
        if self.summary.treasure_stolen >= TREASURE {
            Outcome::Lost
        } else if self.arrivals.all_arrived()
            && self.arrivals.waiting() == 0
            && self.heroes_alive() == 0
        {
            Outcome::Won
        } else {
            Outcome::Playing
        }
    }

    /// Where the game stands: decided once, at the end of the step that decides it.
    #[must_use]
    pub fn outcome(&self) -> Outcome {
        self.outcome
    }

    /// Who gives the keeper's orders.
    #[must_use]
    pub fn mode(&self) -> KeeperMode {
        self.mode
    }

    /// What digging a square costs this game's keeper, in whole gold: [`DIG_COST`] for a
    /// player, the script's own smaller price for the scripted keeper.
    #[must_use]
    pub fn dig_cost(&self) -> u32 {
        match self.mode {
            KeeperMode::Player => DIG_COST,
            KeeperMode::Scripted => SCRIPT_DIG_COST / STEPS_PER_SECOND,
        }
    }

    /// The orders a player gave so far, each with the step it was given before: giving the
    /// same orders before the same steps of a game of the same configuration replays it.
    #[must_use]
    pub fn orders(&self) -> &[LoggedOrder] {
        &self.orders
    }

    /// Steps until the next party arrives (0: in the next step), or `None` when no more
    /// will come.
    #[must_use]
    pub fn next_wave_in(&self) -> Option<u64> {
        self.arrivals.next_wave_in(self.summary.steps)
    }

    /// Heroes in the dungeon, plus those of arrived parties still waiting at the entrance.
    #[must_use]
    pub fn heroes_alive(&self) -> u32 {
        self.count(Team::Heroes) + self.arrivals.waiting()
    }

    /// The keeper's creatures alive.
    #[must_use]
    pub fn creatures_alive(&self) -> u32 {
        self.count(Team::Keeper)
    }

    fn count(&self, team: Team) -> u32 {
        let n = self
            .world
            .query::<&Team>()
            .iter()
            .filter(|t| **t == team)
            .count();
        u32::try_from(n).unwrap_or(u32::MAX)
    }

    /// What happened so far.
    #[must_use]
    pub fn summary(&self) -> Summary {
        self.summary
    }

    /// Gold the keeper holds.
    #[must_use]
    pub fn gold(&self) -> u32 {
        self.keeper.gold()
    }

    /// FNV-1a over every body's position bits, every fighter's id, health and team, and
    /// the summary: equal hashes mean (almost surely) equal games.
    #[must_use]
    pub fn state_hash(&self) -> u64 {
        let mut hash = Fnv1a::new();
        for (_, body) in self.bodies.iter() {
            hash.write_u64(u64::from(body.position().x.to_bits()));
            hash.write_u64(u64::from(body.position().y.to_bits()));
        }
        let mut fighters: Vec<_> = self
            .world
            .query::<(&Id, &Health, &Team, Option<&Carrying>)>()
            .iter()
            .map(|(id, h, t, c)| (id.0, h.hp, *t == Team::Heroes, c.is_some()))
            .collect();
        fighters.sort_unstable();
        for (id, hp, hero, carrying) in fighters {
            hash.write_u64(id);
            hash.write_u64(hp as u64);
            hash.write_u64(u64::from(hero) | u64::from(carrying) << 1);
        }
        let s = self.summary;
        for v in [
            s.steps,
            s.waves.into(),
            s.heroes_lost.into(),
            s.creatures_lost.into(),
            s.treasure_left.into(),
            s.squares_dug.into(),
            self.keeper.gold().into(),
        ] {
            hash.write_u64(v);
        }
        hash.finish()
    }

    /// The map as it is now.
    #[must_use]
    pub fn map(&self) -> &TileMap {
        &self.level.map
    }

    /// The map before any digging (what a GIF's canvas is drawn from).
    #[must_use]
    pub fn initial_map(&self) -> &TileMap {
        &self.initial_map
    }

    /// Squares dug, in order.
    #[must_use]
    pub fn dug(&self) -> &[Cell] {
        &self.dug
    }

    /// The resolver's bodies.
    #[must_use]
    pub fn bodies(&self) -> &Bodies {
        &self.bodies
    }

    /// The ECS world (read-only).
    #[must_use]
    pub fn world(&self) -> &World {
        &self.world
    }

    /// The level (map, navigation, treasure and exit).
    #[must_use]
    pub fn level(&self) -> &Level {
        &self.level
    }

    /// Bodies of heroes carrying treasure.
    pub(crate) fn carriers(&self) -> Vec<tileslide::BodyHandle> {
        self.world
            .query::<(&Body, &Carrying)>()
            .iter()
            .map(|(b, _)| b.0)
            .collect()
    }
}

/// Brings the navigation up to date with the map (see [`Level::catch_up`]), drops creature
/// paths home that the edits affect, and lets heroes try their dead ends again after a dig.
pub(crate) fn refresh_ways(
    level: &mut Level,
    world: &mut World,
    events: &[Event],
) -> Result<(), GameError> {
    if events.iter().any(|e| matches!(e, Event::Dug { .. })) {
        level.explored.forget_dead_ends();
    }
    let change = level.catch_up()?;
    if !change.is_empty() {
        for brain in world.query_mut::<&mut CreatureBrain>() {
            if brain
                .way_home
                .as_ref()
                .is_some_and(|(p, _)| p.is_affected_by(&change))
            {
                brain.way_home = None;
            }
        }
    }
    Ok(())
}
