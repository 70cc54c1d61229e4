//! Seam culling: which segments of a cell are *active* once its neighbours are known.
//!
//! Two solid tiles side by side each have an edge on the seam between them, facing each
//! other. Neither can ever be touched from outside, and worse, a body sliding along the
//! floor would catch on their end points (Box2D's "ghost collisions"; see
//! `docs/seams.md`). A segment that lies on a cell's boundary is hidden where an
//! opposite-facing **solid** segment of the neighbour across that boundary covers it; where
//! the cover is partial (a half-height block beside a full one) only the covered part is
//! hidden and the rest stays active as a shorter piece. Non-solid segments (one-way
//! platforms) hide nothing, so the underside of a block above a platform stays reachable.

use glam::Vec2;

use super::store::HotSegment;
use super::{SegmentFlags, TileSegment, TileShape};

/// Which boundary line of its cell a segment lies on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Side {
    /// `x = 0`.
    MinX,
    /// `x = w`.
    MaxX,
    /// `y = 0`.
    MinY,
    /// `y = h`.
    MaxY,
}

impl Side {
    pub const ALL: [Side; 4] = [Side::MinX, Side::MaxX, Side::MinY, Side::MaxY];

    /// The cell offset of the neighbour across this side.
    pub fn neighbour_offset(self) -> (i64, i64) {
        match self {
            Side::MinX => (-1, 0),
            Side::MaxX => (1, 0),
            Side::MinY => (0, -1),
            Side::MaxY => (0, 1),
        }
    }

    fn opposite(self) -> Side {
        match self {
            Side::MinX => Side::MaxX,
            Side::MaxX => Side::MinX,
            Side::MinY => Side::MaxY,
            Side::MaxY => Side::MinY,
        }
    }

    /// Unit vector pointing out of the cell through this side.
    fn outward(self) -> Vec2 {
        match self {
            Side::MinX => Vec2::NEG_X,
            Side::MaxX => Vec2::X,
            Side::MinY => Vec2::NEG_Y,
            Side::MaxY => Vec2::Y,
        }
    }

    /// True when both end points lie on this side's line (within `eps`).
    fn holds(self, s: &TileSegment, size: Vec2, eps: f32) -> bool {
        let on = |p: Vec2| match self {
            Side::MinX => p.x.abs() <= eps,
            Side::MaxX => (p.x - size.x).abs() <= eps,
            Side::MinY => p.y.abs() <= eps,
            Side::MaxY => (p.y - size.y).abs() <= eps,
        };
        on(s.a) && on(s.b)
    }

    /// The coordinate along the side's line.
    fn along(self, p: Vec2) -> f32 {
        match self {
            Side::MinX | Side::MaxX => p.y,
            Side::MinY | Side::MaxY => p.x,
        }
    }
}

/// Tolerance for "lies on the boundary" and "coincides", in tile-local units.
pub(crate) fn seam_tolerance(size: Vec2) -> f32 {
    size.max_element() * 1e-5
}

/// Computes the active segments of a cell holding `shape`, whose neighbours across each side
/// hold `neighbour(side)`, in world coordinates (`base` is the cell's corner), into `out`.
pub(crate) fn active_segments<'s>(
    shape: &TileShape,
    size: Vec2,
    base: Vec2,
    neighbour: impl Fn(Side) -> Option<&'s TileShape>,
    out: &mut Vec<HotSegment>,
) {
    let eps = seam_tolerance(size);
    let mut covers: Vec<(f32, f32)> = Vec::new();
    for (index, s) in shape.segments().iter().enumerate() {
        let side = Side::ALL
            .into_iter()
            .find(|side| side.holds(s, size, eps) && s.normal.dot(side.outward()) > 0.0);
        covers.clear();
        if let Some(side) = side
            && let Some(other) = neighbour(side)
        {
            let facing = side.opposite();
            for t in other.segments() {
                if t.flags.contains(SegmentFlags::SOLID)
                    && facing.holds(t, size, eps)
                    && t.normal.dot(facing.outward()) > 0.0
                {
                    let (u0, u1) = (side.along(t.a), side.along(t.b));
                    covers.push((u0.min(u1), u0.max(u1)));
                }
            }
        }
        let push = |a: Vec2, b: Vec2, out: &mut Vec<HotSegment>| {
            // Active segments run with their normal on the right of a → b, whatever the
            // authored direction (see `ActiveSegment`).
            let (a, b) = if (b - a).perp_dot(s.normal) > 0.0 {
                (b, a)
            } else {
                (a, b)
            };
            let (wa, wb) = (base + a, base + b);
            out.push(HotSegment {
                a: wa,
                e: wb - wa,
                normal: s.normal,
                flags: s.flags,
                source: index as u16,
                count: 0,
            });
        };
        match side {
            Some(side) if !covers.is_empty() => {
                for (a, b) in uncovered_pieces(s, side, &mut covers, eps) {
                    push(a, b, out);
                }
            }
            _ => push(s.a, s.b, out),
        }
    }
}

/// The parts of `s` (on `side`'s line) that no interval of `covers` hides, in `s`'s
/// direction (`active_segments` then orients them by the normal).
fn uncovered_pieces(
    s: &TileSegment,
    side: Side,
    covers: &mut [(f32, f32)],
    eps: f32,
) -> Vec<(Vec2, Vec2)> {
    let (ua, ub) = (side.along(s.a), side.along(s.b));
    let (lo, hi) = (ua.min(ub), ua.max(ub));
    covers.sort_by(|x, y| x.0.total_cmp(&y.0));
    let mut gaps = Vec::new();
    let mut cursor = lo;
    for &(c0, c1) in covers.iter() {
        if c0 > cursor + eps {
            gaps.push((cursor, c0.min(hi)));
        }
        cursor = cursor.max(c1);
        if cursor >= hi - eps {
            break;
        }
    }
    if cursor < hi - eps {
        gaps.push((cursor, hi));
    }
    // Points on the segment at a given coordinate; the original end points are reused
    // exactly so uncovered ends keep their authored coordinates.
    let at = |u: f32| {
        if u == ua {
            s.a
        } else if u == ub {
            s.b
        } else {
            s.a + (s.b - s.a) * ((u - ua) / (ub - ua))
        }
    };
    let mut pieces: Vec<(Vec2, Vec2)> = gaps
        .into_iter()
        .filter(|(g0, g1)| g1 - g0 > eps)
        .map(|(g0, g1)| {
            if ua <= ub {
                (at(g0), at(g1))
            } else {
                (at(g1), at(g0))
            }
        })
        .collect();
    if ua > ub {
        pieces.reverse();
    }
    pieces
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f32, y: f32) -> Vec2 {
        Vec2::new(x, y)
    }

    fn square() -> TileShape {
        TileShape::polygon(&[v(0.0, 0.0), v(1.0, 0.0), v(1.0, 1.0), v(0.0, 1.0)]).unwrap()
    }

    #[test]
    fn full_neighbour_hides_the_shared_edge() {
        let sq = square();
        let mut out = Vec::new();
        active_segments(
            &sq,
            Vec2::ONE,
            Vec2::ZERO,
            |side| (side == Side::MaxX).then_some(&sq),
            &mut out,
        );
        assert_eq!(out.len(), 3);
        assert!(out.iter().all(|s| s.normal != Vec2::X));
    }

    #[test]
    fn half_height_neighbour_hides_only_the_covered_half() {
        let sq = square();
        // A half-height block occupying y in [0.5, 1] of the cell to the right (y down: the
        // lower half).
        let half =
            TileShape::polygon(&[v(0.0, 0.5), v(1.0, 0.5), v(1.0, 1.0), v(0.0, 1.0)]).unwrap();
        let mut out = Vec::new();
        active_segments(
            &sq,
            Vec2::ONE,
            Vec2::ZERO,
            |side| (side == Side::MaxX).then_some(&half),
            &mut out,
        );
        let right: Vec<_> = out.iter().filter(|s| s.normal == Vec2::X).collect();
        assert_eq!(right.len(), 1);
        let (a, b) = (right[0].a, right[0].b());
        assert_eq!(a.y.min(b.y), 0.0);
        assert_eq!(a.y.max(b.y), 0.5);
        assert_eq!(a.x, 1.0);
    }

    #[test]
    fn one_way_platform_does_not_hide_the_block_above() {
        let sq = square();
        let platform = TileShape::from_segments([TileSegment::new(
            v(0.0, 0.0),
            v(1.0, 0.0),
            v(0.0, -1.0),
            SegmentFlags::ONE_WAY,
        )])
        .unwrap();
        let mut out = Vec::new();
        // The block's MaxY side (y = 1) borders the platform's cell, whose MinY line holds
        // the platform facing the block.
        active_segments(
            &sq,
            Vec2::ONE,
            Vec2::ZERO,
            |side| (side == Side::MaxY).then_some(&platform),
            &mut out,
        );
        assert_eq!(out.len(), 4);
        out.clear();
        // The platform itself is hidden by the solid block above it.
        active_segments(
            &platform,
            Vec2::ONE,
            Vec2::ZERO,
            |side| (side == Side::MinY).then_some(&sq),
            &mut out,
        );
        assert!(out.is_empty());
    }
}
