//! Which face a swept box reports at corners, against an exact reference: the edge of the
//! Minkowski sum of box and segment (the intersection of its support half-planes, whose
//! normals are the segment's normal and the box's axes) that the centre's path enters first,
//! with the tie rule of `sweep_box_segment` for a path through a vertex. Plus the corner
//! cases the rule was made for, and a check that every segment of a block reports the same
//! normal for the same contact, so a caller's order of testing them does not matter.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use proptest::prelude::*;
use tileslide::{Segment, Vec2, geometry::EndCaps, geometry::sweep_box_segment};

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

/// What the reference expects of one sweep.
#[derive(Debug)]
enum Expected {
    /// No contact.
    Miss,
    /// A contact at `t`, reported with one of these outcomes (`None`: the segment leaves
    /// it to its neighbour); more than one only where entries are too close to call.
    Hit { t: f64, outcomes: Vec<Option<Vec2>> },
    /// The box starts with the segment inside it, or the answer hangs on rounding.
    Unclear,
}

/// One sweep: a box of half extents `half` at `c` moving by `m` against the segment
/// `a → b` with unit front normal `n` and end caps `caps`.
#[derive(Clone, Copy, Debug)]
struct Case {
    c: Vec2,
    half: Vec2,
    m: Vec2,
    segment: (Vec2, Vec2, Vec2),
    caps: [bool; 2],
}

/// The reference answer for `case`; entries closer than `tol` (in `t`) are ties too close
/// to call (0 for exact inputs, where ties are exact).
fn reference(case: Case, tol: f64) -> Expected {
    let Case {
        c,
        half,
        m,
        segment: (a, b, n),
        caps,
    } = case;
    let f = |p: Vec2| [f64::from(p.x), f64::from(p.y)];
    let dot = |p: [f64; 2], q: [f64; 2]| p[0] * q[0] + p[1] * q[1];
    let (c, m, a, b, h, nf) = (f(c), f(m), f(a), f(b), f(half), f(n));
    let mut dirs: Vec<[f64; 2]> = vec![nf, [-nf[0], -nf[1]]];
    for d in [[1.0, 0.0], [-1.0, 0.0], [0.0, 1.0], [0.0, -1.0]] {
        if !dirs.contains(&d) {
            dirs.push(d);
        }
    }
    // The Minkowski sum is {x : x·d <= H(d)} over these directions.
    let mut t_enter = f64::NEG_INFINITY;
    let mut t_exit = f64::INFINITY;
    let mut entries = Vec::new();
    // The entry's `t` as a quotient `num / den` (`den > 0`), for the exact sign below.
    let (mut num, mut den) = (-1.0, 1.0);
    for &d in &dirs {
        let support = dot(a, d).max(dot(b, d)) + h[0] * d[0].abs() + h[1] * d[1].abs();
        let (cd, md) = (dot(c, d), dot(m, d));
        if md == 0.0 {
            if cd >= support - tol {
                // Outside or on this edge's line all along: never inside.
                return if (cd - support).abs() <= tol && tol > 0.0 {
                    Expected::Unclear
                } else {
                    Expected::Miss
                };
            }
        } else if md < 0.0 {
            let t = (cd - support) / -md;
            entries.push((t, d));
            if t > t_enter {
                (num, den) = (cd - support, -md);
            }
            t_enter = t_enter.max(t);
        } else {
            t_exit = t_exit.min((support - cd) / md);
        }
    }
    if t_enter < 0.0 && t_exit > 0.0 {
        return Expected::Unclear;
    }
    let near = |x: f64, y: f64| (x - y).abs() <= tol;
    if tol > 0.0 && (near(t_enter, t_exit) || near(t_enter, 1.0) || near(t_enter, 0.0)) {
        return Expected::Unclear;
    }
    if !(t_enter < t_exit && (0.0..=1.0).contains(&t_enter)) {
        return Expected::Miss;
    }
    // The centre's height over the segment's line at the contact, and its sign without
    // rounding `t`: `den` times it is `(c − a)·n·den + num·(m·n)`, exact on the grid of
    // eighths (rounded, `t` can put a centre that is on the line a hair to either side).
    let height = dot(
        [c[0] + m[0] * t_enter - a[0], c[1] + m[1] * t_enter - a[1]],
        nf,
    );
    if tol > 0.0 && height.abs() <= tol {
        return Expected::Unclear;
    }
    let height = dot([c[0] - a[0], c[1] - a[1]], nf) * den + num * dot(m, nf);
    let outcome = |d: [f64; 2]| -> Option<Vec2> {
        if d == nf {
            return Some(n);
        }
        if d == [-nf[0], -nf[1]] {
            return None;
        }
        // A box side, meeting the end point farthest along `d`.
        let end = usize::from(dot(b, d) > dot(a, d));
        (caps[end] && height >= 0.0).then(|| Vec2::new(d[0] as f32, d[1] as f32))
    };
    let tied: Vec<[f64; 2]> = entries
        .iter()
        .filter(|(t, _)| *t >= t_enter - tol)
        .map(|&(_, d)| d)
        .collect();
    let outcomes = if tol > 0.0 {
        tied.iter().map(|&d| outcome(d)).collect()
    } else {
        vec![outcome(tie_winner(&tied, nf, m))]
    };
    Expected::Hit {
        t: t_enter,
        outcomes,
    }
}

/// The edge a path through a vertex of the Minkowski sum reports, among `tied` (the edges
/// entered at the same `t`): the one `m` runs into most head-on (largest `-d · m`); on equal
/// terms a box side over a slanted face, `x` over `y`. A box side of a slanted face's end
/// counts only if the motion runs into both of the box's sides at the corner there (else
/// the end point slides along one, and the face is what enters the box).
fn tie_winner(tied: &[[f64; 2]], n: [f64; 2], m: [f64; 2]) -> [f64; 2] {
    let slanted = n[0] != 0.0 && n[1] != 0.0;
    let into = |d: [f64; 2]| -(d[0] * m[0] + d[1] * m[1]);
    if slanted
        && tied.contains(&n)
        && (-n[0].signum() * m[0] <= 0.0 || -n[1].signum() * m[1] <= 0.0)
    {
        return n;
    }
    let rank = |d: [f64; 2]| {
        let kind = if d[1] == 0.0 {
            2
        } else if d[0] == 0.0 {
            1
        } else {
            0
        };
        (into(d), kind)
    };
    *tied
        .iter()
        .max_by(|p, q| rank(**p).partial_cmp(&rank(**q)).unwrap())
        .unwrap()
}

/// Checks `sweep_box_segment` against [`reference`]; `false` when the case was unclear.
fn agrees(case: Case, tol: f64) -> Result<bool, TestCaseError> {
    let Case {
        c,
        half,
        m,
        segment: (a, b, n),
        caps,
    } = case;
    let got = sweep_box_segment(
        c,
        half,
        m,
        &Segment::new(a, b),
        n,
        EndCaps {
            a: caps[0],
            b: caps[1],
        },
    );
    let slack = 1e-4_f64.max(4.0 * tol);
    match reference(case, tol) {
        Expected::Unclear => return Ok(false),
        Expected::Miss => prop_assert!(got.is_none(), "expected no contact, got {:?}", got),
        Expected::Hit { t, outcomes } => {
            // `None`: no contact now. The box then holds part of the segment (its neighbour
            // or its back let it in), and what a later end point does is not this test's.
            let matches = |o: &Option<Vec2>| match (o, got) {
                (None, None) => true,
                (None, Some(hit)) => f64::from(hit.t) > t + slack,
                (Some(want), Some(hit)) => {
                    (f64::from(hit.t) - t).abs() <= slack
                        && (hit.normal - *want).abs().max_element() <= 1e-5
                }
                (Some(_), None) => false,
            };
            prop_assert!(
                outcomes.iter().any(matches),
                "got {:?}, expected one of {:?} at t = {}",
                got,
                outcomes,
                t
            );
        }
    }
    Ok(true)
}

/// A segment's end points and the unit normal on one side of it.
fn oriented(a: Vec2, b: Vec2, flip: bool) -> (Vec2, Vec2, Vec2) {
    let n = (b - a).perp().normalize();
    (a, b, if flip { -n } else { n })
}

/// An eighth of a unit times `k`: exact in `f32`, so ties between entries are exact.
fn eighths(k: i32) -> f32 {
    k as f32 / 8.0
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4000))]

    /// Any segment (slanted or not), any box and motion: the contact time and the face
    /// reported are the reference's (within rounding where two entries nearly tie).
    #[test]
    fn box_sweeps_report_the_face_the_minkowski_sum_is_entered_through(
        cx in -4.0f32..4.0, cy in -4.0f32..4.0,
        mx in -8.0f32..8.0, my in -8.0f32..8.0,
        hx in 0.1f32..1.5, hy in 0.1f32..1.5,
        ax in -3.0f32..3.0, ay in -3.0f32..3.0,
        bx in -3.0f32..3.0, by in -3.0f32..3.0,
        axis in 0u8..3, flip: bool, caps: [bool; 2], level: bool,
    ) {
        // A third of the segments axis-aligned (every tile face is), and some level moves.
        let (bx, by) = match axis { 0 => (bx, ay), 1 => (ax, by), _ => (bx, by) };
        let my = if level { 0.0 } else { my };
        prop_assume!(v(ax, ay).distance(v(bx, by)) > 0.05);
        let seg = oriented(v(ax, ay), v(bx, by), flip);
        let case = Case { c: v(cx, cy), half: v(hx, hy), m: v(mx, my), segment: seg, caps };
        agrees(case, 1e-4)?;
    }

    /// Axis-aligned segments, boxes and moves on a grid of eighths, so boxes start flush
    /// with segments, slide along them, and meet their ends corner to corner: the reference
    /// with its tie rule, exactly.
    #[test]
    fn flush_and_corner_to_corner_contacts_follow_the_tie_rule_exactly(
        cx in -24i32..24, cy in -24i32..24,
        mx in -32i32..32, my in -32i32..32,
        hx in 1i32..12, hy in 1i32..12,
        ax in -16i32..16, ay in -16i32..16, len in 1i32..24,
        vertical: bool, flip: bool, caps: [bool; 2],
    ) {
        let a = v(eighths(ax), eighths(ay));
        let b = if vertical { a + v(0.0, eighths(len)) } else { a + v(eighths(len), 0.0) };
        let seg = oriented(a, b, flip);
        let case = Case {
            c: v(eighths(cx), eighths(cy)),
            half: v(eighths(hx), eighths(hy)),
            m: v(eighths(mx), eighths(my)),
            segment: seg,
            caps,
        };
        agrees(case, 0.0)?;
    }

    /// A box against the four faces of a block (convex corners, all capped): every face
    /// that reports the earliest contact reports the same normal, so testing the faces in
    /// any order gives one answer; and that answer is the reference's for the block.
    #[test]
    fn a_blocks_faces_agree_on_the_normal_of_a_contact_whatever_their_order(
        cx in -24i32..24, cy in -24i32..24,
        mx in -32i32..32, my in -32i32..32,
        hx in 1i32..12, hy in 1i32..12,
        x0 in -8i32..8, y0 in -8i32..8, w in 1i32..16, h in 1i32..16,
    ) {
        let (c, half, m) = (
            v(eighths(cx), eighths(cy)),
            v(eighths(hx), eighths(hy)),
            v(eighths(mx), eighths(my)),
        );
        let (lo, hi) = (v(eighths(x0), eighths(y0)), v(eighths(x0 + w), eighths(y0 + h)));
        // Start clear of the block.
        prop_assume!(
            !((c.x + half.x > lo.x && c.x - half.x < hi.x)
                && (c.y + half.y > lo.y && c.y - half.y < hi.y))
        );
        // Faces run with the block's outside on their right (as active segments do).
        let faces = [
            (v(lo.x, lo.y), v(hi.x, lo.y), Vec2::NEG_Y),
            (v(hi.x, lo.y), v(hi.x, hi.y), Vec2::X),
            (v(hi.x, hi.y), v(lo.x, hi.y), Vec2::Y),
            (v(lo.x, hi.y), v(lo.x, lo.y), Vec2::NEG_X),
        ];
        let hits: Vec<_> = faces
            .iter()
            .filter_map(|&(a, b, n)| sweep_box_segment(c, half, m, &Segment::new(a, b), n, EndCaps::BOTH))
            .collect();
        let first = hits.iter().map(|h| h.t).fold(f32::INFINITY, f32::min);
        let normals: Vec<Vec2> = hits.iter().filter(|h| h.t == first).map(|h| h.normal).collect();
        prop_assert!(normals.windows(2).all(|w| w[0] == w[1]), "faces disagree: {:?}", hits);
        // The reference for the block: its Minkowski sum with the box is the block grown
        // by the box's half extents, entered through a side (or, at a vertex, by the tie rule).
        let grown = (lo - half, hi + half);
        let block = reference_block(c, m, grown);
        prop_assert_eq!(normals.first().map(|n| (first, *n)), block);
    }
}

/// The first entry of the path `c + m·t`, `t` in [0, 1], into the open rectangle `grown`,
/// with the normal of the side entered (the tie rule at a corner): `None` for a miss.
fn reference_block(c: Vec2, m: Vec2, (lo, hi): (Vec2, Vec2)) -> Option<(f32, Vec2)> {
    let mut t_enter = f64::NEG_INFINITY;
    let mut t_exit = f64::INFINITY;
    let mut tied: Vec<[f64; 2]> = Vec::new();
    for (axis, unit) in [(0, [1.0, 0.0]), (1, [0.0, 1.0])] {
        let (p, d, l, h) = (
            f64::from(c[axis]),
            f64::from(m[axis]),
            f64::from(lo[axis]),
            f64::from(hi[axis]),
        );
        if d == 0.0 {
            if p <= l || p >= h {
                return None;
            }
            continue;
        }
        let (t0, t1) = ((l - p) / d, (h - p) / d);
        let (near, far) = (t0.min(t1), t0.max(t1));
        let normal = [-unit[0] * d.signum(), -unit[1] * d.signum()];
        if near > t_enter {
            t_enter = near;
            tied = vec![normal];
        } else if near == t_enter {
            tied.push(normal);
        }
        t_exit = t_exit.min(far);
    }
    if !(t_enter < t_exit && (0.0..=1.0).contains(&t_enter)) {
        return None;
    }
    let n = tie_winner(&tied, [0.0, 1.0], [f64::from(m.x), f64::from(m.y)]);
    Some((t_enter as f32, Vec2::new(n[0] as f32, n[1] as f32)))
}

/// The faces of a block occupying x in [4, 5], y in [-1, 0] (y up) that a box coming from
/// its left can meet: its top (the surface the box is level with or below) and its left
/// side, both with caps at the shared corner (4, 0).
fn block_faces() -> [(Segment, Vec2); 2] {
    [
        (Segment::new(v(4.0, 0.0), v(5.0, 0.0)), Vec2::Y),
        (Segment::new(v(4.0, -1.0), v(4.0, 0.0)), Vec2::NEG_X),
    ]
}

/// The first contact among `faces` in the order given and in the reverse order, as a
/// caller picks it (the first found on equal `t`).
fn first_contacts(
    c: Vec2,
    half: Vec2,
    m: Vec2,
    faces: [(Segment, Vec2); 2],
) -> [Option<(f32, Vec2)>; 2] {
    let first = |faces: [(Segment, Vec2); 2]| {
        let mut best: Option<(f32, Vec2)> = None;
        for (segment, normal) in faces {
            if let Some(hit) = sweep_box_segment(c, half, m, &segment, normal, EndCaps::BOTH)
                && best.is_none_or(|(t, _)| hit.t < t)
            {
                best = Some((hit.t, hit.normal));
            }
        }
        best
    };
    [first(faces), first([faces[1], faces[0]])]
}

#[test]
fn a_box_running_into_a_blocks_corner_gets_the_blocks_side_level_or_dipping_in_either_order() {
    let half = v(0.5, 0.5);
    // The box's bottom a little below the block's top (at -0.1) moving level or dipping by
    // 0.1, and flush with the top dipping (flush and level, it passes over the block).
    for (center, motion) in [
        (v(2.0, 0.4), v(4.0, 0.0)),
        (v(2.0, 0.4), v(4.0, -0.1)),
        (v(2.0, 0.5), v(4.0, -0.1)),
    ] {
        let side = Some((0.375, Vec2::NEG_X));
        let hits = first_contacts(center, half, motion, block_faces());
        assert_eq!(hits, [side; 2], "box at {center} moving {motion}");
        // The block's top alone does not claim the contact with its normal.
        let (top, n) = block_faces()[0];
        let hit = sweep_box_segment(center, half, motion, &top, n, EndCaps::BOTH);
        assert!(hit.is_none_or(|h| h.normal == Vec2::NEG_X), "{hit:?}");
    }
}

#[test]
fn the_mirrored_corner_gives_the_mirrored_side() {
    // The block at x in [-5, -4], y in [-1, 0]; the box coming from its right.
    let faces = [
        (Segment::new(v(-5.0, 0.0), v(-4.0, 0.0)), Vec2::Y),
        (Segment::new(v(-4.0, 0.0), v(-4.0, -1.0)), Vec2::X),
    ];
    for motion in [v(-4.0, 0.0), v(-4.0, -0.1)] {
        let hits = first_contacts(v(-2.0, 0.4), v(0.5, 0.5), motion, faces);
        assert_eq!(hits, [Some((0.375, Vec2::X)); 2], "moving {motion}");
    }
}

#[test]
fn a_box_flush_with_a_blocks_top_passes_over_its_corner_moving_level() {
    // The box's bottom slides along the top's line: its side only grazes the block's
    // corner, and its bottom only grazes the left side's top end.
    let (center, half, motion) = (v(2.0, 0.5), v(0.5, 0.5), v(4.0, 0.0));
    let [(top, up), (side, left)] = block_faces();
    // The top still is not met (the motion runs along it)...
    assert_eq!(
        sweep_box_segment(center, half, motion, &top, up, EndCaps::BOTH),
        None
    );
    // ...and the left side's end point, under the box's bottom, is not a contact either.
    assert_eq!(
        sweep_box_segment(center, half, motion, &side, left, EndCaps::BOTH),
        None
    );
}

#[test]
fn a_steeper_dip_into_the_corner_lands_on_the_top() {
    // Corner to corner: the box's bottom-right corner (3, 1.5) meets the block's corner
    // (4, 0) at t = 0.5; the motion runs more down (3) than right (2): the top's normal,
    // from both faces.
    let half = v(0.5, 0.5);
    let hits = first_contacts(v(2.5, 2.0), half, v(2.0, -3.0), block_faces());
    assert_eq!(hits, [Some((0.5, Vec2::Y)); 2]);
    // Exactly diagonal: the side (x) wins.
    let hits = first_contacts(v(2.0, 2.0), half, v(3.0, -3.0), block_faces());
    assert_eq!(hits, [Some((0.5, Vec2::NEG_X)); 2]);
}

#[test]
fn a_box_walking_along_a_floor_into_a_ramps_foot_meets_the_ramp() {
    // The ramp rises from (0, 0) to (2, 2), its foot joined to the floor (no cap there).
    // The box's bottom-right corner reaches the foot moving level: the ramp's face is what
    // comes into the box, so the ramp reports its normal, not nothing.
    let ramp = Segment::new(v(0.0, 0.0), v(2.0, 2.0));
    let n = v(-1.0, 1.0).normalize();
    let hit = sweep_box_segment(
        v(-2.5, 0.5),
        v(0.5, 0.5),
        v(4.0, 0.0),
        &ramp,
        n,
        EndCaps { a: false, b: true },
    );
    let hit = hit.expect("the ramp's face");
    assert!((hit.t - 0.5).abs() < 1e-6, "{hit:?}");
    assert_eq!(hit.normal, n);
}
