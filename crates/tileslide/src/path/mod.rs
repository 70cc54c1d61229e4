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
//! - [`NavGrid::update`] brings the grid up to date after a tile edit, recomputing only the
//!   moves near the edited cell, and returns a [`NavChange`] that tells which paths and
//!   fields the edit affects.
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
//! let change = nav.update(&map, tileslide::Cell::new(4, 2))?;
//! // It opens a way right beside the path: the path may no longer be the best one.
//! assert!(path.is_affected_by(&change));
//! let up = nav.find_path(&map, Vec2::new(4.5, 3.5), Vec2::new(4.5, 1.5), 0.4)?.unwrap();
//! assert!((up.length() - 2.0).abs() < 1e-4);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod clearance;
mod flow;
mod landmarks;
mod lattice;
mod radius_class;
mod radix_heap;
mod search;
mod smooth;

use glam::Vec2;
use thiserror::Error;

pub use flow::FlowField;

use crate::geometry::Aabb;
use crate::tiles::{Cell, SegmentFlags, TileMap};
use clearance::{ChangedMove, Clearance};
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

/// What a navigation call refuses.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum NavError {
    /// `max_radius` is not positive and finite, or too large for the cell size.
    #[error("max_radius {max_radius} must be positive, finite and at most {limit} (31 cells)")]
    BadMaxRadius {
        /// The value given.
        max_radius: f32,
        /// The largest allowed for this map.
        limit: f32,
    },
    /// The map has more lattice nodes than [`MAX_NAV_NODES`].
    #[error("a {width} × {height} map has {nodes} navigation nodes, more than {MAX_NAV_NODES}")]
    TooLarge {
        /// Map width in cells.
        width: u32,
        /// Map height in cells.
        height: u32,
        /// Its lattice nodes.
        nodes: u64,
    },
    /// The map reaches so far from (0, 0) that `f32` coordinates there are farther apart
    /// than the grid's margin (1/1000 of a cell), so clearances cannot keep it.
    #[error(
        "the map reaches {corner}, where coordinates are {spacing} apart, more than the navigation grid's margin {margin} (1/1000 of a cell): move its origin nearer (0, 0)"
    )]
    TooFar {
        /// The map's corner farthest from (0, 0).
        corner: Vec2,
        /// The spacing of `f32` values there (map units).
        spacing: f32,
        /// The grid's margin (map units).
        margin: f32,
    },
    /// A radius that is not positive and finite, or above the grid's `max_radius`.
    #[error(
        "radius {radius} must be positive, finite and at most the grid's max_radius {max_radius}"
    )]
    BadRadius {
        /// The radius asked for.
        radius: f32,
        /// The grid's `max_radius`.
        max_radius: f32,
    },
    /// A point with a NaN or infinite coordinate.
    #[error("the {what} point {point} is not finite")]
    NonFinite {
        /// Which point (`from`, `to`, `goal`, …).
        what: &'static str,
        /// Its value.
        point: Vec2,
    },
    /// A point with a coordinate beyond [`MAX_COORD`](crate::MAX_COORD) in magnitude.
    #[error("the {what} point {point} is beyond the ±{max} coordinate range (MAX_COORD)", max = crate::MAX_COORD)]
    OutOfRange {
        /// Which point (`from`, `to`, `goal`, …).
        what: &'static str,
        /// Its value.
        point: Vec2,
    },
    /// The map is not the one the grid was built for, or its tiles changed since without
    /// [`NavGrid::update`].
    #[error(
        "the navigation grid is out of date: the map's tiles changed since it was built or updated (call NavGrid::update after each edit)"
    )]
    Stale,
    /// A cell outside the map.
    #[error("cell ({}, {}) is outside the map", .0.col, .0.row)]
    CellOutside(Cell),
}

/// Refuses a point that is not finite or lies beyond [`MAX_COORD`](crate::MAX_COORD):
/// lattice coordinates of such a point overflow the integers nodes are counted in.
pub(crate) fn check_point(what: &'static str, point: Vec2) -> Result<(), NavError> {
    if !point.is_finite() {
        Err(NavError::NonFinite { what, point })
    } else if !crate::geometry::in_range(point) {
        Err(NavError::OutOfRange { what, point })
    } else {
        Ok(())
    }
}

/// Navigation data for one map: move clearances on a half-cell lattice and search scratch.
#[derive(Clone, Debug)]
pub struct NavGrid {
    table: Clearance,
    max_radius: f32,
    search: Search,
    /// Moves and parts per radius class, most recently used last.
    classes: Vec<RadiusClass>,
    /// The map's tiles revision this grid last matched.
    tiles_revision: u64,
    /// Cells updated since then, sorted, while other edits are still to come (see
    /// `update`).
    updated: Vec<Cell>,
    size: (u32, u32),
}

/// A path found by [`NavGrid::find_path`]: straight runs from the start point to the goal
/// point, each clear for the radius it was found for.
#[derive(Clone, Debug, PartialEq)]
pub struct Path {
    points: Vec<Vec2>,
    length: f32,
    radius: f32,
    /// Clearance steps the radius needs (for [`Path::is_affected_by`]).
    need: u16,
    bounds: Aabb,
}

impl Path {
    fn new(points: Vec<Vec2>, radius: f32, need: u16) -> Self {
        let length = points.windows(2).map(|w| w[0].distance(w[1])).sum();
        let mut bounds = Aabb::from_corners(points[0], points[0]);
        for &p in &points {
            bounds = bounds.union(&Aabb::from_corners(p, p));
        }
        Self {
            points,
            length,
            radius,
            need,
            bounds: bounds.expand(radius),
        }
    }

    /// The corners, from the start point to the goal point.
    #[must_use]
    pub fn points(&self) -> &[Vec2] {
        &self.points
    }

    /// Total length (map units).
    #[must_use]
    pub fn length(&self) -> f32 {
        self.length
    }

    /// The radius the path was found for.
    #[must_use]
    pub fn radius(&self) -> f32 {
        self.radius
    }

    /// True when `change` may have blocked this path or opened a shorter way near it: a
    /// move within reach of the path opened or closed for its radius. Far-away edits and
    /// edits that only change clearances no circle of this radius notices do not affect it.
    #[must_use]
    pub fn is_affected_by(&self, change: &NavChange) -> bool {
        change.region.is_some_and(|r| r.overlaps(&self.bounds))
            && change.flips_for(self.need, |_| true)
    }
}

/// What a tile edit changed in a [`NavGrid`] (from [`NavGrid::update`]).
#[derive(Clone, Debug, PartialEq)]
pub struct NavChange {
    moves: Vec<ChangedMove>,
    /// The moves' extent (map units), `None` if nothing changed.
    region: Option<Aabb>,
    /// Where walls may have changed: the edited cell's 3 × 3 block (seam culling changes
    /// the segments of its neighbours too).
    edited: Aabb,
}

impl NavChange {
    /// True when no move's clearance changed.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.moves.is_empty()
    }

    /// The region whose moves changed, if any.
    #[must_use]
    pub fn region(&self) -> Option<Aabb> {
        self.region
    }

    /// Number of moves whose clearance changed.
    #[must_use]
    pub fn changed_moves(&self) -> usize {
        self.moves.len()
    }

    /// True when some move from a node `node_filter` accepts opened or closed for a circle
    /// needing `need` clearance steps.
    fn flips_for(&self, need: u16, mut touches: impl FnMut(&ChangedMove) -> bool) -> bool {
        self.moves
            .iter()
            .any(|m| (m.before >= need) != (m.after >= need) && touches(m))
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
            search: Search::default(),
            classes: Vec::new(),
            tiles_revision: map.tiles_revision(),
            updated: Vec::new(),
            size: (map.width(), map.height()),
        })
    }

    /// The widest circle this grid serves.
    #[must_use]
    pub fn max_radius(&self) -> f32 {
        self.max_radius
    }

    /// Brings the grid up to date after `map.set_tile(cell, …)` (or `clear_tile`), in time
    /// independent of the map's size. Call it once per edited cell, in any order; the grid
    /// is then what [`NavGrid::new`] would build.
    ///
    /// The grid checks the map's record of its latest edits: until every cell edited since
    /// the grid was last current has been updated, queries refuse with
    /// [`NavError::Stale`]. So does a grid more than 4,096 edits behind, or used with
    /// another map: build it anew then.
    pub fn update(&mut self, map: &TileMap, cell: Cell) -> Result<NavChange, NavError> {
        if (map.width(), map.height()) != self.size
            || map.cell_size() * 0.5 != self.table.lattice.step
        {
            return Err(NavError::Stale);
        }
        if cell.col >= map.width() || cell.row >= map.height() {
            return Err(NavError::CellOutside(cell));
        }
        let moves = self.table.update_cell(map, cell);
        for class in &mut self.classes {
            class.apply(&self.table, &moves);
        }
        self.note_updated(map, cell);
        let lattice = &self.table.lattice;
        let region = moves.iter().fold(None, |acc: Option<Aabb>, m| {
            let p = lattice.position_of(m.node as usize);
            let q = p + lattice.step
                * Vec2::new(
                    lattice::MOVES[m.dir as usize].0 as f32,
                    lattice::MOVES[m.dir as usize].1 as f32,
                );
            let b = Aabb::from_corners(p, q);
            Some(acc.map_or(b, |a| a.union(&b)))
        });
        let corner =
            |c: i64, r: i64| map.origin() + Vec2::new(c as f32, r as f32) * map.cell_size();
        let (c, r) = (i64::from(cell.col), i64::from(cell.row));
        let edited = Aabb::from_corners(corner(c - 1, r - 1), corner(c + 2, r + 2));
        Ok(NavChange {
            moves,
            region,
            edited,
        })
    }

    /// Records that `cell` is up to date, and the grid current if that was the last
    /// edited cell not yet updated.
    fn note_updated(&mut self, map: &TileMap, cell: Cell) {
        // Sorted, so checking a batch of edits costs k log k, not k².
        if let Err(at) = self.updated.binary_search(&cell) {
            self.updated.insert(at, cell);
        }
        let Some(mut edits) = map.edits_since(self.tiles_revision) else {
            return;
        };
        if edits.all(|c| self.updated.binary_search(&c).is_ok()) {
            self.tiles_revision = map.tiles_revision();
            self.updated.clear();
        }
    }

    pub(crate) fn check(&self, map: &TileMap, radius: f32) -> Result<u16, NavError> {
        if map.tiles_revision() != self.tiles_revision {
            return Err(NavError::Stale);
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

    /// True when `from` and `to` are near (at most [`NEAR_CELLS`] apart) and a circle of
    /// `radius` goes from one to the other in a straight line, clear as both ends need.
    pub(crate) fn joins_straight(&self, map: &TileMap, from: Vec2, to: Vec2, radius: f32) -> bool {
        if from.distance(to) > NEAR_CELLS * map.cell_size().min_element() {
            return false;
        }
        let ends = self
            .end_clearance(map, from, radius)
            .zip(self.end_clearance(map, to, radius))
            .map(|(a, b)| a.min(b));
        ends.is_some_and(|e| self.table.segment_clearance(map, from, to) >= e)
    }

    /// The nodes around `p` a circle of `radius` reaches from `p` in a straight line (or,
    /// for a goal, reaches `p` from), with the line's cost; empty if the circle does not
    /// fit at `p`.
    ///
    /// The nodes of the 4 × 4 block around `p`, or if it reaches none of those, of the
    /// block [`WIDE_JOIN`] nodes each way: a circle just behind a one-way platform, near
    /// its end, goes on through the platform only nearly straight along its normal (any
    /// other line closes in on the end in front of it), where the nearest node may be a
    /// few cells away.
    pub(crate) fn attach(&self, map: &TileMap, p: Vec2, radius: f32, end: End) -> Vec<Attach> {
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

    /// The shortest path this grid finds for a circle of `radius` from `from` to `to`,
    /// smoothed into straight runs; `None` when the circle does not fit at either end or
    /// cannot get from one to the other. Every run is clear by the map's circle cast with
    /// `radius`, so a body following it never touches a wall.
    pub fn find_path(
        &mut self,
        map: &TileMap,
        from: Vec2,
        to: Vec2,
        radius: f32,
    ) -> Result<Option<Path>, NavError> {
        check_point("from", from)?;
        check_point("to", to)?;
        let need = self.check(map, radius)?;
        let starts = self.attach(map, from, radius, End::Start);
        let goals = self.attach(map, to, radius, End::Goal);
        if starts.is_empty() || goals.is_empty() {
            return Ok(None);
        }
        // Near ends joined straight: no search needed.
        if self.joins_straight(map, from, to, radius) {
            return Ok(Some(Path::new(vec![from, to], radius, need)));
        }
        let k = self.class(need);
        let class = &mut self.classes[k];
        let lattice = &self.table.lattice;
        let (parts, landmarks, moves) = class.parts(lattice);
        let joined = starts.iter().any(|s| {
            goals
                .iter()
                .any(|g| parts[s.node as usize] == parts[g.node as usize])
        });
        if !joined {
            return Ok(None);
        }
        let Some(nodes) = self.search.find(lattice, moves, landmarks, &starts, &goals) else {
            return Ok(None);
        };
        let lattice = &self.table.lattice;
        let mut points = Vec::with_capacity(nodes.len() + 2);
        points.push(from);
        points.extend(nodes.iter().map(|&n| lattice.position_of(n as usize)));
        points.push(to);
        let smoothed = smooth::smooth(map, &points, radius, &self.table);
        Ok(Some(Path::new(smoothed, radius, need)))
    }

    /// The index in `classes` of the radius class `need`, built on first use.
    fn class(&mut self, need: u16) -> usize {
        match self.classes.iter().position(|c| c.need == need) {
            Some(k) => {
                let class = self.classes.remove(k);
                self.classes.push(class);
            }
            None => {
                if self.classes.len() == CACHED_CLASSES {
                    self.classes.remove(0);
                }
                self.classes.push(RadiusClass::build(&self.table, need));
            }
        }
        self.classes.len() - 1
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
