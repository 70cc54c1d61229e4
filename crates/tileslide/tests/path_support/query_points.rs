//! Query points picked inside a proptest case with a seeded `SplitMix64`: proptest chooses
//! the seed, so a failing case replays exactly.

use tileslide::{NavGrid, TileMap, Vec2};
use tileslide_scenes::SplitMix64;

/// A random point of `map` where a circle of radius `r` fits, if one turns up in 40 draws.
pub fn fitting_point(nav: &NavGrid, map: &TileMap, rng: &mut SplitMix64, r: f32) -> Option<Vec2> {
    let size = map.bounds().size();
    (0..40)
        .map(|_| map.origin() + Vec2::new(rng.range(0.0, size.x), rng.range(0.0, size.y)))
        .find(|&p| nav.fits(map, p, r).unwrap())
}
