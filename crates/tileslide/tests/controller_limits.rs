//! Absurd values at the controller's entry points: every finite value beyond
//! `MAX_COORD` (or one that would overflow inside) is refused with an error naming it, and
//! every value within it moves the character without crossing a wall or making a NaN.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use proptest::prelude::*;
use tileslide::io::ascii;
use tileslide::{
    Character, CharacterShape, ControllerConfig, ControllerError, MoveOptions, Vec2,
    limits::MAX_COORD,
};

const ROOM: &str = "\
; a room of 8 x 3 cells: inside x in (1, 9), y in (1, 4)
##########
#........#
#........#
#........#
##########";

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

fn hero() -> CharacterShape {
    CharacterShape::rect(v(0.25, 0.4)).unwrap()
}

fn new(
    shape: CharacterShape,
    at: Vec2,
    up: Vec2,
    config: ControllerConfig,
) -> Result<Character, ControllerError> {
    Character::new(shape, at, up, config)
}

/// The error's text names `what`.
fn names(err: ControllerError, what: &str) {
    assert!(err.to_string().contains(what), "{err} does not name {what}");
}

const FAR: [f32; 4] = [MAX_COORD * 1.001, 1e20, 3e38, f32::MAX];

#[test]
fn positions_and_moves_beyond_max_coord_are_refused_naming_the_value() {
    let m = ascii::parse(ROOM, "room.txt", 1.0).unwrap();
    let config = ControllerConfig::default();
    for far in FAR {
        for p in [v(far, 2.0), v(2.0, -far)] {
            names(new(hero(), p, Vec2::NEG_Y, config).unwrap_err(), "position");
        }
        let mut ch = new(hero(), v(2.0, 2.0), Vec2::NEG_Y, config).unwrap();
        names(ch.teleport(v(-far, 2.0)).unwrap_err(), "position");
        assert_eq!(ch.position, v(2.0, 2.0));
        // A velocity × dt of 1e20 or 3e38: refused, and the character stays where it was.
        for d in [v(far, 0.0), v(0.0, far), v(-far, far)] {
            let err = ch.move_by(&m, d, MoveOptions::default()).unwrap_err();
            names(err, "displacement");
            assert_eq!(ch.position, v(2.0, 2.0));
        }
        // A move within range whose end point is not.
        ch.position = v(MAX_COORD - 1.0, 2.0);
        names(
            ch.move_by(&m, v(far * 0.5 + 2.0, 0.0), MoveOptions::default())
                .unwrap_err(),
            "displacement",
        );
        // The position is a public field: a far one is refused at the next move.
        ch.position = v(far, 2.0);
        names(
            ch.move_by(&m, v(0.1, 0.0), MoveOptions::default())
                .unwrap_err(),
            "position",
        );
    }
}

#[test]
fn a_velocity_and_time_step_whose_product_overflows_are_named_as_given() {
    let m = ascii::parse(ROOM, "room.txt", 1.0).unwrap();
    let mut ch = new(
        hero(),
        v(2.0, 2.0),
        Vec2::NEG_Y,
        ControllerConfig::default(),
    )
    .unwrap();
    for (velocity, dt) in [
        (v(3e38, 0.0), 10.0),
        (v(0.0, -1e30), 1e10),
        (v(MAX_COORD, 0.0), 2.0),
    ] {
        let mut given = velocity;
        let err = ch
            .move_and_slide(&m, &mut given, dt, MoveOptions::default())
            .unwrap_err();
        names(err, "velocity × dt");
        assert_eq!((ch.position, given), (v(2.0, 2.0), velocity), "unchanged");
    }
}

#[test]
fn shapes_and_distances_beyond_max_coord_are_refused_naming_the_value() {
    for far in FAR {
        names(CharacterShape::circle(far).unwrap_err(), "radius");
        names(
            CharacterShape::rect(v(0.5, far)).unwrap_err(),
            "half extents",
        );
        // The variants' fields are public: `Character::new` checks a shape built directly.
        for shape in [
            CharacterShape::Circle { radius: far },
            CharacterShape::Circle { radius: f32::NAN },
            CharacterShape::Rect { half: v(far, 0.5) },
            CharacterShape::Rect { half: v(0.5, -1.0) },
        ] {
            let err =
                new(shape, v(2.0, 2.0), Vec2::NEG_Y, ControllerConfig::default()).unwrap_err();
            assert!(matches!(err, ControllerError::BadShape { .. }), "{err}");
        }
        for (field, config) in [
            (
                "skin",
                ControllerConfig {
                    skin: far,
                    ..ControllerConfig::default()
                },
            ),
            (
                "snap_distance",
                ControllerConfig {
                    snap_distance: far,
                    ..ControllerConfig::default()
                },
            ),
            (
                "step_height",
                ControllerConfig {
                    step_height: far,
                    ..ControllerConfig::default()
                },
            ),
        ] {
            names(
                new(hero(), v(2.0, 2.0), Vec2::NEG_Y, config).unwrap_err(),
                field,
            );
        }
    }
}

#[test]
fn an_up_with_huge_or_tiny_finite_components_is_normalized_not_refused() {
    // Its length squared overflows (or underflows) though the direction is clear.
    for (up, unit) in [
        (v(0.0, -3e38), v(0.0, -1.0)),
        (
            v(f32::MAX, f32::MAX),
            Vec2::splat(std::f32::consts::FRAC_1_SQRT_2),
        ),
        (v(1e-30, 0.0), v(1.0, 0.0)),
        (v(0.0, -1e-45), v(0.0, -1.0)),
    ] {
        let ch = new(hero(), v(2.0, 2.0), up, ControllerConfig::default()).unwrap();
        assert!((ch.up() - unit).length() < 1e-6, "{up:?} -> {:?}", ch.up());
    }
    names(
        new(hero(), v(2.0, 2.0), Vec2::ZERO, ControllerConfig::default()).unwrap_err(),
        "up",
    );
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// Moves as long as the range allows, in any direction, by a box or a circle of any size
    /// that fits the room: the character stays inside the room, at finite coordinates.
    #[test]
    fn no_move_within_max_coord_crosses_a_wall(
        circle in any::<bool>(),
        size in 0.05f32..0.9,
        x in 1.0f32..9.0, y in 1.0f32..4.0,
        moves in prop::collection::vec((-1.0f32..1.0, -1.0f32..1.0, 0i32..25), 1..8),
    ) {
        let m = ascii::parse(ROOM, "room.txt", 1.0).unwrap();
        let shape = if circle {
            CharacterShape::circle(size).unwrap()
        } else {
            CharacterShape::rect(v(size, size)).unwrap()
        };
        let mut ch = new(shape, v(x, y).clamp(v(1.0 + size, 1.0 + size), v(9.0 - size, 4.0 - size)), Vec2::NEG_Y, ControllerConfig::default()).unwrap();
        for &(dx, dy, scale) in &moves {
            // Up to 2^24 cells: the end point may pass MAX_COORD; then it is refused.
            let d = v(dx, dy) * 2f32.powi(scale) ;
            let before = ch.position;
            match ch.move_by(&m, d, MoveOptions::default()) {
                Ok(_) => {}
                Err(err) => {
                    prop_assert!(matches!(err, ControllerError::OutOfRange { .. }), "{}", err);
                    prop_assert_eq!(ch.position, before);
                }
            }
            let p = ch.position;
            prop_assert!(p.is_finite(), "{:?}", p);
            prop_assert!(p.x > 1.0 && p.x < 9.0 && p.y > 1.0 && p.y < 4.0, "left the room: {:?}", p);
        }
    }
}
