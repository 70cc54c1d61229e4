//! End-point continuity: for each end of an active segment, the active segment that
//! continues the surface from there, if any.
//!
//! A resolver sliding a circle along a floor asks this at every seam: if the floor continues
//! into a collinear (or concave) neighbour, the end point is not a corner and must not push
//! the circle back. This is the information Box2D's chain shapes carry as "ghost vertices".
//! The same pass records which ends need a rounded cap for a swept circle: an end with no
//! continuation, one where the surface turns away (a convex corner), and any end of a
//! one-way platform or where the flags change (there the neighbour does not stop every
//! circle this segment stops).

use glam::Vec2;

use super::SegmentFlags;
use super::link::Link;
use super::store::{CAP_A, CAP_B, HotSegment, SegmentStore};

/// Two ends closer than this (in cells) are the same point.
const JOIN_TOLERANCE: f32 = 1e-4;

/// A neighbour turns away (a convex corner) when its normal leans along this segment's
/// outward direction at the shared end by more than this cosine; below it the surface is
/// flat or concave there and the end needs no cap.
const CONVEX_COSINE: f32 = 1e-4;

/// Recomputes the links of every active segment in cell `(col, row)` from the active
/// segments of that cell and its eight neighbours.
pub(crate) fn link_cell(
    store: &mut SegmentStore,
    width: u32,
    height: u32,
    cell_size: Vec2,
    col: u32,
    row: u32,
) {
    let index = (row * width + col) as usize;
    let count = store.cell(index).len();
    if count == 0 {
        return;
    }
    let tol = cell_size.max_element() * JOIN_TOLERANCE;
    let tol2 = tol * tol;
    for i in 0..count {
        let seg = store.cell(index)[i];
        let mut ends = [Link::NONE; 2];
        let mut caps = CAP_A | CAP_B;
        for (k, end) in [seg.a, seg.b()].into_iter().enumerate() {
            let mut best: Option<(f32, Link, HotSegment)> = None;
            for dr in -1i64..=1 {
                for dc in -1i64..=1 {
                    let (c, r) = (col as i64 + dc, row as i64 + dr);
                    if c < 0 || r < 0 || c >= width as i64 || r >= height as i64 {
                        continue;
                    }
                    let other_index = (r as u32 * width + c as u32) as usize;
                    for (j, other) in store.cell(other_index).iter().enumerate() {
                        if other_index == index && j == i {
                            continue;
                        }
                        let touches = other.a.distance_squared(end) <= tol2
                            || other.b().distance_squared(end) <= tol2;
                        let score = seg.normal.dot(other.normal);
                        // Back-to-back faces (a thin sheet folding back) are not a continuation.
                        if !touches || score < -0.999 {
                            continue;
                        }
                        if best.is_none_or(|(s, _, _)| score > s) {
                            best = Some((score, Link::new(dc, dr, j), *other));
                        }
                    }
                }
            }
            ends[k] = best.map_or(Link::NONE, |(_, link, _)| link);
            if !end_join(&seg, best.map(|(_, _, other)| other).as_ref(), k).needs_cap() {
                caps &= !(if k == 0 { CAP_A } else { CAP_B });
            }
        }
        store.links_mut(index)[i] = ends;
        store.caps_mut(index)[i] = caps;
    }
}

/// How the surface goes on at an end of an active segment, and so whether a swept circle
/// must round that end (a cap): what the map decides for every end it links (see
/// [`TileMap::explain_cell`](crate::TileMap::explain_cell)).
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum EndJoin {
    /// It continues straight on into a segment with the same flags: no cap (a circle
    /// sliding over the seam sees one flat surface).
    Flat,
    /// It turns concave (into the material's side) into a segment with the same flags: no
    /// cap (the neighbour's flat side covers the end).
    Concave,
    /// Nothing continues it: a cap.
    Open,
    /// The surface turns away (a convex corner): a cap.
    Convex,
    /// It continues into a segment with other flags, which does not stop every circle this
    /// one stops: a cap.
    FlagsChange,
    /// It is an end of a one-way platform, whose back side a circle can come from: a cap.
    OneWay,
}

impl EndJoin {
    /// Whether a swept circle must round this end.
    #[must_use]
    pub fn needs_cap(self) -> bool {
        !matches!(self, EndJoin::Flat | EndJoin::Concave)
    }
}

/// How `seg`'s end `end` (0: `a`, 1: `b`) joins `next`, the active segment its link names
/// (none: nothing continues it). The neighbour's flat side covers the end only where the
/// surface does not turn away, only for circles in front of it, and only for bodies it
/// stops too: so only a neighbour with the same flags, and not at a one-way platform's end
/// (whose back side a circle can come from).
pub(crate) fn end_join(seg: &HotSegment, next: Option<&HotSegment>, end: usize) -> EndJoin {
    let Some(next) = next else {
        return EndJoin::Open;
    };
    // The end's outward direction: back along the segment at `a`, forward at `b`.
    let along = seg.e.normalize_or_zero();
    let outward = if end == 0 { -along } else { along };
    let turn = next.normal.dot(outward);
    if turn > CONVEX_COSINE {
        EndJoin::Convex
    } else if next.flags != seg.flags {
        EndJoin::FlagsChange
    } else if seg.flags.contains(SegmentFlags::ONE_WAY) {
        EndJoin::OneWay
    } else if turn < -CONVEX_COSINE {
        EndJoin::Concave
    } else {
        EndJoin::Flat
    }
}
