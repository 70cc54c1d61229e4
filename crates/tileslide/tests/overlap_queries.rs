//! Proves the overlap and point queries: `cells_overlapping`, `segments_overlapping_aabb` and
//! `segments_overlapping_circle` return exactly what a brute force over every cell and every
//! active (and temporary) segment returns, touching included; the box and circle primitives
//! agree with an independent f64 computation; and `is_point_solid` follows each tile's solid
//! outline (squares, both sides of each ramp), never for one-way platforms or outside the map.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use crate::drawn;
use crate::generators;

use std::sync::Arc;

use generators::{rows, tile_chars, tile_map};
use proptest::prelude::*;
use tileslide::io::ascii;
use tileslide::{
    Aabb, Cell, Circle, Owner, Segment, SegmentFlags, SegmentOverlap, SegmentSource,
    TemporarySegment, TileMap, Vec2,
};

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

/// A map drawn as text (see `drawn`).
fn map(drawing: &str) -> TileMap {
    drawn::map(drawing, "overlap.txt")
}

/// Which segment an overlap names: a tile segment by (cell, index) or a temporary by index.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Key {
    Tile(Cell, u32),
    Temporary(usize),
}

fn key_of(o: &SegmentOverlap) -> Key {
    match o.source {
        SegmentSource::Tile { segment, .. } => Key::Tile(segment.cell, segment.index),
        SegmentSource::Temporary { index, .. } => Key::Temporary(index),
        // The brute force lists tile and temporary segments only: a hit on anything else
        // is one it cannot check.
        other => panic!("a segment source the brute force does not list: {other:?}"),
    }
}

/// Every active and temporary segment of the map with its key.
fn every_segment(m: &TileMap) -> Vec<(Key, Segment, Vec2, SegmentFlags)> {
    let mut out = Vec::new();
    for row in 0..m.height() {
        for col in 0..m.width() {
            let cell = Cell::new(col, row);
            for (i, s) in m.active_segments(cell).enumerate() {
                out.push((Key::Tile(cell, i as u32), s.segment, s.normal, s.flags));
            }
        }
    }
    for (i, t) in m.temporaries().iter().enumerate() {
        out.push((Key::Temporary(i), t.segment, t.normal, t.flags));
    }
    out
}

/// Checks a query's result against the brute force `want` (keys of every segment `pred`
/// accepts), including the fields each overlap reports.
fn check_segments(
    m: &TileMap,
    got: &[SegmentOverlap],
    pred: impl Fn(&Segment) -> bool,
) -> Result<(), TestCaseError> {
    let all = every_segment(m);
    let mut want: Vec<Key> = all.iter().filter(|s| pred(&s.1)).map(|s| s.0).collect();
    want.sort();
    let mut keys: Vec<Key> = got.iter().map(key_of).collect();
    keys.sort();
    prop_assert_eq!(&keys, &want);
    for o in got {
        let (_, segment, normal, flags) = all.iter().find(|s| s.0 == key_of(o)).unwrap();
        prop_assert_eq!(o.segment, *segment);
        prop_assert_eq!(o.normal, *normal);
        prop_assert_eq!(o.flags, *flags);
    }
    Ok(())
}

#[derive(Clone, Debug)]
struct World {
    map: TileMap,
    text: String,
}

fn world() -> impl Strategy<Value = World> {
    (
        1u32..=16,
        1u32..=16,
        prop_oneof![Just(1.0f32), Just(0.5), Just(32.0)],
        prop_oneof![Just(v(0.0, 0.0)), Just(v(-3.5, 12.25)), Just(v(64.0, -8.0))],
    )
        .prop_flat_map(|(w, h, cell, origin)| {
            let chars = tile_chars(
                &[(4, '.'), (3, '#'), (1, '/'), (1, '\\'), (1, '=')],
                (w * h) as usize,
            );
            let temps = proptest::collection::vec(
                (
                    (-2.0f32..18.0, -2.0f32..18.0),
                    (-2.0f32..18.0, -2.0f32..18.0),
                ),
                0..3,
            );
            (Just((w, h, cell, origin)), chars, temps)
        })
        .prop_map(|((w, _, cell, origin), chars, temps)| {
            let mut map = tile_map(w, &chars, cell, origin);
            for (i, (a, b)) in temps.into_iter().enumerate() {
                let (a, b) = (origin + v(a.0, a.1) * cell, origin + v(b.0, b.1) * cell);
                if a != b {
                    map.add_temporary(TemporarySegment {
                        segment: Segment::new(a, b),
                        normal: (b - a).perp(),
                        flags: SegmentFlags::SOLID,
                        owner: Owner(i as u64),
                        velocity: Vec2::ZERO,
                    })
                    .unwrap();
                }
            }
            World {
                map,
                text: rows(w, &chars),
            }
        })
}

/// A coordinate in grid units: free, or snapped to a half cell (so box edges land exactly on
/// cell boundaries, segment end points and ramp midpoints).
fn coord(n: u32) -> impl Strategy<Value = f32> {
    let n = n as f32;
    prop_oneof![
        -3.0f32..n + 3.0,
        (-6i32..=(2 * n as i32 + 6)).prop_map(|i| i as f32 * 0.5),
    ]
}

fn grid_box() -> impl Strategy<Value = (Vec2, Vec2)> {
    (coord(16), coord(16), coord(16), coord(16), 0u32..4).prop_map(|(x0, y0, x1, y1, kind)| {
        match kind {
            // A point (zero-size box).
            0 => (v(x0, y0), v(x0, y0)),
            // A zero-width or zero-height box: a line.
            1 => (v(x0, y0), v(x0, y1)),
            _ => (v(x0, y0), v(x1, y1)),
        }
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    #[test]
    fn cells_overlapping_is_every_cell_whose_closed_rectangle_touches_the_box(
        w in world(),
        (a, b) in grid_box(),
    ) {
        let m = &w.map;
        let (o, c) = (m.origin(), m.cell_size());
        let aabb = Aabb::from_corners(o + a * c, o + b * c);
        let got: Vec<Cell> = m.cells_overlapping(&aabb).collect();
        // Row by row, each row by column: the order of this double loop.
        let mut want = Vec::new();
        for row in 0..m.height() {
            for col in 0..m.width() {
                if m.cell_rect(Cell::new(col, row)).overlaps(&aabb) {
                    want.push(Cell::new(col, row));
                }
            }
        }
        prop_assert_eq!(got, want, "box {:?} on\n{}", aabb, w.text);
    }

    #[test]
    fn segments_overlapping_aabb_matches_brute_force(w in world(), (a, b) in grid_box()) {
        let m = &w.map;
        let (o, c) = (m.origin(), m.cell_size());
        let aabb = Aabb::from_corners(o + a * c, o + b * c);
        check_segments(m, &m.segments_overlapping_aabb(&aabb), |s| aabb.overlaps_segment(s))?;
    }

    #[test]
    fn segments_overlapping_circle_matches_brute_force(
        w in world(),
        center in (coord(16), coord(16)),
        radius in prop_oneof![0.0f32..4.0, (0u32..8).prop_map(|i| i as f32 * 0.5)],
    ) {
        let m = &w.map;
        let (o, c) = (m.origin(), m.cell_size());
        let circle = Circle::new(o + v(center.0, center.1) * c, radius * c.x);
        check_segments(m, &m.segments_overlapping_circle(&circle), |s| circle.overlaps_segment(s))?;
    }

    /// The primitives themselves, against f64: clip the segment to the box (Liang–Barsky),
    /// and the distance from a point to a segment. Cases within 1e-4 of touching are left to
    /// the exact scenario tests below.
    #[test]
    fn box_and_circle_segment_tests_agree_with_f64(
        (ax, ay, bx, by) in (-4.0f32..4.0, -4.0f32..4.0, -4.0f32..4.0, -4.0f32..4.0),
        (x0, y0, x1, y1) in (-3.0f32..3.0, -3.0f32..3.0, -3.0f32..3.0, -3.0f32..3.0),
        r in 0.0f32..3.0,
    ) {
        let seg = Segment::new(v(ax, ay), v(bx, by));
        let aabb = Aabb::from_corners(v(x0, y0), v(x1, y1));
        if let Some(margin) = f64_box_margin(&aabb, &seg)
            && margin.abs() > 1e-4
        {
            prop_assert_eq!(aabb.overlaps_segment(&seg), margin > 0.0, "{:?} {:?}", aabb, seg);
        }
        let circle = Circle::new(v(x0, y0), r);
        let d = f64_distance(circle.center, &seg) - r as f64;
        if d.abs() > 1e-4 {
            prop_assert_eq!(circle.overlaps_segment(&seg), d < 0.0, "{:?} {:?}", circle, seg);
        }
    }
}

/// How far the segment reaches into the box (positive) or misses it (negative), by clipping
/// in f64; `None` for a degenerate box.
fn f64_box_margin(aabb: &Aabb, s: &Segment) -> Option<f64> {
    let (lo, hi) = (aabb.min.as_dvec2(), aabb.max.as_dvec2());
    if (hi - lo).min_element() < 1e-3 {
        return None;
    }
    let (a, d) = (s.a.as_dvec2(), (s.b - s.a).as_dvec2());
    // Shrink or grow the box by `m` and ask whether the segment still meets it: bisect for
    // the m at which it stops, within [-8, 8].
    let meets = |m: f64| {
        let (lo, hi) = (lo + m, hi - m);
        if lo.x > hi.x || lo.y > hi.y {
            return false;
        }
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        for axis in 0..2 {
            if d[axis] == 0.0 {
                if a[axis] < lo[axis] || a[axis] > hi[axis] {
                    return false;
                }
            } else {
                let (u, w) = (
                    (lo[axis] - a[axis]) / d[axis],
                    (hi[axis] - a[axis]) / d[axis],
                );
                t0 = t0.max(u.min(w));
                t1 = t1.min(u.max(w));
            }
        }
        t0 <= t1
    };
    let (mut inside, mut outside) = (-8.0f64, 8.0f64);
    if !meets(inside) {
        return Some(-8.0);
    }
    for _ in 0..60 {
        let mid = 0.5 * (inside + outside);
        if meets(mid) {
            inside = mid;
        } else {
            outside = mid;
        }
    }
    Some(inside)
}

fn f64_distance(p: Vec2, s: &Segment) -> f64 {
    let (p, a, b) = (p.as_dvec2(), s.a.as_dvec2(), s.b.as_dvec2());
    let d = b - a;
    let t = if d.length_squared() == 0.0 {
        0.0
    } else {
        ((p - a).dot(d) / d.length_squared()).clamp(0.0, 1.0)
    };
    (a + d * t).distance(p)
}

// ---------------------------------------------------------------------------------------
// Touching counts
// ---------------------------------------------------------------------------------------

#[test]
fn box_touching_a_wall_face_overlaps_it() {
    let m = map("...#");
    // The box's right edge lies on the wall's left face x = 3.
    let aabb = Aabb::from_corners(v(2.0, 0.25), v(3.0, 0.75));
    let hits = m.segments_overlapping_aabb(&aabb);
    assert!(hits.iter().any(|o| o.normal == v(-1.0, 0.0)), "{hits:?}");
    // The cells on both sides of that face are reported.
    let cells: Vec<Cell> = m.cells_overlapping(&aabb).collect();
    assert_eq!(cells, [Cell::new(1, 0), Cell::new(2, 0), Cell::new(3, 0)]);
    // A hair to the left, nothing.
    let apart = Aabb::from_corners(v(2.0, 0.25), v(2.999, 0.75));
    assert!(m.segments_overlapping_aabb(&apart).is_empty());
}

#[test]
fn box_touching_only_a_block_corner_overlaps_its_two_faces_there() {
    let m = map(r"
        ..
        .#
    ");
    let aabb = Aabb::from_corners(v(0.0, 0.0), v(1.0, 1.0));
    let mut normals: Vec<_> = m
        .segments_overlapping_aabb(&aabb)
        .iter()
        .map(|o| (o.normal.x, o.normal.y))
        .collect();
    normals.sort_by(|a, b| a.partial_cmp(b).unwrap());
    assert_eq!(normals, [(-1.0, 0.0), (0.0, -1.0)]);
}

#[test]
fn circle_tangent_to_a_floor_overlaps_it() {
    let m = map(r"
        ....
        ####
    ");
    let c = Circle::new(v(1.5, 0.5), 0.5);
    let hits = m.segments_overlapping_circle(&c);
    assert_eq!(hits.len(), 1, "{hits:?}");
    assert_eq!(hits[0].normal, v(0.0, -1.0));
    assert!(
        m.segments_overlapping_circle(&Circle::new(v(1.5, 0.5), 0.499))
            .is_empty()
    );
    // A point-sized circle exactly on the seam touches both top faces there.
    assert_eq!(
        m.segments_overlapping_circle(&Circle::new(v(2.0, 1.0), 0.0))
            .len(),
        2
    );
}

#[test]
fn circle_reaching_a_ramp_slope_overlaps_it() {
    let m = map(r"
        ...
        ./.
        ...
    ");
    // The slope of `/` in (1, 1) is x + y = 3; the point (1, 1) is at distance 1/√2.
    let near = Circle::new(v(1.0, 1.0), std::f32::consts::FRAC_1_SQRT_2 + 1e-4);
    let hits = m.segments_overlapping_circle(&near);
    assert_eq!(hits.len(), 1, "{hits:?}");
    assert!(hits[0].normal.x < 0.0 && hits[0].normal.y < 0.0);
    let far = Circle::new(v(1.0, 1.0), std::f32::consts::FRAC_1_SQRT_2 - 1e-4);
    assert!(m.segments_overlapping_circle(&far).is_empty());
}

#[test]
fn overlap_queries_report_temporary_segments_anywhere() {
    let mut m = map(r"
        ...
        ...
    ");
    m.add_temporary(TemporarySegment {
        segment: Segment::new(v(10.0, 10.0), v(12.0, 10.0)),
        normal: v(0.0, -1.0),
        flags: SegmentFlags::SOLID,
        owner: Owner(5),
        velocity: v(1.0, 0.0),
    })
    .unwrap();
    let far = Aabb::from_corners(v(11.0, 9.0), v(11.5, 11.0));
    let got = m.segments_overlapping_aabb(&far);
    assert_eq!(got.len(), 1);
    assert!(matches!(
        got[0].source,
        SegmentSource::Temporary {
            owner: Owner(5),
            index: 0,
            ..
        }
    ));
    assert_eq!(
        m.segments_overlapping_circle(&Circle::new(v(11.0, 10.5), 0.5))
            .len(),
        1
    );
    assert_eq!(m.cells_overlapping(&far).count(), 0);
}

#[test]
fn boxes_outside_the_map_or_not_finite_overlap_no_cell() {
    let m = map(r"
        ##
        ##
    ");
    let cases = [
        Aabb::from_corners(v(-3.0, -3.0), v(-0.5, 5.0)),
        Aabb::from_corners(v(2.5, 0.0), v(4.0, 1.0)),
        Aabb {
            min: v(f32::NAN, 0.0),
            max: v(1.0, 1.0),
        },
        Aabb::from_corners(v(0.0, 0.0), v(f32::INFINITY, 1.0)),
        Aabb::from_center(v(1.0, f32::NAN), v(0.5, 0.5)),
    ];
    for aabb in cases {
        assert_eq!(m.cells_overlapping(&aabb).count(), 0, "{aabb:?}");
        assert!(m.segments_overlapping_aabb(&aabb).is_empty(), "{aabb:?}");
    }
    // Touching the map's border from outside still touches the border cells.
    let touching = Aabb::from_corners(v(-1.0, 0.5), v(0.0, 0.5));
    assert_eq!(
        m.cells_overlapping(&touching).collect::<Vec<_>>(),
        [Cell::new(0, 0)]
    );
    assert_eq!(m.segments_overlapping_aabb(&touching).len(), 1);
}

/// Regression: `Aabb::from_corners` took glam's `min`/`max`, which return the other operand
/// when one is NaN, so a box from a NaN corner came out as a valid box at the other corner
/// and the queries answered for it (here 4 cells and 2 segments).
#[test]
fn box_from_a_nan_corner_is_invalid_and_overlaps_nothing() {
    let m = map(r"
        ##
        ##
    ");
    for (a, b) in [
        (v(f32::NAN, 0.0), v(1.0, 1.0)),
        (v(0.0, 0.0), v(1.0, f32::NAN)),
        (v(f32::NAN, f32::NAN), v(1.0, 1.0)),
    ] {
        let aabb = Aabb::from_corners(a, b);
        assert!(!aabb.is_valid(), "{aabb:?}");
        assert_eq!(m.cells_overlapping(&aabb).count(), 0, "{aabb:?}");
        assert!(m.segments_overlapping_aabb(&aabb).is_empty(), "{aabb:?}");
        assert!(!aabb.contains_point(v(1.0, 0.5)));
    }
}

// ---------------------------------------------------------------------------------------
// Points
// ---------------------------------------------------------------------------------------

#[test]
fn points_inside_squares_are_solid_and_beside_them_not() {
    let m = map(r"
        ....
        .##.
        ....
    ");
    for p in [
        v(1.5, 1.5),
        v(2.5, 1.5),
        v(1.01, 1.01),
        v(2.99, 1.99),
        v(2.0, 1.5),
    ] {
        assert!(m.is_point_solid(p), "{p:?}");
    }
    for p in [
        v(0.5, 1.5),
        v(3.5, 1.5),
        v(1.5, 0.99),
        v(1.5, 2.01),
        v(0.99, 1.5),
    ] {
        assert!(!m.is_point_solid(p), "{p:?}");
    }
}

#[test]
fn ramp_points_are_solid_below_the_slope_only() {
    let m = map(r"
        ...
        ./\
        ...
    ");
    // `/` in (1, 1): solid below-right of x + y = 3.
    for (p, solid) in [
        (v(1.9, 1.9), true),
        (v(1.75, 1.5), true),
        (v(1.1, 1.1), false),
        (v(1.25, 1.5), false),
        (v(1.45, 1.45), false),
        (v(1.55, 1.55), true),
    ] {
        assert_eq!(m.is_point_solid(p), solid, "/ at {p:?}");
    }
    // `\` in (2, 1): solid below-left of y − 1 = x − 2.
    for (p, solid) in [
        (v(2.1, 1.9), true),
        (v(2.25, 1.5), true),
        (v(2.9, 1.1), false),
        (v(2.75, 1.5), false),
        (v(2.45, 1.55), true),
        (v(2.55, 1.45), false),
    ] {
        assert_eq!(m.is_point_solid(p), solid, "\\ at {p:?}");
    }
}

#[test]
fn one_way_platforms_are_never_solid() {
    let m = map(r"
        ===
        ===
    ");
    for p in [v(0.5, 0.5), v(1.5, 0.0), v(2.5, 1.0), v(1.0, 1.5)] {
        assert!(!m.is_point_solid(p), "{p:?}");
    }
}

#[test]
fn points_outside_the_map_or_not_finite_are_not_solid() {
    let m = map(r"
        ##
        ##
    ");
    for p in [
        v(-0.01, 0.5),
        v(0.5, -0.01),
        v(2.0, 0.5),
        v(0.5, 2.0),
        v(100.0, 100.0),
        v(f32::NAN, 0.5),
        v(0.5, f32::INFINITY),
    ] {
        assert!(!m.is_point_solid(p), "{p:?}");
    }
}

#[test]
fn point_solidity_scales_with_cell_size_and_origin() {
    let set = Arc::new(ascii::tile_set(32.0).unwrap());
    let origin = v(-64.0, 16.0);
    let m = TileMap::from_tiles(
        set,
        2,
        1,
        origin,
        &[Some(ascii::RAMP_UP_RIGHT), Some(ascii::SOLID)],
    )
    .unwrap();
    assert!(m.is_point_solid(origin + v(30.0, 30.0)));
    assert!(!m.is_point_solid(origin + v(2.0, 2.0)));
    assert!(m.is_point_solid(origin + v(40.0, 2.0)));
    assert!(!m.is_point_solid(origin + v(64.0, 2.0)));
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    /// Away from any outline, a point is solid exactly when the tile in its cell encloses it:
    /// checked against each ASCII tile's shape written out by hand.
    #[test]
    fn point_solidity_matches_each_tiles_region(w in world(), p in (0.0f32..1.0, 0.0f32..1.0), cell in (0u32..16, 0u32..16)) {
        let m = &w.map;
        let cell = Cell::new(cell.0 % m.width(), cell.1 % m.height());
        let (x, y) = p;
        // Stay 1e-3 away from every edge and slope.
        prop_assume!(x > 1e-3 && x < 1.0 - 1e-3 && y > 1e-3 && y < 1.0 - 1e-3 && (x - y).abs() > 1e-3 && (x + y - 1.0).abs() > 1e-3);
        let want = match m.tile(cell) {
            Some(ascii::SOLID) => true,
            Some(ascii::RAMP_UP_RIGHT) => x + y > 1.0,
            Some(ascii::RAMP_DOWN_RIGHT) => y > x,
            _ => false,
        };
        let world = m.cell_corner(cell) + v(x, y) * m.cell_size();
        prop_assert_eq!(m.is_point_solid(world), want, "{:?} in {} at {:?}", m.tile(cell), cell, (x, y));
    }
}

#[test]
fn invalid_circles_and_boxes_overlap_nothing_not_even_temporaries() {
    use tileslide::{Aabb, Circle, Owner, Segment, SegmentFlags, TemporarySegment, Vec2};
    let mut map = tileslide::io::ascii::parse("###\n#.#\n###", "o.txt", 1.0).unwrap();
    map.add_temporary(TemporarySegment {
        segment: Segment::new(Vec2::new(1.2, 1.5), Vec2::new(1.8, 1.5)),
        normal: Vec2::Y,
        flags: SegmentFlags::SOLID,
        owner: Owner(1),
        velocity: Vec2::ZERO,
    })
    .unwrap();
    let center = Vec2::new(1.5, 1.5);
    for radius in [f32::INFINITY, f32::NAN, -1.0] {
        assert!(
            map.segments_overlapping_circle(&Circle::new(center, radius))
                .is_empty(),
            "{radius}"
        );
    }
    assert!(
        map.segments_overlapping_circle(&Circle::new(Vec2::new(f32::NAN, 1.0), 1.0))
            .is_empty()
    );
    let inverted = Aabb {
        min: Vec2::new(2.0, 2.0),
        max: Vec2::new(1.0, 1.0),
    };
    assert!(map.segments_overlapping_aabb(&inverted).is_empty());
    // A valid query still sees both the walls and the temporary segment.
    let all = map.segments_overlapping_circle(&Circle::new(center, 0.6));
    assert!(all.len() >= 5, "{all:?}");
}

/// Finite but absurd inputs: boxes, circles and points up to `f32::MAX`, where grid
/// coordinates and squared lengths overflowed (a box covering the whole map found
/// nothing; a huge circle's squared radius became infinite).
mod absurd_inputs {
    use tileslide::io::ascii;
    use tileslide::{
        Aabb, Circle, Owner, Segment, SegmentFlags, TemporarySegment, Vec2, limits::MAX_COORD,
    };

    fn room() -> tileslide::TileMap {
        let mut map = ascii::parse("###\n#.#\n###", "room.txt", 0.5).unwrap();
        map.add_temporary(TemporarySegment {
            segment: Segment::new(Vec2::new(MAX_COORD, 0.0), Vec2::new(MAX_COORD, 1.0)),
            normal: Vec2::new(-1.0, 0.0),
            flags: SegmentFlags::SOLID,
            owner: Owner(3),
            velocity: Vec2::ZERO,
        })
        .unwrap();
        map
    }

    /// Every active and temporary segment of the map.
    fn all(map: &tileslide::TileMap) -> usize {
        map.segments_overlapping_aabb(&Aabb::from_corners(
            Vec2::splat(-MAX_COORD),
            Vec2::splat(MAX_COORD),
        ))
        .len()
    }

    #[test]
    fn a_box_of_any_finite_size_finds_the_cells_it_covers() {
        // Cells of 0.5: the box scaled to cells would overflow.
        let map = room();
        let cells = |b: Aabb| map.cells_overlapping(&b).count();
        let huge = Aabb::from_corners(Vec2::splat(-f32::MAX), Vec2::splat(f32::MAX));
        assert_eq!(cells(huge), 9);
        let left = Aabb::from_corners(Vec2::splat(-3e38), Vec2::new(0.25, 3e38));
        assert_eq!(cells(left), 3);
        let corner = Aabb::from_corners(Vec2::splat(1.5), Vec2::splat(f32::MAX));
        assert_eq!(cells(corner), 1, "touching the far corner at (1.5, 1.5)");
        let beyond = Aabb::from_corners(Vec2::new(1.6, -f32::MAX), Vec2::splat(f32::MAX));
        assert_eq!(cells(beyond), 0);
    }

    #[test]
    fn a_box_of_any_finite_size_finds_what_it_covers() {
        let map = room();
        let every = all(&map);
        assert!(every > 5, "{every}");
        let huge = Aabb::from_corners(Vec2::splat(-f32::MAX), Vec2::splat(f32::MAX));
        assert_eq!(map.segments_overlapping_aabb(&huge).len(), every);
        let half = Aabb::from_corners(Vec2::new(-3e38, -3e38), Vec2::new(0.75, 3e38));
        let found = map.segments_overlapping_aabb(&half);
        assert!(!found.is_empty() && found.len() < every, "{}", found.len());
        // A box wholly beyond the range touches nothing, not even what lies on its edge.
        let beyond = Aabb::from_corners(Vec2::new(MAX_COORD * 2.0, -1e30), Vec2::splat(1e38));
        assert!(map.segments_overlapping_aabb(&beyond).is_empty());
    }

    #[test]
    fn a_circle_of_any_finite_centre_and_radius_finds_what_it_covers() {
        let map = room();
        let every = all(&map);
        let huge = Circle::new(Vec2::ZERO, 3e38);
        assert_eq!(map.segments_overlapping_circle(&huge).len(), every);
        // Centred far out on the room's middle row: a radius of exactly the distance to the
        // room's left side (x = 0) touches it, and the room (within the f64 test's
        // resolution there, 1e20 · 2⁻⁵³ ≈ 1e4), but not the temporary segment 2²⁴ away;
        // one float less (8.8e12) touches nothing.
        let far = Circle::new(Vec2::new(-1e20, 0.75), 1e20);
        let found = map.segments_overlapping_circle(&far);
        assert!(
            found
                .iter()
                .any(|o| o.segment.a.x == 0.0 && o.segment.b.x == 0.0),
            "{found:?}"
        );
        assert!(found.iter().all(|o| o.segment.a.x <= 1.5), "{found:?}");
        let short = Circle::new(Vec2::new(-1e20, 0.75), 1e20f32.next_down());
        assert!(map.segments_overlapping_circle(&short).is_empty());
    }

    #[test]
    fn points_far_out_are_not_solid() {
        let map = room();
        assert!(map.is_point_solid(Vec2::new(0.25, 0.25)));
        for p in [
            Vec2::splat(f32::MAX),
            Vec2::new(-3e38, 0.25),
            Vec2::new(0.25, 1e30),
        ] {
            assert!(!map.is_point_solid(p), "{p}");
        }
    }
}
