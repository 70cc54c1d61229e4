//! The peer: the `pathfinding` crate's generic A* on tileslide's lattice graph.

use pathfinding::prelude::astar;
use tileslide::NAV_MOVES;

use super::{PathContender, PathQuery, PathScene, PathsError};

/// `pathfinding::prelude::astar` (pathfinding 4) on the graph tileslide's own search runs
/// on, handed over as a table so that the peer does none of tileslide's geometry:
///
/// - nodes are the lattice indices `j · nx + i`;
/// - a node's successors are the moves of its [`NavGrid::open_moves`] bits for the radius,
///   precomputed for every node in [`prepare`](PathContender::prepare) (not timed, which
///   favours the peer: tileslide reads its clearance table during the search);
/// - a move costs [`NavGrid::move_cost`], the same integers tileslide's search uses;
/// - the heuristic is the octile distance with those costs (admissible and consistent);
/// - the goal test is `n == goal`.
///
/// It returns the lattice path's cost, converted to map units with
/// [`PathScene::cost_unit`]: the length of the path before any smoothing.
///
/// [`NavGrid::open_moves`]: tileslide::NavGrid::open_moves
/// [`NavGrid::move_cost`]: tileslide::NavGrid::move_cost
#[derive(Clone, Debug, Default)]
pub struct PathfindingAstar {
    /// Per node, the moves a circle of the prepared radius can make (bit `d`: move `d`).
    moves: Vec<u8>,
    /// Nodes per row.
    nx: usize,
    /// Per move, the change of node index.
    steps: [isize; 8],
    /// Per move, its cost.
    costs: [u64; 8],
    /// Map units per cost unit.
    unit: f32,
}

impl PathfindingAstar {
    /// The name it is reported under.
    pub const NAME: &'static str = "pathfinding-astar";

    /// An empty peer, to be [prepared](PathContender::prepare).
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }
}

impl PathContender for PathfindingAstar {
    fn name(&self) -> &'static str {
        Self::NAME
    }

    fn prepare(&mut self, scene: &PathScene, radius: f32) -> Result<(), PathsError> {
        self.moves = scene.open_moves(radius)?;
        let nx = scene.nav().nodes().0 as usize;
        self.nx = nx;
        for (d, &(di, dj)) in NAV_MOVES.iter().enumerate() {
            self.steps[d] = dj as isize * nx as isize + di as isize;
            self.costs[d] = u64::from(scene.nav().move_cost(d));
        }
        self.unit = scene.cost_unit();
        Ok(())
    }

    fn find(&mut self, _: &PathScene, query: &PathQuery) -> Result<Option<f32>, PathsError> {
        let Self {
            moves,
            nx,
            steps,
            costs,
            unit,
        } = self;
        let (nx, steps, costs) = (*nx, *steps, *costs);
        let goal = query.goal as usize;
        let (gi, gj) = (goal % nx, goal / nx);
        // Octile distance: as many diagonal moves as the shorter side allows, then straight.
        let (straight_x, diagonal, straight_y) = (costs[0], costs[1], costs[2]);
        let heuristic = |&n: &usize| {
            let (dx, dy) = ((n % nx).abs_diff(gi) as u64, (n / nx).abs_diff(gj) as u64);
            let d = dx.min(dy);
            d * diagonal + (dx - d) * straight_x + (dy - d) * straight_y
        };
        let successors = |&n: &usize| {
            let open = moves[n];
            (0..8)
                .filter(move |d| open & (1 << d) != 0)
                .map(move |d| (n.wrapping_add_signed(steps[d]), costs[d]))
        };
        let found = astar(&(query.start as usize), successors, heuristic, |&n| {
            n == goal
        });
        Ok(found.map(|(_, cost)| cost as f32 * *unit))
    }
}
