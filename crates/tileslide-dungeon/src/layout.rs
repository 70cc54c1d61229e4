//! The dungeon's ground: a disc of diggable earth inside undiggable rock, the treasure room
//! in the middle, the entrance on the top edge, and the keeper's digging plan.

use tileslide::io::{LoadError, ascii};
use tileslide::{Cell, TileMap, Vec2};

/// Cells across and down.
pub const SIZE: i32 = 64;
/// Radius of the playable disc (cells), around the map's centre.
pub const EARTH_RADIUS: f32 = 27.0;

/// Which solid cells are rock (never dug) and which are earth: tileslide only knows
/// "solid", so the game keeps the difference.
#[derive(Clone, Debug)]
pub struct Ground {
    rock: Vec<bool>,
}

impl Ground {
    /// True when `cell` is rock (off the map counts as rock).
    #[must_use]
    pub fn is_rock(&self, cell: Cell) -> bool {
        index(cell).is_none_or(|i| self.rock[i])
    }
}

fn index(cell: Cell) -> Option<usize> {
    let (c, r) = (cell.col as i32, cell.row as i32);
    ((0..SIZE).contains(&c) && (0..SIZE).contains(&r)).then(|| (r * SIZE + c) as usize)
}

fn is_earth(col: i32, row: i32) -> bool {
    let centre = Vec2::splat(SIZE as f32 / 2.0);
    (Vec2::new(col as f32 + 0.5, row as f32 + 0.5) - centre).length() < EARTH_RADIUS
}

/// A rectangle of cells, inclusive.
#[derive(Clone, Copy, Debug)]
struct Rooms {
    cols: (i32, i32),
    rows: (i32, i32),
}

impl Rooms {
    fn contains(&self, col: i32, row: i32) -> bool {
        (self.cols.0..=self.cols.1).contains(&col) && (self.rows.0..=self.rows.1).contains(&row)
    }

    /// Its cells row by row from the bottom (the treasure side) up.
    fn cells_upward(&self) -> impl Iterator<Item = (i32, i32)> + '_ {
        (self.rows.0..=self.rows.1)
            .rev()
            .flat_map(move |r| (self.cols.0..=self.cols.1).map(move |c| (c, r)))
    }
}

const TREASURE_ROOM: Rooms = Rooms {
    cols: (29, 35),
    rows: (29, 35),
};
const ENTRANCE_ROOM: Rooms = Rooms {
    cols: (29, 35),
    rows: (5, 8),
};
/// The gap in the rock above the entrance room: the way in and out.
const GATE: Rooms = Rooms {
    cols: (31, 33),
    rows: (2, 4),
};
/// The corridor a player's dungeon starts with: from the entrance room straight down to
/// the treasure room, so that heroes have a way in from the first party on.
const PLAYER_CORRIDOR: Rooms = Rooms {
    cols: (32, 33),
    rows: (9, 28),
};
/// Where the keeper's skeletons wait.
pub const LAIR: Vec2 = Vec2::new(27.5, 21.5);
/// Where the keeper's imps wait.
pub const ROOST: Vec2 = Vec2::new(42.0, 11.0);

/// What the keeper digs, in order: a corridor from the treasure room up towards the
/// entrance with a dog-leg, a skeleton lair beside it and an imp roost off its last leg.
fn plan_rects() -> [Rooms; 7] {
    [
        Rooms {
            cols: (32, 33),
            rows: (22, 28),
        },
        Rooms {
            cols: (25, 31),
            rows: (19, 24),
        },
        Rooms {
            cols: (32, 33),
            rows: (15, 21),
        },
        Rooms {
            cols: (34, 38),
            rows: (15, 16),
        },
        Rooms {
            cols: (37, 38),
            rows: (9, 14),
        },
        Rooms {
            cols: (39, 44),
            rows: (9, 13),
        },
        Rooms {
            cols: (36, 38),
            rows: (7, 8),
        },
    ]
}

/// The map at the start, the ground, and the keeper's plan.
#[derive(Clone, Debug)]
pub struct Layout {
    /// The collision map: rock and earth solid, rooms empty.
    pub map: TileMap,
    /// Rock or earth, per cell.
    pub ground: Ground,
    /// Where the treasure lies.
    pub treasure: Vec2,
    /// Where heroes come in and leave.
    pub exit: Vec2,
    /// The squares the keeper will dig, in order.
    pub plan: Vec<Cell>,
}

impl Layout {
    /// The standard dungeon: the treasure room and the entrance room, not joined (the
    /// scripted keeper digs the way).
    ///
    /// # Errors
    /// Only if the built-in ASCII map fails to parse (a bug).
    pub fn build() -> Result<Self, LoadError> {
        Self::build_with(None)
    }

    /// The dungeon a player starts with: the standard one with a corridor dug from the
    /// entrance room to the treasure room.
    ///
    /// # Errors
    /// Only if the built-in ASCII map fails to parse (a bug).
    pub fn build_for_player() -> Result<Self, LoadError> {
        Self::build_with(Some(PLAYER_CORRIDOR))
    }

    fn build_with(corridor: Option<Rooms>) -> Result<Self, LoadError> {
        let open = |c, r| {
            TREASURE_ROOM.contains(c, r)
                || ENTRANCE_ROOM.contains(c, r)
                || GATE.contains(c, r)
                || corridor.is_some_and(|room| room.contains(c, r))
        };
        let mut text = String::new();
        let mut rock = Vec::new();
        for r in 0..SIZE {
            for c in 0..SIZE {
                text.push(if open(c, r) { '.' } else { '#' });
                rock.push(!is_earth(c, r) && !GATE.contains(c, r));
            }
            text.push('\n');
        }
        let map = ascii::parse(&text, "dungeon", 1.0)?;
        let ground = Ground { rock };
        let mut plan = Vec::new();
        for rect in plan_rects() {
            for (c, r) in rect.cells_upward() {
                let cell = Cell {
                    col: c as u32,
                    row: r as u32,
                };
                if !open(c, r) && !ground.is_rock(cell) && !plan.contains(&cell) {
                    plan.push(cell);
                }
            }
        }
        Ok(Self {
            map,
            ground,
            treasure: Vec2::new(32.5, 32.5),
            exit: Vec2::new(32.5, 3.5),
            plan,
        })
    }

    /// Where a party stands when it arrives: the entrance room's first row, spaced apart.
    #[must_use]
    pub fn arrival_points() -> Vec<Vec2> {
        (0..6)
            .flat_map(|k| {
                [
                    Vec2::new(29.7 + k as f32, 5.7),
                    Vec2::new(29.7 + k as f32, 7.3),
                ]
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plan_digs_only_earth_and_reaches_the_entrance() {
        let layout = Layout::build().unwrap();
        assert!(layout.plan.len() > 50);
        assert!(layout.plan.iter().all(|&c| !layout.ground.is_rock(c)));
        assert!(layout.ground.is_rock(Cell { col: 0, row: 0 }));
        assert!(!layout.ground.is_rock(Cell { col: 32, row: 32 }));
    }

    #[test]
    fn a_players_corridor_is_earth_and_joins_the_entrance_to_the_treasure_room() {
        let (scripted, player) = (
            Layout::build().unwrap(),
            Layout::build_for_player().unwrap(),
        );
        for row in 9..=28 {
            let cell = Cell::new(32, row);
            assert!(!player.ground.is_rock(cell));
            assert!(player.map.tile(cell).is_none(), "{cell:?}");
            assert!(scripted.map.tile(cell).is_some(), "{cell:?}");
        }
        assert!(player.map.tile(Cell::new(31, 20)).is_some());
    }
}
