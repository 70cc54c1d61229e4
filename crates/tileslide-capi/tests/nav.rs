//! Paths and flow fields through the C API as C calls them: on the standard dungeon, 60
//! seeded paths of two radii and a flow field's directions and distances equal the core's
//! bit for bit, "no path" included; a buffer too small gets the count; bad input gets a
//! status and a message naming it.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic, unsafe_code)]

mod support;

use std::ptr;

use support::{ascii_map, assert_refused, core_map, core_nav, last_error};
use tileslide::{FlowField, Vec2};
use tileslide_capi::*;
use tileslide_scenes::{SplitMix64, crowd_candidates, dungeon256};

fn new_nav(map: *const ts_map, max_radius: f32) -> *mut ts_nav {
    let mut nav = ptr::null_mut();
    // SAFETY: a live map and a writable out pointer.
    let status = unsafe { ts_nav_create(map, max_radius, &mut nav) };
    assert_eq!(status, ts_status::TS_OK, "{}", last_error());
    nav
}

/// The path's corners through C, as bits; empty for no path.
fn c_path(
    nav: *const ts_nav,
    map: *const ts_map,
    from: Vec2,
    to: Vec2,
    radius: f32,
) -> Vec<[u32; 2]> {
    // SAFETY: live grid and map; `out` has room for `capacity` corners.
    let find = |out: *mut f32, capacity: usize, count: &mut usize| unsafe {
        ts_nav_find_path(
            nav, map, from.x, from.y, to.x, to.y, radius, out, capacity, count,
        )
    };
    // Capacity 0 asks how many, then room for them.
    let mut n = 0;
    let status = find(ptr::null_mut(), 0, &mut n);
    if n == 0 {
        assert_eq!(status, ts_status::TS_OK, "{}", last_error());
        return Vec::new();
    }
    assert_eq!(status, ts_status::TS_ERROR_BUFFER_TOO_SMALL);
    let mut xy = vec![f32::NAN; 2 * n];
    let mut m = 0;
    assert_eq!((find(xy.as_mut_ptr(), n, &mut m), m), (ts_status::TS_OK, n));
    xy.chunks_exact(2)
        .map(|p| [p[0].to_bits(), p[1].to_bits()])
        .collect()
}

#[test]
fn paths_and_a_flow_field_through_c_equal_the_cores_bit_for_bit() {
    let grid = dungeon256();
    let text = grid.to_ascii();
    let map = ascii_map(&text);
    let core_map = core_map(&text);
    let nav = new_nav(map, 0.5);
    let core_nav = core_nav(&core_map, 0.5);
    let spots = crowd_candidates(&grid);
    let mut rng = SplitMix64::new(0x9a7b);
    let (mut found, mut none) = (0, 0);
    for k in 0..60 {
        let from = rng.pick(&spots).unwrap();
        // Some goals in walls, so some ends do not fit.
        let to = if k % 6 == 0 {
            Vec2::new(rng.range(1.0, 255.0), rng.range(1.0, 255.0))
        } else {
            rng.pick(&spots).unwrap()
        };
        let radius = if k % 2 == 0 { 0.3 } else { 0.2 };
        let expected: Vec<[u32; 2]> = core_nav
            .find_path(&core_map, from, to, radius)
            .unwrap()
            .map_or_else(Vec::new, |p| {
                p.points()
                    .iter()
                    .map(|q| [q.x.to_bits(), q.y.to_bits()])
                    .collect()
            });
        let got = c_path(nav, map, from, to, radius);
        assert_eq!(got, expected, "path {k}: {from} to {to}, radius {radius}");
        if got.is_empty() {
            none += 1;
        } else {
            assert!(got.len() >= 2);
            found += 1;
        }
    }
    assert!(found > 40 && none > 3, "{found} paths, {none} without");
    // A flow field to one goal: each place's direction and distance.
    let goal = spots[spots.len() / 2];
    let mut field = ptr::null_mut();
    // SAFETY: live grid and map, a writable out pointer.
    let status = unsafe { ts_flow_field_create(nav, map, goal.x, goal.y, 0.3, &mut field) };
    assert_eq!(status, ts_status::TS_OK, "{}", last_error());
    let core_field = FlowField::new(&core_nav, &core_map, goal, 0.3).unwrap();
    let mut reached = 0;
    for _ in 0..100 {
        let p = rng.pick(&spots).unwrap();
        let (mut dx, mut dy, mut distance) = (f32::NAN, f32::NAN, f32::NAN);
        // SAFETY: live field, grid and map; writable outputs.
        unsafe {
            assert_eq!(
                ts_flow_field_direction(field, nav, map, p.x, p.y, &mut dx, &mut dy),
                ts_status::TS_OK
            );
            assert_eq!(
                ts_flow_field_distance(field, nav, map, p.x, p.y, &mut distance),
                ts_status::TS_OK
            );
        }
        let d = core_field
            .direction(&core_nav, &core_map, p)
            .unwrap()
            .unwrap_or(Vec2::ZERO);
        let far = core_field
            .distance(&core_nav, &core_map, p)
            .unwrap()
            .unwrap_or(f32::INFINITY);
        assert_eq!(
            [dx, dy, distance].map(f32::to_bits),
            [d.x, d.y, far].map(f32::to_bits),
            "at {p}"
        );
        reached += usize::from(distance.is_finite());
    }
    assert!(reached > 50, "{reached} of 100 reach the goal");
    // SAFETY: freed once.
    unsafe {
        ts_flow_field_free(field);
        ts_nav_free(nav);
        ts_map_free(map);
    }
}

#[test]
fn a_small_buffer_gets_the_count_and_no_path_is_not_an_error() {
    let map = ascii_map("#######\n#.....#\n#.###.#\n#.....#\n#######");
    let nav = new_nav(map, 1.0);
    // SAFETY: live grid and map; buffers as long as said.
    unsafe {
        let mut xy = [7.0_f32; 4];
        let mut n = 0;
        // Round the block: more than two corners.
        assert_refused(
            ts_nav_find_path(
                nav,
                map,
                1.5,
                1.5,
                5.5,
                3.5,
                0.3,
                xy.as_mut_ptr(),
                2,
                &mut n,
            ),
            ts_status::TS_ERROR_BUFFER_TOO_SMALL,
            "path corners do not fit in a buffer of 2",
        );
        assert!(n > 2, "{n}");
        assert_eq!(xy, [7.0; 4], "nothing written");
        let mut room = vec![0.0_f32; 2 * n];
        let mut m = 0;
        assert_eq!(
            ts_nav_find_path(
                nav,
                map,
                1.5,
                1.5,
                5.5,
                3.5,
                0.3,
                room.as_mut_ptr(),
                n,
                &mut m
            ),
            ts_status::TS_OK
        );
        assert_eq!(m, n);
        assert_eq!((room[0], room[1]), (1.5, 1.5));
        assert_eq!((room[2 * n - 2], room[2 * n - 1]), (5.5, 3.5));
        // Too wide for the corridors: no path, TS_OK, count 0, nothing written.
        m = 9;
        assert_eq!(
            ts_nav_find_path(
                nav,
                map,
                1.5,
                1.5,
                5.5,
                3.5,
                0.6,
                xy.as_mut_ptr(),
                2,
                &mut m
            ),
            ts_status::TS_OK
        );
        assert_eq!((m, xy), (0, [7.0; 4]));
        // A goal inside a wall: no path either.
        assert_eq!(
            ts_nav_find_path(
                nav,
                map,
                1.5,
                1.5,
                3.5,
                2.5,
                0.3,
                ptr::null_mut(),
                0,
                &mut m
            ),
            ts_status::TS_OK
        );
        assert_eq!(m, 0);
        ts_nav_free(nav);
        ts_map_free(map);
    }
}

#[test]
fn bad_radii_points_maps_and_pointers_are_refused_by_name() {
    use ts_status::*;
    let map = ascii_map("#####\n#...#\n#####");
    let other = ascii_map("#####\n#...#\n#####");
    // SAFETY: each call gets one bad argument on purpose; the rest are valid.
    unsafe {
        let mut nav = ptr::null_mut();
        for r in [0.0, -1.0, f32::NAN, 40.0] {
            assert_refused(
                ts_nav_create(map, r, &mut nav),
                TS_ERROR_INVALID_ARGUMENT,
                "max_radius",
            );
            assert!(nav.is_null());
        }
        assert_refused(
            ts_nav_create(ptr::null(), 1.0, &mut nav),
            TS_ERROR_NULL_POINTER,
            "map is a null pointer",
        );
        assert_refused(
            ts_nav_create(map, 1.0, ptr::null_mut()),
            TS_ERROR_NULL_POINTER,
            "out is a null pointer",
        );
        let nav = new_nav(map, 0.5);
        let mut xy = [0.0_f32; 8];
        let mut n = 0;
        let p = xy.as_mut_ptr();
        assert_refused(
            ts_nav_find_path(nav, map, f32::NAN, 1.5, 3.5, 1.5, 0.3, p, 4, &mut n),
            TS_ERROR_INVALID_ARGUMENT,
            "x0 is NaN",
        );
        assert_refused(
            ts_nav_find_path(nav, map, 1.5, 1.5, 3.5, f32::INFINITY, 0.3, p, 4, &mut n),
            TS_ERROR_INVALID_ARGUMENT,
            "y1 is inf",
        );
        assert_refused(
            ts_nav_find_path(nav, map, 1.5, 1e30, 3.5, 1.5, 0.3, p, 4, &mut n),
            TS_ERROR_INVALID_ARGUMENT,
            "y0 is",
        );
        assert_refused(
            ts_nav_find_path(nav, map, 1.5, 1.5, 3.5, 1.5, 0.8, p, 4, &mut n),
            TS_ERROR_INVALID_ARGUMENT,
            "radius 0.8",
        );
        assert_refused(
            ts_nav_find_path(nav, map, 1.5, 1.5, 3.5, 1.5, f32::NAN, p, 4, &mut n),
            TS_ERROR_INVALID_ARGUMENT,
            "radius NaN",
        );
        assert_refused(
            ts_nav_find_path(nav, other, 1.5, 1.5, 3.5, 1.5, 0.3, p, 4, &mut n),
            TS_ERROR_INVALID_ARGUMENT,
            "another map",
        );
        assert_refused(
            ts_nav_find_path(nav, map, 1.5, 1.5, 3.5, 1.5, 0.3, p, 4, ptr::null_mut()),
            TS_ERROR_NULL_POINTER,
            "count",
        );
        assert_refused(
            ts_nav_find_path(
                nav,
                map,
                1.5,
                1.5,
                3.5,
                1.5,
                0.3,
                ptr::null_mut(),
                4,
                &mut n,
            ),
            TS_ERROR_NULL_POINTER,
            "out",
        );
        assert_refused(
            ts_nav_find_path(ptr::null(), map, 1.5, 1.5, 3.5, 1.5, 0.3, p, 4, &mut n),
            TS_ERROR_NULL_POINTER,
            "nav",
        );
        assert_eq!(xy, [0.0; 8], "nothing written");
        let mut field = ptr::null_mut();
        assert_refused(
            ts_flow_field_create(nav, map, f32::NAN, 1.5, 0.3, &mut field),
            TS_ERROR_INVALID_ARGUMENT,
            "x is NaN",
        );
        assert_refused(
            ts_flow_field_create(nav, map, 1.5, 1.5, 2.0, &mut field),
            TS_ERROR_INVALID_ARGUMENT,
            "radius",
        );
        assert_refused(
            ts_flow_field_create(nav, map, 1.5, 1.5, 0.3, ptr::null_mut()),
            TS_ERROR_NULL_POINTER,
            "out",
        );
        assert!(field.is_null());
        assert_eq!(
            ts_flow_field_create(nav, map, 3.5, 1.5, 0.3, &mut field),
            TS_OK
        );
        let (mut dx, mut dy, mut d) = (0.0, 0.0, 0.0);
        assert_eq!(
            ts_flow_field_direction(field, nav, map, 1.5, 1.5, &mut dx, &mut dy),
            TS_OK
        );
        assert_eq!((dx, dy), (1.0, 0.0));
        assert_eq!(
            ts_flow_field_distance(field, nav, map, 1.5, 1.5, &mut d),
            TS_OK
        );
        assert!((d - 2.0).abs() < 1e-3, "{d}");
        // In the wall: no way, no error.
        assert_eq!(
            ts_flow_field_distance(field, nav, map, 0.5, 0.5, &mut d),
            TS_OK
        );
        assert_eq!(d, f32::INFINITY);
        assert_eq!(
            ts_flow_field_direction(field, nav, map, 0.5, 0.5, &mut dx, &mut dy),
            TS_OK
        );
        assert_eq!((dx, dy), (0.0, 0.0));
        assert_refused(
            ts_flow_field_direction(field, nav, map, 1.5, f32::NAN, &mut dx, &mut dy),
            TS_ERROR_INVALID_ARGUMENT,
            "y is NaN",
        );
        assert_refused(
            ts_flow_field_direction(field, nav, map, 1.5, 1.5, &mut dx, ptr::null_mut()),
            TS_ERROR_NULL_POINTER,
            "dy",
        );
        assert_refused(
            ts_flow_field_distance(ptr::null(), nav, map, 1.5, 1.5, &mut d),
            TS_ERROR_NULL_POINTER,
            "field",
        );
        assert_refused(
            ts_flow_field_distance(field, nav, other, 1.5, 1.5, &mut d),
            TS_ERROR_INVALID_ARGUMENT,
            "another map",
        );
        ts_flow_field_free(field);
        ts_flow_field_free(ptr::null_mut());
        ts_nav_free(nav);
        ts_nav_free(ptr::null_mut());
        ts_map_free(map);
        ts_map_free(other);
    }
}
