//! What the heroes know of the dungeon: the squares they have seen, and whether they have
//! seen the treasure. Heroes come for a treasure they have only heard of: until one of
//! them sees it, they explore, each walking to the nearest *frontier* square (one they have
//! seen that borders an open square none of them has), which the keeper's digging keeps
//! opening. Sight is the game's line of sight (a ray cast between centres).
//!
//! The knowledge is the heroes' guild's, shared by every party: later parties know what
//! earlier ones saw.

use tileslide::{Cell, TileMap, Vec2};

/// How far heroes see (cells).
pub const SIGHT: f32 = 6.0;

/// The heroes' map of the dungeon.
#[derive(Clone, Debug)]
pub struct Explored {
    width: u32,
    height: u32,
    seen: Vec<bool>,
    /// Frontier squares no hero could find a way to; forgotten when a square is dug.
    dead_ends: Vec<bool>,
    treasure_seen: bool,
}

impl Explored {
    /// Nothing seen yet on `map`.
    #[must_use]
    pub fn new(map: &TileMap) -> Self {
        let cells = map.width() as usize * map.height() as usize;
        Self {
            width: map.width(),
            height: map.height(),
            seen: vec![false; cells],
            dead_ends: vec![false; cells],
            treasure_seen: false,
        }
    }

    /// Whether a hero has seen the treasure.
    #[must_use]
    pub fn treasure_seen(&self) -> bool {
        self.treasure_seen
    }

    /// Squares seen so far.
    #[must_use]
    pub fn seen_count(&self) -> usize {
        self.seen.iter().filter(|&&s| s).count()
    }

    /// Whether `cell` has been seen.
    #[must_use]
    pub fn is_seen(&self, cell: Cell) -> bool {
        self.index(cell).is_some_and(|i| self.seen[i])
    }

    fn index(&self, cell: Cell) -> Option<usize> {
        (cell.col < self.width && cell.row < self.height)
            .then(|| cell.row as usize * self.width as usize + cell.col as usize)
    }

    /// Marks what a hero at `from` sees on `map`: the open squares within `SIGHT` (6 cells)
    /// whose centres it has a line of sight to (`sees`), and the treasure at `treasure`.
    pub fn look(
        &mut self,
        map: &TileMap,
        from: Vec2,
        treasure: Vec2,
        sees: impl Fn(Vec2, Vec2) -> bool,
    ) {
        let Some(here) = map.cell_at(from) else {
            return;
        };
        let reach = SIGHT.ceil() as i64;
        for dr in -reach..=reach {
            for dc in -reach..=reach {
                let (col, row) = (i64::from(here.col) + dc, i64::from(here.row) + dr);
                let (Ok(col), Ok(row)) = (u32::try_from(col), u32::try_from(row)) else {
                    continue;
                };
                let cell = Cell::new(col, row);
                let Some(i) = self.index(cell) else {
                    continue;
                };
                if self.seen[i] || map.tile(cell).is_some() {
                    continue;
                }
                let centre = centre_of(map, cell);
                if centre.distance(from) <= SIGHT && sees(from, centre) {
                    self.seen[i] = true;
                }
            }
        }
        if !self.treasure_seen && treasure.distance(from) <= SIGHT && sees(from, treasure) {
            self.treasure_seen = true;
        }
    }

    /// Whether `cell` is a frontier square of `map`: seen, open, next to an open square
    /// not seen yet.
    #[must_use]
    pub fn is_frontier(&self, map: &TileMap, cell: Cell) -> bool {
        if !self.is_seen(cell) || map.tile(cell).is_some() {
            return false;
        }
        neighbours(cell).any(|n| {
            self.index(n)
                .is_some_and(|i| !self.seen[i] && map.tile(n).is_none())
        })
    }

    /// The frontier square nearest `from` (ties: the lower row, then column), leaving out
    /// dead ends.
    #[must_use]
    pub fn nearest_frontier(&self, map: &TileMap, from: Vec2) -> Option<Cell> {
        let mut best: Option<(f32, Cell)> = None;
        for row in 0..self.height {
            for col in 0..self.width {
                let cell = Cell::new(col, row);
                let i = row as usize * self.width as usize + col as usize;
                if self.dead_ends[i] || !self.is_frontier(map, cell) {
                    continue;
                }
                let d = centre_of(map, cell).distance(from);
                if best.is_none_or(|(bd, _)| d < bd) {
                    best = Some((d, cell));
                }
            }
        }
        best.map(|(_, c)| c)
    }

    /// No hero finds a way to `cell`: leave it out until the dungeon changes.
    pub fn dead_end(&mut self, cell: Cell) {
        if let Some(i) = self.index(cell) {
            self.dead_ends[i] = true;
        }
    }

    /// The dungeon changed (a square was dug): every frontier square is worth a try again.
    pub fn forget_dead_ends(&mut self) {
        self.dead_ends.fill(false);
    }
}

/// The middle of `cell`.
#[must_use]
pub fn centre_of(map: &TileMap, cell: Cell) -> Vec2 {
    let r = map.cell_rect(cell);
    (r.min + r.max) * 0.5
}

/// The four squares beside `cell` (those with a negative coordinate left out).
pub(crate) fn neighbours(cell: Cell) -> impl Iterator<Item = Cell> {
    [(-1i64, 0i64), (1, 0), (0, -1), (0, 1)]
        .into_iter()
        .filter_map(move |(dc, dr)| {
            let col = u32::try_from(i64::from(cell.col) + dc).ok()?;
            let row = u32::try_from(i64::from(cell.row) + dr).ok()?;
            Some(Cell::new(col, row))
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use tileslide::io::ascii;

    /// A room with a corridor to a second room behind a wall: from the first room the
    /// heroes see the room and the corridor's mouth, not the second room, and the mouth is
    /// the frontier.
    #[test]
    fn what_is_in_sight_is_seen_and_the_corridor_mouth_is_the_frontier() {
        let map = ascii::parse(
            "##########\n#...######\n#...######\n#.........\n##########",
            "e.txt",
            1.0,
        )
        .unwrap();
        let sees = |a: Vec2, b: Vec2| {
            map.cast_ray(
                tileslide::Ray::between(a, b),
                &tileslide::QueryFilter::default(),
            )
            .is_none()
        };
        let mut explored = Explored::new(&map);
        explored.look(&map, Vec2::new(1.5, 1.5), Vec2::new(9.5, 3.5), sees);
        assert!(explored.is_seen(Cell::new(3, 2)));
        assert!(!explored.treasure_seen(), "the treasure is out of sight");
        // Far along the corridor is beyond sight.
        assert!(!explored.is_seen(Cell::new(9, 3)));
        let frontier = explored
            .nearest_frontier(&map, Vec2::new(1.5, 1.5))
            .unwrap();
        assert!(frontier.row == 3 && frontier.col >= 3, "{frontier:?}");
        assert!(explored.is_frontier(&map, frontier));
        // A dead end is left out until forgotten.
        explored.dead_end(frontier);
        assert_ne!(
            explored.nearest_frontier(&map, Vec2::new(1.5, 1.5)),
            Some(frontier)
        );
        explored.forget_dead_ends();
        assert_eq!(
            explored.nearest_frontier(&map, Vec2::new(1.5, 1.5)),
            Some(frontier)
        );
        // Walking down the corridor, the treasure comes into sight.
        explored.look(&map, Vec2::new(6.5, 3.5), Vec2::new(9.5, 3.5), sees);
        assert!(explored.treasure_seen());
        assert!(explored.seen_count() > 8);
    }
}
