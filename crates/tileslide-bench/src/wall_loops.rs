//! The walls as closed loops: the boundary of the grid's solid cells traced into simple
//! rectilinear polygons, for the peers whose walls are chains of segments (Box2D's chain loops).
//!
//! [`SolidGrid::merged_exposed_edges`] gives the same boundary as loose runs; a chain needs
//! them joined end to end, each loop closed. Cells outside the grid count as empty here, so
//! that every loop closes: a solid cell on the grid's edge gets its outer side too. Those
//! sides face out of the map, where nothing starts (on the standard maps they are the outer
//! faces of the solid border ring), so a one-sided wall there is never met from inside.

use glam::{IVec2, Vec2};
use tileslide_scenes::SolidGrid;

/// One closed loop of wall: the corners of a simple rectilinear polygon, in order, each
/// side having the solid cells on its left and the empty ones on its right (y up). That is
/// counter-clockwise around a solid region and clockwise around a hole in one: the winding of
/// Box2D's chain loops, whose segments collide on their right side only, and the orientation
/// of [`ExposedEdge`](tileslide_scenes::ExposedEdge) (`a → b`, normal `(d.y, −d.x)`).
///
/// The corners are where the boundary turns (collinear unit sides are merged), no corner
/// appears twice, and there are at least 4.
///
/// ```
/// use glam::Vec2;
/// use tileslide_bench::wall_loops::wall_loops;
/// use tileslide_scenes::SolidGrid;
/// // One solid cell (1, 1) in open space: one loop, counter-clockwise around it.
/// let loops = wall_loops(&SolidGrid::from_rows(&["...", ".#.", "..."]));
/// assert_eq!(loops.len(), 1);
/// assert_eq!(
///     loops[0].corners,
///     [Vec2::new(1.0, 1.0), Vec2::new(2.0, 1.0), Vec2::new(2.0, 2.0), Vec2::new(1.0, 2.0)]
/// );
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct WallLoop {
    /// The corners; the last one joins back to the first.
    pub corners: Vec<Vec2>,
}

impl WallLoop {
    /// The loop's sides as `(from, to)`, the closing side last.
    pub fn sides(&self) -> impl Iterator<Item = (Vec2, Vec2)> + '_ {
        let n = self.corners.len();
        (0..n).map(move |i| (self.corners[i], self.corners[(i + 1) % n]))
    }
}

/// Unit steps along the grid lines: east, north, west, south (a left turn is `+1`).
const STEPS: [IVec2; 4] = [IVec2::X, IVec2::Y, IVec2::NEG_X, IVec2::NEG_Y];

/// The boundary of the solid cells of `grid` as closed loops (see [`WallLoop`]), cells
/// outside the grid counting as empty.
///
/// Every unit side between a solid cell and an empty one (or the outside) is on exactly one
/// loop. Where two solid cells touch only at a corner, the loops keep them apart (solid cells
/// connect through their sides, not their corners): the trace turns left there, hugging the
/// cell it was following, and a loop that still comes back to a corner it has passed is split
/// there into two loops that touch, so that no loop repeats a corner (Box2D rejects a chain
/// whose points are not all distinct).
///
/// Order: loops by the lowest-indexed corner where their trace starts (row-major over the
/// grid's corner points), so the result depends only on the grid.
#[must_use]
pub fn wall_loops(grid: &SolidGrid) -> Vec<WallLoop> {
    let corners_wide = grid.width + 1;
    let corner_count = corners_wide * (grid.height + 1);
    // For each grid corner point, a bit per step direction: an untraced unit side leaves it
    // that way.
    let mut leaving = vec![0u8; corner_count];
    let index = |p: IVec2| p.y as usize * corners_wide + p.x as usize;
    for y in 0..grid.height {
        for x in 0..grid.width {
            let (xi, yi) = (x as i64, y as i64);
            if !grid.is_solid(xi, yi) {
                continue;
            }
            let cell = IVec2::new(x as i32, y as i32);
            // Counter-clockwise around the cell: bottom side east, right side north, top side
            // west, left side south; each where the neighbour across it is empty.
            let sides = [
                (yi - 1, xi, cell, 0),
                (yi, xi + 1, cell + IVec2::X, 1),
                (yi + 1, xi, cell + IVec2::ONE, 2),
                (yi, xi - 1, cell + IVec2::Y, 3),
            ];
            for (ny, nx, from, step) in sides {
                if !grid.is_solid(nx, ny) {
                    leaving[index(from)] |= 1 << step;
                }
            }
        }
    }

    let mut loops = Vec::new();
    // Scratch for one trace: the corners passed and the step leaving each, and where each
    // corner sits on that path (u32::MAX when it is not on it).
    let mut path: Vec<(IVec2, u8)> = Vec::new();
    let mut on_path = vec![u32::MAX; corner_count];
    for start in 0..corner_count {
        while leaving[start] != 0 {
            let first = IVec2::new((start % corners_wide) as i32, (start / corners_wide) as i32);
            let mut at = first;
            let mut step = leaving[start].trailing_zeros() as u8;
            loop {
                // A corner already on the path closes a loop: cut it off.
                let here = index(at);
                if on_path[here] != u32::MAX {
                    let from = on_path[here] as usize;
                    for &(p, _) in &path[from..] {
                        on_path[index(p)] = u32::MAX;
                    }
                    loops.push(merged(&path[from..]));
                    path.truncate(from);
                }
                if leaving[here] == 0 {
                    break;
                }
                // Prefer the left turn, then straight on, then the right turn.
                step = [1, 0, 3]
                    .iter()
                    .map(|turn| (step + turn) % 4)
                    .find(|&s| leaving[here] & (1 << s) != 0)
                    .unwrap_or(step);
                leaving[here] &= !(1 << step);
                on_path[here] = path.len() as u32;
                path.push((at, step));
                at += STEPS[step as usize];
            }
            debug_assert!(at == first && path.is_empty());
        }
    }
    loops
}

/// The loop through `path`'s corners (each with the step leaving it), keeping only the corners
/// where the direction changes.
fn merged(path: &[(IVec2, u8)]) -> WallLoop {
    let n = path.len();
    let corners = (0..n)
        .filter(|&i| path[(i + n - 1) % n].1 != path[i].1)
        .map(|i| path[i].0.as_vec2())
        .collect();
    WallLoop { corners }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rays::test_grids::random_grid;
    use std::collections::HashMap;
    use tileslide_scenes::{SplitMix64, dungeon256};

    /// A unit side: the corner it leaves and its step direction (an index into `STEPS`).
    type UnitSide = (IVec2, usize);

    /// The cell left of and the cell right of a unit side.
    fn cells_beside((from, step): UnitSide) -> (IVec2, IVec2) {
        match step {
            0 => (from, from - IVec2::Y),
            1 => (from - IVec2::X, from),
            2 => (from - IVec2::ONE, from - IVec2::X),
            _ => (from - IVec2::Y, from - IVec2::ONE),
        }
    }

    /// The unit sides of `loops`, each with the number of times it is traced.
    fn traced_sides(loops: &[WallLoop]) -> HashMap<UnitSide, usize> {
        let mut sides = HashMap::new();
        for l in loops {
            for (a, b) in l.sides() {
                let (a, d) = (a.as_ivec2(), (b - a).as_ivec2());
                let step = STEPS.iter().position(|&s| s == d.signum()).unwrap();
                for k in 0..d.abs().max_element() {
                    *sides.entry((a + STEPS[step] * k, step)).or_insert(0) += 1;
                }
            }
        }
        sides
    }

    /// Twice the signed area of a loop: positive counter-clockwise.
    fn doubled_area(l: &WallLoop) -> f32 {
        l.sides().map(|(a, b)| a.perp_dot(b)).sum()
    }

    /// Checks `wall_loops(grid)` against the grid: every unit side between a solid cell and an
    /// empty one (or the outside) traced exactly once, solid on its left, and nothing else;
    /// every loop simple, with at least 4 corners, all of them turns. Returns the loops.
    fn check(grid: &SolidGrid) -> Vec<WallLoop> {
        let solid = |c: IVec2| grid.is_solid(i64::from(c.x), i64::from(c.y));
        let loops = wall_loops(grid);
        let traced = traced_sides(&loops);
        let mut expected = 0;
        for y in 0..grid.height as i32 {
            for x in 0..grid.width as i32 {
                let c = IVec2::new(x, y);
                if !solid(c) {
                    continue;
                }
                for (step, from) in [c, c + IVec2::X, c + IVec2::ONE, c + IVec2::Y]
                    .into_iter()
                    .enumerate()
                {
                    let (left, right) = cells_beside((from, step));
                    assert_eq!(left, c);
                    if !solid(right) {
                        expected += 1;
                        let count = traced.get(&(from, step)).copied().unwrap_or(0);
                        assert_eq!(count, 1, "side {step} of cell {c} traced {count} times");
                    }
                }
            }
        }
        // Nothing else: every traced side is one of the expected ones.
        assert_eq!(traced.len(), expected);
        for l in &loops {
            assert!(l.corners.len() >= 4, "{l:?}");
            let mut distinct: Vec<IVec2> = l.corners.iter().map(|c| c.as_ivec2()).collect();
            distinct.sort_by_key(|c| (c.x, c.y));
            distinct.dedup();
            assert_eq!(distinct.len(), l.corners.len(), "a corner twice in {l:?}");
            let sides: Vec<_> = l.sides().collect();
            for (i, &(a, b)) in sides.iter().enumerate() {
                let (_, c) = sides[(i + 1) % sides.len()];
                assert_eq!((b - a).dot(c - b), 0.0, "not a turn at {b} in {l:?}");
            }
        }
        loops
    }

    #[test]
    fn a_lone_cell_is_one_counter_clockwise_square() {
        let loops = check(&SolidGrid::from_rows(&["...", ".#.", "..."]));
        assert_eq!(loops.len(), 1);
        assert_eq!(doubled_area(&loops[0]), 2.0);
    }

    #[test]
    fn cells_touching_at_a_corner_get_a_loop_each() {
        //   ....
        //   .#..
        //   ..#.
        //   ....
        let loops = check(&SolidGrid::from_rows(&["....", ".#..", "..#.", "...."]));
        assert_eq!(loops.len(), 2);
        assert!(loops.iter().all(|l| l.corners.len() == 4));
    }

    #[test]
    fn a_hole_is_a_clockwise_loop_even_where_it_touches_the_outer_one() {
        // Row 0 first: the empty cell (1, 1) is closed in on its four sides, but meets the
        // outside at the corner (2, 2), where the loop around the hole and the outer loop touch.
        //   ###
        //   #.#
        //   ##.
        let loops = check(&SolidGrid::from_rows(&["###", "#.#", "##."]));
        assert_eq!(loops.len(), 2);
        let hole = loops.iter().find(|l| doubled_area(l) < 0.0).unwrap();
        assert_eq!(doubled_area(hole), -2.0);
        let pinch = Vec2::new(2.0, 2.0);
        assert!(loops.iter().all(|l| l.corners.contains(&pinch)));
    }

    #[test]
    fn the_outside_counts_as_empty_so_every_loop_closes() {
        // A wall across the whole grid, touching its left and right edges.
        let loops = check(&SolidGrid::from_rows(&["...", "###", "..."]));
        assert_eq!(loops.len(), 1);
        assert_eq!(loops[0].corners.len(), 4);
        assert_eq!(doubled_area(&loops[0]), 6.0);
    }

    #[test]
    fn random_grids_are_traced_side_by_side() {
        let mut rng = SplitMix64::new(0x5EED_0000_0000_0002);
        for round in 0..12 {
            check(&random_grid(&mut rng, 20, round % 2 == 0));
        }
    }

    #[test]
    fn dungeon256_has_its_published_edges_plus_the_outline() {
        let grid = dungeon256();
        let loops = check(&grid);
        let sides: usize = loops.iter().map(|l| l.corners.len()).sum();
        let length: f32 = loops
            .iter()
            .flat_map(WallLoop::sides)
            .map(|(a, b)| a.distance(b))
            .sum();
        // BENCHMARKS.md: 46,306 exposed unit edges, 34,652 merged runs; the grid's outline
        // (the outer faces of the border ring) adds 1,024 unit sides in 4 runs.
        assert_eq!(length, 46_306.0 + 1_024.0);
        assert_eq!(sides, 34_652 + 4);
        assert_eq!(grid.merged_exposed_edges().len(), 34_652);
    }
}
