//! Proves that the grid ray casts (`cast_ray`, `cast_ray_all`) agree with a brute-force
//! cast against **every** active segment of the map and every temporary segment, on random
//! ASCII maps, cell sizes and origins, for random rays, rays on exact grid lines and rays
//! through exact lattice points, under every kind of filter: the same hits, and for
//! `cast_ray` the globally nearest one.
//!
//! Tolerance: `t` may differ by at most `T_TOL = 1e-5` (a fraction of the ray's length).
//! Both sides run the same f32 intersection, but the brute force sees a segment through its
//! public end points `a` and `b = a + e` and recomputes `b − a`, which can differ from the
//! stored `e` in the last bit when the origin is not a dyadic number; on a well-conditioned
//! crossing that moves `t` by a few ulps (~1e-7), far below the tolerance. Contacts that f32
//! cannot decide (phantoms and near-parallel crossings, see `f64_verdict`) are arbitrated
//! in f64; every other hit must be found exactly, including contacts at a single point
//! (segment end points, cell corners, the map's border). Two smaller properties aim
//! straight at the bug classes found this way: rays along grid lines, and rays crossing the
//! map's border at a lattice point.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use crate::generators;

use generators::{query_filter, rows, tile_chars, tile_map, varied_tile_chars};
use proptest::prelude::*;
use tileslide::{
    Cell, Owner, QueryFilter, Ray, RayHit, Segment, SegmentFlags, SegmentSource, TemporarySegment,
    TileMap, Vec2, geometry::cast_ray_segment,
};

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

/// Largest allowed difference in `t` between the grid walk and the brute force.
const T_TOL: f32 = 1e-5;

/// A random world: an ASCII map on a cell size and origin, plus temporary segments.
#[derive(Clone, Debug)]
struct World {
    width: u32,
    height: u32,
    chars: Vec<char>,
    cell: f32,
    origin: Vec2,
    temporaries: Vec<TemporarySegment>,
}

impl World {
    fn map(&self) -> TileMap {
        let mut map = tile_map(self.width, &self.chars, self.cell, self.origin);
        for t in &self.temporaries {
            map.add_temporary(*t).unwrap();
        }
        map
    }

    /// A point given in grid units (cells), in world coordinates.
    fn world(&self, g: Vec2) -> Vec2 {
        self.origin + g * self.cell
    }

    /// The map drawn as text, for failure messages.
    fn ascii(&self) -> String {
        rows(self.width, &self.chars)
    }
}

/// Cell sizes: powers of two, so lattice points are exact.
const CELLS: [f32; 4] = [1.0, 0.5, 32.0, 0.25];
/// Dyadic origins keep lattice points exact; 0.1 and −7.3 do not (see the file comment).
const ORIGINS: [(f32, f32); 6] = [
    (0.0, 0.0),
    (-3.5, 12.25),
    (-100.0, -64.0),
    (1000.0, -8.0),
    (0.1, 0.1),
    (-7.3, 2.9),
];

fn temporary(width: u32, height: u32) -> impl Strategy<Value = (Vec2, Vec2, bool, bool, u64)> {
    let (w, h) = (width as f32, height as f32);
    (
        (-2.0f32..w + 2.0, -2.0f32..h + 2.0),
        (-2.0f32..w + 2.0, -2.0f32..h + 2.0),
        any::<bool>(),
        any::<bool>(),
        0u64..3,
    )
        .prop_map(|((ax, ay), (bx, by), flip, solid, owner)| {
            (Vec2::new(ax, ay), Vec2::new(bx, by), flip, solid, owner)
        })
}

fn world() -> impl Strategy<Value = World> {
    (
        1u32..=24,
        1u32..=24,
        0usize..CELLS.len(),
        0usize..ORIGINS.len(),
    )
        .prop_flat_map(|(width, height, cell, origin)| {
            (
                Just(width),
                Just(height),
                varied_tile_chars((width * height) as usize),
                Just(CELLS[cell]),
                Just(ORIGINS[origin]),
                proptest::collection::vec(temporary(width, height), 0..3),
            )
        })
        .prop_map(|(width, height, chars, cell, (ox, oy), temps)| {
            let origin = Vec2::new(ox, oy);
            let temporaries = temps
                .into_iter()
                .filter(|(a, b, ..)| (*a - *b).length() > 0.01)
                .map(|(a, b, flip, solid, owner)| {
                    let (a, b) = (origin + a * cell, origin + b * cell);
                    let perp = (b - a).perp();
                    TemporarySegment {
                        segment: Segment::new(a, b),
                        normal: if flip { -perp } else { perp },
                        flags: if solid {
                            SegmentFlags::SOLID
                        } else {
                            SegmentFlags::ONE_WAY
                        },
                        owner: Owner(owner),
                        velocity: Vec2::ZERO,
                    }
                })
                .collect();
            World {
                width,
                height,
                chars,
                cell,
                origin,
                temporaries,
            }
        })
}

/// A ray in grid units (cells); the test maps it to world coordinates.
#[derive(Clone, Copy, Debug)]
enum GridRay {
    /// Arbitrary end points, inside or up to 3 cells outside the map.
    Free(Vec2, Vec2),
    /// Both ends on lattice points (it passes through every lattice point on its line).
    Lattice(Vec2, Vec2),
    /// Both ends on half-lattice points: through cell corners, edge midpoints and centres.
    HalfLattice(Vec2, Vec2),
    /// Along the horizontal grid line `y = line`, or the vertical one if `vertical`.
    OnGridLine {
        line: i32,
        from: f32,
        to: f32,
        vertical: bool,
    },
    /// Through the lattice point `at`, in direction `dir` (small integers), from
    /// `at − before·dir` to `at + after·dir`: any slope, not only diagonals.
    ThroughPoint {
        at: Vec2,
        dir: Vec2,
        before: f32,
        after: f32,
    },
}

impl GridRay {
    fn ends(self) -> (Vec2, Vec2) {
        match self {
            GridRay::Free(a, b) | GridRay::Lattice(a, b) | GridRay::HalfLattice(a, b) => (a, b),
            GridRay::OnGridLine {
                line,
                from,
                to,
                vertical,
            } => {
                let l = line as f32;
                if vertical {
                    (Vec2::new(l, from), Vec2::new(l, to))
                } else {
                    (Vec2::new(from, l), Vec2::new(to, l))
                }
            }
            GridRay::ThroughPoint {
                at,
                dir,
                before,
                after,
            } => (at - dir * before, at + dir * after),
        }
    }
}

fn grid_ray(width: u32, height: u32) -> impl Strategy<Value = GridRay> {
    let (w, h) = (width as i32, height as i32);
    let (wf, hf) = (width as f32, height as f32);
    let free_point = (-3.0f32..wf + 3.0, -3.0f32..hf + 3.0).prop_map(|(x, y)| Vec2::new(x, y));
    let lattice = (-2..=w + 2, -2..=h + 2).prop_map(|(x, y)| Vec2::new(x as f32, y as f32));
    let half = (-4..=2 * w + 4, -4..=2 * h + 4)
        .prop_map(|(x, y)| Vec2::new(x as f32 * 0.5, y as f32 * 0.5));
    let snapped = prop_oneof![
        (-3.0f32..wf.max(hf) + 3.0),
        (-3i32..=w.max(h) + 3).prop_map(|i| i as f32 * 0.5),
    ];
    prop_oneof![
        3 => (free_point.clone(), free_point).prop_map(|(a, b)| GridRay::Free(a, b)),
        2 => (lattice.clone(), lattice.clone()).prop_map(|(a, b)| GridRay::Lattice(a, b)),
        2 => (half.clone(), half).prop_map(|(a, b)| GridRay::HalfLattice(a, b)),
        2 => (-1..=w.max(h) + 1, snapped.clone(), snapped, any::<bool>())
            .prop_map(|(line, from, to, vertical)| GridRay::OnGridLine { line, from, to, vertical }),
        2 => (lattice, (-4i32..=4, -4i32..=4), 1u32..=8, 0u32..=8).prop_map(
            |(at, (dx, dy), before, after)| GridRay::ThroughPoint {
                at,
                dir: Vec2::new(dx as f32, dy as f32),
                before: before as f32 * 0.25,
                after: after as f32 * 0.25,
            }
        ),
    ]
}

/// The number of cases: `PROPTEST_CASES` if set, else `default`.
fn cases_or(default: u32) -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// Which segment a hit is on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Key {
    Tile(Cell, u32),
    Temporary(usize),
}

fn key_of(hit: &RayHit) -> Key {
    match hit.source {
        SegmentSource::Tile { segment, .. } => Key::Tile(segment.cell, segment.index),
        SegmentSource::Temporary { index, .. } => Key::Temporary(index),
        // The brute force lists tile and temporary segments only: a hit on anything else
        // is one it cannot check.
        other => panic!("a segment source the brute force does not list: {other:?}"),
    }
}

/// One candidate segment of the brute force: every active segment and temporary segment.
struct Candidate {
    key: Key,
    segment: Segment,
    normal: Vec2,
    flags: SegmentFlags,
    owner: Option<Owner>,
}

fn candidates(map: &TileMap) -> Vec<Candidate> {
    let mut out = Vec::new();
    for row in 0..map.height() {
        for col in 0..map.width() {
            let cell = Cell::new(col, row);
            for (i, s) in map.active_segments(cell).enumerate() {
                out.push(Candidate {
                    key: Key::Tile(cell, i as u32),
                    segment: s.segment,
                    normal: s.normal,
                    flags: s.flags,
                    owner: None,
                });
            }
        }
    }
    for (i, t) in map.temporaries().iter().enumerate() {
        out.push(Candidate {
            key: Key::Temporary(i),
            segment: t.segment,
            normal: t.normal,
            flags: t.flags,
            owner: Some(t.owner),
        });
    }
    out
}

/// A hit of the brute force.
#[derive(Clone, Copy, Debug)]
struct BruteHit {
    key: Key,
    t: f32,
    normal: Vec2,
    /// Whether the grid casts must report it (see `verdict`).
    required: bool,
    /// How far their `t` may differ from this one.
    t_tol: f32,
}

/// Every hit, by testing every candidate segment.
fn brute_hits(cands: &[Candidate], ray: &Ray, filter: &QueryFilter) -> Vec<BruteHit> {
    if !ray.is_finite() {
        return Vec::new();
    }
    cands
        .iter()
        .filter(|c| filter.accepts(ray.delta, c.normal, c.flags, c.owner))
        .filter_map(|c| {
            cast_ray_segment(ray, &c.segment).map(|h| {
                let (required, t_tol) = verdict(ray, &c.segment);
                BruteHit {
                    key: c.key,
                    t: h.t,
                    normal: c.normal,
                    required,
                    t_tol,
                }
            })
        })
        .collect()
}

/// Whether an f32 hit of `cast_ray_segment` must be found by the grid casts, and with what
/// tolerance on `t`, decided by redoing its arithmetic in f64 (where the products of the f32
/// inputs are exact):
/// - if every f32 step (`b − a`, `a − origin`, the three cross products) is exact, the f32
///   verdict is the exact one: the hit is required, with `T_TOL`. This holds on dyadic
///   coordinates, so contacts at a single point (end points, corners, the border, `t` = 0
///   or 1) are always required there;
/// - otherwise the hit is required only if it lies inside the hit region (`0 ≤ t, s ≤ 1`) by
///   more than the first-order rounding bounds of the f32 numerators and denominator
///   (|Δ| ≲ 2ε·|u||v| for each cross product of u and v), and `t` is compared within
///   `max(T_TOL, 2 · bound on Δt)`: at a shallow angle f32 Cramer's rule cannot do better
///   (a ray meant to run along a ramp, on an origin that is not dyadic, crosses it at
///   ~1e-7 rad and its f32 `t` can be anywhere along the ray). A contact closer to the
///   edge of the hit region than rounding can resolve is optional: either answer is right.
fn verdict(ray: &Ray, s: &Segment) -> (bool, f32) {
    let (o, d) = (ray.origin.as_dvec2(), ray.delta.as_dvec2());
    let (a, b) = (s.a.as_dvec2(), s.b.as_dvec2());
    let (e, w) = (b - a, a - o);
    let (den, tn, sn) = (d.perp_dot(e), w.perp_dot(e), w.perp_dot(d));
    // The f32 steps of the kernel, replayed.
    let (e32, w32) = (s.b - s.a, s.a - ray.origin);
    let exact = e32.as_dvec2() == e
        && w32.as_dvec2() == w
        && f64::from(ray.delta.perp_dot(e32)) == den
        && f64::from(w32.perp_dot(e32)) == tn
        && f64::from(w32.perp_dot(ray.delta)) == sn;
    if exact {
        return (true, T_TOL);
    }
    // Positive denominator (negating is exact).
    let sign = if den < 0.0 { -1.0 } else { 1.0 };
    let (den, tn, sn) = (den * sign, tn * sign, sn * sign);
    let eps = f64::from(f32::EPSILON);
    let err_den = 2.0 * eps * d.length() * e.length();
    let err_tn = 2.0 * eps * w.length() * e.length();
    let err_sn = 2.0 * eps * w.length() * d.length();
    let inside = den > err_den
        && tn > err_tn
        && den - tn > err_tn + err_den
        && sn > err_sn
        && den - sn > err_sn + err_den;
    let t_bound = (err_tn + (tn / den).abs() * err_den) / (den - err_den).max(f64::MIN_POSITIVE);
    (inside, T_TOL.max(2.0 * t_bound as f32))
}

/// Compares `cast_ray` and `cast_ray_all` with the brute force for one ray and filter.
fn check(
    w: &World,
    map: &TileMap,
    cands: &[Candidate],
    ray: Ray,
    filter: &QueryFilter,
) -> Result<(), TestCaseError> {
    let brute = brute_hits(cands, &ray, filter);
    let context = || {
        format!(
            "\nmap (cell {}, origin {:?}):\n{}\ntemporaries {:?}\nray {ray:?}\nfilter {filter:?}\nbrute {brute:?}",
            w.cell,
            w.origin,
            w.ascii(),
            w.temporaries
        )
    };
    // Every hit the grid casts report must be a real one: a segment the brute force hits,
    // with its normal, at the same t within that hit's tolerance (any t for an optional hit).
    let is_real = |h: &RayHit| {
        brute.iter().any(|b| {
            b.key == key_of(h)
                && b.normal == h.normal
                && (!b.required || (b.t - h.t).abs() <= b.t_tol)
        })
    };

    // Hits the grid casts must find: every one that is not optional.
    let strict: Vec<BruteHit> = brute.iter().filter(|b| b.required).copied().collect();

    // cast_ray: the globally nearest hit. It lies no later than the nearest required hit
    // (an optional one may be nearer).
    let nearest = strict
        .iter()
        .map(|b| b.t + b.t_tol)
        .fold(f32::INFINITY, f32::min);
    let got = map.cast_ray(ray, filter);
    match got {
        None => prop_assert!(
            strict.is_empty(),
            "cast_ray missed; nearest required hit at t ≤ {nearest}{}",
            context()
        ),
        Some(hit) => {
            prop_assert!(
                is_real(&hit),
                "cast_ray reported {hit:?}, not a segment hit at that t{}",
                context()
            );
            prop_assert!(
                hit.t <= nearest,
                "cast_ray t = {} but nearest is {nearest}: {hit:?}{}",
                hit.t,
                context()
            );
            prop_assert!(
                hit.point.distance(ray.point_at(hit.t)) <= 1e-4 * w.cell.max(1.0),
                "hit point {:?} is not the point at t{}",
                hit.point,
                context()
            );
            prop_assert!((0.0..=1.0).contains(&hit.t));
        }
    }

    // cast_ray_all: the same set of segments, each at its t, sorted.
    let all = map.cast_ray_all(ray, filter);
    prop_assert!(
        all.windows(2).all(|p| p[0].t <= p[1].t),
        "cast_ray_all not sorted: {all:?}{}",
        context()
    );
    for a in &all {
        prop_assert!(
            is_real(a),
            "cast_ray_all reported {a:?}, not a real hit{}",
            context()
        );
    }
    let mut got_keys: Vec<Key> = all.iter().map(key_of).collect();
    got_keys.sort();
    let count = got_keys.len();
    got_keys.dedup();
    prop_assert_eq!(
        count,
        got_keys.len(),
        "duplicates in {:?}{}",
        all,
        context()
    );
    // Every hit it must find is there (the rest are real: checked above).
    for b in &strict {
        prop_assert!(
            got_keys.contains(&b.key),
            "cast_ray_all misses {b:?}: got {all:?}{}",
            context()
        );
    }
    // cast_ray's hit is cast_ray_all's first (up to optional hits).
    if let Some(hit) = got {
        let first = all.first();
        prop_assert!(
            first.is_some_and(|f| f.t <= hit.t + T_TOL),
            "cast_ray_all starts at {first:?}, cast_ray gave {hit:?}{}",
            context()
        );
    }
    Ok(())
}

fn world_and_rays() -> impl Strategy<Value = (World, Vec<(GridRay, QueryFilter)>)> {
    world().prop_flat_map(|w| {
        let rays = proptest::collection::vec((grid_ray(w.width, w.height), query_filter()), 24);
        (Just(w), rays)
    })
}

proptest! {
    // 400 maps × 24 rays, each cast both ways and checked with cast_ray and cast_ray_all:
    // 19 200 rays, about 1.5 s in a debug build. `PROPTEST_CASES=n` overrides the number of
    // maps for a longer run.
    #![proptest_config(ProptestConfig {
        cases: cases_or(400),
        ..ProptestConfig::default()
    })]

    #[test]
    fn grid_ray_casts_match_brute_force_over_all_active_segments((w, rays) in world_and_rays()) {
        let map = w.map();
        let cands = candidates(&map);
        for (g, filter) in rays {
            let (a, b) = g.ends();
            let ray = Ray::between(w.world(a), w.world(b));
            check(&w, &map, &cands, ray, &filter)?;
            // The reversed ray too: front and back faces swap.
            check(&w, &map, &cands, Ray::between(ray.end(), ray.origin), &filter)?;
        }
    }
}

/// A small random ASCII map on unit cells at the origin.
fn small_map() -> impl Strategy<Value = TileMap> {
    (2u32..=12, 2u32..=12).prop_flat_map(|(w, h)| {
        tile_chars(
            &[(4, '.'), (2, '#'), (1, '/'), (1, '\\'), (1, '=')],
            (w * h) as usize,
        )
        .prop_map(move |chars| tile_map(w, &chars, 1.0, Vec2::ZERO))
    })
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: cases_or(256),
        ..ProptestConfig::default()
    })]

    /// Focused on the grid-line bug (see `ray_scenarios.rs`): along any grid line, `cast_ray`
    /// returns the first of `cast_ray_all`'s hits (which the main property checks).
    #[test]
    fn cast_ray_along_a_grid_line_is_the_first_of_cast_ray_all(
        m in small_map(),
        line in 0u32..=12,
        from in -2.0f32..14.0,
        to in -2.0f32..14.0,
        vertical in any::<bool>(),
    ) {
        let (p0, p1) = if vertical {
            (v(line as f32, from), v(line as f32, to))
        } else {
            (v(from, line as f32), v(to, line as f32))
        };
        let r = Ray::between(p0, p1);
        let first = m.cast_ray_all(r, &QueryFilter::default()).first().map(|h| h.t);
        prop_assert_eq!(m.cast_ray(r, &QueryFilter::default()).map(|h| h.t), first);
    }

    /// Focused on the border bugs (see `ray_scenarios.rs`): a ray entering or leaving the map
    /// through a lattice point of the border gets the same nearest hit as a brute force over
    /// every active segment.
    #[test]
    fn ray_crossing_the_border_at_a_lattice_point_sees_the_cells_touched_there(
        m in small_map(),
        along in 0u32..=12,
        side in 0u32..4,
        dir in (1i32..=4, 1i32..=4, any::<bool>()),
        before in 1u32..=16,
        leaving in any::<bool>(),
    ) {
        let (w, h) = (m.width() as f32, m.height() as f32);
        let a = (along as f32).min(if side < 2 { w } else { h });
        // The entry point on one of the four sides, and a direction into the map.
        let (entry, d) = match side {
            0 => (v(a, 0.0), v(if dir.2 { 1.0 } else { -1.0 } * dir.0 as f32, dir.1 as f32)),
            1 => (v(a, h), v(if dir.2 { 1.0 } else { -1.0 } * dir.0 as f32, -(dir.1 as f32))),
            2 => (v(0.0, a), v(dir.0 as f32, if dir.2 { 1.0 } else { -1.0 } * dir.1 as f32)),
            _ => (v(w, a), v(-(dir.0 as f32), if dir.2 { 1.0 } else { -1.0 } * dir.1 as f32)),
        };
        let (outside, inside) = (entry - d * (before as f32 * 0.25), entry + d * 0.5);
        let r = if leaving {
            Ray::between(inside, outside)
        } else {
            Ray::between(outside, inside)
        };
        // Brute force over every active segment.
        let mut nearest = None::<f32>;
        for row in 0..m.height() {
            for col in 0..m.width() {
                for s in m.active_segments(Cell::new(col, row)) {
                    if s.normal.dot(r.delta) < 0.0
                        && let Some(hit) = tileslide::geometry::cast_ray_segment(&r, &s.segment)
                    {
                        nearest = Some(nearest.map_or(hit.t, |n| n.min(hit.t)));
                    }
                }
            }
        }
        let got = m.cast_ray(r, &QueryFilter::default()).map(|h| h.t);
        prop_assert_eq!(got.is_some(), nearest.is_some(), "got {:?}, expected {:?}, ray {:?}", got, nearest, r);
        if let (Some(g), Some(n)) = (got, nearest) {
            prop_assert!((g - n).abs() <= 1e-5, "got {}, expected {}, ray {:?}", g, n, r);
        }
    }
}
