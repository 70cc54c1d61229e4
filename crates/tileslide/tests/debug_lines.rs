//! Debug lines against the map and bodies they describe: the map's active and hidden
//! pieces are its tile segments, a view gives exactly what touches it, bodies' circles are
//! where the bodies are.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use crate::generators;

use generators::small_map_at;
use proptest::prelude::*;
use tileslide::debug::DebugKinds;
use tileslide::{
    Aabb, Bodies, BodyDesc, BodyShape, Cell, DebugKind, DebugLines, Owner, Segment, TileMap, Vec2,
};
use tileslide_scenes::SplitMix64;

fn lines_of(map: &TileMap) -> DebugLines {
    let mut lines = DebugLines::new();
    map.debug_lines(&mut lines);
    lines
}

fn of_kinds(lines: &DebugLines, kinds: &[DebugKind]) -> Vec<Segment> {
    lines
        .segments()
        .iter()
        .filter(|s| kinds.contains(&s.kind))
        .map(|s| s.segment)
        .collect()
}

/// The length two segments running the same way along one line share (0 for segments
/// on different lines or running opposite ways: those face opposite ways, as pieces run
/// with their normal on the right).
fn shared_length(s: &Segment, t: &Segment) -> f32 {
    let d = s.delta();
    let length = d.length();
    if length == 0.0 || t.delta().dot(d) <= 0.0 {
        return 0.0;
    }
    let u = d / length;
    let off_line = |p: Vec2| (p - s.a).perp_dot(u).abs();
    if off_line(t.a) > 1e-4 * length || off_line(t.b) > 1e-4 * length {
        return 0.0;
    }
    let (t0, t1) = ((t.a - s.a).dot(u), (t.b - s.a).dot(u));
    (t0.max(t1).min(length) - t0.min(t1).max(0.0)).max(0.0)
}

fn any_origin() -> impl Fn(u32, u32, f32, usize) -> Vec2 + Clone + 'static {
    |_, _, cell, k| [Vec2::ZERO, Vec2::new(-3.0, 5.0), Vec2::new(100.5, -7.25)][k] * cell
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

    /// Every active segment appears once with its normal; the active and hidden pieces
    /// together have the length of every placed tile segment, and no hidden piece overlaps
    /// an active one facing the same way (a hidden one-way platform under a block lies
    /// against the block's active underside, facing the other way).
    #[test]
    fn active_and_hidden_pieces_make_up_the_tile_segments(map in small_map_at(any_origin())) {
        let lines = lines_of(&map);
        let active = of_kinds(&lines, &[DebugKind::ActiveSegment, DebugKind::OneWaySegment]);
        let hidden = of_kinds(&lines, &[DebugKind::HiddenSegment]);
        prop_assert_eq!(active.len(), map.active_segment_count());
        prop_assert_eq!(
            lines.count(DebugKind::Normal),
            map.active_segment_count() + map.temporaries().len()
        );
        let mut placed = 0.0f64;
        for row in 0..map.height() {
            for col in 0..map.width() {
                let cell = Cell::new(col, row);
                if let Some(shape) = map.tile(cell).and_then(|id| map.tile_set().shape(id)) {
                    placed += shape.segments().iter().map(|s| f64::from(s.segment().length())).sum::<f64>();
                }
            }
        }
        let total: f64 = active.iter().chain(&hidden).map(|s| f64::from(s.length())).sum();
        let cell = f64::from(map.cell_size().x);
        prop_assert!((total - placed).abs() <= 1e-4 * cell * (1.0 + placed / cell), "{} vs {}", total, placed);
        for h in &hidden {
            for a in &active {
                prop_assert!(shared_length(h, a) <= 1e-4 * map.cell_size().x, "{:?} overlaps {:?}", h, a);
            }
        }
    }

    /// A view gives exactly the shapes of the whole map's lines that touch it, in the same
    /// order.
    #[test]
    fn a_view_gives_what_touches_it(
        map in small_map_at(any_origin()),
        corners in (0.0f32..1.0, 0.0f32..1.0, 0.0f32..1.0, 0.0f32..1.0),
    ) {
        let bounds = map.bounds().expand(map.cell_size().x);
        let at = |fx: f32, fy: f32| bounds.min + bounds.size() * Vec2::new(fx, fy);
        let view = Aabb::from_corners(at(corners.0, corners.1), at(corners.2, corners.3));
        let whole = lines_of(&map);
        let mut seen = DebugLines::new().with_view(view);
        map.debug_lines(&mut seen);
        let expected: Vec<_> = whole
            .segments()
            .iter()
            .filter(|s| view.overlaps(&s.segment.aabb()))
            .copied()
            .collect();
        prop_assert_eq!(seen.segments(), expected.as_slice());
    }

    /// Kinds left out are left out, and nothing else changes.
    #[test]
    fn a_buffer_without_hidden_segments_holds_the_rest(map in small_map_at(any_origin())) {
        let whole = lines_of(&map);
        let mut walls = DebugLines::new()
            .with_kinds(DebugKinds::ALL.without(DebugKind::HiddenSegment));
        map.debug_lines(&mut walls);
        let expected: Vec<_> = whole
            .segments()
            .iter()
            .filter(|s| s.kind != DebugKind::HiddenSegment)
            .copied()
            .collect();
        prop_assert_eq!(walls.segments(), expected.as_slice());
    }
}

/// A crowd stepped a few times: one circle per body, where the body is, with its owner, in
/// slot order, and a broadphase box around each.
#[test]
fn bodies_circles_are_where_the_bodies_are() {
    let map = tileslide::io::ascii::parse(
        "\
##########
#........#
#..#.....#
#........#
##########",
        "room.txt",
        1.0,
    )
    .unwrap();
    let mut rng = SplitMix64::new(23);
    let mut bodies = Bodies::new();
    let mut handles = Vec::new();
    for k in 0..12 {
        let p = Vec2::new(1.3 + (k % 6) as f32 * 1.2, 1.3 + (k / 6) as f32 * 1.4);
        let shape = BodyShape::circle(0.2 + 0.01 * k as f32).unwrap();
        handles.push(
            bodies
                .add(BodyDesc::new(p, shape).with_owner(Owner(100 + k)))
                .unwrap(),
        );
    }
    let mut lines = DebugLines::new();
    for _ in 0..20 {
        for &h in &handles {
            let motion = Vec2::new(rng.range(-0.3, 0.3), rng.range(-0.3, 0.3));
            bodies.propose(h, motion).unwrap();
        }
        bodies.step(&map);
        lines.clear();
        bodies.debug_lines(&mut lines);
        assert_eq!(lines.circles().len(), handles.len());
        for (c, (_, body)) in lines.circles().iter().zip(bodies.iter()) {
            assert_eq!(c.kind, DebugKind::Body);
            assert_eq!(c.circle.center, body.position());
            assert_eq!(c.circle.radius, body.shape().circles()[0].radius);
            assert_eq!(c.owner, body.owner());
        }
        assert_eq!(lines.boxes().len(), handles.len());
    }
    // A cleared buffer is empty.
    lines.clear();
    assert!(lines.is_empty());
    assert_eq!(lines.len(), 0);
}
