//! A small batch of rays, small enough to run under Miri (`cargo +nightly miri test`, see
//! docs/fuzzing.md): the batch answers as the single casts do. Built with AVX2 enabled
//! (`RUSTFLAGS="-C target-feature=+avx2,+bmi1,+bmi2,+lzcnt,+popcnt"`), `cast_rays` takes
//! its one `unsafe` block, the call into the AVX2 walk, which Miri checks for undefined
//! behaviour: a call into code for instructions the processor lacks, an out-of-bounds or
//! misaligned access in the walk's lanes.

#![allow(clippy::unwrap_used)]

use tileslide::io::ascii;
use tileslide::{QueryFilter, Ray, Vec2};

#[test]
fn a_small_batch_answers_as_the_single_casts_do() {
    let map = ascii::parse(
        "\
##########
#....#...#
#.##.../.#
#....=...#
#..\\.....#
##########",
        "small.txt",
        1.0,
    )
    .unwrap();
    // Rays from inside and outside the map, along the axes and diagonals, some a whole
    // lane group (8) long so the walk fills and drains its lanes.
    let mut rays = Vec::new();
    for k in 0..19u8 {
        let f = f32::from(k);
        let from = Vec2::new(0.5 + f * 0.47, 0.5 + f * 0.29);
        let to = Vec2::new(9.5 - f * 0.41, 5.5 - (f * 0.61) % 5.0);
        rays.push(Ray::between(from, to));
        rays.push(Ray::between(to, Vec2::new(-1.0, f * 0.3)));
    }
    for filter in [QueryFilter::default(), QueryFilter::both_sides()] {
        let batch = map.cast_rays(&rays, &filter);
        for (ray, hit) in rays.iter().zip(&batch) {
            assert_eq!(*hit, map.cast_ray(*ray, &filter), "{ray:?}");
        }
        assert!(batch.iter().any(Option::is_some), "the rays hit something");
    }
}
