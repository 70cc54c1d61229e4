//! Proves the seam culling and end-point continuity rules of `TileMap`: a boundary segment is
//! hidden exactly where an opposite-facing solid segment of the neighbour covers it (partial
//! covers leave the uncovered pieces), one-way platforms hide nothing, and each active
//! segment's `continues` names, for each end, the touching active segment whose normal is
//! closest to its own (never a back-to-back face), or nothing.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use crate::generators;

use std::sync::Arc;

use generators::{rows, tile_chars};
use proptest::prelude::*;
use tileslide::io::ascii;
use tileslide::{
    ActiveSegment, Cell, QueryFilter, Ray, Segment, SegmentFlags, SegmentRef, TileId, TileMap,
    TileSet, TileShape, Vec2,
};

/// A block filling the lower half of its cell (y down): `[0, 1] × [0.5, 1]`.
const HALF_LOW: TileId = TileId(10);
/// A small box on the left edge of its cell, covering y in `[0.25, 0.75]` of that edge.
const NUB_LEFT: TileId = TileId(11);

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

/// The ASCII tile set plus `h` (half-height block) and `n` (nub on the left edge).
fn tile_set() -> Arc<TileSet> {
    let mut set = ascii::tile_set(1.0).unwrap();
    set.insert(
        HALF_LOW,
        TileShape::polygon(&[v(0.0, 0.5), v(1.0, 0.5), v(1.0, 1.0), v(0.0, 1.0)]).unwrap(),
    )
    .unwrap();
    set.insert(
        NUB_LEFT,
        TileShape::polygon(&[v(0.0, 0.25), v(0.5, 0.25), v(0.5, 0.75), v(0.0, 0.75)]).unwrap(),
    )
    .unwrap();
    Arc::new(set)
}

fn tile_of(c: char) -> Option<TileId> {
    match c {
        'h' => Some(HALF_LOW),
        'n' => Some(NUB_LEFT),
        c => ascii::tile_for_char(c).unwrap(),
    }
}

/// A unit-cell map drawn as text, one line per row, top row first, in ASCII characters plus
/// `h` and `n`. Indentation and blank lines are ignored (empty cells are `.`).
fn map(drawing: &str) -> TileMap {
    let rows: Vec<&str> = drawing
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect();
    let width = rows[0].chars().count();
    assert!(rows.iter().all(|r| r.chars().count() == width));
    let tiles: Vec<_> = rows.iter().flat_map(|r| r.chars()).map(tile_of).collect();
    TileMap::from_tiles(
        tile_set(),
        width as u32,
        rows.len() as u32,
        Vec2::ZERO,
        &tiles,
    )
    .unwrap()
}

fn segments(m: &TileMap, col: u32, row: u32) -> Vec<ActiveSegment> {
    m.active_segments(Cell::new(col, row)).collect()
}

fn all_segments(m: &TileMap) -> Vec<(SegmentRef, ActiveSegment)> {
    let mut out = Vec::new();
    for row in 0..m.height() {
        for col in 0..m.width() {
            let cell = Cell::new(col, row);
            for (i, s) in m.active_segments(cell).enumerate() {
                out.push((
                    SegmentRef {
                        cell,
                        index: i as u32,
                    },
                    s,
                ));
            }
        }
    }
    out
}

const UP: Vec2 = Vec2::new(0.0, -1.0);
const DOWN: Vec2 = Vec2::new(0.0, 1.0);
const LEFT: Vec2 = Vec2::new(-1.0, 0.0);
const RIGHT: Vec2 = Vec2::new(1.0, 0.0);

// ---------------------------------------------------------------------------------------
// Culling
// ---------------------------------------------------------------------------------------

#[test]
fn full_neighbours_hide_the_shared_edges_of_both() {
    let m = map("##");
    assert_eq!(m.placed_segment_count(), 8);
    assert_eq!(m.active_segment_count(), 6);
    for (_, s) in all_segments(&m) {
        assert!(
            !(s.segment.a.x == 1.0 && s.segment.b.x == 1.0),
            "the seam x = 1 is active: {s:?}"
        );
    }
}

#[test]
fn half_height_neighbour_leaves_only_the_uncovered_part_active() {
    let m = map("#h");
    // The block's right face (1, 0)–(1, 1) is covered on y ∈ [0.5, 1] by the half block's
    // left face: the piece (1, 0)–(1, 0.5) stays, oriented like the tile segment.
    let right: Vec<_> = segments(&m, 0, 0)
        .into_iter()
        .filter(|s| s.normal == RIGHT)
        .collect();
    assert_eq!(right.len(), 1, "{right:?}");
    assert!(
        same_segment(right[0].segment, Segment::new(v(1.0, 0.0), v(1.0, 0.5))),
        "{right:?}"
    );
    assert_eq!(right[0].source, 1, "still names the tile's right edge");
    // The half block's left face is fully covered: hidden.
    assert!(segments(&m, 1, 0).iter().all(|s| s.normal != LEFT));
    assert_eq!(m.placed_segment_count(), 8);
    assert_eq!(m.active_segment_count(), 7);

    // Rays agree: a ray moving left above the half block meets the piece; one moving left
    // inside the half block's height meets no seam at x = 1.
    let h = m
        .cast_ray(
            Ray::between(v(1.75, 0.25), v(0.5, 0.25)),
            &QueryFilter::default(),
        )
        .unwrap();
    assert!(h.point.distance(v(1.0, 0.25)) < 1e-6, "{h:?}");
    assert_eq!(h.normal, RIGHT);
    let all = m.cast_ray_all(
        Ray::between(v(1.75, 0.75), v(0.25, 0.75)),
        &QueryFilter::both_sides(),
    );
    assert!(all.is_empty(), "{all:?}");
}

#[test]
fn half_height_neighbour_on_the_left_leaves_the_upper_part_of_the_left_face() {
    let m = map("h#");
    let left: Vec<_> = segments(&m, 1, 0)
        .into_iter()
        .filter(|s| s.normal == LEFT)
        .collect();
    assert_eq!(left.len(), 1, "{left:?}");
    assert!(
        same_segment(left[0].segment, Segment::new(v(1.0, 0.5), v(1.0, 0.0))),
        "{left:?}"
    );
}

#[test]
fn cover_in_the_middle_of_an_edge_leaves_two_pieces() {
    let m = map("#n");
    let right: Vec<_> = segments(&m, 0, 0)
        .into_iter()
        .filter(|s| s.normal == RIGHT)
        .collect();
    assert_eq!(right.len(), 2, "{right:?}");
    for piece in [
        Segment::new(v(1.0, 0.0), v(1.0, 0.25)),
        Segment::new(v(1.0, 0.75), v(1.0, 1.0)),
    ] {
        assert!(
            right.iter().any(|s| same_segment(s.segment, piece)),
            "{piece:?} in {right:?}"
        );
    }
    // The nub's left face is hidden; its other three faces stay.
    assert_eq!(segments(&m, 1, 0).len(), 3);
    assert!(segments(&m, 1, 0).iter().all(|s| s.normal != LEFT));
    assert_eq!(m.active_segment_count(), 3 + 2 + 3);
}

#[test]
fn two_half_blocks_side_by_side_hide_each_other_like_full_blocks() {
    let m = map("hh");
    assert_eq!(m.placed_segment_count(), 8);
    assert_eq!(m.active_segment_count(), 6);
}

#[test]
fn half_block_under_a_full_block_is_not_covered_on_top() {
    // The half block's top face lies inside its cell (y = 1.5), not on the boundary: it is
    // never a seam. The block above keeps its bottom face: nothing solid touches it.
    let m = map(r"
        #
        h
    ");
    assert_eq!(m.active_segment_count(), 8);
}

#[test]
fn ramps_hide_the_full_edges_they_share_with_neighbours() {
    // `/` has full right and bottom edges; `\` full left and bottom edges.
    let cases: [(&[&str], usize, usize); 7] = [
        (&[r"/#"], 7, 5),
        (&[r"#\"], 7, 5),
        (&[r"/\"], 6, 4),
        (&[r"\/"], 6, 6),
        (&[r"/", r"#"], 7, 5),
        (&[r"\", r"/"], 6, 6),
        (&[r"#", r"/"], 7, 7),
    ];
    for (rows, placed, active) in cases {
        let m = map(&rows.join("\n"));
        assert_eq!(m.placed_segment_count(), placed, "{rows:?}");
        assert_eq!(m.active_segment_count(), active, "{rows:?}");
    }
}

#[test]
fn one_way_platform_hides_nothing_and_is_hidden_by_a_solid_block_above() {
    // Block above the platform: the block's bottom stays (a platform hides nothing), the
    // platform's top is covered by the block.
    let m = map(r"
        #
        =
    ");
    assert_eq!(m.active_segment_count(), 4);
    assert!(segments(&m, 0, 1).is_empty());
    assert!(segments(&m, 0, 0).iter().any(|s| s.normal == DOWN));
    // Platform above a block: both stay.
    let m = map(r"
        =
        #
    ");
    assert_eq!(m.active_segment_count(), 5);
    // A ramp's bottom covers a platform below it too.
    let m = map(r"
        /
        =
    ");
    assert!(segments(&m, 0, 1).is_empty());
    // Platforms side by side are untouched.
    let m = map("===");
    assert_eq!(m.active_segment_count(), 3);
}

#[test]
fn map_border_does_not_hide_anything() {
    let m = map("#");
    assert_eq!(m.active_segment_count(), 4);
}

/// Which sides of each ASCII tile are full boundary edges, by (dc, dr) of the neighbour
/// across them, and the local index of that edge in the tile's shape.
fn full_edges(c: char) -> &'static [((i64, i64), u32)] {
    match c {
        // Square (0,0)→(1,0)→(1,1)→(0,1): top, right, bottom, left.
        '#' => &[((0, -1), 0), ((1, 0), 1), ((0, 1), 2), ((-1, 0), 3)],
        // `/` (0,1)→(1,1)→(1,0): bottom, right, slope.
        '/' => &[((0, 1), 0), ((1, 0), 1)],
        // `\` (0,0)→(0,1)→(1,1): left, bottom, slope.
        '\\' => &[((-1, 0), 0), ((0, 1), 1)],
        // `=`: its only segment lies on the top edge.
        '=' => &[((0, -1), 0)],
        _ => &[],
    }
}

/// True when a tile of char `c` has a solid full edge across from a neighbour at offset
/// `(dc, dr)`, i.e. on its own side facing back `(−dc, −dr)`.
fn covers(c: char, dc: i64, dr: i64) -> bool {
    c != '=' && full_edges(c).iter().any(|&(o, _)| o == (-dc, -dr))
}

fn ascii_map() -> impl Strategy<Value = (u32, u32, Vec<char>)> {
    (1u32..=12, 1u32..=12).prop_flat_map(|(w, h)| {
        let chars = tile_chars(
            &[(3, '.'), (3, '#'), (1, '/'), (1, '\\'), (1, '=')],
            (w * h) as usize,
        );
        (Just(w), Just(h), chars)
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    /// For ASCII tiles every boundary edge is either whole or hidden: it is hidden exactly
    /// when the neighbour across it has a solid full edge facing back; every other segment
    /// (slopes) is always active.
    #[test]
    fn ascii_tile_edges_are_hidden_exactly_when_the_neighbour_covers_them((w, h, chars) in ascii_map()) {
        let m = map(&rows(w, &chars));
        let at = |c: i64, r: i64| -> char {
            if c < 0 || r < 0 || c >= w as i64 || r >= h as i64 {
                '.'
            } else {
                chars[(r * w as i64 + c) as usize]
            }
        };
        for row in 0..h {
            for col in 0..w {
                let c = at(col as i64, row as i64);
                let Some(id) = tile_of(c) else { continue };
                let shape = m.tile_set().shape(id).unwrap();
                let mut want: Vec<u32> = (0..shape.segments().len() as u32)
                    .filter(|&i| {
                        match full_edges(c).iter().find(|&&(_, j)| j == i) {
                            Some(&((dc, dr), _)) => {
                                !covers(at(col as i64 + dc, row as i64 + dr), dc, dr)
                            }
                            None => true,
                        }
                    })
                    .collect();
                want.sort();
                let got: Vec<ActiveSegment> = segments(&m, col, row);
                let mut got_sources: Vec<u32> = got.iter().map(|s| s.source).collect();
                got_sources.sort();
                prop_assert_eq!(&got_sources, &want, "cell ({}, {}) '{}' in\n{}", col, row, c, rows(w, &chars));
                // Active pieces of ASCII tiles are always whole tile segments.
                let corner = m.cell_corner(Cell::new(col, row));
                for s in got {
                    let t = shape.segments()[s.source as usize];
                    let whole = Segment::new(corner + t.a, corner + t.b);
                    prop_assert!(same_segment(s.segment, whole), "{:?} vs {:?}", s.segment, whole);
                    prop_assert_eq!(s.normal, t.normal);
                    prop_assert_eq!(s.flags, t.flags);
                    prop_assert_eq!(s.tile, id);
                    // Every active segment runs with its normal on the right of a → b.
                    prop_assert!(s.segment.delta().perp_dot(s.normal) < 0.0, "{:?}", s);
                }
            }
        }
    }
}

// ---------------------------------------------------------------------------------------
// Continuity
// ---------------------------------------------------------------------------------------

/// The active segment `r` names, which must exist.
fn follow(m: &TileMap, r: Option<SegmentRef>) -> (SegmentRef, ActiveSegment) {
    let r = r.expect("a continuation");
    (r, m.active_segment(r).expect("the continuation exists"))
}

fn touches(s: &ActiveSegment, p: Vec2) -> bool {
    s.segment.a.distance(p) < 1e-5 || s.segment.b.distance(p) < 1e-5
}

/// Which end of `s` (0 for `segment.a`, 1 for `segment.b`) is at `p`. Active segments may
/// run either way along their line, so the tests name ends by position.
fn end_at(s: &ActiveSegment, p: Vec2) -> usize {
    if s.segment.a == p {
        0
    } else if s.segment.b == p {
        1
    } else {
        panic!("{p:?} is not an end of {s:?}")
    }
}

/// The same segment whichever way it runs.
fn same_segment(a: Segment, b: Segment) -> bool {
    (a.a == b.a && a.b == b.b) || (a.a == b.b && a.b == b.a)
}

#[test]
fn flat_floor_top_faces_continue_into_their_neighbours_at_both_ends() {
    let m = map(r"
        ........
        ########
    ");
    for col in 1..7u32 {
        let top = segments(&m, col, 1)
            .into_iter()
            .find(|s| s.normal == UP)
            .unwrap();
        for (end, point) in [(0, top.segment.a), (1, top.segment.b)] {
            let (r, next) = follow(&m, top.continues[end]);
            assert_eq!(next.normal, UP, "col {col} end {end}");
            assert!(touches(&next, point), "col {col} end {end}: {next:?}");
            // The neighbour on that side, not the cell itself.
            let want = if point.x < top.segment.a.x.max(top.segment.b.x) {
                col - 1
            } else {
                col + 1
            };
            assert_eq!(r.cell, Cell::new(want, 1), "col {col} end {end}");
        }
    }
}

#[test]
fn outer_corner_of_a_block_continues_the_top_face_into_the_side_face() {
    let m = map(r"
        ....
        .##.
        ....
    ");
    // Top of (2, 1) runs (2, 1) → (3, 1); at (3, 1) it turns down the right face of (2, 1).
    let top = segments(&m, 2, 1)
        .into_iter()
        .find(|s| s.normal == UP)
        .unwrap();
    let corner = v(3.0, 1.0);
    let (r, side) = follow(&m, top.continues[end_at(&top, corner)]);
    assert_eq!(r.cell, Cell::new(2, 1));
    assert_eq!(side.normal, RIGHT);
    // And the side face's upper end continues back into the top face.
    let (_, back) = follow(&m, side.continues[end_at(&side, corner)]);
    assert_eq!(back.normal, UP);
    // The other end of the floor: top of (1, 1) at (1, 1) turns into the left face.
    let top = segments(&m, 1, 1)
        .into_iter()
        .find(|s| s.normal == UP)
        .unwrap();
    assert_eq!(
        follow(&m, top.continues[end_at(&top, v(1.0, 1.0))])
            .1
            .normal,
        LEFT
    );
}

#[test]
fn lone_one_way_platform_ends_do_not_continue() {
    let m = map(r"
        ...
        .=.
        ...
    ");
    let platform = segments(&m, 1, 1);
    assert_eq!(platform.len(), 1);
    assert_eq!(platform[0].continues, [None, None]);
}

#[test]
fn row_of_one_way_platforms_continues_inside_and_stops_at_its_ends() {
    let m = map(".===.");
    let left = segments(&m, 1, 0)[0];
    let mid = segments(&m, 2, 0)[0];
    let right = segments(&m, 3, 0)[0];
    let link = |s: &ActiveSegment, x: f32| s.continues[end_at(s, v(x, 0.0))];
    assert_eq!(link(&left, 1.0), None);
    assert_eq!(link(&right, 4.0), None);
    assert_eq!(follow(&m, link(&left, 2.0)).0.cell, Cell::new(2, 0));
    assert_eq!(follow(&m, link(&mid, 2.0)).0.cell, Cell::new(1, 0));
    assert_eq!(follow(&m, link(&mid, 3.0)).0.cell, Cell::new(3, 0));
    assert_eq!(follow(&m, link(&right, 3.0)).0.cell, Cell::new(2, 0));
}

#[test]
fn valley_between_two_ramps_links_slope_to_slope() {
    let m = map(r"\/");
    let slope = |col| {
        segments(&m, col, 0)
            .into_iter()
            .find(|s| s.normal.x != 0.0 && s.normal.y != 0.0)
            .unwrap()
    };
    let (left, right) = (slope(0), slope(1));
    // They meet at (1, 1): each continues into the other there.
    let bottom = v(1.0, 1.0);
    assert_eq!(
        follow(&m, left.continues[end_at(&left, bottom)]).0.cell,
        Cell::new(1, 0)
    );
    assert_eq!(
        follow(&m, right.continues[end_at(&right, bottom)]).0.cell,
        Cell::new(0, 0)
    );
}

#[test]
fn ramp_foot_and_floor_continue_into_each_other() {
    let m = map(r"
        ..../
        #####
    ");
    // The slope of `/` in (4, 0) runs (5, 0) → (4, 1); the floor's top reaches (4, 1) from
    // the left (the top of (4, 1) is hidden under the ramp).
    let slope = segments(&m, 4, 0)
        .into_iter()
        .find(|s| s.normal.x < 0.0 && s.normal.y < 0.0)
        .unwrap();
    let foot = v(4.0, 1.0);
    let (r, floor) = follow(&m, slope.continues[end_at(&slope, foot)]);
    assert_eq!((r.cell, floor.normal), (Cell::new(3, 1), UP));
    let (r, up) = follow(&m, floor.continues[end_at(&floor, foot)]);
    assert_eq!(r.cell, Cell::new(4, 0));
    assert_eq!(up.segment, slope.segment);
}

#[test]
fn partly_hidden_piece_continues_into_the_lower_neighbours_top() {
    let m = map("#h");
    // The piece (1, 0)–(1, 0.5) of the block's right face ends at (1, 0.5), where the half
    // block's top face (1, 0.5)–(2, 0.5) starts: a concave corner, which continues.
    let piece = segments(&m, 0, 0)
        .into_iter()
        .find(|s| s.normal == RIGHT)
        .unwrap();
    let (r, top) = follow(&m, piece.continues[end_at(&piece, v(1.0, 0.5))]);
    assert_eq!(r.cell, Cell::new(1, 0));
    assert_eq!(top.normal, UP);
    assert_eq!(top.segment.a.min(top.segment.b), v(1.0, 0.5));
}

fn mixed_map() -> impl Strategy<Value = Vec<String>> {
    (1usize..=10, 1usize..=10).prop_flat_map(|(w, h)| {
        tile_chars(
            &[
                (4, '.'),
                (3, '#'),
                (1, '/'),
                (1, '\\'),
                (1, '='),
                (1, 'h'),
                (1, 'n'),
            ],
            w * h,
        )
        .prop_map(move |chars| chars.chunks(w).map(|r| r.iter().collect()).collect())
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    /// Each end's link, checked against every active segment of the map: `None` exactly
    /// when no other active segment touches that end (except back-to-back faces), and
    /// otherwise a touching segment whose normal is as close as any other's.
    #[test]
    fn links_follow_the_closest_normal_rule_over_all_segments(rows in mixed_map()) {
        let m = map(&rows.join("\n"));
        let all = all_segments(&m);
        // Join tolerance of `tiles::continuity`: 1e-4 of a cell.
        let tol = 1e-4f32;
        for (me, s) in &all {
            for (end, p) in [(0usize, s.segment.a), (1, s.segment.b)] {
                let candidates: Vec<(SegmentRef, f32)> = all
                    .iter()
                    .filter(|(r, _)| r != me)
                    .filter(|(_, o)| o.segment.a.distance(p) <= tol || o.segment.b.distance(p) <= tol)
                    .map(|(r, o)| (*r, s.normal.dot(o.normal)))
                    .filter(|(_, score)| *score >= -0.999)
                    .collect();
                let best = candidates.iter().map(|c| c.1).fold(f32::NEG_INFINITY, f32::max);
                match s.continues[end] {
                    None => prop_assert!(
                        candidates.is_empty(),
                        "{:?} end {} has no link but could continue into {:?}\n{}",
                        me, end, candidates, rows.join("\n")
                    ),
                    Some(r) => {
                        let chosen = candidates.iter().find(|c| c.0 == r);
                        prop_assert!(
                            chosen.is_some_and(|c| c.1 == best),
                            "{:?} end {} links {:?}, best of {:?}\n{}",
                            me, end, r, candidates, rows.join("\n")
                        );
                    }
                }
            }
        }
    }

    /// No two active solid segments of neighbouring cells coincide face to face: seams are
    /// gone wherever both sides are solid, whatever the shapes.
    #[test]
    fn no_active_solid_segments_overlap_face_to_face(rows in mixed_map()) {
        let m = map(&rows.join("\n"));
        let all = all_segments(&m);
        for (ra, a) in &all {
            for (rb, b) in &all {
                if ra.cell == rb.cell
                    || !a.flags.contains(SegmentFlags::SOLID)
                    || !b.flags.contains(SegmentFlags::SOLID)
                    || a.normal.dot(b.normal) > -0.999
                {
                    continue;
                }
                // Collinear and overlapping by more than a point?
                let d = a.segment.b - a.segment.a;
                let off = |p: Vec2| d.perp_dot(p - a.segment.a).abs() / d.length();
                if off(b.segment.a) > 1e-5 || off(b.segment.b) > 1e-5 {
                    continue;
                }
                let along = |p: Vec2| (p - a.segment.a).dot(d) / d.length_squared();
                let (lo, hi) = (along(b.segment.a).min(along(b.segment.b)), along(b.segment.a).max(along(b.segment.b)));
                let overlap = hi.min(1.0) - lo.max(0.0);
                prop_assert!(
                    overlap <= 1e-5,
                    "{:?} {:?} and {:?} {:?} overlap face to face\n{}",
                    ra, a.segment, rb, b.segment, rows.join("\n")
                );
            }
        }
    }
}
