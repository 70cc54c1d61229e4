//! Bodies through the C API as C calls it: the standard crowd ends on the core's golden
//! hash, bit for bit; ids go stale when their body is removed; bad input gets a status and a
//! message naming what and where.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic, unsafe_code)]

mod support;

use std::ptr;

use support::{ascii_map, last_error};
use tileslide::Vec2;
use tileslide_capi::*;
use tileslide_scenes::{CROWD_RADIUS, dungeon256, positions_hash, scene_crowd};

/// The core's golden hash of the crowd (crates/tileslide/tests/resolver_golden.rs): 2,000
/// bodies, 40 steps, positions hashed with FNV-1a 64.
const GOLDEN: u64 = 0x527e_da96_98ab_4a5d;

fn new_bodies() -> *mut ts_bodies {
    let mut bodies = ptr::null_mut();
    // SAFETY: a writable out pointer.
    assert_eq!(unsafe { ts_bodies_create(&mut bodies) }, ts_status::TS_OK);
    bodies
}

#[test]
fn the_crowd_through_c_ends_on_the_cores_golden_hash() {
    let grid = dungeon256();
    let text = grid.to_ascii();
    let map = ascii_map(&text);
    let bodies = new_bodies();
    let crowd = scene_crowd(&grid, 2_000);
    let mut ids = Vec::new();
    let mut moves = Vec::new();
    for b in &crowd {
        let def = ts_body_def {
            x: b.position.x,
            y: b.position.y,
            radius: CROWD_RADIUS,
            ..ts_default_body_def()
        };
        let mut id = ts_body_id {
            index: 0,
            generation: 0,
        };
        // SAFETY: a live set, a definition and a writable id.
        assert_eq!(
            unsafe { ts_bodies_add(bodies, &def, &mut id) },
            ts_status::TS_OK
        );
        ids.push(id);
        moves.extend([b.velocity.x, b.velocity.y]);
    }
    let mut report = ts_step_report::default();
    for _ in 0..40 {
        // SAFETY: n ids and 2 n floats; a live set and map.
        unsafe {
            assert_eq!(
                ts_bodies_propose_many(bodies, ids.as_ptr(), moves.as_ptr(), ids.len()),
                ts_status::TS_OK
            );
            assert_eq!(ts_bodies_step(bodies, map, &mut report), ts_status::TS_OK);
        }
    }
    assert!(report.moving > 0 && report.contacts > 0, "{report:?}");
    let mut xy = vec![0.0_f32; 2 * ids.len()];
    // SAFETY: n ids and room for 2 n floats.
    assert_eq!(
        unsafe { ts_bodies_positions(bodies, ids.as_ptr(), ids.len(), xy.as_mut_ptr()) },
        ts_status::TS_OK
    );
    let positions: Vec<Vec2> = xy.chunks_exact(2).map(|p| Vec2::new(p[0], p[1])).collect();
    let hash = positions_hash(&positions);
    assert_eq!(hash, GOLDEN, "the crowd through C hashes to {hash:#018x}");
    // SAFETY: the live set and map, freed once.
    unsafe {
        assert_eq!(ts_bodies_count(bodies), 2_000);
        ts_bodies_free(bodies);
        ts_map_free(map);
    }
}

#[test]
fn a_removed_bodys_id_is_stale_even_when_its_slot_is_reused() {
    let map = ascii_map("######\n#....#\n#....#\n######");
    let bodies = new_bodies();
    // SAFETY: live sets and maps, valid definitions and outputs throughout.
    unsafe {
        let def = ts_body_def {
            x: 1.5,
            y: 1.5,
            radius: 0.4,
            ..ts_default_body_def()
        };
        let mut a = std::mem::zeroed::<ts_body_id>();
        assert_eq!(ts_bodies_add(bodies, &def, &mut a), ts_status::TS_OK);
        assert_eq!(ts_bodies_remove(bodies, a), ts_status::TS_OK);
        let mut b = std::mem::zeroed::<ts_body_id>();
        assert_eq!(ts_bodies_add(bodies, &def, &mut b), ts_status::TS_OK);
        assert_eq!(b.index, a.index, "the slot is reused");
        assert_ne!(b.generation, a.generation);
        assert_eq!(
            ts_bodies_propose(bodies, a, 1.0, 0.0),
            ts_status::TS_ERROR_STALE_HANDLE
        );
        assert!(
            last_error().contains("stale body handle"),
            "{}",
            last_error()
        );
        assert_eq!(
            ts_bodies_remove(bodies, a),
            ts_status::TS_ERROR_STALE_HANDLE
        );
        let made_up = ts_body_id {
            index: 99,
            generation: 0,
        };
        let (mut x, mut y) = (7.0, 7.0);
        assert_eq!(
            ts_bodies_position(bodies, made_up, &mut x, &mut y),
            ts_status::TS_ERROR_STALE_HANDLE
        );
        assert_eq!((x, y), (7.0, 7.0), "nothing written");
        let mut xy = [7.0_f32; 4];
        let ids = [b, a];
        assert_eq!(
            ts_bodies_positions(bodies, ids.as_ptr(), 2, xy.as_mut_ptr()),
            ts_status::TS_ERROR_STALE_HANDLE
        );
        assert!(last_error().contains("entry 1"), "{}", last_error());
        assert_eq!(xy, [7.0; 4], "nothing written");
        // b walks right into the wall at x = 5 and stops short of it.
        for _ in 0..10 {
            assert_eq!(ts_bodies_propose(bodies, b, 0.5, 0.0), ts_status::TS_OK);
            assert_eq!(
                ts_bodies_step(bodies, map, ptr::null_mut()),
                ts_status::TS_OK
            );
        }
        assert_eq!(
            ts_bodies_position(bodies, b, &mut x, &mut y),
            ts_status::TS_OK
        );
        assert!(x > 4.59 && x <= 4.6, "{x}");
        assert_eq!(y, 1.5);
        ts_bodies_free(bodies);
        ts_map_free(map);
    }
}

#[test]
fn bad_definitions_moves_and_pointers_are_refused() {
    let bodies = new_bodies();
    // SAFETY: each call gets one bad argument on purpose; the rest are valid.
    unsafe {
        let mut id = std::mem::zeroed::<ts_body_id>();
        for radius in [0.0, -1.0, f32::NAN] {
            let def = ts_body_def {
                radius,
                ..ts_default_body_def()
            };
            assert_eq!(
                ts_bodies_add(bodies, &def, &mut id),
                ts_status::TS_ERROR_INVALID_ARGUMENT
            );
            assert!(last_error().contains("radius"), "{}", last_error());
        }
        let far = ts_body_def {
            x: f32::INFINITY,
            ..ts_default_body_def()
        };
        assert_eq!(
            ts_bodies_add(bodies, &far, &mut id),
            ts_status::TS_ERROR_INVALID_ARGUMENT
        );
        let no_circles = ts_body_def {
            circle_count: 2,
            ..ts_default_body_def()
        };
        assert_eq!(
            ts_bodies_add(bodies, &no_circles, &mut id),
            ts_status::TS_ERROR_NULL_POINTER
        );
        assert!(last_error().contains("def.circles"), "{}", last_error());
        let pair = [
            ts_circle {
                x: -0.3,
                y: 0.0,
                radius: 0.25,
            },
            ts_circle {
                x: 0.3,
                y: 0.0,
                radius: 0.25,
            },
        ];
        let compound = ts_body_def {
            x: 2.0,
            y: 2.0,
            circles: pair.as_ptr(),
            circle_count: 2,
            ..ts_default_body_def()
        };
        assert_eq!(ts_bodies_add(bodies, &compound, &mut id), ts_status::TS_OK);
        assert_eq!(
            ts_bodies_add(bodies, ptr::null(), &mut id),
            ts_status::TS_ERROR_NULL_POINTER
        );
        assert_eq!(
            ts_bodies_propose(bodies, id, f32::NAN, 0.0),
            ts_status::TS_ERROR_INVALID_ARGUMENT
        );
        assert!(last_error().contains("not finite"), "{}", last_error());
        let moves = [1.0, 0.0, f32::NAN, 0.0];
        let ids = [id, id];
        assert_eq!(
            ts_bodies_propose_many(bodies, ids.as_ptr(), moves.as_ptr(), 2),
            ts_status::TS_ERROR_INVALID_ARGUMENT
        );
        assert!(last_error().contains("entry 1"), "{}", last_error());
        // Counts no memory could hold are refused before anything is read: a slice of
        // them would be undefined behaviour however valid the pointer.
        let mut xy = [0.0f32; 4];
        for n in [
            usize::MAX / 2,
            usize::MAX / 8,
            (isize::MAX as usize) / 8 + 1,
        ] {
            assert_eq!(
                ts_bodies_propose_many(bodies, ids.as_ptr(), moves.as_ptr(), n),
                ts_status::TS_ERROR_INVALID_ARGUMENT
            );
            assert!(last_error().contains("too many"), "{}", last_error());
            assert_eq!(
                ts_bodies_positions(bodies, ids.as_ptr(), n, xy.as_mut_ptr()),
                ts_status::TS_ERROR_INVALID_ARGUMENT
            );
            assert!(last_error().contains("too many"), "{}", last_error());
        }
        let many = vec![pair[0]; tileslide::limits::MAX_COMPOUND_CIRCLES + 1];
        for (circles, circle_count) in [(many.as_ptr(), many.len()), (pair.as_ptr(), usize::MAX)] {
            let def = ts_body_def {
                circles,
                circle_count,
                ..compound
            };
            assert_eq!(
                ts_bodies_add(bodies, &def, &mut id),
                ts_status::TS_ERROR_INVALID_ARGUMENT
            );
            assert!(
                last_error().contains(&format!("def.circle_count is {circle_count}, at most 1024")),
                "{}",
                last_error()
            );
        }
        assert_eq!(
            ts_bodies_step(bodies, ptr::null(), ptr::null_mut()),
            ts_status::TS_ERROR_NULL_POINTER
        );
        assert_eq!(
            ts_bodies_propose(ptr::null_mut(), id, 0.0, 0.0),
            ts_status::TS_ERROR_NULL_POINTER
        );
        assert_eq!(ts_bodies_count(ptr::null()), 0);
        ts_bodies_free(bodies);
        ts_bodies_free(ptr::null_mut());
    }
}
