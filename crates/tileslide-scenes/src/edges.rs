//! Exposed edges: the unit cell sides that separate a solid cell from an empty one.
//!
//! Only sides between two cells of the grid count: the outer boundary of the
//! grid is never exposed, even next to a solid border cell. That is the reading
//! that reproduces the published dungeon256 figures (46,306 unit edges, 34,652
//! merged); also counting the outer sides of the solid border ring, as if the
//! outside were empty, gives 1,024 more unit edges (47,330).
//!
//! [`reference_hit_distance`](crate::reference_hit_distance) instead treats
//! cells outside the grid as empty. The two agree on the standard maps: their
//! border ring is solid, so a ray starting in an empty cell is stopped by the
//! ring's inner faces before it could reach the grid's outer boundary.

use glam::Vec2;

use crate::SolidGrid;

/// One maximal straight run of exposed cell sides, all facing the same way.
///
/// `a → b` runs counter-clockwise around the solid region in a y-up frame:
/// with `d = (b − a) / |b − a|`, `normal = (d.y, −d.x)` (`d` turned by −90°).
/// The normal is the unit axis vector pointing from the solid side into the
/// empty side.
///
/// ```
/// use glam::Vec2;
/// use tileslide_scenes::{ExposedEdge, SolidGrid};
/// // One solid cell (1, 1) in open space: four exposed sides, one run each.
/// let mut solid = vec![false; 9];
/// solid[4] = true;
/// let grid = SolidGrid { width: 3, height: 3, solid };
/// let edges = grid.merged_exposed_edges();
/// assert_eq!(edges.len(), 4);
/// assert!(edges.contains(&ExposedEdge {
///     a: Vec2::new(1.0, 1.0),
///     b: Vec2::new(2.0, 1.0),
///     normal: Vec2::new(0.0, -1.0),
/// }));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExposedEdge {
    /// Start of the run.
    pub a: Vec2,
    /// End of the run.
    pub b: Vec2,
    /// Unit normal pointing out of the solid side into the empty side.
    pub normal: Vec2,
}

/// Which way an exposed unit side faces, or `None` if it is not exposed.
///
/// `before` is the cell on the lower-coordinate side of the line, `after` the
/// one on the higher side. A solid `before` faces `+1` (towards `after`).
fn facing(before: bool, after: bool) -> Option<f32> {
    match (before, after) {
        (true, false) => Some(1.0),
        (false, true) => Some(-1.0),
        _ => None,
    }
}

/// Converts a grid coordinate to `i64`; grids never come near `i64::MAX` cells.
fn coord(v: usize) -> i64 {
    i64::try_from(v).unwrap_or(i64::MAX)
}

/// Converts a grid-line coordinate to `f32` (exact for grids up to 2²⁴ cells wide).
fn line_pos(v: usize) -> f32 {
    // Grid coordinates are small enough for f32 to hold them exactly.
    v as f32
}

impl SolidGrid {
    /// Number of unit cell sides between a solid cell and an empty one, both in
    /// the grid (the grid's outer boundary never counts, even next to a solid
    /// border cell). dungeon256 has 46,306.
    #[must_use]
    pub fn exposed_unit_edges(&self) -> usize {
        let (w, h) = (coord(self.width), coord(self.height));
        let mut count = 0;
        // Inner horizontal lines y = 1..h, between rows y-1 and y.
        for y in 1..h {
            for x in 0..w {
                count += usize::from(self.is_solid(x, y - 1) != self.is_solid(x, y));
            }
        }
        // Inner vertical lines x = 1..w, between columns x-1 and x.
        for x in 1..w {
            for y in 0..h {
                count += usize::from(self.is_solid(x - 1, y) != self.is_solid(x, y));
            }
        }
        count
    }

    /// Exposed edges merged into maximal collinear runs with the same facing,
    /// each oriented so that its outward normal (pointing from the solid side
    /// into the empty side) is known; see [`ExposedEdge`]. dungeon256 has 34,652.
    ///
    /// A run ends where the side stops being exposed or flips which side is
    /// solid, so two runs may meet end to end on one line when the solid cells
    /// touch only at a corner. As in [`exposed_unit_edges`](Self::exposed_unit_edges),
    /// the grid's outer boundary is never exposed. Order: horizontal runs
    /// by line `y` then `x`, then vertical runs by line `x` then `y`.
    #[must_use]
    pub fn merged_exposed_edges(&self) -> Vec<ExposedEdge> {
        let mut edges = Vec::new();
        // Horizontal lines: a solid cell below the line (row y-1) faces +y.
        for y in 1..self.height {
            let yi = coord(y);
            let side =
                |x: usize| facing(self.is_solid(coord(x), yi - 1), self.is_solid(coord(x), yi));
            for_each_run(self.width, side, |start, end, dir| {
                let (x0, x1, yf) = (line_pos(start), line_pos(end), line_pos(y));
                let normal = Vec2::new(0.0, dir);
                // Counter-clockwise around the solid: facing +y runs towards -x.
                let (a, b) = if dir > 0.0 {
                    (Vec2::new(x1, yf), Vec2::new(x0, yf))
                } else {
                    (Vec2::new(x0, yf), Vec2::new(x1, yf))
                };
                edges.push(ExposedEdge { a, b, normal });
            });
        }
        // Vertical lines: a solid cell left of the line (column x-1) faces +x.
        for x in 1..self.width {
            let xi = coord(x);
            let side =
                |y: usize| facing(self.is_solid(xi - 1, coord(y)), self.is_solid(xi, coord(y)));
            for_each_run(self.height, side, |start, end, dir| {
                let (y0, y1, xf) = (line_pos(start), line_pos(end), line_pos(x));
                let normal = Vec2::new(dir, 0.0);
                // Counter-clockwise around the solid: facing +x runs towards +y.
                let (a, b) = if dir > 0.0 {
                    (Vec2::new(xf, y0), Vec2::new(xf, y1))
                } else {
                    (Vec2::new(xf, y1), Vec2::new(xf, y0))
                };
                edges.push(ExposedEdge { a, b, normal });
            });
        }
        edges
    }
}

/// Calls `emit(start, end, facing)` for every maximal run `start..end` of unit
/// sides along one grid line (`len` sides) on which `side` returns the same
/// `Some(facing)`.
fn for_each_run(
    len: usize,
    side: impl Fn(usize) -> Option<f32>,
    mut emit: impl FnMut(usize, usize, f32),
) {
    let mut run: Option<(usize, f32)> = None;
    for i in 0..len {
        let here = side(i);
        match (run, here) {
            (Some((_, dir)), Some(d)) if dir == d => {}
            _ => {
                if let Some((start, dir)) = run {
                    emit(start, i, dir);
                }
                run = here.map(|d| (i, d));
            }
        }
    }
    if let Some((start, dir)) = run {
        emit(start, len, dir);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(rows: &[&str]) -> SolidGrid {
        SolidGrid::from_rows(rows)
    }

    #[test]
    fn single_cell_has_four_unit_sides_oriented_counter_clockwise() {
        let g = grid(&["...", ".#.", "..."]);
        assert_eq!(g.exposed_unit_edges(), 4);
        let edges = g.merged_exposed_edges();
        assert_eq!(edges.len(), 4);
        for e in &edges {
            let d = (e.b - e.a).normalize();
            assert_eq!(e.normal, Vec2::new(d.y, -d.x));
            assert_eq!((e.b - e.a).length(), 1.0);
        }
    }

    #[test]
    fn a_straight_wall_merges_into_one_run_per_side() {
        // A 3-cell horizontal wall in open space:
        //   .....
        //   .###.
        //   .....
        let g = grid(&[".....", ".###.", "....."]);
        assert_eq!(g.exposed_unit_edges(), 8);
        let edges = g.merged_exposed_edges();
        assert_eq!(edges.len(), 4);
        assert!(edges.contains(&ExposedEdge {
            a: Vec2::new(1.0, 1.0),
            b: Vec2::new(4.0, 1.0),
            normal: Vec2::new(0.0, -1.0),
        }));
        assert!(edges.contains(&ExposedEdge {
            a: Vec2::new(4.0, 2.0),
            b: Vec2::new(1.0, 2.0),
            normal: Vec2::new(0.0, 1.0),
        }));
    }

    #[test]
    fn runs_split_where_the_solid_side_flips_at_a_corner_contact() {
        //   ....
        //   .#..
        //   ..#.
        //   ....
        // The line y = 2 has the solid cell below it on the left and above it
        // on the right.
        let g = grid(&["....", ".#..", "..#.", "...."]);
        assert_eq!(g.exposed_unit_edges(), 8);
        let edges = g.merged_exposed_edges();
        assert_eq!(edges.len(), 8);
        let on_y2: Vec<_> = edges
            .iter()
            .filter(|e| e.a.y == 2.0 && e.b.y == 2.0)
            .collect();
        assert_eq!(on_y2.len(), 2);
        assert_ne!(on_y2[0].normal, on_y2[1].normal);
    }

    #[test]
    fn outer_boundary_of_the_grid_is_never_exposed() {
        //   ###
        //   #.#
        //   ###
        // Only the four sides around the empty centre count.
        let g = grid(&["###", "#.#", "###"]);
        assert_eq!(g.exposed_unit_edges(), 4);
        let edges = g.merged_exposed_edges();
        assert_eq!(edges.len(), 4);
        assert!(edges.contains(&ExposedEdge {
            a: Vec2::new(2.0, 1.0),
            b: Vec2::new(1.0, 1.0),
            normal: Vec2::new(0.0, 1.0),
        }));
        assert_eq!(grid(&["#"]).exposed_unit_edges(), 0);
    }

    #[test]
    fn merged_runs_cover_exactly_the_unit_edges() {
        let g = grid(&["##..#", "#.#.#", "###..", "..#.#"]);
        let total: f32 = g
            .merged_exposed_edges()
            .iter()
            .map(|e| (e.b - e.a).length())
            .sum();
        assert_eq!(total as usize, g.exposed_unit_edges());
    }

    #[test]
    fn normals_point_into_empty_cells() {
        let g = grid(&["##..#", "#.#.#", "###..", "..#.#"]);
        for e in g.merged_exposed_edges() {
            let mid = (e.a + e.b) * 0.5;
            let empty = mid + e.normal * 0.5;
            let solid = mid - e.normal * 0.5;
            assert!(!g.is_solid(empty.x.floor() as i64, empty.y.floor() as i64));
            assert!(g.is_solid(solid.x.floor() as i64, solid.y.floor() as i64));
        }
    }
}
