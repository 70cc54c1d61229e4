//! The resolver's behaviour in the situations the write-up and the issue name: sliding over
//! seams, stopping in concave corners, rounding convex ones, bodies meeting head-on,
//! obstacles, compound bodies, moves past thin walls, and handles.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use tileslide::io::ascii;
use tileslide::{
    Bodies, BodyDesc, BodyError, BodyFilter, BodyHandle, BodyShape, Circle, ResolveConfig,
    SegmentFlags, SlideMode, TileMap, Vec2,
};

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

fn map(text: &str) -> TileMap {
    ascii::parse(text, "test.txt", 1.0).unwrap()
}

fn circle(bodies: &mut Bodies, at: Vec2, r: f32) -> BodyHandle {
    bodies
        .add(BodyDesc::new(at, BodyShape::circle(r).unwrap()))
        .unwrap()
}

/// Steps `steps` times with `h` proposing `motion` every step.
fn push(bodies: &mut Bodies, map: &TileMap, h: BodyHandle, motion: Vec2, steps: usize) -> Vec2 {
    for _ in 0..steps {
        bodies.propose(h, motion).unwrap();
        bodies.step(map);
    }
    bodies.get(h).unwrap().position()
}

const HALL: &str = "\
####################
#..................#
#..................#
####################";

#[test]
fn sliding_along_a_floor_of_many_tiles_never_stops_at_a_seam() {
    let m = map(HALL);
    let mut bodies = Bodies::new();
    // Pressed into the floor (y down: +y) while moving right, over 16 tile seams.
    let h = circle(&mut bodies, v(1.5, 2.5), 0.4);
    let end = push(&mut bodies, &m, h, v(0.25, 0.1), 80);
    assert!(end.x > 18.5, "stopped at x = {}", end.x);
    assert!((end.y - 2.6).abs() < 2e-3, "{end}");
}

#[test]
fn a_body_pushed_into_a_concave_corner_stops_in_it() {
    let m = map(HALL);
    let mut bodies = Bodies::new();
    let h = circle(&mut bodies, v(15.5, 1.5), 0.4);
    let end = push(&mut bodies, &m, h, v(0.3, 0.2), 40);
    // The corner of the right wall (x = 19) and the floor (y = 3).
    assert!((end - v(18.6, 2.6)).length() < 2e-3, "{end}");
    // And it stays there.
    let again = push(&mut bodies, &m, h, v(0.3, 0.2), 5);
    assert_eq!(again, end);
}

#[test]
fn a_body_rounds_a_convex_corner() {
    let m = map("\
##########
#........#
#........#
#...##...#
#...##...#
#........#
##########");
    let mut bodies = Bodies::new();
    // Sliding down the left face of the block (x = 4) while pushing right: past the
    // block's bottom-left corner (4, 5) it swings round it instead of catching on it.
    let h = circle(&mut bodies, v(3.59, 3.5), 0.4);
    let mut closest = f32::INFINITY;
    for _ in 0..40 {
        bodies.propose(h, v(0.05, 0.1)).unwrap();
        bodies.step(&m);
        let p = bodies.get(h).unwrap().position();
        closest = closest.min(p.distance(v(4.0, 5.0)));
    }
    let end = bodies.get(h).unwrap().position();
    assert!(end.y > 5.2 && end.x > 4.0, "caught on the corner at {end}");
    assert!(closest >= 0.4, "cut into the corner: {closest}");
}

#[test]
fn two_bodies_meeting_head_on_turn_opposite_ways_and_pass() {
    let m = map("\
############
#..........#
#..........#
#..........#
############");
    let mut bodies = Bodies::new();
    let a = circle(&mut bodies, v(2.0, 2.5), 0.4);
    let b = circle(&mut bodies, v(10.0, 2.5), 0.4);
    for _ in 0..60 {
        bodies.propose(a, v(0.2, 0.0)).unwrap();
        bodies.propose(b, v(-0.2, 0.0)).unwrap();
        bodies.step(&m);
    }
    let (pa, pb) = (
        bodies.get(a).unwrap().position(),
        bodies.get(b).unwrap().position(),
    );
    // They swapped sides, one above and one below the line they met on.
    assert!(pa.x > pb.x, "{pa} {pb}");
    assert!((pa.y - 2.5) * (pb.y - 2.5) < 0.0, "{pa} {pb}");
}

#[test]
fn bodies_without_a_move_are_obstacles_that_others_slide_around() {
    let m = map("\
####################
#..................#
#..................#
#..................#
#..................#
####################");
    let mut bodies = Bodies::new();
    let rock = circle(&mut bodies, v(8.0, 3.0), 0.5);
    let walker = circle(&mut bodies, v(2.0, 2.9), 0.3);
    let end = push(&mut bodies, &m, walker, v(0.2, 0.0), 60);
    assert_eq!(bodies.get(rock).unwrap().position(), v(8.0, 3.0));
    assert!(end.x > 9.0, "did not get round the rock: {end}");
}

#[test]
fn compound_bodies_collide_with_every_circle() {
    let m = map(HALL);
    let mut bodies = Bodies::new();
    let cart = BodyShape::compound([
        Circle::new(v(-0.5, 0.0), 0.3),
        Circle::new(v(0.5, 0.0), 0.3),
    ])
    .unwrap();
    let h = bodies.add(BodyDesc::new(v(3.0, 2.0), cart)).unwrap();
    let end = push(&mut bodies, &m, h, v(0.5, 0.0), 60);
    // Its front wheel stops at the right wall: centre at 19 − 0.3 − 0.5.
    assert!((end.x - 18.2).abs() < 2e-3, "{end}");
}

#[test]
fn filters_choose_what_collides() {
    let m = map(HALL);
    let mut bodies = Bodies::new();
    let ghost_filter = BodyFilter {
        groups: 2,
        collides_with: 2,
        walls: SegmentFlags::NONE,
    };
    let ghost = bodies
        .add(BodyDesc::new(v(2.0, 2.0), BodyShape::circle(0.4).unwrap()).with_filter(ghost_filter))
        .unwrap();
    let _wall_of_people = circle(&mut bodies, v(5.0, 2.0), 0.9);
    // Through the body and out through the wall.
    let end = push(&mut bodies, &m, ghost, v(1.0, 0.0), 25);
    assert!(end.x > 20.0, "{end}");
}

#[test]
fn a_move_that_ends_beyond_a_thin_wall_stops_at_it() {
    let m = map("\
##########
#...#....#
##########");
    // A move that ends beyond the one-cell wall (the write-up's bisection, which checks
    // only sampled positions starting with the end, passes through: see
    // `toi_exact_vs_bisection.rs`), and one that ends inside it.
    for (motion, slide) in [(4.0, SlideMode::FullLength), (1.8, SlideMode::Stop)] {
        let mut bodies = Bodies::with_config(ResolveConfig {
            slide,
            ..ResolveConfig::default()
        })
        .unwrap();
        let h = circle(&mut bodies, v(2.0, 1.5), 0.3);
        let end = push(&mut bodies, &m, h, v(motion, 0.0), 1);
        let gap = ResolveConfig::default().gap;
        assert!(end.x <= 4.0 - 0.3 - gap / 2.0, "{end}");
        assert!(end.x >= 4.0 - 0.3 - gap - 1e-6, "{end}");
    }
}

#[test]
fn stale_handles_and_bad_numbers_are_errors() {
    let mut bodies = Bodies::new();
    let h = circle(&mut bodies, v(1.0, 1.0), 0.3);
    bodies.remove(h).unwrap();
    let reused = circle(&mut bodies, v(2.0, 2.0), 0.3);
    assert_eq!(reused.index(), h.index());
    assert_eq!(
        bodies.propose(h, v(1.0, 0.0)),
        Err(BodyError::StaleHandle(h))
    );
    assert!(matches!(bodies.get(h), Err(BodyError::StaleHandle(_))));
    assert!(matches!(bodies.remove(h), Err(BodyError::StaleHandle(_))));
    assert!(matches!(
        bodies.propose(reused, v(f32::NAN, 0.0)),
        Err(BodyError::NonFinite { what: "move", .. })
    ));
    assert!(matches!(
        bodies.add(BodyDesc::new(
            v(f32::INFINITY, 0.0),
            BodyShape::circle(1.0).unwrap()
        )),
        Err(BodyError::NonFinite {
            what: "position",
            ..
        })
    ));
    assert!(matches!(
        BodyShape::compound([Circle::new(v(0.0, f32::NAN), 1.0)]),
        Err(BodyError::InvalidOffset { index: 0, .. })
    ));
    assert_eq!(BodyShape::compound([]), Err(BodyError::EmptyShape));
    assert_eq!(bodies.len(), 1);
}

#[test]
fn positions_and_move_end_points_past_max_coord_are_refused() {
    use tileslide::limits::MAX_COORD;
    let mut bodies = Bodies::new();
    let shape = BodyShape::circle(0.3).unwrap();
    let refused = |what: &'static str, value: Vec2| Err(BodyError::OutOfRange { what, value });
    let far = v(5.0, 1e20);
    assert_eq!(
        bodies.add(BodyDesc::new(far, shape.clone())),
        refused("position", far).map(|()| unreachable!())
    );
    let edge = v(-MAX_COORD, MAX_COORD);
    let h = bodies.add(BodyDesc::new(edge, shape.clone())).unwrap();
    // A move to the opposite corner is the longest accepted.
    bodies
        .propose(h, v(2.0 * MAX_COORD, -2.0 * MAX_COORD))
        .unwrap();
    // 3e38 is finite: its end point is refused, and the move stays as it was.
    assert_eq!(
        bodies.propose(h, v(3e38, 0.0)),
        refused("move's end point", v(3e38, MAX_COORD))
    );
    assert_eq!(
        bodies.get(h).unwrap().proposed_move(),
        v(2.0 * MAX_COORD, -2.0 * MAX_COORD)
    );
    // A teleport from which the proposed move would end out of range is refused too.
    assert_eq!(
        bodies.set_position(h, v(1.0, -1.0)),
        refused(
            "move's end point",
            v(1.0 + 2.0 * MAX_COORD, -1.0 - 2.0 * MAX_COORD)
        )
    );
    assert_eq!(bodies.get(h).unwrap().position(), edge);
    let message = bodies.propose(h, v(0.0, 1e20)).unwrap_err().to_string();
    assert!(
        message.contains("out of range") && message.contains("16777216"),
        "{message}"
    );
}

#[test]
fn radii_offsets_and_settings_out_of_range_are_refused() {
    use tileslide::limits::MAX_COORD;
    assert!(BodyShape::circle(MAX_COORD).is_ok());
    for radius in [
        f32::MAX,
        MAX_COORD * 1.0001,
        f32::INFINITY,
        f32::NAN,
        0.0,
        -1.0,
    ] {
        assert!(
            matches!(
                BodyShape::circle(radius),
                Err(BodyError::InvalidRadius { index: 0, .. })
            ),
            "radius {radius}"
        );
    }
    let offset = [Circle::new(v(0.0, 0.0), 0.5), Circle::new(v(2e7, 0.0), 0.5)];
    assert!(matches!(
        BodyShape::compound(offset),
        Err(BodyError::InvalidOffset { index: 1, .. })
    ));
    let default = ResolveConfig::default();
    for gap in [
        f32::NAN,
        f32::INFINITY,
        2.4e24,
        -1e-3,
        ResolveConfig::MAX_GAP * 1.01,
    ] {
        let config = ResolveConfig { gap, ..default };
        assert!(
            matches!(
                Bodies::with_config(config),
                Err(BodyError::BadConfig { field: "gap", .. })
            ),
            "gap {gap}"
        );
    }
    for gap in [0.0, ResolveConfig::MAX_GAP] {
        Bodies::with_config(ResolveConfig { gap, ..default }).unwrap();
    }
    let mut bodies = Bodies::new();
    let slow = ResolveConfig {
        passes: ResolveConfig::MAX_PASSES + 1,
        ..default
    };
    assert!(matches!(
        bodies.set_config(slow),
        Err(BodyError::BadConfig {
            field: "passes",
            ..
        })
    ));
    assert_eq!(bodies.config(), &default);
}

#[test]
fn a_slide_that_would_end_past_max_coord_stops_at_the_contact() {
    use tileslide::{Owner, Segment, TemporarySegment, limits::MAX_COORD};
    let mut m = map(HALL);
    // A floor along the edge of the range, at y = 1 (y down: the floor faces −y).
    let floor = TemporarySegment {
        segment: Segment::new(v(MAX_COORD - 128.0, 1.0), v(MAX_COORD, 1.0)),
        normal: v(0.0, -1.0),
        flags: SegmentFlags::SOLID,
        owner: Owner(1),
        velocity: Vec2::ZERO,
    };
    m.add_temporary(floor).unwrap();
    // Coarse numbers: at 2²⁴ an f32 has no fractions left.
    let mut bodies = Bodies::new();
    let h = circle(&mut bodies, v(MAX_COORD - 40.0, -20.0), 4.0);
    // Into the floor at 45°, ending inside the range: it meets the floor 17 along, and the
    // remainder (25.5 long), turned along the floor, would end past MAX_COORD.
    let end = push(&mut bodies, &m, h, v(35.0, 35.0), 1);
    assert!(end.x <= MAX_COORD - 22.0, "{end}");
    assert!(end.y <= -3.0 && end.y > -3.5, "{end}");
    // Away from the edge, the same slide is taken.
    let mut free = Bodies::new();
    let g = circle(&mut free, v(MAX_COORD - 100.0, -20.0), 4.0);
    let slid = push(&mut free, &m, g, v(35.0, 35.0), 1);
    assert!(slid.x >= MAX_COORD - 60.0, "{slid}");
    assert!(slid.y <= -3.0 && slid.y > -3.5, "{slid}");
}

#[test]
fn a_compound_of_more_circles_than_the_limit_is_refused_before_they_are_all_collected() {
    use tileslide::limits::MAX_COMPOUND_CIRCLES;
    let circle = Circle::new(Vec2::ZERO, 0.25);
    let at_limit = BodyShape::compound(std::iter::repeat_n(circle, MAX_COMPOUND_CIRCLES));
    assert_eq!(at_limit.unwrap().circles().len(), MAX_COMPOUND_CIRCLES);
    let over = BodyShape::compound(std::iter::repeat_n(circle, MAX_COMPOUND_CIRCLES + 1));
    assert_eq!(
        over,
        Err(BodyError::TooManyCircles {
            max: MAX_COMPOUND_CIRCLES
        })
    );
    assert_eq!(
        over.unwrap_err().to_string(),
        "a body shape has more than 1024 circles"
    );
    // An endless list: refused after MAX_COMPOUND_CIRCLES + 1 are read, not collected
    // until memory runs out.
    assert!(BodyShape::compound(std::iter::repeat(circle)).is_err());
}
