//! A* over the lattice for one radius (Hart, Nilsson & Raphael 1968), with a dense per-node
//! record stamped by a search number, so a query touches only the nodes it reaches and
//! nothing is cleared between queries, and a radix heap for the open list (f never
//! decreases under a consistent heuristic).
//!
//! The query's end points are off the lattice: the start joins the search through the
//! nodes around it it can reach in a straight line (each with the cost of that line), and
//! the goal is a virtual node reached the same way. The heuristic is the octile distance to
//! the node nearest the goal, less the farthest the goal's own nodes are from it, so it
//! never overestimates and stays consistent; the search stops when nothing left in the open
//! list can beat the best way found to the goal.

use super::landmarks::Landmarks;
use super::lattice::{Lattice, MOVES};
use super::radix_heap::RadixHeap;

/// `parent` of a node the search started from.
const START: u8 = u8::MAX;

/// What a search knows of one node; valid when `stamp` is the search's number, so
/// nothing is cleared between searches. One 16-byte record, so a node costs one cache
/// line touch, not one per array.
#[derive(Clone, Copy, Debug, Default)]
struct NodeState {
    stamp: u32,
    /// Cheapest cost found from the start side.
    g: u32,
    /// The heuristic, computed once when the node is first seen.
    h: u32,
    /// The move that reached the node, or [`START`].
    parent: u8,
    closed: bool,
    /// The goal is joined from this node.
    target: bool,
}

/// Scratch for searches, reused between queries.
#[derive(Clone, Debug, Default)]
pub(crate) struct Search {
    /// Number of the current search.
    generation: u32,
    nodes: Vec<NodeState>,
    /// Open nodes by f = g + h (a consistent heuristic makes f pop in order).
    open: RadixHeap,
}

/// A node an end point joins the lattice through, with the cost of the straight line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Attach {
    pub node: u32,
    pub cost: u32,
}

impl Search {
    fn begin(&mut self, nodes: usize) {
        if self.nodes.len() != nodes {
            self.nodes = vec![NodeState::default(); nodes];
            self.generation = 0;
        }
        self.generation = self.generation.wrapping_add(1);
        if self.generation == 0 {
            // After 2³² searches the stamps wrap: forget them all once.
            self.nodes.fill(NodeState::default());
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
        let h = |index: usize, at: (u32, u32)| {
            let octile = lattice.octile(at, centre).saturating_sub(slack);
            octile.max(landmarks.lower_bound(index, &bounds))
        };
        let state = &mut self.nodes;
        // A node seen for the first time in this search: not reached yet, heuristic known.
        let fresh = |state: &mut [NodeState], n: usize, at: (u32, u32)| {
            let s = &mut state[n];
            if s.stamp != generation {
                *s = NodeState {
                    stamp: generation,
                    g: u32::MAX,
                    h: h(n, at),
                    parent: START,
                    closed: false,
                    target: false,
                };
            }
        };
        for a in goals {
            let n = a.node as usize;
            fresh(state, n, lattice.coords(n));
            state[n].target = true;
        }
        for a in starts {
            let n = a.node as usize;
            fresh(state, n, lattice.coords(n));
            let s = &mut state[n];
            if a.cost < s.g {
                s.g = a.cost;
                s.parent = START;
                self.open.push(a.cost.saturating_add(s.h), a.node);
            }
        }
        // Index step of each move, so a neighbour costs an add, not a multiplication.
        let nx = lattice.nx as isize;
        let offsets = MOVES.map(|(dx, dy)| dy as isize * nx + dx as isize);
        let mut best: Option<(u32, u32)> = None;
        while let Some((f, node)) = self.open.pop() {
            if best.is_some_and(|(cost, _)| f >= cost) {
                break;
            }
            let n = node as usize;
            let s = &mut state[n];
            if s.closed {
                continue;
            }
            s.closed = true;
            let g = s.g;
            if s.target {
                let join = goals.iter().find(|a| a.node == node).map_or(0, |a| a.cost);
                let total = g.saturating_add(join);
                if best.is_none_or(|(cost, _)| total < cost) {
                    best = Some((total, node));
                }
            }
            let (i, j) = lattice.coords(n);
            let mut bits = moves[n];
            while bits != 0 {
                let d = bits.trailing_zeros() as usize;
                bits &= bits - 1;
                // Open moves stay on the lattice.
                let m = n.wrapping_add_signed(offsets[d]);
                let (dx, dy) = MOVES[d];
                fresh(
                    state,
                    m,
                    (i.wrapping_add_signed(dx), j.wrapping_add_signed(dy)),
                );
                let t = &mut state[m];
                let ng = g.saturating_add(lattice.costs[d]);
                if !t.closed && ng < t.g {
                    t.g = ng;
                    t.parent = d as u8;
                    self.open.push(ng.saturating_add(t.h), m as u32);
                }
            }
        }
        let (_, mut node) = best?;
        let mut nodes = vec![node];
        while state[node as usize].parent != START {
            let d = state[node as usize].parent as usize;
            node = (node as usize).wrapping_add_signed(-offsets[d]) as u32;
            nodes.push(node);
        }
        nodes.reverse();
        Some(nodes)
    }
}
