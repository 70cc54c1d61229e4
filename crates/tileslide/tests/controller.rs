//! The platformer controller on ASCII maps (y down: `up` is −y): landing, walls, ceilings,
//! ramps, seams, one-way platforms, corners, frame-rate independence, and a property test
//! that a character never ends inside solid or outside its room.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use proptest::prelude::*;
use tileslide::io::ascii;
use tileslide::{
    Aabb, Character, CharacterShape, Contacts, ControllerConfig, MoveOptions, Owner, Segment,
    SegmentFlags, TemporarySegment, TileMap, Vec2,
};

const UP: Vec2 = Vec2::NEG_Y;
const SKIN: f32 = 1e-3;

fn map(text: &str) -> TileMap {
    ascii::parse(text, "test.txt", 1.0).unwrap()
}

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

fn boxed() -> CharacterShape {
    CharacterShape::rect(v(0.25, 0.4)).unwrap()
}

fn ball() -> CharacterShape {
    CharacterShape::circle(0.3).unwrap()
}

fn hero(shape: CharacterShape, at: Vec2) -> Character {
    Character::new(shape, at, UP, ControllerConfig::default()).unwrap()
}

fn step(ch: &mut Character, m: &TileMap, d: Vec2) -> Contacts {
    ch.move_by(m, d, MoveOptions::default()).unwrap()
}

/// The distance from the shape's centre to its lowest point.
fn foot(shape: CharacterShape) -> f32 {
    match shape {
        CharacterShape::Circle { radius } => radius,
        CharacterShape::Rect { half } => half.y,
        // Any other shape: the bottom of its bounding box.
        other => -other.bounds(Vec2::ZERO).min.y,
    }
}

/// Whether the character at its position overlaps a solid segment by more than `eps`
/// (one-way platforms excepted: a character may stand in one while passing through).
fn in_solid(ch: &Character, m: &TileMap, eps: f32) -> bool {
    let p = ch.position;
    if m.is_point_solid(p) {
        return true;
    }
    let solid = |f: SegmentFlags| f.contains(SegmentFlags::SOLID);
    match ch.shape() {
        CharacterShape::Circle { radius } => {
            let probe = tileslide::Circle::new(p, radius - eps);
            m.segments_overlapping_circle(&probe)
                .iter()
                .any(|s| solid(s.flags))
        }
        CharacterShape::Rect { half } => {
            let probe = Aabb::from_center(p, half - Vec2::splat(eps));
            m.segments_overlapping_aabb(&probe)
                .iter()
                .any(|s| solid(s.flags))
        }
        // Any other shape: its bounding box, shrunk by `eps` (may report more than it
        // overlaps, never less).
        other => {
            let b = other.bounds(p);
            let probe = Aabb::from_center(p, (b.max - b.min) * 0.5 - Vec2::splat(eps));
            m.segments_overlapping_aabb(&probe)
                .iter()
                .any(|s| solid(s.flags))
        }
    }
}

const ROOM: &str = "\
##########
#........#
#........#
#........#
##########";

#[test]
fn falling_characters_land_flush_on_the_floor() {
    let m = map(ROOM);
    for shape in [boxed(), ball()] {
        let mut ch = hero(shape, v(3.5, 1.5));
        let c = step(&mut ch, &m, v(0.0, 5.0));
        assert!(c.is_grounded(), "{shape:?}");
        assert_eq!(c.ground.unwrap().normal, UP);
        assert!(
            (ch.position.y - (4.0 - foot(shape) - SKIN)).abs() < 1e-5,
            "{:?}",
            ch.position
        );
        assert_eq!(ch.position.x, 3.5);
        assert!(ch.ground().is_some());
    }
}

#[test]
fn walking_into_walls_stops_flush_with_a_left_or_right_contact() {
    let m = map(ROOM);
    for shape in [boxed(), ball()] {
        let half_width = match shape {
            CharacterShape::Circle { radius } => radius,
            CharacterShape::Rect { half } => half.x,
            other => other.bounds(Vec2::ZERO).max.x,
        };
        let mut ch = hero(shape, v(4.5, 2.0));
        step(&mut ch, &m, v(0.0, 3.0));
        let c = step(&mut ch, &m, v(20.0, 0.1));
        assert!(
            c.right.is_some() && c.left.is_none() && c.is_grounded(),
            "{c:?}"
        );
        assert_eq!(c.right.unwrap().normal, v(-1.0, 0.0));
        assert!((ch.position.x - (9.0 - half_width - SKIN)).abs() < 1e-4);
        let c = step(&mut ch, &m, v(-20.0, 0.1));
        assert!(c.left.is_some() && c.right.is_none(), "{c:?}");
        assert!((ch.position.x - (1.0 + half_width + SKIN)).abs() < 1e-4);
    }
}

#[test]
fn jumping_into_the_ceiling_stops_with_a_ceiling_contact() {
    let m = map(ROOM);
    for shape in [boxed(), ball()] {
        let mut ch = hero(shape, v(4.5, 2.5));
        step(&mut ch, &m, v(0.0, 3.0));
        let c = step(&mut ch, &m, v(0.5, -10.0));
        assert!(c.ceiling.is_some() && !c.is_grounded(), "{c:?}");
        assert!((ch.position.y - (1.0 + foot(shape) + SKIN)).abs() < 1e-4);
        assert!(
            (ch.position.x - 5.0).abs() < 1e-5,
            "the sideways part is kept"
        );
    }
}

const HILL: &str = "\
##############
#............#
#............#
#............#
#..../##\\....#
##############";

#[test]
fn walking_over_a_45_degree_hill_stays_on_the_ground_every_step() {
    let m = map(HILL);
    for shape in [boxed(), ball()] {
        // The floor is at y = 5, the hill's top at y = 4.
        let mut ch = hero(shape, v(1.5, 5.0 - foot(shape) - SKIN));
        step(&mut ch, &m, v(0.0, 0.1));
        let mut top = f32::INFINITY;
        for k in 0..200 {
            let c = step(&mut ch, &m, v(0.06, 0.02));
            assert!(
                c.is_grounded(),
                "{shape:?} left the ground at step {k}: {:?}",
                ch.position
            );
            assert!(!in_solid(&ch, &m, 1e-3), "{shape:?} in solid at step {k}");
            top = top.min(ch.position.y);
        }
        // Over the hill (one cell high) and down to the far wall.
        assert!(ch.position.x > 12.0 - 0.5, "{:?}", ch.position);
        assert!(
            (top - (4.0 - foot(shape) - SKIN)).abs() < 0.05,
            "{shape:?}: top {top}"
        );
        assert!((ch.position.y - (5.0 - foot(shape) - SKIN)).abs() < 1e-4);
    }
}

#[test]
fn a_slope_steeper_than_the_limit_is_a_wall() {
    let m = map(HILL);
    let config = ControllerConfig {
        max_slope_degrees: 40.0,
        ..ControllerConfig::default()
    };
    let mut ch = Character::new(boxed(), v(2.5, 4.0), UP, config).unwrap();
    step(&mut ch, &m, v(0.0, 1.0));
    let y = ch.position.y;
    let mut c = Contacts::default();
    for _ in 0..100 {
        c = step(&mut ch, &m, v(0.06, 0.02));
    }
    assert!(c.right.is_some(), "{c:?}");
    assert!(c.is_grounded());
    assert_eq!(ch.position.y, y, "it must not climb the steep ramp");
    assert!(ch.position.x < 5.0);
}

#[test]
fn standing_on_a_ramp_under_gravity_does_not_creep() {
    let m = map(HILL);
    for shape in [boxed(), ball()] {
        let mut ch = hero(shape, v(5.5, 2.0));
        for _ in 0..20 {
            step(&mut ch, &m, v(0.0, 0.2));
        }
        assert!(ch.ground().is_some());
        let rest = ch.position;
        for _ in 0..300 {
            let c = step(&mut ch, &m, v(0.0, 0.05));
            assert!(c.is_grounded());
        }
        assert!(
            (ch.position - rest).length() < 1e-5,
            "{shape:?}: {rest:?} → {:?}",
            ch.position
        );
    }
}

#[test]
fn walking_over_many_seams_keeps_the_height_exactly() {
    let m = map("\
##############################
#............................#
#............................#
##############################");
    for shape in [boxed(), ball()] {
        let mut ch = hero(shape, v(1.5, 2.0));
        step(&mut ch, &m, v(0.0, 1.0));
        let y = ch.position.y;
        for k in 0..350 {
            let c = step(&mut ch, &m, v(0.07, 0.03));
            assert!(
                c.is_grounded() && c.right.is_none(),
                "{shape:?} step {k}: {c:?}"
            );
            assert_eq!(ch.position.y, y, "{shape:?} bumped at step {k}");
        }
        assert!(ch.position.x > 25.0);
    }
}

const PLATFORM: &str = "\
##########
#........#
#........#
#..====..#
#........#
#........#
##########";

#[test]
fn a_jump_passes_up_through_a_one_way_platform_and_lands_on_it() {
    let m = map(PLATFORM);
    for shape in [boxed(), ball()] {
        let mut ch = hero(shape, v(4.5, 5.0));
        step(&mut ch, &m, v(0.0, 1.0));
        assert!(ch.ground().is_some());
        // Up through the platform (y = 3) to well above it.
        let c = step(&mut ch, &m, v(0.0, -3.3));
        assert!(c.ceiling.is_none() && !c.is_grounded(), "{c:?}");
        assert!(ch.position.y < 3.0 - foot(shape));
        // Fall back: lands on it.
        let c = step(&mut ch, &m, v(0.0, 2.0));
        let ground = c.ground.expect("lands on the platform");
        assert!(ground.flags.contains(SegmentFlags::ONE_WAY));
        assert!((ch.position.y - (3.0 - foot(shape) - SKIN)).abs() < 1e-4);
        // Drop through on request, then fall to the floor.
        let drop = MoveOptions { drop_through: true };
        ch.move_by(&m, v(0.0, 0.2), drop).unwrap();
        for _ in 0..20 {
            step(&mut ch, &m, v(0.0, 0.2));
        }
        assert!((ch.position.y - (6.0 - foot(shape) - SKIN)).abs() < 1e-4);
    }
}

#[test]
fn walking_into_the_end_of_a_one_way_platform_passes_under_and_through_it() {
    let m = map("\
##########
#........#
#........#
#..====..#
##########");
    // A box 0.8 tall on the floor (y = 4): its top is above the platform at y = 3.
    let mut ch = hero(boxed(), v(1.5, 3.5));
    step(&mut ch, &m, v(0.0, 1.0));
    let y = ch.position.y;
    for _ in 0..60 {
        let c = step(&mut ch, &m, v(0.1, 0.05));
        assert!(c.right.is_none() && c.ceiling.is_none(), "{c:?}");
    }
    assert!(ch.position.x > 7.0);
    assert_eq!(ch.position.y, y);
}

#[test]
fn moving_diagonally_into_a_corner_ends_flush_against_both_surfaces() {
    let m = map(ROOM);
    for shape in [boxed(), ball()] {
        let mut ch = hero(shape, v(4.5, 2.0));
        let c = step(&mut ch, &m, v(10.0, 10.0));
        assert!(c.is_grounded() && c.right.is_some(), "{shape:?}: {c:?}");
        let (hw, hh) = match shape {
            CharacterShape::Circle { radius } => (radius, radius),
            CharacterShape::Rect { half } => (half.x, half.y),
            other => other.bounds(Vec2::ZERO).max.into(),
        };
        assert!(
            (ch.position.x - (9.0 - hw - SKIN)).abs() < 1e-3,
            "{:?}",
            ch.position
        );
        assert!(
            (ch.position.y - (4.0 - hh - SKIN)).abs() < 1e-3,
            "{:?}",
            ch.position
        );
    }
}

/// A game loop at `rate` steps per second for `seconds`: walk right at 3 cells/s under
/// gravity (30 cells/s²), with a jump (12 cells/s up) half a second in. Returns the end
/// position.
fn game_run(m: &TileMap, shape: CharacterShape, rate: f32, seconds: f32) -> Vec2 {
    let mut ch = hero(shape, v(1.5, 2.0));
    let dt = 1.0 / rate;
    let mut vy = 0.0f32;
    let steps = (seconds * rate).round() as usize;
    let jump_at = (0.5 * rate).round() as usize;
    for k in 0..steps {
        if k == jump_at && ch.ground().is_some() {
            vy = -12.0;
        }
        vy += 30.0 * dt;
        let c = step(&mut ch, m, v(3.0 * dt, vy * dt));
        if c.is_grounded() && vy > 0.0 || c.ceiling.is_some() && vy < 0.0 {
            vy = 0.0;
        }
        assert!(!in_solid(&ch, m, 1e-3), "in solid at {rate} Hz step {k}");
    }
    ch.position
}

#[test]
fn the_same_run_at_30_60_and_144_steps_per_second_ends_in_the_same_place() {
    let m = map(HILL);
    for shape in [boxed(), ball()] {
        let ends: Vec<Vec2> = [30.0, 60.0, 144.0]
            .iter()
            .map(|&rate| game_run(&m, shape, rate, 3.0))
            .collect();
        // Walking right for 3 s at 3 cells/s from x = 1.5, over the hill and its ramps,
        // with a jump: x = 10.5 at every rate, resting on the floor.
        for end in &ends {
            assert!((end.x - ends[0].x).abs() < 1e-3, "{shape:?}: {ends:?}");
            assert!((end.y - ends[0].y).abs() < 1e-3, "{shape:?}: {ends:?}");
        }
        assert!((ends[0].x - 10.5).abs() < 1e-3, "{ends:?}");
        assert!(
            (ends[0].y - (5.0 - foot(shape) - SKIN)).abs() < 1e-4,
            "{ends:?}"
        );
    }
}

#[test]
fn bad_input_is_an_error_naming_the_value() {
    let m = map(ROOM);
    let mut ch = hero(boxed(), v(3.5, 2.0));
    let err = ch
        .move_by(&m, v(f32::NAN, 0.0), MoveOptions::default())
        .unwrap_err();
    assert!(err.to_string().contains("displacement"), "{err}");
    assert_eq!(ch.position, v(3.5, 2.0));
    assert!(
        Character::new(
            boxed(),
            v(1.0, 1.0),
            Vec2::ZERO,
            ControllerConfig::default()
        )
        .is_err()
    );
    assert!(
        Character::new(
            boxed(),
            v(f32::INFINITY, 1.0),
            UP,
            ControllerConfig::default()
        )
        .is_err()
    );
    let bad = ControllerConfig {
        max_slope_degrees: 95.0,
        ..ControllerConfig::default()
    };
    let err = Character::new(boxed(), v(1.0, 1.0), UP, bad).unwrap_err();
    assert!(err.to_string().contains("max_slope_degrees"), "{err}");
    assert!(CharacterShape::rect(v(0.5, -1.0)).is_err());
    assert!(CharacterShape::circle(0.0).is_err());
}

/// Two rooms with ramps and platforms, separated by a thick wall.
const ROOMS: &str = "\
########################
#.......##.....#.......#
#...==..##.........=...#
#.......##../\\...#.....#
#../##\\.##.//\\\\..#..\\..#
########################";

/// The room (0 left, 1 right) a position is in, by which side of the thick wall it is.
fn room_of(p: Vec2) -> u8 {
    u8::from(p.x > 9.0)
}

proptest! {
    // Starts inside solid are rejected (about two in five), hence the reject budget.
    #![proptest_config(ProptestConfig {
        cases: 300,
        max_global_rejects: 100_000,
        ..ProptestConfig::default()
    })]

    /// From random free positions, random moves (walks, jumps, falls, of up to several
    /// cells a step, drop-throughs): the character never ends a move inside solid, and
    /// never leaves its room.
    #[test]
    fn a_character_never_ends_inside_solid_or_outside_its_room(
        circle in any::<bool>(),
        x in 1.2f32..22.8, y in 1.2f32..4.8,
        moves in prop::collection::vec((-4.0f32..4.0, -4.0f32..4.0, any::<bool>()), 1..30),
    ) {
        let m = map(ROOMS);
        let shape = if circle { ball() } else { boxed() };
        let mut ch = hero(shape, v(x, y));
        prop_assume!(!in_solid(&ch, &m, 0.0));
        let room = room_of(ch.position);
        for (k, &(dx, dy, drop)) in moves.iter().enumerate() {
            ch.move_by(&m, v(dx, dy), MoveOptions { drop_through: drop }).unwrap();
            prop_assert!(!in_solid(&ch, &m, 2e-3), "move {}: in solid at {:?}", k, ch.position);
            prop_assert_eq!(room_of(ch.position), room, "move {}: left its room to {:?}", k, ch.position);
        }
    }
}

/// Cells of 0.25: a one-cell step (0.25 high) at x = 1.75, and a column rising 0.5 above the
/// step at x = 2.75.
const STEPS: &str = "\
####################
#..................#
#..................#
#..................#
#..........#.......#
#..........#.......#
#......#######.....#
####################";

fn small_box() -> CharacterShape {
    CharacterShape::rect(v(0.1, 0.2)).unwrap()
}

#[test]
fn a_walk_steps_up_onto_a_ledge_no_higher_than_the_step_height() {
    let m = ascii::parse(STEPS, "steps.txt", 0.25).unwrap();
    let walk = |step_height: f32| {
        let config = ControllerConfig {
            step_height,
            ..ControllerConfig::default()
        };
        let mut ch = Character::new(small_box(), v(0.5, 1.5), UP, config).unwrap();
        step(&mut ch, &m, v(0.0, 1.0));
        let mut last = Contacts::default();
        for _ in 0..100 {
            last = step(&mut ch, &m, v(0.05, 0.02));
            assert!(last.is_grounded(), "{:?}", ch.position);
            assert!(!in_solid(&ch, &m, 1e-3));
        }
        (ch.position, last)
    };
    // Without stepping: stopped at the step's face (x = 1.75).
    let (at, contacts) = walk(0.0);
    assert!((at.x - (1.75 - 0.1 - SKIN)).abs() < 1e-4, "{at:?}");
    assert!(contacts.right.is_some());
    // With a 0.3 step height: up onto the step (top at y = 1.5), and stopped by the
    // column 0.5 higher (x = 2.75).
    let (at, contacts) = walk(0.3);
    assert!((at.y - (1.5 - 0.2 - SKIN)).abs() < 1e-4, "{at:?}");
    assert!((at.x - (2.75 - 0.1 - SKIN)).abs() < 1e-4, "{at:?}");
    assert!(contacts.right.is_some());
}

const OPEN: &str = "\
####################
#..................#
#..................#
#..................#
#..................#
#..................#
#..................#
#..................#
####################";

/// A platform: owner 7's solid top segment, 2 wide, centred at `at`, facing up.
fn platform(m: &mut TileMap, at: Vec2, velocity: Vec2) {
    m.clear_temporaries();
    m.add_temporary(TemporarySegment {
        segment: Segment::new(at - v(1.0, 0.0), at + v(1.0, 0.0)),
        normal: UP,
        flags: SegmentFlags::SOLID,
        owner: Owner(7),
        velocity,
    })
    .unwrap();
}

#[test]
fn a_rider_is_carried_exactly_however_fast_its_platform_moves() {
    let mut m = map(OPEN);
    for shape in [boxed(), ball()] {
        let mut at = v(5.0, 6.0);
        platform(&mut m, at, Vec2::ZERO);
        let mut ch = hero(shape, v(5.2, 4.0));
        for _ in 0..10 {
            step(&mut ch, &m, v(0.0, 0.3));
        }
        assert!(ch.ground().is_some());
        let offset = ch.position - at;
        assert!((offset.y + foot(shape) + SKIN).abs() < 1e-4, "{offset:?}");
        // Sideways, then up fast, then down fast (faster than the character falls).
        let moves = [v(0.1, 0.0); 20]
            .into_iter()
            .chain([v(0.0, -0.45); 6])
            .chain([v(-0.2, 0.6); 5]);
        for (k, d) in moves.enumerate() {
            at += d;
            platform(&mut m, at, d);
            let c = step(&mut ch, &m, v(0.0, 0.05));
            let ground = c
                .ground
                .unwrap_or_else(|| panic!("{shape:?} fell off at frame {k}"));
            assert_eq!(ground.platform_velocity(), d);
            assert!(
                (ch.position - at - offset).length() < 1e-3,
                "{shape:?} frame {k}: {:?} vs platform {at:?}",
                ch.position
            );
        }
    }
}

/// The open room with a still platform at (5, 6), and a box that fell onto it.
fn standing_on_a_platform() -> (TileMap, Vec2, Character) {
    let mut m = map(OPEN);
    let at = v(5.0, 6.0);
    platform(&mut m, at, Vec2::ZERO);
    let mut ch = hero(boxed(), v(5.0, 5.0));
    for _ in 0..5 {
        step(&mut ch, &m, v(0.0, 0.3));
    }
    assert!(ch.ground().is_some());
    (m, at, ch)
}

#[test]
fn a_platform_rising_into_the_ceiling_crushes_its_rider_without_tunnelling() {
    let (mut m, mut at, mut ch) = standing_on_a_platform();
    let mut crushed = false;
    for _ in 0..30 {
        at.y -= 0.3;
        if at.y < 0.5 {
            break;
        }
        platform(&mut m, at, v(0.0, -0.3));
        let c = step(&mut ch, &m, v(0.0, 0.05));
        crushed |= c.crush.is_some();
        // Never through the ceiling at y = 1.
        assert!(ch.position.y - 0.4 >= 1.0, "{:?}", ch.position);
    }
    assert!(crushed);
}

#[test]
fn a_platform_moving_sideways_into_a_character_pushes_it() {
    let mut m = map(OPEN);
    let mut ch = hero(boxed(), v(5.0, 5.0));
    step(&mut ch, &m, v(0.0, 5.0));
    // The left face of a block moving left: a vertical segment facing −x.
    for k in 0..10 {
        let x = 6.0 - 0.2 * k as f32;
        m.clear_temporaries();
        m.add_temporary(TemporarySegment {
            segment: Segment::new(v(x, 8.0), v(x, 6.0)),
            normal: v(-1.0, 0.0),
            flags: SegmentFlags::SOLID,
            owner: Owner(3),
            velocity: v(-0.2, 0.0),
        })
        .unwrap();
        step(&mut ch, &m, v(0.0, 0.05));
        assert!(
            ch.position.x + 0.25 <= x,
            "frame {k}: {:?} vs face at {x}",
            ch.position
        );
    }
    assert!(ch.position.x < 4.5);
}

#[test]
fn a_platform_rising_beside_a_character_lifts_it_only_when_more_of_it_is_under_it_than_in_it() {
    // A box standing on the floor (y = 8), its right side at x = 5.25; a platform's top
    // appears 0.1 above the floor with its left end `overlap` under the box. Touching the
    // box's side, or reaching less far under it than into it (0.1 less a skin), it pushes
    // the box sideways off its end, a skin clear; reaching further under it, it lifts the
    // box onto itself. (A box wedged in a gap as wide as itself was once lifted
    // out of it by the end of a ledge's top that its side touched.)
    let stand = 8.0 - 0.4 - SKIN;
    for (overlap, x, y) in [
        (0.0, 5.0 - SKIN, stand),
        (1e-4, 5.0 - 1e-4 - SKIN, stand),
        (0.05, 5.0 - 0.05 - SKIN, stand),
        (0.2, 5.0, 7.9 - 0.4 - SKIN),
    ] {
        let mut m = map(OPEN);
        let mut ch = hero(boxed(), v(5.0, 7.0));
        step(&mut ch, &m, v(0.0, 2.0));
        assert!((ch.position - v(5.0, stand)).abs().max_element() < 1e-5);
        platform(&mut m, v(5.25 - overlap + 1.0, 7.9), v(0.0, -0.1));
        let c = step(&mut ch, &m, Vec2::ZERO);
        assert!(
            (ch.position - v(x, y)).abs().max_element() < 1e-4,
            "overlap {overlap}: {:?}, not ({x}, {y})",
            ch.position
        );
        assert!(c.crush.is_none(), "overlap {overlap}");
    }
}

#[test]
fn level_bounds_hold_when_submitted_as_segments_and_nothing_breaks_without_them() {
    // A floor with no side walls: the map's edge is x = 0 and x = 10.
    let mut m = map("\
..........
..........
##########");
    let mut ch = hero(boxed(), v(5.0, 1.0));
    step(&mut ch, &m, v(0.0, 1.0));
    // Without bounds, walking left off the map's edge: it leaves the map and falls, no panic.
    for _ in 0..100 {
        step(&mut ch, &m, v(-0.2, 0.1));
    }
    assert!(
        ch.position.x < 0.0 && ch.position.y > 3.0,
        "{:?}",
        ch.position
    );
    // The level's bounds as temporary segments facing in (the map's own edges are not walls:
    // a game decides whether leaving the level is a fall, a wall or a door).
    let bounds = [
        (v(0.0, -5.0), v(0.0, 3.0), v(1.0, 0.0)),
        (v(10.0, 3.0), v(10.0, -5.0), v(-1.0, 0.0)),
    ];
    for (a, b, normal) in bounds {
        m.add_temporary(TemporarySegment {
            segment: Segment::new(a, b),
            normal,
            flags: SegmentFlags::SOLID,
            owner: Owner(99),
            velocity: Vec2::ZERO,
        })
        .unwrap();
    }
    let mut ch = hero(boxed(), v(5.0, 1.0));
    step(&mut ch, &m, v(0.0, 1.0));
    let mut c = Contacts::default();
    for _ in 0..100 {
        c = step(&mut ch, &m, v(-0.2, 0.1));
    }
    assert!(c.left.is_some() && c.is_grounded(), "{c:?}");
    assert!(
        (ch.position.x - (0.25 + SKIN)).abs() < 1e-4,
        "{:?}",
        ch.position
    );
}

#[test]
fn a_jump_off_a_moving_platform_can_keep_its_velocity() {
    let (mut m, mut at, mut ch) = standing_on_a_platform();
    let carry = v(0.15, 0.0);
    at += carry;
    platform(&mut m, at, carry);
    let c = step(&mut ch, &m, v(0.0, 0.05));
    // The game adds the platform's velocity to the jump.
    let keep = c.ground.unwrap().platform_velocity();
    assert_eq!(keep, carry);
    let before = ch.position;
    m.clear_temporaries();
    let c = step(&mut ch, &m, keep + v(0.0, -0.3));
    assert!(!c.is_grounded());
    assert!((ch.position - before - v(0.15, -0.3)).length() < 1e-5);
}

/// Submits `segments` (start, end, normal) as owner 5's temporary segments, solid unless
/// `one_way`.
fn submit(m: &mut TileMap, segments: &[(Vec2, Vec2, Vec2)], one_way: bool) {
    m.clear_temporaries();
    let flags = if one_way {
        SegmentFlags::ONE_WAY
    } else {
        SegmentFlags::SOLID
    };
    for &(a, b, normal) in segments {
        m.add_temporary(TemporarySegment {
            segment: Segment::new(a, b),
            normal,
            flags,
            owner: Owner(5),
            velocity: Vec2::ZERO,
        })
        .unwrap();
    }
}

#[test]
fn a_slanted_platform_with_a_rough_normal_holds_its_rider_without_hovering() {
    // Submitted with straight-up as its normal, though it slopes by 14 degrees.
    let mut m = map(OPEN);
    submit(&mut m, &[(v(4.0, 5.0), v(8.0, 6.0), UP)], false);
    let mut ch = hero(boxed(), v(7.0, 4.0));
    for _ in 0..20 {
        let c = step(&mut ch, &m, v(0.0, 0.1));
        assert!(c.crush.is_none());
    }
    assert!(ch.ground().is_some(), "{:?}", ch.position);
    // Its bottom-left corner (6.75, y + 0.4) a skin above the slope (y = 5 + (x − 4) / 4).
    let surface = 5.0 + (6.75 - 4.0) / 4.0;
    let gap = surface - (ch.position.y + 0.4);
    assert!(gap > 0.0 && gap < 3.0 * SKIN, "gap {gap}");
}

#[test]
fn walking_under_a_still_one_way_platform_does_not_pop_up_onto_it() {
    // A one-way temporary platform 0.3 above the floor: the box (0.8 tall) walks through.
    let mut m = map(OPEN);
    submit(&mut m, &[(v(6.0, 7.7), v(9.0, 7.7), UP)], true);
    let mut ch = hero(boxed(), v(3.0, 7.0));
    step(&mut ch, &m, v(0.0, 1.0));
    let y = ch.position.y;
    for _ in 0..80 {
        let c = step(&mut ch, &m, v(0.1, 0.05));
        assert!(c.crush.is_none());
        assert_eq!(ch.position.y, y, "popped up at {:?}", ch.position);
    }
    assert!(ch.position.x > 9.5);
}

#[test]
fn a_rider_stays_put_when_its_platform_resubmits_its_segments_in_another_order() {
    let top = (v(4.0, 6.0), v(6.0, 6.0), UP);
    let bottom = (v(6.0, 6.5), v(4.0, 6.5), Vec2::Y);
    let mut m = map(OPEN);
    submit(&mut m, &[top, bottom], false);
    let mut ch = hero(boxed(), v(5.0, 5.0));
    for _ in 0..10 {
        step(&mut ch, &m, v(0.0, 0.2));
    }
    let rest = ch.position;
    // Reordered, then the top reversed end for end.
    submit(&mut m, &[bottom, top], false);
    step(&mut ch, &m, v(0.0, 0.05));
    let reversed = (top.1, top.0, UP);
    submit(&mut m, &[reversed, bottom], false);
    let c = step(&mut ch, &m, v(0.0, 0.05));
    assert!(c.is_grounded());
    assert!(
        (ch.position - rest).length() < 1e-5,
        "{rest:?} → {:?}",
        ch.position
    );
}

#[test]
fn a_position_set_to_nan_or_an_overflowing_move_is_an_error() {
    let m = map(ROOM);
    let mut ch = hero(boxed(), v(3.5, 2.0));
    let err = ch
        .move_by(&m, v(3.0e38, 3.0e38), MoveOptions::default())
        .unwrap_err();
    assert!(err.to_string().contains("displacement"), "{err}");
    ch.position = v(f32::NAN, 2.0);
    let err = ch
        .move_by(&m, v(0.1, 0.0), MoveOptions::default())
        .unwrap_err();
    assert!(err.to_string().contains("position"), "{err}");
}

/// A circle running up a ramp into the wedge it makes with a ceiling, and on pushing into
/// it for 10 seconds, stays out of both. Where the x coordinate's unit in the last place is
/// half the y coordinate's (x in [32, 64), y in [64, 128)), each push used to advance the
/// character a unit along x and none along y, off the ramp's line and into the ramp: 10⁻⁴
/// deep after 40 steps and deeper each step (the soak found it).
#[test]
fn a_circle_pushing_into_the_wedge_of_a_ramp_and_a_ceiling_stays_out_of_both() {
    // A pocket at (56, 88): the ceiling is the bottom of the ramps above, the floor a ramp
    // down to the right onto a block.
    let (w, h) = (64usize, 92usize);
    let mut rows = vec![vec!['.'; w]; h];
    for (r, row) in rows.iter_mut().enumerate() {
        for (c, cell) in row.iter_mut().enumerate() {
            if r == 0 || c == 0 || r == h - 1 || c == w - 1 {
                *cell = '#';
            }
        }
    }
    rows[87][56] = '/';
    rows[87][57] = '\\';
    rows[88][56] = '\\';
    rows[89][57] = '#';
    let text: String = rows
        .iter()
        .map(|r| r.iter().collect::<String>() + "\n")
        .collect();
    let m = map(&text);
    let radius = 0.297_474_24;
    let mut ch = hero(CharacterShape::circle(radius).unwrap(), v(56.9, 88.35));
    let ramp = Segment::new(v(56.0, 88.0), v(57.0, 89.0));
    let mut velocity = Vec2::ZERO;
    for frame in 0..600 {
        velocity.x = -6.0;
        velocity.y = (velocity.y + 40.0 / 60.0).min(20.0);
        ch.move_and_slide(&m, &mut velocity, 1.0 / 60.0, MoveOptions::default())
            .unwrap();
        let p = ch.position;
        let into_ramp = radius - ramp.distance_squared_to(p).sqrt();
        let into_ceiling = 88.0 - (p.y - radius);
        assert!(
            into_ramp <= 0.0 && into_ceiling <= 0.0,
            "frame {frame}: at {p}, {into_ramp} into the ramp, {into_ceiling} into the ceiling"
        );
    }
    // It got into the wedge.
    assert!(ch.position.x < 56.75, "{}", ch.position);
}
