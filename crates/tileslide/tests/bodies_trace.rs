//! The resolver's trace against hand-checked scenes: what each pass met, where it came
//! from, and what the resolver did with it; and that tracing changes no result.
//!
//! ```text
//!   seam: ##|##       corner: ...#       head-on:  A→  ←B
//!   a body sliding    a body pushed      two bodies meet
//!   over it meets     into it slides     on the line of their
//!   only the tops     along the floor    centres and turn
//!                     and stops there    opposite ways
//! ```
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use tileslide::io::ascii;
use tileslide::{
    Bodies, BodyDesc, BodyFate, BodyHandle, BodyShape, Cell, ContactPart, ContactSource, PassTrace,
    ResolveTrace, Response, TileMap, Vec2, WallSource,
};

fn map(text: &str) -> TileMap {
    ascii::parse(text, "trace.txt", 1.0).unwrap()
}

fn add(bodies: &mut Bodies, at: Vec2, radius: f32) -> BodyHandle {
    bodies
        .add(BodyDesc::new(at, BodyShape::circle(radius).unwrap()))
        .unwrap()
}

/// The tile segment a contact came from, or a panic naming the contact.
fn tile_of(source: ContactSource) -> (Cell, u32) {
    match source {
        ContactSource::Wall(WallSource::Tile { segment, .. }) => (segment.cell, segment.index),
        other => panic!("not a tile segment: {other:?}"),
    }
}

/// A floor of five blocks (row 2) under open space: the seams between the blocks are
/// hidden, and the floor's top is one flat surface.
const FLOOR: &str = "\
.......
.......
#######";

#[test]
fn a_circle_sliding_over_floor_seams_meets_only_the_floor_tops() {
    let m = map(FLOOR);
    let mut bodies = Bodies::new();
    // Resting on the floor (y = 2) within the gap band, it is pushed right and a little
    // down, across the seams at x = 2, 3 and 4.
    let ball = add(&mut bodies, Vec2::new(1.5, 2.0 - 0.4 - 0.0008), 0.4);
    let mut trace = ResolveTrace::of(ball);
    let mut contacts = 0;
    for _ in 0..6 {
        bodies.propose(ball, Vec2::new(0.5, 0.05)).unwrap();
        bodies.step_traced(&m, &mut trace);
        let story = trace.body(ball).unwrap();
        assert_eq!(story.fate, BodyFate::Resolved);
        for pass in &story.passes {
            for contact in &pass.contacts {
                contacts += 1;
                // Never a seam face (normal ±x) nor a rounded end: the top faces only.
                assert_eq!(contact.part, ContactPart::Face, "{contact:?}");
                assert_eq!(contact.normal, Vec2::new(0.0, -1.0), "{contact:?}");
                let (cell, _) = tile_of(contact.source);
                assert_eq!(cell.row, 2);
                assert_eq!(contact.point.y, 2.0);
            }
        }
    }
    assert!(contacts >= 6, "the floor was met every step: {contacts}");
    let x = bodies.get(ball).unwrap().position().x;
    assert!(x > 4.4, "it slid over three seams, to {x}");
}

#[test]
fn a_circle_pushed_into_a_concave_corner_slides_along_the_floor_and_stops_there() {
    // The floor's top at y = 3, the right wall's face at x = 4.
    let m = map("#####\n#...#\n#...#\n#####");
    let mut bodies = Bodies::new();
    let ball = add(&mut bodies, Vec2::new(2.0, 2.0), 0.4);
    bodies.propose(ball, Vec2::new(2.0, 1.0)).unwrap();
    let mut trace = ResolveTrace::new();
    bodies.resolve_traced(&m, &mut trace);
    let passes = &trace.body(ball).unwrap().passes;
    // Pass 0 meets the floor first (3 − 0.4 − gap from y = 2: t ≈ 0.599, x ≈ 3.198; the
    // wall's face is reached at x = 4 − 0.4 − gap, t ≈ 0.7995), and slides right.
    let first = passes[0].chosen().unwrap();
    assert_eq!(first.normal, Vec2::new(0.0, -1.0));
    assert_eq!(tile_of(first.source).0.row, 3);
    assert!((first.t - 0.599).abs() < 1e-4, "{first:?}");
    let Response::Slid { slide } = passes[0].response else {
        panic!("{:?}", passes[0].response);
    };
    assert!(slide.x > 0.0 && slide.y == 0.0, "{slide}");
    // Pass 1 slides (0.897 long) into the right wall straight on: stopped in the corner.
    let second = passes[1].chosen().unwrap();
    assert_eq!(second.normal, Vec2::new(-1.0, 0.0));
    assert_eq!(
        tile_of(second.source).0,
        Cell::new(4, passes_row(second.point.y))
    );
    assert_eq!(passes[1].response, Response::StoppedInCorner);
    assert_eq!(passes.len(), 2);
    let end = passes[1].from + passes[1].moved;
    assert!((end - Vec2::new(3.599, 2.599)).length() < 1e-4, "{end}");
}

/// The row of a point on the room's right wall (rows 1 and 2 hold its face).
fn passes_row(y: f32) -> u32 {
    y.floor() as u32
}

#[test]
fn a_circle_driven_straight_into_a_wall_stops_head_on() {
    let m = map("#####\n#...#\n#####");
    let mut bodies = Bodies::new();
    let ball = add(&mut bodies, Vec2::new(1.5, 1.5), 0.4);
    bodies.propose(ball, Vec2::new(3.0, 0.0)).unwrap();
    let mut trace = ResolveTrace::new();
    bodies.resolve_traced(&m, &mut trace);
    let passes = &trace.body(ball).unwrap().passes;
    assert_eq!(passes.len(), 1);
    assert_eq!(passes[0].response, Response::StoppedHeadOn);
    assert_eq!(
        tile_of(passes[0].chosen().unwrap().source).0,
        Cell::new(4, 1)
    );
}

#[test]
fn a_circle_passing_a_block_rounds_its_convex_corner() {
    // A block at x, y in [3, 4] x [2, 3]; the circle passes 0.3 above its top.
    let m = map("######\n#....#\n#..#.#\n#....#\n######");
    let mut bodies = Bodies::new();
    let ball = add(&mut bodies, Vec2::new(2.0, 1.7), 0.4);
    bodies.propose(ball, Vec2::new(2.0, 0.0)).unwrap();
    let mut trace = ResolveTrace::new();
    bodies.resolve_traced(&m, &mut trace);
    let pass = &trace.body(ball).unwrap().passes[0];
    let contact = pass.chosen().unwrap();
    // The corner (3, 2) is met by the rounded end at x = 3 − √(0.401² − 0.3²).
    assert_eq!(contact.part, ContactPart::RoundedEnd);
    assert_eq!(contact.point, Vec2::new(3.0, 2.0));
    assert_eq!(tile_of(contact.source).0, Cell::new(3, 2));
    let x = 3.0 - (0.401f32 * 0.401 - 0.09).sqrt();
    assert!((contact.t - (x - 2.0) / 2.0).abs() < 1e-4, "{contact:?}");
    let Response::RoundedCorner { slide } = pass.response else {
        panic!("{:?}", pass.response);
    };
    // Up and on along the corner's tangent.
    assert!(slide.x > 0.0 && slide.y < 0.0, "{slide}");
}

#[test]
fn a_body_meeting_another_head_on_takes_the_tie_break_and_the_other_slides_the_other_way() {
    let m = map("########\n#......#\n#......#\n#......#\n########");
    let mut bodies = Bodies::new();
    let a = add(&mut bodies, Vec2::new(2.5, 2.5), 0.4);
    let b = add(&mut bodies, Vec2::new(4.0, 2.5), 0.4);
    bodies.propose(a, Vec2::new(1.0, 0.0)).unwrap();
    bodies.propose(b, Vec2::new(-1.0, 0.0)).unwrap();
    let mut trace = ResolveTrace::new();
    bodies.resolve_traced(&m, &mut trace);
    let first_pass = |who: BodyHandle, other: BodyHandle| {
        let pass: &PassTrace = &trace.body(who).unwrap().passes[0];
        let contact = *pass.chosen().unwrap();
        assert_eq!(
            contact.source,
            ContactSource::Body {
                handle: other,
                circle: 0
            }
        );
        assert_eq!(contact.part, ContactPart::Circle);
        (contact, pass.response)
    };
    // A (the lower slot, resolved first) meets B where B stands, on the line of their
    // centres: t = (1.5 − 0.8 − gap) / 1, at B's circle's point facing A.
    let (contact, response) = first_pass(a, b);
    assert!((contact.t - 0.699).abs() < 1e-5, "{contact:?}");
    assert!((contact.point - Vec2::new(3.6, 2.5)).length() < 1e-6);
    let Response::TieBreak { slide: sa } = response else {
        panic!("{response:?}");
    };
    // The tie-break turns it along the tangent, the whole remainder's length.
    assert_eq!(sa.x, 0.0);
    assert!((sa.y.abs() - 0.301).abs() < 1e-5, "{sa}");
    // B then meets A where A ended, off its line: it slides, the other way.
    let (_, response) = first_pass(b, a);
    let Response::Slid { slide: sb } = response else {
        panic!("{response:?}");
    };
    assert!(sa.y * sb.y < 0.0, "{sa} {sb}");
}

#[test]
fn a_move_along_a_touching_body_is_a_graze_and_goes_on() {
    let m = map("########\n#......#\n#......#\n#......#\n########");
    let mut bodies = Bodies::new();
    let still = add(&mut bodies, Vec2::new(4.0, 2.8), 0.4);
    // Inside the gap band above it (0.8 + 0.0002 apart), moving right and in by 1e-7 of
    // the move: rounding, not an approach.
    let mover = add(&mut bodies, Vec2::new(4.0, 2.0 - 0.0002), 0.4);
    bodies.propose(mover, Vec2::new(0.5, 0.5e-7)).unwrap();
    let mut trace = ResolveTrace::new();
    bodies.resolve_traced(&m, &mut trace);
    assert_eq!(trace.body(still).unwrap().fate, BodyFate::Still);
    let pass = &trace.body(mover).unwrap().passes[0];
    let graze = pass
        .contacts
        .iter()
        .find(|c| c.grazed)
        .unwrap_or_else(|| panic!("{pass:?}"));
    assert_eq!(
        graze.source,
        ContactSource::Body {
            handle: still,
            circle: 0
        }
    );
    assert_eq!(graze.t, 0.0);
    assert_eq!(pass.response, Response::Free);
    assert_eq!(pass.first, None);
    assert!((trace.body(mover).unwrap().resolved.x - 0.5).abs() < 1e-6);
}

#[test]
fn a_body_blocked_in_place_is_reported_settled() {
    let m = map("#####\n#...#\n#####");
    let mut bodies = Bodies::new();
    let ball = add(&mut bodies, Vec2::new(1.5, 1.5), 0.4);
    let mut trace = ResolveTrace::of(ball);
    let mut fates = Vec::new();
    for _ in 0..5 {
        bodies.propose(ball, Vec2::new(1.0, 0.0)).unwrap();
        bodies.step_traced(&m, &mut trace);
        fates.push(trace.body(ball).unwrap().fate);
    }
    assert_eq!(fates[0], BodyFate::Resolved);
    assert_eq!(fates[4], BodyFate::Settled, "{fates:?}");
    assert!(trace.body(ball).unwrap().passes.is_empty());
}

#[test]
fn a_temporary_segment_is_named_by_its_owner_and_index() {
    use tileslide::{Owner, Segment, SegmentFlags, TemporarySegment};
    let mut m = map("#######\n#.....#\n#.....#\n#######");
    let door = Segment::new(Vec2::new(4.0, 1.0), Vec2::new(4.0, 3.0));
    m.add_temporary(TemporarySegment {
        segment: door,
        normal: Vec2::new(-1.0, 0.0),
        flags: SegmentFlags::SOLID,
        owner: Owner(9),
        velocity: Vec2::ZERO,
    })
    .unwrap();
    let mut bodies = Bodies::new();
    let ball = add(&mut bodies, Vec2::new(2.0, 2.0), 0.4);
    bodies.propose(ball, Vec2::new(3.0, 0.0)).unwrap();
    let mut trace = ResolveTrace::new();
    bodies.resolve_traced(&m, &mut trace);
    let contact = *trace.body(ball).unwrap().passes[0].chosen().unwrap();
    assert_eq!(
        contact.source,
        ContactSource::Wall(WallSource::Temporary {
            owner: Owner(9),
            index: 0
        })
    );
    assert_eq!(contact.point.x, 4.0);
}

#[test]
fn a_traced_resolve_moves_bodies_exactly_as_an_untraced_one() {
    traced_and_plain_agree(None);
}

#[test]
fn a_trace_of_some_bodies_records_those_alone_and_moves_every_body_as_untraced() {
    // Out of order and repeated: the trace takes each once, in slot order.
    traced_and_plain_agree(Some(&[7, 2, 7, 11]));
}

/// Steps bodies on a map of blocks and a one-way platform, traced (every body, or those
/// at `some` indices) and not, and asserts the same moves and a story for each traced body.
fn traced_and_plain_agree(some: Option<&[usize]>) {
    let m = map(
        "############\n#....#.....#\n#.#..#..#..#\n#....=.....#\n#..#.....#.#\n#..........#\n############",
    );
    let mut plain = Bodies::new();
    let mut traced = Bodies::new();
    let mut handles = Vec::new();
    for k in 0..24 {
        let at = Vec2::new(1.5 + (k % 10) as f32, 1.5 + (k / 10) as f32 * 1.5);
        if m.is_point_solid(at) {
            continue;
        }
        handles.push(add(&mut plain, at, 0.3));
        add(&mut traced, at, 0.3);
    }
    let (mut trace, mut wanted) = match some {
        None => (ResolveTrace::new(), handles.clone()),
        Some(indices) => {
            let chosen: Vec<BodyHandle> = indices.iter().map(|&i| handles[i]).collect();
            (ResolveTrace::of_bodies(chosen.iter().copied()), chosen)
        }
    };
    wanted.sort_unstable();
    wanted.dedup();
    for step in 0..40 {
        for (k, &h) in handles.iter().enumerate() {
            let angle = (k * 7 + step) as f32 * 0.37;
            let motion = Vec2::new(angle.cos(), angle.sin()) * 0.35;
            plain.propose(h, motion).unwrap();
            traced.propose(h, motion).unwrap();
        }
        let a = plain.step(&m);
        let b = traced.step_traced(&m, &mut trace);
        assert_eq!(a, b);
        let recorded: Vec<BodyHandle> = trace.bodies.iter().map(|b| b.handle).collect();
        assert_eq!(recorded, wanted);
        for &h in &handles {
            let (p, q) = (plain.get(h).unwrap(), traced.get(h).unwrap());
            assert_eq!(
                p.position().to_array(),
                q.position().to_array(),
                "step {step}"
            );
            if let Some(story) = trace.body(h) {
                assert_eq!(story.start + story.resolved, q.position());
            }
        }
    }
}
