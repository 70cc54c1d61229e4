//! The character's trace against hand-checked moves (ASCII maps, y down: `up` is −y): a
//! jump up through a one-way platform, the landing on it, the drop through it, a ride on a
//! moving platform and a crush; and that tracing changes no move.
//!
//! ```text
//!   #.....#
//!   #.===.#   ↑ jump: passes from below; ↓ fall: lands; ↓ drop: drops through
//!   #..▯..#
//!   #######
//! ```
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use tileslide::io::ascii;
use tileslide::{
    Cell, Character, CharacterShape, ControllerConfig, MoveEvent, MoveOptions, MoveTrace,
    OneWayPass, Owner, Segment, SegmentFlags, SlideResponse, Surface, SweepPurpose,
    TemporarySegment, TileMap, Vec2, WallSource,
};

const UP: Vec2 = Vec2::NEG_Y;

/// A room with a one-way platform (its top at y = 3) over a floor (its top at y = 5).
const PLATFORM: &str = "\
#######
#.....#
#.....#
#.===.#
#.....#
#######";

fn map(text: &str) -> TileMap {
    ascii::parse(text, "trace.txt", 1.0).unwrap()
}

fn hero(at: Vec2) -> Character {
    let shape = CharacterShape::rect(Vec2::new(0.25, 0.25)).unwrap();
    Character::new(shape, at, UP, ControllerConfig::default()).unwrap()
}

/// The cell of a tile segment, or a panic naming the source.
fn cell_of(source: WallSource) -> Cell {
    match source {
        WallSource::Tile { segment, .. } => segment.cell,
        other => panic!("not a tile: {other:?}"),
    }
}

fn one_way_events(trace: &MoveTrace) -> Vec<(Cell, OneWayPass)> {
    trace
        .events
        .iter()
        .filter_map(|e| match *e {
            MoveEvent::OneWay { source, pass } => Some((cell_of(source), pass)),
            _ => None,
        })
        .collect()
}

#[test]
fn a_jump_passes_up_through_a_one_way_platform_and_the_fall_lands_on_it() {
    let m = map(PLATFORM);
    let mut ch = hero(Vec2::new(3.5, 4.5));
    let mut trace = MoveTrace::default();
    // Down onto the floor.
    ch.move_by_traced(&m, Vec2::new(0.0, 1.0), MoveOptions::default(), &mut trace)
        .unwrap();
    assert!(ch.ground().is_some());
    // Up 2.5: from y 4.749 to 2.249, its box crossing the platform's line (y = 3) from
    // below: the platform (cell (3, 3)) lets it through.
    let c = ch
        .move_by_traced(&m, Vec2::new(0.0, -2.5), MoveOptions::default(), &mut trace)
        .unwrap();
    assert!(c.ground.is_none() && c.ceiling.is_none());
    assert_eq!(
        one_way_events(&trace),
        [(Cell::new(3, 3), OneWayPass::FromBelow)]
    );
    assert!(trace.events.contains(&MoveEvent::Airborne));
    let sweep = trace
        .events
        .iter()
        .find_map(|e| match e {
            MoveEvent::Sweep(s) => Some(*s),
            _ => None,
        })
        .unwrap();
    assert_eq!(sweep.purpose, SweepPurpose::Air);
    assert!(sweep.hit.is_none(), "{sweep:?}");
    assert_eq!(trace.end, ch.position);
    // Down 1: its bottom from 2.499 to 3.499, so it meets the platform's top and lands.
    ch.move_by_traced(&m, Vec2::new(0.0, 1.0), MoveOptions::default(), &mut trace)
        .unwrap();
    let hit = trace
        .events
        .iter()
        .find_map(|e| match e {
            MoveEvent::Sweep(s) => s.hit,
            _ => None,
        })
        .unwrap();
    assert_eq!(cell_of(hit.source), Cell::new(3, 3));
    assert_eq!(hit.flags, SegmentFlags::ONE_WAY);
    assert_eq!(hit.normal, UP);
    assert_eq!(hit.point, Vec2::new(3.5, 3.0));
    assert!(trace.events.contains(&MoveEvent::Slide {
        surface: Surface::Ground,
        response: SlideResponse::Landed,
        next: Vec2::ZERO,
    }));
    assert!(one_way_events(&trace).is_empty());
    assert!(trace.events.iter().any(|e| matches!(
        e,
        MoveEvent::Grounded { source, .. } if cell_of(*source) == Cell::new(3, 3)
    )));
    assert!((ch.position.y - (3.0 - 0.25 - 0.001)).abs() < 1e-5);
}

#[test]
fn a_drop_through_a_one_way_platform_is_named() {
    let m = map(PLATFORM);
    let mut ch = hero(Vec2::new(2.5, 2.5));
    let mut trace = MoveTrace::default();
    ch.move_by(&m, Vec2::new(0.0, 0.5), MoveOptions::default())
        .unwrap();
    assert!(ch.ground().is_some(), "standing on the platform");
    let drop = MoveOptions { drop_through: true };
    ch.move_by_traced(&m, Vec2::new(0.0, 0.5), drop, &mut trace)
        .unwrap();
    assert_eq!(
        one_way_events(&trace),
        [(Cell::new(2, 3), OneWayPass::DroppedThrough)]
    );
    assert!(ch.position.y > 3.2, "{}", ch.position);
}

#[test]
fn a_rider_is_carried_by_its_platform_and_a_crush_is_named() {
    let mut m = map("#########\n#.......#\n#.......#\n#.......#\n#########");
    let lift = |m: &mut TileMap, x: f32, y: f32| {
        m.clear_temporaries();
        m.add_temporary(TemporarySegment {
            segment: Segment::new(Vec2::new(x, y), Vec2::new(x + 2.0, y)),
            normal: UP,
            flags: SegmentFlags::SOLID,
            owner: Owner(5),
            velocity: Vec2::ZERO,
        })
        .unwrap();
    };
    lift(&mut m, 2.0, 3.0);
    let mut ch = hero(Vec2::new(3.0, 2.5));
    ch.move_by(&m, Vec2::new(0.0, 0.3), MoveOptions::default())
        .unwrap();
    assert!(ch.ground().is_some());
    // The platform moves right by 0.5: the rider goes with it.
    lift(&mut m, 2.5, 3.0);
    let mut trace = MoveTrace::default();
    ch.move_by_traced(&m, Vec2::new(0.0, 0.01), MoveOptions::default(), &mut trace)
        .unwrap();
    assert_eq!(
        trace.events[0],
        MoveEvent::Carried {
            owner: Owner(5),
            by: Vec2::new(0.5, 0.0)
        }
    );
    assert!((ch.position.x - 3.5).abs() < 1e-5, "{}", ch.position);
    // It rises into the ceiling (y = 1) far faster than the rider fits: carried up, then
    // pushed out of the platform against the ceiling, crushed.
    lift(&mut m, 2.5, 1.3);
    ch.move_by_traced(&m, Vec2::ZERO, MoveOptions::default(), &mut trace)
        .unwrap();
    let crushed: Vec<_> = trace
        .events
        .iter()
        .filter_map(|e| match *e {
            MoveEvent::Pushed {
                source, crushed, ..
            } => Some((source, crushed)),
            _ => None,
        })
        .collect();
    assert_eq!(
        crushed,
        [(
            WallSource::Temporary {
                owner: Owner(5),
                index: 0
            },
            true
        )]
    );
}

#[test]
fn a_traced_move_is_the_untraced_move() {
    let m = map(PLATFORM);
    let mut plain = hero(Vec2::new(1.5, 1.5));
    let mut traced = hero(Vec2::new(1.5, 1.5));
    let mut trace = MoveTrace::default();
    for k in 0..60 {
        let x = [0.3, -0.2, 0.45, 0.0][k % 4];
        let y = if k % 9 == 0 { -1.2 } else { 0.35 };
        let options = MoveOptions {
            drop_through: k % 13 == 5,
        };
        let d = Vec2::new(x, y);
        let a = plain.move_by(&m, d, options).unwrap();
        let b = traced.move_by_traced(&m, d, options, &mut trace).unwrap();
        assert_eq!(a, b, "move {k}");
        assert_eq!(plain.position.to_array(), traced.position.to_array());
        assert_eq!(trace.end, traced.position);
        assert_eq!(trace.displacement, d);
    }
}
