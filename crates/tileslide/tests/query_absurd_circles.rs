//! Proves that circle casts answer every finite input: centres from 10⁷ to 10³⁰ units from
//! the map (on either side), radii from a hundredth of a cell to `f32::MAX`.
//!
//! A far centre travels its exact line: rounding it to `f32` near the map would move the
//! line by a unit at 10⁷ and by 10²³ units at 10³⁰. Each hit is checked against a
//! brute force over every segment in `f64`: its centre lies on the caller's line at the
//! caller's `t` and touches its segment, and sphere tracing the path finds no point where
//! the circle is inside a segment before it. Each answer is also checked against the cast
//! of the same line from a start moved onto it near the map. A circle that holds every
//! segment gets the answer of the smallest circle within range that holds them too.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use crate::generators;
use crate::path_support;

use generators::{map_of, small_map_at};
use glam::DVec2;
use path_support::walls::point_segment_distance;
use proptest::prelude::*;
use tileslide::{
    CastError, Cell, CircleHit, Faces, QueryFilter, SegmentSource, TileMap, Vec2, limits::MAX_COORD,
};

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

/// Which segment a hit is on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Key {
    Tile(Cell, u32),
    Temporary(usize),
}

fn key_of(hit: &CircleHit) -> Key {
    match hit.source {
        SegmentSource::Tile { segment, .. } => Key::Tile(segment.cell, segment.index),
        SegmentSource::Temporary { index, .. } => Key::Temporary(index),
        // The brute force lists tile and temporary segments only: a hit on anything else
        // is one it cannot check.
        other => panic!("a segment source the brute force does not list: {other:?}"),
    }
}

/// A segment that can block a cast: its key and ends, in `f64`.
type Wall = (Key, DVec2, DVec2);

/// Every active and temporary segment with one of `filter`'s flags.
fn walls(map: &TileMap, filter: &QueryFilter) -> Vec<Wall> {
    let mut out = Vec::new();
    for row in 0..map.height() {
        for col in 0..map.width() {
            let cell = Cell::new(col, row);
            for (i, s) in map.active_segments(cell).enumerate() {
                if s.flags.intersects(filter.mask) {
                    let (a, b) = (s.segment.a.as_dvec2(), s.segment.b.as_dvec2());
                    out.push((Key::Tile(cell, i as u32), a, b));
                }
            }
        }
    }
    for (i, t) in map.temporaries().iter().enumerate() {
        if t.flags.intersects(filter.mask) {
            let (a, b) = (t.segment.a.as_dvec2(), t.segment.b.as_dvec2());
            out.push((Key::Temporary(i), a, b));
        }
    }
    out
}

/// The corners of the box of the map's rectangle and every temporary segment.
fn corners(map: &TileMap) -> [DVec2; 4] {
    let b = map.bounds();
    let (mut lo, mut hi) = (b.min.as_dvec2(), b.max.as_dvec2());
    for t in map.temporaries() {
        for p in [t.segment.a.as_dvec2(), t.segment.b.as_dvec2()] {
            lo = lo.min(p);
            hi = hi.max(p);
        }
    }
    [lo, hi, DVec2::new(lo.x, hi.y), DVec2::new(hi.x, lo.y)]
}

/// A circle cast whose line is known exactly: `through` is a point of it near the map.
#[derive(Clone, Copy, Debug)]
struct Cast {
    center: Vec2,
    radius: f32,
    motion: Vec2,
    through: DVec2,
}

impl Cast {
    fn dir(&self) -> DVec2 {
        self.motion.as_dvec2().normalize()
    }

    /// How far along the line `p` lies from `through`.
    fn along(&self, p: DVec2) -> f64 {
        (p - self.through).dot(self.dir())
    }

    /// How far `p` lies from the line.
    fn off_line(&self, p: DVec2) -> f64 {
        (p - self.through).perp_dot(self.dir()).abs()
    }

    fn at(&self, s: f64) -> DVec2 {
        self.through + self.dir() * s
    }

    /// Where the motion starts and ends along the line (the end `center + motion` is
    /// exact in `f64` wherever it lies near the map).
    fn span(&self) -> (f64, f64) {
        let c = self.center.as_dvec2();
        (self.along(c), self.along(c + self.motion.as_dvec2()))
    }

    /// How far `through` is from the farthest corner of the map's box, plus the radius
    /// and two cells: a circle this far along the line from `through` touches nothing.
    fn clear(&self, map: &TileMap) -> f64 {
        let far = corners(map)
            .iter()
            .map(|c| c.distance(self.through))
            .fold(0.0, f64::max);
        far + f64::from(self.radius) + 2.0 * f64::from(map.cell_size().max_element())
    }

    /// What rounding allows a hit to be off: a few `f32` roundings of the map's
    /// coordinates, the radius and the distance to the map; and what the `f32` quadratic
    /// of a rounded end loses from a distance `d` (its `b² − a·c` cancels down to `a·r²`
    /// from terms of `a·d²`, so the contact moves by about `ε·d²/r`).
    fn tolerance(&self, map: &TileMap) -> f64 {
        let extent = corners(map)
            .iter()
            .map(|c| c.abs().max_element())
            .fold(0.0, f64::max);
        let clear = self.clear(map);
        let quadratic = 8.0 * f64::from(f32::EPSILON) * clear * clear / f64::from(self.radius);
        (extent + clear) * 2f64.powi(-17) + quadratic
    }
}

/// The first point along the line from `from` to `to` where the circle of `cast` is more
/// than `depth` inside a segment of `walls`, by sphere tracing (the distance to the
/// segments changes no faster than the point moves, so a step of the distance less the
/// radius skips nothing; a step is at least `depth / 4`, which can skip only a point less
/// than `depth / 4` deeper still).
fn first_inside(cast: &Cast, walls: &[Wall], depth: f64, from: f64, to: f64) -> Option<f64> {
    let r = f64::from(cast.radius) - depth;
    let mut s = from;
    while s <= to {
        let p = cast.at(s);
        let d = walls
            .iter()
            .map(|&(_, a, b)| point_segment_distance(p, a, b))
            .fold(f64::INFINITY, f64::min);
        if d < r {
            return Some(s);
        }
        s += (d - r).max(depth / 4.0);
    }
    None
}

/// Checks one cast from far away against the brute force: a hit is sane, on the caller's
/// line at the caller's `t`, touches its segment, and its point lies on it; with
/// `Faces::Both` no point of the path before the hit has the circle inside a segment.
fn check_against_brute_force(
    map: &TileMap,
    cast: &Cast,
    filter: &QueryFilter,
) -> Result<Option<CircleHit>, TestCaseError> {
    let hit = map
        .cast_circle(cast.center, cast.radius, cast.motion, filter)
        .unwrap();
    let walls = walls(map, filter);
    let tol = cast.tolerance(map);
    let r = f64::from(cast.radius);
    let (start, end) = cast.span();
    let length = cast.motion.as_dvec2().length();
    if let Some(h) = hit {
        prop_assert!((0.0..=1.0).contains(&h.t), "{:?}: {:?}", cast, h);
        prop_assert!(
            h.center.is_finite() && h.point.is_finite(),
            "{:?}: {:?}",
            cast,
            h
        );
        prop_assert!(
            (h.normal.length() - 1.0).abs() < 1e-5,
            "{:?}: {:?}",
            cast,
            h
        );
        let c = h.center.as_dvec2();
        prop_assert!(cast.off_line(c) <= tol, "{:?}: off the line: {:?}", cast, h);
        let t = (cast.along(c) - start) / length;
        prop_assert!(
            (f64::from(h.t) - t).abs() <= 4.0 * f64::from(f32::EPSILON) * t + tol / length,
            "{:?}: t {} for {}",
            cast,
            h.t,
            t
        );
        // The contact: on the segment, a radius from the centre (which can be less than a
        // radius from the segment's flat side: a circle coming round an end from behind,
        // which the front face does not stop, meets the end's cap there).
        let &(_, a, b) = walls.iter().find(|w| w.0 == key_of(&h)).unwrap();
        let p = h.point.as_dvec2();
        prop_assert!(
            point_segment_distance(p, a, b) <= tol,
            "{:?}: point of {:?}",
            cast,
            h
        );
        let gap = c.distance(p) - r;
        prop_assert!(gap.abs() <= tol, "{:?}: {:?} is {} off", cast, h, gap);
        if filter.faces == Faces::Both {
            let gap = point_segment_distance(c, a, b) - r;
            prop_assert!(
                gap.abs() <= tol,
                "{:?}: {:?} is {} off its segment",
                cast,
                h,
                gap
            );
        }
    }
    if filter.faces == Faces::Both {
        let clear = cast.clear(map);
        let (from, to) = (start.max(-clear), end.min(clear));
        if let Some(s) = first_inside(cast, &walls, 4.0 * tol, from, to) {
            let h = hit.ok_or_else(|| {
                TestCaseError::fail(format!("{cast:?}: no hit, but inside at {s}"))
            })?;
            prop_assert!(
                cast.along(h.center.as_dvec2()) <= s + tol,
                "{:?}: {:?} comes after a point inside at {}",
                cast,
                h,
                s
            );
        }
    }
    Ok(hit)
}

/// Checks one cast from far away against the same line cast from a start moved onto it
/// near the map (rounded to `f32` there, which moves the line by no more than rounding the
/// map's own coordinates does), to the same end: the same segment at the same centre and
/// normal, unless the first of the two contacts only grazes (is as good as a miss).
fn check_against_moved_start(
    map: &TileMap,
    cast: &Cast,
    filter: &QueryFilter,
    hit: Option<CircleHit>,
) -> Result<(), TestCaseError> {
    let clear = cast.clear(map);
    let (_, end) = cast.span();
    let from = cast.at(-clear);
    let to = cast.at(end.min(clear));
    let moved = map
        .cast_circle(from.as_vec2(), cast.radius, (to - from).as_vec2(), filter)
        .unwrap();
    let tol = cast.tolerance(map);
    let r = f64::from(cast.radius);
    // A contact whose point the line passes a hair less than a radius from only grazes
    // it: rounding (the `f32` quadratic's, or the graze rule's) decides it either way.
    let grazes = |h: &CircleHit| cast.off_line(h.point.as_dvec2()) >= r - (1e-3 * r + tol);
    let along = |h: &CircleHit| cast.along(h.center.as_dvec2());
    match (hit, moved) {
        (None, None) => {}
        // The same contact, or two met at the same place (a tie that rounding breaks).
        (Some(h), Some(m)) if h.center.as_dvec2().distance(m.center.as_dvec2()) <= tol => {
            let turn = f64::from((h.normal - m.normal).length());
            // A segment's flat side and its rounded end meet a circle at the same place
            // when the contact lies within `r · turn` of the end: a tie between the two
            // that rounding breaks either way, each normal true to its own point.
            let ends = walls(map, filter)
                .into_iter()
                .find(|w| w.0 == key_of(&h))
                .map(|(_, a, b)| [a, b]);
            let at_end = |x: &CircleHit| {
                let p = x.point.as_dvec2();
                ends.is_some_and(|ends| ends.iter().any(|e| e.distance(p) <= r * turn + 4.0 * tol))
            };
            prop_assert!(
                key_of(&h) != key_of(&m)
                    || turn <= 1e-3 + 4.0 * tol / r
                    || grazes(&h)
                    || at_end(&h)
                    || at_end(&m),
                "{:?}: {:?} against {:?}",
                cast,
                h,
                m
            );
        }
        (Some(h), Some(m)) => {
            let first = if along(&h) <= along(&m) { h } else { m };
            prop_assert!(grazes(&first), "{:?}: {:?} against {:?}", cast, h, m);
        }
        (Some(h), None) | (None, Some(h)) => {
            prop_assert!(grazes(&h), "{:?}: {:?} against none", cast, h);
        }
    }
    Ok(())
}

/// Maps centred on the world origin (so that lines through it cross them), cornered at it,
/// or beside it.
fn map() -> impl Strategy<Value = TileMap> {
    small_map_at(|w, h, cell, k| match k {
        0 => -v(w as f32, h as f32) * cell * 0.5,
        1 => Vec2::ZERO,
        _ => v(-3.5, 12.25),
    })
}

/// A distance from 2²³ (about 10⁷) to 2¹⁰⁰ (about 10³⁰).
fn far() -> impl Strategy<Value = f32> {
    (23i32..=100, 1.0f32..2.0).prop_map(|(e, m)| m * 2f32.powi(e))
}

/// A direction with a component of at least 1/2.
fn direction() -> impl Strategy<Value = Vec2> {
    (-1.0f32..1.0, -1.0f32..1.0, any::<bool>())
        .prop_map(|(x, y, flip)| {
            if flip {
                v(y.signum(), x)
            } else {
                v(x, y.signum())
            }
        })
        .prop_map(|d| d * 0.5 + d.signum() * 0.5)
}

/// Casts from far away whose line is exact in `f32` whatever the distance, and enters a
/// map around the origin: through the origin (from `−dir·2^e` by `dir·2^(e+1)`, exact
/// multiples of the direction), or along an axis at any offset, either way.
fn far_cast(map: &TileMap) -> impl Strategy<Value = Cast> + use<> {
    let cell = map.cell_size().x;
    let [lo, hi, ..] = corners(map);
    let (lo, hi) = (lo.as_vec2(), hi.as_vec2());
    let radius = (0.01f32..3.0).prop_map(move |r| r * cell);
    let through_origin = (direction(), 23i32..=100, radius.clone()).prop_map(|(d, e, radius)| {
        let far = 2f32.powi(e);
        Cast {
            center: -d * far,
            radius,
            motion: d * (2.0 * far),
            through: DVec2::ZERO,
        }
    });
    let along_axis = (far(), 0.0f32..1.0, 1.2f32..3.0, 0usize..4, radius).prop_map(
        move |(far, across, k, way, radius)| {
            let (axis, sign) = (way % 2, if way < 2 { 1.0 } else { -1.0 });
            let mid = (lo + hi) * 0.5;
            let offset =
                lo[1 - axis] - radius + (hi[1 - axis] - lo[1 - axis] + 2.0 * radius) * across;
            let (mut center, mut motion, mut through) = (Vec2::ZERO, Vec2::ZERO, mid.as_dvec2());
            center[axis] = mid[axis] - sign * far;
            center[1 - axis] = offset;
            motion[axis] = sign * far * k;
            through[1 - axis] = f64::from(offset);
            Cast {
                center,
                radius,
                motion,
                through,
            }
        },
    );
    prop_oneof![through_origin, along_axis]
}

/// Casts from 10⁷ units up to 2³⁰ away, aimed at a point near the map in any direction
/// (both rounded to `f32`, so the line passes within a few units of the point), ending
/// before the map, in it or past it.
fn aimed_cast(map: &TileMap) -> impl Strategy<Value = Cast> + use<> {
    let cell = map.cell_size().x;
    let [lo, hi, ..] = corners(map);
    let target =
        (0.0f64..1.0, 0.0f64..1.0).prop_map(move |(x, y)| lo + (hi - lo) * DVec2::new(x, y));
    (
        target,
        direction(),
        1e7f64..1.07e9,
        0.8f64..3.0,
        0.01f32..3.0,
    )
        .prop_map(move |(p, d, far, k, r)| {
            let center = (p - d.as_dvec2() * far).as_vec2();
            let motion = ((p - center.as_dvec2()) * k).as_vec2();
            let (c, m) = (center.as_dvec2(), motion.as_dvec2());
            let through = c + m * ((p - c).dot(m) / m.length_squared());
            Cast {
                center,
                radius: r * cell,
                motion,
                through,
            }
        })
}

/// A map of [`map`] with 8 casts of `casts_for` it.
fn map_and_casts<S: Strategy<Value = Cast>>(
    casts_for: impl Fn(&TileMap) -> S,
) -> impl Strategy<Value = (TileMap, Vec<Cast>)> {
    map().prop_flat_map(move |m| {
        let casts = proptest::collection::vec(casts_for(&m), 8);
        (Just(m), casts)
    })
}

/// Checks every cast against the brute force and against its moved start.
fn check_casts(map: &TileMap, casts: &[Cast], filter: &QueryFilter) -> Result<(), TestCaseError> {
    for cast in casts {
        let hit = check_against_brute_force(map, cast, filter)?;
        check_against_moved_start(map, cast, filter, hit)?;
    }
    Ok(())
}

/// Front faces only, or `Faces::Both` when `both`.
fn front_or_both(both: bool) -> QueryFilter {
    if both {
        QueryFilter::both_sides()
    } else {
        QueryFilter::default()
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// Centres from 10⁷ to 10³⁰ away on exact lines through the map: the brute force's
    /// answer, and the answer of the same line cast from near the map.
    #[test]
    fn far_circle_casts_travel_their_exact_line(
        (map, casts) in map_and_casts(far_cast),
        both in any::<bool>(),
    ) {
        check_casts(&map, &casts, &front_or_both(both))?;
    }

    /// Centres from 10⁷ to 10⁹ away aimed at the map in any direction, ending anywhere.
    #[test]
    fn aimed_circle_casts_from_afar_match_the_brute_force(
        (map, casts) in map_and_casts(aimed_cast),
        both in any::<bool>(),
    ) {
        check_casts(&map, &casts, &front_or_both(both))?;
    }

    /// A circle of radius 2²⁵ to `f32::MAX` around a centre near the map holds every
    /// segment: it gets the answer of the smallest circle within range that holds every
    /// segment over the whole motion (its point aside, which is on the circle's edge).
    #[test]
    fn a_circle_holding_the_map_answers_as_the_smallest_that_holds_it(
        (map, center, motion) in map().prop_flat_map(|m| {
            let [lo, hi, ..] = corners(&m);
            let cell = m.cell_size().x;
            let center = (0.0f64..1.0, 0.0f64..1.0)
                .prop_map(move |(x, y)| (lo + (hi - lo) * DVec2::new(x, y)).as_vec2());
            let motion = (-4.0f32..4.0, -4.0f32..4.0).prop_map(move |(x, y)| v(x, y) * cell);
            (Just(m), center, motion)
        }),
        exponent in 25i32..=127,
        mantissa in 1.0f32..2.0,
        both in any::<bool>(),
    ) {
        let filter = front_or_both(both);
        let radius = (mantissa * 2f32.powi(exponent)).min(f32::MAX);
        let holding = corners(&map)
            .iter()
            .map(|c| c.distance(center.as_dvec2()))
            .fold(0.0, f64::max)
            + motion.as_dvec2().length()
            + f64::from(map.cell_size().x);
        let holding = holding as f32;
        let hit = map.cast_circle(center, radius, motion, &filter).unwrap();
        let small = map.cast_circle(center, holding, motion, &filter).unwrap();
        match (hit, small) {
            (None, None) => {}
            (Some(h), Some(s)) => {
                prop_assert_eq!(key_of(&h), key_of(&s), "{:?} against {:?}", h, s);
                prop_assert!((h.t - s.t).abs() <= 1e-5, "{:?} against {:?}", h, s);
                prop_assert!(h.center.distance(s.center) <= 1e-4 * holding, "{:?} against {:?}", h, s);
                prop_assert!((h.normal - s.normal).length() <= 1e-4, "{:?} against {:?}", h, s);
                let edge = h.center.as_dvec2() - h.normal.as_dvec2() * f64::from(radius);
                prop_assert!(
                    h.point.as_dvec2().distance(edge) <= f64::from(radius) * 1e-6,
                    "{:?}",
                    h
                );
            }
            (h, s) => prop_assert!(false, "{:?} against {:?}", h, s),
        }
    }
}

/// A one-row map `rows` of half-unit cells from the origin.
fn row_map(rows: &str) -> TileMap {
    map_of(rows, 0.5, Vec2::ZERO)
}

#[test]
fn a_circle_from_beyond_max_coord_stops_at_the_wall() {
    // A centre or radius beyond MAX_COORD hit nothing: the circle passed through the
    // wall it was cast at.
    let right = row_map("....#");
    let left = row_map("#....");
    for far in [MAX_COORD * 2.0, 1e20, 1e30, 1.5e38] {
        let hit = right
            .cast_circle(
                v(-far, 0.25),
                0.1,
                v(2.0 * far, 0.0),
                &QueryFilter::default(),
            )
            .unwrap()
            .unwrap_or_else(|| panic!("from {far}: no hit"));
        assert_eq!(hit.normal, v(-1.0, 0.0), "from {far}");
        assert!(
            (hit.center - v(1.9, 0.25)).length() < 1e-6,
            "from {far}: {hit:?}"
        );
        assert_eq!(hit.point, v(2.0, 0.25), "from {far}");
        let t = (f64::from(far) + 1.9) / (2.0 * f64::from(far));
        assert!((f64::from(hit.t) - t).abs() < 1e-7, "from {far}: {hit:?}");
        let hit = left
            .cast_circle(
                v(far, 0.25),
                0.1,
                v(-2.0 * far, 0.0),
                &QueryFilter::default(),
            )
            .unwrap()
            .unwrap_or_else(|| panic!("from {far}: no hit"));
        assert_eq!(hit.normal, v(1.0, 0.0), "from {far}");
        assert!(
            (hit.center - v(0.6, 0.25)).length() < 1e-6,
            "from {far}: {hit:?}"
        );
    }
}

#[test]
fn a_circle_from_afar_travels_its_exact_line() {
    // A wall facing left at x = 2 across a map centred on the origin; lines through the
    // origin from 10³⁰ away at slopes 1/4 and 3/8 meet it at y = x·slope.
    let map = map_of(
        "......#.\n......#.\n......#.\n......#.\n......#.\n......#.\n......#.\n......#.",
        1.0,
        v(-4.0, -4.0),
    );
    for dir in [v(1.0, 0.25), v(0.8, 0.3), v(1.0, -0.375)] {
        for far in [2f32.powi(24), 2f32.powi(60), 2f32.powi(100)] {
            let hit = map
                .cast_circle(-dir * far, 0.5, dir * (2.0 * far), &QueryFilter::default())
                .unwrap()
                .unwrap_or_else(|| panic!("{dir} from {far}: no hit"));
            let y = 1.5 * f64::from(dir.y) / f64::from(dir.x);
            assert_eq!(hit.normal, v(-1.0, 0.0), "{dir} from {far}");
            assert!(
                (hit.center.as_dvec2() - DVec2::new(1.5, y)).length() < 1e-6,
                "{dir} from {far}: {hit:?}"
            );
        }
    }
}

#[test]
fn a_circle_holding_the_map_stops_at_once_against_a_face_it_moves_towards() {
    let room = map_of("#####\n#...#\n#####", 1.0, Vec2::ZERO);
    let filter = QueryFilter::default();
    // From inside the room, moving right: the right wall's inner face, at once.
    let hit = room
        .cast_circle(v(2.5, 1.5), 1e30, v(1.0, 0.0), &filter)
        .unwrap()
        .unwrap();
    assert_eq!(hit.t, 0.0);
    assert_eq!(
        key_of(&hit),
        Key::Tile(Cell::new(4, 1), key_index(&room, 4, 1, v(-1.0, 0.0)))
    );
    assert_eq!((hit.center, hit.normal), (v(2.5, 1.5), v(-1.0, 0.0)));
    assert_eq!(hit.point, v(2.5 + 1e30, 1.5));
    // From 10³⁰ to the left, holding the room and moving towards it: the first face in
    // row order that faces the centre and that it moves towards is the left face of the
    // top-left cell, by its rounded top end (the room's corner).
    let hit = room
        .cast_circle(v(-1e30, 1.5), 3e38, v(1e30, 0.0), &filter)
        .unwrap()
        .unwrap();
    assert_eq!(hit.t, 0.0);
    assert!(
        matches!(key_of(&hit), Key::Tile(c, _) if c == Cell::new(0, 0)),
        "{hit:?}"
    );
    assert!((hit.normal - v(-1.0, 0.0)).length() < 1e-6, "{hit:?}");
    assert_eq!(hit.center, v(-1e30, 1.5));
    // Moving away from it, from the left or from above: nothing stops it.
    assert!(
        room.cast_circle(v(-1e30, 1.5), 3e38, v(-1e30, 0.0), &filter)
            .unwrap()
            .is_none()
    );
    assert!(
        room.cast_circle(v(1.5, -1e30), 3e38, v(0.0, -1e30), &filter)
            .unwrap()
            .is_none()
    );
}

/// The index in cell `(col, row)` of the active segment whose normal is `normal`.
fn key_index(map: &TileMap, col: u32, row: u32, normal: Vec2) -> u32 {
    map.active_segments(Cell::new(col, row))
        .position(|s| s.normal == normal)
        .unwrap() as u32
}

#[test]
fn a_radius_that_is_not_a_positive_finite_number_is_refused_naming_it() {
    let map = row_map("....#");
    let filter = QueryFilter::default();
    for radius in [0.0, -0.1, -1e30, f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        for center in [v(0.5, 0.25), v(-1e30, 0.25), v(f32::NAN, 0.25)] {
            let cast = map.cast_circle(center, radius, v(1e31, 0.0), &filter);
            assert!(
                matches!(cast, Err(CastError::InvalidRadius(r)) if r.to_bits() == radius.to_bits()),
                "radius {radius} from {center}: {cast:?}"
            );
        }
    }
}

#[test]
fn a_position_or_motion_that_is_not_finite_hits_nothing() {
    let map = row_map("....#");
    let filter = QueryFilter::default();
    for (center, motion) in [
        (v(f32::NAN, 0.25), v(1.0, 0.0)),
        (v(f32::NEG_INFINITY, 0.25), v(1.0, 0.0)),
        (v(-1e30, 0.25), v(f32::INFINITY, 0.0)),
        (v(-1e30, 0.25), v(f32::NAN, 0.0)),
    ] {
        assert!(
            map.cast_circle(center, 0.1, motion, &filter)
                .unwrap()
                .is_none(),
            "{center} by {motion}"
        );
    }
}
