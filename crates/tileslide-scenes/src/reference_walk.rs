//! A plain reference grid walk, the ground truth for ray hits on a [`SolidGrid`].

use crate::{SceneRay, SolidGrid};

/// Reference: a plain, obviously-correct grid walk (not optimised) returning the
/// distance along the ray to the first solid-cell boundary the ray meets within
/// its length, treating cells outside the grid as empty, or `None`.
///
/// The walk is Amanatides & Woo (1987) "A Fast Voxel Traversal Algorithm",
/// computed in f64 from the ray's f32 values so that rounding in the walk
/// itself cannot move a hit: it visits cells in the order the ray enters them
/// and stops at the first solid one. A boundary exactly at `length` counts as a
/// hit. Deviations, for inputs the rays scene never produces: a ray whose
/// origin is inside a solid cell hits at distance 0; a ray with a non-finite
/// field, a negative length or a zero direction misses. When the ray passes
/// exactly through a cell corner the x step is taken first, so a solid cell
/// touched only at that corner counts as met.
///
/// ```
/// use glam::Vec2;
/// use tileslide_scenes::{SceneRay, SolidGrid, reference_hit_distance};
/// // ". . #": a wall at x = 2.
/// let grid = SolidGrid { width: 3, height: 1, solid: vec![false, false, true] };
/// let ray = SceneRay { origin: Vec2::new(0.5, 0.5), dir: Vec2::X, length: 10.0 };
/// assert_eq!(reference_hit_distance(&grid, &ray), Some(1.5));
/// let short = SceneRay { length: 1.0, ..ray };
/// assert_eq!(reference_hit_distance(&grid, &short), None);
/// ```
#[must_use]
pub fn reference_hit_distance(grid: &SolidGrid, ray: &SceneRay) -> Option<f32> {
    let origin = [f64::from(ray.origin.x), f64::from(ray.origin.y)];
    let dir = [f64::from(ray.dir.x), f64::from(ray.dir.y)];
    let length = f64::from(ray.length);
    let finite = origin.iter().chain(&dir).all(|v| v.is_finite()) && length.is_finite();
    if !finite || length < 0.0 || dir == [0.0, 0.0] {
        return None;
    }
    // Both origin coordinates are finite f32 values, so they fit an i64 cell.
    let mut cell = [origin[0].floor() as i64, origin[1].floor() as i64];
    if grid.is_solid(cell[0], cell[1]) {
        return Some(0.0);
    }
    // Per axis: the step direction, the ray parameter of the next cell boundary
    // (t_max) and the parameter span of one cell (t_delta).
    let mut step = [0_i64; 2];
    let mut t_max = [f64::INFINITY; 2];
    let mut t_delta = [f64::INFINITY; 2];
    for axis in 0..2 {
        let c = cell[axis] as f64;
        if dir[axis] > 0.0 {
            step[axis] = 1;
            t_max[axis] = (c + 1.0 - origin[axis]) / dir[axis];
            t_delta[axis] = 1.0 / dir[axis];
        } else if dir[axis] < 0.0 {
            step[axis] = -1;
            t_max[axis] = (c - origin[axis]) / dir[axis];
            t_delta[axis] = -1.0 / dir[axis];
        }
    }
    loop {
        let axis = if t_max[0] <= t_max[1] { 0 } else { 1 };
        let t = t_max[axis];
        if t > length {
            return None;
        }
        cell[axis] += step[axis];
        if grid.is_solid(cell[0], cell[1]) {
            return Some(t as f32);
        }
        t_max[axis] += t_delta[axis];
    }
}

#[cfg(test)]
mod tests {
    use glam::Vec2;

    use super::*;

    fn grid(rows: &[&str]) -> SolidGrid {
        SolidGrid::from_rows(rows)
    }

    fn ray(origin: (f32, f32), dir: (f32, f32), length: f32) -> SceneRay {
        SceneRay {
            origin: origin.into(),
            dir: Vec2::from(dir).normalize(),
            length,
        }
    }

    #[test]
    fn axis_rays_hit_the_near_face_of_each_wall() {
        //   #####
        //   #...#
        //   #####
        let g = grid(&["#####", "#...#", "#####"]);
        let o = (2.25, 1.5);
        assert_eq!(
            reference_hit_distance(&g, &ray(o, (1.0, 0.0), 9.0)),
            Some(1.75)
        );
        assert_eq!(
            reference_hit_distance(&g, &ray(o, (-1.0, 0.0), 9.0)),
            Some(1.25)
        );
        assert_eq!(
            reference_hit_distance(&g, &ray(o, (0.0, 1.0), 9.0)),
            Some(0.5)
        );
        assert_eq!(
            reference_hit_distance(&g, &ray(o, (0.0, -1.0), 9.0)),
            Some(0.5)
        );
    }

    #[test]
    fn diagonal_ray_finds_the_first_solid_cell_it_enters() {
        //   ....
        //   ....
        //   ..#.
        // From (0.5, 0.5) along +45° the ray enters (2, 2) at t = 1.5·√2.
        let g = grid(&["....", "....", "..#."]);
        let hit = reference_hit_distance(&g, &ray((0.5, 0.5), (1.0, 1.0), 9.0));
        let expected = 1.5 * std::f32::consts::SQRT_2;
        assert!(hit.is_some_and(|t| (t - expected).abs() < 1e-5), "{hit:?}");
    }

    #[test]
    fn a_ray_that_stops_short_of_the_wall_misses_and_one_that_reaches_it_hits() {
        let g = grid(&["..#"]);
        assert_eq!(
            reference_hit_distance(&g, &ray((0.5, 0.5), (1.0, 0.0), 1.49)),
            None
        );
        assert_eq!(
            reference_hit_distance(&g, &ray((0.5, 0.5), (1.0, 0.0), 1.5)),
            Some(1.5)
        );
    }

    #[test]
    fn cells_outside_the_grid_are_empty() {
        let g = grid(&["...", "...", "..."]);
        assert_eq!(
            reference_hit_distance(&g, &ray((1.5, 1.5), (1.0, 0.3), 64.0)),
            None
        );
        assert_eq!(
            reference_hit_distance(&g, &ray((-5.0, 1.5), (1.0, 0.0), 64.0)),
            None
        );
        let walled = grid(&["#.."]);
        assert_eq!(
            reference_hit_distance(&walled, &ray((-5.0, 0.5), (1.0, 0.0), 64.0)),
            Some(5.0)
        );
    }

    #[test]
    fn degenerate_rays_follow_the_documented_rules() {
        let g = grid(&["#."]);
        assert_eq!(
            reference_hit_distance(&g, &ray((0.5, 0.5), (1.0, 0.0), 1.0)),
            Some(0.0)
        );
        let zero = SceneRay {
            origin: Vec2::new(1.5, 0.5),
            dir: Vec2::ZERO,
            length: 1.0,
        };
        assert_eq!(reference_hit_distance(&g, &zero), None);
        let nan = SceneRay {
            length: f32::NAN,
            ..zero
        };
        assert_eq!(reference_hit_distance(&g, &nan), None);
        let back = ray((1.5, 0.5), (-1.0, 0.0), -1.0);
        assert_eq!(reference_hit_distance(&g, &back), None);
    }

    #[test]
    fn agrees_with_brute_force_sampling_on_a_small_map() {
        // Brute force: march in tiny steps and report the first solid sample.
        let g = grid(&["#######", "#..#..#", "#.#...#", "#....##", "#######"]);
        let mut rng = crate::SplitMix64::new(99);
        for _ in 0..500 {
            let origin = Vec2::new(1.0 + 5.0 * rng.f32(), 1.0 + 3.0 * rng.f32());
            if g.is_solid(origin.x.floor() as i64, origin.y.floor() as i64) {
                continue;
            }
            let a = rng.f32() * std::f32::consts::TAU;
            let r = SceneRay {
                origin,
                dir: Vec2::new(a.cos(), a.sin()),
                length: 8.0,
            };
            let brute = (1..=80_000).map(|i| i as f32 * 1e-4).find(|&t| {
                let p = r.origin + r.dir * t;
                g.is_solid(p.x.floor() as i64, p.y.floor() as i64)
            });
            let walk = reference_hit_distance(&g, &r);
            match (walk, brute) {
                (Some(w), Some(b)) => assert!((w - b).abs() < 2e-4, "{w} vs {b}"),
                (None, None) => {}
                other => panic!("walk and brute force disagree: {other:?} for {r:?}"),
            }
        }
    }
}
