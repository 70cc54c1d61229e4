//! The controller beside ledges (ASCII maps, y down: `up` is −y): stepping up never climbs
//! more than `step_height`, for boxes and circles, and a move through the air, a walk off a
//! ledge and a walk across a gap end in the same place whatever the frame rate.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use tileslide::io::ascii;
use tileslide::{
    Character, CharacterShape, ControllerConfig, MoveOptions, Owner, Segment, SegmentFlags,
    TemporarySegment, TileMap, Vec2,
};

const UP: Vec2 = Vec2::NEG_Y;
const SKIN: f32 = 1e-3;
/// The default snap distance: a walk steps down a ledge no higher than this.
const SNAP: f32 = 0.3;

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

/// A room whose floor is at y = 5.
const FLOOR: &str = "\
##############################
#............................#
#............................#
#............................#
#............................#
##############################";

/// The floor with a ledge `height` high whose face is at x = 10 (two temporary segments:
/// the face, facing left, and the top, facing up, meeting at the ledge's corner).
fn ledge(height: f32) -> TileMap {
    let mut m = ascii::parse(FLOOR, "floor.txt", 1.0).unwrap();
    let top = 5.0 - height;
    for (a, b, normal) in [
        (v(10.0, 5.0), v(10.0, top), v(-1.0, 0.0)),
        (v(10.0, top), v(25.0, top), v(0.0, -1.0)),
    ] {
        m.add_temporary(TemporarySegment {
            segment: Segment::new(a, b),
            normal,
            flags: SegmentFlags::SOLID,
            owner: Owner(1),
            velocity: Vec2::ZERO,
        })
        .unwrap();
    }
    m
}

/// Stands `shape` on the floor left of the ledge and walks it right by `speed` a step for
/// 6 cells; returns whether it got onto the ledge (its centre past the face, on the ledge's
/// top).
fn climbs(shape: CharacterShape, config: ControllerConfig, height: f32, speed: f32) -> bool {
    let m = ledge(height);
    // Dropped from 0.1 above the floor: a box more than a cell tall once started at y = 4,
    // sunk into the floor, and measured from there a ledge lower than the step height was
    // too high to step onto.
    let start = v(7.0, 5.0 - half_height(shape) - 0.1);
    let mut ch = Character::new(shape, start, UP, config).unwrap();
    ch.move_by(&m, v(0.0, 1.0), MoveOptions::default()).unwrap();
    assert!(
        ch.ground().is_some(),
        "{shape:?} does not stand at {start:?}"
    );
    for _ in 0..(6.0 / speed).ceil() as usize {
        ch.move_by(&m, v(speed, 0.02), MoveOptions::default())
            .unwrap();
    }
    ch.position.x > 10.0 && ch.position.y < 5.0 - height
}

fn stepping(step_height: f32) -> ControllerConfig {
    ControllerConfig {
        step_height,
        ..ControllerConfig::default()
    }
}

#[test]
fn a_circle_does_not_step_up_a_one_cell_wall_with_a_step_height_of_0_86() {
    // The step-up once accepted the wall's rounded corner as ground when its normal was
    // walkable: 0.86 + 0.4·(1 − cos 50°) = 1.003 cells climbed.
    let ball = CharacterShape::circle(0.4).unwrap();
    for speed in [0.05, 0.1, 0.2, 0.4] {
        assert!(!climbs(ball, stepping(0.86), 1.0, speed), "speed {speed}");
        assert!(!climbs(ball, stepping(0.86), 0.87, speed), "speed {speed}");
    }
    // With no step height a circle does not roll up a ledge either (it once rolled up
    // 0.4·(1 − cos 50°) = 0.143).
    assert!(!climbs(ball, stepping(0.0), 0.1, 0.2));
    let hero = CharacterShape::rect(v(0.25, 0.4)).unwrap();
    assert!(!climbs(hero, stepping(0.86), 0.87, 0.2));
    assert!(climbs(hero, stepping(0.86), 0.85, 0.2));
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    /// Over random shapes, slope limits, step heights, ledge heights and walking speeds: a
    /// ledge higher than the step height is never climbed (give or take the skin: a
    /// character may stand closer to the ground than the skin, and the climb is measured
    /// from where it stands), and a box climbs every ledge lower than it.
    #[test]
    fn stepping_up_never_climbs_more_than_the_step_height(
        circle in any::<bool>(),
        size in 0.1f32..0.6,
        aspect in 0.5f32..2.0,
        max_slope_degrees in 10.0f32..80.0,
        step_height in 0.0f32..1.2,
        height in 0.01f32..1.6,
        speed in 0.02f32..0.5,
    ) {
        let shape = if circle {
            CharacterShape::circle(size).unwrap()
        } else {
            CharacterShape::rect(v(size, size * aspect)).unwrap()
        };
        let config = ControllerConfig { max_slope_degrees, step_height, ..ControllerConfig::default() };
        let climbed = climbs(shape, config, height, speed);
        prop_assert!(!climbed || height <= step_height + SKIN,
            "{:?} climbed a ledge {} high with a step height of {}", shape, height, step_height);
        if !circle && height < step_height - 2.0 * SKIN {
            prop_assert!(climbed, "the box stopped at a ledge {} high with a step height of {}", height, step_height);
        }
    }
}

/// A room with a block two cells high (top at y = 3, left face at x = 10) on a floor at
/// y = 5.
const BLOCK: &str = "\
##############################
#............................#
#............................#
#.........######.............#
#.........######.............#
##############################";

/// Moves `shape` from `start` at the constant velocity `velocity` (cells per second) for
/// 0.2 s at `rate` steps per second; returns where it ends.
fn fly(m: &TileMap, shape: CharacterShape, start: Vec2, velocity: Vec2, rate: f32) -> Vec2 {
    let mut ch = Character::new(shape, start, UP, ControllerConfig::default()).unwrap();
    for _ in 0..(0.2 * rate).round() as usize {
        ch.move_by(m, velocity / rate, MoveOptions::default())
            .unwrap();
    }
    ch.position
}

const RATES: [f32; 4] = [30.0, 60.0, 120.0, 240.0];

#[test]
fn a_box_falling_past_a_ledge_corner_slides_down_its_face_at_30_hz_too() {
    // One 30 Hz step of (0.2, 0.5): the box's path meets the block's face (its right side
    // reaches x = 10 when its bottom is 0.1 below the top), so it slides down to the floor.
    // Split into a sideways then a vertical sweep it once landed on the top, 0.08 onto it.
    let m = ascii::parse(BLOCK, "block.txt", 1.0).unwrap();
    let hero = CharacterShape::rect(v(0.25, 0.4)).unwrap();
    let start = v(10.0 - 0.12 - 0.25, 3.0 - 0.2 - 0.4);
    for rate in RATES {
        let end = fly(&m, hero, start, v(6.0, 15.0), rate);
        let floor = v(10.0 - 0.25 - SKIN, 5.0 - 0.4 - SKIN);
        assert!(
            (end - floor).abs().max_element() < 1e-4,
            "{rate} Hz: {end:?}"
        );
    }
}

#[test]
fn a_box_falling_onto_a_ledge_edge_beside_it_slides_onto_the_top_at_30_60_120_and_240_hz() {
    // The box's path passes 3e-4 above the block's corner: its fall meets the top's end
    // when its side is still 7e-4 short of being over it. It once took that for a landing,
    // found no ground under the walk's start, flew the step again into the same end, and
    // hung there in the air for the rest of the run at every rate (240 Hz 1.2e-3 nearer the
    // block than 30 Hz). It slides onto the top and walks on along it.
    let m = ascii::parse(BLOCK, "block.txt", 1.0).unwrap();
    let hero = CharacterShape::rect(v(0.1, 0.1)).unwrap();
    let (start, velocity) = (v(9.6506815, 2.8328457), v(11.934995, 3.190716));
    let ends = RATES.map(|rate| fly(&m, hero, start, velocity, rate));
    // Flown 0.25 to the corner, then walked along the top for the rest of the 0.2 s.
    let top = v(start.x + 0.2 * velocity.x, 3.0 - 0.1 - SKIN);
    for (rate, end) in RATES.iter().zip(ends) {
        assert!(
            (end - top).abs().max_element() <= TOLERANCE,
            "{rate} Hz ends at {end:?}, not on the top at {top:?}"
        );
    }
}

#[test]
fn a_circle_pressed_round_a_corner_onto_the_face_below_it_slides_down_the_face() {
    // Circles about 0.5 in radius, their centres up to 0.15 above the block's corner
    // (10, 3), moving fast into the block and slowly down: each rolls down round the corner
    // until level with it, then slides down the face a skin from it at every rate.
    // - The first once rolled on round the corner's cap below the corner, where the face is
    //   the surface: the sideways push rolled it further down, by a different amount at
    //   each rate (30 Hz 0.003 lower).
    // - The second, at 30 Hz, met the face's cap a hair below the corner (rounding), a
    //   normal already past the face's, and rolled round it too: 0.005 lower than 60 Hz.
    let m = ascii::parse(BLOCK, "block.txt", 1.0).unwrap();
    for (radius, gap, above, velocity) in [
        (0.539_826_6, 0.01, 0.393_769_8, v(10.161_679, 1.0)),
        (
            0.503_309_7,
            0.329_611_33,
            0.354_422_36,
            v(10.793_678, 1.455_210_1),
        ),
    ] {
        let ball = CharacterShape::circle(radius).unwrap();
        let start = v(10.0 - gap - radius, 3.0 + above - radius);
        let ends = RATES.map(|rate| fly(&m, ball, start, velocity, rate));
        for (rate, end) in RATES.iter().zip(ends) {
            assert!(end.y > 3.0, "radius {radius}, {rate} Hz: {end:?}");
            assert!(
                (end.x - (10.0 - radius - SKIN)).abs() < 1e-4,
                "radius {radius}, {rate} Hz: {end:?}, not a skin from the face"
            );
            assert!(
                (end - ends[0]).abs().max_element() <= TOLERANCE,
                "radius {radius}, {rate} Hz: {end:?} vs {:?}",
                ends[0]
            );
        }
    }
}

/// Moves `shape` (half extents `half`) from `gap` left of the block's face and `above` its
/// top (its right side and its bottom) at `velocity` for 0.2 s at each of [`RATES`]; an
/// error unless every end is within [`TOLERANCE`] of the 30 Hz one.
fn ends_alike(
    shape: CharacterShape,
    half: Vec2,
    gap: f32,
    above: f32,
    velocity: Vec2,
) -> Result<(), TestCaseError> {
    let m = ascii::parse(BLOCK, "block.txt", 1.0).unwrap();
    let start = v(10.0 - gap - half.x, 3.0 - above - half.y);
    let ends = RATES.map(|rate| fly(&m, shape, start, velocity, rate));
    for (rate, end) in RATES.iter().zip(ends) {
        prop_assert!(
            (end - ends[0]).abs().max_element() <= TOLERANCE,
            "{:?} from {:?} at {:?}: {} Hz ends at {:?}, 30 Hz at {:?}",
            shape,
            start,
            velocity,
            rate,
            end,
            ends[0]
        );
    }
    Ok(())
}

/// How far apart the end positions at different rates may be (in cells): the skin. Every
/// stop keeps a skin from the surface along its normal, except a stop on a move that only
/// grazes a surface, which may end closer (down to the skin times the cosine of the angle
/// of approach); which step of a run grazes depends on the rate.
const TOLERANCE: f32 = SKIN;

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// From random places beside the block, at random velocities down and right, the same
    /// 0.2 s of motion at 30, 60, 120 and 240 steps a second ends in the same place: on the
    /// block's top, against its face, or on the floor. A circle meeting the block's corner
    /// rolls around it exactly, whatever the rate.
    #[test]
    fn a_circle_moving_past_a_ledge_ends_in_the_same_place_at_30_60_120_and_240_hz(
        radius in 0.1f32..0.6,
        gap in 0.01f32..1.0,
        above in -0.6f32..0.8,
        vx in 0.5f32..12.0,
        vy in 1.0f32..25.0,
    ) {
        let ball = CharacterShape::circle(radius).unwrap();
        ends_alike(ball, Vec2::splat(radius), gap, above, v(vx, vy))?;
    }

    /// The same for a box.
    #[test]
    fn a_box_moving_past_a_ledge_ends_in_the_same_place_at_30_60_120_and_240_hz(
        half_width in 0.1f32..0.6,
        half_height in 0.1f32..0.6,
        gap in 0.01f32..1.0,
        above in -0.6f32..0.8,
        vx in 0.5f32..12.0,
        vy in 1.0f32..25.0,
    ) {
        let half = v(half_width, half_height);
        let hero = CharacterShape::rect(half).unwrap();
        ends_alike(hero, half, gap, above, v(vx, vy))?;
    }
}

/// A room with a ledge two cells high (top at y = 3, its edge at x = 9) above a floor at
/// y = 5.
const EDGE: &str = "\
##############################
#............................#
#............................#
#########....................#
#########....................#
##############################";

/// Half the height of `shape`: how far its centre stands above the ground.
fn half_height(shape: CharacterShape) -> f32 {
    match shape {
        CharacterShape::Circle { radius } => radius,
        CharacterShape::Rect { half } => half.y,
        // Any other shape: the top of its bounding box.
        other => other.bounds(Vec2::ZERO).max.y,
    }
}

/// Stands `shape` on `m` with its centre at `x`, half its height and a skin above
/// `ground`, then moves it by `velocity` (cells per second; a walk while on the ground) for
/// `time` seconds at `rate` steps per second; returns where it ends.
fn walk(
    m: &TileMap,
    shape: CharacterShape,
    x: f32,
    ground: f32,
    velocity: Vec2,
    time: f32,
    rate: f32,
) -> Vec2 {
    let start = v(x, ground - half_height(shape) - SKIN);
    let mut ch = Character::new(shape, start, UP, ControllerConfig::default()).unwrap();
    ch.move_by(m, v(0.0, 0.01), MoveOptions::default()).unwrap();
    assert!(ch.ground().is_some(), "not standing at {start:?}");
    for _ in 0..(time * rate).round() as usize {
        ch.move_by(m, velocity / rate, MoveOptions::default())
            .unwrap();
    }
    ch.position
}

#[test]
fn a_box_walking_off_a_ledge_starts_to_fall_at_its_edge_at_30_60_120_and_240_hz() {
    // Walking at 5 cells/s from x = 6 with a fall speed of 4 cells/s, the box's left side
    // passes the edge (its centre at 9.25) after 0.65 s: 0.35 s later it has fallen 1.4.
    // It once walked a whole step past the edge before it fell: 30 Hz ended 0.067 higher.
    let m = ascii::parse(EDGE, "edge.txt", 1.0).unwrap();
    let half = v(0.25, 0.4);
    for rate in RATES {
        let hero = CharacterShape::rect(half).unwrap();
        let end = walk(&m, hero, 6.0, 3.0, v(5.0, 4.0), 1.0, rate);
        let ideal = v(11.0, 3.0 - half.y - SKIN + 1.4);
        assert!(
            (end - ideal).abs().max_element() < 1e-4,
            "{rate} Hz: {end:?}"
        );
    }
}

/// How far apart rounding may put a walk's x after the same time at different rates: each
/// step's sum rounds by up to half a unit in the last place of an x below 16 (2⁻²¹), and
/// 240 Hz makes up to 192 steps in 0.8 s.
const DRIFT: f32 = 192.0 / 2_097_152.0;

/// An error unless the ends of a walk at every rate of [`RATES`] are within `tolerance` of
/// the 30 Hz one; `what` describes the walk.
fn walks_alike(ends: [Vec2; 4], tolerance: f32, what: &str) -> Result<(), TestCaseError> {
    for (rate, end) in RATES.iter().zip(ends) {
        prop_assert!(
            (end - ends[0]).abs().max_element() <= tolerance,
            "{}: {} Hz ends at {:?}, 30 Hz at {:?}",
            what,
            rate,
            end,
            ends[0]
        );
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// Boxes of random sizes walking left off a ledge of random height (stepping down one
    /// lower than the snap distance, falling off a higher one) from random places on it,
    /// at random walking and fall speeds, for a random time (0.1 to 0.8 s): the ends at 30, 60, 120 and
    /// 240 steps a second agree within [`TOLERANCE`], plus the rounding of the walk's x
    /// ([`DRIFT`]) and how much that moves the fall. The walk ends where the ground does
    /// and the step's rest is flown from there, so the fall starts at the edge whatever
    /// the rate.
    #[test]
    fn a_box_walking_off_a_ledge_ends_in_the_same_place_at_30_60_120_and_240_hz(
        half_width in 0.1f32..0.6,
        half_height in 0.1f32..0.6,
        height in 0.01f32..1.6,
        gap in 0.0f32..2.0,
        vx in 0.5f32..12.0,
        vy in 1.0f32..25.0,
        steps in 3u8..24,
    ) {
        // A whole number of 30 Hz steps, so every rate runs for the same time.
        let time = f32::from(steps) / 30.0;
        let m = ledge(height);
        let half = v(half_width, half_height);
        let hero = CharacterShape::rect(half).unwrap();
        let x = 10.0 + half.x + gap;
        let ends = RATES.map(|rate| walk(&m, hero, x, 5.0 - height, v(-vx, vy), time, rate));
        // Rounding moves the walk's x by up to DRIFT, and so when it reaches the edge by
        // DRIFT / vx seconds: the fall then differs by DRIFT · vy / vx. A step down (a
        // ledge lower than the snap distance) is no fall but a drop of the ledge's height
        // where the box's side passes the face: a walk that ends within DRIFT of there
        // ends above or below it, by rounding.
        let passes = 10.0 - half.x;
        let straddles = height <= SNAP && (x - vx * time - passes).abs() <= DRIFT;
        let step = if straddles { height } else { 0.0 };
        let tolerance = TOLERANCE + DRIFT * (1.0 + vy / vx) + step;
        let what = format!("{half:?} from x = {x} off a ledge {height} high at {:?} for {time} s", v(-vx, vy));
        walks_alike(ends, tolerance, &what)?;
    }
}

#[test]
fn a_circle_walking_off_a_ledge_falls_from_where_the_corner_turns_steeper_than_50_degrees() {
    // A circle of radius 0.3 walking at 5 cells/s from x = 6 rolls over the edge's corner
    // (9, 3) until its contact normal there is 50° (the slope limit) from up: its centre
    // 0.3 · sin 50° right of the corner, a skin further than its radius from it. It flies
    // the rest of the 1 s at (5, 4) from there. It once fell from where a step's straight
    // leg left the corner, above the arc: 30 Hz ended 0.014 higher.
    let m = ascii::parse(EDGE, "edge.txt", 1.0).unwrap();
    let radius = 0.3f32;
    let ball = CharacterShape::circle(radius).unwrap();
    let across = radius * 50f32.to_radians().sin();
    let leave = v(
        9.0 + across,
        3.0 - ((radius + SKIN).powi(2) - across * across).sqrt(),
    );
    let ideal = leave + v(5.0, 4.0) * (1.0 - (leave.x - 6.0) / 5.0);
    for rate in RATES {
        let end = walk(&m, ball, 6.0, 3.0, v(5.0, 4.0), 1.0, rate);
        assert!(
            (end - ideal).abs().max_element() < 1e-4,
            "{rate} Hz: {end:?}, not {ideal:?}"
        );
    }
}

/// How much higher a circle of `radius` wedged between the two corners of a gap `width`
/// wide rests when it is a skin from both than when it touches them: 0 when it does not
/// wedge. Its distance from each corner is between its radius and that plus a skin (a stop
/// on a move that grazes a surface may end closer than a skin), and its height over the
/// corners is `√(d² − (width/2)²)` at distance `d`, steep in `d` near `width/2`: in the
/// case the property test below found, 3.6e-4 closer to a corner than a skin put the
/// circle 2.5e-3 lower.
fn wedge(radius: f32, width: f32) -> f32 {
    let half = 0.5 * width;
    let far = radius + SKIN;
    if half >= far {
        return 0.0;
    }
    (far * far - half * half).sqrt() - (radius * radius - half * half).max(0.0).sqrt()
}

/// [`ledge`] with a gap `width` wide left of it: a platform as high as the ledge, its
/// right face at x = 10 − `width`.
fn gap(height: f32, width: f32) -> TileMap {
    let mut m = ledge(height);
    let top = 5.0 - height;
    let edge = 10.0 - width;
    for (a, b, normal) in [
        (v(edge, top), v(edge, 5.0), v(1.0, 0.0)),
        (v(2.0, top), v(edge, top), v(0.0, -1.0)),
    ] {
        m.add_temporary(TemporarySegment {
            segment: Segment::new(a, b),
            normal,
            flags: SegmentFlags::SOLID,
            owner: Owner(2),
            velocity: Vec2::ZERO,
        })
        .unwrap();
    }
    m
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// The same as for boxes, for circles: a circle walking left off a ledge rolls over its
    /// rounded corner until the contact normal there is steeper than the slope limit, and
    /// falls from there whatever the rate.
    #[test]
    fn a_circle_walking_off_a_ledge_ends_in_the_same_place_at_30_60_120_and_240_hz(
        radius in 0.1f32..0.6,
        height in 0.01f32..1.6,
        gap in 0.0f32..2.0,
        vx in 0.5f32..12.0,
        vy in 1.0f32..25.0,
        steps in 3u8..24,
    ) {
        let time = f32::from(steps) / 30.0;
        let m = ledge(height);
        let ball = CharacterShape::circle(radius).unwrap();
        let x = 10.0 + radius + gap;
        let ends = RATES.map(|rate| walk(&m, ball, x, 5.0 - height, v(-vx, vy), time, rate));
        let tolerance = TOLERANCE + DRIFT * (1.0 + vy / vx);
        let what = format!("radius {radius} from x = {x} off a ledge {height} high at {:?} for {time} s", v(-vx, vy));
        walks_alike(ends, tolerance, &what)?;
    }

    /// Boxes and circles walking left across a gap of random width in a ledge deeper than
    /// the snap distance (0.3): a walker fast enough to cross the gap in one step falls
    /// into it where a slower step would, so the ends at every rate agree within
    /// [`TOLERANCE`] and the rounding of the walk ([`DRIFT`]), plus, for a circle that can
    /// end wedged between the gap's two corners, how much higher that leaves it at a skin
    /// from them than touching them ([`wedge`]).
    #[test]
    fn a_walker_crossing_a_gap_ends_in_the_same_place_at_30_60_120_and_240_hz(
        circle in any::<bool>(),
        size in 0.1f32..0.6,
        height in 0.31f32..1.6,
        width in 0.0f32..1.5,
        vx in 0.5f32..12.0,
        vy in 1.0f32..25.0,
        steps in 3u8..24,
    ) {
        let time = f32::from(steps) / 30.0;
        let m = gap(height, width);
        let shape = if circle {
            CharacterShape::circle(size).unwrap()
        } else {
            CharacterShape::rect(Vec2::splat(size)).unwrap()
        };
        let x = 10.0 + size + 0.05;
        let ends = RATES.map(|rate| walk(&m, shape, x, 5.0 - height, v(-vx, vy), time, rate));
        let wedged = if circle { wedge(size, width) } else { 0.0 };
        let tolerance = TOLERANCE + wedged + DRIFT * (1.0 + vy / vx);
        let what = format!("{shape:?} across a gap {width} wide in a ledge {height} high at {:?} for {time} s", v(-vx, vy));
        walks_alike(ends, tolerance, &what)?;
    }
}

#[test]
fn a_circle_stepping_down_a_low_ledge_lands_where_the_floor_is_at_30_60_120_and_240_hz() {
    // A circle of radius 0.373 walking left off a ledge 0.136 high (lower than the snap
    // distance) rolls over its corner until the normal there is steeper than the slope
    // limit, then, too far above the floor to stand on it, rolls on round the corner down
    // onto it. A longer step walking the corner's tangent once passed over where the
    // circle stands on neither (between there and where the floor comes within two skins
    // below the corner) and stepped straight down to the floor: 30 Hz ended 0.0018 right of
    // 240 Hz, whose step ended in that stretch.
    let (radius, height, gap) = (0.373388, 0.13605924, 0.5346017);
    let (vx, vy, time) = (3.925913, 19.360802, 10.0 / 30.0);
    let m = ledge(height);
    let ball = CharacterShape::circle(radius).unwrap();
    let x = 10.0 + radius + gap;
    let ends = RATES.map(|rate| walk(&m, ball, x, 5.0 - height, v(-vx, vy), time, rate));
    for (rate, end) in RATES.iter().zip(ends) {
        assert!(
            (end - ends[0]).abs().max_element() <= TOLERANCE,
            "{rate} Hz ends at {end:?}, 30 Hz at {:?}",
            ends[0]
        );
    }
}
