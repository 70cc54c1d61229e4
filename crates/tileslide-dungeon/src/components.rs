//! The components of the game's entities (hecs).

use tileslide::{BodyHandle, Cell, NavPath, Vec2};

/// A stable number per entity, in spawn order: systems that need an order sort by it, so
/// nothing depends on how the ECS stores entities.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Id(pub u64);

/// The entity's circle in the resolver's [`tileslide::Bodies`].
#[derive(Clone, Copy, Debug)]
pub struct Body(pub BodyHandle);

/// Hit points.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Health {
    /// What is left.
    pub hp: i32,
    /// What it started with.
    pub max: i32,
}

/// Which side an entity fights on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Team {
    /// The raiding heroes.
    Heroes,
    /// The keeper's creatures.
    Keeper,
}

/// What kind of fighter an entity is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Kind {
    /// A hero: melee, goes for the treasure.
    Hero,
    /// A skeleton: a melee tank.
    Skeleton,
    /// An imp: shoots fireballs.
    Imp,
}

impl Kind {
    /// Circle radius.
    #[must_use]
    pub fn radius(self) -> f32 {
        match self {
            Kind::Hero => 0.3,
            Kind::Skeleton => 0.35,
            Kind::Imp => 0.25,
        }
    }

    /// Walking speed (cells per second).
    #[must_use]
    pub fn speed(self) -> f32 {
        match self {
            Kind::Hero => 2.5,
            Kind::Skeleton => 2.0,
            Kind::Imp => 2.2,
        }
    }

    /// Starting hit points.
    #[must_use]
    pub fn max_hp(self) -> i32 {
        match self {
            Kind::Hero => 30,
            Kind::Skeleton => 40,
            Kind::Imp => 14,
        }
    }

    /// Its team.
    #[must_use]
    pub fn team(self) -> Team {
        match self {
            Kind::Hero => Team::Heroes,
            Kind::Skeleton | Kind::Imp => Team::Keeper,
        }
    }
}

/// What a hero wants.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Goal {
    /// Reach the treasure.
    Treasure,
    /// Leave by the exit.
    Exit,
}

/// A hero's mind.
#[derive(Clone, Debug)]
pub struct HeroBrain {
    /// Where it is going.
    pub goal: Goal,
    /// While the treasure has not been seen: the frontier square it explores towards,
    /// and its path there with the next point to reach.
    pub exploring: Option<(Cell, NavPath, usize)>,
}

/// A creature's mind: where it waits, and its way back there.
#[derive(Clone, Debug)]
pub struct CreatureBrain {
    /// Its post.
    pub post: Vec2,
    /// Its way back to the post, dropped when a dug square affects it.
    pub way_home: Option<(NavPath, usize)>,
}

/// Steps until it may attack again.
#[derive(Clone, Copy, Debug, Default)]
pub struct Cooldown(pub u32);

/// A hero carrying a piece of the treasure.
#[derive(Clone, Copy, Debug)]
pub struct Carrying;

/// A melee swing under way: for a few steps an attack volume in front of the fighter,
/// hitting each victim at most once.
#[derive(Clone, Copy, Debug)]
pub struct Swing {
    /// The swing's id (from [`crate::spawn::Ids`]), unique for the game.
    pub id: u64,
    /// Which way it swings (unit length).
    pub direction: Vec2,
    /// Damage per hit.
    pub damage: i32,
    /// Steps it still lasts.
    pub steps_left: u32,
}

/// A fireball: an attack volume swept along its velocity each step.
#[derive(Clone, Copy, Debug)]
pub struct Fireball {
    /// Its owner in the hit volumes (from [`crate::spawn::Ids`]).
    pub key: u64,
    /// Centre.
    pub position: Vec2,
    /// Cells per second.
    pub velocity: Vec2,
    /// Steps left before it fizzles.
    pub ttl: u32,
}

/// Radius of a fireball.
pub const FIREBALL_RADIUS: f32 = 0.12;
