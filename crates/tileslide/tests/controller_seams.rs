//! A circle rolling across seams where one-way platforms meet each other or solid tiles
//! (ASCII maps, y down: `up` is −y) keeps its ground normal and its height to the bit, as it
//! does on an all-solid floor.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use tileslide::io::ascii;
use tileslide::{Character, CharacterShape, ControllerConfig, MoveOptions, Vec2};

const UP: Vec2 = Vec2::NEG_Y;

/// Row 3 mixes one-way platforms and solid tiles with every kind of seam: `==`, `=#`,
/// `#=`, single tiles of each between the other.
const MIXED: &str = "\
##############################
#............................#
#............................#
#..====##===#=#=##====#######.
##############################";

/// The same floor all solid, for reference.
const SOLID: &str = "\
##############################
#............................#
#............................#
#..##########################.
##############################";

/// Rolls circles of several radii at several speeds along row 3's top (y = 3) from x = 3.5
/// to x = 27; returns the largest tilt of the ground normal from up and the largest change
/// of height after any step from the height after the first.
fn wobble(text: &str) -> (f32, f32) {
    let m = ascii::parse(text, "seams.txt", 1.0).unwrap();
    let (mut tilt, mut stray) = (0.0f32, 0.0f32);
    for radius in [0.25, 0.3, 0.4, 0.45] {
        for speed in [0.0093, 0.037, 0.11] {
            let shape = CharacterShape::circle(radius).unwrap();
            let mut ch =
                Character::new(shape, Vec2::new(3.5, 2.0), UP, ControllerConfig::default())
                    .unwrap();
            ch.move_by(&m, Vec2::new(0.0, 1.0), MoveOptions::default())
                .unwrap();
            // (Landing leaves it a skin above the floor give or take rounding; walking then
            // settles it to the height it keeps.)
            ch.move_by(&m, Vec2::new(speed, 0.03), MoveOptions::default())
                .unwrap();
            let height = ch.position.y;
            while ch.position.x < 27.0 {
                let contacts = ch
                    .move_by(&m, Vec2::new(speed, 0.03), MoveOptions::default())
                    .unwrap();
                let ground = contacts.ground.expect("stays on the ground");
                // (The angle from its sine and cosine: `acos` of a cosine rounded to 1 says 0.)
                let angle = UP.perp_dot(ground.normal).atan2(UP.dot(ground.normal));
                tilt = tilt.max(angle.abs());
                stray = stray.max((ch.position.y - height).abs());
            }
        }
    }
    (tilt, stray)
}

#[test]
fn a_circle_rolls_across_one_way_seams_as_flat_as_across_a_solid_floor() {
    assert_eq!(wobble(SOLID), (0.0, 0.0));
    assert_eq!(wobble(MIXED), (0.0, 0.0));
}
