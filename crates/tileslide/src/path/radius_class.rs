//! What a navigation grid keeps per radius class (per clearance need): every node's open
//! moves as one byte, and the connected parts of that graph.
//!
//! One-way platforms make the graph directed. Parts and landmark distances are those of
//! its undirected closure (a move counts if it is open either way): a shorter way there
//! is no longer than any way on the directed graph, so the parts still prove a goal
//! unreachable when they differ and the landmark bounds stay admissible and consistent
//! for the directed search. Where a platform makes a goal unreachable from one side only,
//! A* finds out by exhausting what it can reach.
//!
//! The moves byte turns a search's eight clearance comparisons per node into one load. The
//! parts answer "is the goal reachable at all?" before any search: A* proves a goal
//! unreachable only by exhausting the start's whole part, which on a dungeon map is most
//! of the map, so an unreachable query would cost more than any reachable one.

use std::collections::VecDeque;

use super::clearance::{ChangedMove, Clearance, open_moves};
use super::landmarks::Landmarks;
use super::lattice::Lattice;

/// The moves and parts for circles needing `need` clearance steps.
#[derive(Clone, Debug)]
pub(crate) struct RadiusClass {
    pub need: u16,
    /// Per node, bit `d` set when move `d` is open.
    pub moves: Vec<u8>,
    /// Per node, the smallest node index of its part; valid when `parts_current`.
    parts: Vec<u32>,
    parts_current: bool,
    /// Landmark distances (see `landmarks`), built with the parts; `None` after a move
    /// opened (closing moves keep their bounds valid).
    landmarks: Option<Landmarks>,
}

impl RadiusClass {
    pub fn build(table: &Clearance, need: u16) -> Self {
        let lattice = &table.lattice;
        let mut moves = vec![0u8; lattice.len()];
        for j in 0..lattice.ny {
            for i in 0..lattice.nx {
                let n = lattice.index(i, j);
                moves[n] = open_moves(table, n, i, j, need);
            }
        }
        Self {
            need,
            moves,
            parts: Vec::new(),
            parts_current: false,
            landmarks: None,
        }
    }

    /// Brings the moves up to date after the clearances of `changed` moves changed (both
    /// of each move's nodes see it); the parts are recomputed when next asked for, if a
    /// move opened or closed for this class.
    pub fn apply(&mut self, table: &Clearance, changed: &[ChangedMove]) {
        let lattice = &table.lattice;
        for m in changed {
            if (m.before >= self.need) == (m.after >= self.need) {
                continue;
            }
            self.parts_current = false;
            if m.after >= self.need {
                self.landmarks = None;
            }
            let n = m.node as usize;
            let (i, j) = lattice.coords(n);
            self.moves[n] = open_moves(table, n, i, j, self.need);
            if let Some((a, b)) = lattice.neighbour(i, j, m.dir as usize) {
                let o = lattice.index(a, b);
                self.moves[o] = open_moves(table, o, a, b, self.need);
            }
        }
    }

    /// Per node, an id shared exactly by the nodes connected to it; the landmarks; and the
    /// moves.
    pub fn parts(&mut self, lattice: &Lattice) -> (&[u32], &Landmarks, &[u8]) {
        // Both are found on the undirected closure (see the module's notes).
        let mut links: Option<Vec<u8>> = None;
        if !self.parts_current {
            let links = links.insert(undirected(lattice, &self.moves));
            self.parts = label_parts(lattice, links);
            self.parts_current = true;
        }
        let (moves, parts) = (&self.moves, &self.parts);
        let landmarks = self.landmarks.get_or_insert_with(|| {
            let links = links.unwrap_or_else(|| undirected(lattice, moves));
            Landmarks::build(lattice, &links, parts)
        });
        (parts, landmarks, moves)
    }
}

/// The moves of the undirected closure of `moves`: bit `d` of a node when its move `d` or
/// the reverse of it is open.
fn undirected(lattice: &Lattice, moves: &[u8]) -> Vec<u8> {
    let mut links = moves.to_vec();
    for (n, &bits) in moves.iter().enumerate() {
        for (d, m) in lattice.neighbours(n, bits) {
            links[m] |= 1 << ((d + 4) % 8);
        }
    }
    links
}

/// Breadth-first labelling of the graph's connected parts.
fn label_parts(lattice: &Lattice, moves: &[u8]) -> Vec<u32> {
    const UNLABELLED: u32 = u32::MAX;
    let mut parts = vec![UNLABELLED; moves.len()];
    let mut queue = VecDeque::new();
    for start in 0..moves.len() {
        if parts[start] != UNLABELLED {
            continue;
        }
        parts[start] = start as u32;
        queue.push_back(start);
        while let Some(n) = queue.pop_front() {
            for (_, m) in lattice.neighbours(n, moves[n]) {
                if parts[m] == UNLABELLED {
                    parts[m] = start as u32;
                    queue.push_back(m);
                }
            }
        }
    }
    parts
}
