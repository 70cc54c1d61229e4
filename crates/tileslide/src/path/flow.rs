//! Flow fields: for one goal and one radius, every lattice node's distance to the goal and
//! its next move there (Dijkstra from the goal over the moves the radius can make), so any
//! number of agents sharing the goal steer by lookups instead of searches.
//!
//! An agent steers towards the farthest of the next few nodes on its way that it can reach
//! in a straight line, not towards the next node: it cuts the lattice's 45° turns and
//! never aims at a node behind a corner it would have to round, so agents moved by the
//! resolver flow around each other and corners instead of catching on them. It aims only
//! at points that every point of the line joins as well, so an agent that follows the
//! directions from a point the field reaches gets one at every step until it arrives.
//!
//! A field catches up with the map by itself ([`FlowField::sync`]): it keeps, for every node
//! it reaches, which moves into and out of the node were open, and after edits compares
//! them with the grid's near each edited cell. Only a change there (or near the goal, where
//! the goal joins the lattice) can change its distances, so only then is it recomputed.

use glam::Vec2;

use super::clearance::{incoming_moves, open_moves};
use super::lattice::MOVES;
use super::radix_heap::RadixHeap;
use super::sync::behind;
use super::{End, NavError, NavGrid, WIDE_JOIN, check_point};
use crate::geometry::Aabb;
use crate::tiles::{Cell, JournalError, MapRevision, TileMap};

/// Distance of a node the goal cannot be reached from.
pub(super) const UNREACHED: u32 = u32::MAX;
/// `next` of a node that joins the goal straight.
pub(super) const TO_GOAL: u8 = u8::MAX;
/// How many next moves an agent looks ahead along its way.
const LOOKAHEAD: usize = 8;

/// The moves out of (low byte) and into (high byte) node `n` of `nav` open for circles
/// that need clearance `need`.
fn open_moves_of(nav: &NavGrid, need: u16, n: usize) -> u16 {
    let (i, j) = nav.table.lattice.coords(n);
    let out = open_moves(&nav.table, n, i, j, need);
    u16::from(out) | u16::from(incoming_moves(&nav.table, n, i, j, need)) << 8
}

/// How a point reaches the goal of a field.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Entry {
    /// Through this node.
    Node(u32),
    /// Straight to the goal.
    Straight,
}

/// Distances to one goal for circles of one radius (see the module docs).
#[derive(Clone, Debug, PartialEq)]
pub struct FlowField {
    pub(super) goal: Vec2,
    radius: f32,
    need: u16,
    /// Per node, cost to the goal ([`UNREACHED`] if none).
    pub(super) distance: Vec<u32>,
    /// Per node, the move to take ([`TO_GOAL`]: go straight to the goal).
    pub(super) next: Vec<u8>,
    /// Map units per cost unit.
    unit: f32,
    /// Per node the field reaches, the moves open out of it (low byte) and into it (high
    /// byte) when it was filled; 0 for the others.
    open: Vec<u16>,
    /// The map's revision the field is caught up with.
    revision: MapRevision,
}

impl FlowField {
    /// The field of `goal` for circles of `radius` on `map` (whose grid is `nav`). If the
    /// circle does not fit at the goal, no node reaches it.
    pub fn new(nav: &NavGrid, map: &TileMap, goal: Vec2, radius: f32) -> Result<Self, NavError> {
        check_point("goal", goal)?;
        let need = nav.check(map, radius)?;
        let nodes = nav.table.lattice.len();
        let mut field = Self {
            goal,
            radius,
            need,
            distance: vec![UNREACHED; nodes],
            next: vec![TO_GOAL; nodes],
            unit: nav.table.lattice.unit,
            open: vec![0; nodes],
            revision: map.revision(),
        };
        field.fill(nav, map);
        Ok(field)
    }

    /// Dijkstra from the nodes that join the goal straight, along the moves into each node
    /// (one-way platforms make a move and its reverse differ: agents go from the node to
    /// the goal, the search from the goal outwards).
    fn fill(&mut self, nav: &NavGrid, map: &TileMap) {
        let table = &nav.table;
        let lattice = &table.lattice;
        self.distance.fill(UNREACHED);
        self.next.fill(TO_GOAL);
        let mut open = RadixHeap::default();
        for a in nav.attach(map, self.goal, self.radius, End::Goal, |_| true) {
            let n = a.node as usize;
            if a.cost < self.distance[n] {
                self.distance[n] = a.cost;
                open.push(a.cost, a.node);
            }
        }
        while let Some((d, node)) = open.pop() {
            let n = node as usize;
            if d > self.distance[n] {
                continue;
            }
            let (i, j) = lattice.coords(n);
            for (dir, m) in lattice.neighbours(n, incoming_moves(table, n, i, j, self.need)) {
                let nd = d.saturating_add(lattice.costs[dir]);
                if nd < self.distance[m] {
                    self.distance[m] = nd;
                    // From m, the way on is the opposite move, the one found open.
                    self.next[m] = ((dir + 4) % 8) as u8;
                    open.push(nd, m as u32);
                }
            }
        }
        let moves = |n: usize, open: &mut u16| {
            *open = if self.distance[n] == UNREACHED {
                0
            } else {
                open_moves_of(nav, self.need, n)
            };
        };
        let mut open = std::mem::take(&mut self.open);
        #[cfg(feature = "parallel")]
        {
            use rayon::prelude::*;
            // Each node's own: the same on any number of threads.
            open.par_iter_mut()
                .enumerate()
                .with_min_len(4096)
                .for_each(|(n, open)| moves(n, open));
        }
        #[cfg(not(feature = "parallel"))]
        for (n, open) in open.iter_mut().enumerate() {
            moves(n, open);
        }
        self.open = open;
    }

    /// The fields of several goals, each `(goal, radius)` as [`FlowField::new`] makes it,
    /// in order. With the `parallel` feature they are built on the threads of the current
    /// rayon pool (the global pool unless called inside `rayon::ThreadPool::install`), each
    /// the same field, bit for bit, as `new` builds; without it, one after another.
    #[must_use]
    pub fn new_many(
        nav: &NavGrid,
        map: &TileMap,
        goals: &[(Vec2, f32)],
    ) -> Vec<Result<Self, NavError>> {
        let build = |&(goal, radius): &(Vec2, f32)| Self::new(nav, map, goal, radius);
        #[cfg(feature = "parallel")]
        {
            use rayon::prelude::*;
            goals.par_iter().map(build).collect()
        }
        #[cfg(not(feature = "parallel"))]
        goals.iter().map(build).collect()
    }

    /// The moves out of (low byte) and into (high byte) node `n` open for the field's
    /// radius on `nav`.
    fn open_moves(&self, nav: &NavGrid, n: usize) -> u16 {
        open_moves_of(nav, self.need, n)
    }

    /// The goal.
    #[must_use]
    pub fn goal(&self) -> Vec2 {
        self.goal
    }

    /// The radius the field serves.
    #[must_use]
    pub fn radius(&self) -> f32 {
        self.radius
    }

    /// How `p` reaches the goal most cheaply, and the cost: through the best node it joins,
    /// or straight to the goal when that is near, clear (as [`NavGrid::find_path`] joins
    /// near ends) and cheaper. A point in front of a one-way platform, within its reach, may
    /// go on straight to a goal there while every node it joins leads back round through
    /// the platform.
    fn entry(&self, nav: &NavGrid, map: &TileMap, p: Vec2) -> Option<(u32, Entry)> {
        // Only nodes the field reaches: a point joined to nearby nodes that do not lead to
        // the goal still looks farther for ones that do.
        let reached = |n: usize| self.distance[n] != UNREACHED;
        let through = nav
            .attach(map, p, self.radius, End::Start, reached)
            .into_iter()
            .map(|a| {
                (
                    a.cost.saturating_add(self.distance[a.node as usize]),
                    Entry::Node(a.node),
                )
            })
            .min();
        let straight = nav.table.lattice.cost_of_length(p.distance(self.goal));
        if through.is_some_and(|(cost, _)| cost <= straight)
            || !nav.joins_straight(map, p, self.goal, self.radius)
        {
            return through;
        }
        Some((straight, Entry::Straight))
    }

    /// The length of the way from `p` to the goal along the field (map units), or `None`
    /// if a circle at `p` cannot reach it.
    pub fn distance(&self, nav: &NavGrid, map: &TileMap, p: Vec2) -> Result<Option<f32>, NavError> {
        self.check(nav, map, p)?;
        Ok(self
            .entry(nav, map, p)
            .map(|(cost, _)| cost as f32 * self.unit))
    }

    /// The unit direction a circle at `p` should move in to reach the goal: towards the
    /// farthest of the next few points on its way that it reaches in a straight line and
    /// that every point of the line reaches the goal through too (a node within the block
    /// `p` joins the lattice through, or the goal when it is at most 4 cells away).
    /// `None` if it cannot reach the goal or is on it.
    pub fn direction(
        &self,
        nav: &NavGrid,
        map: &TileMap,
        p: Vec2,
    ) -> Result<Option<Vec2>, NavError> {
        self.check(nav, map, p)?;
        let node = match self.entry(nav, map, p) {
            Some((_, Entry::Node(node))) => node,
            Some((_, Entry::Straight)) => return Ok((self.goal - p).try_normalize()),
            None => return Ok(None),
        };
        let lattice = &nav.table.lattice;
        let Some(need) = nav.end_clearance(map, p, self.radius) else {
            return Ok(None);
        };
        let clear = |q: Vec2| nav.table.segment_clearance(map, p, q) >= need;
        // The way on: up to LOOKAHEAD nodes, then the goal if reached; each with whether
        // every point of the line from `p` to it joins it as `entry` joins points (a node
        // `attach` tries for `p`, the goal when near), so that an agent moving along the
        // line keeps a way to the goal. Away from one-way platforms some node near the
        // agent always joins it; within reach of a platform's end, where only lines nearly
        // along its normal are clear, none may.
        let mut way = Vec::with_capacity(LOOKAHEAD + 1);
        let mut n = node as usize;
        way.push((lattice.position_of(n), true));
        while way.len() <= LOOKAHEAD {
            let d = self.next[n];
            if d == TO_GOAL {
                way.push((self.goal, NavGrid::is_near(map, p, self.goal)));
                break;
            }
            let (i, j) = lattice.coords(n);
            let (dx, dy) = MOVES[d as usize];
            let (i, j) = ((i as i32 + dx) as u32, (j as i32 + dy) as u32);
            n = lattice.index(i, j);
            way.push((lattice.position(i, j), nav.in_join_block(p, i, j)));
        }
        // The farthest point of the way the agent keeps joining, in a straight line; the
        // entry node always is.
        let target = way
            .iter()
            .rev()
            .find(|&&(q, joined)| joined && q != p && clear(q))
            .map_or(way[0].0, |&(q, _)| q);
        Ok((target - p).try_normalize())
    }

    /// A cheap unit direction for a circle at `p`: along the field's lattice moves, with no
    /// straight-line checks, for crowds of thousands that ask every step.
    ///
    /// Of the (up to four) nodes at the corners of the lattice square `p` is in, it takes
    /// the one the goal is reached from whose distance plus the length from `p` is least
    /// (ties: the lowest node index), and aims from `p` at that node's next node on the
    /// way (at the goal for the nodes that join it straight; one node further when `p` is
    /// on the next node). It costs a few array reads, where [`direction`](Self::direction)
    /// checks a dozen or more lines against the walls, but it steers along the lattice's
    /// 45° moves instead of cutting them, and it does not check that `p` reaches the node
    /// it chose in a straight line: a circle steered by it can press against a corner it
    /// should round, and relies on a resolver ([`Bodies`](crate::Bodies)) to slide it on.
    /// Where the way is one straight line along lattice moves (a corridor's middle line
    /// towards a goal on it) the two directions are the same.
    ///
    /// `None` if no node around `p` reaches the goal or `p` is on the goal.
    ///
    /// ```
    /// use tileslide::{io::ascii, FlowField, NavConfig, NavGrid, Vec2};
    ///
    /// let map = ascii::parse("\
    /// ########
    /// #......#
    /// ########", "hall.txt", 1.0)?;
    /// let nav = NavGrid::new(&map, NavConfig::default())?;
    /// let field = FlowField::new(&nav, &map, Vec2::new(6.5, 1.5), 0.3)?;
    /// let p = Vec2::new(1.5, 1.5);
    /// let cheap = field.lattice_direction(&nav, &map, p)?.unwrap();
    /// assert!(cheap.abs_diff_eq(Vec2::X, 1e-6));
    /// // Along the hall's middle line, the way is one straight run: the same direction.
    /// let full = field.direction(&nav, &map, p)?.unwrap();
    /// assert!(cheap.abs_diff_eq(full, 1e-6));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// [`NavError::NonFinite`] or [`NavError::OutOfRange`] for such a `p`;
    /// [`NavError::Stale`] when `nav` or the field has not caught up with `map`'s edits;
    /// [`NavError::OtherMap`] when `map` (or `nav`) is not the field's.
    pub fn lattice_direction(
        &self,
        nav: &NavGrid,
        map: &TileMap,
        p: Vec2,
    ) -> Result<Option<Vec2>, NavError> {
        self.check(nav, map, p)?;
        let lattice = &nav.table.lattice;
        if self.distance.len() != lattice.len() {
            return Err(NavError::OtherMap);
        }
        let base = lattice.local(p).floor();
        let mut best: Option<(u64, usize)> = None;
        for (di, dj) in [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)] {
            let (i, j) = (base.x + di, base.y + dj);
            if i < 0.0 || j < 0.0 || i >= lattice.nx as f32 || j >= lattice.ny as f32 {
                continue;
            }
            let n = lattice.index(i as u32, j as u32);
            if self.distance[n] == UNREACHED {
                continue;
            }
            let to_node = lattice.cost_of_length(p.distance(lattice.position_of(n)));
            let cost = u64::from(self.distance[n]) + u64::from(to_node);
            if best.is_none_or(|(c, _)| cost < c) {
                best = Some((cost, n));
            }
        }
        let Some((_, mut n)) = best else {
            return Ok(None);
        };
        // The node after `n` on the way, twice at most: once more when `p` is on it.
        for _ in 0..2 {
            let aim = match self.next[n] {
                TO_GOAL => return Ok((self.goal - p).try_normalize()),
                d => {
                    let (i, j) = lattice.coords(n);
                    let (dx, dy) = MOVES[usize::from(d)];
                    n = lattice.index((i as i32 + dx) as u32, (j as i32 + dy) as u32);
                    lattice.position_of(n)
                }
            };
            if let Some(dir) = (aim - p).try_normalize() {
                return Ok(Some(dir));
            }
        }
        Ok(None)
    }

    /// Catches up with `map`'s tile edits since the field was made or last synced, once
    /// `nav` has ([`NavGrid::sync`]): recomputes the field if an edit opened or closed a
    /// move into or out of a node the field reaches, or changed walls near enough to the
    /// goal to change how it joins the lattice (a goal walled in and dug out again), or if
    /// the field is more edits behind than the map remembers. Returns true when it
    /// recomputed the field: its distances and directions may then differ.
    ///
    /// # Errors
    /// [`NavError::Stale`] when `nav` has not caught up with `map`;
    /// [`NavError::OtherMap`] when `map` (or `nav`) is not the field's map.
    pub fn sync(&mut self, nav: &NavGrid, map: &TileMap) -> Result<bool, NavError> {
        nav.check(map, self.radius)?;
        let affected = match map.changes_since(&self.revision) {
            Err(JournalError::OtherMap) => return Err(NavError::OtherMap),
            Err(JournalError::Overrun { .. }) => true,
            Ok(cells) if cells.len() == 0 => return Ok(false),
            Ok(mut cells) => {
                // The goal joins nodes up to WIDE_JOIN away (`NavGrid::attach`), by lines
                // that walls within the radius and margin (less than the cap) of them block.
                let reach = nav.table.lattice.step.max_element() * WIDE_JOIN as f32;
                let joins = Aabb::from_corners(self.goal, self.goal).expand(reach + nav.table.cap);
                cells.any(|cell| {
                    // Walls change in the cell's 3 × 3 block (seam culling).
                    let corner = map.cell_corner(cell) - map.cell_size();
                    let block = Aabb::from_corners(corner, corner + 3.0 * map.cell_size());
                    block.overlaps(&joins) || self.moves_changed(nav, map, cell)
                })
            }
        };
        if affected {
            self.fill(nav, map);
        }
        self.revision = map.revision();
        Ok(affected)
    }

    /// True when a move into or out of a node the field reaches is open or closed on `nav`
    /// where it was not when the field was filled, among the moves an edit of `cell` may
    /// change (those stored at the nodes `nav` recomputes for it, which touch those nodes
    /// or their neighbours).
    fn moves_changed(&self, nav: &NavGrid, map: &TileMap, cell: Cell) -> bool {
        let lattice = &nav.table.lattice;
        let (i0, j0, i1, j1) = nav.table.cell_nodes(map, cell);
        let (i0, j0) = (i0.saturating_sub(1), j0.saturating_sub(1));
        let (i1, j1) = ((i1 + 1).min(lattice.nx - 1), (j1 + 1).min(lattice.ny - 1));
        (j0..=j1).any(|j| {
            (i0..=i1).any(|i| {
                let n = lattice.index(i, j);
                self.distance[n] != UNREACHED && self.open_moves(nav, n) != self.open[n]
            })
        })
    }

    /// Refuses `p` if not finite, and `nav` or the field if not caught up with `map`.
    fn check(&self, nav: &NavGrid, map: &TileMap, p: Vec2) -> Result<(), NavError> {
        check_point("p", p)?;
        nav.check(map, self.radius)?;
        if !map.tiles_at(&self.revision) {
            return Err(behind(map, &self.revision));
        }
        Ok(())
    }

    /// Per node: its distance and the node its next move reaches (tests check that every
    /// next move goes downhill).
    #[cfg(test)]
    pub(crate) fn downhill_pairs(&self, nav: &NavGrid) -> Vec<(u32, u32)> {
        let lattice = &nav.table.lattice;
        (0..self.distance.len())
            .filter(|&n| self.distance[n] != UNREACHED && self.next[n] != TO_GOAL)
            .map(|n| {
                let (i, j) = lattice.coords(n);
                let (dx, dy) = MOVES[self.next[n] as usize];
                let m = lattice.index((i as i32 + dx) as u32, (j as i32 + dy) as u32);
                (self.distance[n], self.distance[m])
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::ascii;
    use crate::path::NavConfig;

    #[test]
    fn every_next_move_goes_downhill() {
        let map = ascii::parse(
            "##########\n#....#...#\n#.##.#.#.#\n#.#....#.#\n#...##...#\n##########",
            "t.txt",
            1.0,
        )
        .unwrap();
        let nav = NavGrid::new(&map, NavConfig::default()).unwrap();
        let field = FlowField::new(&nav, &map, Vec2::new(8.5, 4.5), 0.3).unwrap();
        let pairs = field.downhill_pairs(&nav);
        assert!(pairs.len() > 40, "{}", pairs.len());
        assert!(pairs.iter().all(|&(here, there)| there < here));
    }

    #[test]
    fn lattice_direction_is_none_in_a_wall_and_on_the_goal_and_follows_the_bend() {
        let map = ascii::parse("#####\n#...#\n###.#\n#####", "bend.txt", 1.0).unwrap();
        let nav = NavGrid::new(&map, NavConfig::default()).unwrap();
        let goal = Vec2::new(3.5, 2.5);
        let field = FlowField::new(&nav, &map, goal, 0.3).unwrap();
        let at = |x: f32, y: f32| {
            field
                .lattice_direction(&nav, &map, Vec2::new(x, y))
                .unwrap()
        };
        assert_eq!(at(0.5, 0.5), None, "inside a wall");
        assert_eq!(at(goal.x, goal.y), None, "on the goal");
        // Along the top row towards the bend, then down it.
        let near = |d: Option<Vec2>, want: Vec2| d.is_some_and(|d| d.abs_diff_eq(want, 1e-6));
        assert!(near(at(1.5, 1.5), Vec2::X), "{:?}", at(1.5, 1.5));
        assert!(near(at(3.5, 1.6), Vec2::Y), "{:?}", at(3.5, 1.6));
    }

    #[test]
    fn lattice_direction_refuses_a_point_that_is_not_finite() {
        let map = ascii::parse("####\n#..#\n####", "t.txt", 1.0).unwrap();
        let nav = NavGrid::new(&map, NavConfig::default()).unwrap();
        let field = FlowField::new(&nav, &map, Vec2::new(2.5, 1.5), 0.3).unwrap();
        let nan = Vec2::new(f32::NAN, 1.5);
        assert!(matches!(
            field.lattice_direction(&nav, &map, nan),
            Err(NavError::NonFinite { what: "p", .. })
        ));
    }
}
