//! Landmark lower bounds for A* (ALT: Goldberg & Harrelson, "Computing the shortest path:
//! A* search meets graph theory", 2005).
//!
//! For a few landmark nodes the exact distance from each to every node is stored. By the
//! triangle inequality `d(n, a) ≥ |d(L, n) − d(L, a)|` for any landmark `L`, which bounds the
//! distance left far better than the octile distance does in a dungeon, where the way
//! round a wall is much longer than the straight line: A* then expands a fraction of the
//! nodes. The bound stays admissible and consistent, so paths stay optimal.
//!
//! Landmarks are chosen farthest-first (each the node farthest from those already chosen)
//! in the largest part of the graph. Closing moves only lengthens distances, so the bounds
//! stay valid; opening a move can shorten them, so then the landmarks are recomputed.

use std::cmp::Reverse;

use super::lattice::Lattice;
use super::radix_heap::RadixHeap;

/// Landmarks per radius class.
pub(crate) const LANDMARKS: usize = 8;

/// Distance of a node a landmark does not reach.
const FAR: u32 = u32::MAX;

/// Distances from each landmark, node-major (`LANDMARKS` per node, one cache line).
#[derive(Clone, Debug)]
pub(crate) struct Landmarks {
    distance: Vec<[u32; LANDMARKS]>,
}

/// A query's view of the landmarks: per landmark, the least and greatest distance of the
/// goal's nodes (those it reaches).
pub(crate) struct GoalBounds {
    bounds: [(u32, u32); LANDMARKS],
}

impl Landmarks {
    /// Landmarks in the part labelled `part` (the largest), over the open `moves`.
    pub fn build(lattice: &Lattice, moves: &[u8], parts: &[u32]) -> Self {
        let nodes = moves.len();
        let mut distance = vec![[FAR; LANDMARKS]; nodes];
        // The largest part, by its label.
        let mut sizes = std::collections::BTreeMap::new();
        for &p in parts {
            *sizes.entry(p).or_insert(0usize) += 1;
        }
        let Some((&part, _)) = sizes.iter().max_by_key(|&(&p, &size)| (size, Reverse(p))) else {
            return Self { distance };
        };
        // Farthest-first: the first landmark is the node farthest from the part's first
        // node; each next one the node whose nearest landmark is farthest.
        let mut scratch = vec![FAR; nodes];
        dijkstra(lattice, moves, part as usize, &mut scratch);
        let mut nearest = scratch.clone();
        for k in 0..LANDMARKS {
            let next = (0..nodes)
                .filter(|&n| nearest[n] != FAR)
                .max_by_key(|&n| (nearest[n], Reverse(n)))
                .unwrap_or(part as usize);
            dijkstra(lattice, moves, next, &mut scratch);
            for ((row, near), &d) in distance.iter_mut().zip(&mut nearest).zip(&scratch) {
                row[k] = d;
                *near = if k == 0 { d } else { (*near).min(d) };
            }
        }
        Self { distance }
    }

    /// The bounds for a goal joined through `goals`.
    pub fn goal_bounds(&self, goals: impl Iterator<Item = u32>) -> GoalBounds {
        let mut bounds = [(FAR, 0); LANDMARKS];
        for g in goals {
            for (b, &d) in bounds.iter_mut().zip(&self.distance[g as usize]) {
                if d != FAR {
                    *b = (b.0.min(d), b.1.max(d));
                }
            }
        }
        GoalBounds { bounds }
    }

    /// A lower bound of the distance from `node` to the nearest goal node.
    #[inline]
    pub fn lower_bound(&self, node: usize, goal: &GoalBounds) -> u32 {
        let mut best = 0;
        for (&d, &(lo, hi)) in self.distance[node].iter().zip(&goal.bounds) {
            if d == FAR || lo == FAR {
                continue;
            }
            best = best.max(d.saturating_sub(hi)).max(lo.saturating_sub(d));
        }
        best
    }
}

/// Distances from `source` over the open `moves` into `out` (Dijkstra, with a radix heap:
/// distances pop in order, so the monotone queue applies).
fn dijkstra(lattice: &Lattice, moves: &[u8], source: usize, out: &mut [u32]) {
    out.fill(FAR);
    out[source] = 0;
    let mut open = RadixHeap::default();
    open.push(0, source as u32);
    while let Some((d, node)) = open.pop() {
        let n = node as usize;
        if d > out[n] {
            continue;
        }
        for (dir, m) in lattice.neighbours(n, moves[n]) {
            let nd = d.saturating_add(lattice.costs[dir]);
            if nd < out[m] {
                out[m] = nd;
                open.push(nd, m as u32);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::ascii;
    use crate::path::clearance::Clearance;
    use crate::path::radius_class::RadiusClass;
    use crate::tiles::SegmentFlags;

    #[test]
    fn landmark_bounds_never_exceed_the_true_distance() {
        let map = ascii::parse(
            "############\n#....#.....#\n#.##.#.###.#\n#.#......#.#\n#...##.#...#\n############",
            "t.txt",
            1.0,
        )
        .unwrap();
        let table = Clearance::build(&map, 1.0, SegmentFlags::SOLID);
        let mut class = RadiusClass::build(&table, table.need(0.3));
        let (_, landmarks, moves) = class.parts(&table.lattice);
        let free: Vec<usize> = (0..moves.len()).filter(|&n| moves[n] != 0).collect();
        let mut truth = vec![0; moves.len()];
        let mut checked = 0;
        for &g in free.iter().step_by(7) {
            dijkstra(&table.lattice, moves, g, &mut truth);
            let bounds = landmarks.goal_bounds(std::iter::once(g as u32));
            for &n in &free {
                if truth[n] != FAR {
                    let bound = landmarks.lower_bound(n, &bounds);
                    assert!(bound <= truth[n], "{n} → {g}: {bound} > {}", truth[n]);
                    checked += usize::from(bound > 0);
                }
            }
        }
        assert!(checked > 100, "the bounds are not all zero: {checked}");
    }
}
