//! Test fixtures shared by the peers' unit tests: hand-made grids, seeded random grids and rays,
//! a brute-force reference ray cast (f64 slab test against every solid cell), and a check against
//! the scenes crate's reference walk on the real benchmark scene.

use glam::Vec2;

use tileslide_scenes::{SceneRay, SolidGrid, SplitMix64, reference_hit_distance, scene_rays};

/// Builds a grid from a predicate on cell coordinates.
pub fn grid_from(width: usize, height: usize, solid: impl Fn(usize, usize) -> bool) -> SolidGrid {
    let mut cells = Vec::with_capacity(width * height);
    for y in 0..height {
        for x in 0..width {
            cells.push(solid(x, y));
        }
    }
    SolidGrid {
        width,
        height,
        solid: cells,
    }
}

/// 8×8, solid border ring, plus the single solid cell (4, 4).
pub fn boxed_8x8() -> SolidGrid {
    grid_from(8, 8, |x, y| {
        x == 0 || y == 0 || x == 7 || y == 7 || (x, y) == (4, 4)
    })
}

/// 8×8 with no border: only the cell (4, 4) is solid, so rays can leave the map.
pub fn lone_cell_8x8() -> SolidGrid {
    grid_from(8, 8, |x, y| (x, y) == (4, 4))
}

/// A ray from `origin` along the unit vector of `dir`.
pub fn ray(origin: (f32, f32), dir: (f32, f32), length: f32) -> SceneRay {
    SceneRay {
        origin: Vec2::new(origin.0, origin.1),
        dir: Vec2::new(dir.0, dir.1).normalize(),
        length,
    }
}

/// A random `size`×`size` grid (about 35% solid), with or without a solid border ring.
pub fn random_grid(rng: &mut SplitMix64, size: usize, border: bool) -> SolidGrid {
    let mut cells = Vec::with_capacity(size * size);
    for y in 0..size {
        for x in 0..size {
            let on_border = x == 0 || y == 0 || x == size - 1 || y == size - 1;
            cells.push((border && on_border) || rng.f32() < 0.35);
        }
    }
    SolidGrid {
        width: size,
        height: size,
        solid: cells,
    }
}

/// Random rays as in the "rays" scene: origin uniform in a random empty cell, uniform angle,
/// length uniform in (0, `max_len`].
pub fn random_rays(
    rng: &mut SplitMix64,
    grid: &SolidGrid,
    n: usize,
    max_len: f32,
) -> Vec<SceneRay> {
    let empties: Vec<(usize, usize)> = (0..grid.height)
        .flat_map(|y| (0..grid.width).map(move |x| (x, y)))
        .filter(|&(x, y)| !grid.solid[y * grid.width + x])
        .collect();
    (0..n)
        .map(|_| {
            let (cx, cy) = empties[rng.below(empties.len() as u64) as usize];
            let origin = Vec2::new(cx as f32 + rng.f32(), cy as f32 + rng.f32());
            let angle = rng.f32() * std::f32::consts::TAU;
            SceneRay {
                origin,
                dir: Vec2::new(angle.cos(), angle.sin()),
                length: max_len * (1.0 - rng.f32()),
            }
        })
        .collect()
}

/// Reference answer: the smallest entry distance, in [0, length], of the ray into any solid cell,
/// by an f64 slab test against every solid cell (the ray starts outside all of them), with the
/// cosine between the ray and the normal of the face it enters through.
pub fn reference_cast(grid: &SolidGrid, ray: &SceneRay) -> Option<(f64, f64)> {
    let (ox, oy) = (f64::from(ray.origin.x), f64::from(ray.origin.y));
    let (dx, dy) = (f64::from(ray.dir.x), f64::from(ray.dir.y));
    let mut best: Option<(f64, f64)> = None;
    for y in 0..grid.height {
        for x in 0..grid.width {
            if !grid.solid[y * grid.width + x] {
                continue;
            }
            let (mut tmin, mut cos) = (0.0_f64, 0.0_f64);
            let mut tmax = f64::from(ray.length);
            for (o, d, lo) in [(ox, dx, x as f64), (oy, dy, y as f64)] {
                let hi = lo + 1.0;
                if d == 0.0 {
                    if o < lo || o > hi {
                        tmin = f64::INFINITY;
                    }
                } else {
                    let (mut a, mut b) = ((lo - o) / d, (hi - o) / d);
                    if a > b {
                        std::mem::swap(&mut a, &mut b);
                    }
                    if a > tmin {
                        (tmin, cos) = (a, d.abs());
                    }
                    tmax = tmax.min(b);
                }
            }
            if tmin <= tmax && best.is_none_or(|(b, _)| tmin < b) {
                best = Some((tmin, cos));
            }
        }
    }
    best
}

/// Checks a peer's `cast` against [`reference_cast`] on seeded random grids (with and without a
/// border) and random rays; returns how many rays hit.
pub fn check_against_reference(
    build_and_cast: impl Fn(&SolidGrid, &[SceneRay]) -> Vec<Option<f32>>,
) -> usize {
    let mut rng = SplitMix64::new(0x5EED_0000_0000_0001);
    let mut hits = 0;
    for round in 0..8 {
        let grid = random_grid(&mut rng, 24, round % 2 == 0);
        let rays = random_rays(&mut rng, &grid, 2_000, 30.0);
        let got = build_and_cast(&grid, &rays);
        for (ray, got) in rays.iter().zip(got) {
            let want = reference_cast(&grid, ray);
            match (got, want) {
                (Some(g), Some((w, cos))) => {
                    // Compare the hit points across the face hit: parry works in f32 on
                    // coordinates up to 24 (its segment cast loses up to ~1.2e-5 there), and a
                    // grazing ray stretches that error along the ray by 1 / cos. A wrong face
                    // or cell would be off by far more than the tolerance.
                    assert!(
                        (f64::from(g) - w).abs() * cos < 5e-5,
                        "round {round}: ray {:?} {:?} {}: got {g}, want {w}",
                        ray.origin,
                        ray.dir,
                        ray.length
                    );
                    hits += 1;
                }
                (None, None) => {}
                _ => panic!("round {round}: {ray:?}: got {got:?}, want {want:?}"),
            }
        }
    }
    hits
}

/// Checks a peer's `cast` against the scenes crate's [`reference_hit_distance`] on the first `n`
/// rays of the "rays" scene on `grid`; returns how many rays hit.
pub fn check_against_scene(
    grid: &SolidGrid,
    n: usize,
    cast: impl Fn(&SceneRay) -> Option<f32>,
) -> usize {
    let mut hits = 0;
    for (i, ray) in scene_rays(grid, n).iter().enumerate() {
        let (got, want) = (cast(ray), reference_hit_distance(grid, ray));
        match (got, want) {
            (Some(g), Some(w)) => {
                // Compared across the face hit, as above (the face is found from the hit point:
                // the coordinate nearer a grid line). Coordinates here go up to 256 and merged
                // edges are long: on the full million rays parry's segment cast is off by up to
                // ~4.3e-4 across the face, its voxel cast by ~7.6e-6.
                let p = ray.origin + ray.dir * w;
                let cos = if (p.x - p.x.round()).abs() < (p.y - p.y.round()).abs() {
                    ray.dir.x.abs()
                } else {
                    ray.dir.y.abs()
                };
                assert!(
                    (g - w).abs() * cos < 1e-3,
                    "ray {i} {ray:?}: got {g}, want {w}"
                );
                hits += 1;
            }
            (None, None) => {}
            _ => panic!("ray {i} {ray:?}: got {got:?}, want {want:?}"),
        }
    }
    hits
}

/// The tests every ray peer passes, as `mod tests` of the peer's file: the hand-made grids'
/// exact answers, a brute-force reference on random grids and the reference walk on the
/// dungeon's rays. `$peer` has `cast(&SceneRay) -> Option<f32>` and is built by `$build`, a
/// `fn(&SolidGrid) -> $peer` (by default its `new`); the invocation stands under
/// `#[cfg(test)]`.
macro_rules! ray_peer_tests {
    ($peer:ty) => {
        $crate::rays::test_grids::ray_peer_tests!($peer, <$peer>::new);
    };
    ($peer:ty, $build:expr) => {
        // `cfg(test)` again on the module itself, where clippy looks for it (the one on the
        // invocation is gone once expanded): `$build` may unwrap, as tests do.
        #[cfg(test)]
        mod tests {
            use super::*;
            use $crate::rays::test_grids::{
                boxed_8x8, check_against_reference, check_against_scene, lone_cell_8x8, ray,
            };

            fn build(grid: &tileslide_scenes::SolidGrid) -> $peer {
                let build: fn(&tileslide_scenes::SolidGrid) -> $peer = $build;
                build(grid)
            }

            fn assert_hit(got: Option<f32>, want: f32) {
                let got = got.unwrap_or_else(|| panic!("expected a hit at {want}, got a miss"));
                assert!(
                    (got - want).abs() < 1e-5,
                    "expected a hit at {want}, got {got}"
                );
            }

            #[test]
            fn axis_rays_hit_the_faces_of_the_lone_cell() {
                let peer = build(&boxed_8x8());
                // Cell (4, 4) covers [4, 5] × [4, 5].
                assert_hit(peer.cast(&ray((1.5, 4.5), (1.0, 0.0), 10.0)), 2.5);
                assert_hit(peer.cast(&ray((6.5, 4.5), (-1.0, 0.0), 10.0)), 1.5);
                assert_hit(peer.cast(&ray((4.5, 1.5), (0.0, 1.0), 10.0)), 2.5);
                assert_hit(peer.cast(&ray((4.5, 6.5), (0.0, -1.0), 10.0)), 1.5);
            }

            #[test]
            fn rays_hit_the_inner_faces_of_the_border() {
                let peer = build(&boxed_8x8());
                // The border ring leaves [1, 7] × [1, 7] open.
                assert_hit(peer.cast(&ray((1.5, 1.5), (-1.0, 0.0), 10.0)), 0.5);
                assert_hit(peer.cast(&ray((1.5, 2.25), (0.0, -1.0), 10.0)), 1.25);
                assert_hit(peer.cast(&ray((2.5, 5.5), (1.0, 0.0), 10.0)), 4.5);
                assert_hit(peer.cast(&ray((5.5, 5.75), (0.0, 1.0), 10.0)), 1.25);
            }

            #[test]
            fn a_diagonal_ray_hits_the_side_face_it_reaches_first() {
                let peer = build(&boxed_8x8());
                // Along (0.6, 0.8) from (1.5, 1.5): reaches x = 4 at t = 2.5 / 0.6 = 25/6, where
                // y = 1.5 + 0.8 · 25/6 = 4.833.., inside the left face of cell (4, 4).
                assert_hit(peer.cast(&ray((1.5, 1.5), (0.6, 0.8), 10.0)), 25.0 / 6.0);
                // Along (0.8, 0.6) from (1.5, 2.0): passes x = 4 below the cell (y = 3.875), then
                // reaches y = 4 at t = 2 / 0.6 = 10/3, where x = 4.166.., inside its bottom face.
                assert_hit(peer.cast(&ray((1.5, 2.0), (0.8, 0.6), 20.0)), 10.0 / 3.0);
                // Along (0.8, 0.6) from (5.5, 1.5): reaches the border column x = 7 at
                // t = 1.5 / 0.8 = 1.875 (y = 2.625); from (1.5, 5.5), the border row y = 7 at
                // t = 1.5 / 0.6 = 2.5 (x = 3.5).
                assert_hit(peer.cast(&ray((5.5, 1.5), (0.8, 0.6), 20.0)), 1.875);
                assert_hit(peer.cast(&ray((1.5, 5.5), (0.8, 0.6), 20.0)), 2.5);
            }

            #[test]
            fn a_ray_that_stops_short_misses() {
                let peer = build(&boxed_8x8());
                assert_eq!(peer.cast(&ray((1.5, 4.5), (1.0, 0.0), 2.0)), None);
                assert_eq!(peer.cast(&ray((1.5, 1.5), (0.0, 1.0), 5.0)), None);
                // Just long enough.
                assert_hit(peer.cast(&ray((1.5, 4.5), (1.0, 0.0), 2.5001)), 2.5);
            }

            #[test]
            fn a_ray_that_leaves_the_map_misses() {
                let peer = build(&lone_cell_8x8());
                assert_eq!(peer.cast(&ray((1.5, 1.5), (1.0, 0.0), 100.0)), None);
                assert_eq!(peer.cast(&ray((1.5, 4.5), (-1.0, 0.0), 100.0)), None);
                // Passes above the cell (y = 7.375 at x = 4) and leaves the map.
                assert_eq!(peer.cast(&ray((1.5, 5.5), (0.8, 0.6), 100.0)), None);
                // The same map still has its lone cell where it should be.
                assert_hit(peer.cast(&ray((1.5, 4.5), (1.0, 0.0), 100.0)), 2.5);
                assert_hit(peer.cast(&ray((4.5, 7.5), (0.0, -1.0), 100.0)), 2.5);
            }

            #[test]
            fn agrees_with_a_brute_force_reference_on_random_grids() {
                let hits = check_against_reference(|grid, rays| {
                    let peer = build(grid);
                    rays.iter().map(|r| peer.cast(r)).collect()
                });
                assert!(hits > 1_000, "only {hits} hits: the check is too weak");
            }

            #[test]
            fn agrees_with_the_reference_walk_on_the_dungeon_rays() {
                let grid = tileslide_scenes::dungeon256();
                let peer = build(&grid);
                let hits = check_against_scene(&grid, 20_000, |r| peer.cast(r));
                // BENCHMARKS.md: 943,906 of 1,000,000 rays hit on dungeon256.
                assert!((18_500..19_300).contains(&hits), "{hits} hits");
            }
        }
    };
}
pub(crate) use ray_peer_tests;
