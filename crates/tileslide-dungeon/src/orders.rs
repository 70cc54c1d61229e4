//! A player's orders to the keeper: dig a square of earth, summon a creature. Each is
//! checked against the rules first and refused with an [`OrderError`] that says why; an
//! accepted order takes effect at once (the map, the navigation, the purse and the summary
//! are up to date when it returns) and is logged with the step it was given before, so a
//! game is replayed by giving the same orders before the same steps.

use tileslide::{Cell, Vec2};

use crate::components::Kind;
use crate::config::KeeperMode;
use crate::error::GameError;
use crate::events::Event;
use crate::explore::neighbours;
use crate::game::{Game, refresh_ways};
use crate::keeper::{DIG_COST, MAX_CREATURES, creature_cost, free_spot};
use crate::spawn;
use crate::summary::chronicle;

/// What a player tells the keeper to do.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Order {
    /// Dig out a square of earth ([`DIG_COST`] gold).
    Dig(Cell),
    /// Summon a creature of this kind (an imp or a skeleton, at its
    /// [`creature_cost`]) near this point, which must lie in an open square; it keeps that
    /// place as its post.
    Summon(Kind, Vec2),
}

impl std::fmt::Display for Order {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Order::Dig(cell) => write!(f, "digging square ({}, {})", cell.col, cell.row),
            Order::Summon(kind, at) => {
                write!(f, "summoning {} at ({}, {})", kind_name(*kind), at.x, at.y)
            }
        }
    }
}

fn kind_name(kind: Kind) -> &'static str {
    match kind {
        Kind::Hero => "a hero",
        Kind::Skeleton => "a skeleton",
        Kind::Imp => "an imp",
    }
}

/// An accepted order and the step it was given before (the number of steps run then).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LoggedOrder {
    /// Steps run when the order was given.
    pub step: u64,
    /// The order.
    pub order: Order,
}

/// Why the keeper refused an order.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum OrderError {
    /// The scripted keeper plays this game; it takes no orders.
    #[error("{order}: the scripted keeper plays this game and takes no orders")]
    Scripted {
        /// The order refused.
        order: Order,
    },
    /// The game is decided.
    #[error("{order}: the game is over")]
    GameOver {
        /// The order refused.
        order: Order,
    },
    /// The square is outside the map.
    #[error("{order}: the square is outside the {width} × {height} map")]
    OffMap {
        /// The order refused.
        order: Order,
        /// Columns of the map.
        width: u32,
        /// Rows of the map.
        height: u32,
    },
    /// The square is rock, which nobody digs.
    #[error("{order}: the square is rock; only earth can be dug")]
    Rock {
        /// The order refused.
        order: Order,
    },
    /// The square is open already.
    #[error("{order}: the square is open already")]
    AlreadyOpen {
        /// The order refused.
        order: Order,
    },
    /// No side of the square touches an open square.
    #[error("{order}: the square is not beside an open square")]
    NotBesideOpen {
        /// The order refused.
        order: Order,
    },
    /// The keeper summons creatures, not heroes.
    #[error("{order}: the keeper summons imps and skeletons only")]
    NotACreature {
        /// The order refused.
        order: Order,
    },
    /// A coordinate is NaN or infinite.
    #[error("{order}: the point must be finite")]
    NotFinite {
        /// The order refused.
        order: Order,
    },
    /// The point is not in an open square of the map.
    #[error("{order}: the point is not in an open square")]
    NotOpen {
        /// The order refused.
        order: Order,
    },
    /// There is no room for the creature there: other bodies or walls are in the way.
    #[error("{order}: no room there (walls or other bodies in the way)")]
    NoRoom {
        /// The order refused.
        order: Order,
    },
    /// The keeper already has as many creatures as it can keep.
    #[error("{order}: the keeper has {MAX_CREATURES} creatures, the most it keeps")]
    TooManyCreatures {
        /// The order refused.
        order: Order,
    },
    /// The keeper cannot pay.
    #[error("{order}: it costs {cost} gold and the keeper has {gold}")]
    NotEnoughGold {
        /// The order refused.
        order: Order,
        /// Its price.
        cost: u32,
        /// Gold the keeper holds.
        gold: u32,
    },
    /// The library refused carrying out an accepted order (a bug in the game).
    #[error("{order}: {source}")]
    Game {
        /// The order.
        order: Order,
        /// What went wrong.
        source: Box<GameError>,
    },
}

impl Game {
    /// Whether `cell` can be dug: earth (inside the disc, not rock), still standing, and
    /// beside an open square. Gold is not considered ([`DIG_COST`] is the price).
    #[must_use]
    pub fn is_diggable(&self, cell: Cell) -> bool {
        self.dig_refusal(Order::Dig(cell), cell).is_none()
    }

    /// Every square [`Game::is_diggable`] accepts, row by row.
    #[must_use]
    pub fn diggable(&self) -> Vec<Cell> {
        let map = self.map();
        (0..map.height())
            .flat_map(|row| (0..map.width()).map(move |col| Cell::new(col, row)))
            .filter(|&cell| self.is_diggable(cell))
            .collect()
    }

    /// Why `cell` cannot be dug (gold aside), if it cannot.
    fn dig_refusal(&self, order: Order, cell: Cell) -> Option<OrderError> {
        let map = self.map();
        if cell.col >= map.width() || cell.row >= map.height() {
            return Some(OrderError::OffMap {
                order,
                width: map.width(),
                height: map.height(),
            });
        }
        if map.tile(cell).is_none() {
            return Some(OrderError::AlreadyOpen { order });
        }
        if self.level().ground.is_rock(cell) {
            return Some(OrderError::Rock { order });
        }
        let beside_open = neighbours(cell)
            .any(|n| n.col < map.width() && n.row < map.height() && map.tile(n).is_none());
        (!beside_open).then_some(OrderError::NotBesideOpen { order })
    }

    /// Digs out `cell` for [`DIG_COST`] gold: the square opens, and the navigation grid,
    /// the heroes' flow fields and the creatures' paths catch up before this returns.
    ///
    /// # Errors
    /// Why the keeper refused (see [`OrderError`]); nothing changes then.
    pub fn dig(&mut self, cell: Cell) -> Result<(), OrderError> {
        self.order(Order::Dig(cell))
    }

    /// Summons a creature of `kind` (an imp or a skeleton) for its [`creature_cost`], at
    /// `at` or, if that place is taken, at the first free place on a small spiral around
    /// it; `at` must lie in an open square. The creature keeps the place as its post.
    ///
    /// # Errors
    /// Why the keeper refused (see [`OrderError`]); nothing changes then.
    pub fn summon(&mut self, kind: Kind, at: Vec2) -> Result<(), OrderError> {
        self.order(Order::Summon(kind, at))
    }

    /// Carries out a player's `order` now, and logs it.
    ///
    /// # Errors
    /// Why the keeper refused (see [`OrderError`]); nothing changes then.
    pub fn order(&mut self, order: Order) -> Result<(), OrderError> {
        if self.mode() == KeeperMode::Scripted {
            return Err(OrderError::Scripted { order });
        }
        if self.outcome().is_over() {
            return Err(OrderError::GameOver { order });
        }
        let event = match order {
            Order::Dig(cell) => {
                if let Some(refusal) = self.dig_refusal(order, cell) {
                    return Err(refusal);
                }
                self.pay(order, DIG_COST)?;
                self.level
                    .map
                    .clear_tile(cell)
                    .map_err(|e| bug(order, e.into()))?;
                Event::Dug { cell }
            }
            Order::Summon(kind, at) => {
                let at = self.place(order, kind, at)?;
                let cost = creature_cost(kind).ok_or(OrderError::NotACreature { order })?;
                self.pay(order, cost)?;
                spawn::fighter(
                    &mut self.world,
                    &mut self.bodies,
                    &mut self.ids,
                    kind,
                    at,
                    kind.max_hp(),
                )
                .map_err(|e| bug(order, e))?;
                Event::Summoned { kind }
            }
        };
        let events = [event];
        refresh_ways(&mut self.level, &mut self.world, &events).map_err(|e| bug(order, e))?;
        chronicle(&mut self.summary, &mut self.dug, &events[0]);
        self.orders.push(LoggedOrder {
            step: self.summary.steps,
            order,
        });
        Ok(())
    }

    /// Where a creature of `kind` ordered at `at` goes, or why it cannot.
    fn place(&self, order: Order, kind: Kind, at: Vec2) -> Result<Vec2, OrderError> {
        if kind == Kind::Hero {
            return Err(OrderError::NotACreature { order });
        }
        if !at.is_finite() {
            return Err(OrderError::NotFinite { order });
        }
        let map = self.map();
        if map.cell_at(at).is_none_or(|cell| map.tile(cell).is_some()) {
            return Err(OrderError::NotOpen { order });
        }
        if self.creatures_alive() >= MAX_CREATURES {
            return Err(OrderError::TooManyCreatures { order });
        }
        free_spot(self.level(), self.bodies(), at, kind.radius())
            .ok_or(OrderError::NoRoom { order })
    }

    /// Pays `cost` from the keeper's purse.
    fn pay(&mut self, order: Order, cost: u32) -> Result<(), OrderError> {
        self.keeper
            .spend(cost)
            .map_err(|gold| OrderError::NotEnoughGold { order, cost, gold })
    }
}

/// An accepted order the library refused to carry out.
fn bug(order: Order, source: GameError) -> OrderError {
    OrderError::Game {
        order,
        source: Box::new(source),
    }
}
