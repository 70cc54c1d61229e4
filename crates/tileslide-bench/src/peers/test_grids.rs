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
