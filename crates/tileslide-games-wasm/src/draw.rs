//! What a canvas draws, as flat arrays of numbers: plain Rust (tested natively), which the
//! JavaScript classes hand over as typed arrays.

use tileslide::{Cell, TileMap};
use tileslide_dungeon::{Fighter, Game, Kind, Team};

/// Floats per segment in [`segments`]: `x0, y0, x1, y1, nx, ny, flags`.
pub const SEGMENT_STRIDE: usize = 7;
/// Floats per fighter in [`fighters`]: `x, y, radius, kind, team, hp fraction, carrying`.
pub const FIGHTER_STRIDE: usize = 7;

/// Every active segment of `map`, cell by cell in row order: its ends, its outward unit
/// normal and its flags' bits (1 solid, 2 one-way; see `tileslide::SegmentFlags`).
#[must_use]
pub fn segments(map: &TileMap) -> Vec<f32> {
    let mut out = Vec::with_capacity(map.active_segment_count() * SEGMENT_STRIDE);
    for row in 0..map.height() {
        for col in 0..map.width() {
            for s in map.active_segments(Cell::new(col, row)) {
                let (a, b) = (s.segment.a, s.segment.b);
                // Flags are small bit sets: the low bits a game defines fit an f32 exactly.
                out.extend([a.x, a.y, b.x, b.y, s.normal.x, s.normal.y, s.flags.0 as f32]);
            }
        }
    }
    out
}

/// A fighter's kind as a number: 0 hero, 1 skeleton, 2 imp.
#[must_use]
pub fn kind_code(kind: Kind) -> u8 {
    match kind {
        Kind::Hero => 0,
        Kind::Skeleton => 1,
        Kind::Imp => 2,
    }
}

/// The fighters of [`Game::fighters`], [`FIGHTER_STRIDE`] floats each: centre, radius,
/// [`kind_code`], team (0 heroes, 1 keeper), hit points left as a fraction of the start,
/// and 1 when it carries a piece of the treasure.
#[must_use]
pub fn fighters(all: &[Fighter]) -> Vec<f32> {
    let mut out = Vec::with_capacity(all.len() * FIGHTER_STRIDE);
    for f in all {
        let team = match f.team {
            Team::Heroes => 0.0,
            Team::Keeper => 1.0,
        };
        let hp = if f.max_hp > 0 {
            (f.hp.max(0) as f32 / f.max_hp as f32).min(1.0)
        } else {
            0.0
        };
        out.extend([
            f.position.x,
            f.position.y,
            f.radius,
            f32::from(kind_code(f.kind)),
            team,
            hp,
            f32::from(u8::from(f.carrying)),
        ]);
    }
    out
}

/// What a dungeon square is, for [`squares`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
pub enum Square {
    /// Open, and seen by the heroes.
    Seen = 0,
    /// Open, and not seen by any hero yet (the write-up's yellow).
    Unseen = 1,
    /// Earth the keeper can dig now.
    Diggable = 2,
    /// Earth not beside an open square.
    Earth = 3,
    /// Rock, which nobody digs.
    Rock = 4,
}

/// One [`Square`] code per cell of `game`'s map, row by row.
#[must_use]
pub fn squares(game: &Game) -> Vec<u8> {
    let map = game.map();
    let level = game.level();
    let mut out = Vec::with_capacity(map.width() as usize * map.height() as usize);
    for row in 0..map.height() {
        for col in 0..map.width() {
            let cell = Cell::new(col, row);
            let square = if map.tile(cell).is_none() {
                if level.explored.is_seen(cell) {
                    Square::Seen
                } else {
                    Square::Unseen
                }
            } else if level.ground.is_rock(cell) {
                Square::Rock
            } else if game.is_diggable(cell) {
                Square::Diggable
            } else {
                Square::Earth
            };
            out.push(square as u8);
        }
    }
    out
}

/// The cells of `cells` as `col, row` pairs.
#[must_use]
pub fn cell_pairs(cells: &[Cell]) -> Vec<u32> {
    cells.iter().flat_map(|c| [c.col, c.row]).collect()
}
