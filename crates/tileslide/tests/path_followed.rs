//! Proves that bodies can follow the paths and flow fields of `tileslide::path`: on random
//! maps with ramps and one-way platforms, a circle body moved by the resolver (`Bodies`,
//! default settings) along every run of a found path, or along a flow field's directions,
//! arrives at the goal without being stopped. One-way platforms are directed edges of the
//! navigation graph: a path crosses one only from behind, moving the way its normal points.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use crate::generators;
use crate::path_support;

use generators::{rows, tile_chars, wall_in};
use proptest::prelude::*;
use tileslide::io::ascii;
use tileslide::{
    Bodies, BodyDesc, BodyShape, Circle, FlowField, NavConfig, NavGrid, SegmentFlags, TileMap, Vec2,
};

use path_support::query_points::fitting_point;
use tileslide_scenes::SplitMix64;

/// How far a body is moved per step along a run (cells).
const STEP: f32 = 0.1;

/// How near the goal a body must end (cells): the resolver keeps bodies up to its gap
/// (10⁻³ cell) from what they touch, and a run passing a wall at just over the radius makes
/// the body slide round it by that much.
const ARRIVED: f32 = 0.01;

const RADII: [f32; 4] = [0.2, 0.3, 0.45, 0.7];

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

/// A random `width × height` map of mostly empty cells, some solid squares, ramps and
/// one-way platforms, walled in but for a quarter of the maps.
fn random_map(width: u32, height: u32) -> impl Strategy<Value = String> {
    (
        tile_chars(
            &[(12, '.'), (4, '#'), (1, '/'), (1, '\\'), (4, '=')],
            (width * height) as usize,
        ),
        prop::bool::weighted(0.25),
    )
        .prop_map(move |(mut chars, open)| {
            if !open {
                wall_in(width, &mut chars);
            }
            rows(width, &chars)
        })
}

/// Moves a body of radius `r` from the first point of `points` along each straight run in
/// turn, at most [`STEP`] a step, aiming at the run's end every step; returns where it
/// ends and the steps it took, or the step at which it made no progress for 20 steps.
fn follow(map: &TileMap, points: &[Vec2], r: f32) -> Result<Vec2, String> {
    let mut bodies = Bodies::new();
    let body = bodies
        .add(BodyDesc::new(points[0], BodyShape::circle(r).unwrap()))
        .unwrap();
    let length: f32 = points.windows(2).map(|w| w[0].distance(w[1])).sum();
    let budget = (length / STEP * 1.25) as usize + 4 * points.len() + 20;
    let mut steps = 0;
    for (k, &corner) in points.iter().enumerate().skip(1) {
        loop {
            let at = bodies.get(body).unwrap().position();
            let left = corner - at;
            if left.length() <= ARRIVED * 0.1 {
                break;
            }
            if steps == budget {
                return Err(format!(
                    "stopped at {at} on the run to corner {k} ({corner}) after {steps} steps"
                ));
            }
            let motion = left.clamp_length_max(STEP);
            bodies.propose(body, motion).unwrap();
            bodies.step(map);
            steps += 1;
            let moved = bodies.get(body).unwrap().position() - at;
            // The last step of a run ends on its corner; a body that slid round a wall by
            // rounding ends within the resolver's gap of it: go on to the next run.
            if motion == left && moved.distance(motion) <= ARRIVED {
                break;
            }
        }
    }
    Ok(bodies.get(body).unwrap().position())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 32, ..ProptestConfig::default() })]

    /// On random maps with ramps and one-way platforms, a body of the path's radius moved
    /// by the resolver along every run of every path found between random points where it
    /// fits reaches the goal (within 0.01 cell) in little more steps than the path's length
    /// needs: no run leads it into a one-way platform's front face or any other wall.
    #[test]
    fn a_body_moved_by_the_resolver_along_a_found_path_arrives_at_the_goal(
        text in random_map(12, 10),
        seed in any::<u64>(),
    ) {
        let map = ascii::parse(&text, "random.txt", 1.0).unwrap();
        let nav = NavGrid::new(&map, NavConfig::default()).unwrap();
        let mut rng = SplitMix64::new(seed);
        for k in 0..8 {
            let r = RADII[k % RADII.len()];
            let (Some(from), Some(to)) = (
                fitting_point(&nav, &map, &mut rng, r),
                fitting_point(&nav, &map, &mut rng, r),
            ) else {
                continue;
            };
            let Some(path) = nav.find_path(&map, from, to, r).unwrap() else {
                continue;
            };
            let end = follow(&map, path.points(), r);
            let end = end.map_err(|e| {
                TestCaseError::fail(format!("r {r}: {e}\npath {:?}\n{text}", path.points()))
            })?;
            prop_assert!(
                end.distance(to) <= ARRIVED,
                "r {}: the body ended at {}, {} from the goal {}\npath {:?}\n{}",
                r, end, end.distance(to), to, path.points(), text
            );
        }
    }
}

/// Moves a body of radius `r` from `start` by the directions of `field`, at most [`STEP`]
/// a step and never past the goal; returns where it ends, or where it was when the steps
/// the field's distance needs (and a quarter more) ran out.
fn follow_field(
    nav: &NavGrid,
    map: &TileMap,
    field: &FlowField,
    start: Vec2,
    distance: f32,
) -> Result<Vec2, String> {
    let mut bodies = Bodies::new();
    let body = bodies
        .add(BodyDesc::new(
            start,
            BodyShape::circle(field.radius()).unwrap(),
        ))
        .unwrap();
    let budget = (distance / STEP * 1.25) as usize + 20;
    for steps in 0..budget {
        let at = bodies.get(body).unwrap().position();
        let left = at.distance(field.goal());
        if left <= ARRIVED * 0.1 {
            return Ok(at);
        }
        let Some(dir) = field.direction(nav, map, at).unwrap() else {
            return Err(format!("no direction at {at} after {steps} steps"));
        };
        bodies.propose(body, dir * STEP.min(left)).unwrap();
        bodies.step(map);
    }
    let at = bodies.get(body).unwrap().position();
    Err(format!("still at {at} after {budget} steps"))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 16, ..ProptestConfig::default() })]

    /// On random maps with ramps and one-way platforms, a body moved by the resolver along
    /// a flow field's directions from random points the field reaches arrives at the goal
    /// (within 0.01 cell) in little more steps than the field's distance needs: the field
    /// leads agents through one-way platforms only the way the platforms let them. Goals
    /// are out of reach of one-way platforms (see below).
    #[test]
    fn a_body_moved_by_the_resolver_along_a_flow_field_arrives_at_the_goal(
        text in random_map(12, 10),
        seed in any::<u64>(),
    ) {
        let map = ascii::parse(&text, "random.txt", 1.0).unwrap();
        let nav = NavGrid::new(&map, NavConfig::default()).unwrap();
        let mut rng = SplitMix64::new(seed);
        for k in 0..2 {
            let r = RADII[(k + seed as usize) % RADII.len()];
            let Some(goal) = fitting_point(&nav, &map, &mut rng, r) else {
                continue;
            };
            // A goal within a body's reach of a one-way platform, in front of it, is
            // reached only by crossing the platform on a line that ends there; an agent
            // that overshoots the node it aims at ends past that line and must go round
            // again (a found path's runs lead there exactly: see the test above).
            let reach = Circle::new(goal, r + 0.01);
            if map
                .segments_overlapping_circle(&reach)
                .iter()
                .any(|s| s.flags.contains(SegmentFlags::ONE_WAY))
            {
                continue;
            }
            let field = FlowField::new(&nav, &map, goal, r).unwrap();
            for _ in 0..4 {
                let Some(start) = fitting_point(&nav, &map, &mut rng, r) else {
                    continue;
                };
                let Some(distance) = field.distance(&nav, &map, start).unwrap() else {
                    continue;
                };
                let end = follow_field(&nav, &map, &field, start, distance).map_err(|e| {
                    TestCaseError::fail(format!(
                        "r {r}: from {start} to {goal} (distance {distance}): {e}\n{text}"
                    ))
                })?;
                prop_assert!(end.distance(goal) <= ARRIVED, "{} {}", end, goal);
            }
        }
    }
}

/// A floor of one-way platforms (normal up, y down) with a gap at its right end.
const LEDGE: &str = "\
#########
#.......#
#.......#
#===.####
#.......#
#.......#
#########";

/// Up through the platforms is the straight way; down, the way goes round through the gap,
/// for paths and for flow fields alike.
#[test]
fn paths_and_flow_fields_cross_a_one_way_platform_only_from_behind() {
    let map = ascii::parse(LEDGE, "ledge.txt", 1.0).unwrap();
    let nav = NavGrid::new(&map, NavConfig::default()).unwrap();
    let (below, above, r) = (v(2.5, 4.5), v(2.5, 1.5), 0.3);
    let up = nav.find_path(&map, below, above, r).unwrap().unwrap();
    assert_eq!(
        up.points(),
        &[below, above],
        "straight up through the platform"
    );
    let down = nav.find_path(&map, above, below, r).unwrap().unwrap();
    assert!(
        down.length() > 4.0 && down.points().iter().any(|p| p.x > 4.0),
        "round through the gap: {:?}",
        down.points()
    );
    let to_above = FlowField::new(&nav, &map, above, r).unwrap();
    let to_below = FlowField::new(&nav, &map, below, r).unwrap();
    let d_up = to_above.distance(&nav, &map, below).unwrap().unwrap();
    let d_down = to_below.distance(&nav, &map, above).unwrap().unwrap();
    assert!((d_up - 3.0).abs() < 0.01, "{d_up}");
    assert!(d_down > 4.0, "{d_down}");
    let dir = to_below.direction(&nav, &map, above).unwrap().unwrap();
    assert!(
        dir.x > 0.5,
        "towards the gap, not down onto the platform: {dir}"
    );
    for (points, to) in [(up.points(), above), (down.points(), below)] {
        let end = follow(&map, points, r).unwrap();
        assert!(end.distance(to) <= ARRIVED, "{end}");
    }
}

/// A case the flow-field property test found: solid cells either side of a gap two cells
/// wide (x from 8 to 10) in row 6, and below it the one-way platform from (8, 7) to (9, 7)
/// (normal up), a ramp to its left and open cells to its right.
const PLATFORM_END: &str = "\
############
#..........#
#........=.#
#.........=#
###...#=..##
#..##.=....#
#..=/=\\#.=##
##.=#../=..#
#.=#...=/=.#
############";

/// A body of radius 0.7 just below that platform, 0.2 cells left of its right end, goes up
/// through the platform and the gap to a goal 4.3 cells above. Only lines nearly along the
/// platform's normal pass its end there, and the only node it joins is the end itself, by
/// a line whose slant steepens as the body rises straight up; the field steers it only
/// along lines every point of which joins the point it aims at, so it gets a direction at
/// every step and arrives.
#[test]
fn a_body_following_a_flow_field_up_past_a_one_way_platforms_end_keeps_a_direction() {
    let map = ascii::parse(PLATFORM_END, "platform_end.txt", 1.0).unwrap();
    let nav = NavGrid::new(&map, NavConfig::default()).unwrap();
    let (start, goal, r) = (v(8.794352, 7.28006), v(8.782031, 2.965796), 0.7);
    let field = FlowField::new(&nav, &map, goal, r).unwrap();
    let distance = field.distance(&nav, &map, start).unwrap().unwrap();
    let end = follow_field(&nav, &map, &field, start, distance).unwrap();
    assert!(end.distance(goal) <= ARRIVED, "{end}");
}
