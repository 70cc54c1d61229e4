//! Circle casts that the `f32` sweep of `cast_circle` does not take as given: a centre far
//! from the map, or a radius beyond [`MAX_COORD`](crate::limits::MAX_COORD).
//!
//! Rounding such a start to `f32` near the map would move the line it travels (at 10⁷ an
//! `f32` is a whole unit apart from the next, at 10³⁰ about 10²³ units). So the motion is
//! clipped in `f64` to the box where a wall can be reached, each wall is swept from there
//! with its offset taken in `f64` and the problem scaled by a power of two into the sweep's
//! range, and `t`, the centre and the point are mapped back to the caller's motion in `f64`.

use glam::{DVec2, Vec2};

use super::QueryFilter;
use super::circle_cast::{Capsule, CircleHit};
use crate::geometry::{Aabb, Segment, SweepHit, circle_segment};
use crate::tiles::TileMap;

/// The size, as a power of two, that a wall's sweep is scaled to: the largest component of
/// its offset, segment and motion lies in `[2²⁴, 2²⁵)`. Then the sum of the magnitudes of a
/// cap's offset and motion (below `2²⁷`) and its radius (clamped below `2²⁸`, see
/// [`sweep_scaled`]) stays below the `2³⁰` up to which the `f32` sweep runs as written.
const SWEEP_EXPONENT: i32 = 24;

/// The smallest size, as a power of two, a segment is scaled to for its flat side: a
/// segment much shorter than the distance to it (a circle of radius 10³⁰ around a map of
/// unit cells) would otherwise square to 0 in `f32`.
const SEGMENT_EXPONENT: i32 = -40;

/// How far beyond [`SWEEP_EXPONENT`] a segment's scale may raise the other sizes: up to
/// `2¹⁰¹`, where their products with the segment still stay below `f32::MAX`.
const SEGMENT_RAISE: i32 = 76;

/// The part of a circle's motion along which it can reach a wall, in `f64`: from `start`
/// by `motion`, which is the caller's motion from `t0` to `t0 + dt`.
#[derive(Clone, Copy, Debug, PartialEq)]
struct MotionPart {
    start: DVec2,
    motion: DVec2,
    t0: f64,
    dt: f64,
}

impl MotionPart {
    /// The part of the motion of `center` by `motion` inside the box `[lo, hi]`, or `None`
    /// when it does not enter the box (or does not move).
    ///
    /// The line is taken exactly, not through a rounded point: its distance from a point
    /// `q` of the box comes from the cross product `center × motion − q × motion`, whose
    /// products of two `f32` values are exact in `f64`, so the one rounding is relative to
    /// the result (the distance times the length), however far `center` is. Points on it
    /// are `q + distance·n + s·u` (`u` its direction, `n` perpendicular to it). The end of
    /// the motion is `center + motion` in `f64`, which is exact whenever it lies near the
    /// box (a sum of two `f32` values is exact unless it is as large as the larger of
    /// them). A motion inside the box is kept as given.
    fn clip(center: Vec2, motion: Vec2, lo: DVec2, hi: DVec2) -> Option<Self> {
        let (c, m) = (center.as_dvec2(), motion.as_dvec2());
        let length = m.length();
        if length == 0.0 {
            return None;
        }
        let u = m / length;
        // A point of the box with `f32` coordinates, so that its products are exact too.
        let q = ((lo + hi) * 0.5).as_vec2().as_dvec2();
        let cross = |p: DVec2| p.x * m.y - p.y * m.x;
        let dot = |p: DVec2| p.x * m.x + p.y * m.y;
        let distance = (cross(c) - cross(q)) / length;
        let foot = q + DVec2::new(u.y, -u.x) * distance;
        let s_start = (dot(c) - dot(q)) / length;
        let s_end = (c + m - q).dot(u);
        // The slabs of the box along the line (Kay & Kajiya 1986).
        let (mut s_in, mut s_out) = (f64::NEG_INFINITY, f64::INFINITY);
        for axis in 0..2 {
            if u[axis] == 0.0 {
                if foot[axis] < lo[axis] || foot[axis] > hi[axis] {
                    return None;
                }
            } else {
                let (a, b) = (
                    (lo[axis] - foot[axis]) / u[axis],
                    (hi[axis] - foot[axis]) / u[axis],
                );
                s_in = s_in.max(a.min(b));
                s_out = s_out.min(a.max(b));
            }
        }
        if s_start.max(s_in) >= s_end.min(s_out) {
            return None;
        }
        // Lengths along the line, not differences of `t`: near the map a part a few cells
        // long of a motion of 10³⁰ is a difference of 10⁻³⁰ between two values near 1/2.
        let (start, from, t0) = if s_start >= s_in {
            (c, s_start, 0.0)
        } else {
            (foot + u * s_in, s_in, (s_in - s_start) / length)
        };
        let (to, whole) = if s_end <= s_out {
            (s_end, t0 == 0.0)
        } else {
            (s_out, false)
        };
        Some(Self {
            start,
            motion: if whole { m } else { u * (to - from) },
            t0,
            dt: if whole { 1.0 } else { (to - from) / length },
        })
    }
}

impl TileMap {
    /// [`cast_circle`](Self::cast_circle) for a finite centre far from the map, or a finite
    /// radius beyond `MAX_COORD` (both checked by the caller: `radius > 0`, every input
    /// finite). Out of line: no game's cast comes here.
    #[cold]
    #[inline(never)]
    pub(super) fn cast_circle_wide(
        &self,
        center: Vec2,
        radius: f32,
        motion: Vec2,
        filter: &QueryFilter,
    ) -> Option<CircleHit> {
        let r = f64::from(radius);
        let (lo, hi) = self.walls_box();
        // Beyond the rounding of every wall's `f32` coordinates and of the sweeps' offsets
        // (2⁻²⁴ of them), with a cell to spare: a circle this far outside the box touches
        // nothing.
        let extent = lo.abs().max(hi.abs()).max_element();
        let slack = f64::from(self.cell_size().max_element()) + (extent + r) * 2f64.powi(-20);
        let reach = r + slack;
        let part = MotionPart::clip(center, motion, lo - reach, hi + reach)?;
        // The cells and temporary segments the swept circle can touch, cut to the box.
        let end = part.start + part.motion;
        let region_lo = (part.start.min(end) - reach).max(lo - slack);
        let region_hi = (part.start.max(end) + reach).min(hi + slack);
        if region_lo.cmpgt(region_hi).any() {
            return None;
        }
        let region = Aabb::from_corners(region_lo.as_vec2(), region_hi.as_vec2());
        let best = self.first_wall_in(&region, filter, |capsule| {
            sweep_wide(capsule, part.start, r, part.motion)
        });
        best.map(|(hit, wall)| {
            let t = f64::from(hit.t);
            let at = part.start + part.motion * t;
            CircleHit {
                t: (part.t0 + t * part.dt).clamp(0.0, 1.0) as f32,
                center: at.as_vec2(),
                normal: hit.normal,
                point: (at - hit.normal.as_dvec2() * r).as_vec2(),
                flags: wall.flags,
                source: wall.source,
            }
        })
    }

    /// The box, in `f64`, that holds every segment: the map's rectangle and the temporary
    /// segments.
    fn walls_box(&self) -> (DVec2, DVec2) {
        let origin = self.origin().as_dvec2();
        let size = DVec2::new(f64::from(self.width()), f64::from(self.height()))
            * self.cell_size().as_dvec2();
        let (mut lo, mut hi) = (origin, origin + size);
        for tmp in self.temporaries() {
            for p in [tmp.segment.a.as_dvec2(), tmp.segment.b.as_dvec2()] {
                lo = lo.min(p);
                hi = hi.max(p);
            }
        }
        (lo, hi)
    }
}

/// The time of impact of a circle of `radius` whose centre starts at `start` and moves by
/// `motion` against `capsule`, all in `f64`: [`circle_segment`]'s rule, with the flat side
/// and each rounded end swept on its own (each at its own scale, see [`sweep_scaled`]),
/// and the same choice among them (a cap only when strictly earlier than the flat side).
fn sweep_wide(capsule: &Capsule, start: DVec2, radius: f64, motion: DVec2) -> Option<SweepHit> {
    let (a, b) = (capsule.segment.a.as_dvec2(), capsule.segment.b.as_dvec2());
    let normal = capsule.normal;
    let mut best = sweep_scaled(start - a, b - a, radius, motion, normal, false);
    for (end, capped) in [(a, capsule.caps[0]), (b, capsule.caps[1])] {
        if capped
            && let Some(hit) = sweep_scaled(start - end, DVec2::ZERO, radius, motion, normal, true)
            && best.is_none_or(|b| hit.t < b.t)
        {
            best = Some(hit);
        }
    }
    best
}

/// [`circle_segment`] for a centre at `offset` from the segment's first end, the segment
/// `e` long, with its rounded first end when `cap` (a cap alone when `e` is zero), scaled
/// by the power of two that brings the largest component of `offset`, `e` and `motion` to
/// [`SWEEP_EXPONENT`] and rounded to `f32`. The scaling is exact and changes neither `t`
/// nor the normal.
///
/// Two sizes are adjusted first. A radius larger than twice the sum of the magnitudes of
/// the components (so that the circle holds the segment over the whole motion) is
/// clamped to that: the sweep's answer is the same for every such radius (a flat side
/// within the radius and a cap inside the circle are met at once, whatever the radius),
/// and it keeps the squares of the caps' quadratic in range. A segment that the scaling
/// would leave shorter than `2^SEGMENT_EXPONENT` (a circle of radius 10³⁰ around a map of
/// unit cells) is scaled up to that instead, by up to [`SEGMENT_RAISE`] more binary
/// orders, which only the flat side sees (it never squares the offset).
fn sweep_scaled(
    offset: DVec2,
    e: DVec2,
    radius: f64,
    motion: DVec2,
    normal: Vec2,
    cap: bool,
) -> Option<SweepHit> {
    let size = offset.abs().max(e.abs()).max(motion.abs()).max_element();
    if size == 0.0 {
        return None;
    }
    let mut k = SWEEP_EXPONENT - size.log2().floor() as i32;
    let segment = e.abs().max_element();
    if segment > 0.0 {
        k = k.max((SEGMENT_EXPONENT - segment.log2().floor() as i32).min(k + SEGMENT_RAISE));
    }
    let scale = 2f64.powi(k);
    // (Only a motion or offset below 2⁻⁹⁷⁰ units, which moves nothing, gets here.)
    if !(scale.is_finite() && scale > 0.0) {
        return None;
    }
    let holds = 2.0 * (offset.abs() + e.abs() + motion.abs()).element_sum() * scale;
    circle_segment(
        (offset * scale).as_vec2(),
        (radius * scale).min(holds) as f32,
        (motion * scale).as_vec2(),
        &Segment::new(Vec2::ZERO, (e * scale).as_vec2()),
        normal,
        [cap, false],
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clipping_a_motion_of_1e30_keeps_its_line_and_its_t() {
        // The line y = x/4 through the origin, from 2¹⁰⁰ to the left, clipped to [−2, 2]².
        let (c, m) = (
            Vec2::new(-2f32.powi(100), -2f32.powi(98)),
            Vec2::new(2f32.powi(101), 2f32.powi(99)),
        );
        let part = MotionPart::clip(c, m, DVec2::splat(-2.0), DVec2::splat(2.0)).unwrap();
        assert!(
            (part.start - DVec2::new(-2.0, -0.5)).length() < 1e-12,
            "{part:?}"
        );
        assert!(
            (part.motion - DVec2::new(4.0, 1.0)).length() < 1e-12,
            "{part:?}"
        );
        let length = m.as_dvec2().length();
        assert!((part.dt * length - 17f64.sqrt()).abs() < 1e-12, "{part:?}");
        assert!((part.t0 - 0.5).abs() < 1e-15, "{part:?}");
        // Pointing away, or passing beside the box: nothing.
        assert_eq!(
            MotionPart::clip(c, -m, DVec2::splat(-2.0), DVec2::splat(2.0)),
            None
        );
        let beside = Vec2::new(0.0, 2f32.powi(80));
        assert_eq!(
            MotionPart::clip(c + beside, m, DVec2::splat(-2.0), DVec2::splat(2.0)),
            None
        );
    }

    #[test]
    fn a_motion_inside_the_box_is_kept_as_given() {
        let (c, m) = (Vec2::new(0.3, -1.1), Vec2::new(1.25, 0.7));
        let part = MotionPart::clip(c, m, DVec2::splat(-2.0), DVec2::splat(2.0)).unwrap();
        let whole = MotionPart {
            start: c.as_dvec2(),
            motion: m.as_dvec2(),
            t0: 0.0,
            dt: 1.0,
        };
        assert_eq!(part, whole);
        assert_eq!(
            MotionPart::clip(c, Vec2::ZERO, DVec2::splat(-2.0), DVec2::splat(2.0)),
            None
        );
    }

    #[test]
    fn a_radius_holding_the_segment_gets_the_answer_of_every_such_radius() {
        // A floor from (0, 0) to (1, 0) facing up, the centre above it moving down-right,
        // and its rounded ends: radii from 4 to 10³⁰ units all hold it, and all meet it at
        // once with the same normal.
        let floor = Capsule::new(Segment::new(Vec2::ZERO, Vec2::X), Vec2::Y, [true; 2]);
        let (start, motion) = (DVec2::new(0.25, 0.5), DVec2::new(1.0, -1.0));
        let hits: Vec<_> = [4.0, 1e5, 1e15, 1e30]
            .into_iter()
            .map(|r| sweep_wide(&floor, start, r, motion))
            .collect();
        assert_eq!(
            hits[0],
            Some(SweepHit {
                t: 0.0,
                normal: Vec2::Y
            })
        );
        assert!(hits.iter().all(|h| *h == hits[0]), "{hits:?}");
        // A centre 10²⁸ above a floor a unit long, inside a circle of radius 10³⁰, moving
        // down: its flat side, whose squared length at the problem's scale would be 0 in
        // `f32`, still stops it at once.
        let far = DVec2::new(0.5, 1e28);
        let hit = sweep_wide(&floor, far, 1e30, DVec2::new(0.0, -1.0)).unwrap();
        // (Its caps meet it at once too, with normals a hair off vertical: the flat side,
        // found first, is the one reported.)
        assert_eq!((hit.t, hit.normal), (0.0, Vec2::Y));
    }
}
