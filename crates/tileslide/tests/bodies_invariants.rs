//! The resolver's invariants, over thousands of random scenes: random ASCII maps with ramps
//! and one-way platforms, crowds of circles and compound bodies of random sizes, and moves
//! of up to several cells per step. After **every** step:
//!
//! - no two bodies overlap by more than `SKIN` (1e-4 cell);
//! - no circle penetrates a solid front face by more than `SKIN`, and no centre is inside a
//!   solid tile;
//! - nothing passed through a wall: on maps of whole cells, every body is still in the
//!   room (4-connected empty region) it started in, whatever its speed;
//! - bodies without a move did not move.
//!
//! And two runs of the same scene give bit-identical positions, and a resolver that
//! remembers its last step (to skip bodies blocked in place again) moves every body exactly
//! as one without memory, whatever happens between steps.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use crate::generators;

use generators::{tile_chars, tile_map, wall_in};
use proptest::prelude::*;
use tileslide::io::ascii;
use tileslide::{
    Bodies, BodyDesc, BodyError, BodyFilter, BodyHandle, BodyShape, Cell, Circle, Owner,
    ResolveConfig, Segment, SegmentFlags, SlideMode, TemporarySegment, TileMap, Vec2,
    broadphase::PairMethod,
};

/// Largest overlap allowed after a step, in cells (the skin).
const SKIN: f32 = 1e-4;

/// Characters of a random map's interior and their weights.
fn map_strategy(ramps: bool) -> impl Strategy<Value = (u32, u32, Vec<char>)> {
    (6u32..14, 6u32..14).prop_flat_map(move |(w, h)| {
        let mix: &[(u32, char)] = if ramps {
            &[(14, '.'), (3, '#'), (1, '/'), (1, '\\'), (1, '=')]
        } else {
            &[(5, '.'), (1, '#')]
        };
        tile_chars(mix, (w * h) as usize).prop_map(move |mut chars| {
            wall_in(w, &mut chars);
            (w, h, chars)
        })
    })
}

/// Every active segment of the map: (a, b, normal, flags).
fn all_segments(map: &TileMap) -> Vec<(Vec2, Vec2, Vec2, SegmentFlags)> {
    let mut out = Vec::new();
    for r in 0..map.height() {
        for c in 0..map.width() {
            for s in map.active_segments(tileslide::Cell::new(c, r)) {
                out.push((s.segment.a, s.segment.b, s.normal, s.flags));
            }
        }
    }
    out
}

fn distance_to_segment(p: Vec2, a: Vec2, b: Vec2) -> f32 {
    tileslide::Segment::new(a, b).distance_squared_to(p).sqrt()
}

/// A body proposal: position, shape (one circle or a pair), and a move per step.
#[derive(Clone, Debug)]
struct Proposal {
    position: Vec2,
    circles: Vec<Circle>,
    moves: Vec<Vec2>,
}

fn proposals(steps: usize, max_speed: f32) -> impl Strategy<Value = Vec<Proposal>> {
    let one = (
        0.0f32..1.0,
        0.0f32..1.0,
        0.08f32..0.45,
        prop::option::weighted(0.2, (-0.5f32..0.5, -0.5f32..0.5, 0.08f32..0.3)),
        prop::collection::vec(
            prop_oneof![
                1 => Just(Vec2::ZERO),
                4 => (-1.0f32..1.0, -1.0f32..1.0).prop_map(|(x, y)| Vec2::new(x, y)),
            ],
            steps,
        ),
    )
        .prop_map(move |(x, y, r, second, moves)| {
            let mut circles = vec![Circle::new(Vec2::ZERO, r)];
            if let Some((ox, oy, r2)) = second {
                circles.push(Circle::new(Vec2::new(ox, oy), r2));
            }
            Proposal {
                position: Vec2::new(x, y),
                circles,
                moves: moves.into_iter().map(|m| m * max_speed).collect(),
            }
        });
    prop::collection::vec(one, 10..120)
}

/// A dense crowd in a corridor one to three cells wide with bends: bodies packed on a
/// lattice, all pushing the same general way (so they queue, jostle and slide).
fn corridor_strategy() -> impl Strategy<Value = (u32, u32, Vec<char>, Vec<Proposal>)> {
    (1u32..4, 12u32..24, -1.0f32..1.0, 0.1f32..0.4).prop_flat_map(|(width, length, lean, r)| {
        let (w, h) = (length + 2, width + 6);
        let mut chars = vec!['#'; (w * h) as usize];
        for c in 1..w - 1 {
            // The corridor steps down one row halfway: a bend with concave and convex corners.
            let top = if c < w / 2 { 2 } else { 3 };
            for row in top..top + width {
                chars[(row * w + c) as usize] = '.';
            }
        }
        let moves = prop::collection::vec(
            (0.5f32..1.5, -0.6f32..0.6)
                .prop_map(move |(x, y)| Vec2::new(x * 0.3, (y + lean * 0.5) * 0.3)),
            STEPS,
        );
        prop::collection::vec(moves, 60).prop_map(move |all| {
            let mut proposals = Vec::new();
            for (k, moves) in all.into_iter().enumerate() {
                let (col, row) = (k % 30, k / 30);
                proposals.push(Proposal {
                    position: Vec2::new(
                        (1.0 + (col as f32 + 0.5) * (2.0 * r + 0.02)) / w as f32,
                        (2.0 + (row as f32 + 0.5) * (2.0 * r + 0.02)) / h as f32,
                    ),
                    circles: vec![Circle::new(Vec2::ZERO, r)],
                    moves,
                });
            }
            (w, h, chars.clone(), proposals)
        })
    })
}

/// Places the proposals (positions given as fractions of the map) that fit: clear of
/// every segment by a margin, not in a solid, not overlapping a body already placed.
fn place(map: &TileMap, proposals: &[Proposal]) -> (Bodies, Vec<(BodyHandle, Proposal)>) {
    let segments = all_segments(map);
    let mut bodies = Bodies::new();
    let mut placed: Vec<(BodyHandle, Proposal)> = Vec::new();
    let size = Vec2::new(map.width() as f32, map.height() as f32);
    for p in proposals {
        let position = p.position * size;
        let fits = p.circles.iter().all(|c| {
            let at = position + c.center;
            !map.is_point_solid(at)
                && at.cmpgt(Vec2::ZERO).all()
                && at.cmplt(size).all()
                && segments
                    .iter()
                    .all(|&(a, b, _, _)| distance_to_segment(at, a, b) > c.radius + 0.01)
                && placed.iter().all(|(h, q)| {
                    let other = bodies.get(*h).unwrap().position();
                    q.circles
                        .iter()
                        .all(|d| (other + d.center).distance(at) > c.radius + d.radius + 0.01)
                })
        });
        if fits {
            let shape = BodyShape::compound(p.circles.iter().copied()).unwrap();
            let h = bodies.add(BodyDesc::new(position, shape)).unwrap();
            placed.push((h, p.clone()));
        }
    }
    (bodies, placed)
}

/// Checks the invariants after a step; `before` are the positions before it.
fn check_step(
    map: &TileMap,
    bodies: &Bodies,
    placed: &[(BodyHandle, Proposal)],
    step: usize,
    before: &[Vec2],
) -> Result<(), TestCaseError> {
    let segments = all_segments(map);
    let circles: Vec<(usize, Vec2, f32)> = placed
        .iter()
        .enumerate()
        .flat_map(|(i, (h, p))| {
            let at = bodies.get(*h).unwrap().position();
            p.circles.iter().map(move |c| (i, at + c.center, c.radius))
        })
        .collect();
    for (k, &(i, c, r)) in circles.iter().enumerate() {
        prop_assert!(
            !map.is_point_solid(c),
            "step {step}: body {i} centre {c} is in a solid"
        );
        for &(a, b, n, flags) in &segments {
            if flags.contains(SegmentFlags::ONE_WAY) || (c - a).dot(n) < 0.0 {
                continue;
            }
            let d = distance_to_segment(c, a, b);
            prop_assert!(
                d >= r - SKIN,
                "step {step}: body {i} (r {r}) at {c} penetrates {a}->{b} by {}",
                r - d
            );
        }
        for &(j, c2, r2) in &circles[k + 1..] {
            if i == j {
                continue;
            }
            let d = c.distance(c2);
            prop_assert!(
                d >= r + r2 - SKIN,
                "step {step}: bodies {i} and {j} overlap by {}",
                r + r2 - d
            );
        }
    }
    for (i, (h, p)) in placed.iter().enumerate() {
        if p.moves[step] == Vec2::ZERO {
            prop_assert_eq!(
                bodies.get(*h).unwrap().position(),
                before[i],
                "body {} had no move but moved",
                i
            );
        }
    }
    Ok(())
}

fn positions(bodies: &Bodies, placed: &[(BodyHandle, Proposal)]) -> Vec<Vec2> {
    placed
        .iter()
        .map(|(h, _)| bodies.get(*h).unwrap().position())
        .collect()
}

fn run(
    map: &TileMap,
    proposals: &[Proposal],
    steps: usize,
    config: ResolveConfig,
    mut after_step: impl FnMut(
        &Bodies,
        &[(BodyHandle, Proposal)],
        usize,
        &[Vec2],
    ) -> Result<(), TestCaseError>,
) -> Result<Vec<Vec2>, TestCaseError> {
    let (mut bodies, placed) = place(map, proposals);
    bodies.set_config(config).unwrap();
    for step in 0..steps {
        let before = positions(&bodies, &placed);
        for (h, p) in &placed {
            bodies.propose(*h, p.moves[step]).unwrap();
        }
        bodies.step(map);
        after_step(&bodies, &placed, step, &before)?;
    }
    Ok(positions(&bodies, &placed))
}

/// 4-connected regions of empty cells; `None` for solid cells.
fn regions(w: u32, h: u32, chars: &[char]) -> Vec<Option<u32>> {
    let mut label = vec![None; chars.len()];
    let mut next = 0;
    for start in 0..chars.len() {
        if chars[start] != '.' || label[start].is_some() {
            continue;
        }
        let mut stack = vec![start];
        label[start] = Some(next);
        while let Some(i) = stack.pop() {
            let (c, r) = ((i as u32) % w, (i as u32) / w);
            let around = [
                (c.wrapping_sub(1), r),
                (c + 1, r),
                (c, r.wrapping_sub(1)),
                (c, r + 1),
            ];
            for (nc, nr) in around {
                if nc < w && nr < h {
                    let j = (nr * w + nc) as usize;
                    if chars[j] == '.' && label[j].is_none() {
                        label[j] = Some(next);
                        stack.push(j);
                    }
                }
            }
        }
        next += 1;
    }
    label
}

const STEPS: usize = 6;

/// Steps of the memory model test: long enough for crowds to jam against walls.
const JAM_STEPS: usize = 16;

/// Something that happens between two steps of the memory model test (fractions pick the
/// body, the cell or the place).
#[derive(Clone, Debug)]
enum Event {
    Nothing,
    /// A body jumps somewhere else.
    Teleport(f32, f32, f32),
    /// A cell of the map becomes solid or empty.
    Edit(f32, f32, bool),
    /// The temporary segments are cleared and one is submitted at a place (solid, or a
    /// one-way platform), as a moving platform is each frame.
    Platform(f32, f32, bool),
    /// The temporary segments are cleared and the same ones submitted again.
    Resubmit,
    Remove(f32),
    /// A body proposes no move this step.
    Pause(f32),
    /// A body stops colliding with the others.
    Ghost(f32),
    /// Resolve without integrating: the next resolve starts from the same positions.
    NoIntegrate,
    /// Fewer passes.
    Config,
    /// A body's move this step ends at a point of the `MAX_COORD` square (fractions from
    /// one corner to the other).
    Fling(f32, f32, f32),
    /// A body jumps to a point of the `MAX_COORD` square.
    Far(f32, f32, f32),
    /// A body of radius `MAX_COORD` times a fraction joins, in the map, pushing right.
    Giant(f32, f32, f32),
    /// A call with a value beyond the limits, which must be refused (which call, and the
    /// body).
    Absurd(u8, f32),
    /// The gap becomes this fraction of the largest.
    Gap(f32),
    /// The temporary segments are cleared and a wall is submitted near a point of the
    /// `MAX_COORD` square, where `Far` and `Fling` send bodies.
    FarWall(f32, f32),
}

/// Ends of a fraction's range, as likely as the values between.
fn fraction() -> impl Strategy<Value = f32> {
    prop_oneof![Just(0.0f32), Just(1.0f32), 0.0f32..1.0]
}

/// Events at the limits of what is accepted, and beyond (see
/// `memory_never_changes_a_result_at_the_limits`).
fn extreme_events() -> impl Strategy<Value = Vec<Event>> {
    let unit = || 0.0f32..1.0;
    let one = prop_oneof![
        6 => Just(Event::Nothing),
        1 => (unit(), unit(), unit()).prop_map(|(k, x, y)| Event::Teleport(k, x, y)),
        3 => (unit(), fraction(), fraction()).prop_map(|(k, x, y)| Event::Fling(k, x, y)),
        2 => (unit(), fraction(), fraction()).prop_map(|(k, x, y)| Event::Far(k, x, y)),
        1 => (unit(), unit(), fraction()).prop_map(|(x, y, r)| Event::Giant(x, y, r)),
        3 => (0u8..ABSURD_CALLS, unit()).prop_map(|(which, k)| Event::Absurd(which, k)),
        1 => fraction().prop_map(Event::Gap),
        2 => (fraction(), fraction()).prop_map(|(x, y)| Event::FarWall(x, y)),
        1 => (unit(), unit(), any::<bool>()).prop_map(|(x, y, s)| Event::Edit(x, y, s)),
        1 => Just(Event::NoIntegrate),
    ];
    prop::collection::vec(one, JAM_STEPS)
}

/// How many kinds of refused call `Event::Absurd` makes.
const ABSURD_CALLS: u8 = 8;

/// A point of the `MAX_COORD` square, from fractions of its side.
fn in_square(x: f32, y: f32) -> Vec2 {
    (Vec2::new(x, y) * 2.0 - Vec2::ONE) * tileslide::limits::MAX_COORD
}

/// Whether an error is the one expected.
type ErrorCheck = Box<dyn Fn(&BodyError) -> bool>;

/// Makes refused call `which` on `handle`'s body; checks that it is refused with the right
/// error and that the body and the settings are as they were.
fn absurd_call(bodies: &mut Bodies, handle: BodyHandle, which: u8) -> Result<(), TestCaseError> {
    use tileslide::limits::MAX_COORD;
    let before = bodies.get(handle).unwrap().clone();
    let config = *bodies.config();
    let far = |what: &'static str| move |e: &BodyError| matches!(e, BodyError::OutOfRange { what: w, .. } if *w == what);
    let end = "move's end point";
    let (result, expected): (Result<(), BodyError>, ErrorCheck) = match which {
        0 => (
            bodies.propose(handle, Vec2::new(1e20, 0.0)),
            Box::new(far(end)),
        ),
        1 => (
            bodies.propose(handle, Vec2::new(0.0, -3e38)),
            Box::new(far(end)),
        ),
        2 => {
            let beyond = Vec2::new(2.0 * MAX_COORD, -2.0 * MAX_COORD) - before.position();
            (bodies.propose(handle, beyond), Box::new(far(end)))
        }
        3 => (
            bodies.propose(handle, Vec2::new(f32::NAN, 0.0)),
            Box::new(|e: &BodyError| matches!(e, BodyError::NonFinite { .. })),
        ),
        4 => (
            bodies.set_position(handle, Vec2::new(5.0, 1e20)),
            Box::new(far("position")),
        ),
        5 => (
            bodies.set_position(handle, Vec2::new(-MAX_COORD * 1.0001, 0.0)),
            Box::new(far("position")),
        ),
        6 => {
            let radius = [f32::MAX, MAX_COORD * 1.0001, f32::INFINITY, f32::NAN];
            for r in radius {
                let shape = BodyShape::circle(r);
                prop_assert!(
                    matches!(shape, Err(BodyError::InvalidRadius { .. })),
                    "radius {} accepted",
                    r
                );
            }
            let offset = Circle::new(Vec2::new(0.0, 3e38), 0.5);
            (
                BodyShape::compound([offset]).map(|_| ()),
                Box::new(|e: &BodyError| matches!(e, BodyError::InvalidOffset { .. })),
            )
        }
        _ => {
            for gap in [
                f32::INFINITY,
                f32::NAN,
                2.4e24,
                -1e-3,
                ResolveConfig::MAX_GAP * 1.01,
            ] {
                let refused = bodies.set_config(ResolveConfig { gap, ..config });
                prop_assert!(
                    matches!(refused, Err(BodyError::BadConfig { field: "gap", .. })),
                    "gap {} accepted",
                    gap
                );
            }
            (
                bodies.set_config(ResolveConfig {
                    passes: u32::MAX,
                    ..config
                }),
                Box::new(|e: &BodyError| {
                    matches!(
                        e,
                        BodyError::BadConfig {
                            field: "passes",
                            ..
                        }
                    )
                }),
            )
        }
    };
    match result {
        Err(e) => prop_assert!(expected(&e), "call {}: wrong error {:?}", which, e),
        Ok(()) => prop_assert!(false, "call {} was accepted", which),
    }
    prop_assert_eq!(
        bodies.get(handle).unwrap(),
        &before,
        "call {} changed the body",
        which
    );
    prop_assert_eq!(
        bodies.config(),
        &config,
        "call {} changed the settings",
        which
    );
    Ok(())
}

fn events() -> impl Strategy<Value = Vec<Event>> {
    let unit = || 0.0f32..1.0;
    let one = prop_oneof![
        12 => Just(Event::Nothing),
        1 => (unit(), unit(), unit()).prop_map(|(k, x, y)| Event::Teleport(k, x, y)),
        2 => (unit(), unit(), any::<bool>()).prop_map(|(x, y, s)| Event::Edit(x, y, s)),
        1 => (unit(), unit(), any::<bool>()).prop_map(|(x, y, s)| Event::Platform(x, y, s)),
        1 => Just(Event::Resubmit),
        1 => unit().prop_map(Event::Remove),
        1 => unit().prop_map(Event::Pause),
        1 => unit().prop_map(Event::Ghost),
        1 => Just(Event::NoIntegrate),
        1 => Just(Event::Config),
    ];
    prop::collection::vec(one, JAM_STEPS)
}

/// Index `k` (a fraction) of a list of `len` > 0.
fn pick(k: f32, len: usize) -> usize {
    ((k * len as f32) as usize).min(len - 1)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    /// Crowds on maps with ramps and one-way platforms, moves up to a cell per step.
    #[test]
    fn no_overlap_no_penetration_no_motion_without_a_move(
        (w, _, chars) in map_strategy(true),
        proposals in proposals(STEPS, 1.0),
        tangential in any::<bool>(),
        sap in any::<bool>(),
    ) {
        let map = tile_map(w, &chars, 1.0, Vec2::ZERO);
        let config = ResolveConfig {
            slide: if tangential { SlideMode::Tangential } else { SlideMode::FullLength },
            broadphase: if sap { PairMethod::SweepAndPrune } else { PairMethod::UniformGrid },
            ..ResolveConfig::default()
        };
        run(&map, &proposals, STEPS, config, |bodies, placed, step, before| {
            check_step(&map, bodies, placed, step, before)
        })?;
    }

    /// Dense crowds queueing through a bending corridor.
    #[test]
    fn dense_crowds_in_a_corridor_never_overlap((w, _, chars, proposals) in corridor_strategy()) {
        let map = tile_map(w, &chars, 1.0, Vec2::ZERO);
        run(&map, &proposals, STEPS, ResolveConfig::default(), |bodies, placed, step, before| {
            check_step(&map, bodies, placed, step, before)
        })?;
    }

    /// Fast bodies (up to 6 cells a step) on maps of one-cell walls never leave their room.
    #[test]
    fn nothing_passes_through_a_wall_at_any_speed(
        (w, h, chars) in map_strategy(false),
        proposals in proposals(STEPS, 6.0),
    ) {
        let map = tile_map(w, &chars, 1.0, Vec2::ZERO);
        let label = regions(w, h, &chars);
        let room = |p: Vec2| label[(p.y as u32 * w + p.x as u32) as usize];
        let (bodies, placed) = place(&map, &proposals);
        let start: Vec<_> = positions(&bodies, &placed).into_iter().map(room).collect();
        run(&map, &proposals, STEPS, ResolveConfig::default(), |bodies, placed, step, before| {
            check_step(&map, bodies, placed, step, before)?;
            for (i, p) in positions(bodies, placed).into_iter().enumerate() {
                prop_assert_eq!(room(p), start[i], "step {}: body {} left its room", step, i);
            }
            Ok(())
        })?;
    }

    /// The same inputs give bit-identical positions, whichever broadphase finds the pairs.
    #[test]
    fn identical_inputs_give_identical_positions(
        (w, _, chars) in map_strategy(true),
        proposals in proposals(STEPS, 1.0),
    ) {
        let map = tile_map(w, &chars, 1.0, Vec2::ZERO);
        let ok = |_: &Bodies, _: &[(BodyHandle, Proposal)], _: usize, _: &[Vec2]| Ok(());
        let a = run(&map, &proposals, STEPS, ResolveConfig::default(), ok)?;
        let b = run(&map, &proposals, STEPS, ResolveConfig::default(), ok)?;
        let sap = ResolveConfig { broadphase: PairMethod::SweepAndPrune, ..ResolveConfig::default() };
        let c = run(&map, &proposals, STEPS, sap, ok)?;
        // And on any number of threads (the `parallel` feature).
        let one = generators::on_threads(1, || run(&map, &proposals, STEPS, ResolveConfig::default(), ok))?;
        let three = generators::on_threads(3, || run(&map, &proposals, STEPS, ResolveConfig::default(), ok))?;
        let bits = |v: &[Vec2]| v.iter().map(|p| (p.x.to_bits(), p.y.to_bits())).collect::<Vec<_>>();
        prop_assert_eq!(bits(&a), bits(&b));
        prop_assert_eq!(bits(&a), bits(&c));
        prop_assert_eq!(bits(&a), bits(&one));
        prop_assert_eq!(bits(&a), bits(&three));
    }

    /// Bodies with constant moves jam against walls and each other, so the resolver skips
    /// those blocked in place again; between steps, bodies jump, pause, vanish or turn into
    /// ghosts, the map is edited (tiles, and temporary segments moved or submitted again)
    /// and settings change. Every step, each resolved move and
    /// the report are bit-identical to those of a fresh resolver without memory (no settled
    /// bodies, no walls kept near each circle, no neighbour candidates kept from earlier
    /// steps).
    #[test]
    fn settled_bodies_move_exactly_as_without_memory(
        (w, h, chars) in map_strategy(true),
        proposals in proposals(1, 0.7),
        events in events(),
        sap in any::<bool>(),
    ) {
        same_as_without_memory(w, h, &chars, &proposals, &events, sap)?;
    }

    /// The same model test at the limits of what is accepted, with the refused calls in
    /// between: moves to the far corners of the `MAX_COORD` square (a body crossing the
    /// whole map and beyond in one step), teleports far away and back, bodies of radius up
    /// to `MAX_COORD`, the largest and smallest gaps; and moves, positions, radii and gaps
    /// beyond the limits (1e20, 3e38, NaN, infinity), each of which must be refused and
    /// leave everything as it was. The memory of absurd steps must not change a later
    /// result (a body flung through a floor once used to leave wall lists behind that let
    /// every later body through).
    #[test]
    fn memory_never_changes_a_result_at_the_limits(
        (w, h, chars) in map_strategy(true),
        proposals in proposals(1, 0.7),
        events in extreme_events(),
        sap in any::<bool>(),
    ) {
        same_as_without_memory(w, h, &chars, &proposals, &events, sap)?;
    }
}

/// The memory model test: runs `events` between the steps of a crowd with constant moves,
/// and checks every step's resolved moves and report against a fresh resolver's.
fn same_as_without_memory(
    w: u32,
    h: u32,
    chars: &[char],
    proposals: &[Proposal],
    events: &[Event],
    sap: bool,
) -> Result<(), TestCaseError> {
    let mut map = tile_map(w, chars, 1.0, Vec2::ZERO);
    let (mut bodies, placed) = place(&map, proposals);
    let mut config = ResolveConfig {
        broadphase: if sap {
            PairMethod::SweepAndPrune
        } else {
            PairMethod::UniformGrid
        },
        ..ResolveConfig::default()
    };
    bodies.set_config(config).unwrap();
    let mut live: Vec<(BodyHandle, Vec2)> = placed.iter().map(|(h, p)| (*h, p.moves[0])).collect();
    let moves = |b: &Bodies| {
        b.iter()
            .map(|(_, b)| (b.resolved_move().x.to_bits(), b.resolved_move().y.to_bits()))
            .collect::<Vec<_>>()
    };
    for (step, event) in events.iter().enumerate() {
        let mut paused = None;
        let mut flung = None;
        let mut integrate = true;
        match *event {
            Event::Nothing => {}
            Event::Teleport(k, x, y) if !live.is_empty() => {
                let to = Vec2::new(x * w as f32, y * h as f32);
                bodies
                    .set_position(live[pick(k, live.len())].0, to)
                    .unwrap();
            }
            Event::Edit(x, y, solid) => {
                let cell = Cell::new(pick(x, w as usize) as u32, pick(y, h as usize) as u32);
                let id = ascii::tile_for_char(if solid { '#' } else { '.' }).unwrap();
                map.set_tile(cell, id).unwrap();
            }
            Event::Platform(x, y, solid) => {
                map.clear_temporaries();
                let a = Vec2::new(x * w as f32, y * h as f32);
                map.add_temporary(TemporarySegment {
                    segment: Segment::new(a, a + Vec2::new(1.5, 0.25)),
                    normal: Vec2::new(-0.25, 1.5),
                    flags: if solid {
                        SegmentFlags::SOLID
                    } else {
                        SegmentFlags::ONE_WAY
                    },
                    owner: Owner(1),
                    velocity: Vec2::ZERO,
                })
                .unwrap();
            }
            Event::Resubmit => {
                let again = map.temporaries().to_vec();
                map.clear_temporaries();
                for t in again {
                    map.add_temporary(t).unwrap();
                }
            }
            Event::Remove(k) if !live.is_empty() => {
                let (handle, _) = live.remove(pick(k, live.len()));
                bodies.remove(handle).unwrap();
            }
            Event::Pause(k) if !live.is_empty() => paused = Some(pick(k, live.len())),
            Event::Ghost(k) if !live.is_empty() => {
                let ghost = BodyFilter {
                    groups: 2,
                    collides_with: 2,
                    ..BodyFilter::default()
                };
                bodies
                    .set_filter(live[pick(k, live.len())].0, ghost)
                    .unwrap();
            }
            Event::NoIntegrate => integrate = false,
            Event::Config => {
                config.passes = config.passes.saturating_sub(1).max(1);
                bodies.set_config(config).unwrap();
            }
            Event::Fling(k, x, y) if !live.is_empty() => {
                flung = Some((pick(k, live.len()), in_square(x, y)))
            }
            Event::Far(k, x, y) if !live.is_empty() => {
                bodies
                    .set_position(live[pick(k, live.len())].0, in_square(x, y))
                    .unwrap();
            }
            Event::Giant(x, y, r) => {
                let radius = (r * tileslide::limits::MAX_COORD).max(0.5);
                let at = Vec2::new(x * w as f32, y * h as f32);
                let giant = BodyDesc::new(at, BodyShape::circle(radius).unwrap());
                live.push((bodies.add(giant).unwrap(), Vec2::new(0.6, -0.1)));
            }
            Event::Absurd(which, k) if !live.is_empty() => {
                absurd_call(&mut bodies, live[pick(k, live.len())].0, which)?;
            }
            Event::FarWall(x, y) => {
                map.clear_temporaries();
                // Two cells inward from the point, across the way bodies come from the map.
                let p = in_square(x, y);
                let a = p - p.signum() * 2.0;
                map.add_temporary(TemporarySegment {
                    segment: Segment::new(a - Vec2::new(3.0, -3.0), a + Vec2::new(3.0, -3.0)),
                    normal: -p.signum(),
                    flags: SegmentFlags::SOLID,
                    owner: Owner(2),
                    velocity: Vec2::ZERO,
                })
                .unwrap();
            }
            Event::Gap(g) => {
                config.gap = g * ResolveConfig::MAX_GAP;
                bodies.set_config(config).unwrap();
            }
            _ => {}
        }
        for (i, (handle, motion)) in live.iter().enumerate() {
            let motion = if paused == Some(i) {
                Vec2::ZERO
            } else {
                *motion
            };
            let position = bodies.get(*handle).unwrap().position();
            let motion = match flung {
                Some((f, to)) if f == i => to - position,
                _ => motion,
            };
            if let Err(e) = bodies.propose(*handle, motion) {
                // A move from far away can end beyond the square (its end point is refused,
                // with the move unchanged): no move this step.
                prop_assert!(
                    !tileslide::limits::MAX_COORD.ge(&(position + motion).abs().max_element()),
                    "{}",
                    e
                );
                bodies.propose(*handle, Vec2::ZERO).unwrap();
            }
        }
        let mut fresh = Bodies::with_config(config).unwrap();
        for (_, b) in bodies.iter() {
            let desc = BodyDesc::new(b.position(), b.shape().clone()).with_filter(b.filter());
            let handle = fresh.add(desc).unwrap();
            fresh.propose(handle, b.proposed_move()).unwrap();
        }
        // With the `parallel` feature, the fresh resolver on one thread (in slot order) and
        // the one with memory on two, three or eight (in waves).
        let expected = generators::on_threads(1, || fresh.resolve(&map));
        let threads = [2, 3, 8][step % 3];
        let got = generators::on_threads(threads, || bodies.resolve(&map));
        prop_assert_eq!(got, expected, "step {}: report", step);
        prop_assert_eq!(
            moves(&bodies),
            moves(&fresh),
            "step {}: resolved moves",
            step
        );
        if integrate {
            bodies.integrate();
        }
    }
    Ok(())
}
