//! Debug lines through the C API as C calls it: a map, bodies after a step, a character
//! after a move, a hit world after a step and a flow field give the core's lines bit for
//! bit, with their kinds by the core's numbers and their owners; kinds and a view limit
//! what is taken; a buffer too small gets the count; bad input gets a status and a message.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic, unsafe_code)]

mod support;

use std::ptr;

use support::{ascii_map, assert_refused, core_map, core_nav, last_error};
use tileslide::debug::DebugKinds;
use tileslide::{
    Aabb, Bodies, BodyDesc, BodyShape, Character, CharacterShape, ControllerConfig, DebugKind,
    DebugLines, FlowField, HitObject, HitTypes, HitWorld, MoveOptions, Owner, TeamRule, Vec2,
    Volume,
};
use tileslide_capi::*;

const LEVEL: &str = "\
##########
#........#
#..==....#
#.....#..#
#..../####
##########";

fn new_lines() -> *mut ts_debug_lines {
    let mut lines = ptr::null_mut();
    // SAFETY: a writable out pointer.
    assert_eq!(
        unsafe { ts_debug_lines_create(&mut lines) },
        ts_status::TS_OK
    );
    lines
}

/// What the C buffer holds, read with just enough room.
fn read(lines: *mut ts_debug_lines) -> Vec<ts_debug_line> {
    let mut n = 0;
    // SAFETY: a live buffer; capacity 0 asks how many, then room for them.
    unsafe {
        let status = ts_debug_lines_read(lines, ptr::null_mut(), 0, &mut n);
        assert!(n == 0 || status == ts_status::TS_ERROR_BUFFER_TOO_SMALL);
        assert_eq!(n, ts_debug_lines_count(lines));
        let mut out = Vec::with_capacity(n);
        assert_eq!(
            ts_debug_lines_read(lines, out.as_mut_ptr(), n, &mut n),
            ts_status::TS_OK
        );
        out.set_len(n);
        out
    }
}

/// A line as bits: (shape, kind, the four numbers, owner).
type Bits = (u32, u32, [u32; 4], u64);

fn c_bits(lines: &[ts_debug_line]) -> Vec<Bits> {
    lines
        .iter()
        .map(|l| {
            (
                l.shape as u32,
                l.kind as u32,
                [l.x0, l.y0, l.x1, l.y1].map(f32::to_bits),
                l.owner,
            )
        })
        .collect()
}

/// The core's lines as the C API documents them: segments (a to b), circles (centre,
/// radius, 0), points (twice), boxes (min, max).
fn core_bits(lines: &DebugLines) -> Vec<Bits> {
    let bits = |v: [f32; 4]| v.map(f32::to_bits);
    let mut out = Vec::new();
    for s in lines.segments() {
        let (a, b) = (s.segment.a, s.segment.b);
        out.push((0, s.kind as u32, bits([a.x, a.y, b.x, b.y]), s.owner.0));
    }
    for c in lines.circles() {
        let (p, r) = (c.circle.center, c.circle.radius);
        out.push((1, c.kind as u32, bits([p.x, p.y, r, 0.0]), c.owner.0));
    }
    for p in lines.points() {
        let q = p.point;
        out.push((2, p.kind as u32, bits([q.x, q.y, q.x, q.y]), p.owner.0));
    }
    for b in lines.boxes() {
        let (lo, hi) = (b.aabb.min, b.aabb.max);
        out.push((3, b.kind as u32, bits([lo.x, lo.y, hi.x, hi.y]), b.owner.0));
    }
    out
}

/// Asserts the C buffer holds the core's lines and every kind in `kinds`.
#[track_caller]
fn assert_same(lines: *mut ts_debug_lines, core: &DebugLines, kinds: &[DebugKind]) {
    let got = read(lines);
    assert_eq!(c_bits(&got), core_bits(core));
    for kind in kinds {
        assert!(
            got.iter().any(|l| l.kind as u32 == *kind as u32),
            "no {kind:?} line"
        );
    }
}

#[test]
fn every_part_draws_the_cores_lines_bit_for_bit() {
    let map = ascii_map(LEVEL);
    let core_map = core_map(LEVEL);
    let lines = new_lines();
    let mut core = DebugLines::new();
    // SAFETY: live objects and buffers throughout.
    unsafe {
        // The map: walls, one-way platforms, normals, hidden seams.
        assert_eq!(
            ts_map_debug_lines(map, lines),
            ts_status::TS_OK,
            "{}",
            last_error()
        );
        core_map.debug_lines(&mut core);
        assert_same(
            lines,
            &core,
            &[
                DebugKind::ActiveSegment,
                DebugKind::OneWaySegment,
                DebugKind::Normal,
                DebugKind::HiddenSegment,
            ],
        );

        // Bodies after a step: circles and broadphase boxes, owned by their ids.
        let mut bodies = ptr::null_mut();
        assert_eq!(ts_bodies_create(&mut bodies), ts_status::TS_OK);
        let mut core_bodies = Bodies::new();
        let mut ids = Vec::new();
        for (k, x) in [2.0_f32, 3.0, 7.5].into_iter().enumerate() {
            let def = ts_body_def {
                x,
                y: 1.5,
                radius: 0.3 + 0.05 * k as f32,
                ..ts_default_body_def()
            };
            let mut id = std::mem::zeroed::<ts_body_id>();
            assert_eq!(ts_bodies_add(bodies, &def, &mut id), ts_status::TS_OK);
            let owner = Owner(u64::from(id.generation) << 32 | u64::from(id.index));
            let shape = BodyShape::circle(def.radius).unwrap();
            let handle = core_bodies
                .add(BodyDesc::new(Vec2::new(x, 1.5), shape).with_owner(owner))
                .unwrap();
            ids.push((id, handle));
        }
        // Remove the first, so owners are not slot numbers by accident of order.
        assert_eq!(ts_bodies_remove(bodies, ids[0].0), ts_status::TS_OK);
        core_bodies.remove(ids[0].1).unwrap();
        for (id, handle) in &ids[1..] {
            assert_eq!(ts_bodies_propose(bodies, *id, 0.4, 0.2), ts_status::TS_OK);
            core_bodies.propose(*handle, Vec2::new(0.4, 0.2)).unwrap();
        }
        assert_eq!(
            ts_bodies_step(bodies, map, ptr::null_mut()),
            ts_status::TS_OK
        );
        core_bodies.step(&core_map);
        assert_eq!(ts_debug_lines_clear(lines), ts_status::TS_OK);
        core.clear();
        assert_eq!(ts_bodies_debug_lines(bodies, lines), ts_status::TS_OK);
        core_bodies.debug_lines(&mut core);
        assert_same(lines, &core, &[DebugKind::Body, DebugKind::BroadphaseBox]);
        assert!(read(lines).iter().all(|l| l.owner != 0));

        // A character after a move: its box and its contacts, with the owner given.
        let def = ts_character_def {
            x: 7.5,
            y: 1.0,
            ..ts_default_character_def()
        };
        let mut hero = ptr::null_mut();
        assert_eq!(ts_character_create(&def, &mut hero), ts_status::TS_OK);
        let shape = CharacterShape::rect(Vec2::new(def.half_width, def.half_height)).unwrap();
        let mut core_hero = Character::new(
            shape,
            Vec2::new(7.5, 1.0),
            Vec2::NEG_Y,
            ControllerConfig::default(),
        )
        .unwrap();
        assert_eq!(
            ts_character_move_by(hero, map, 3.0, 2.0, false),
            ts_status::TS_OK
        );
        let contacts = core_hero
            .move_by(&core_map, Vec2::new(3.0, 2.0), MoveOptions::default())
            .unwrap();
        assert_eq!(ts_debug_lines_clear(lines), ts_status::TS_OK);
        core.clear();
        assert_eq!(ts_character_debug_lines(hero, 77, lines), ts_status::TS_OK);
        core_hero.debug_lines(Some(&contacts), Owner(77), &mut core);
        assert_same(lines, &core, &[DebugKind::Character, DebugKind::Contact]);

        // A hit world after a step: volumes, swept boxes, the hit.
        let mut world = ptr::null_mut();
        assert_eq!(ts_hit_world_create(&mut world), ts_status::TS_OK);
        let fist = ts_volume {
            shape: TS_SHAPE_CIRCLE,
            x: 1.0,
            y: 0.0,
            radius: 0.4,
            half_width: 0.0,
            half_height: 0.0,
            hit: TS_HIT_TYPE_HIT,
        };
        let body = ts_volume {
            shape: TS_SHAPE_RECT,
            radius: 0.0,
            half_width: 0.3,
            half_height: 0.5,
            ..fist
        };
        let body = ts_volume {
            x: 0.0,
            hit: TS_HIT_TYPE_ANY,
            ..body
        };
        let a_def = ts_hit_object_def {
            x: 2.0,
            y: 2.0,
            team: 1,
            attack: &fist,
            attack_count: 1,
            vulnerable: &body,
            vulnerable_count: 1,
            ..ts_default_hit_object_def()
        };
        let b_def = ts_hit_object_def {
            x: 3.2,
            team: 2,
            ..a_def
        };
        let (mut a, mut b) = (std::mem::zeroed(), std::mem::zeroed::<ts_hit_object_id>());
        assert_eq!(ts_hit_world_add(world, &a_def, &mut a), ts_status::TS_OK);
        assert_eq!(ts_hit_world_add(world, &b_def, &mut b), ts_status::TS_OK);
        assert_eq!(ts_hit_world_step(world), ts_status::TS_OK);
        let mut core_world = HitWorld::new();
        core_world.begin_frame();
        let core_fist = [Volume::circle(Vec2::new(1.0, 0.0), 0.4, HitTypes::HIT).unwrap()];
        let core_body = [Volume::rect(Vec2::ZERO, Vec2::new(0.3, 0.5), HitTypes::ANY).unwrap()];
        for (id, x, team) in [(a, 2.0, 1), (b, 3.2, 2)] {
            let owner = Owner(u64::from(id.generation) << 32 | u64::from(id.index));
            let object = HitObject {
                team,
                ..HitObject::new(owner, Vec2::new(x, 2.0), Vec2::ZERO)
            };
            core_world.register(object, &core_fist, &core_body).unwrap();
        }
        core_world.detect(&mut TeamRule);
        assert_eq!(ts_debug_lines_clear(lines), ts_status::TS_OK);
        core.clear();
        assert_eq!(ts_hit_world_debug_lines(world, lines), ts_status::TS_OK);
        core_world.debug_lines(&mut core);
        assert_same(
            lines,
            &core,
            &[
                DebugKind::AttackVolume,
                DebugKind::VulnerabilityVolume,
                DebugKind::BroadphaseBox,
                DebugKind::Hit,
            ],
        );

        // A flow field's arrows.
        let mut nav = ptr::null_mut();
        assert_eq!(ts_nav_create(map, 0.5, &mut nav), ts_status::TS_OK);
        let mut field = ptr::null_mut();
        assert_eq!(
            ts_flow_field_create(nav, map, 1.5, 1.5, 0.3, &mut field),
            ts_status::TS_OK
        );
        let core_nav = core_nav(&core_map, 0.5);
        let core_field = FlowField::new(&core_nav, &core_map, Vec2::new(1.5, 1.5), 0.3).unwrap();
        assert_eq!(ts_debug_lines_clear(lines), ts_status::TS_OK);
        core.clear();
        assert_eq!(
            ts_flow_field_debug_lines(field, nav, lines),
            ts_status::TS_OK
        );
        core_field.debug_lines(&core_nav, &mut core);
        assert_same(lines, &core, &[DebugKind::FlowArrow]);

        ts_flow_field_free(field);
        ts_nav_free(nav);
        ts_hit_world_free(world);
        ts_character_free(hero);
        ts_bodies_free(bodies);
        ts_debug_lines_free(lines);
        ts_map_free(map);
    }
}

#[test]
fn kinds_and_a_view_limit_what_is_taken() {
    let map = ascii_map(LEVEL);
    let core_map = core_map(LEVEL);
    let lines = new_lines();
    // SAFETY: live objects and buffers; a view of 4 floats.
    unsafe {
        let walls = 1 << ts_debug_kind::TS_DEBUG_ACTIVE_SEGMENT as u32
            | 1 << ts_debug_kind::TS_DEBUG_HIDDEN_SEGMENT as u32;
        assert_eq!(ts_debug_lines_set_kinds(lines, walls), ts_status::TS_OK);
        let view = [0.0_f32, 0.0, 3.0, 2.0];
        assert_eq!(
            ts_debug_lines_set_view(lines, view.as_ptr()),
            ts_status::TS_OK
        );
        assert_eq!(ts_map_debug_lines(map, lines), ts_status::TS_OK);
        let window = Aabb::from_corners(Vec2::ZERO, Vec2::new(3.0, 2.0));
        let mut core = DebugLines::new()
            .with_kinds(
                DebugKinds::NONE
                    .with(DebugKind::ActiveSegment)
                    .with(DebugKind::HiddenSegment),
            )
            .with_view(window);
        core_map.debug_lines(&mut core);
        assert_same(
            lines,
            &core,
            &[DebugKind::ActiveSegment, DebugKind::HiddenSegment],
        );
        let mut everything = DebugLines::new();
        core_map.debug_lines(&mut everything);
        assert!(read(lines).len() < everything.len() / 4);
        // Back to every kind, everywhere: clear keeps the settings until they change.
        assert_eq!(ts_debug_lines_clear(lines), ts_status::TS_OK);
        assert_eq!(ts_debug_lines_count(lines), 0);
        assert_eq!(
            ts_debug_lines_set_kinds(lines, TS_DEBUG_ALL_KINDS),
            ts_status::TS_OK
        );
        assert_eq!(
            ts_debug_lines_set_view(lines, ptr::null()),
            ts_status::TS_OK
        );
        assert_eq!(ts_map_debug_lines(map, lines), ts_status::TS_OK);
        assert_same(lines, &everything, &[]);
        ts_debug_lines_free(lines);
        ts_map_free(map);
    }
}

#[test]
fn a_small_buffer_bad_views_and_null_pointers_are_refused() {
    use ts_status::*;
    let map = ascii_map(LEVEL);
    let lines = new_lines();
    // SAFETY: each call gets one bad argument on purpose; the rest are valid.
    unsafe {
        assert_eq!(ts_map_debug_lines(map, lines), TS_OK);
        let n = ts_debug_lines_count(lines);
        assert!(n > 20);
        let marker = ts_debug_line {
            x0: 7.0,
            y0: 7.0,
            x1: 7.0,
            y1: 7.0,
            kind: ts_debug_kind::TS_DEBUG_RAY,
            shape: ts_debug_shape::TS_DEBUG_POINT,
            owner: 7,
        };
        let mut few = [marker; 4];
        let mut count = 0;
        assert_refused(
            ts_debug_lines_read(lines, few.as_mut_ptr(), 4, &mut count),
            TS_ERROR_BUFFER_TOO_SMALL,
            &format!("{n} debug lines do not fit in a buffer of 4"),
        );
        assert_eq!((count, few), (n, [marker; 4]));
        assert_refused(
            ts_debug_lines_read(lines, few.as_mut_ptr(), 4, ptr::null_mut()),
            TS_ERROR_NULL_POINTER,
            "count",
        );
        assert_refused(
            ts_debug_lines_read(lines, ptr::null_mut(), n, &mut count),
            TS_ERROR_NULL_POINTER,
            "out",
        );
        for (view, words) in [
            ([f32::NAN, 0.0, 1.0, 1.0], "view[0] is NaN"),
            ([0.0, 0.0, f32::INFINITY, 1.0], "view[2] is inf"),
            ([2.0, 0.0, 1.0, 1.0], "lowest corner above its highest"),
        ] {
            assert_refused(
                ts_debug_lines_set_view(lines, view.as_ptr()),
                TS_ERROR_INVALID_ARGUMENT,
                words,
            );
        }
        assert_refused(
            ts_map_debug_lines(ptr::null(), lines),
            TS_ERROR_NULL_POINTER,
            "map is a null pointer",
        );
        assert_refused(
            ts_map_debug_lines(map, ptr::null_mut()),
            TS_ERROR_NULL_POINTER,
            "lines is a null pointer",
        );
        assert_refused(
            ts_bodies_debug_lines(ptr::null(), lines),
            TS_ERROR_NULL_POINTER,
            "bodies",
        );
        assert_refused(
            ts_character_debug_lines(ptr::null(), 0, lines),
            TS_ERROR_NULL_POINTER,
            "character",
        );
        assert_refused(
            ts_hit_world_debug_lines(ptr::null(), lines),
            TS_ERROR_NULL_POINTER,
            "world",
        );
        assert_refused(
            ts_flow_field_debug_lines(ptr::null(), ptr::null(), lines),
            TS_ERROR_NULL_POINTER,
            "field",
        );
        assert_refused(
            ts_debug_lines_clear(ptr::null_mut()),
            TS_ERROR_NULL_POINTER,
            "lines",
        );
        assert_refused(
            ts_debug_lines_create(ptr::null_mut()),
            TS_ERROR_NULL_POINTER,
            "out",
        );
        assert_eq!(ts_debug_lines_count(ptr::null()), 0);
        // Nothing was added by the refused calls.
        assert_eq!(ts_debug_lines_count(lines), n);
        ts_debug_lines_free(lines);
        ts_debug_lines_free(ptr::null_mut());
        ts_map_free(map);
    }
}
