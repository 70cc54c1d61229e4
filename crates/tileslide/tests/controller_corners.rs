//! The controller in a concave corner reached exactly (ASCII maps, y down: `up` is −y): a
//! box that lands on a floor at the same instant its side reaches a wall meets both at
//! equal `t`, and which it stops on first must not depend on the order the segments come
//! in.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use proptest::prelude::*;
use tileslide::io::ascii;
use tileslide::{
    Character, CharacterShape, Contact, Contacts, ControllerConfig, MoveOptions, Owner, Segment,
    SegmentFlags, TemporarySegment, TileMap, Vec2, geometry::EndCaps, geometry::sweep_box_segment,
};

const UP: Vec2 = Vec2::NEG_Y;
const SKIN: f32 = 1e-3;

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

/// An open room, 16 cells square, with nothing solid in it.
fn open() -> TileMap {
    let row = ".".repeat(16);
    let text = vec![row; 16].join("\n");
    ascii::parse(&text, "open.txt", 1.0).unwrap()
}

/// A concave corner: a floor at `floor_y` facing up (−y) and a wall at `wall_x` facing left,
/// meeting at (`wall_x`, `floor_y`).
fn corner(wall_x: f32, floor_y: f32) -> [(Segment, Vec2); 2] {
    [
        (
            Segment::new(v(0.0, floor_y), v(wall_x, floor_y)),
            v(0.0, -1.0),
        ),
        (
            Segment::new(v(wall_x, floor_y), v(wall_x, 0.0)),
            v(-1.0, 0.0),
        ),
    ]
}

/// The open room with `segments` submitted as owner 1's solid temporary segments in the
/// order given.
fn with(segments: &[(Segment, Vec2)]) -> TileMap {
    let mut m = open();
    for &(segment, normal) in segments {
        m.add_temporary(TemporarySegment {
            segment,
            normal,
            flags: SegmentFlags::SOLID,
            owner: Owner(1),
            velocity: Vec2::ZERO,
        })
        .unwrap();
    }
    m
}

/// What a contact says about the surface: its normal and flags (its source names the
/// temporary segment's index, which is the submission order).
fn surface(contact: Option<Contact>) -> Option<(Vec2, SegmentFlags)> {
    contact.map(|c| (c.normal, c.flags))
}

/// Every contact's surface, in the order ground, ceiling, left, right, crush.
fn surfaces(contacts: &Contacts) -> [Option<(Vec2, SegmentFlags)>; 5] {
    [
        surface(contacts.ground),
        surface(contacts.ceiling),
        surface(contacts.left),
        surface(contacts.right),
        surface(contacts.crush),
    ]
}

/// Moves a box with half extents `half` from `start` by `motion` once through `m`; returns
/// where it ends and what it touched.
fn land(m: &TileMap, half: Vec2, start: Vec2, motion: Vec2) -> (Vec2, Contacts) {
    let hero = CharacterShape::rect(half).unwrap();
    let mut ch = Character::new(hero, start, UP, ControllerConfig::default()).unwrap();
    let contacts = ch.move_by(m, motion, MoveOptions::default()).unwrap();
    (ch.position, contacts)
}

/// Whether the box's sweep (as the controller makes it: the motion lengthened by the skin)
/// meets both of the corner's faces at exactly the same `t`.
fn tied(corner: &[(Segment, Vec2); 2], half: Vec2, start: Vec2, motion: Vec2) -> bool {
    let length = motion.length();
    let reach = motion / length * (length + SKIN);
    let [t0, t1] = corner.map(|(segment, normal)| {
        sweep_box_segment(start, half, reach, &segment, normal, EndCaps::BOTH).map(|hit| hit.t)
    });
    t0.is_some() && t0 == t1
}

#[test]
fn a_box_landing_exactly_in_a_corner_ends_alike_whichever_face_is_submitted_first() {
    // The box's right side is 0.5 from the wall and its bottom 1 above the floor; the move
    // (1.5, 3) meets both at the same t. Found first, the wall once took the skin along
    // the move and the box slid down to the floor a skin from each, while the floor first
    // left it half a skin from the wall: segment order decided where it stood.
    let half = v(0.25, 0.5);
    let start = v(2.0, 2.0);
    let motion = v(1.5, 3.0);
    let faces = corner(2.75, 3.5);
    assert!(
        tied(&faces, half, start, motion),
        "not a corner reached exactly"
    );
    let floor_first = land(&with(&faces), half, start, motion);
    let wall_first = land(&with(&[faces[1], faces[0]]), half, start, motion);
    assert_eq!(floor_first.0, wall_first.0);
    assert_eq!(surfaces(&floor_first.1), surfaces(&wall_first.1));
    // It stands on the floor and is stopped by the wall, never inside either.
    let (end, contacts) = floor_first;
    assert_eq!(surface(contacts.ground), Some((UP, SegmentFlags::SOLID)));
    assert_eq!(
        surface(contacts.right),
        Some((v(-1.0, 0.0), SegmentFlags::SOLID))
    );
    assert!(end.x + half.x < 2.75 && end.y + half.y < 3.5, "{end:?}");
    assert!((end.y + half.y - (3.5 - SKIN)).abs() < 1e-5, "{end:?}");
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// Boxes of random sizes landing exactly in a corner (gaps to the wall and the floor in
    /// the ratio of the move's components, 1:4 to 4:1 by powers of two, so both faces are
    /// met at the same t; the few cases that rounding leaves untied are skipped), with the corner's two faces and two more floor and wall pieces
    /// submitted in every order: the box ends in the same place with the same contacts, on
    /// the floor and against the wall.
    #[test]
    fn a_box_landing_exactly_in_a_corner_ends_alike_in_every_segment_order(
        half_width in 6u8..40,
        half_height in 6u8..40,
        gap in 3u8..96,
        ratio in 0usize..5,
        speed in 8u8..24,
        order in Just([0usize, 1, 2, 3]).prop_shuffle(),
    ) {
        // Sizes and gaps in 64ths of a cell, speeds in 8ths, so the corner's coordinates
        // are exact.
        let half = v(f32::from(half_width), f32::from(half_height)) / 64.0;
        let (gap, speed) = (f32::from(gap) / 64.0, f32::from(speed) / 8.0);
        let start = v(4.0, 4.0);
        let (rx, ry) = [(1.0, 4.0), (1.0, 2.0), (1.0, 1.0), (2.0, 1.0), (4.0, 1.0)][ratio];
        let (wall_x, floor_y) = (start.x + half.x + gap * rx, start.y + half.y + gap * ry);
        let motion = v(rx, ry) * gap * speed;
        let faces = corner(wall_x, floor_y);
        prop_assume!(tied(&faces, half, start, motion));
        // A floor beyond the wall and a wall above the floor's far end: more of each kind,
        // out of the way.
        let extra = [
            (Segment::new(v(wall_x + 2.0, floor_y), v(15.0, floor_y)), v(0.0, -1.0)),
            (Segment::new(v(1.0, floor_y), v(1.0, 1.0)), v(1.0, 0.0)),
        ];
        let all = [faces[0], faces[1], extra[0], extra[1]];
        let first = land(&with(&all), half, start, motion);
        let shuffled = land(&with(&order.map(|i| all[i])), half, start, motion);
        prop_assert_eq!(first.0, shuffled.0);
        prop_assert_eq!(surfaces(&first.1), surfaces(&shuffled.1));
        prop_assert!(first.1.is_grounded() && first.1.right.is_some(), "{:?}", first.1);
        prop_assert!(first.0.x + half.x < wall_x && first.0.y + half.y < floor_y);
    }
}
