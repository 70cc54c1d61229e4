//! Proves the navigation grid (`NavGrid`, `NavPath`, `FlowField`) against
//! references built without `tileslide::path` (see `path_support`):
//!
//! - the moves it opens and the points it connects equal a brute-force lattice whose
//!   clearances are measured against every wall of the map;
//! - every run of every found path is clear by the map's own circle cast;
//! - found paths are never shorter than a lower bound of the exact any-angle shortest path
//!   (a visibility graph among inscribed polygons), and at most 8 % longer;
//! - flow fields lead every point to the goal, lowering the distance at every step and
//!   never nearer a wall than the radius, and a crowd moved by the resolver along one
//!   reaches the goal through a door and past pillars;
//! - a grid and a field caught up with random digs and fills (`sync`, read from the map's
//!   edit journal, rebuilt when the journal was overrun) equal ones built on the edited
//!   map, and `NavPath::is_affected_by` never misses a change;
//! - a grid or field used with a map that is not its own (another map, a clone edited
//!   apart) is refused;
//! - bad input is refused with the error naming it.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use crate::generators;
use crate::path_support;

use generators::{rows, tile_chars, tile_map, wall_in};
use glam::DVec2;
use proptest::prelude::*;
use tileslide::io::ascii;
use tileslide::{
    Bodies, BodyDesc, BodyHandle, BodyShape, Cell, Faces, FlowField, NavConfig, NavError, NavGrid,
    NavPath, QueryFilter, SegmentFlags, TileMap, Vec2, limits::JOURNAL_EDITS,
};

use path_support::any_angle::{InflatedScene, room_and_blocks};
use path_support::lattice_reference::{LatticeReference, QUANTISATION, Verdict};
use path_support::query_points::fitting_point;
use path_support::walls::Walls;
use tileslide_scenes::SplitMix64;

/// The grid's margin on unit cells: a circle needs clearance `r + MARGIN`.
const MARGIN: f64 = 1e-3;

/// How far a body may overlap a wall or another body (the resolver's skin, in cells).
const SKIN: f32 = 1e-4;

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

fn map(text: &str) -> TileMap {
    ascii::parse(text, "path.txt", 1.0).unwrap()
}

fn both_faces() -> QueryFilter {
    QueryFilter {
        faces: Faces::Both,
        ..QueryFilter::default()
    }
}

// ----------------------------------------------------------------------------------------
// Random maps
// ----------------------------------------------------------------------------------------

/// A random ASCII map, `width × height`, with a solid border ring unless `open_border`.
#[derive(Clone, Debug)]
struct RandomMap {
    width: u32,
    chars: Vec<char>,
}

impl RandomMap {
    fn text(&self) -> String {
        rows(self.width, &self.chars)
    }

    fn build(&self) -> TileMap {
        tile_map(self.width, &self.chars, 1.0, Vec2::ZERO)
    }
}

/// A random `width × height` map of mostly empty cells, some solid squares and a few ramps
/// (partial tiles with sloped faces), walled in but for a quarter of the maps.
fn random_map(width: u32, height: u32) -> impl Strategy<Value = RandomMap> {
    (
        tile_chars(
            &[(14, '.'), (5, '#'), (1, '/'), (1, '\\')],
            (width * height) as usize,
        ),
        prop::bool::weighted(0.25),
    )
        .prop_map(move |(mut chars, open_border)| {
            if !open_border {
                wall_in(width, &mut chars);
            }
            RandomMap { width, chars }
        })
}

// ----------------------------------------------------------------------------------------
// 1. Reachability and open moves equal a brute-force lattice
// ----------------------------------------------------------------------------------------

const REACH_RADII: [f32; 4] = [0.2, 0.3, 0.45, 0.7];
const PAIRS_PER_RADIUS: usize = 24;

/// Whether `b` can be reached from `a` (both nodes of `reference`) when each end may also
/// join any node within two lattice steps, or the other end, by a straight line clear for
/// `need` (what `find_path` does with its end points, taken generously), borderline moves
/// open: an upper bound of what `find_path` may connect.
fn reachable_with_straight_joins(
    map: &TileMap,
    walls: &Walls,
    reference: &LatticeReference,
    (a, b): (usize, usize),
    need: f64,
) -> bool {
    let joins = |n: usize| -> Vec<usize> {
        let (i, j) = reference.coords(n);
        let mut out = vec![n];
        for dj in -2i64..=2 {
            for di in -2i64..=2 {
                let (qi, qj) = (i64::from(i) + di, i64::from(j) + dj);
                if qi < 0
                    || qj < 0
                    || qi >= i64::from(reference.nx)
                    || qj >= i64::from(reference.ny)
                {
                    continue;
                }
                let q = reference.index(qi as u32, qj as u32);
                let clear = walls.clearance(map, reference.positions[n], reference.positions[q]);
                if clear >= need - QUANTISATION {
                    out.push(q);
                }
            }
        }
        out
    };
    let (pa, pb) = (reference.positions[a], reference.positions[b]);
    if pa.distance(pb) <= 4.0 && walls.clearance(map, pa, pb) >= need - QUANTISATION {
        return true;
    }
    let seen = reference.flood(&joins(a), need, true);
    joins(b).into_iter().any(|q| seen[q])
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 8, ..ProptestConfig::default() })]

    /// (a) `open_moves` at every node equals the brute-force verdict for each radius
    /// (except within the grid's quantisation of the threshold); (b) between random pairs
    /// of nodes where the circle fits, `find_path` finds a path whenever the brute-force
    /// lattice connects them, and only when it does, give or take the straight lines its
    /// end points join the lattice by.
    #[test]
    fn open_moves_and_reachability_equal_a_brute_force_lattice(
        random in random_map(12, 10),
        seed in any::<u64>(),
    ) {
        let map = random.build();
        let nav = NavGrid::new(&map, NavConfig::default()).unwrap();
        let walls = Walls::of(&map);
        let reference = LatticeReference::build(&map, &walls);
        prop_assert_eq!(nav.nodes(), (reference.nx, reference.ny));
        for n in 0..reference.len() {
            let (i, j) = reference.coords(n);
            prop_assert_eq!(nav.node_position(i, j), reference.positions[n]);
        }
        let mut rng = SplitMix64::new(seed);
        for r in REACH_RADII {
            let need = f64::from(r) + MARGIN;
            for n in 0..reference.len() {
                let (i, j) = reference.coords(n);
                let bits = nav.open_moves(&map, i, j, r).unwrap();
                for d in 0..8 {
                    let open = bits >> d & 1 == 1;
                    let verdict = reference.verdict(n, d, need);
                    let expected = match verdict {
                        Verdict::Borderline => continue,
                        Verdict::Open => true,
                        Verdict::Closed | Verdict::Missing => false,
                    };
                    prop_assert_eq!(
                        open, expected,
                        "r {}: move {} from node ({}, {}) at {}: brute-force clearance {:?}\n{}",
                        r, d, i, j, reference.positions[n], reference.moves[n][d], random.text()
                    );
                }
            }
            let free: Vec<usize> = (0..reference.len())
                .filter(|&n| reference.point[n] >= need + QUANTISATION)
                .collect();
            if free.len() < 2 {
                continue;
            }
            for _ in 0..PAIRS_PER_RADIUS {
                let (a, b) = (rng.pick(&free).unwrap(), rng.pick(&free).unwrap());
                let (pa, pb) = (reference.positions[a], reference.positions[b]);
                let found = nav.find_path(&map, pa, pb, r).unwrap().is_some();
                let by_lattice = reference.flood(&[a], need, false)[b];
                let at_most = reachable_with_straight_joins(&map, &walls, &reference, (a, b), need);
                prop_assert!(
                    !by_lattice || found,
                    "r {}: {} and {} are connected on the lattice but no path was found\n{}",
                    r, pa, pb, random.text()
                );
                prop_assert!(
                    !found || at_most,
                    "r {}: a path from {} to {} was found but the lattice does not connect them\n{}",
                    r, pa, pb, random.text()
                );
            }
        }
    }
}

// ----------------------------------------------------------------------------------------
// 2. Every smoothed path is clear
// ----------------------------------------------------------------------------------------

/// Checks the promises of a path found from `from` to `to` for `r`: its ends, its length,
/// and every straight run clear by the map's circle cast (both faces) and, independently,
/// at least `r` from every wall.
fn check_path(
    map: &TileMap,
    walls: &Walls,
    path: &NavPath,
    (from, to): (Vec2, Vec2),
    r: f32,
) -> Result<(), TestCaseError> {
    let points = path.points();
    prop_assert!(points.len() >= 2, "{:?}", points);
    prop_assert_eq!(points[0], from);
    prop_assert_eq!(points[points.len() - 1], to);
    prop_assert_eq!(path.radius(), r);
    let mut sum = 0.0;
    for run in points.windows(2) {
        let (a, b) = (run[0], run[1]);
        let hit = map.cast_circle(a, r, b - a, &both_faces()).unwrap();
        prop_assert!(
            hit.is_none(),
            "r {}: the run {} -> {} of {:?} hits a wall: {:?}",
            r,
            a,
            b,
            points,
            hit
        );
        let clear = walls.distance_to_move(a, b);
        prop_assert!(
            clear >= f64::from(r - SKIN),
            "r {}: the run {} -> {} passes {} from a wall",
            r,
            a,
            b,
            clear
        );
        sum += a.distance(b);
    }
    prop_assert!(
        (path.length() - sum).abs() <= 1e-4 * sum.max(1.0),
        "length {} but the runs add up to {}",
        path.length(),
        sum
    );
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 12, ..ProptestConfig::default() })]

    /// Random queries between points where the circle fits, for radii up to 0.9 cell: every
    /// found path starts at the start, ends at the goal, is as long as its runs, and every
    /// run is clear by `cast_circle` with both faces.
    #[test]
    fn every_run_of_a_smoothed_path_is_clear_by_circle_cast(
        random in random_map(12, 10),
        seed in any::<u64>(),
    ) {
        let map = random.build();
        let nav = NavGrid::new(&map, NavConfig::default()).unwrap();
        let walls = Walls::of(&map);
        let mut rng = SplitMix64::new(seed);
        for _ in 0..20 {
            let r = rng.pick(&[0.2f32, 0.35, 0.5, 0.7, 0.9]).unwrap();
            let (Some(from), Some(to)) = (
                fitting_point(&nav, &map, &mut rng, r),
                fitting_point(&nav, &map, &mut rng, r),
            ) else {
                continue;
            };
            if let Some(path) = nav.find_path(&map, from, to, r).unwrap() {
                check_path(&map, &walls, &path, (from, to), r)?;
            }
        }
    }
}

// ----------------------------------------------------------------------------------------
// 3. Path length within 8 % of the exact any-angle shortest path
// ----------------------------------------------------------------------------------------

/// Blocks of different sizes in an open room.
const BLOCKS: &str = "\
####################
#..................#
#..####............#
#..####.....##.....#
#...........##.....#
#.......#####......#
#..................#
#...##.........###.#
#...##.........###.#
#...##.............#
#.........####.....#
#.........####.....#
#..###.............#
#..###.......##....#
#............##....#
####################";

/// A corridor two cells wide winding back and forth.
const SERPENTINE: &str = "\
####################
#..................#
#..................#
#################..#
#..................#
#..................#
#..#################
#..................#
#..................#
#################..#
#..................#
####################";

/// Pillars of one cell and a wall with a gap.
const PILLARS: &str = "\
##################
#................#
#..#...#...#..#..#
#................#
#.....#....#.....#
#.#..............#
#######...########
#................#
#..#....#....#...#
#................#
##################";

/// The longest a found path may be over the exact shortest.
const LENGTH_RATIO: f64 = 1.08;

/// One query of [`lengths_against_any_angle`]: a found path and the lower bound of the
/// exact shortest path between its ends.
struct LengthCheck {
    what: String,
    path: NavPath,
    bound: f64,
}

impl LengthCheck {
    fn ratio(&self) -> f64 {
        f64::from(self.path.length()) / self.bound
    }
}

/// For each test map and radius 0.3 and 0.8: the farthest-apart nodes where the circle
/// fits and random pairs of them at least 3 cells apart, `pairs` queries in all whose ends
/// the lower bound connects, each with the lower bound of its exact shortest path (corner
/// arcs sampled at 8 edges per quarter circle) and the path found. Asserts that every
/// query finds a path and that the bound is sane: at least the straight line and at most
/// the found path (which is a real path of the disc).
fn lengths_against_any_angle(pairs: usize, seed: u64) -> Vec<LengthCheck> {
    let mut rng = SplitMix64::new(seed);
    let mut checks = Vec::new();
    for (name, text) in [
        ("blocks", BLOCKS),
        ("serpentine", SERPENTINE),
        ("pillars", PILLARS),
    ] {
        let map = map(text);
        let nav = NavGrid::new(&map, NavConfig::default()).unwrap();
        let (room, blocks) = room_and_blocks(&map);
        for r in [0.3f32, 0.8] {
            let scene = InflatedScene::new(room, &blocks, f64::from(r), 8);
            let (nx, ny) = nav.nodes();
            let nodes: Vec<Vec2> = (0..ny)
                .flat_map(|j| (0..nx).map(move |i| (i, j)))
                .map(|(i, j)| nav.node_position(i, j))
                .filter(|&p| nav.fits(&map, p, r).unwrap())
                .collect();
            let random =
                std::iter::repeat_with(|| (rng.pick(&nodes).unwrap(), rng.pick(&nodes).unwrap()))
                    .filter(|(a, b)| a.distance(*b) > 3.0);
            let queries = std::iter::once((nodes[0], nodes[nodes.len() - 1])).chain(random);
            let mut asked = 0;
            for (from, to) in queries {
                if asked == pairs {
                    break;
                }
                let what = format!("{name}, r {r}: {from} -> {to}");
                let Some(bound) = scene.lower_bound(from.as_dvec2(), to.as_dvec2()) else {
                    continue;
                };
                asked += 1;
                let path = nav.find_path(&map, from, to, r).unwrap();
                let path = path.unwrap_or_else(|| panic!("{what}: no path found"));
                let straight = from.as_dvec2().distance(to.as_dvec2());
                let length = f64::from(path.length());
                assert!(
                    bound >= straight - 1e-9,
                    "{what}: the lower bound {bound} is shorter than the straight line {straight}"
                );
                assert!(
                    bound <= length + 1e-3,
                    "{what}: the lower bound {bound} exceeds the found path {length}: {:?}",
                    path.points()
                );
                checks.push(LengthCheck { what, path, bound });
            }
        }
    }
    checks
}

/// The part of the length requirement that holds today: the lower bound is sane and never
/// above a found path (so found paths never cut through the inflated obstacles).
#[test]
fn found_paths_are_never_shorter_than_the_exact_any_angle_shortest_path() {
    let checks = lengths_against_any_angle(10, 7);
    assert_eq!(checks.len(), 60);
}

/// Found paths are within 8 % of the exact any-angle shortest path on the test maps.
#[test]
fn found_paths_are_within_8_percent_of_the_exact_any_angle_shortest_path() {
    let checks = lengths_against_any_angle(40, 7);
    let over: Vec<String> = checks
        .iter()
        .filter(|c| c.ratio() > LENGTH_RATIO)
        .map(|c| {
            format!(
                "{}: path {} is {:.1} % over the shortest (at least {:.4}): {:?}",
                c.what,
                c.path.length(),
                (c.ratio() - 1.0) * 100.0,
                c.bound,
                c.path.points()
            )
        })
        .collect();
    assert!(
        over.is_empty(),
        "{} of {} paths are more than 8 % over the exact shortest:\n{}",
        over.len(),
        checks.len(),
        over.join("\n")
    );
}

/// The serpentine's first bend for r = 0.8, worked out by hand (tangent 0.6, arc 0.742,
/// straight 1.0, arc 1.009, tangent 0.781: 4.132): the lower bound converges to it from
/// below as the arcs are sampled more finely.
#[test]
fn the_any_angle_lower_bound_matches_a_bend_worked_out_by_hand() {
    let map = map(SERPENTINE);
    let (room, blocks) = room_and_blocks(&map);
    let (from, to) = (DVec2::new(3.0, 5.0), DVec2::new(3.5, 8.0));
    let (half_pi, r) = (std::f64::consts::FRAC_PI_2, 0.8f64);
    // From (3, 5), 1 from the corner (3, 6): tangent, arc to the corner's left, straight
    // down to the corner (3, 7), arc round it, tangent to (3.5, 8), √1.25 from it.
    let exact = (1.0 - r * r).sqrt()
        + r * (half_pi - r.acos())
        + 1.0
        + r * (half_pi + 0.5f64.atan() - (r / 1.25f64.sqrt()).acos())
        + (1.25 - r * r).sqrt();
    let mut last = 0.0;
    for arc_segments in [4, 8, 32] {
        let bound = InflatedScene::new(room, &blocks, 0.8, arc_segments)
            .lower_bound(from, to)
            .unwrap();
        assert!(bound <= exact + 1e-9, "{arc_segments}: {bound} > {exact}");
        assert!(bound >= last, "{arc_segments}: {bound} < {last}");
        last = bound;
    }
    assert!(exact - last < 1e-3, "{last} vs {exact}");
}

// ----------------------------------------------------------------------------------------
// 4. Flow fields
// ----------------------------------------------------------------------------------------

/// Rooms, a dead end, pillars and a narrow door.
const FLOW: &str = "\
################
#......#.......#
#.##...#...#...#
#.##.......#...#
#......##......#
#..#...##..#...#
#..#.......#...#
################";

/// How far an agent moves per step (cells).
const STEP: f32 = 0.05;

/// From every cell centre where the circle fits and the goal is reachable,
/// steps of 0.05 along `direction` reach the goal within 1.1 × the field's distance, every
/// step lowers the field's distance, and no point on the way is nearer a wall than the
/// radius (plus the grid's margin).
#[test]
fn following_a_flow_field_reaches_the_goal_and_never_nears_a_wall() {
    let map = map(FLOW);
    let nav = NavGrid::new(&map, NavConfig::default()).unwrap();
    for (goal, r) in [(v(14.0, 6.0), 0.3f32), (v(1.5, 1.5), 0.45)] {
        let field = FlowField::new(&nav, &map, goal, r).unwrap();
        let (nx, ny) = nav.nodes();
        let mut followed = 0;
        let centres = (1..ny)
            .step_by(2)
            .flat_map(|j| (1..nx).step_by(2).map(move |i| (i, j)));
        for (i, j) in centres {
            let start = nav.node_position(i, j);
            if !nav.fits(&map, start, r).unwrap() {
                continue;
            }
            let Some(d0) = field.distance(&nav, &map, start).unwrap() else {
                continue;
            };
            followed += 1;
            let limit = (d0 / STEP * 1.1) as usize + 1;
            let (mut p, mut d, mut steps) = (start, d0, 0);
            while p.distance(goal) > 1e-3 {
                assert!(
                    steps < limit,
                    "r {r}: from {start} (distance {d0}), still {d} away at {p} after {steps} steps"
                );
                let dir = field.direction(&nav, &map, p).unwrap();
                let dir = dir.unwrap_or_else(|| panic!("r {r}: from {start}, no direction at {p}"));
                p += dir * STEP.min(p.distance(goal));
                steps += 1;
                assert!(
                    nav.fits(&map, p, r).unwrap(),
                    "r {r}: from {start}, the way leads to {p}, nearer a wall than {r}"
                );
                let next = field.distance(&nav, &map, p).unwrap().unwrap();
                assert!(
                    next < d,
                    "r {r}: from {start}, the distance went from {d} to {next} at {p}"
                );
                d = next;
            }
        }
        assert!(followed > 30, "r {r}: only {followed} starts");
    }
}

/// A room with pillars two cells apart, a door two cells wide, a hall with blocks and a
/// corridor back under the room.
const CROWD: &str = "\
########################
#........#.............#
#..#..#..#.............#
#........#....##.......#
#........#....##.......#
#..#..#................#
#......................#
#........#.............#
#..#..#..#.......##....#
#........#.......##....#
##########.............#
#......................#
#......................#
########################";

/// 30 agents of radius 0.3 in a room with pillars steer by one flow field
/// (`FlowField::direction`), are moved 0.05 a step by `Bodies`, and leave through the goal
/// (removed within 1.5 cells of it) within 2,500 steps; no two overlap and none touches a
/// wall closer than its radius at any step.
#[test]
fn a_crowd_following_a_flow_field_reaches_the_goal_without_overlapping_or_sticking() {
    crowd_reaches_the_goal(|field, nav, map, p| field.direction(nav, map, p).unwrap());
}

/// The same crowd steered by the cheap `FlowField::lattice_direction` (no straight-line
/// checks): the resolver slides the agents round the pillars and the door's corners it
/// presses them against, and all leave through the goal within the same 2,500 steps.
#[test]
fn a_crowd_following_lattice_directions_reaches_the_goal_without_overlapping_or_sticking() {
    crowd_reaches_the_goal(|field, nav, map, p| field.lattice_direction(nav, map, p).unwrap());
}

/// The crowd of the two tests above, steered by `steer` (a circle's direction at a point).
fn crowd_reaches_the_goal(steer: impl Fn(&FlowField, &NavGrid, &TileMap, Vec2) -> Option<Vec2>) {
    const R: f32 = 0.3;
    const AGENTS: usize = 30;
    const EXIT: f32 = 1.5;
    const MAX_STEPS: usize = 2500;
    let map = map(CROWD);
    let nav = NavGrid::new(&map, NavConfig::default()).unwrap();
    let walls = Walls::of(&map);
    let goal = v(2.0, 12.0);
    let field = FlowField::new(&nav, &map, goal, R).unwrap();
    let mut bodies = Bodies::new();
    // Every other free cell centre of the room with pillars.
    let mut agents: Vec<BodyHandle> = (1..10)
        .flat_map(|row| (1..9).map(move |col| v(col as f32 + 0.5, row as f32 + 0.5)))
        .filter(|&p| nav.fits(&map, p, R).unwrap())
        .step_by(2)
        .take(AGENTS)
        .map(|p| {
            bodies
                .add(BodyDesc::new(p, BodyShape::circle(R).unwrap()))
                .unwrap()
        })
        .collect();
    assert_eq!(agents.len(), AGENTS);
    for step in 1..=MAX_STEPS {
        for &h in &agents {
            let p = bodies.get(h).unwrap().position();
            let dir = steer(&field, &nav, &map, p);
            bodies.propose(h, dir.unwrap_or(Vec2::ZERO) * STEP).unwrap();
        }
        bodies.step(&map);
        let positions: Vec<Vec2> = agents
            .iter()
            .map(|&h| bodies.get(h).unwrap().position())
            .collect();
        for (k, &p) in positions.iter().enumerate() {
            let wall = walls.distance_to_point(p);
            assert!(
                !map.is_point_solid(p) && wall >= f64::from(R - SKIN),
                "step {step}: agent at {p} is {wall} from a wall"
            );
            for &q in &positions[k + 1..] {
                assert!(
                    p.distance(q) >= 2.0 * R - SKIN,
                    "step {step}: agents at {p} and {q} overlap"
                );
            }
        }
        // Agents at the goal leave through it.
        for (&h, &p) in agents.iter().zip(&positions) {
            if p.distance(goal) <= EXIT {
                bodies.remove(h).unwrap();
            }
        }
        agents.retain(|&h| bodies.contains(h));
        if agents.is_empty() {
            return;
        }
    }
    let stuck: Vec<String> = agents
        .iter()
        .map(|&h| {
            let p = bodies.get(h).unwrap().position();
            let dir = steer(&field, &nav, &map, p);
            format!(
                "{p} (direction {dir:?}, {:.4} from a wall)",
                walls.distance_to_point(p)
            )
        })
        .collect();
    panic!(
        "{} agents still out after {MAX_STEPS} steps:\n{}",
        agents.len(),
        stuck.join("\n")
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Along a corridor one cell wide, whose middle line is a line of lattice nodes, the
    /// way to a goal on that line is that line: `lattice_direction` and `direction` agree
    /// (both `None` only on the goal) at every point of it where the circle fits.
    #[test]
    fn lattice_direction_equals_direction_along_a_corridor(
        length in 3u32..40,
        r in 0.05f32..0.45,
        goal_at in 0.0f32..1.0,
        points in prop::collection::vec(0.0f32..1.0, 1..16),
    ) {
        let text = format!(
            "{wall}\n#{floor}#\n{wall}",
            wall = "#".repeat(length as usize + 2),
            floor = ".".repeat(length as usize),
        );
        let map = map(&text);
        let nav = NavGrid::new(&map, NavConfig::default()).unwrap();
        // Points on the middle line, from the corridor's left end to its right end.
        let on_line = |t: f32| v(1.0 + t * length as f32, 1.5);
        let goal = on_line(goal_at);
        prop_assume!(nav.fits(&map, goal, r).unwrap());
        let field = FlowField::new(&nav, &map, goal, r).unwrap();
        for p in points.into_iter().map(on_line).chain([goal]) {
            if !nav.fits(&map, p, r).unwrap() {
                continue;
            }
            let cheap = field.lattice_direction(&nav, &map, p).unwrap();
            let full = field.direction(&nav, &map, p).unwrap();
            // Equal up to the rounding of normalizing vectors of different lengths.
            let same = match (cheap, full) {
                (Some(a), Some(b)) => a.abs_diff_eq(b, 1e-6),
                (a, b) => a == b,
            };
            prop_assert!(same, "at {} towards {}: {:?} against {:?}", p, goal, cheap, full);
            prop_assert_eq!(cheap.is_none(), p == goal, "at {} towards {}", p, goal);
        }
    }
}

/// Regression (FlowField): the resolver keeps bodies between r + gap/2 and r + gap from
/// walls (`ResolveConfig::gap`, 1e-3 units on these unit cells), but
/// `FlowField::direction` (and `distance`, and `NavGrid::fits`) need r + the grid's margin
/// (also 1e-3 cell): a body pushed against
/// a wall gets no direction, proposes no move and stays there for good, a plug for others.
#[test]
fn a_body_the_resolver_left_against_a_wall_still_gets_a_flow_direction() {
    let map = map(ROOM);
    let nav = NavGrid::new(&map, NavConfig::default()).unwrap();
    let field = FlowField::new(&nav, &map, v(6.0, 2.0), 0.3).unwrap();
    let mut bodies = Bodies::new();
    let h = bodies
        .add(BodyDesc::new(v(2.0, 2.0), BodyShape::circle(0.3).unwrap()))
        .unwrap();
    // Into the left wall (x = 1), as a crowd pushes its members.
    for _ in 0..6 {
        bodies.propose(h, v(-0.2, 0.0)).unwrap();
        bodies.step(&map);
    }
    let p = bodies.get(h).unwrap().position();
    assert!(p.x >= 1.3 && p.x < 1.301, "{p}");
    assert!(
        field.direction(&nav, &map, p).unwrap().is_some(),
        "a body at {p}, {} from the wall, gets no direction to the goal",
        p.x - 1.0
    );
    assert!(field.distance(&nav, &map, p).unwrap().is_some());
    assert!(nav.fits(&map, p, 0.3).unwrap());
    // A path from there, along the wall and away, is clear by the circle cast.
    let path = nav.find_path(&map, p, v(6.0, 2.0), 0.3).unwrap().unwrap();
    for w in path.points().windows(2) {
        let hit = map
            .cast_circle(w[0], 0.3, w[1] - w[0], &both_faces())
            .unwrap();
        assert!(hit.is_none(), "{w:?}: {hit:?}");
    }
    // Where fitting ends: half the resolver's gap from the wall fits, an eighth of the
    // grid's margin does not, nor does overlapping it.
    for (x, fits) in [
        (1.3 + 5e-4, true),
        (1.3 + 1.25e-4, false),
        (1.3 - 1e-2, false),
    ] {
        assert_eq!(nav.fits(&map, v(x, 2.0), 0.3).unwrap(), fits, "x {x}");
    }
}

/// Regression (Bodies): a body touching another (as the resolver leaves them, within the
/// gap band) and moving obliquely into it is cut to a zero move instead of sliding round it
/// along the contact tangent, for some directions: crowds lock up in open space. Found by
/// the crowd test; the first case is two of its agents as it left them.
#[test]
fn a_body_touching_another_slides_round_it_when_moving_obliquely_into_it() {
    let map = map(TWO_ROOMS);
    let v = Vec2::new;
    let at_angle = |k: f32, separation: f32| {
        let a = k / 64.0 * std::f32::consts::TAU;
        let dir = v(a.cos(), a.sin());
        let mover = v(10.0, 6.5) + dir * separation;
        (mover, v(10.0, 6.5), (dir.perp() - dir).normalize() * 0.05)
    };
    for (mover, still, motion) in [
        (
            v(10.041976, 7.06332),
            v(9.649439, 7.517759),
            v(0.0077051776, 0.049402736),
        ),
        at_angle(2.0, 0.6005),
        at_angle(3.0, 0.6003),
    ] {
        let mut bodies = Bodies::new();
        let a = bodies
            .add(BodyDesc::new(mover, BodyShape::circle(0.3).unwrap()))
            .unwrap();
        bodies
            .add(BodyDesc::new(still, BodyShape::circle(0.3).unwrap()))
            .unwrap();
        bodies.propose(a, motion).unwrap();
        let report = bodies.resolve(&map);
        let moved = bodies.get(a).unwrap().resolved_move();
        assert!(
            moved.length() > 0.025,
            "a body at {mover}, {} from one at {still}, moving {motion} ({:.0}° into it) moved {moved}: {report:?}",
            mover.distance(still),
            (motion.normalize().dot((still - mover).normalize()))
                .acos()
                .to_degrees()
        );
    }
}

// ----------------------------------------------------------------------------------------
// 5. Catching up with edits equals a full recompute
// ----------------------------------------------------------------------------------------

/// A tile for an edit: `None` digs (`clear_tile`), `Some` fills (one-way platforms too).
fn edit_tile() -> impl Strategy<Value = Option<char>> {
    prop_oneof![
        5 => Just(None),
        4 => Just(Some('#')),
        1 => Just(Some('/')),
        1 => Just(Some('\\')),
        2 => Just(Some('=')),
    ]
}

const UPDATE_RADII: [f32; 4] = [0.2, 0.45, 0.8, 1.0];

/// Asserts that `nav` opens the same moves as `fresh` at every node for every radius of
/// [`UPDATE_RADII`].
fn assert_same_moves(nav: &NavGrid, fresh: &NavGrid, map: &TileMap, context: &str) {
    let (nx, ny) = fresh.nodes();
    assert_eq!(nav.nodes(), (nx, ny));
    for r in UPDATE_RADII {
        for j in 0..ny {
            for i in 0..nx {
                assert_eq!(
                    nav.open_moves(map, i, j, r).unwrap(),
                    fresh.open_moves(map, i, j, r).unwrap(),
                    "r {r}: node ({i}, {j}) {context}"
                );
            }
        }
    }
}

/// Where each run of `path` first meets a wall on `map`, as `t` along the run (infinite
/// when it meets none): solid walls cast from both sides, one-way platforms from the front.
///
/// A found path's runs meet no solid wall, and meet a one-way platform only where the grid
/// lets them graze its end: a run that starts just through a platform, still within reach
/// of its end, and closes in on the end by less than a quarter of the grid's margin. The
/// cast stops the circle at once there, the resolver moves a body on along the run (see
/// `a_far_edit_leaves_a_path_grazing_the_end_of_a_platform_it_just_crossed_as_it_was`).
fn first_contacts(path: &NavPath, map: &TileMap) -> Vec<[f32; 2]> {
    let solid = both_faces().with_mask(SegmentFlags::SOLID);
    let one_way = QueryFilter::default().with_mask(SegmentFlags::ONE_WAY);
    let r = path.radius();
    let t = |a: Vec2, motion: Vec2, filter: &QueryFilter| {
        let hit = map.cast_circle(a, r, motion, filter).unwrap();
        hit.map_or(f32::INFINITY, |h| h.t)
    };
    path.points()
        .windows(2)
        .map(|run| {
            let (a, motion) = (run[0], run[1] - run[0]);
            [t(a, motion, &solid), t(a, motion, &one_way)]
        })
        .collect()
}

/// Asserts that no run of `path` meets a wall on `map` sooner than it did on the map it
/// was found on (`found`, from [`first_contacts`]): the edits since blocked none of it.
fn assert_still_clear(path: &NavPath, found: &[[f32; 2]], map: &TileMap, context: &str) {
    let now = first_contacts(path, map);
    for ((run, then), now) in path.points().windows(2).zip(found).zip(now) {
        assert!(
            now[0] >= then[0] && now[1] >= then[1],
            "the edits blocked the run {} -> {} of a path they do not affect (t of the first \
             solid and one-way contact {now:?}, {then:?} when found): {context}",
            run[0],
            run[1]
        );
    }
}

/// The tile `tile` stands for (`None`: dig).
fn edit_to(map: &mut TileMap, cell: Cell, tile: Option<char>) {
    match tile {
        None => map.clear_tile(cell).unwrap(),
        Some(c) => map
            .set_tile(cell, ascii::tile_for_char(c).unwrap())
            .unwrap(),
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    /// After random digs and fills anywhere (border included), with `sync` after some of
    /// them (several edits between two syncs too): the grid opens the same moves as one
    /// built from scratch at every node for every radius; a flow field synced along with it
    /// equals a new one (recomputed only when its way changed); and a path that
    /// `is_affected_by` calls unaffected meets no wall by circle cast sooner than when it
    /// was found (see [`first_contacts`]).
    #[test]
    fn syncs_after_random_digs_and_fills_equal_a_full_recompute(
        random in random_map(10, 8),
        edits in prop::collection::vec(
            (0u32..10, 0u32..8, edit_tile(), prop::bool::weighted(0.6)), 1..16),
        seed in any::<u64>(),
    ) {
        let mut map = random.build();
        let mut nav = NavGrid::new(&map, NavConfig::default()).unwrap();
        let mut rng = SplitMix64::new(seed);
        let r = 0.4;
        let goal = fitting_point(&nav, &map, &mut rng, r).unwrap_or(v(5.0, 4.0));
        let mut field = FlowField::new(&nav, &map, goal, r).unwrap();
        let from = fitting_point(&nav, &map, &mut rng, r).unwrap_or(v(1.0, 1.0));
        let mut path = nav.find_path(&map, from, goal, r).unwrap();
        let mut found = path.as_ref().map(|p| first_contacts(p, &map));
        let context = || format!("after edits {edits:?}\n{}", random.text());
        for (k, &(col, row, tile, sync)) in edits.iter().enumerate() {
            edit_to(&mut map, Cell::new(col, row), tile);
            if !sync && k + 1 < edits.len() {
                continue;
            }
            let change = nav.sync(&map).unwrap();
            prop_assert!(!change.is_rebuild());
            field.sync(&nav, &map).unwrap();
            if let (Some(p), Some(found_on)) = (&path, &found) {
                if p.is_affected_by(&change) {
                    path = nav.find_path(&map, from, goal, r).unwrap();
                    found = path.as_ref().map(|p| first_contacts(p, &map));
                } else {
                    assert_still_clear(p, found_on, &map, &context());
                }
            }
        }
        let fresh = NavGrid::new(&map, NavConfig::default()).unwrap();
        assert_same_moves(&nav, &fresh, &map, &context());
        let new = FlowField::new(&fresh, &map, goal, r).unwrap();
        prop_assert!(field == new, "a synced field differs from a new one {}", context());
    }

    /// More edits between two syncs than the map's journal keeps (and, for comparison, a
    /// few fewer): the grid and the field rebuild, say so, and equal ones built on the
    /// edited map; within the journal they catch up edit by edit and say they did not
    /// rebuild.
    #[test]
    fn a_sync_past_the_journal_rebuilds_says_so_and_equals_a_full_recompute(
        random in random_map(10, 8),
        edits in prop_oneof![1usize..40, JOURNAL_EDITS - 8..JOURNAL_EDITS + 8],
        seed in any::<u64>(),
    ) {
        let mut map = random.build();
        let mut nav = NavGrid::new(&map, NavConfig::default()).unwrap();
        let mut rng = SplitMix64::new(seed);
        let r = 0.4;
        let goal = fitting_point(&nav, &map, &mut rng, r).unwrap_or(v(5.0, 4.0));
        let mut field = FlowField::new(&nav, &map, goal, r).unwrap();
        let from = fitting_point(&nav, &map, &mut rng, r).unwrap_or(v(1.0, 1.0));
        let path = nav.find_path(&map, from, goal, r).unwrap();
        // Every edit changes its cell (the same tile again is no edit).
        let tiles = ['.', '#', '/', '='];
        for _ in 0..edits {
            let cell = Cell::new(rng.below(10) as u32, rng.below(8) as u32);
            let now = map.tile(cell);
            let tile = tiles
                .iter()
                .map(|&c| ascii::tile_for_char(c).unwrap())
                .cycle()
                .skip(rng.below(4) as usize)
                .find(|&t| t != now)
                .unwrap();
            map.set_tile(cell, tile).unwrap();
        }
        let change = nav.sync(&map).unwrap();
        let rebuilt = field.sync(&nav, &map).unwrap();
        prop_assert_eq!(change.is_rebuild(), edits > JOURNAL_EDITS, "{} edits", edits);
        if edits > JOURNAL_EDITS {
            prop_assert!(rebuilt, "the field is recomputed");
            prop_assert!(!change.is_empty() && change.region() == Some(map.bounds()));
            prop_assert!(path.as_ref().is_none_or(|p| p.is_affected_by(&change)));
        }
        let fresh = NavGrid::new(&map, NavConfig::default()).unwrap();
        assert_same_moves(&nav, &fresh, &map, &format!("{edits} edits\n{}", random.text()));
        let new = FlowField::new(&fresh, &map, goal, r).unwrap();
        prop_assert!(field == new, "a synced field differs from a new one");
        prop_assert!(nav.find_path(&map, from, goal, r).is_ok());
    }
}

/// Two rooms joined by a corridor, and a closet far from it.
const TWO_ROOMS: &str = "\
####################
#.....#......#.....#
#.....#......#.....#
#..................#
#.....#......#.....#
#######......#######
#....#.............#
#....#.............#
####################";

#[test]
fn a_far_edit_does_not_affect_a_path_and_filling_a_cell_on_it_does() {
    let mut map = map(TWO_ROOMS);
    let mut nav = NavGrid::new(&map, NavConfig::default()).unwrap();
    let (from, to) = (v(2.5, 3.5), v(17.5, 3.5));
    let path = nav.find_path(&map, from, to, 0.4).unwrap().unwrap();
    assert_eq!(path.points(), &[from, to], "a straight run along row 3");
    let field = FlowField::new(&nav, &map, to, 0.4).unwrap();

    // A block put in the closet, which is closed off from every room: moves close in it,
    // none the field's nodes make.
    let mut field = field;
    map.set_tile(Cell::new(2, 6), Some(ascii::SOLID)).unwrap();
    let closet = nav.sync(&map).unwrap();
    assert!(!closet.is_empty() && !path.is_affected_by(&closet));
    assert_eq!(
        field.sync(&nav, &map),
        Ok(false),
        "the field's way is the same"
    );
    // Dig in the closet at the bottom left, far from the path.
    map.clear_tile(Cell::new(5, 7)).unwrap();
    let far = nav.sync(&map).unwrap();
    assert!(!far.is_empty(), "digging opens moves in the closet");
    assert!(!far.is_rebuild());
    assert!(!path.is_affected_by(&far));
    // The dug cell joins the closet to the bottom room, which the field reaches: the
    // field's way changes (the closet's nodes now reach the goal).
    assert_eq!(
        field.distance(&nav, &map, v(3.5, 7.5)),
        Err(NavError::Stale)
    );
    assert_eq!(field.sync(&nav, &map), Ok(true));
    assert!(field.distance(&nav, &map, v(3.5, 7.5)).unwrap().is_some());
    // Fill a cell of the corridor the path runs through.
    map.set_tile(Cell::new(9, 3), Some(ascii::SOLID)).unwrap();
    let near = nav.sync(&map).unwrap();
    assert!(path.is_affected_by(&near));
    assert_eq!(field.sync(&nav, &map), Ok(true));
    // Round the block, above or below it: at least as far as the straight lines to and
    // from its top corners at the radius's distance (the doors only add to that).
    let around = nav.find_path(&map, from, to, 0.4).unwrap().unwrap();
    let (left, right) = (v(9.0, 3.0 - 0.4), v(10.0, 3.0 - 0.4));
    let shortest = from.distance(left) + 1.0 + right.distance(to);
    assert!(
        around.length() >= shortest - 1e-3 && around.length() > path.length() + 0.1,
        "{} against at least {shortest}: {:?}",
        around.length(),
        around.points()
    );
    assert!(
        around
            .points()
            .iter()
            .any(|p| p.y <= 2.6 + 1e-3 || p.y >= 4.4 - 1e-3),
        "{:?}",
        around.points()
    );
}

/// Regression (the sync property test's expectation): a path found up through a one-way
/// platform turns just past it, where the circle still overlaps the platform's end at
/// (7, 5) and closes in on it by 4·10⁻⁵ before drawing away. The grid lets such a run
/// graze the end (less than a quarter of its margin, see `docs/path.md`) and the resolver
/// moves a body along it untouched, but the circle cast stops the circle there at `t = 0`.
/// The test took that for a block by a later edit that changed no move at all.
#[test]
fn a_far_edit_leaves_a_path_grazing_the_end_of_a_platform_it_just_crossed_as_it_was() {
    let mut map = map("\
##########
#........#
#........#
#........#
#........#
##....=..#
#........#
##########");
    let mut nav = NavGrid::new(&map, NavConfig::default()).unwrap();
    let (from, to, r) = (v(6.6532, 5.180343), v(7.0756884, 3.8625817), 0.4);
    let path = nav.find_path(&map, from, to, r).unwrap().unwrap();
    let found = first_contacts(&path, &map);
    let grazing = found.iter().position(|&[solid, one_way]| {
        assert_eq!(solid, f32::INFINITY, "{:?}", path.points());
        one_way == 0.0
    });
    let k = grazing.expect("a run grazes the platform's end");
    let start = path.points()[k];
    assert!(start.y < 5.0 && start.distance(v(7.0, 5.0)) < r, "{start}");
    // A body moved by the resolver along the runs reaches every corner: the end it grazes
    // does not stop it.
    let mut bodies = Bodies::new();
    let h = bodies
        .add(BodyDesc::new(from, BodyShape::circle(r).unwrap()))
        .unwrap();
    for run in path.points().windows(2) {
        for _ in 0..20 {
            let at = bodies.get(h).unwrap().position();
            bodies
                .propose(h, (run[1] - at).clamp_length_max(0.1))
                .unwrap();
            bodies.step(&map);
        }
        let at = bodies.get(h).unwrap().position();
        assert!(at.distance(run[1]) < 1e-4, "{at} on the run {run:?}");
    }
    // Digging out a corner of the border changes no move, and the path is as it was.
    map.clear_tile(Cell::new(0, 0)).unwrap();
    let change = nav.sync(&map).unwrap();
    assert!(change.is_empty() && !path.is_affected_by(&change));
    assert_still_clear(&path, &found, &map, "a corner dug");
}

/// Regression (FlowField::is_affected_by, now `sync`): it only looked at moves touching
/// nodes the field reaches, so a field whose goal was walled in (it reaches no node) was
/// never told that digging the goal out changed it. Found by the update property test.
#[test]
fn a_field_whose_goal_was_walled_in_is_recomputed_when_it_is_dug_out() {
    let mut map = map(ROOM);
    let mut nav = NavGrid::new(&map, NavConfig::default()).unwrap();
    let (goal, far) = (v(2.5, 1.5), v(5.5, 4.5));
    let mut field = FlowField::new(&nav, &map, goal, 0.3).unwrap();
    assert!(field.distance(&nav, &map, far).unwrap().is_some());
    let cell = Cell::new(2, 1);
    map.set_tile(cell, Some(ascii::SOLID)).unwrap();
    nav.sync(&map).unwrap();
    assert_eq!(field.sync(&nav, &map), Ok(true));
    assert_eq!(
        field.distance(&nav, &map, far),
        Ok(None),
        "the goal is in a wall"
    );
    map.clear_tile(cell).unwrap();
    nav.sync(&map).unwrap();
    assert_eq!(
        field.sync(&nav, &map),
        Ok(true),
        "digging the goal out lets every node reach it again, but the field was not recomputed"
    );
    assert!(field.distance(&nav, &map, far).unwrap().is_some());
}

// ----------------------------------------------------------------------------------------
// 6. Errors
// ----------------------------------------------------------------------------------------

const ROOM: &str = "\
########
#......#
#......#
#..##..#
#......#
########";

/// True when `result` is a `NonFinite` error naming `what` and the point `bad` (bit for
/// bit, so NaN matches NaN).
fn names_non_finite<T>(result: Result<T, NavError>, what: &str, bad: Vec2) -> bool {
    match result {
        Err(NavError::NonFinite { what: w, point }) => {
            w == what && point.to_array().map(f32::to_bits) == bad.to_array().map(f32::to_bits)
        }
        _ => false,
    }
}

#[test]
fn non_finite_points_are_refused_naming_the_point() {
    let map = map(ROOM);
    let nav = NavGrid::new(&map, NavConfig::default()).unwrap();
    let ok = v(1.5, 1.5);
    let field = FlowField::new(&nav, &map, ok, 0.3).unwrap();
    for bad in [
        v(f32::NAN, 1.5),
        v(1.5, f32::INFINITY),
        v(f32::NEG_INFINITY, 1.0),
    ] {
        assert!(names_non_finite(
            nav.find_path(&map, bad, ok, 0.3),
            "from",
            bad
        ));
        assert!(names_non_finite(
            nav.find_path(&map, ok, bad, 0.3),
            "to",
            bad
        ));
        assert!(names_non_finite(
            FlowField::new(&nav, &map, bad, 0.3),
            "goal",
            bad
        ));
        assert!(names_non_finite(nav.fits(&map, bad, 0.3), "p", bad));
        assert!(names_non_finite(field.direction(&nav, &map, bad), "p", bad));
        assert!(names_non_finite(field.distance(&nav, &map, bad), "p", bad));
    }
}

#[test]
fn radii_that_are_not_positive_or_above_max_radius_are_refused() {
    let map = map(ROOM);
    let nav = NavGrid::new(
        &map,
        NavConfig {
            max_radius: 0.6,
            ..NavConfig::default()
        },
    )
    .unwrap();
    assert_eq!(nav.max_radius(), 0.6);
    let (a, b) = (v(1.7, 1.7), v(6.3, 4.3));
    for radius in [0.0, -0.3, 0.61, f32::NAN, f32::INFINITY] {
        let bad = NavError::BadRadius {
            radius,
            max_radius: 0.6,
        };
        let same = |e: NavError| match e {
            NavError::BadRadius {
                radius: got,
                max_radius,
            } => (got == radius || got.is_nan() && radius.is_nan()) && max_radius == 0.6,
            _ => false,
        };
        assert!(
            same(nav.find_path(&map, a, b, radius).unwrap_err()),
            "{bad}"
        );
        assert!(
            same(nav.open_moves(&map, 3, 3, radius).unwrap_err()),
            "{bad}"
        );
        assert!(same(nav.fits(&map, a, radius).unwrap_err()), "{bad}");
        assert!(
            same(FlowField::new(&nav, &map, b, radius).unwrap_err()),
            "{bad}"
        );
    }
    // The largest radius is served.
    assert!(nav.find_path(&map, a, b, 0.6).unwrap().is_some());
}

#[test]
fn max_radius_that_is_not_positive_finite_or_is_over_31_cells_is_refused() {
    let map = map(ROOM);
    for max_radius in [
        f32::NAN,
        0.0,
        -1.0,
        f32::INFINITY,
        31.5,
        1e20,
        f32::MAX,
        -f32::MAX,
    ] {
        let err = NavGrid::new(
            &map,
            NavConfig {
                max_radius,
                ..NavConfig::default()
            },
        )
        .unwrap_err();
        assert!(
            matches!(err, NavError::BadMaxRadius { limit, .. } if limit == 31.0),
            "{max_radius}: {err:?}"
        );
    }
    assert!(
        NavGrid::new(
            &map,
            NavConfig {
                max_radius: 31.0,
                ..NavConfig::default()
            }
        )
        .is_ok()
    );
}

#[test]
fn a_map_edited_without_sync_makes_every_query_stale() {
    let mut map = map(ROOM);
    let mut nav = NavGrid::new(&map, NavConfig::default()).unwrap();
    let mut field = FlowField::new(&nav, &map, v(5.5, 4.5), 0.3).unwrap();
    let (a, b) = (v(1.5, 1.5), v(5.5, 4.5));
    map.clear_tile(Cell::new(3, 3)).unwrap();
    assert_eq!(nav.find_path(&map, a, b, 0.3), Err(NavError::Stale));
    assert_eq!(nav.open_moves(&map, 2, 2, 0.3), Err(NavError::Stale));
    assert_eq!(nav.fits(&map, a, 0.3), Err(NavError::Stale));
    assert_eq!(field.direction(&nav, &map, a), Err(NavError::Stale));
    assert_eq!(field.distance(&nav, &map, a), Err(NavError::Stale));
    assert_eq!(
        FlowField::new(&nav, &map, b, 0.3).unwrap_err(),
        NavError::Stale
    );
    assert_eq!(field.sync(&nav, &map), Err(NavError::Stale), "grid first");
    // After the grid's sync the grid answers, and the field once synced too.
    assert!(!nav.sync(&map).unwrap().is_empty());
    assert!(nav.find_path(&map, a, b, 0.3).unwrap().is_some());
    assert_eq!(field.direction(&nav, &map, a), Err(NavError::Stale));
    field.sync(&nav, &map).unwrap();
    assert!(field.direction(&nav, &map, a).unwrap().is_some());
    // Synced again with nothing new: no change. Temporary segments are no tile edits.
    assert!(nav.sync(&map).unwrap().is_empty());
    map.add_temporary(tileslide::TemporarySegment {
        segment: tileslide::Segment::new(v(1.0, 2.0), v(3.0, 2.0)),
        normal: Vec2::Y,
        flags: SegmentFlags::SOLID,
        owner: tileslide::Owner(1),
        velocity: Vec2::ZERO,
    })
    .unwrap();
    assert!(nav.fits(&map, a, 0.3).unwrap());
}

/// One sync catches up with every edit since the last, in the order they were made,
/// filled and dug cells alike (an edit that sets the same tile again is none).
#[test]
fn one_sync_catches_up_with_every_edit_since_the_last() {
    let mut map = map(ROOM);
    let mut nav = NavGrid::new(&map, NavConfig::default()).unwrap();
    let a = v(1.5, 1.5);
    let (c1, c2, c3) = (Cell::new(3, 3), Cell::new(4, 1), Cell::new(2, 4));
    let before = map.revision();
    map.clear_tile(c1).unwrap();
    map.set_tile(c2, Some(ascii::SOLID)).unwrap();
    map.clear_tile(c1).unwrap(); // no change: not an edit
    map.set_tile(c3, Some(ascii::SOLID)).unwrap();
    let edited: Vec<Cell> = map.changes_since(&before).unwrap().collect();
    assert_eq!(edited, [c1, c2, c3]);
    assert_eq!(map.changes_since(&map.revision()).unwrap().len(), 0);
    let change = nav.sync(&map).unwrap();
    assert!(!change.is_empty() && !change.is_rebuild());
    assert!(nav.fits(&map, a, 0.3).unwrap());
    let fresh = NavGrid::new(&map, NavConfig::default()).unwrap();
    assert_same_moves(&nav, &fresh, &map, "after three edits");
}

/// A grid (or field) answers only on its own map: another map, even of the same tiles, is
/// refused, by the queries and by `sync`, and leaves the grid as it was.
#[test]
fn a_grid_or_field_used_with_another_map_is_refused() {
    let mut map = map(ROOM);
    let mut nav = NavGrid::new(&map, NavConfig::default()).unwrap();
    let mut field = FlowField::new(&nav, &map, v(5.5, 4.5), 0.3).unwrap();
    let a = v(1.5, 1.5);
    let same_tiles = self::map(ROOM);
    let wider = self::map("#########\n#.......#\n#########");
    for other in [&same_tiles, &wider] {
        assert_eq!(nav.sync(other), Err(NavError::OtherMap));
        assert_eq!(nav.fits(other, a, 0.3), Err(NavError::OtherMap));
        assert_eq!(nav.open_moves(other, 1, 1, 0.3), Err(NavError::OtherMap));
        assert_eq!(
            nav.find_path(other, a, v(2.5, 1.5), 0.3),
            Err(NavError::OtherMap)
        );
        assert_eq!(field.sync(&nav, other), Err(NavError::OtherMap));
        assert_eq!(field.distance(&nav, other, a), Err(NavError::OtherMap));
    }
    // A grid and field of the other map, used with this one's field and grid.
    let other_nav = NavGrid::new(&same_tiles, NavConfig::default()).unwrap();
    assert_eq!(field.sync(&other_nav, &same_tiles), Err(NavError::OtherMap));
    assert_eq!(
        field.distance(&other_nav, &same_tiles, a),
        Err(NavError::OtherMap)
    );
    // Still this map's, and catching up with it.
    map.clear_tile(Cell::new(3, 3)).unwrap();
    assert!(!nav.sync(&map).unwrap().is_empty());
    field.sync(&nav, &map).unwrap();
    assert!(field.distance(&nav, &map, a).unwrap().is_some());
    // A map dropped and another made in its place is still another map.
    let nav2 = NavGrid::new(&self::map(ROOM), NavConfig::default()).unwrap();
    let later = self::map(ROOM);
    assert_eq!(nav2.fits(&later, a, 0.3), Err(NavError::OtherMap));
}

/// A clone is its original as it was when cloned: a grid caught up with the original then
/// answers on the clone and catches up with the clone's edits. Once the two are edited
/// apart, a grid that has seen one's edits is refused by the other.
#[test]
fn a_clone_is_the_same_map_until_the_two_are_edited_apart() {
    let mut map = map(ROOM);
    let mut nav = NavGrid::new(&map, NavConfig::default()).unwrap();
    let a = v(1.5, 1.5);
    let mut clone = map.clone();
    assert!(
        nav.fits(&clone, a, 0.3).unwrap(),
        "an unedited clone is the map"
    );
    // Both edited, differently.
    map.clear_tile(Cell::new(3, 3)).unwrap();
    clone.set_tile(Cell::new(2, 1), Some(ascii::SOLID)).unwrap();
    // The grid has seen neither edit: it can catch up with either copy. A copy of it
    // follows the clone (as a worker thread would, with its own copies).
    let mut clone_nav = nav.clone();
    clone_nav.sync(&clone).unwrap();
    nav.sync(&map).unwrap();
    assert_same_moves(
        &clone_nav,
        &NavGrid::new(&clone, NavConfig::default()).unwrap(),
        &clone,
        "clone",
    );
    assert_same_moves(
        &nav,
        &NavGrid::new(&map, NavConfig::default()).unwrap(),
        &map,
        "original",
    );
    // Each grid has seen an edit the other copy never had.
    assert_eq!(nav.sync(&clone), Err(NavError::OtherMap));
    assert_eq!(nav.fits(&clone, a, 0.3), Err(NavError::OtherMap));
    assert_eq!(clone_nav.sync(&map), Err(NavError::OtherMap));
    // Flow fields follow the same rule.
    let mut field = FlowField::new(&nav, &map, v(5.5, 4.5), 0.3).unwrap();
    assert_eq!(field.sync(&clone_nav, &clone), Err(NavError::OtherMap));
    assert_eq!(field.sync(&nav, &map), Ok(false));
}

#[test]
fn unreachable_goals_and_ends_inside_walls_give_no_path() {
    let map = map("\
##########
#...#....#
#...#....#
#...#....#
##########");
    let nav = NavGrid::new(&map, NavConfig::default()).unwrap();
    let (left, right) = (v(2.0, 2.0), v(7.0, 2.0));
    assert_eq!(
        nav.find_path(&map, left, right, 0.3),
        Ok(None),
        "walled off"
    );
    assert_eq!(
        nav.find_path(&map, v(4.5, 2.0), left, 0.3),
        Ok(None),
        "start in a wall"
    );
    assert_eq!(
        nav.find_path(&map, left, v(4.5, 2.0), 0.3),
        Ok(None),
        "goal in a wall"
    );
    assert_eq!(
        nav.find_path(&map, v(1.1, 2.0), left, 0.3),
        Ok(None),
        "start too near a wall"
    );
    assert_eq!(
        nav.find_path(&map, left, v(2.0, 2.0), 1.0),
        Ok(None),
        "too wide to fit"
    );
    // A goal in a wall reaches nothing; neither does a point in the other room.
    let field = FlowField::new(&nav, &map, v(4.5, 2.0), 0.3).unwrap();
    assert_eq!(field.distance(&nav, &map, left), Ok(None));
    assert_eq!(field.direction(&nav, &map, left), Ok(None));
    let field = FlowField::new(&nav, &map, right, 0.3).unwrap();
    assert_eq!(field.distance(&nav, &map, left), Ok(None));
    assert_eq!(field.direction(&nav, &map, left), Ok(None));
    assert!(field.distance(&nav, &map, v(6.0, 3.0)).unwrap().is_some());
}

// ----------------------------------------------------------------------------------------
// One grid, shared

#[test]
fn searches_through_a_shared_grid_on_several_threads_find_what_one_thread_finds() {
    // `find_path` takes `&self`: a grid shared by reference across threads answers each
    // query as a lone search does, whatever the radii and order of the others.
    let text = "\
############
#..........#
#.####.###.#
#.#......#.#
#.#.####.#.#
#...#..#...#
#.#.#..#.#.#
#.#......#.#
#.####.###.#
#..........#
############";
    let map = map(text);
    let open: Vec<Vec2> = text
        .lines()
        .enumerate()
        .flat_map(|(row, line)| {
            line.chars()
                .enumerate()
                .filter(|&(_, c)| c == '.')
                .map(move |(col, _)| v(col as f32 + 0.5, row as f32 + 0.5))
        })
        .collect();
    let nav = NavGrid::new(&map, NavConfig::default()).unwrap();
    let mut rng = SplitMix64::new(22);
    let queries: Vec<(Vec2, Vec2, f32)> = (0..48)
        .map(|_| {
            let mut cell = || open[rng.below(open.len() as u64) as usize];
            let (a, b) = (cell(), cell());
            (a, b, [0.2, 0.3, 0.45][rng.below(3) as usize])
        })
        .collect();
    let alone: Vec<_> = queries
        .iter()
        .map(|&(a, b, r)| nav.clone().find_path(&map, a, b, r).unwrap())
        .collect();
    assert!(
        alone.iter().filter(|p| p.is_some()).count() > 4,
        "too few paths to compare"
    );
    let shared = &nav;
    let found: Vec<Vec<Option<NavPath>>> = std::thread::scope(|scope| {
        let workers: Vec<_> = (0..3)
            .map(|w| {
                let (map, queries) = (&map, &queries);
                scope.spawn(move || {
                    // Each worker runs the queries from a different place in the list.
                    (0..queries.len())
                        .map(|k| {
                            let (a, b, r) = queries[(k + 16 * w) % queries.len()];
                            shared.find_path(map, a, b, r).unwrap()
                        })
                        .collect()
                })
            })
            .collect();
        workers.into_iter().map(|w| w.join().unwrap()).collect()
    });
    for (w, paths) in found.iter().enumerate() {
        for (k, path) in paths.iter().enumerate() {
            assert_eq!(
                path,
                &alone[(k + 16 * w) % queries.len()],
                "worker {w}, query {k}"
            );
        }
    }
}

/// `FlowField::new_many` gives, in order, each field `FlowField::new` gives (and each
/// error): on dungeon256's 262,144 nodes, on 1, 2, 3 and 8 threads with the `parallel`
/// feature (the fields built side by side, and each field's open moves split across
/// threads), on the calling thread without it.
#[test]
fn fields_built_together_are_the_fields_built_one_by_one() {
    let map = tileslide_scenes::dungeon256().to_tile_map().unwrap();
    let nav = NavGrid::new(&map, NavConfig::default()).unwrap();
    let goals = [
        (v(128.5, 128.5), 0.3),
        (v(f32::NAN, 3.0), 0.3),
        (v(20.5, 200.5), 0.8),
        (v(240.0, 17.0), 0.3),
    ];
    let one_by_one: Vec<_> = goals
        .iter()
        .map(|&(goal, r)| FlowField::new(&nav, &map, goal, r))
        .collect();
    assert!(one_by_one[1].is_err());
    // (An error names the NaN it refused, and NaN equals nothing: errors compare by text.)
    let text = |fields: &[Result<FlowField, NavError>]| -> Vec<Result<FlowField, String>> {
        fields
            .iter()
            .map(|f| f.clone().map_err(|e| e.to_string()))
            .collect()
    };
    for threads in [1, 2, 3, 8] {
        let together = generators::on_threads(threads, || FlowField::new_many(&nav, &map, &goals));
        assert!(text(&together) == text(&one_by_one), "{threads} threads");
    }
}
