use glam::Vec2;

use super::SegmentSource;
use crate::geometry::{Aabb, Circle, Segment};
use crate::tiles::{Cell, SegmentFlags, SegmentRef, TileId, TileMap};

/// A segment found by an overlap query.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SegmentOverlap {
    /// The segment, in world coordinates.
    pub segment: Segment,
    /// Its outward unit normal.
    pub normal: Vec2,
    /// Its flags.
    pub flags: SegmentFlags,
    /// Where it comes from.
    pub source: SegmentSource,
}

impl TileMap {
    /// The cells whose closed rectangles share a point with the closed box, row by row.
    /// Empty for a box outside the map or with a non-finite coordinate.
    pub fn cells_overlapping(&self, aabb: &Aabb) -> impl Iterator<Item = Cell> + use<> {
        let (c0, r0, c1, r1) = self.cell_range(aabb).unwrap_or((1, 1, 0, 0));
        (r0..=r1).flat_map(move |r| (c0..=c1).map(move |c| Cell::new(c, r)))
    }

    /// The first and last column and row of the cells whose closed rectangles share a
    /// point with the closed box, or `None`.
    pub(crate) fn cell_range(&self, aabb: &Aabb) -> Option<(u32, u32, u32, u32)> {
        let inv = self.inv_cell_size();
        let lo = (aabb.min - self.origin()) * inv;
        let hi = (aabb.max - self.origin()) * inv;
        let (w, h) = (self.width() as f32, self.height() as f32);
        let valid = aabb.is_valid()
            && lo.is_finite()
            && hi.is_finite()
            && hi.x >= 0.0
            && hi.y >= 0.0
            && lo.x <= w
            && lo.y <= h;
        // Cell c's closed rectangle [c, c+1] touches [lo, hi] when c ≥ lo − 1 and c ≤ hi.
        valid.then(|| {
            (
                (lo.x.ceil() - 1.0).max(0.0) as u32,
                (lo.y.ceil() - 1.0).max(0.0) as u32,
                hi.x.floor().min(w - 1.0) as u32,
                hi.y.floor().min(h - 1.0) as u32,
            )
        })
    }

    /// Active and temporary segments that share a point with the closed box. A box with a
    /// NaN or infinite coordinate, or with `min > max`, overlaps nothing.
    #[must_use]
    pub fn segments_overlapping_aabb(&self, aabb: &Aabb) -> Vec<SegmentOverlap> {
        self.segments_overlapping(aabb, |s| aabb.overlaps_segment(s))
    }

    /// Active and temporary segments that share a point with the disc. A circle with a
    /// non-finite centre or radius, or a negative radius, overlaps nothing.
    #[must_use]
    pub fn segments_overlapping_circle(&self, circle: &Circle) -> Vec<SegmentOverlap> {
        if !(circle.radius >= 0.0 && circle.radius.is_finite()) {
            return Vec::new();
        }
        self.segments_overlapping(&circle.aabb(), |s| circle.overlaps_segment(s))
    }

    fn segments_overlapping(
        &self,
        bounds: &Aabb,
        overlaps: impl Fn(&Segment) -> bool,
    ) -> Vec<SegmentOverlap> {
        let mut out = Vec::new();
        if !bounds.is_valid() {
            return out;
        }
        for cell in self.cells_overlapping(bounds) {
            let tile = self.tile(cell).unwrap_or(TileId(u32::MAX));
            for (index, s) in self.active_segments(cell).enumerate() {
                if overlaps(&s.segment) {
                    out.push(SegmentOverlap {
                        segment: s.segment,
                        normal: s.normal,
                        flags: s.flags,
                        source: SegmentSource::Tile {
                            segment: SegmentRef {
                                cell,
                                index: index as u32,
                            },
                            tile,
                        },
                    });
                }
            }
        }
        for (index, t) in self.temporaries.iter().enumerate() {
            if overlaps(&t.segment) {
                out.push(SegmentOverlap {
                    segment: t.segment,
                    normal: t.normal,
                    flags: t.flags,
                    source: SegmentSource::Temporary {
                        owner: t.owner,
                        index,
                        velocity: t.velocity,
                    },
                });
            }
        }
        out
    }

    /// True when world point `p` lies inside the solid outline of the tile in its cell
    /// (see [`TileShape::contains_point`](crate::TileShape::contains_point)). Points outside
    /// the map, and tiles without a closed outline, are not solid.
    #[must_use]
    pub fn is_point_solid(&self, p: Vec2) -> bool {
        let Some(cell) = self.cell_at(p) else {
            return false;
        };
        let Some(shape) = self.tile(cell).and_then(|id| self.tile_set().shape(id)) else {
            return false;
        };
        shape.contains_point(p - self.cell_corner(cell))
    }
}
