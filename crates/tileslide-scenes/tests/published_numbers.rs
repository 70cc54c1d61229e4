//! The check figures BENCHMARKS.md publishes for the standard scenes, reproduced
//! from this crate's generators and its reference grid walk.

use tileslide_scenes::{Scene, SolidGrid, dungeon256, open256, reference_hit_distance, scene_rays};

/// Hit count and mean hit distance of the first `n` scene rays on `grid`.
fn ray_stats(grid: &SolidGrid, n: usize) -> (usize, f64) {
    let mut hits = 0;
    let mut sum = 0.0_f64;
    for ray in scene_rays(grid, n) {
        if let Some(t) = reference_hit_distance(grid, &ray) {
            hits += 1;
            sum += f64::from(t);
        }
    }
    (hits, sum / hits as f64)
}

#[test]
fn dungeon256_solid_cells_and_fingerprint() {
    let grid = dungeon256();
    assert_eq!(grid.solid_count(), 20_365);
    assert_eq!(grid.fingerprint_hex(), "a36c9fd56f2ba422");
    assert_eq!(
        Scene::Dungeon256.expected_fingerprint(),
        Some("a36c9fd56f2ba422")
    );
}

#[test]
fn open256_solid_cells() {
    assert_eq!(open256().solid_count(), 7_459);
}

#[test]
fn dungeon256_exposed_edges_unit_and_merged() {
    let grid = dungeon256();
    assert_eq!(grid.exposed_unit_edges(), 46_306);
    assert_eq!(grid.merged_exposed_edges().len(), 34_652);
}

#[test]
fn dungeon256_million_rays_hit_count_and_mean_distance() {
    let (hits, mean) = ray_stats(&dungeon256(), 1_000_000);
    assert_eq!(hits, 943_906, "mean {mean}");
    assert!((mean - 3.2925).abs() <= 1e-4, "mean {mean}");
}

#[test]
fn open256_million_rays_hit_count_and_mean_distance() {
    let (hits, mean) = ray_stats(&open256(), 1_000_000);
    assert_eq!(hits, 804_611, "mean {mean}");
    assert!((mean - 9.2143).abs() <= 1e-4, "mean {mean}");
}
