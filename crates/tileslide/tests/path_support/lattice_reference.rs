//! The navigation lattice built by brute force: a node every half cell (node
//! (i, j) at origin + (i, j) half cells, i in 0..=2W, j in 0..=2H), joined to its eight
//! neighbours ([`NAV_MOVES`]); a move is open for a circle of radius r iff neither end is
//! inside a solid tile and the straight move keeps at least r + margin from every wall of
//! the whole map ([`Walls`]).

use std::collections::VecDeque;

use tileslide::{NAV_MOVES, TileMap, Vec2};

use super::walls::Walls;

/// How far from the threshold a clearance must be for the reference to have a verdict:
/// the grid stores clearances rounded down to 1/2048 cell and computes them in `f32`.
pub const QUANTISATION: f64 = 1e-3;

/// What the reference says about one move for one radius.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// Off the lattice.
    Missing,
    Open,
    Closed,
    /// Within [`QUANTISATION`] of the threshold: either answer is right.
    Borderline,
}

/// Clearances of every node and move of a map's lattice.
#[derive(Clone, Debug)]
pub struct LatticeReference {
    pub nx: u32,
    pub ny: u32,
    pub positions: Vec<Vec2>,
    /// Per node, how wide a circle standing there can be (0 inside a solid).
    pub point: Vec<f64>,
    /// Per node and move of `NAV_MOVES`, the move's clearance; `None` off the lattice.
    pub moves: Vec<[Option<f64>; 8]>,
}

impl LatticeReference {
    /// The lattice of `map` whose walls are `walls`.
    pub fn build(map: &TileMap, walls: &Walls) -> Self {
        let (nx, ny) = (2 * map.width() + 1, 2 * map.height() + 1);
        let half = map.cell_size() * 0.5;
        let mut positions = Vec::new();
        for j in 0..ny {
            for i in 0..nx {
                positions.push(map.origin() + Vec2::new(i as f32, j as f32) * half);
            }
        }
        let point = positions
            .iter()
            .map(|&p| walls.clearance(map, p, p))
            .collect();
        // Moves 0..4 measured here; moves 4..8 are the neighbours' moves 0..4 reversed.
        let mut moves: Vec<[Option<f64>; 8]> = (0..positions.len())
            .map(|n| {
                let mut out = [None; 8];
                for (d, slot) in out.iter_mut().enumerate().take(4) {
                    *slot = Self::neighbour_in(nx, ny, n, d)
                        .map(|m| walls.clearance(map, positions[n], positions[m]));
                }
                out
            })
            .collect();
        for n in 0..positions.len() {
            for d in 4..8 {
                if let Some(m) = Self::neighbour_in(nx, ny, n, d) {
                    moves[n][d] = moves[m][d - 4];
                }
            }
        }
        Self {
            nx,
            ny,
            positions,
            point,
            moves,
        }
    }

    fn neighbour_in(nx: u32, ny: u32, n: usize, d: usize) -> Option<usize> {
        let (i, j) = ((n % nx as usize) as i64, (n / nx as usize) as i64);
        let (di, dj) = NAV_MOVES[d];
        let (ni, nj) = (i + i64::from(di), j + i64::from(dj));
        (ni >= 0 && nj >= 0 && ni < i64::from(nx) && nj < i64::from(ny))
            .then_some((nj * i64::from(nx) + ni) as usize)
    }

    /// The node one `d` move from node `n`, if on the lattice.
    pub fn neighbour(&self, n: usize, d: usize) -> Option<usize> {
        Self::neighbour_in(self.nx, self.ny, n, d)
    }

    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.positions.len()
    }

    /// Node index of (`i`, `j`).
    pub fn index(&self, i: u32, j: u32) -> usize {
        (j * self.nx + i) as usize
    }

    /// Lattice coordinates of node `n`.
    pub fn coords(&self, n: usize) -> (u32, u32) {
        ((n % self.nx as usize) as u32, (n / self.nx as usize) as u32)
    }

    /// The verdict on move `d` from node `n` for a clearance threshold `need` (radius plus
    /// margin).
    pub fn verdict(&self, n: usize, d: usize, need: f64) -> Verdict {
        match self.moves[n][d] {
            None => Verdict::Missing,
            Some(c) if (c - need).abs() <= QUANTISATION => Verdict::Borderline,
            Some(c) if c >= need => Verdict::Open,
            Some(_) => Verdict::Closed,
        }
    }

    /// The nodes a circle needing clearance `need` reaches from `starts` by lattice moves;
    /// borderline moves count as open iff `borderline_open`.
    pub fn flood(&self, starts: &[usize], need: f64, borderline_open: bool) -> Vec<bool> {
        let mut seen = vec![false; self.len()];
        let mut queue = VecDeque::new();
        for &s in starts {
            if !seen[s] {
                seen[s] = true;
                queue.push_back(s);
            }
        }
        while let Some(n) = queue.pop_front() {
            for d in 0..8 {
                let open = match self.verdict(n, d, need) {
                    Verdict::Open => true,
                    Verdict::Borderline => borderline_open,
                    Verdict::Closed | Verdict::Missing => false,
                };
                if !open {
                    continue;
                }
                if let Some(m) = self.neighbour(n, d)
                    && !seen[m]
                {
                    seen[m] = true;
                    queue.push_back(m);
                }
            }
        }
        seen
    }
}
