//! The node lattice a navigation grid searches: a node every half cell, so on every cell
//! corner, edge midpoint and centre.
//!
//! Half cells, not cells, because of wide agents: a circle of radius 0.8 fits a corridor two
//! cells wide only along its middle line, which runs on cell boundaries, never through a
//! cell centre. Nodes are joined to their eight neighbours; moves have integer costs (the
//! move's length in units of 1/1024 of the shorter half-cell side, rounded), so searches
//! compare exactly and are the same on every machine.

use glam::Vec2;

/// The eight moves, counter-clockwise from +x (in map coordinates, where +y is the next
/// row): E, SE-ish (+1, +1), S-ish (0, +1), … Moves `d` and `d + 4` are opposite; moves
/// 0..4 are the *forward* ones whose clearance a node stores (the other four are its
/// neighbours' forward moves).
pub(crate) const MOVES: [(i32, i32); 8] = [
    (1, 0),
    (1, 1),
    (0, 1),
    (-1, 1),
    (-1, 0),
    (-1, -1),
    (0, -1),
    (1, -1),
];

/// Cost units per shorter half-cell side.
const COST_SCALE: f32 = 1024.0;

/// Node positions and move costs of a map's lattice.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Lattice {
    /// Position of node (0, 0): the map's origin.
    pub origin: Vec2,
    /// Spacing: half a cell on each axis.
    pub step: Vec2,
    /// Nodes per row (2 · width + 1) and per column (2 · height + 1).
    pub nx: u32,
    pub ny: u32,
    /// Cost of each move in [`MOVES`] order.
    pub costs: [u32; 8],
    /// Map units per cost unit.
    pub unit: f32,
}

impl Lattice {
    /// The lattice of a `width × height` map of `cell` cells from `origin`.
    pub fn new(origin: Vec2, cell: Vec2, width: u32, height: u32) -> Self {
        let step = cell * 0.5;
        let unit = step.min_element() / COST_SCALE;
        let cost = |(dx, dy): (i32, i32)| {
            let length = Vec2::new(dx as f32 * step.x, dy as f32 * step.y).length();
            (length / unit).round() as u32
        };
        Self {
            origin,
            step,
            nx: 2 * width + 1,
            ny: 2 * height + 1,
            costs: MOVES.map(cost),
            unit,
        }
    }

    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.nx as usize * self.ny as usize
    }

    pub fn index(&self, i: u32, j: u32) -> usize {
        j as usize * self.nx as usize + i as usize
    }

    pub fn coords(&self, index: usize) -> (u32, u32) {
        (
            (index % self.nx as usize) as u32,
            (index / self.nx as usize) as u32,
        )
    }

    pub fn position(&self, i: u32, j: u32) -> Vec2 {
        self.origin + Vec2::new(i as f32, j as f32) * self.step
    }

    pub fn position_of(&self, index: usize) -> Vec2 {
        let (i, j) = self.coords(index);
        self.position(i, j)
    }

    /// The node one `d` move from (`i`, `j`), if it is on the lattice.
    pub fn neighbour(&self, i: u32, j: u32, d: usize) -> Option<(u32, u32)> {
        let (dx, dy) = MOVES[d];
        let (ni, nj) = (i as i64 + dx as i64, j as i64 + dy as i64);
        (ni >= 0 && nj >= 0 && ni < self.nx as i64 && nj < self.ny as i64)
            .then_some((ni as u32, nj as u32))
    }

    /// The node each move set in `bits` (bit `d` for move `d`) reaches from node `index`,
    /// with the move. The moves must stay on the lattice (open moves always do).
    #[inline]
    pub fn neighbours(&self, index: usize, bits: u8) -> impl Iterator<Item = (usize, usize)> {
        let (i, j) = self.coords(index);
        let mut bits = bits;
        std::iter::from_fn(move || {
            if bits == 0 {
                return None;
            }
            let d = bits.trailing_zeros() as usize;
            bits &= bits - 1;
            let (dx, dy) = MOVES[d];
            Some((
                d,
                self.index((i as i32 + dx) as u32, (j as i32 + dy) as u32),
            ))
        })
    }

    /// The lattice coordinates of `p`, fractional (node (i, j) at (i, j)).
    pub fn local(&self, p: Vec2) -> Vec2 {
        (p - self.origin) / self.step
    }

    /// A cost for a straight move of `length` map units, rounded up so that it never
    /// undercuts the lattice's own moves.
    pub fn cost_of_length(&self, length: f32) -> u32 {
        (length / self.unit).ceil().min(u32::MAX as f32 / 4.0) as u32
    }

    /// The octile distance between two nodes in cost units: the cost of the cheapest path
    /// on an empty lattice, so a search heuristic that never overestimates.
    pub fn octile(&self, (i0, j0): (u32, u32), (i1, j1): (u32, u32)) -> u32 {
        let dx = i0.abs_diff(i1);
        let dy = j0.abs_diff(j1);
        let (cx, cy, cd) = (self.costs[0], self.costs[2], self.costs[1]);
        let diagonal = dx.min(dy);
        // Each diagonal step replaces one x step and one y step.
        (dx * cx + dy * cy).saturating_sub(diagonal * (cx + cy).saturating_sub(cd))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn square_cells_cost_1024_straight_and_1448_diagonal() {
        let l = Lattice::new(Vec2::ZERO, Vec2::ONE, 4, 3);
        assert_eq!((l.nx, l.ny, l.len()), (9, 7, 63));
        assert_eq!(l.costs, [1024, 1448, 1024, 1448, 1024, 1448, 1024, 1448]);
        assert_eq!(l.position(3, 2), Vec2::new(1.5, 1.0));
        assert_eq!(l.coords(l.index(3, 2)), (3, 2));
        assert_eq!(l.octile((0, 0), (3, 1)), 2 * 1024 + 1448);
        assert_eq!(l.neighbour(0, 0, 4), None);
        assert_eq!(l.neighbour(8, 6, 1), None);
        assert_eq!(l.neighbour(2, 2, 5), Some((1, 1)));
    }

    #[test]
    fn opposite_moves_are_four_apart() {
        for d in 0..4 {
            let (a, b) = (MOVES[d], MOVES[d + 4]);
            assert_eq!((a.0 + b.0, a.1 + b.1), (0, 0));
        }
    }
}
