//! A* over the lattice for one radius (Hart, Nilsson & Raphael 1968), with dense per-node
//! arrays stamped by a search number, so a query touches only the nodes it reaches and
//! nothing is cleared between queries.
//!
//! The query's end points are off the lattice: the start joins the search through the
//! nodes around it it can reach in a straight line (each with the cost of that line), and
//! the goal is a virtual node reached the same way. The heuristic is the octile distance to
//! the node nearest the goal, less the farthest the goal's own nodes are from it, so it
//! never overestimates and stays consistent; the search stops when nothing left in the open
//! list can beat the best way found to the goal.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use super::landmarks::Landmarks;
use super::lattice::{Lattice, MOVES};

/// `parent` of a node the search started from.
const START: u8 = u8::MAX;

/// Scratch for searches, reused between queries.
#[derive(Clone, Debug, Default)]
pub(crate) struct Search {
    /// Number of the current search; a node's `g` and `parent` are valid when its `seen`
    /// equals it, and it is closed when its `closed` equals it.
    generation: u32,
    seen: Vec<u32>,
    closed: Vec<u32>,
    /// Search numbers marking the nodes the goal is reached from.
    target: Vec<u32>,
    g: Vec<u32>,
    /// The move that reached the node.
    parent: Vec<u8>,
    /// Open nodes by (f, h) then node: among equal f the one nearest the goal first,
    /// which keeps open ground from being expanded row after row.
    open: BinaryHeap<Reverse<(u64, u32)>>,
}

/// A node an end point joins the lattice through, with the cost of the straight line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Attach {
    pub node: u32,
    pub cost: u32,
}

impl Search {
    fn begin(&mut self, nodes: usize) {
        if self.seen.len() != nodes {
            *self = Self {
                seen: vec![0; nodes],
                closed: vec![0; nodes],
                target: vec![0; nodes],
                g: vec![0; nodes],
                parent: vec![START; nodes],
                ..Self::default()
            };
        }
        self.generation = self.generation.wrapping_add(1);
        if self.generation == 0 {
            // After 2³² searches the stamps wrap: forget them all once.
            self.seen.fill(0);
            self.closed.fill(0);
            self.target.fill(0);
            self.generation = 1;
        }
        self.open.clear();
    }

    /// The cheapest lattice path over the open `moves` (per node, see `RadiusClass`) from
    /// any of `starts` to any of `goals` (each with its joining cost): the nodes from the
    /// start side to the goal side, or `None` if no path exists.
    pub fn find(
        &mut self,
        lattice: &Lattice,
        moves: &[u8],
        landmarks: &Landmarks,
        starts: &[Attach],
        goals: &[Attach],
    ) -> Option<Vec<u32>> {
        self.begin(lattice.len());
        let generation = self.generation;
        let goal_at = |attach: &Attach| lattice.coords(attach.node as usize);
        let centre = goals.first().map(goal_at)?;
        let slack = goals
            .iter()
            .map(|a| lattice.octile(goal_at(a), centre))
            .max()
            .unwrap_or(0);
        let bounds = landmarks.goal_bounds(goals.iter().map(|a| a.node));
        let h = |index: usize| {
            let octile = lattice
                .octile(lattice.coords(index), centre)
                .saturating_sub(slack);
            octile.max(landmarks.lower_bound(index, &bounds))
        };
        for a in goals {
            self.target[a.node as usize] = generation;
        }
        for a in starts {
            let n = a.node as usize;
            if self.seen[n] != generation || a.cost < self.g[n] {
                self.seen[n] = generation;
                self.g[n] = a.cost;
                self.parent[n] = START;
                self.open.push(key(a.cost, h(n), a.node));
            }
        }
        let mut best: Option<(u32, u32)> = None;
        while let Some(Reverse((k, node))) = self.open.pop() {
            let f = (k >> 32) as u32;
            if best.is_some_and(|(cost, _)| f >= cost) {
                break;
            }
            let n = node as usize;
            if self.closed[n] == generation {
                continue;
            }
            self.closed[n] = generation;
            let g = self.g[n];
            if self.target[n] == generation {
                let join = goals.iter().find(|a| a.node == node).map_or(0, |a| a.cost);
                let total = g.saturating_add(join);
                if best.is_none_or(|(cost, _)| total < cost) {
                    best = Some((total, node));
                }
            }
            for (d, m) in lattice.neighbours(n, moves[n]) {
                if self.closed[m] == generation {
                    continue;
                }
                let ng = g.saturating_add(lattice.costs[d]);
                if self.seen[m] != generation || ng < self.g[m] {
                    self.seen[m] = generation;
                    self.g[m] = ng;
                    self.parent[m] = d as u8;
                    self.open.push(key(ng, h(m), m as u32));
                }
            }
        }
        let (_, mut node) = best?;
        let mut nodes = vec![node];
        while self.parent[node as usize] != START {
            let d = self.parent[node as usize] as usize;
            let (i, j) = lattice.coords(node as usize);
            let (dx, dy) = MOVES[d];
            node = lattice.index((i as i32 - dx) as u32, (j as i32 - dy) as u32) as u32;
            nodes.push(node);
        }
        nodes.reverse();
        Some(nodes)
    }
}

/// The open list's order: f, then h (nearest the goal first), then the node.
fn key(g: u32, h: u32, node: u32) -> Reverse<(u64, u32)> {
    let f = u64::from(g.saturating_add(h));
    Reverse((f << 32 | u64::from(h), node))
}
