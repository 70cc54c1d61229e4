//! Smoothing: a lattice path pulled taut into straight runs.
//!
//! The lattice path turns only in steps of 45°; the shortest way runs at any angle. From
//! each corner kept, the path goes straight to the farthest later point that the circle
//! can reach in a straight line (greedy string pulling, as in Botea et al.'s HPA*
//! smoothing), checked with the map's own circle cast, so a body that follows the result
//! never touches a wall.
//!
//! String pulling keeps corners on lattice nodes, up to half a cell out from the wall the
//! path turns round, where the exact shortest path of a circle wraps an arc of its radius
//! round the wall's corner. So each corner is then cut: its two runs are joined by the
//! longest chord, at the same fraction back along each run (at most half of each, so the
//! corner at a run's other end keeps its share), that the circle cast finds clear, and
//! the two new corners are cut in turn until they turn by less than [`FINE_TURN`]. That
//! is corner cutting in the manner of Chaikin's subdivision, but maximal and checked; the
//! cuts shrink towards the arc from outside, each one shorter than what it replaces. The
//! pieces kept of the two runs are cast again, as the new corners lie on them only up to
//! rounding.

use glam::Vec2;

use super::clearance::Clearance;
use crate::query::{Faces, QueryFilter};
use crate::tiles::{SegmentFlags, TileMap};

/// Corners turning by less than this (radians) are not cut: a corner of turn θ in place of
/// an arc of radius r costs about r·θ³/12 of length, 0.5 % of r here, and a right angle
/// is done in three cuts.
const FINE_TURN: f32 = 0.4;

/// Farthest a cut reaches back or ahead along a run, in cells: the arc of the exact path
/// round a wall's corner lies within the radius (at most `max_radius`, a cell or so) of
/// it, and a corner kept by string pulling is within a cell of that, so longer chords
/// would only make the circle casts slower.
const CUT_REACH: f32 = 3.0;

/// Halvings of the search for the longest clear chord: the cut found is within 1/16 of
/// the longest (a fifth halving made no path on the test maps measurably shorter).
const CUT_STEPS: u32 = 4;

/// Deepest cutting of one corner (2^depth − 1 cuts at most): two halvings of a right angle
/// already turn by less than [`FINE_TURN`].
const CUT_DEPTH: u32 = 3;

/// The largest `t` in [0, 1) that `clear` accepts, by [`CUT_STEPS`] halvings from `t = 0`
/// (taken as clear): every value returned was tested, so a caller may trust it even where
/// `clear` is not monotone.
fn largest_clear(clear: impl Fn(f32) -> bool) -> f32 {
    let (mut lo, mut hi) = (0.0f32, 1.0f32);
    for _ in 0..CUT_STEPS {
        let mid = 0.5 * (lo + hi);
        if clear(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

/// True when a circle of `radius` moves from `a` to `b` without touching any segment with
/// one of the `table`'s mask flags from either side, and with the grid's margin clear of the
/// front of every one-way platform it could run into going that way.
///
/// A one-way platform that carries another flag of the mask too is cast against as well, so
/// it blocks both ways here: a smoothed run never crosses one, though lattice moves may.
pub(crate) fn is_clear(map: &TileMap, a: Vec2, b: Vec2, radius: f32, table: &Clearance) -> bool {
    if a == b {
        return true;
    }
    let filter = QueryFilter {
        faces: Faces::Both,
        ..QueryFilter::default()
    }
    .with_mask(SegmentFlags(table.mask.0 & !SegmentFlags::ONE_WAY.0));
    map.cast_valid_circle(a, radius, b - a, &filter).is_none()
        && (!table.has_one_way() || table.one_way_clearance(map, a, b) >= radius + table.margin)
}

/// The corners of `points` (a path whose every straight piece is clear): drops points in
/// the middle of straight runs, pulls the path taut, then cuts its corners.
pub(crate) fn smooth(map: &TileMap, points: &[Vec2], radius: f32, table: &Clearance) -> Vec<Vec2> {
    let pulled = pull_taut(map, &turning_points(points), radius, table);
    let mut cut = round_corners(map, &pulled, radius, table);
    relax(map, &mut cut, radius, table);
    cut
}

/// Cutting keeps every new corner on the runs it cut, so where string pulling left a
/// corner off the arc's tangents, the runs into the cut keep their old direction. Relaxing
/// moves each corner whose runs are short (within [`CUT_REACH`] cells; long runs cost
/// long casts and gain little) towards the straight line between its neighbours, as far
/// as the circle cast finds both its runs clear: one pass of the taut-string iteration of an
/// elastic band (Quinlan & Khatib 1993), with moves checked instead of forces balanced.
/// It never lengthens the path: the length through a corner is convex in the corner's
/// position and least on that line.
fn relax(map: &TileMap, points: &mut [Vec2], radius: f32, table: &Clearance) {
    let reach = map.cell_size().min_element() * CUT_REACH;
    for i in 1..points.len().saturating_sub(1) {
        let (a, v, b) = (points[i - 1], points[i], points[i + 1]);
        let ab = b - a;
        let along = ab.length_squared();
        if along == 0.0
            || (v - a).angle_to(b - v).abs() < FINE_TURN * 0.5
            || a.distance(v).max(b.distance(v)) > reach
        {
            continue;
        }
        let target = a + ab * ((v - a).dot(ab) / along).clamp(0.0, 1.0);
        let at = |s: f32| v + (target - v) * s;
        let clear = |s: f32| {
            let p = at(s);
            is_clear(map, a, p, radius, table) && is_clear(map, p, b, radius, table)
        };
        let lo = largest_clear(clear);
        if lo > 0.0 {
            points[i] = at(lo);
        }
    }
}

/// Greedy string pulling over `corners` (a path whose every straight piece is clear):
/// from each corner kept, straight on to a far later corner the circle reaches.
///
/// The far corner is found by galloping (Bentley & Yao 1976): corners 2, 4, 8, … ahead
/// until one is out of reach, then halving between the last reached and that one. A
/// linear scan casts to every corner up to the first out of reach, so its casts add up
/// to the square of the run's length on the lattice's staircases of short turns; this
/// casts a logarithmic number of times, each run still checked by a cast.
fn pull_taut(map: &TileMap, corners: &[Vec2], radius: f32, table: &Clearance) -> Vec<Vec2> {
    let Some((&first, _)) = corners.split_first() else {
        return Vec::new();
    };
    let last = corners.len() - 1;
    let mut out = vec![first];
    let mut anchor = 0;
    while anchor < last {
        let reaches = |k: usize| is_clear(map, corners[anchor], corners[k], radius, table);
        // `reached` is in reach (the next corner always is: it was a clear piece of the
        // path); `beyond` is not, or is past the end.
        let mut reached = anchor + 1;
        let mut step = 1;
        let mut beyond = loop {
            if reached == last {
                break last + 1;
            }
            step *= 2;
            let k = (anchor + step).min(last);
            if reaches(k) {
                reached = k;
            } else {
                break k;
            }
        };
        while beyond - reached > 1 {
            let mid = reached + (beyond - reached) / 2;
            if reaches(mid) {
                reached = mid;
            } else {
                beyond = mid;
            }
        }
        out.push(corners[reached]);
        anchor = reached;
    }
    out
}

/// `points` (a path whose every straight piece is clear) with every corner cut towards
/// the walls it turns round (see the module's notes).
fn round_corners(map: &TileMap, points: &[Vec2], radius: f32, table: &Clearance) -> Vec<Vec2> {
    let Some((&first, rest)) = points.split_first() else {
        return Vec::new();
    };
    let mut out = Vec::with_capacity(points.len() * 4);
    out.push(first);
    for pair in rest.windows(2) {
        let cutter = Cutter {
            map,
            radius,
            table,
            cell: map.cell_size().min_element(),
        };
        cutter.cut(&mut out, pair[0], pair[1], CUT_DEPTH);
    }
    if let Some(&last) = rest.last() {
        out.push(last);
    }
    out
}

/// What cutting a corner needs to check chords.
struct Cutter<'a> {
    map: &'a TileMap,
    radius: f32,
    table: &'a Clearance,
    /// The map's shorter cell side.
    cell: f32,
}

impl Cutter<'_> {
    /// Pushes onto `out` the corner `v` or what replaces it, between the last point of
    /// `out` and `next`: the runs from `out`'s last point to `v` and from `v` to `next`
    /// are clear, and so is every run of what is pushed.
    fn cut(&self, out: &mut Vec<Vec2>, v: Vec2, next: Vec2, depth: u32) {
        let Some(&prev) = out.last() else {
            out.push(v);
            return;
        };
        let (back, ahead) = (prev - v, next - v);
        let turn = (-back).angle_to(ahead).abs();
        if depth == 0 || !turn.is_finite() || turn < FINE_TURN {
            out.push(v);
            return;
        }
        // Chords reach at most half way along either run, which leaves the other half to
        // the corner at its other end, and at most CUT_REACH cells.
        let reach = self.cell * CUT_REACH;
        let longest = back.length().max(ahead.length());
        let t_max = if longest > 2.0 * reach {
            reach / longest
        } else {
            0.5
        };
        let chord = |t: f32| (v + back * (t * t_max), v + ahead * (t * t_max));
        let clear = |t: f32| {
            let (p, q) = chord(t);
            is_clear(self.map, p, q, self.radius, self.table)
        };
        // Whole runs: the corner goes. `next` is the following corner, so the path from
        // `prev` runs straight on to it, clear.
        if prev.distance(next) <= 2.0 * reach
            && is_clear(self.map, prev, next, self.radius, self.table)
        {
            return;
        }
        // The longest clear chord by halving; `t = 0` is the corner itself.
        let lo = largest_clear(clear);
        let (p, q) = chord(lo);
        // The new corners lie on the old runs only up to rounding, which can bring a run
        // that grazes a wall's corner at the radius onto it: the pieces kept of the old
        // runs are cast too, so every run of the result has been checked itself.
        if lo == 0.0
            || p == v
            || q == v
            || !is_clear(self.map, prev, p, self.radius, self.table)
            || !is_clear(self.map, q, next, self.radius, self.table)
        {
            out.push(v);
            return;
        }
        self.cut(out, p, q, depth - 1);
        self.cut(out, q, next, depth - 1);
    }
}

/// The first and last points and every point where the direction changes.
fn turning_points(points: &[Vec2]) -> Vec<Vec2> {
    let mut out: Vec<Vec2> = Vec::with_capacity(points.len());
    for &p in points {
        if out.last() == Some(&p) {
            continue;
        }
        if let [.., a, b] = out[..] {
            let (u, v) = (b - a, p - b);
            if u.perp_dot(v).abs() <= 1e-6 * u.length() * v.length() && u.dot(v) > 0.0 {
                out.pop();
            }
        }
        out.push(p);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::ascii;

    /// Round a block's corner, a wide circle's path is within 2 % of the exact shortest
    /// way (two tangents and the arc of radius 0.8 round the block's corner (4, 4) on the
    /// side away from the block, worked out by hand: 5.485), never below it, every run
    /// clear.
    #[test]
    fn a_corner_is_cut_towards_the_arc_round_the_wall() {
        let map = ascii::parse(
            "#########\n#.......#\n#.......#\n#.......#\n#...#####\n#...#####\n#...#####\n#########",
            "l.txt",
            1.0,
        )
        .unwrap();
        let r = 0.8;
        let (from, to) = (Vec2::new(2.5, 6.0), Vec2::new(6.0, 2.5));
        let nav = crate::path::NavGrid::new(&map, crate::path::NavConfig::default()).unwrap();
        let path = nav.find_path(&map, from, to, r).unwrap().unwrap();
        let (tangent, arc) = (
            (2.5f32 * 2.5 - r * r).sqrt(),
            // The ends are 163.7° apart seen from the corner, but the arc goes the other
            // way round, outside the block.
            std::f32::consts::TAU - (-0.96f32).acos() - 2.0 * (r / 2.5).acos(),
        );
        let exact = 2.0 * tangent + r * arc;
        assert!((exact - 5.485).abs() < 1e-3, "{exact}");
        let got = path.length();
        assert!(
            got >= exact - 1e-3 && got <= exact * 1.02,
            "{got} against {exact}: {:?}",
            path.points()
        );
        for w in path.points().windows(2) {
            assert!(is_clear(&map, w[0], w[1], r, &nav.table), "{w:?}");
        }
    }

    #[test]
    fn straight_runs_keep_only_their_ends() {
        let v = |x: f32, y: f32| Vec2::new(x, y);
        let points = [
            v(0.0, 0.0),
            v(1.0, 0.0),
            v(2.0, 0.0),
            v(3.0, 1.0),
            v(4.0, 2.0),
        ];
        assert_eq!(
            turning_points(&points),
            vec![v(0.0, 0.0), v(2.0, 0.0), v(4.0, 2.0)]
        );
    }
}
