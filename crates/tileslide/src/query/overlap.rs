use glam::{DVec2, Vec2};

use super::SegmentSource;
use crate::geometry::{Aabb, Circle, MAX_COORD, Segment, in_range};
use crate::tiles::{Cell, SegmentFlags, SegmentRef, TileId, TileMap};

/// A segment found by an overlap query.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
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
    /// Empty for a box outside the map or with a non-finite coordinate; a box of any
    /// finite size is answered.
    pub fn cells_overlapping(&self, aabb: &Aabb) -> impl Iterator<Item = Cell> + use<> {
        // Cut to the map's bounds and a cell beyond first (which changes no answer: every
        // cell lies within them), so that nothing computed from the box overflows.
        let bounds = self.bounds();
        let (lo, hi) = (bounds.min - self.cell_size(), bounds.max + self.cell_size());
        let range = aabb
            .is_valid()
            .then(|| Aabb {
                min: aabb.min.clamp(lo, hi),
                max: aabb.max.clamp(lo, hi),
            })
            .and_then(|cut| self.cell_range(&cut));
        let (c0, r0, c1, r1) = range.unwrap_or((1, 1, 0, 0));
        (r0..=r1).flat_map(move |r| (c0..=c1).map(move |c| Cell::new(c, r)))
    }

    /// The first and last column and row of the cells whose closed rectangles share a
    /// point with the closed box, or `None`.
    // Always inlined natively: the resolver's wall gathering calls it for every moving
    // circle, and with more than one caller in a program LLVM keeps it out of line (2 % of
    // the crowd's step). Not in WebAssembly, where the copies in every query cost the web
    // package 0.5 KB of its size budget.
    #[cfg_attr(not(target_arch = "wasm32"), inline(always))]
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
        // Clamped to one cell beyond the map first (which changes no answer), so that the
        // integer rounding below stays in range.
        valid.then(|| {
            let lo = lo.clamp(Vec2::splat(-1.0), Vec2::new(w, h));
            let hi = hi.clamp(Vec2::ZERO, Vec2::new(w + 1.0, h + 1.0));
            (
                (ceil_in_range(lo.x) - 1).max(0) as u32,
                (ceil_in_range(lo.y) - 1).max(0) as u32,
                floor_in_range(hi.x).min(w as i32 - 1) as u32,
                floor_in_range(hi.y).min(h as i32 - 1) as u32,
            )
        })
    }

    /// Active and temporary segments that share a point with the closed box. A box with a
    /// NaN or infinite coordinate, or with `min > max`, overlaps nothing.
    #[must_use]
    ///
    /// A box of any finite size is answered: every segment lies within
    /// [`MAX_COORD`], so the box is first cut to that range (which
    /// changes no answer), and nothing computed from it can overflow.
    pub fn segments_overlapping_aabb(&self, aabb: &Aabb) -> Vec<SegmentOverlap> {
        if !aabb.is_valid() {
            return Vec::new();
        }
        let range = Vec2::splat(MAX_COORD);
        if aabb.min.cmpgt(range).any() || aabb.max.cmplt(-range).any() {
            return Vec::new();
        }
        let cut = Aabb {
            min: aabb.min.clamp(-range, range),
            max: aabb.max.clamp(-range, range),
        };
        self.segments_overlapping(&cut, |s| cut.overlaps_segment(s))
    }

    /// Active and temporary segments that share a point with the disc. A circle with a
    /// non-finite centre or radius, or a negative radius, overlaps nothing.
    #[must_use]
    ///
    /// A circle of any finite centre and radius is answered: within
    /// [`MAX_COORD`] by the `f32` test of [`Circle::overlaps_segment`],
    /// beyond by the same test in `f64` (where the squares of `f32` values cannot
    /// overflow), on the cells of its box cut to the range where segments lie.
    pub fn segments_overlapping_circle(&self, circle: &Circle) -> Vec<SegmentOverlap> {
        if !(circle.radius >= 0.0 && circle.radius.is_finite() && circle.center.is_finite()) {
            return Vec::new();
        }
        if in_range(circle.center) && circle.radius <= MAX_COORD {
            return self.segments_overlapping(&circle.aabb(), |s| circle.overlaps_segment(s));
        }
        let range = DVec2::splat(f64::from(MAX_COORD));
        let (c, r) = (circle.center.as_dvec2(), f64::from(circle.radius));
        let bounds = Aabb {
            min: (c - r).clamp(-range, range).as_vec2(),
            max: (c + r).clamp(-range, range).as_vec2(),
        };
        self.segments_overlapping(&bounds, |s| {
            // The closest point of the segment to the centre, as `distance_squared_to`
            // finds it, in f64.
            let (a, e) = (s.a.as_dvec2(), s.delta().as_dvec2());
            let len2 = e.length_squared();
            let u = if len2 > 0.0 {
                ((c - a).dot(e) / len2).clamp(0.0, 1.0)
            } else {
                0.0
            };
            (a + e * u).distance_squared(c) <= r * r
        })
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

/// `x.floor()` as an integer, for `|x|` well inside `i32`'s range. `f32::floor` is a libm
/// call on x86-64 without SSE4.1, which made it most of the cost of finding the cells a box
/// touches; truncation and one correction give the same integer.
#[inline]
fn floor_in_range(x: f32) -> i32 {
    let i = x as i32;
    i - i32::from(i as f32 > x)
}

/// `x.ceil()` as an integer, for `|x|` well inside `i32`'s range (see [`floor_in_range`]).
#[inline]
fn ceil_in_range(x: f32) -> i32 {
    let i = x as i32;
    i + i32::from((i as f32) < x)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integer_rounding_matches_floor_and_ceil() {
        let mut values = vec![0.0, -0.0, 1.0, -1.0, 0.5, -0.5, 255.99998, 256.0, -1.0e-7];
        for k in -300..300 {
            let x = k as f32 * 0.37;
            values.extend([x, x.next_up(), x.next_down(), k as f32]);
        }
        for x in values {
            assert_eq!(floor_in_range(x), x.floor() as i32, "floor of {x}");
            assert_eq!(ceil_in_range(x), x.ceil() as i32, "ceil of {x}");
        }
    }
}
