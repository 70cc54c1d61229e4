//! The pathfinding benchmark: random queries between free nodes of the navigation lattice
//! of dungeon256, answered by tileslide's [`NavGrid::find_path`] and by a generic A* on the
//! same graph, for two radii.
//!
//! The scene ("paths"; not in BENCHMARKS.md yet):
//!
//! - the map is dungeon256 ([`dungeon256`]), its [`NavGrid`] built with
//!   [`NavConfig::default`] (circles up to 1 cell);
//! - for each radius `r` of [`PATHS_RADII`], the *free* nodes are the lattice nodes, in
//!   index order (`j · nx + i`), from which a circle of radius `r` can make at least one
//!   move ([`NavGrid::open_moves`] not 0);
//! - a fresh [`SplitMix64`] seeded with [`PATHS_SEED`] draws each query as
//!   `(free[below(len)], free[below(len)])`, start then goal; the query's points are the
//!   two nodes' positions ([`NavGrid::node_position`]).
//!
//! A contender implements [`PathContender`]; [`run_paths`] answers every query of one radius
//! with it in one timed loop. The contenders:
//!
//! - [`TileslidePaths`]: [`NavGrid::find_path`] between the two points, A* on the lattice
//!   and smoothing into straight runs (each checked by a circle cast), timed together;
//! - [`PathfindingAstar`]: the `pathfinding` crate's `astar` on the same graph (the moves
//!   [`NavGrid::open_moves`] allows, precomputed for every node before timing, with the
//!   grid's integer [`move costs`](NavGrid::move_cost) and an octile heuristic), returning
//!   the lattice path without smoothing.
//!
//! The peer answers an easier question (no smoothing, no circle casts, the graph handed to
//! it as a table), so its lengths are the lattice paths' (longer than tileslide's smoothed
//! ones) and its times a lower bound for a game that would use it. Both must find a path for
//! exactly the same queries: [`count_mismatches`] checks it.
//!
//! ```no_run
//! use tileslide_bench::paths::{PATHS_RADII, PathScene, contenders, run_paths};
//!
//! let scene = PathScene::dungeon256()?;
//! for radius in PATHS_RADII {
//!     let queries = scene.queries(radius, 1_000)?;
//!     for mut contender in contenders(&scene) {
//!         let result = run_paths(contender.as_mut(), &scene, radius, &queries)?;
//!         println!("r = {radius} {}: {:.1} µs/query, {} found", result.name,
//!             result.us_per_query, result.found);
//!     }
//! }
//! # Ok::<(), tileslide_bench::paths::PathsError>(())
//! ```

mod pathfinding_astar;
mod tileslide_paths;

pub use pathfinding_astar::PathfindingAstar;
pub use tileslide_paths::TileslidePaths;

use std::time::Instant;

use glam::Vec2;
use tileslide::{NavConfig, NavError, NavGrid, TileMap};
use tileslide_scenes::{SplitMix64, TileMapError, dungeon256};

/// The seed of the queries' generator (a fresh one per radius).
pub const PATHS_SEED: u64 = 0x9A7400000000007;

/// The radii the scene is run for: a small circle and one that needs corridors of two cells.
pub const PATHS_RADII: [f32; 2] = [0.3, 0.8];

/// Queries per radius by default.
pub const PATHS_QUERIES: usize = 1_000;

/// Why the scene could not be set up or a query not answered.
#[derive(Debug, thiserror::Error)]
pub enum PathsError {
    /// The grid could not become a map.
    #[error(transparent)]
    Map(#[from] TileMapError),
    /// The navigation grid refused the map, a radius or a query.
    #[error(transparent)]
    Nav(#[from] NavError),
}

/// One query: from lattice node `start` to node `goal` (indices `j · nx + i`), which are at
/// `from` and `to`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PathQuery {
    /// The start node's index.
    pub start: u32,
    /// The goal node's index.
    pub goal: u32,
    /// The start node's position (map units).
    pub from: Vec2,
    /// The goal node's position (map units).
    pub to: Vec2,
}

/// A map and its navigation grid: what every contender is given.
#[derive(Clone, Debug)]
pub struct PathScene {
    map: TileMap,
    nav: NavGrid,
}

impl PathScene {
    /// The scene of `map`, its navigation grid built with [`NavConfig::default`].
    ///
    /// # Errors
    /// When the navigation grid refuses the map (too large).
    pub fn new(map: TileMap) -> Result<Self, PathsError> {
        let nav = NavGrid::new(&map, NavConfig::default())?;
        Ok(Self { map, nav })
    }

    /// The standard scene: dungeon256.
    ///
    /// # Errors
    /// Never in practice (the map and its grid are fixed).
    pub fn dungeon256() -> Result<Self, PathsError> {
        Self::new(dungeon256().to_tile_map()?)
    }

    /// The map.
    #[must_use]
    pub fn map(&self) -> &TileMap {
        &self.map
    }

    /// Its navigation grid.
    #[must_use]
    pub fn nav(&self) -> &NavGrid {
        &self.nav
    }

    /// [`NavGrid::open_moves`] for `radius` of every node, by index `j · nx + i`.
    ///
    /// # Errors
    /// When the grid refuses `radius`.
    pub fn open_moves(&self, radius: f32) -> Result<Vec<u8>, PathsError> {
        let (nx, ny) = self.nav.nodes();
        let mut moves = Vec::with_capacity(nx as usize * ny as usize);
        for j in 0..ny {
            for i in 0..nx {
                moves.push(self.nav.open_moves(&self.map, i, j, radius)?);
            }
        }
        Ok(moves)
    }

    /// The first `n` queries of the scene for `radius` (none if no node is free).
    ///
    /// # Errors
    /// When the grid refuses `radius`.
    pub fn queries(&self, radius: f32, n: usize) -> Result<Vec<PathQuery>, PathsError> {
        let free: Vec<u32> = self
            .open_moves(radius)?
            .iter()
            .enumerate()
            .filter(|&(_, &m)| m != 0)
            .map(|(k, _)| k as u32)
            .collect();
        if free.is_empty() {
            return Ok(Vec::new());
        }
        let mut rng = SplitMix64::new(PATHS_SEED);
        let mut draw = || free[rng.below(free.len() as u64) as usize];
        Ok((0..n)
            .map(|_| {
                let start = draw();
                let goal = draw();
                PathQuery {
                    start,
                    goal,
                    from: self.node_position(start),
                    to: self.node_position(goal),
                }
            })
            .collect())
    }

    /// The position of node `index`.
    #[must_use]
    pub fn node_position(&self, index: u32) -> Vec2 {
        let nx = self.nav.nodes().0;
        self.nav.node_position(index % nx, index / nx)
    }

    /// Map units per unit of [`NavGrid::move_cost`]: move 0 (one node along +x) is half a
    /// cell wide.
    #[must_use]
    pub fn cost_unit(&self) -> f32 {
        let half_cell = self.nav.node_position(1, 0).x - self.nav.node_position(0, 0).x;
        half_cell / self.nav.move_cost(0) as f32
    }
}

/// Every contender of `tileslide bench paths`, in report order: tileslide, then the peer.
#[must_use]
pub fn contenders(scene: &PathScene) -> Vec<Box<dyn PathContender>> {
    vec![
        Box::new(TileslidePaths::new(scene)),
        Box::new(PathfindingAstar::new()),
    ]
}

/// Something that finds paths for circles on a [`PathScene`]: tileslide or a peer.
pub trait PathContender {
    /// The name the contender is reported under (e.g. `"pathfinding-astar"`).
    fn name(&self) -> &'static str;

    /// Gets ready to answer queries for circles of `radius`. Not timed.
    ///
    /// # Errors
    /// When the scene's grid refuses `radius`.
    fn prepare(&mut self, scene: &PathScene, radius: f32) -> Result<(), PathsError>;

    /// The length (map units) of the path the contender finds for `query`, `None` if it
    /// finds none. The timed part.
    ///
    /// # Errors
    /// When the scene's grid refuses the query.
    fn find(&mut self, scene: &PathScene, query: &PathQuery) -> Result<Option<f32>, PathsError>;
}

/// One contender's figures for one radius.
#[derive(Clone, Debug, PartialEq)]
pub struct PathsResult {
    /// The contender's [`name`](PathContender::name).
    pub name: &'static str,
    /// The circles' radius.
    pub radius: f32,
    /// Wall time of all the queries, in milliseconds.
    pub ms_total: f64,
    /// The same per query, in microseconds (0 for no queries).
    pub us_per_query: f64,
    /// Queries for which it found a path.
    pub found: usize,
    /// Mean length of the paths found (map units; 0 if none).
    pub mean_length: f64,
    /// Per query, the length found (`None`: no path).
    pub lengths: Vec<Option<f32>>,
    /// Queries found by this contender and not by the first of the same radius, or the
    /// other way round ([`count_mismatches`]; 0 until then).
    pub mismatches: usize,
}

/// Answers `queries` for circles of `radius` with `contender`:
/// [`prepare`](PathContender::prepare)s it (not timed), then times the loop of
/// [`find`](PathContender::find)s over all the queries ([`Instant`], wall time).
///
/// # Errors
/// When the contender refuses the radius or a query.
pub fn run_paths(
    contender: &mut dyn PathContender,
    scene: &PathScene,
    radius: f32,
    queries: &[PathQuery],
) -> Result<PathsResult, PathsError> {
    contender.prepare(scene, radius)?;
    let mut lengths = Vec::with_capacity(queries.len());
    let start = Instant::now();
    for query in queries {
        lengths.push(contender.find(scene, query)?);
    }
    let ms_total = start.elapsed().as_secs_f64() * 1e3;
    let found = lengths.iter().flatten().count();
    let total: f64 = lengths.iter().flatten().map(|&l| f64::from(l)).sum();
    Ok(PathsResult {
        name: contender.name(),
        radius,
        ms_total,
        us_per_query: if queries.is_empty() {
            0.0
        } else {
            ms_total * 1e3 / queries.len() as f64
        },
        found,
        mean_length: if found == 0 {
            0.0
        } else {
            total / found as f64
        },
        lengths,
        mismatches: 0,
    })
}

/// Sets every result's [`mismatches`](PathsResult::mismatches): the queries on which it and
/// the first result of the same radius disagree about whether there is a path.
pub fn count_mismatches(results: &mut [PathsResult]) {
    for k in 0..results.len() {
        let Some(first) = results.iter().position(|r| r.radius == results[k].radius) else {
            continue;
        };
        let mismatches = results[k]
            .lengths
            .iter()
            .zip(&results[first].lengths)
            .filter(|(a, b)| a.is_some() != b.is_some())
            .count()
            + results[k]
                .lengths
                .len()
                .abs_diff(results[first].lengths.len());
        results[k].mismatches = mismatches;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use tileslide_scenes::SolidGrid;

    /// Two rooms joined by a corridor one cell wide (row 3), and a closed room on the right.
    fn rooms() -> PathScene {
        let grid = SolidGrid::from_rows(&[
            "##############",
            "#....#....####",
            "#....#....#..#",
            "#.........#..#",
            "#....#....#..#",
            "##############",
        ]);
        PathScene::new(grid.to_tile_map().unwrap()).unwrap()
    }

    fn node(scene: &PathScene, p: Vec2) -> PathQuery {
        let nx = scene.nav().nodes().0;
        let (i, j) = ((p.x * 2.0) as u32, (p.y * 2.0) as u32);
        PathQuery {
            start: j * nx + i,
            goal: j * nx + i,
            from: p,
            to: p,
        }
    }

    fn query(scene: &PathScene, from: Vec2, to: Vec2) -> PathQuery {
        PathQuery {
            goal: node(scene, to).start,
            to,
            ..node(scene, from)
        }
    }

    #[test]
    fn the_cost_unit_makes_half_a_cell_of_move_zero() {
        let scene = rooms();
        assert_eq!(scene.cost_unit() * scene.nav().move_cost(0) as f32, 0.5);
        let p = Vec2::new(2.5, 3.0);
        assert_eq!(scene.node_position(node(&scene, p).start), p);
    }

    #[test]
    fn queries_are_free_nodes_and_the_same_every_time() {
        let scene = rooms();
        let queries = scene.queries(0.3, 50).unwrap();
        assert_eq!(queries.len(), 50);
        assert_eq!(queries, scene.queries(0.3, 50).unwrap());
        let moves = scene.open_moves(0.3).unwrap();
        for q in &queries {
            assert_ne!(moves[q.start as usize], 0);
            assert_ne!(moves[q.goal as usize], 0);
            assert!(scene.nav().fits(scene.map(), q.from, 0.3).unwrap());
            assert_eq!(scene.node_position(q.goal), q.to);
        }
    }

    #[test]
    fn both_contenders_agree_on_which_queries_have_a_path() {
        let scene = rooms();
        let left = Vec2::new(2.0, 2.0);
        let right = Vec2::new(8.5, 4.0);
        let closed = Vec2::new(12.0, 3.0);
        let queries = vec![
            query(&scene, left, right),
            query(&scene, left, closed),
            query(&scene, closed, closed),
        ];
        for (radius, through) in [(0.3, true), (0.6, false)] {
            let mut results: Vec<PathsResult> = contenders(&scene)
                .into_iter()
                .map(|mut c| run_paths(c.as_mut(), &scene, radius, &queries).unwrap())
                .collect();
            count_mismatches(&mut results);
            let [ours, peer] = results.as_slice() else {
                panic!("two contenders")
            };
            assert_eq!((ours.name, peer.name), ("tileslide", "pathfinding-astar"));
            assert_eq!(ours.lengths[0].is_some(), through, "r = {radius}");
            assert_eq!(ours.lengths[1], None);
            assert_eq!(ours.lengths[2], Some(0.0));
            assert_eq!((ours.mismatches, peer.mismatches), (0, 0), "r = {radius}");
            if through {
                // Smoothing shortens the lattice path, never lengthens it.
                let (a, b) = (ours.lengths[0].unwrap(), peer.lengths[0].unwrap());
                assert!(a <= b + 1e-4 && a >= left.distance(right), "{a} vs {b}");
            }
        }
    }

    #[test]
    fn a_contender_that_disagrees_is_counted() {
        let scene = rooms();
        let queries = scene.queries(0.3, 20).unwrap();
        let mut results: Vec<PathsResult> = contenders(&scene)
            .into_iter()
            .map(|mut c| run_paths(c.as_mut(), &scene, 0.3, &queries).unwrap())
            .collect();
        results[1].lengths[3] = results[1].lengths[3].xor(Some(1.0));
        count_mismatches(&mut results);
        assert_eq!((results[0].mismatches, results[1].mismatches), (0, 1));
    }
}
