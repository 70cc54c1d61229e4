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

/// A side of a cell: the boundary line a tile segment lies on when a neighbour can hide it
/// (see [`TileMap::explain_cell`](crate::TileMap::explain_cell)). `x` and `y` are the map's
/// own axes, in a cell of size `w × h`; the map does not know which way is up.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CellSide {
    /// `x = 0`.
    MinX,
    /// `x = w`.
    MaxX,
    /// `y = 0`.
    MinY,
    /// `y = h`.
    MaxY,
}

impl CellSide {
    pub(crate) const ALL: [CellSide; 4] = [
        CellSide::MinX,
        CellSide::MaxX,
        CellSide::MinY,
        CellSide::MaxY,
    ];

    /// The cell offset of the neighbour across this side.
    pub(crate) fn neighbour_offset(self) -> (i64, i64) {
        match self {
            CellSide::MinX => (-1, 0),
            CellSide::MaxX => (1, 0),
            CellSide::MinY => (0, -1),
            CellSide::MaxY => (0, 1),
        }
    }

    pub(crate) fn opposite(self) -> CellSide {
        match self {
            CellSide::MinX => CellSide::MaxX,
            CellSide::MaxX => CellSide::MinX,
            CellSide::MinY => CellSide::MaxY,
            CellSide::MaxY => CellSide::MinY,
        }
    }

    /// Unit vector pointing out of the cell through this side.
    pub(crate) fn outward(self) -> Vec2 {
        match self {
            CellSide::MinX => Vec2::NEG_X,
            CellSide::MaxX => Vec2::X,
            CellSide::MinY => Vec2::NEG_Y,
            CellSide::MaxY => Vec2::Y,
        }
    }

    /// True when both end points lie on this side's line (within `eps`).
    fn holds(self, s: &TileSegment, size: Vec2, eps: f32) -> bool {
        let on = |p: Vec2| match self {
            CellSide::MinX => p.x.abs() <= eps,
            CellSide::MaxX => (p.x - size.x).abs() <= eps,
            CellSide::MinY => p.y.abs() <= eps,
            CellSide::MaxY => (p.y - size.y).abs() <= eps,
        };
        on(s.a) && on(s.b)
    }

    /// The coordinate along the side's line.
    pub(crate) fn along(self, p: Vec2) -> f32 {
        match self {
            CellSide::MinX | CellSide::MaxX => p.y,
            CellSide::MinY | CellSide::MaxY => p.x,
        }
    }
}

/// Tolerance for "lies on the boundary" and "coincides", in tile-local units.
pub(crate) fn seam_tolerance(size: Vec2) -> f32 {
    size.max_element() * 1e-5
}

/// The side of its cell that tile segment `s` lies on and faces out of, if any: the only
/// segments a neighbour can hide.
pub(crate) fn boundary_side(s: &TileSegment, size: Vec2, eps: f32) -> Option<CellSide> {
    CellSide::ALL
        .into_iter()
        .find(|side| side.holds(s, size, eps) && s.normal.dot(side.outward()) > 0.0)
}

/// The segments of `other`, the shape of the neighbour across `side`, that hide a segment on
/// `side`'s line: solid, on the facing side's line and facing back. Each with its index in
/// `other` and the interval of the line it covers (low, high), in `side`'s coordinate along
/// it.
pub(crate) fn covers_across(
    side: CellSide,
    other: &TileShape,
    size: Vec2,
    eps: f32,
) -> impl Iterator<Item = (usize, (f32, f32))> + '_ {
    let facing = side.opposite();
    other
        .segments()
        .iter()
        .enumerate()
        .filter(move |(_, t)| {
            t.flags.contains(SegmentFlags::SOLID)
                && facing.holds(t, size, eps)
                && t.normal.dot(facing.outward()) > 0.0
        })
        .map(move |(j, t)| {
            let (u0, u1) = (side.along(t.a), side.along(t.b));
            (j, (u0.min(u1), u0.max(u1)))
        })
}

/// Computes the active segments of a cell holding `shape`, whose neighbours across each side
/// hold `neighbour(side)`, in world coordinates (`base` is the cell's corner), into `out`.
pub(crate) fn active_segments<'s>(
    shape: &TileShape,
    size: Vec2,
    base: Vec2,
    neighbour: impl Fn(CellSide) -> Option<&'s TileShape>,
    out: &mut Vec<HotSegment>,
) {
    let eps = seam_tolerance(size);
    let mut covers: Vec<(f32, f32)> = Vec::new();
    for (index, s) in shape.segments().iter().enumerate() {
        let side = boundary_side(s, size, eps);
        covers.clear();
        if let Some(side) = side
            && let Some(other) = neighbour(side)
        {
            covers.extend(covers_across(side, other, size, eps).map(|(_, span)| span));
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
    side: CellSide,
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
            |side| (side == CellSide::MaxX).then_some(&sq),
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
            |side| (side == CellSide::MaxX).then_some(&half),
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
            |side| (side == CellSide::MaxY).then_some(&platform),
            &mut out,
        );
        assert_eq!(out.len(), 4);
        out.clear();
        // The platform itself is hidden by the solid block above it.
        active_segments(
            &platform,
            Vec2::ONE,
            Vec2::ZERO,
            |side| (side == CellSide::MinY).then_some(&sq),
            &mut out,
        );
        assert!(out.is_empty());
    }
}
