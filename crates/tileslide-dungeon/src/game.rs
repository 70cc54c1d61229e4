//! The game loop: a fixed 1/30 s step running the systems in a fixed order over the hecs
//! world, talking through the event queue.

use hecs::World;
use tileslide::{Bodies, Cell, TileMap};

use crate::GameError;
use crate::arrivals::Arrivals;
use crate::audit::Audit;
use crate::brains::{self, Sightings};
use crate::components::{Body, Carrying, FIREBALL_RADIUS, Health, Id, Kind, Team};
use crate::events::Event;
use crate::hits::Hits;
use crate::keeper::Keeper;
use crate::layout::Layout;
use crate::level::Level;
use crate::spawn::Ids;
use crate::{combat, treasure};
use tileslide_scenes::{Fnv1a, SplitMix64};

/// Pieces of treasure at the start.
const TREASURE: u32 = 5;

/// How a game is set up.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GameConfig {
    /// The seed of the game's random numbers.
    pub seed: u64,
    /// Whether the keeper summons creatures (false: an undefended dungeon).
    pub defenders: bool,
    /// What the hero parties are like.
    pub party: Party,
}

impl GameConfig {
    /// A defended game from `seed` with the usual parties.
    #[must_use]
    pub fn new(seed: u64) -> Self {
        Self {
            seed,
            defenders: true,
            party: Party::default(),
        }
    }
}

/// The hero parties: how many heroes each brings and how tough they are.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Party {
    /// Fewest heroes in a party.
    pub min_heroes: u32,
    /// Most heroes in a party (at least `min_heroes`).
    pub max_heroes: u32,
    /// Each hero's hit points.
    pub hero_hp: i32,
}

impl Default for Party {
    /// Three to five heroes of [`Kind::Hero`]'s hit points.
    fn default() -> Self {
        Self {
            min_heroes: 3,
            max_heroes: 5,
            hero_hp: Kind::Hero.max_hp(),
        }
    }
}

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

/// The Dungeon Builder game.
pub struct Game {
    world: World,
    bodies: Bodies,
    level: Level,
    initial_map: TileMap,
    dug: Vec<Cell>,
    keeper: Keeper,
    arrivals: Arrivals,
    ids: Ids,
    hits: Hits,
    events: Vec<Event>,
    summary: Summary,
}

impl Game {
    /// A defended game from `seed`.
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
        let layout = Layout::build()?;
        let initial_map = layout.map.clone();
        let keeper = Keeper::new(layout.plan.clone(), config.defenders);
        Ok(Self {
            world: World::new(),
            bodies: Bodies::new(),
            level: Level::new(layout)?,
            initial_map,
            dug: Vec::new(),
            keeper,
            arrivals: Arrivals::new(SplitMix64::new(config.seed), config.party),
            ids: Ids::default(),
            hits: Hits::new(FIREBALL_RADIUS)?,
            events: Vec::new(),
            summary: Summary {
                treasure_left: TREASURE,
                ..Summary::default()
            },
        })
    }

    /// One fixed step (1/30 s).
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
        self.bodies.step(&self.level.map);
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
        Ok(())
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
fn refresh_ways(level: &mut Level, world: &mut World, events: &[Event]) -> Result<(), GameError> {
    if events.iter().any(|e| matches!(e, Event::Dug { .. })) {
        level.explored.forget_dead_ends();
    }
    let change = level.catch_up()?;
    if !change.is_empty() {
        for brain in world.query_mut::<&mut crate::components::CreatureBrain>() {
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

/// Counts an event into the summary.
fn chronicle(summary: &mut Summary, dug: &mut Vec<Cell>, event: &Event) {
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
