//! Proves that `cast_rays` gives every ray exactly `cast_ray`'s answer, bit for bit, on
//! random maps (solid squares, ramps, one-way platforms), cell sizes and origins, for
//! batches of random rays mixed with the rays the fast walk declines (starts on grid lines
//! and lattice points, rays along an axis, through corners, from outside the map, zero
//! length, NaN and infinite), under every kind of filter and with temporary segments.
//! Both instruction sets of the batch are checked: `cast_rays` (AVX2 where the processor
//! has it), `cast_rays_portable`, and on an AVX2 processor the AVX2 walk with the other
//! processor family's steps between refills (`cast_rays_avx2_other_family`).
//! `ray_vs_brute_force.rs` proves `cast_ray` itself right; this file ties the batch to it.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use crate::generators;

use generators::{query_filter, tile_chars, tile_map};
use proptest::prelude::*;
use tileslide::io::ascii;
use tileslide::{Owner, QueryFilter, Ray, RayHit, Segment, SegmentFlags, TemporarySegment, Vec2};

/// Every bit of an answer, so that `-0.0` and `0.0` (equal as floats) count as different.
fn bits(hit: &Option<RayHit>) -> Option<(Vec<u32>, String)> {
    hit.map(|h| {
        let floats = [h.t, h.point.x, h.point.y, h.normal.x, h.normal.y];
        let mut words: Vec<u32> = floats.iter().map(|f| f.to_bits()).collect();
        words.push(h.flags.0);
        (words, format!("{:?}", h.source))
    })
}

/// A ray in grid units: a start and an end, each either anywhere or snapped to the lattice
/// (grid lines, corners), so that the fast walk's every exit is taken.
fn grid_ray(width: u32, height: u32) -> impl Strategy<Value = (Vec2, Vec2)> {
    let (w, h) = (width as f32, height as f32);
    let point = move || {
        (-3.0f32..w + 3.0, -3.0f32..h + 3.0, 0u8..6).prop_map(|(x, y, snap)| match snap {
            0 => Vec2::new(x.round(), y),
            1 => Vec2::new(x, y.round()),
            2 => Vec2::new(x.round(), y.round()),
            _ => Vec2::new(x, y),
        })
    };
    (point(), point(), 0u8..9).prop_map(|(a, b, kind)| match kind {
        // Along an axis, and exactly diagonal (through every corner it meets).
        0 => (a, Vec2::new(b.x, a.y)),
        1 => (a, Vec2::new(a.x, b.y)),
        2 => (a, a + Vec2::splat((b.x - a.x).round())),
        // Diagonal from a start whose fractions are equal: through the corner of every
        // cell it crosses, where both side cells must be visited.
        3 => {
            let f = a.x - a.x.floor();
            let start = Vec2::new(a.x.floor() + f, a.y.floor() + f);
            let d = (b - a).signum() * (b - a).abs().max_element();
            (start, start + d)
        }
        4 => (a, a),
        _ => (a, b),
    })
}

const CELLS: [f32; 3] = [1.0, 0.5, 32.0];
const ORIGINS: [(f32, f32); 3] = [(0.0, 0.0), (-3.5, 12.25), (0.1, -7.3)];

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn batch_answers_are_single_answers_bit_for_bit(
        (width, chars, rays) in (1u32..=20, 1u32..=20).prop_flat_map(|(w, h)| (
            Just(w),
            tile_chars(&[(6, '.'), (6, '#'), (1, '/'), (1, '\\'), (1, '=')], (w * h) as usize),
            proptest::collection::vec(grid_ray(w, h), 0..150),
        )),
        cell in 0usize..CELLS.len(),
        origin in 0usize..ORIGINS.len(),
        filter in query_filter(),
        temporary in any::<bool>(),
    ) {
        let (cell, origin) = (CELLS[cell], Vec2::from(ORIGINS[origin]));
        let mut map = tile_map(width, &chars, cell, origin);
        if temporary {
            map.add_temporary(TemporarySegment {
                segment: Segment::new(origin, origin + Vec2::new(3.0, 2.0) * cell),
                normal: Vec2::new(-2.0, 3.0).normalize(),
                flags: SegmentFlags::SOLID,
                owner: Owner(1),
                velocity: Vec2::ZERO,
            }).unwrap();
        }
        let rays: Vec<Ray> = rays
            .iter()
            .map(|&(a, b)| Ray::between(origin + a * cell, origin + b * cell))
            .collect();
        // `cast_rays` takes the AVX2 walk where the processor has it; the portable walk
        // is checked too, so that both instruction sets are proven on such machines.
        let batch = map.cast_rays(&rays, &filter);
        let portable = map.cast_rays_portable(&rays, &filter);
        // And the AVX2 walk with the other processor family's steps between refills.
        let other = map.cast_rays_avx2_other_family(&rays, &filter);
        prop_assert_eq!(batch.len(), rays.len());
        prop_assert_eq!(portable.len(), rays.len());
        for (i, ((ray, answer), portable)) in rays.iter().zip(&batch).zip(&portable).enumerate() {
            let single = map.cast_ray(*ray, &filter);
            prop_assert_eq!(bits(answer), bits(&single), "ray {:?}", ray);
            prop_assert_eq!(bits(portable), bits(&single), "portable, ray {:?}", ray);
            if let Some(other) = &other {
                prop_assert_eq!(bits(&other[i]), bits(&single), "other AVX2, ray {:?}", ray);
            }
        }
    }
}

#[test]
fn rays_the_fast_walk_declines_get_the_single_answer() {
    let map = ascii::parse("######\n#....#\n#.#..#\n#....#\n######", "t.txt", 1.0).unwrap();
    let v = Vec2::new;
    let rays = [
        // On a grid line, through a lattice point, along an axis, from outside the map.
        Ray::between(v(1.0, 1.5), v(7.5, 1.5)),
        Ray::between(v(1.5, 1.5), v(7.5, 7.5)),
        Ray::between(v(1.5, 3.5), v(1.5, 0.2)),
        Ray::between(v(-2.0, 1.7), v(3.1, 1.9)),
        // Zero length, NaN, infinite: no hit.
        Ray::between(v(1.5, 1.5), v(1.5, 1.5)),
        Ray::between(v(f32::NAN, 1.5), v(3.0, 1.5)),
        Ray {
            origin: v(1.5, 1.5),
            delta: v(f32::INFINITY, 0.0),
        },
        // An ordinary ray, decided by the fast walk. (Every ray that ends beyond the
        // border hits a wall.)
        Ray::between(v(1.3, 3.6), v(9.7, 0.2)),
    ];
    let filter = QueryFilter::default();
    let batch = map.cast_rays(&rays, &filter);
    for (ray, answer) in rays.iter().zip(&batch) {
        assert_eq!(bits(answer), bits(&map.cast_ray(*ray, &filter)), "{ray:?}");
    }
    assert!(batch[0].is_some() && batch[1].is_some() && batch[7].is_some());
    assert!(batch[4].is_none() && batch[5].is_none() && batch[6].is_none());
}

#[test]
fn many_rays_fill_many_lanes_and_the_buffer_is_reused() {
    // More rays than the lanes and the waiting groups hold, so lanes are refilled many
    // times; then a shorter batch into the same buffer, which is cleared first.
    let map = ascii::parse(
        "##########\n#...#....#\n#.#....#.#\n#....#...#\n##########",
        "t.txt",
        1.0,
    )
    .unwrap();
    let rays: Vec<Ray> = (0..5_000)
        .map(|i| {
            let a = i as f32 * 0.618_034 * std::f32::consts::TAU;
            let from = Vec2::new(1.5 + (i % 7) as f32 * 0.9, 1.3 + (i % 3) as f32 * 0.8);
            Ray {
                origin: from,
                delta: Vec2::new(a.cos(), a.sin()) * (1.0 + (i % 11) as f32),
            }
        })
        .collect();
    let filter = QueryFilter::default();
    let mut out = Vec::new();
    map.cast_rays_into(&rays, &filter, &mut out);
    assert_eq!(out.len(), rays.len());
    let hits = out.iter().filter(|h| h.is_some()).count();
    assert!(hits > 4_000, "{hits} hits");
    let portable = map.cast_rays_portable(&rays, &filter);
    let other = map.cast_rays_avx2_other_family(&rays, &filter);
    for (i, ((ray, answer), portable)) in rays.iter().zip(&out).zip(&portable).enumerate() {
        let single = bits(&map.cast_ray(*ray, &filter));
        assert_eq!(bits(answer), single);
        assert_eq!(bits(portable), single);
        if let Some(other) = &other {
            assert_eq!(bits(&other[i]), single);
        }
    }
    // The portable walk into a reused buffer: cleared, then as long as its rays.
    let mut reused = vec![None; 7];
    map.cast_rays_portable_into(&rays[..100], &filter, &mut reused);
    assert_eq!(reused, portable[..100]);
    map.cast_rays_into(&rays[..3], &filter, &mut out);
    assert_eq!(out.len(), 3);
    map.cast_rays_into(&[], &filter, &mut out);
    assert!(out.is_empty());
}

/// A batch large enough to be split across threads (the `parallel` feature) answers every
/// ray as `cast_ray` does on 1, 2, 3 and 8 threads; without the feature, on one.
#[test]
fn a_batch_split_across_threads_answers_as_one_thread() {
    let map = ascii::parse(
        "############\n#...#......#\n#.#..../..#\n#....#..=.##\n#.\\.......#\n############",
        "t.txt",
        1.0,
    )
    .unwrap();
    // 20,011 rays: several blocks of 4,096 and a ragged last one.
    let rays: Vec<Ray> = (0..20_011)
        .map(|i| {
            let a = i as f32 * 0.618_034 * std::f32::consts::TAU;
            let from = Vec2::new(1.2 + (i % 9) as f32 * 1.1, 1.3 + (i % 4) as f32 * 0.9);
            Ray {
                origin: from,
                delta: Vec2::new(a.cos(), a.sin()) * (0.5 + (i % 13) as f32),
            }
        })
        .collect();
    let single: Vec<_> = rays
        .iter()
        .map(|ray| bits(&map.cast_ray(*ray, &QueryFilter::default())))
        .collect();
    // The default filter takes the batch walk; one for both faces, the single casts (split
    // across threads too).
    let one_way_off = QueryFilter::both_sides();
    let skipping: Vec<_> = rays
        .iter()
        .map(|ray| bits(&map.cast_ray(*ray, &one_way_off)))
        .collect();
    for threads in [1, 2, 3, 8] {
        let (batch, other) = generators::on_threads(threads, || {
            (
                map.cast_rays(&rays, &QueryFilter::default()),
                map.cast_rays(&rays, &one_way_off),
            )
        });
        let batch: Vec<_> = batch.iter().map(bits).collect();
        let other: Vec<_> = other.iter().map(bits).collect();
        assert!(batch == single, "{threads} threads: the batch walk differs");
        assert!(
            other == skipping,
            "{threads} threads: the single casts differ"
        );
    }
}
