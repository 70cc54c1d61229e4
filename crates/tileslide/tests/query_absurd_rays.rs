//! Proves that ray casts answer every finite ray, however absurd: origins and lengths up to
//! `f32::MAX`, origins millions of cells from the map, lengths down to the subnormal range
//! (where `t` itself is subnormal). For each such ray `cast_ray`, the first hit of
//! `cast_ray_all` and `cast_rays` (both instruction sets) agree bit for bit, nothing
//! panics, `t` lies in `[0, 1]` and the point is finite, and the hit is the nearest of a
//! brute-force test of every active and temporary segment with `cast_ray_segment`, to the
//! bit on maps whose lattice points are exact.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use crate::generators;

use std::sync::Arc;

use generators::{small_map_at, tile_chars, tile_map};
use proptest::prelude::*;
use tileslide::io::ascii;
use tileslide::{
    Cell, Faces, QueryFilter, Ray, RayHit, Segment, SegmentSource, TileId, TileMap, Vec2,
    geometry::cast_ray_segment,
};

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

/// Every bit of an answer, so that `-0.0` and `0.0` (equal as floats) count as different.
fn bits(hit: Option<&RayHit>) -> Option<(Vec<u32>, String)> {
    hit.map(|h| {
        let floats = [h.t, h.point.x, h.point.y, h.normal.x, h.normal.y];
        let mut words: Vec<u32> = floats.iter().map(|f| f.to_bits()).collect();
        words.push(h.flags.0);
        (words, format!("{:?}", h.source))
    })
}

/// Whether the casts walk `ray` in `f32` (the rule of `docs/ray-casting.md`, restated): it
/// starts within the map's larger side plus 8 cells of the map, and each axis of its
/// motion is 0 or between 2⁻³² and 2³² cells.
fn ordinary(map: &TileMap, ray: &Ray) -> bool {
    let inv = map.cell_size().recip();
    let (o, d) = ((ray.origin - map.origin()) * inv, ray.delta * inv);
    let (w, h) = (map.width() as f32, map.height() as f32);
    let m = w.max(h) + 8.0;
    let near = o.x >= -m && o.x <= w + m && o.y >= -m && o.y <= h + m;
    let length_ok = |x: f32| x == 0.0 || (x.abs() >= 2f32.powi(-32) && x.abs() <= 2f32.powi(32));
    near && length_ok(d.x) && length_ok(d.y)
}

/// A hit of the brute force: the segment, its `t` by the kernel the casts use for the ray,
/// and whether the casts must find it.
#[derive(Clone, Copy, Debug)]
struct BruteHit {
    key: Key,
    t: f32,
    required: bool,
}

/// Which segment a hit is on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Key {
    Tile(Cell, u32),
    Temporary(usize),
}

fn key_of(hit: &RayHit) -> Key {
    match hit.source {
        SegmentSource::Tile { segment, .. } => Key::Tile(segment.cell, segment.index),
        SegmentSource::Temporary { index, .. } => Key::Temporary(index),
        // The brute force lists tile and temporary segments only: a hit on anything else
        // is one it cannot check.
        other => panic!("a segment source the brute force does not list: {other:?}"),
    }
}

/// The ray–segment kernel in `f64` (`cast_ray_segment`'s rule, with exact products),
/// restated: `t` rounded to `f32`.
fn solve_f64(ray: &Ray, segment: &Segment) -> Option<f32> {
    let (o, d) = (ray.origin.as_dvec2(), ray.delta.as_dvec2());
    let (a, e) = (segment.a.as_dvec2(), segment.delta().as_dvec2());
    let den = d.perp_dot(e);
    let w = a - o;
    let sign = 1.0f64.copysign(den);
    let (den, tn, sn) = (den * sign, w.perp_dot(e) * sign, w.perp_dot(d) * sign);
    let crossing = den > f64::from(tileslide::geometry::PARALLEL_TOLERANCE) * e.length_squared();
    let inside = crossing && tn >= 0.0 && tn <= den && sn >= 0.0 && sn <= den;
    inside.then(|| (tn / den) as f32)
}

/// Whether a hit of the kernel with unit rounding `eps` must be found: it lies inside the
/// hit region (`0 ≤ t, s ≤ 1`, crossing) by more than the rounding of the kernel and of
/// this `f64` check can move its edges (|Δ| ≲ 2ε·|u||v| for each cross product of u and
/// v). A contact closer to an edge than that is optional: rounding decides it, and the
/// walk, which follows the exact line within a tolerance, may see it either way.
fn required(ray: &Ray, segment: &Segment, eps: f64) -> bool {
    let (o, d) = (ray.origin.as_dvec2(), ray.delta.as_dvec2());
    let (a, e) = (segment.a.as_dvec2(), segment.delta().as_dvec2());
    let w = a - o;
    let (den, tn, sn) = (d.perp_dot(e), w.perp_dot(e), w.perp_dot(d));
    let sign = if den < 0.0 { -1.0 } else { 1.0 };
    let (den, tn, sn) = (den * sign, tn * sign, sn * sign);
    let c = 2.0 * eps + 4.0 * f64::EPSILON;
    let err_den = c * d.length() * e.length();
    let err_tn = c * w.length() * e.length();
    let err_sn = c * w.length() * d.length();
    let threshold = f64::from(tileslide::geometry::PARALLEL_TOLERANCE) * e.length_squared();
    den > threshold * (1.0 + 1e-5) + err_den
        && tn > err_tn
        && den - tn > err_tn + err_den
        && sn > err_sn
        && den - sn > err_sn + err_den
}

/// Every hit of a brute-force test of every active and temporary segment that the filter
/// lets the ray hit (`QueryFilter::accepts`), by
/// `cast_ray_segment` for an ordinary ray and by the `f64` kernel for any other.
fn brute_hits(map: &TileMap, ray: &Ray, filter: &QueryFilter) -> Vec<BruteHit> {
    let wide = !ordinary(map, ray);
    let eps = if wide {
        f64::EPSILON
    } else {
        f64::from(f32::EPSILON)
    };
    let mut hits = Vec::new();
    let mut consider = |key: Key, segment: &Segment| {
        let t = if wide {
            solve_f64(ray, segment)
        } else {
            cast_ray_segment(ray, segment).map(|h| h.t)
        };
        if let Some(t) = t {
            let required = required(ray, segment, eps);
            hits.push(BruteHit { key, t, required });
        }
    };
    for row in 0..map.height() {
        for col in 0..map.width() {
            let cell = Cell::new(col, row);
            for (i, s) in map.active_segments(cell).enumerate() {
                if filter.accepts(ray.delta, s.normal, s.flags, None) {
                    consider(Key::Tile(cell, i as u32), &s.segment);
                }
            }
        }
    }
    for (i, t) in map.temporaries().iter().enumerate() {
        if filter.accepts(ray.delta, t.normal, t.flags, Some(t.owner)) {
            consider(Key::Temporary(i), &t.segment);
        }
    }
    hits
}

/// Checks one ray: the casts agree bit for bit, every hit is sane and is a brute-force hit
/// at the very same `t`, and every hit the brute force requires is found (so `cast_ray`'s
/// hit, the first of them all, is the nearest).
fn check(map: &TileMap, ray: Ray, filter: &QueryFilter) -> Result<(), TestCaseError> {
    let single = map.cast_ray(ray, filter);
    let all = map.cast_ray_all(ray, filter);
    let batch = map.cast_rays(&[ray], filter);
    let portable = map.cast_rays_portable(&[ray], filter);
    prop_assert_eq!(
        bits(single.as_ref()),
        bits(all.first()),
        "ray {:?}: all {:?}",
        ray,
        all
    );
    prop_assert_eq!(
        bits(single.as_ref()),
        bits(batch[0].as_ref()),
        "batch, ray {:?}",
        ray
    );
    prop_assert_eq!(
        bits(single.as_ref()),
        bits(portable[0].as_ref()),
        "portable, ray {:?}",
        ray
    );
    prop_assert!(
        all.windows(2).all(|p| p[0].t <= p[1].t),
        "unsorted {:?}",
        all
    );
    let brute = brute_hits(map, &ray, filter);
    for h in &all {
        prop_assert!(
            (0.0..=1.0).contains(&h.t),
            "t {} of {:?}, ray {:?}",
            h.t,
            h,
            ray
        );
        prop_assert!(h.point.is_finite(), "point of {:?}, ray {:?}", h, ray);
        prop_assert!(
            brute
                .iter()
                .any(|b| b.key == key_of(h) && b.t.to_bits() == h.t.to_bits()),
            "ray {:?}: {:?} is not a brute-force hit: {:?}",
            ray,
            h,
            brute
        );
    }
    for b in brute.iter().filter(|b| b.required) {
        prop_assert!(
            all.iter().any(|h| key_of(h) == b.key),
            "ray {:?}: misses {:?}; got {:?}",
            ray,
            b,
            all
        );
    }
    Ok(())
}

#[test]
fn finite_ray_whose_grid_length_overflows_does_not_panic_and_hits_the_wall() {
    // Delta / cell size overflows to infinity: the grid walk's inverse became 0, its stop
    // fraction NaN, and the walk ran off the map (index out of bounds in `fast_walk`).
    let map = ascii::parse("...\n...\n..#", "open.txt", 0.5).unwrap();
    let ray = Ray::between(v(0.2565, 0.2605), v(0.5565, 3.4e38));
    check(&map, ray, &QueryFilter::default()).unwrap();
    // Straight up the middle column the ray leaves the map without a hit; through the
    // solid cell's column it hits its floor.
    let up = Ray {
        origin: v(1.25, 0.25),
        delta: v(1e-30, 3.4e38),
    };
    let hit = map.cast_ray(up, &QueryFilter::default()).unwrap();
    assert_eq!(hit.normal, v(0.0, -1.0));
    assert_eq!(hit.point.y, 1.0);
    check(&map, up, &QueryFilter::default()).unwrap();
}

#[test]
fn cast_ray_all_never_reports_nan_far_out() {
    // Around 1e27 the ray–segment solve overflowed its numerator and denominator to
    // infinity and accepted them as a hit at t = NaN.
    let map = ascii::parse("####\n#..#\n####", "box.txt", 1.0).unwrap();
    for scale in [1e19f32, 1e25, 1e27, 1e30, 1e35, 1.5e38] {
        let ray = Ray::between(v(-scale, -scale * 0.5), v(scale, scale * 0.5 + 1.0));
        check(&map, ray, &QueryFilter::default()).unwrap();
        check(
            &map,
            ray,
            &QueryFilter {
                faces: Faces::Both,
                ..QueryFilter::default()
            },
        )
        .unwrap();
        let back = Ray::between(ray.end(), ray.origin);
        check(&map, back, &QueryFilter::default()).unwrap();
    }
}

#[test]
fn subnormal_t_agrees_between_casts() {
    // A wall at x = 1 a hair in front of the origin on a ray of huge length: t ≈ 1e-40.
    let map = ascii::parse("..#\n..#\n..#", "wall.txt", 1.0).unwrap();
    for (gap, length) in [
        (1e-7f32, 1e33f32),
        (1e-7, 1e38),
        (1e-30, 1e10),
        (1e-38, 1.0),
    ] {
        let ray = Ray {
            origin: v(2.0 - gap, 1.5),
            delta: v(length, length * 1e-3),
        };
        check(&map, ray, &QueryFilter::default()).unwrap();
    }
    // Subnormal t on an ordinary ray: a start a subnormal distance before the map's left
    // border (a wall at x = 0), on a ray 2³¹ cells long.
    let map = ascii::parse("#..\n#..\n#..", "border.txt", 1.0).unwrap();
    for gap in [1e-40f32, 1e-44, 1e-30, 0.0] {
        let ray = Ray {
            origin: v(-gap, 1.5),
            delta: v(2f32.powi(31), 3.0),
        };
        check(&map, ray, &QueryFilter::default()).unwrap();
        // The wall is hit; `t` (gap / 2³¹) rounds to 0 or a subnormal, so the point is the
        // origin, within the gap of the wall.
        let hit = map.cast_ray(ray, &QueryFilter::default()).unwrap();
        assert_eq!(hit.normal, v(-1.0, 0.0), "gap {gap}");
        assert!(
            hit.t <= gap && hit.point.x.abs() <= gap,
            "gap {gap}: {hit:?}"
        );
    }
}

#[test]
fn ray_from_millions_of_cells_away_agrees_between_casts() {
    let map = ascii::parse("#.#.\n.#..\n..#.\n#...", "far.txt", 1.0).unwrap();
    for far in [1e6f32, 16_777_216.0, 16_800_000.0, 1e9] {
        for (sx, sy) in [(1.0, 0.37), (-1.0, 0.61), (0.29, -1.0), (-0.73, 1.0)] {
            let target = v(2.1, 1.9);
            let dir = v(sx, sy);
            let ray = Ray {
                origin: target - dir * far,
                delta: dir * (far * 2.0),
            };
            check(&map, ray, &QueryFilter::default()).unwrap();
        }
    }
}

/// Small random maps, on cell sizes and origins whose lattice points are exact.
fn small_map() -> impl Strategy<Value = TileMap> {
    small_map_at(|_, _, _, k| [v(0.0, 0.0), v(-3.5, 12.25), v(1000.0, -64.0)][k])
}

/// A power of two from 2⁻¹⁴⁹ to 2¹²⁷ times a mantissa in [1, 2), with a random sign.
fn magnitude() -> impl Strategy<Value = f32> {
    (-149i32..=127, 1.0f32..2.0, any::<bool>()).prop_map(|(e, m, neg)| {
        let x = (m * 2f32.powi(e.max(-126))) * 2f32.powi((e + 126).min(0));
        let x = if x.is_finite() { x } else { f32::MAX };
        if neg { -x } else { x }
    })
}

/// Absurd rays around a map of `w × h` cells of `cell` at `origin`.
fn absurd_ray(w: u32, h: u32, cell: f32, origin: Vec2) -> impl Strategy<Value = Ray> {
    let (wf, hf) = (w as f32, h as f32);
    let near =
        (-2.0f32..wf + 2.0, -2.0f32..hf + 2.0).prop_map(move |(x, y)| origin + v(x, y) * cell);
    prop_oneof![
        // From near the map, of any length (huge or subnormal).
        (near.clone(), magnitude(), magnitude()).prop_map(|(p, dx, dy)| Ray {
            origin: p,
            delta: v(dx, dy),
        }),
        // From far away, aimed through a point near the map, reaching it or not.
        (
            near.clone(),
            magnitude(),
            -1.0f32..1.0,
            -1.0f32..1.0,
            0.5f32..3.0
        )
            .prop_map(|(p, far, dx, dy, k)| {
                let dir = v(dx, dy);
                let far = far.abs().min(f32::MAX / 4.0);
                Ray {
                    origin: p - dir * far,
                    delta: dir * (far * k),
                }
            }),
        // A hair in front of a point near the map, along a huge or tiny delta.
        (near, -40i32..=0, magnitude(), magnitude()).prop_map(|(p, gap, dx, dy)| Ray {
            origin: p - v(dx, dy).signum() * 2f32.powi(gap * 3),
            delta: v(dx, dy),
        }),
        // Anything finite.
        (magnitude(), magnitude(), magnitude(), magnitude()).prop_map(|(a, b, c, d)| Ray {
            origin: v(a, b),
            delta: v(c, d),
        }),
    ]
}

/// A map of `maps` with `n` rays of `rays_for` it.
fn map_and_rays<R: Strategy<Value = Ray>>(
    maps: impl Strategy<Value = TileMap>,
    rays_for: impl Fn(&TileMap) -> R,
    n: usize,
) -> impl Strategy<Value = (TileMap, Vec<Ray>)> {
    maps.prop_flat_map(move |m| {
        let rays = proptest::collection::vec(rays_for(&m), n);
        (Just(m), rays)
    })
}

/// Front faces only, or `Faces::Both` when `both`.
fn front_or_both(both: bool) -> QueryFilter {
    if both {
        QueryFilter {
            faces: Faces::Both,
            ..QueryFilter::default()
        }
    } else {
        QueryFilter::default()
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn absurd_finite_rays_get_the_brute_force_answer_from_every_cast(
        (map, rays) in map_and_rays(
            small_map(),
            |m| absurd_ray(m.width(), m.height(), m.cell_size().x, m.origin()),
            32,
        ),
        both in any::<bool>(),
    ) {
        let filter = front_or_both(both);
        for ray in rays {
            check(&map, ray, &filter)?;
        }
    }
}

#[test]
fn circle_cast_of_any_finite_length_stops_at_the_wall() {
    // The swept box's grid coordinates overflowed, so no cell was tested and the circle
    // passed through the wall.
    let map = ascii::parse("....#", "wall.txt", 0.5).unwrap();
    for length in [10.0f32, 1e8, 1e20, 1e30, 3.4e38] {
        let hit = map
            .cast_circle(v(0.5, 0.25), 0.1, v(length, 0.0), &QueryFilter::default())
            .unwrap()
            .unwrap_or_else(|| panic!("length {length}: no hit"));
        assert_eq!(hit.normal, v(-1.0, 0.0), "length {length}");
        assert!(
            (hit.center.x - 1.9).abs() < 1e-5,
            "length {length}: {hit:?}"
        );
        assert!(
            (hit.t * length - 1.4).abs() < 1e-4 * 1.4,
            "length {length}: {hit:?}"
        );
    }
    // A motion longer than 2^27 along an axis is swept as its exact scaling by a power of
    // two down to 2^27: the answer is that one's, with `t` scaled back.
    let filter = QueryFilter::default();
    let short = map
        .cast_circle(v(0.5, 0.25), 0.1, v(2f32.powi(27), 0.0), &filter)
        .unwrap();
    let long = map
        .cast_circle(v(0.5, 0.25), 0.1, v(2f32.powi(90), 0.0), &filter)
        .unwrap();
    let (short, long) = (short.unwrap(), long.unwrap());
    assert_eq!(short.t * 2f32.powi(-63), long.t);
    assert_eq!(
        (short.center, short.normal, short.point),
        (long.center, long.normal, long.point)
    );
}

/// Rays grazing an active segment of `map` (or, on a map without any, its bottom edge):
/// through a point of the segment's line from half a length before it to half a length
/// after it (often near an end), at 10^-5.5 to 10^-2 radians to it, either way along it, from up to 6 cells
/// before that point to up to 6 cells after it. At such angles the intersection's `t` is
/// ill-conditioned: `f32` can place a hit on a segment of a later cell before the cell is
/// entered, and before the nearest hit `cast_ray` stops at.
fn grazing_ray(map: &TileMap) -> impl Strategy<Value = Ray> + use<> {
    let mut segments: Vec<Segment> = (0..map.height())
        .flat_map(|row| (0..map.width()).map(move |col| Cell::new(col, row)))
        .flat_map(|cell| {
            map.active_segments(cell)
                .map(|s| s.segment)
                .collect::<Vec<_>>()
        })
        .collect();
    let cell = map.cell_size().x;
    if segments.is_empty() {
        let o = map.origin();
        segments.push(Segment::new(o, o + v(map.width() as f32 * cell, 0.0)));
    }
    (
        proptest::sample::select(segments),
        prop_oneof![
            -0.5f32..1.5,
            // Near an end, where the neighbour along a surface is hit as well.
            (any::<bool>(), -0.02f32..0.02).prop_map(|(b, d)| if b { 1.0 + d } else { d }),
        ],
        -5.5f32..-2.0,
        any::<bool>(),
        any::<bool>(),
        0.0f32..6.0,
        0.0f32..6.0,
    )
        .prop_map(move |(seg, f, log_angle, ccw, reverse, before, after)| {
            let e = seg.delta();
            let along = e / e.length() * if reverse { -1.0 } else { 1.0 };
            let angle = 10f32.powf(log_angle) * if ccw { 1.0 } else { -1.0 };
            let dir = Vec2::from_angle(angle).rotate(along);
            let through = seg.a + e * f;
            Ray {
                origin: through - dir * (before * cell),
                delta: dir * ((before + after) * cell),
            }
        })
}

/// The rule of `cast_ray_all`: its first hit is `cast_ray`'s, bit for bit (none when
/// `cast_ray` has none), the rest follow sorted by `t`, and no segment is listed twice.
fn check_first_hit_is_cast_rays(
    map: &TileMap,
    ray: Ray,
    filter: &QueryFilter,
) -> Result<(), TestCaseError> {
    let single = map.cast_ray(ray, filter);
    let all = map.cast_ray_all(ray, filter);
    prop_assert_eq!(
        bits(single.as_ref()),
        bits(all.first()),
        "ray {:?}: cast_ray {:?}, all {:?}",
        ray,
        single,
        all
    );
    prop_assert!(
        all.windows(2).all(|p| p[0].t <= p[1].t),
        "ray {:?}: unsorted {:?}",
        ray,
        all
    );
    for (i, h) in all.iter().enumerate() {
        prop_assert!(
            all[..i].iter().all(|k| k.source != h.source),
            "ray {:?}: {:?} listed twice in {:?}",
            ray,
            h,
            all
        );
    }
    Ok(())
}

/// Small random maps of slopes and blocks on origins whose lattice points are not exact
/// (so stored end points and neighbours' `b − a` carry rounding).
fn inexact_map() -> impl Strategy<Value = TileMap> {
    (2u32..=8, 2u32..=8, 0usize..3, 0usize..2).prop_flat_map(|(w, h, cell, origin)| {
        let cell = [1.0f32, 0.5, 0.25][cell];
        let origin = [v(0.1, 0.1), v(-7.3, 2.9)][origin];
        tile_chars(&[(3, '.'), (2, '#'), (2, '/'), (2, '\\')], (w * h) as usize)
            .prop_map(move |chars| tile_map(w, &chars, cell, origin))
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(600))]

    /// `cast_ray_all` starts with `cast_ray`'s hit for rays grazing the map's segments
    /// (and through their ends and the lattice points where slopes meet), where the two
    /// differed: the list put first a hit that `f32` placed a hair before the one
    /// `cast_ray` stopped at, in a cell `cast_ray` rightly did not walk to.
    #[test]
    fn cast_ray_all_starts_with_cast_rays_hit_for_grazing_rays(
        (map, rays) in map_and_rays(prop_oneof![small_map(), inexact_map()], grazing_ray, 64),
        both in any::<bool>(),
    ) {
        let filter = front_or_both(both);
        for ray in rays {
            check_first_hit_is_cast_rays(&map, ray, &filter)?;
            check_first_hit_is_cast_rays(&map, Ray { origin: ray.end(), delta: -ray.delta }, &filter)?;
        }
    }
}

/// A map of `width` × `height` half cells at (−3.5, 12.25), row by row, of the tiles of the
/// ASCII set with the ids `ids` (0: none).
fn half_cells(width: u32, height: u32, ids: &[u32]) -> TileMap {
    let tiles: Vec<Option<TileId>> = ids
        .iter()
        .map(|&id| (id != 0).then_some(TileId(id)))
        .collect();
    let set = Arc::new(ascii::tile_set(0.5).unwrap());
    TileMap::from_tiles(set, width, height, Vec2::new(-3.5, 12.25), &tiles).unwrap()
}

/// Where each hit is: its height, and its cell's column and row.
fn floors(hits: &[RayHit]) -> Vec<(f32, Option<(u32, u32)>)> {
    hits.iter()
        .map(|h| (h.point.y, h.cell().map(|c| (c.col, c.row))))
        .collect()
}

/// Regression: a long ray running a hair beside a grid line, from far enough to take the
/// `f64` path, was walked on the wrong side of the line, and `cast_ray_all` listed the
/// first floor it crosses but missed the ones after it (found by
/// `absurd_finite_rays_get_the_brute_force_answer_from_every_cast`). From (−6e-8, 1) with
/// delta (1, 2.7e8) on a map of half cells at (−3.5, 12.25), the ray runs down just left of
/// x = 0 through column 6: the squares of rows 0 and 3 (tops at y = 12.25 and 13.75) face
/// it, and it crosses the second at x ≈ −1.2e-8, t ≈ 4.75e-8.
#[test]
fn a_long_ray_a_hair_beside_a_grid_line_lists_every_floor_it_crosses() {
    #[rustfmt::skip]
    let map = half_cells(8, 6, &[
        2, 1, 4, 1, 1, 2, 1, 0,
        0, 0, 0, 0, 4, 3, 4, 2,
        0, 3, 0, 2, 1, 1, 0, 1,
        0, 0, 0, 2, 1, 2, 1, 3,
        3, 0, 3, 2, 4, 1, 2, 0,
        1, 1, 1, 0, 2, 0, 3, 1,
    ]);
    let ray = Ray {
        origin: Vec2::new(-5.960_464_5e-8, 1.0),
        delta: Vec2::new(1.0, 268_435_460.0),
    };
    let hit = map.cast_ray(ray, &QueryFilter::default());
    let hit = hit.expect("the ray crosses the top of cell (6, 0)");
    assert_eq!((hit.normal, hit.point.y), (Vec2::new(0.0, -1.0), 12.25));
    let all = map.cast_ray_all(ray, &QueryFilter::default());
    assert_eq!(all.first().map(|h| h.point), Some(hit.point));
    let floors = floors(&all);
    assert!(
        floors.contains(&(13.75, Some((6, 3)))),
        "the square of row 3 is missing: {floors:?}"
    );
}

/// Regression: the same kind of ray a hair inside the map's own edge. From (−6e-8, 1) by
/// (0.25, 6.5e7) on a map of half cells at (−3.5, 12.25) whose right edge is x = 0, the
/// ray runs up through column 6 without leaving the map; rounded to `f32` grid units its
/// `f64` clipped piece lay on that edge, and the walk left the map after the first floor.
/// Both faces count: it crosses the tops of rows 3 and 7 from behind (y = 14.25, 16.25).
#[test]
fn a_long_ray_a_hair_inside_the_maps_edge_lists_every_floor_it_crosses() {
    #[rustfmt::skip]
    let map = half_cells(7, 8, &[
        1, 1, 0, 0, 1, 0, 1,
        1, 0, 2, 0, 3, 1, 4,
        0, 1, 0, 4, 1, 4, 0,
        0, 3, 1, 0, 0, 1, 2,
        0, 3, 1, 1, 1, 1, 0,
        2, 0, 2, 1, 1, 1, 2,
        1, 1, 4, 4, 1, 2, 1,
        4, 0, 2, 1, 2, 0, 1,
    ]);
    let ray = Ray {
        origin: Vec2::new(-5.960_464_5e-8, 1.0),
        delta: Vec2::new(0.25, 64_631_264.0),
    };
    let filter = QueryFilter {
        faces: Faces::Both,
        ..QueryFilter::default()
    };
    let all = map.cast_ray_all(ray, &filter);
    let first = map.cast_ray(ray, &filter).map(|h| h.point);
    assert_eq!(all.first().map(|h| h.point), first);
    let floors = floors(&all);
    for (y, row) in [(14.25, 3), (14.75, 5), (16.25, 7)] {
        assert!(
            floors
                .iter()
                .any(|&(fy, cell)| fy == y && cell == Some((6, row))),
            "the floor of row {row} at y = {y} is missing: {floors:?}"
        );
    }
}
