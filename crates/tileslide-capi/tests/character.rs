//! The character through the C API as C calls it: a run of steps (walking, jumping onto a
//! one-way platform, dropping through it, up a ramp, into a wall) equals the same run on the
//! core bit for bit, contacts included; bad input gets a status and a message naming it.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic, unsafe_code)]

mod support;

use std::ptr;

use support::{ascii_map, assert_refused, core_map, last_error};
use tileslide::{
    Character, CharacterShape, Contacts, ControllerConfig, MoveOptions, SegmentSource, Vec2,
};
use tileslide_capi::*;

const LEVEL: &str = "\
##############
#............#
#............#
#...====.....#
#............#
#......./#####
#....../######
##############";

const DT: f32 = 1.0 / 60.0;
const GRAVITY: f32 = 30.0;

/// What the game asks at `step`: the run speed, whether to jump (when grounded), whether
/// to drop through platforms.
fn input(step: usize) -> (f32, bool, bool) {
    let run = match step {
        0..=44 => 3.0,
        45..=119 => 0.0,
        120..=259 => 5.0,
        _ => -3.0,
    };
    (run, step == 30 || step == 200, (90..=100).contains(&step))
}

fn new_character(def: &ts_character_def) -> *mut ts_character {
    let mut c = ptr::null_mut();
    // SAFETY: a definition and a writable out pointer.
    let status = unsafe { ts_character_create(def, &mut c) };
    assert_eq!(status, ts_status::TS_OK, "{}", last_error());
    c
}

fn state(c: *const ts_character) -> ts_character_state {
    let mut s = ts_character_state::default();
    // SAFETY: a live character and a writable state.
    assert_eq!(
        unsafe { ts_character_get_state(c, &mut s) },
        ts_status::TS_OK
    );
    s
}

fn contacts(c: *const ts_character) -> Vec<ts_character_contact> {
    let mut out = Vec::with_capacity(TS_CHARACTER_MAX_CONTACTS);
    let mut n = 0;
    // SAFETY: room for the most contacts there are, and a writable count.
    unsafe {
        assert_eq!(
            ts_character_contacts(c, out.as_mut_ptr(), out.capacity(), &mut n),
            ts_status::TS_OK
        );
        out.set_len(n);
    }
    out
}

/// The core's contacts as the C API lists them: (side, normal bits, flags, tile's cell and
/// id or `TS_NONE`).
fn core_contacts(k: &Contacts) -> Vec<(ts_contact_side, [u32; 2], u32, [u32; 3])> {
    use ts_contact_side::*;
    [
        (TS_CONTACT_GROUND, k.ground),
        (TS_CONTACT_CEILING, k.ceiling),
        (TS_CONTACT_LEFT, k.left),
        (TS_CONTACT_RIGHT, k.right),
        (TS_CONTACT_CRUSH, k.crush),
    ]
    .into_iter()
    .filter_map(|(side, c)| {
        let c = c?;
        let tile = match c.source {
            SegmentSource::Tile { segment, tile } => [segment.cell.col, segment.cell.row, tile.0],
            _ => [TS_NONE; 3],
        };
        Some((
            side,
            [c.normal.x.to_bits(), c.normal.y.to_bits()],
            c.flags.0,
            tile,
        ))
    })
    .collect()
}

fn c_contacts(list: &[ts_character_contact]) -> Vec<(ts_contact_side, [u32; 2], u32, [u32; 3])> {
    list.iter()
        .map(|c| {
            (
                c.side,
                [c.nx.to_bits(), c.ny.to_bits()],
                c.flags,
                [c.col, c.row, c.tile],
            )
        })
        .collect()
}

/// Runs 300 steps through C and through the core side by side, for a character of `def`,
/// and returns the sides it touched along the way, with their flags.
fn run_both(def: &ts_character_def, shape: CharacterShape) -> Vec<(ts_contact_side, u32)> {
    let map = ascii_map(LEVEL);
    let core_map = core_map(LEVEL);
    let c = new_character(def);
    let mut core = Character::new(
        shape,
        Vec2::new(def.x, def.y),
        Vec2::NEG_Y,
        ControllerConfig::default(),
    )
    .unwrap();
    let mut velocity = Vec2::ZERO;
    let mut touched = Vec::new();
    for step in 0..300 {
        let (run, jump, drop_through) = input(step);
        // The game's rules, the same on both sides.
        let s = state(c);
        let mut vy = s.vy + GRAVITY * DT;
        if jump && s.grounded {
            vy = -16.0;
        }
        // SAFETY: a live character and map.
        unsafe {
            assert_eq!(
                ts_character_set_input(c, run, vy, drop_through),
                ts_status::TS_OK
            );
            assert_eq!(ts_character_step(c, map, DT), ts_status::TS_OK);
        }
        velocity.y += GRAVITY * DT;
        if jump && core.ground().is_some() {
            velocity.y = -16.0;
        }
        velocity.x = run;
        let k = core
            .move_and_slide(&core_map, &mut velocity, DT, MoveOptions { drop_through })
            .unwrap();
        let s = state(c);
        let p = core.position;
        assert_eq!(
            [s.x, s.y, s.vx, s.vy].map(f32::to_bits),
            [p.x, p.y, velocity.x, velocity.y].map(f32::to_bits),
            "step {step}: C ({}, {}) v ({}, {}), core {p} v {velocity}",
            s.x,
            s.y,
            s.vx,
            s.vy
        );
        assert_eq!(s.grounded, k.is_grounded(), "step {step}");
        let list = contacts(c);
        assert_eq!(c_contacts(&list), core_contacts(&k), "step {step}");
        touched.extend(list.iter().map(|c| (c.side, c.flags)));
    }
    // SAFETY: freed once.
    unsafe {
        ts_character_free(c);
        ts_map_free(map);
    }
    touched
}

#[test]
fn a_box_run_through_c_equals_the_cores_bit_for_bit() {
    let def = ts_character_def {
        x: 2.0,
        y: 6.0,
        ..ts_default_character_def()
    };
    let shape = CharacterShape::rect(Vec2::new(def.half_width, def.half_height)).unwrap();
    let touched = run_both(&def, shape);
    // The run is worth comparing: it stands on the one-way platform (jumped up through it),
    // on the floor (dropped through it), and meets the right wall.
    use ts_contact_side::*;
    for touch in [
        (TS_CONTACT_GROUND, TS_SEGMENT_ONE_WAY),
        (TS_CONTACT_GROUND, TS_SEGMENT_SOLID),
        (TS_CONTACT_RIGHT, TS_SEGMENT_SOLID),
    ] {
        assert!(touched.contains(&touch), "never touched {touch:?}");
    }
}

#[test]
fn a_circle_run_through_c_equals_the_cores_bit_for_bit() {
    let def = ts_character_def {
        x: 2.0,
        y: 6.0,
        shape: TS_SHAPE_CIRCLE,
        radius: 0.35,
        ..ts_default_character_def()
    };
    let touched = run_both(&def, CharacterShape::circle(0.35).unwrap());
    let one_way = (ts_contact_side::TS_CONTACT_GROUND, TS_SEGMENT_ONE_WAY);
    assert!(touched.contains(&one_way), "never stood on the platform");
}

#[test]
fn the_one_way_platform_holds_it_until_it_drops_through() {
    let map = ascii_map(LEVEL);
    let def = ts_character_def {
        x: 5.5,
        y: 2.0,
        ..ts_default_character_def()
    };
    let c = new_character(&def);
    // SAFETY: a live character and map throughout.
    unsafe {
        for _ in 0..30 {
            assert_eq!(
                ts_character_move_by(c, map, 0.0, 0.2, false),
                ts_status::TS_OK
            );
        }
        let s = state(c);
        assert!(
            s.grounded && (s.y - (3.0 - 0.4 - 0.001)).abs() < 1e-4,
            "{s:?}"
        );
        let list = contacts(c);
        assert_eq!(list[0].side, ts_contact_side::TS_CONTACT_GROUND);
        assert_eq!(list[0].flags & TS_SEGMENT_ONE_WAY, TS_SEGMENT_ONE_WAY);
        assert_eq!((list[0].col, list[0].row), (5, 3));
        assert_ne!(list[0].tile, TS_NONE);
        for _ in 0..10 {
            assert_eq!(
                ts_character_move_by(c, map, 0.0, 0.2, true),
                ts_status::TS_OK
            );
        }
        let s = state(c);
        assert!(s.y > 3.5, "dropped through: {s:?}");
        // Teleported: no ground, no contacts, the velocity kept.
        assert_eq!(ts_character_set_input(c, 1.0, 2.0, false), ts_status::TS_OK);
        assert_eq!(ts_character_teleport(c, 3.0, 1.5), ts_status::TS_OK);
        let s = state(c);
        assert_eq!(
            (s.x, s.y, s.vx, s.vy, s.grounded),
            (3.0, 1.5, 1.0, 2.0, false)
        );
        assert!(contacts(c).is_empty());
        ts_character_free(c);
        ts_map_free(map);
    }
}

#[test]
fn a_buffer_too_small_gets_the_count_and_nothing_else() {
    let map = ascii_map(LEVEL);
    let def = ts_character_def {
        x: 12.5,
        y: 4.0,
        ..ts_default_character_def()
    };
    let c = new_character(&def);
    // SAFETY: a live character and map; buffers as long as said.
    unsafe {
        // Into the corner: ground and the right wall.
        for _ in 0..20 {
            assert_eq!(
                ts_character_move_by(c, map, 0.3, 0.3, false),
                ts_status::TS_OK
            );
        }
        let mut one = [ts_character_contact {
            side: ts_contact_side::TS_CONTACT_CRUSH,
            nx: 7.0,
            ny: 7.0,
            flags: 7,
            col: 7,
            row: 7,
            tile: 7,
        }];
        let before = one;
        let mut n = 0;
        assert_refused(
            ts_character_contacts(c, one.as_mut_ptr(), 1, &mut n),
            ts_status::TS_ERROR_BUFFER_TOO_SMALL,
            "2 contacts do not fit in a buffer of 1",
        );
        assert_eq!(n, 2);
        assert_eq!(one, before, "nothing written");
        // Capacity 0 and a null buffer: how many there are.
        n = 0;
        assert_eq!(
            ts_character_contacts(c, ptr::null_mut(), 0, &mut n),
            ts_status::TS_ERROR_BUFFER_TOO_SMALL
        );
        assert_eq!(n, 2);
        assert_refused(
            ts_character_contacts(c, one.as_mut_ptr(), 1, ptr::null_mut()),
            ts_status::TS_ERROR_NULL_POINTER,
            "count is a null pointer",
        );
        assert_refused(
            ts_character_contacts(c, ptr::null_mut(), 5, &mut n),
            ts_status::TS_ERROR_NULL_POINTER,
            "out is a null pointer",
        );
        ts_character_free(c);
        ts_map_free(map);
    }
}

#[test]
fn bad_definitions_inputs_and_pointers_are_refused_by_name() {
    use ts_status::*;
    let map = ascii_map(LEVEL);
    // SAFETY: each call gets one bad argument on purpose; the rest are valid.
    unsafe {
        let mut c = ptr::null_mut();
        let bad_defs = [
            (
                ts_character_def {
                    x: f32::NAN,
                    ..ts_default_character_def()
                },
                "position",
            ),
            (
                ts_character_def {
                    y: 1e30,
                    ..ts_default_character_def()
                },
                "position",
            ),
            (
                ts_character_def {
                    half_width: 0.0,
                    ..ts_default_character_def()
                },
                "half extents",
            ),
            (
                ts_character_def {
                    shape: TS_SHAPE_CIRCLE,
                    radius: -1.0,
                    ..ts_default_character_def()
                },
                "radius",
            ),
            (
                ts_character_def {
                    shape: 9,
                    ..ts_default_character_def()
                },
                "def.shape is 9",
            ),
            (
                ts_character_def {
                    up_x: 0.0,
                    up_y: 0.0,
                    ..ts_default_character_def()
                },
                "up",
            ),
            (
                ts_character_def {
                    max_slope_degrees: 90.0,
                    ..ts_default_character_def()
                },
                "max_slope_degrees",
            ),
            (
                ts_character_def {
                    skin: f32::INFINITY,
                    ..ts_default_character_def()
                },
                "skin",
            ),
            (
                ts_character_def {
                    max_slides: 0,
                    ..ts_default_character_def()
                },
                "max_slides",
            ),
        ];
        for (def, words) in bad_defs {
            assert_refused(
                ts_character_create(&def, &mut c),
                TS_ERROR_INVALID_ARGUMENT,
                words,
            );
            assert!(c.is_null(), "out written on failure");
        }
        assert_refused(
            ts_character_create(ptr::null(), &mut c),
            TS_ERROR_NULL_POINTER,
            "def is a null pointer",
        );
        let def = ts_default_character_def();
        assert_refused(
            ts_character_create(&def, ptr::null_mut()),
            TS_ERROR_NULL_POINTER,
            "out is a null pointer",
        );
        let def = ts_character_def {
            x: 2.0,
            y: 6.0,
            ..def
        };
        let c = new_character(&def);
        assert_refused(
            ts_character_set_input(c, f32::NAN, 0.0, false),
            TS_ERROR_INVALID_ARGUMENT,
            "vx is NaN",
        );
        assert_refused(
            ts_character_set_input(c, 0.0, 1e30, false),
            TS_ERROR_INVALID_ARGUMENT,
            "vy is",
        );
        assert_refused(
            ts_character_set_input(ptr::null_mut(), 0.0, 0.0, false),
            TS_ERROR_NULL_POINTER,
            "character is a null pointer",
        );
        assert_eq!(ts_character_set_input(c, 1.0, 0.0, false), TS_OK);
        for dt in [-0.1, f32::NAN, f32::INFINITY] {
            assert_refused(
                ts_character_step(c, map, dt),
                TS_ERROR_INVALID_ARGUMENT,
                "dt",
            );
        }
        // A velocity in range whose step ends out of range.
        assert_eq!(ts_character_set_input(c, 1.6e7, 0.0, false), TS_OK);
        assert_refused(
            ts_character_step(c, map, 1e3),
            TS_ERROR_INVALID_ARGUMENT,
            "velocity × dt",
        );
        assert_refused(
            ts_character_step(c, ptr::null(), DT),
            TS_ERROR_NULL_POINTER,
            "map",
        );
        assert_refused(
            ts_character_move_by(c, map, f32::NAN, 0.0, false),
            TS_ERROR_INVALID_ARGUMENT,
            "dx",
        );
        assert_refused(
            ts_character_teleport(c, 0.0, f32::INFINITY),
            TS_ERROR_INVALID_ARGUMENT,
            "position",
        );
        let s = state(c);
        assert_eq!((s.x, s.y), (2.0, 6.0), "nothing moved");
        assert_refused(
            ts_character_get_state(c, ptr::null_mut()),
            TS_ERROR_NULL_POINTER,
            "out",
        );
        assert_refused(
            ts_character_get_state(ptr::null(), &mut ts_character_state::default()),
            TS_ERROR_NULL_POINTER,
            "character",
        );
        ts_character_free(c);
        ts_character_free(ptr::null_mut());
        ts_map_free(map);
    }
}
