//! Pathfinding for circles of any radius, and flow fields for crowds.
//!
//! A [`NavGrid`] is built from a map once: for every move between neighbouring nodes of a
//! half-cell lattice it stores how wide a circle can make the move, measured against the
//! map's actual segments (ramps and partial tiles included, see `clearance`). Then:
//! - [`NavGrid::find_path`] runs A* for a circle of radius `r` (8 directions; a diagonal
//!   move is allowed only if the circle clears the corner) between any two points and
//!   smooths the result into straight runs, each checked with the map's circle cast;
//!   one-way platforms are directed edges: a path crosses one only from behind, moving the
//!   way its normal points, as the resolver lets a body through;
//! - [`FlowField`] holds, for one goal and one radius, every node's distance to the goal
//!   and the way there, for crowds that share the goal;
//! - [`NavGrid::sync`] catches the grid up with the map's edits (read from the map's edit
//!   journal, [`TileMap::changes_since`]), recomputing only the moves near each edited
//!   cell, and returns a [`NavChange`] that tells which paths the edits affect;
//!   [`FlowField::sync`] does the same for a field, which recomputes itself only when an
//!   edit changed its way.
//!
//! Nothing has to be told which cells changed, and a grid or field is never used with a map
//! it was not built for: it refuses with [`NavError::OtherMap`].
//!
//! ```
//! use tileslide::{io::ascii, NavConfig, NavGrid, Vec2};
//! let mut map = ascii::parse("\
//! ##########
//! #........#
//! #.######.#
//! #........#
//! ##########", "doc.txt", 1.0)?;
//! let mut nav = NavGrid::new(&map, NavConfig::default())?;
//! // From the bottom-left corridor to the bottom right: straight along the corridor.
//! let path = nav.find_path(&map, Vec2::new(1.5, 3.5), Vec2::new(8.5, 3.5), 0.4)?.unwrap();
//! assert_eq!(path.points(), &[Vec2::new(1.5, 3.5), Vec2::new(8.5, 3.5)]);
//! // Too wide for the one-cell corridors: no path.
//! assert!(nav.find_path(&map, Vec2::new(1.5, 3.5), Vec2::new(8.5, 1.5), 0.6)?.is_none());
//! // Dig out the middle: the way from the top corridor to the bottom one gets shorter.
//! map.clear_tile(tileslide::Cell::new(4, 2))?;
//! let change = nav.sync(&map)?;
//! // It opens a way right beside the path: the path may no longer be the best one.
//! assert!(path.is_affected_by(&change));
//! let up = nav.find_path(&map, Vec2::new(4.5, 3.5), Vec2::new(4.5, 1.5), 0.4)?.unwrap();
//! assert!((up.length() - 2.0).abs() < 1e-4);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod clearance;
mod debug_lines;
mod error;
mod flow;
mod landmarks;
mod lattice;
mod radius_class;
mod radix_heap;
mod route;
mod search;
mod smooth;
mod sync;

use std::sync::{Mutex, MutexGuard, PoisonError};

use glam::Vec2;

pub use error::NavError;
pub(crate) use error::check_point;
pub use flow::FlowField;
pub use route::NavPath;
pub use sync::NavChange;

use crate::tiles::{MapRevision, SegmentFlags, TileMap};
use clearance::Clearance;
use radius_class::RadiusClass;
use search::{Attach, Search};

/// The share of the grid's margin an end point must be clear of walls by (see
/// [`NavGrid::end_clearance`]).
const END_MARGIN: f32 = 0.25;

/// End points at most this many cells apart are joined straight when the line is clear.
const NEAR_CELLS: f32 = 4.0;

/// Nodes each way of the wider block an end point joins the lattice through when it joins
/// none of the 4 × 4 block around it (see [`NavGrid::attach`]): 4 cells.
const WIDE_JOIN: i64 = 8;

/// Radius classes a grid keeps moves and parts for (the least recently used goes first).
const CACHED_CLASSES: usize = 8;

/// The eight lattice moves as (di, dj) node steps, in the order of the bits of
/// [`NavGrid::open_moves`]: moves `d` and `d + 4` are opposite.
pub const NAV_MOVES: [(i32, i32); 8] = lattice::MOVES;

/// Most lattice nodes a navigation grid takes (about a 4,096 × 4,096-cell map). A grid
/// keeps about 30 bytes a node (clearances each way and search scratch), and 37 more for
/// each radius class searched (moves, parts and landmark distances), so a 256 × 256 map
/// takes about 8 MB, plus 10 MB a radius.
pub const MAX_NAV_NODES: usize = 1 << 26;

/// How a [`NavGrid`] is built.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NavConfig {
    /// The widest circle the grid serves (map units). Clearances are measured up to this,
    /// so building costs more for larger values. At most 31 of the map's shorter cell side.
    pub max_radius: f32,
    /// Segments with one of these flags block. Those with the `ONE_WAY` flag block only
    /// from their front, as the resolver's do: a path crosses a one-way platform only from
    /// behind, moving the way its normal points (up through a floor platform, never down).
    pub mask: SegmentFlags,
}

impl Default for NavConfig {
    /// Circles up to one cell (of a unit-cell map) wide; solid segments and one-way
    /// platforms block.
    fn default() -> Self {
        Self {
            max_radius: 1.0,
            mask: SegmentFlags::SOLID | SegmentFlags::ONE_WAY,
        }
    }
}

/// Which end of a way a point is, so which way the line joining it to the lattice runs
/// (one-way platforms let it through one way only).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum End {
    /// The way starts here: lines run from the point to the lattice.
    Start,
    /// The way ends here: lines run from the lattice to the point.
    Goal,
}

/// Navigation data for one map: move clearances on a half-cell lattice, and what the
/// searches remember between queries.
///
/// Queries take `&self`, so one grid serves every agent of a game (and a Bevy resource
/// read by several systems). Searches on one grid from several threads at once take
/// turns; a clone of the grid per thread runs them side by side.
#[derive(Debug)]
pub struct NavGrid {
    table: Clearance,
    max_radius: f32,
    /// What searches remember between queries, behind a lock so that a search needs only
    /// `&self`: it is held for one search, never across calls.
    memory: Mutex<SearchMemory>,
    /// The map's revision the grid is caught up with (see [`NavGrid::sync`]).
    revision: MapRevision,
}

/// What a grid's searches remember between queries: the search scratch, and the moves and
/// parts per radius class.
#[derive(Clone, Debug, Default)]
struct SearchMemory {
    search: Search,
    /// Moves and parts per radius class, most recently used last.
    classes: Vec<RadiusClass>,
}

impl SearchMemory {
    /// The index in `classes` of the radius class `need`, built on first use (the least
    /// recently used of [`CACHED_CLASSES`] goes first).
    fn class_in(classes: &mut Vec<RadiusClass>, table: &Clearance, need: u16) -> usize {
        match classes.iter().position(|c| c.need == need) {
            Some(k) => {
                let class = classes.remove(k);
                classes.push(class);
            }
            None => {
                if classes.len() == CACHED_CLASSES {
                    classes.remove(0);
                }
                classes.push(RadiusClass::build(table, need));
            }
        }
        classes.len() - 1
    }
}

impl Clone for NavGrid {
    fn clone(&self) -> Self {
        Self {
            table: self.table.clone(),
            max_radius: self.max_radius,
            memory: Mutex::new(self.memory().clone()),
            revision: self.revision.clone(),
        }
    }
}

impl NavGrid {
    /// The navigation grid of `map` for circles up to `config.max_radius`.
    pub fn new(map: &TileMap, config: NavConfig) -> Result<Self, NavError> {
        let limit = map.cell_size().min_element() * 31.0;
        if !(config.max_radius > 0.0 && config.max_radius <= limit) {
            return Err(NavError::BadMaxRadius {
                max_radius: config.max_radius,
                limit,
            });
        }
        // The corner farthest from (0, 0): float spacing grows with the magnitude.
        let bounds = map.bounds();
        let far = |a: f32, b: f32| if b.abs() >= a.abs() { b } else { a };
        let corner = Vec2::new(
            far(bounds.min.x, bounds.max.x),
            far(bounds.min.y, bounds.max.y),
        );
        let largest = corner.abs().max_element();
        let spacing = largest.next_up() - largest;
        let margin = map.cell_size().min_element() * clearance::MARGIN_PER_CELL;
        if spacing > margin {
            return Err(NavError::TooFar {
                corner,
                spacing,
                margin,
            });
        }
        let nodes = (2 * u64::from(map.width()) + 1) * (2 * u64::from(map.height()) + 1);
        if nodes > MAX_NAV_NODES as u64 {
            return Err(NavError::TooLarge {
                width: map.width(),
                height: map.height(),
                nodes,
            });
        }
        Ok(Self {
            table: Clearance::build(map, config.max_radius, config.mask),
            max_radius: config.max_radius,
            memory: Mutex::new(SearchMemory::default()),
            revision: map.revision(),
        })
    }

    /// The searches' memory. A search that panicked (a bug) leaves it as any search
    /// leaves it between steps, so a poisoned lock is taken as it is.
    fn memory(&self) -> MutexGuard<'_, SearchMemory> {
        self.memory.lock().unwrap_or_else(PoisonError::into_inner)
    }

    /// The searches' memory, when the grid is borrowed mutably (no lock needed).
    fn memory_mut(&mut self) -> &mut SearchMemory {
        self.memory
            .get_mut()
            .unwrap_or_else(PoisonError::into_inner)
    }

    /// The widest circle this grid serves.
    #[must_use]
    pub fn max_radius(&self) -> f32 {
        self.max_radius
    }

    /// The clearance steps a circle of `radius` needs, once the grid is known to be
    /// caught up with `map` ([`NavError::Stale`] or [`NavError::OtherMap`] if not).
    pub(crate) fn check(&self, map: &TileMap, radius: f32) -> Result<u16, NavError> {
        if !map.tiles_at(&self.revision) {
            return Err(sync::behind(map, &self.revision));
        }
        if !(radius > 0.0 && radius <= self.max_radius) {
            return Err(NavError::BadRadius {
                radius,
                max_radius: self.max_radius,
            });
        }
        Ok(self.table.need(radius))
    }

    /// How clear of walls a straight line from the end point `p` must stay for a circle of
    /// `radius`, or `None` if the circle does not fit at `p`.
    ///
    /// Lattice moves keep the grid's whole margin from walls, but end points are where
    /// bodies are, and the resolver leaves a body closer than that to a wall it was pushed
    /// against (`ResolveConfig::gap`). So an end point fits when it is clear of walls by a
    /// quarter of the margin ([`END_MARGIN`]), and a line from it must stay clear by the
    /// margin or, if `p` itself is closer, by `p`'s own clearance less an eighth of the
    /// margin: it may run along the wall or away from it, never towards it. Either way it
    /// stays more than the radius from every wall, so the circle cast finds it clear.
    pub(crate) fn end_clearance(&self, map: &TileMap, p: Vec2, radius: f32) -> Option<f32> {
        let margin = self.table.margin;
        let own = self.table.segment_clearance(map, p, p);
        (own >= radius + margin * END_MARGIN)
            .then(|| (radius + margin).min(own - margin * END_MARGIN * 0.5))
    }

    /// True when `a` and `b` are near enough (at most [`NEAR_CELLS`] apart) to be joined
    /// straight ([`joins_straight`](Self::joins_straight)).
    pub(crate) fn is_near(map: &TileMap, a: Vec2, b: Vec2) -> bool {
        a.distance(b) <= NEAR_CELLS * map.cell_size().min_element()
    }

    /// True when `from` and `to` are near (at most [`NEAR_CELLS`] apart) and a circle of
    /// `radius` goes from one to the other in a straight line, clear as both ends need.
    pub(crate) fn joins_straight(&self, map: &TileMap, from: Vec2, to: Vec2, radius: f32) -> bool {
        if !Self::is_near(map, from, to) {
            return false;
        }
        let ends = self
            .end_clearance(map, from, radius)
            .zip(self.end_clearance(map, to, radius))
            .map(|(a, b)| a.min(b));
        ends.is_some_and(|e| self.table.segment_clearance(map, from, to) >= e)
    }

    /// The nodes around `p` that `usable` accepts and a circle of `radius` reaches from `p`
    /// in a straight line (or, for a goal, reaches `p` from), with the line's cost; empty
    /// if the circle does not fit at `p`.
    ///
    /// The nodes of the 4 × 4 block around `p`, or if it reaches none of those, of the
    /// block [`WIDE_JOIN`] nodes each way: a circle just behind a one-way platform, near
    /// its end, goes on through the platform only nearly straight along its normal (any
    /// other line closes in on the end in front of it), where the nearest node may be a
    /// few cells away.
    pub(crate) fn attach(
        &self,
        map: &TileMap,
        p: Vec2,
        radius: f32,
        end: End,
        usable: impl Fn(usize) -> bool,
    ) -> Vec<Attach> {
        let lattice = &self.table.lattice;
        let Some(need) = self.end_clearance(map, p, radius) else {
            return Vec::new();
        };
        let base = lattice.local(p).floor();
        let (bi, bj) = (base.x as i64, base.y as i64);
        let near = |d: i64| (-1..=2).contains(&d);
        let mut out = Vec::new();
        for span in [2, WIDE_JOIN] {
            for dj in 1 - span..=span {
                for di in 1 - span..=span {
                    let (i, j) = (bi + di, bj + dj);
                    if (span != 2 && near(di) && near(dj))
                        || i < 0
                        || j < 0
                        || i >= i64::from(lattice.nx)
                        || j >= i64::from(lattice.ny)
                        || !usable(lattice.index(i as u32, j as u32))
                    {
                        continue;
                    }
                    let q = lattice.position(i as u32, j as u32);
                    let (a, b) = match end {
                        End::Start => (p, q),
                        End::Goal => (q, p),
                    };
                    if self.table.segment_clearance(map, a, b) >= need {
                        out.push(Attach {
                            node: lattice.index(i as u32, j as u32) as u32,
                            cost: lattice.cost_of_length(p.distance(q)),
                        });
                    }
                }
            }
            if !out.is_empty() {
                break;
            }
        }
        out
    }

    /// True when node (`i`, `j`) is among the nodes [`attach`](Self::attach) tries for
    /// `p` (the block [`WIDE_JOIN`] nodes each way). Then it is among those it tries for
    /// every point of the line from `p` to the node too: along the line each coordinate
    /// only nears the node's.
    pub(crate) fn in_join_block(&self, p: Vec2, i: u32, j: u32) -> bool {
        let base = self.table.lattice.local(p).floor();
        let within = |node: u32, b: f32| {
            let d = i64::from(node) - b as i64;
            (1 - WIDE_JOIN..=WIDE_JOIN).contains(&d)
        };
        within(i, base.x) && within(j, base.y)
    }

    /// The shortest path this grid finds for a circle of `radius` from `from` to `to`,
    /// smoothed into straight runs; `None` when the circle does not fit at either end or
    /// cannot get from one to the other. Every run is clear by the map's circle cast with
    /// `radius`, so a body following it never touches a wall.
    ///
    /// The map is asked for because the grid answers only when it is caught up with it
    /// ([`NavError::Stale`] until [`sync`](Self::sync), [`NavError::OtherMap`] for
    /// another map): a path is never found on tiles that have changed since.
    pub fn find_path(
        &self,
        map: &TileMap,
        from: Vec2,
        to: Vec2,
        radius: f32,
    ) -> Result<Option<NavPath>, NavError> {
        check_point("from", from)?;
        check_point("to", to)?;
        let need = self.check(map, radius)?;
        let starts = self.attach(map, from, radius, End::Start, |_| true);
        let goals = self.attach(map, to, radius, End::Goal, |_| true);
        if starts.is_empty() || goals.is_empty() {
            return Ok(None);
        }
        // Near ends joined straight: no search needed.
        if self.joins_straight(map, from, to, radius) {
            return Ok(Some(NavPath::new(vec![from, to], radius, need)));
        }
        let mut memory = self.memory();
        let SearchMemory { search, classes } = &mut *memory;
        let k = SearchMemory::class_in(classes, &self.table, need);
        let lattice = &self.table.lattice;
        let (parts, landmarks, moves) = classes[k].parts(lattice);
        let joined = starts.iter().any(|s| {
            goals
                .iter()
                .any(|g| parts[s.node as usize] == parts[g.node as usize])
        });
        if !joined {
            return Ok(None);
        }
        let Some(nodes) = search.find(lattice, moves, landmarks, &starts, &goals) else {
            return Ok(None);
        };
        drop(memory);
        let lattice = &self.table.lattice;
        let mut points = Vec::with_capacity(nodes.len() + 2);
        points.push(from);
        points.extend(nodes.iter().map(|&n| lattice.position_of(n as usize)));
        points.push(to);
        let smoothed = smooth::smooth(map, &points, radius, &self.table);
        Ok(Some(NavPath::new(smoothed, radius, need)))
    }

    /// Lattice nodes per row and per column (`2 · width + 1`, `2 · height + 1`): a node
    /// every half cell, on every cell corner, edge midpoint and centre.
    #[must_use]
    pub fn nodes(&self) -> (u32, u32) {
        (self.table.lattice.nx, self.table.lattice.ny)
    }

    /// Where node (`i`, `j`) is: the map's origin plus (`i`, `j`) half cells.
    #[must_use]
    pub fn node_position(&self, i: u32, j: u32) -> Vec2 {
        self.table.lattice.position(i, j)
    }

    /// The cost the searches give move `d` of [`NAV_MOVES`]: its length in units of 1/1024
    /// of the shorter half-cell side, rounded.
    #[must_use]
    pub fn move_cost(&self, d: usize) -> u32 {
        self.table.lattice.costs[d % 8]
    }

    /// The moves (bit `d` for move `d` of [`NAV_MOVES`]) a circle of `radius` can make
    /// from node (`i`, `j`) without coming nearer a wall than its radius plus the grid's
    /// margin: the graph every search here runs on. 0 for a node off the lattice.
    pub fn open_moves(&self, map: &TileMap, i: u32, j: u32, radius: f32) -> Result<u8, NavError> {
        let need = self.check(map, radius)?;
        let lattice = &self.table.lattice;
        if i >= lattice.nx || j >= lattice.ny {
            return Ok(0);
        }
        Ok(clearance::open_moves(
            &self.table,
            lattice.index(i, j),
            i,
            j,
            need,
        ))
    }

    /// True when a circle of `radius` fits at `p`: clear of walls by a quarter of the
    /// grid's margin (2.5·10⁻⁴ of a cell), which takes in every place the resolver leaves
    /// a body of that radius (at least half its default gap, 5·10⁻⁴ of a cell, from walls).
    pub fn fits(&self, map: &TileMap, p: Vec2, radius: f32) -> Result<bool, NavError> {
        check_point("p", p)?;
        self.check(map, radius)?;
        Ok(self.end_clearance(map, p, radius).is_some())
    }
}
