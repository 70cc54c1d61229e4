//! Bodies slide round what they touch. A body left in the gap band of a round obstacle
//! (another body, or a wall's rounded convex corner) or of a flat wall at any slope, as
//! `resolve` leaves it after a contact, and moving obliquely into it, slides along the
//! contact tangent instead of stopping: the write-up's slide, from any approach angle. Until
//! this was fixed, the slide itself was blocked at `t = 0` by the contact it slid off,
//! whenever its projection on the contact normal rounded negative (5–15 % of approach
//! angles round another body, about 8 % along a sloped wall), and crowds locked up.
//!
//! ```text
//!           motion (α into the normal)
//!             ↘
//!      ( mover )  ← within the gap band of →  ( still ) / ▛ corner
//!             ↓ slide along the tangent: at least |motion|·sin α
//! ```
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use tileslide::io::ascii;
use tileslide::{
    Bodies, BodyDesc, BodyShape, Owner, ResolveConfig, Segment, SegmentFlags, SlideMode,
    TemporarySegment, TileMap, Vec2,
};

/// A room with nothing in it: the still body stands at its centre, (6, 6).
const OPEN: &str = "\
############
#..........#
#..........#
#..........#
#..........#
#..........#
#..........#
#..........#
#..........#
#..........#
#..........#
############";

/// A room with one solid tile in the middle, x and y in [6, 7]: four convex corners.
const PILLAR: &str = "\
#############
#...........#
#...........#
#...........#
#...........#
#...........#
#.....#.....#
#...........#
#...........#
#...........#
#...........#
#...........#
#############";

fn map(text: &str) -> TileMap {
    ascii::parse(text, "bodies_slide.txt", 1.0).unwrap()
}

/// The gap band's width on these maps (cells of side 1).
fn gap() -> f32 {
    ResolveConfig::default().gap
}

/// The shortest resolved move a slide round the obstacle allows: the blocked move's part
/// along the tangent, `|motion|·sin α`, less what the resolver may leave out on the way. A
/// safe part before the contact shorter than an eighth of the gap is not taken (see
/// `MIN_STEP` in `bodies/resolver.rs`), and rounding.
fn least_slide(motion: Vec2, into: f32) -> f32 {
    motion.length() * into.sin() * (1.0 - 1e-4) - gap() / 8.0
}

/// A move of `length` leaning `into` radians into the contact normal `normal` (pointing
/// from the obstacle to the mover), to the left or right of it.
fn oblique(normal: Vec2, into: f32, left: bool, length: f32) -> Vec2 {
    let side = if left { normal.perp() } else { -normal.perp() };
    (-normal * into.cos() + side * into.sin()) * length
}

fn slide_mode() -> impl Strategy<Value = SlideMode> {
    prop_oneof![Just(SlideMode::FullLength), Just(SlideMode::Tangential)]
}

/// Distance from `p` to the pillar's tile, the square [6, 7]².
fn distance_to_pillar(p: Vec2) -> f32 {
    p.distance(p.clamp(Vec2::splat(6.0), Vec2::splat(7.0)))
}

/// How a lone body meets a wall: its radius, where in the gap band it starts (a fraction of
/// the band), how far it leans into the contact normal (20°–80°), to which side, how far it
/// moves, and the slide rule.
#[derive(Clone, Debug)]
struct Lean {
    radius: f32,
    band: f32,
    into: f32,
    left: bool,
    length: f32,
    slide: SlideMode,
}

fn lean() -> impl Strategy<Value = Lean> {
    (
        0.1f32..0.5,
        0.25f32..=1.0,
        20.0f32..=80.0,
        any::<bool>(),
        0.02f32..0.3,
        slide_mode(),
    )
        .prop_map(|(radius, band, into_degrees, left, length, slide)| Lean {
            radius,
            band,
            into: into_degrees.to_radians(),
            left,
            length,
            slide,
        })
}

/// A lone body in the gap band of the wall point `contact`, off it along `normal`, moving
/// as `lean` says (`clearance` gives a centre's distance from the wall): it moves at least
/// `|motion|·sin α`, ends at least its radius clear of the wall, and does not close in
/// beyond the band's inner edge.
fn lone_body_slides(
    map: &TileMap,
    contact: Vec2,
    normal: Vec2,
    lean: &Lean,
    clearance: impl Fn(Vec2) -> f32,
) -> Result<(), TestCaseError> {
    let Lean {
        radius,
        band,
        into,
        left,
        length,
        slide,
    } = *lean;
    let start = contact + normal * (radius + band * gap());
    let motion = oblique(normal, into, left, length);
    let mut bodies = Bodies::new();
    bodies
        .set_config(ResolveConfig {
            slide,
            ..ResolveConfig::default()
        })
        .unwrap();
    let a = bodies
        .add(BodyDesc::new(start, BodyShape::circle(radius).unwrap()))
        .unwrap();
    bodies.propose(a, motion).unwrap();
    let report = bodies.resolve(map);
    let moved = bodies.get(a).unwrap().resolved_move();
    prop_assert!(
        moved.length() >= least_slide(motion, into),
        "a body {} from a wall, moving {motion} ({}° into it), moved {moved}, less than {}: \
         {report:?}",
        clearance(start),
        into.to_degrees(),
        least_slide(motion, into)
    );
    bodies.integrate();
    let clear = clearance(bodies.get(a).unwrap().position());
    prop_assert!(clear >= radius, "in the wall: {clear} < {radius}");
    let floor = clearance(start).min(radius + gap() / 2.0) - 1e-5;
    prop_assert!(clear >= floor, "closed in to {clear}, under {floor}");
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2_000, ..ProptestConfig::default() })]

    /// Two bodies within the gap band of each other (from a quarter of it to all of it),
    /// at any approach angle, either slot order, and the mover leaning 20°–80° into the
    /// other: it moves at least `|motion|·sin α`, and they do not overlap afterwards (nor
    /// close in beyond the band's inner edge).
    #[test]
    fn a_body_moving_obliquely_into_one_it_touches_slides_round_it(
        approach in 0.0f32..std::f32::consts::TAU,
        (r_mover, r_still) in (0.1f32..0.5, 0.1f32..0.5),
        band in 0.25f32..=1.0,
        into_degrees in 20.0f32..=80.0,
        left: bool,
        length in 0.02f32..0.3,
        mover_first: bool,
        slide in slide_mode(),
    ) {
        let map = map(OPEN);
        let normal = Vec2::new(approach.cos(), approach.sin());
        let still = Vec2::new(6.0, 6.0);
        let contact = r_mover + r_still;
        let mover = still + normal * (contact + band * gap());
        let into = into_degrees.to_radians();
        let motion = oblique(normal, into, left, length);

        let mut bodies = Bodies::new();
        bodies.set_config(ResolveConfig { slide, ..ResolveConfig::default() }).unwrap();
        let mover_desc = BodyDesc::new(mover, BodyShape::circle(r_mover).unwrap());
        let still_desc = BodyDesc::new(still, BodyShape::circle(r_still).unwrap());
        let (a, b) = if mover_first {
            let a = bodies.add(mover_desc).unwrap();
            (a, bodies.add(still_desc).unwrap())
        } else {
            let b = bodies.add(still_desc).unwrap();
            (bodies.add(mover_desc).unwrap(), b)
        };
        bodies.propose(a, motion).unwrap();
        let report = bodies.resolve(&map);
        let moved = bodies.get(a).unwrap().resolved_move();
        prop_assert!(
            moved.length() >= least_slide(motion, into),
            "a body {} from one it touches, moving {motion} ({into_degrees}° into it), moved \
             {moved}, less than {}: {report:?}",
            mover.distance(still),
            least_slide(motion, into)
        );
        bodies.integrate();
        let (end, still_end) = (bodies.get(a).unwrap().position(), bodies.get(b).unwrap().position());
        prop_assert_eq!(still_end, still, "a body without a move moved");
        let apart = end.distance(still_end);
        prop_assert!(apart >= contact, "overlap: {apart} < {contact}");
        let floor = mover.distance(still).min(contact + gap() / 2.0) - 1e-5;
        prop_assert!(apart >= floor, "closed in to {apart}, under {floor}");
    }

    /// The same at a wall's rounded end: a body within the gap band of a convex corner of a
    /// pillar, seen from any direction in which the corner is the nearest point, leaning
    /// 20°–80° into it, moves at least `|motion|·sin α` and stays out of the pillar.
    #[test]
    fn a_body_moving_obliquely_into_a_convex_corner_it_touches_slides_round_it(
        corner in 0usize..4,
        around_degrees in 5.0f32..=85.0,
        lean in lean(),
    ) {
        let map = map(PILLAR);
        // The corner's outward quadrant: (sx, sy) from the pillar's centre.
        let (sx, sy) = [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)][corner];
        let corner_at = Vec2::new(6.5 + 0.5 * sx, 6.5 + 0.5 * sy);
        let around = around_degrees.to_radians();
        let normal = Vec2::new(sx * around.cos(), sy * around.sin());
        lone_body_slides(&map, corner_at, normal, &lean, distance_to_pillar)?;
    }

    /// The same along a flat wall at any slope: a body within the gap band of a long
    /// straight wall (a temporary segment through (6, 6), far from both its ends), leaning
    /// 20°–80° into it, moves at least `|motion|·sin α` along it and stays in front of it.
    /// Axis-aligned and 45° walls slide exactly; at other slopes the slide's lean into the
    /// wall is rounding noise, and for about 8 % of moves it used to stop the body dead.
    #[test]
    fn a_body_moving_obliquely_into_a_sloped_wall_it_touches_slides_along_it(
        slope in 0.0f32..std::f32::consts::TAU,
        lean in lean(),
    ) {
        let mut map = map(OPEN);
        let along = Vec2::new(slope.cos(), slope.sin());
        let through = Vec2::new(6.0, 6.0);
        map.add_temporary(TemporarySegment {
            segment: Segment::new(through - along * 4.0, through + along * 4.0),
            normal: along.perp(),
            flags: SegmentFlags::SOLID,
            owner: Owner(1),
            velocity: Vec2::ZERO,
        })
        .unwrap();
        let normal = along.perp();
        lone_body_slides(&map, through, normal, &lean, |p| (p - through).dot(normal))?;
    }
}

/// The crowd's pair and the two approach angles of `tests/path.rs`
/// (`a_body_touching_another_slides_round_it_when_moving_obliquely_into_it`), pinned here
/// with the resolver's own tests.
#[test]
fn the_crowd_pair_that_locked_up_slides_round() {
    let map = map(OPEN);
    let v = Vec2::new;
    let at_angle = |k: f32, separation: f32| {
        let a = k / 64.0 * std::f32::consts::TAU;
        let dir = v(a.cos(), a.sin());
        let still = v(6.0, 6.0);
        (
            still + dir * separation,
            still,
            (dir.perp() - dir).normalize() * 0.05,
        )
    };
    for (mover, still, motion) in [
        (
            // Shifted from (10.041976, 7.06332) and (9.649439, 7.517759) in the path test's
            // map, by a whole number of cells: the same float spacing.
            v(6.041976, 5.06332),
            v(5.649439, 5.517759),
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
            "a body at {mover} moving {motion} moved {moved}: {report:?}"
        );
    }
}

/// Thirteen bodies of a soak's crowd against the map's right-hand wall, as they were: one
/// (0.379 across) pressed between the wall and a neighbour, sliding up the wall along the
/// neighbour, where x's float spacing (1.5·10⁻⁵ at x = 135) is thirty times y's. The slide
/// leans 1 % away from the neighbour; each pass rounded that component away and kept the
/// rest, and the body crept into its neighbour by 6·10⁻⁶ a pass (8.9·10⁻⁵ deep here, the
/// soak found it past 10⁻⁴). A step never takes it deeper.
#[test]
fn a_body_sliding_up_a_wall_past_a_neighbour_never_creeps_into_it() {
    // The map's top right corner (columns 124 to 137 of 138), walled below.
    let corner = [
        "##############",
        "..../......#.#",
        ".#...##..#...#",
        "..\\.=#..#.#.##",
        "==\\..=//.#\\.\\#",
        "\\...../.=#./.#",
        "..#/#..#\\.=\\.#",
        ".#..#.\\.../..#",
        "...=#.//\\.\\#.#",
        ".=./....#.\\/.#",
    ];
    let mut text = String::new();
    for r in 0..12 {
        let mut row = vec!['.'; 138];
        if let Some(known) = corner.get(r) {
            for (k, ch) in known.chars().enumerate() {
                row[124 + k] = ch;
            }
        }
        if r == 0 || r >= 10 {
            row.fill('#');
        }
        row[0] = '#';
        row[137] = '#';
        text.extend(row);
        text.push('\n');
    }
    let map = ascii::parse(&text, "corner.txt", 1.0).unwrap();
    type Placed = ([f32; 2], &'static [(f32, f32, f32)], [f32; 2]);
    let crowd: [Placed; 13] = [
        (
            [135.02599, 4.2145634],
            &[(0.0, 0.0, 0.21513012)],
            [0.0041668676, -0.021524461],
        ),
        (
            [132.6923, 4.3076887],
            &[(0.0, 0.0, 0.30668867)],
            [0.13028097, 0.13071026],
        ),
        (
            [135.62, 4.220513],
            &[(0.0, 0.0, 0.37899864)],
            [-0.08367095, -0.095025465],
        ),
        (
            [132.4163, 4.769064],
            &[(0.0, 0.0, 0.22993597)],
            [0.09321738, 0.18390757],
        ),
        (
            [136.68756, 6.632388],
            &[(0.0, 0.0, 0.31143135)],
            [0.02022158, -0.2053808],
        ),
        (
            [136.62015, 5.9444036],
            &[(0.0, 0.0, 0.37934792)],
            [0.1117523, -0.003834198],
        ),
        (
            [136.67545, 2.651861],
            &[(0.0, 0.0, 0.31896925)],
            [-0.00018291063, -0.0011467215],
        ),
        (
            [136.3172, 5.3171935],
            &[(0.0, 0.0, 0.3161934)],
            [-0.12075085, 0.21510045],
        ),
        (
            [135.60974, 4.7741475],
            &[
                (-0.18409663, 0.0, 0.20028625),
                (0.18409663, 0.0, 0.20028625),
            ],
            [-0.025544884, 0.029532788],
        ),
        (
            [135.55937, 3.395568],
            &[(0.0, 0.0, 0.23458624)],
            [-0.04110718, -0.04627792],
        ),
        (
            [132.87143, 4.7043757],
            &[(0.0, 0.0, 0.12806496)],
            [0.12183955, -0.12694263],
        ),
        (
            [135.29572, 5.266896],
            &[(0.0, 0.0, 0.30877584)],
            [0.041568596, -0.039282214],
        ),
        (
            [134.2754, 5.72409],
            &[(0.0, 0.0, 0.27490976)],
            [-0.12503569, 0.14081633],
        ),
    ];
    let mut bodies = Bodies::new();
    let handles: Vec<_> = crowd
        .iter()
        .map(|(at, circles, proposed)| {
            let shape = BodyShape::compound(
                circles
                    .iter()
                    .map(|&(x, y, r)| tileslide::Circle::new(Vec2::new(x, y), r)),
            )
            .unwrap();
            let h = bodies.add(BodyDesc::new(Vec2::from(*at), shape)).unwrap();
            bodies.propose(h, Vec2::from(*proposed)).unwrap();
            h
        })
        .collect();
    // The pressed body (2) and its neighbour (0).
    let (r0, r2) = (crowd[0].1[0].2, crowd[2].1[0].2);
    let overlap = |b: &Bodies| {
        let (p, q) = (
            b.get(handles[0]).unwrap().position(),
            b.get(handles[2]).unwrap().position(),
        );
        r0 + r2 - p.distance(q)
    };
    let before = overlap(&bodies);
    assert!(before > 8e-5, "{before}");
    bodies.step(&map);
    let after = overlap(&bodies);
    assert!(
        after <= before,
        "{before} deep before the step, {after} after"
    );
}

/// The soak's second creep: a body sliding up a ramp at (110.69, 42.06), where x's float
/// spacing (7.6·10⁻⁶) is twice y's, on a slide that pressed it gently into the ramp. The
/// slide is tangent to the ramp, but each step's end rounded x and y the same way, and the
/// body crept into the ramp by 2.7·10⁻⁶ a step (9.9·10⁻⁵ deep here, past 10⁻⁴ in the soak).
/// No step takes it deeper, and rounding no longer takes it past the ramp's surface.
#[test]
fn a_body_sliding_along_a_ramp_never_creeps_into_it() {
    // The ramp '/' at column 110, row 42 (its face from (110, 43) to (111, 42)), and the
    // block above its top end.
    let mut text = String::new();
    for r in 0..43 {
        let mut row = vec!['.'; 112];
        match r {
            41 => row[111] = '#',
            42 => row[110] = '/',
            _ => {}
        }
        text.extend(row);
        text.push('\n');
    }
    let map = ascii::parse(&text, "ramp.txt", 1.0).unwrap();
    let radius = 0.17561081;
    let mut bodies = Bodies::new();
    let h = bodies
        .add(BodyDesc::new(
            Vec2::new(110.6872, 42.064587),
            BodyShape::circle(radius).unwrap(),
        ))
        .unwrap();
    let normal = Vec2::new(-1.0, -1.0).normalize();
    let depth = |b: &Bodies| {
        let p = b.get(h).unwrap().position();
        radius - (p - Vec2::new(111.0, 42.0)).dot(normal)
    };
    let start = depth(&bodies);
    assert!(start > 9.9e-5, "{start}");
    for step in 0..60 {
        bodies
            .propose(h, Vec2::new(0.0009268843, -0.0006820779))
            .unwrap();
        let before = depth(&bodies);
        bodies.step(&map);
        let after = depth(&bodies);
        // Into the ramp, never deeper; clear of it, rounding may bring it up to the ramp.
        assert!(
            after <= before.max(0.0),
            "step {step}: {before} deep before, {after} after"
        );
    }
    // It slid on, up the ramp, and out to its surface.
    assert!(bodies.get(h).unwrap().position().x > 110.72);
    assert!(depth(&bodies) <= 0.0, "{}", depth(&bodies));
}
