//! `Character::move_and_slide`: the velocity a move leaves a character, on ASCII maps (y
//! down: `up` is −y). Landing zeroes the fall, sliding along a steep slope keeps the
//! tangential part, walking up a ramp keeps the sideways speed, and (property test) after
//! any move on random maps the velocity never points into a ceiling or wall it touched,
//! nor down into its ground.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use crate::generators;

use generators::{rows, tile_chars, wall_in};
use proptest::prelude::*;
use tileslide::io::ascii;
use tileslide::{Character, CharacterShape, ControllerConfig, MoveOptions, TileMap, Vec2};

const UP: Vec2 = Vec2::NEG_Y;
const DT: f32 = 1.0 / 60.0;
const GRAVITY: f32 = 30.0;

fn map(text: &str) -> TileMap {
    ascii::parse(text, "test.txt", 1.0).unwrap()
}

fn hero(shape: CharacterShape, at: Vec2, config: ControllerConfig) -> Character {
    Character::new(shape, at, UP, config).unwrap()
}

#[test]
fn landing_on_a_floor_zeroes_the_fall_and_keeps_the_run() {
    let m = map("\
########
#......#
#......#
#......#
########");
    let shape = CharacterShape::rect(Vec2::new(0.25, 0.4)).unwrap();
    let mut ch = hero(shape, Vec2::new(2.0, 1.5), ControllerConfig::default());
    let mut velocity = Vec2::new(1.0, 0.0);
    let mut landed = None;
    for frame in 0..120 {
        velocity.y += GRAVITY * DT;
        let contacts = ch
            .move_and_slide(&m, &mut velocity, DT, MoveOptions::default())
            .unwrap();
        if contacts.is_grounded() {
            landed = Some(frame);
            break;
        }
        assert!(velocity.y > 0.0, "falling until it lands");
    }
    assert!(landed.is_some(), "never landed");
    assert_eq!(velocity, Vec2::new(1.0, 0.0));
}

#[test]
fn sliding_down_a_steep_slope_keeps_the_tangential_part_of_the_velocity() {
    // A 45° ramp, steeper than the slope limit of 30°: a wall to slide down.
    let m = map("\
#######
#.....#
#.....#
#..../#
#######");
    let config = ControllerConfig {
        max_slope_degrees: 30.0,
        ..ControllerConfig::default()
    };
    let shape = CharacterShape::circle(0.25).unwrap();
    let mut ch = hero(shape, Vec2::new(5.5, 3.05), config);
    let before = Vec2::new(0.0, 12.0);
    let mut velocity = before;
    let contacts = ch
        .move_and_slide(&m, &mut velocity, DT, MoveOptions::default())
        .unwrap();
    let slope = contacts
        .right
        .unwrap_or_else(|| panic!("meets the ramp as a wall: {contacts:?} at {}", ch.position));
    let n = slope.normal;
    let tangent = n.perp();
    assert!((n - Vec2::new(-1.0, -1.0).normalize()).length() < 1e-5);
    assert!(
        (velocity.dot(tangent) - before.dot(tangent)).abs() < 1e-4,
        "{velocity} {contacts:?}"
    );
    assert!(velocity.dot(n).abs() < 1e-4);
    assert!(
        velocity.x < 0.0 && velocity.y > 0.0,
        "down the slope: {velocity}"
    );
}

#[test]
fn walking_up_a_walkable_ramp_keeps_the_sideways_speed() {
    let m = map("\
##########
#........#
#........#
#..../####
##########");
    let shape = CharacterShape::circle(0.3).unwrap();
    let mut ch = hero(shape, Vec2::new(2.0, 3.699), ControllerConfig::default());
    let mut velocity = Vec2::new(3.0, 0.0);
    let mut on_ramp = 0;
    for _ in 0..90 {
        velocity.y += GRAVITY * DT;
        let contacts = ch
            .move_and_slide(&m, &mut velocity, DT, MoveOptions::default())
            .unwrap();
        assert!(contacts.is_grounded(), "left the ground at {}", ch.position);
        assert_eq!(velocity, Vec2::new(3.0, 0.0));
        on_ramp += usize::from(contacts.ground.unwrap().normal.x < 0.0);
    }
    assert!(on_ramp > 0, "never walked on the ramp");
    assert!(ch.position.y < 3.0, "climbed the ramp: {}", ch.position);
}

/// A random 10 × 8 walled room of empty cells, solid squares, ramps and one-way platforms,
/// with cell (2, 2) and the cells around it empty (where the character starts).
fn random_room() -> impl Strategy<Value = String> {
    tile_chars(&[(10, '.'), (3, '#'), (1, '/'), (1, '\\'), (2, '=')], 80).prop_map(|mut chars| {
        wall_in(10, &mut chars);
        for (c, r) in [(1, 1), (2, 1), (3, 1), (1, 2), (2, 2), (3, 2)] {
            chars[r * 10 + c] = '.';
        }
        rows(10, &chars)
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    /// On random rooms, a box or circle run left and right under gravity, jumping now and
    /// then, keeps after every move a velocity that points into no ceiling or wall it
    /// touched (within rounding) and not down into its ground.
    #[test]
    fn the_velocity_after_a_move_never_points_into_what_the_move_touched(
        text in random_room(),
        circle in any::<bool>(),
        size in 0.15f32..0.4,
        max_slope in 20.0f32..60.0,
        inputs in prop::collection::vec((-8.0f32..8.0, any::<bool>()), 90),
    ) {
        let m = map(&text);
        let shape = if circle {
            CharacterShape::circle(size).unwrap()
        } else {
            CharacterShape::rect(Vec2::new(size * 0.8, size)).unwrap()
        };
        let config = ControllerConfig { max_slope_degrees: max_slope, ..ControllerConfig::default() };
        let mut ch = hero(shape, Vec2::new(2.5, 2.5), config);
        let mut velocity = Vec2::ZERO;
        for (frame, &(run, jump)) in inputs.iter().enumerate() {
            velocity.x = run;
            velocity.y += GRAVITY * DT;
            if jump && ch.ground().is_some() {
                velocity.y = -9.0;
            }
            let asked = velocity;
            let contacts = ch.move_and_slide(&m, &mut velocity, DT, MoveOptions::default()).unwrap();
            let tolerance = 1e-5 * asked.length().max(1.0);
            for (what, c) in [("ceiling", contacts.ceiling), ("left", contacts.left), ("right", contacts.right)] {
                if let Some(c) = c {
                    prop_assert!(
                        velocity.dot(c.normal) >= -tolerance,
                        "frame {frame}: {velocity} (asked {asked}) into the {what} {}\n{text}", c.normal
                    );
                }
            }
            if contacts.is_grounded() {
                prop_assert!(velocity.dot(UP) >= 0.0, "frame {frame}: {velocity} falls into the ground\n{text}");
            }
            prop_assert!(velocity.length() <= asked.length() * (1.0 + 1e-5), "frame {frame}: {velocity} faster than {asked}");
        }
    }
}
