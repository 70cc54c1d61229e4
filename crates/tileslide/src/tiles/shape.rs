use glam::Vec2;
use thiserror::Error;

use super::SegmentFlags;
use crate::geometry::{Ray, Segment, cast_ray_segment, in_range, unit_normal};

/// One segment of a tile shape, in tile-local coordinates.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TileSegment {
    /// Start point, tile-local.
    pub a: Vec2,
    /// End point, tile-local.
    pub b: Vec2,
    /// Outward unit normal: the side the segment blocks from.
    pub normal: Vec2,
    /// What the segment is.
    pub flags: SegmentFlags,
}

impl TileSegment {
    /// A segment from `a` to `b` facing `normal` (normalised by [`TileShape::from_segments`]).
    #[must_use]
    pub fn new(a: Vec2, b: Vec2, normal: Vec2, flags: SegmentFlags) -> Self {
        Self {
            a,
            b,
            normal,
            flags,
        }
    }

    /// The segment as plain geometry.
    #[must_use]
    pub fn segment(&self) -> Segment {
        Segment::new(self.a, self.b)
    }
}

/// Most segments one tile shape may have.
pub const MAX_SHAPE_SEGMENTS: usize = 4096;

/// Why a tile shape was refused.
#[derive(Clone, Debug, PartialEq, Error)]
#[non_exhaustive]
pub enum ShapeError {
    /// A coordinate or normal component is NaN or infinite.
    #[error("segment {segment} has a non-finite coordinate or normal")]
    NonFinite {
        /// Index of the segment (or polygon edge).
        segment: usize,
    },
    /// Start and end point are the same.
    #[error("segment {segment} has zero length")]
    ZeroLength {
        /// Index of the segment (or polygon edge).
        segment: usize,
    },
    /// The normal is the zero vector.
    #[error("segment {segment} has a zero normal")]
    ZeroNormal {
        /// Index of the segment.
        segment: usize,
    },
    /// A polygon needs at least three corners.
    #[error("a polygon needs at least 3 points, got {points}")]
    TooFewPoints {
        /// How many points were given.
        points: usize,
    },
    /// The polygon encloses no area, so its winding (and its normals) are undefined.
    #[error("the polygon has zero area")]
    ZeroArea,
    /// A point lies beyond [`MAX_COORD`](crate::limits::MAX_COORD) from the tile's corner:
    /// no tile of a map is that large, and the shape's areas and normals would overflow.
    #[error(
        "segment {segment} has the point ({x}, {y}), beyond the ±{max} coordinate range \
         (MAX_COORD)",
        max = crate::geometry::MAX_COORD
    )]
    OutOfRange {
        /// Index of the segment (or polygon edge) the point starts or ends.
        segment: usize,
        /// The point's x.
        x: f32,
        /// The point's y.
        y: f32,
    },
    /// Two edges of the polygon cross or overlap.
    #[error("polygon edges {first} and {second} intersect")]
    SelfIntersecting {
        /// Index of the first edge.
        first: usize,
        /// Index of the second edge.
        second: usize,
    },
    /// A pixel mask whose length is not its width times its height.
    #[error("a {width} × {height} mask needs {} pixels, got {len}", u64::from(*width) * u64::from(*height))]
    MaskSize {
        /// The width given.
        width: u32,
        /// The height given.
        height: u32,
        /// The mask's length.
        len: usize,
    },
    /// A tracing tolerance that is negative or not finite.
    #[error("the tracing tolerance must be finite and not negative, got {tolerance}")]
    BadTolerance {
        /// The tolerance given.
        tolerance: f32,
    },
    /// More than [`MAX_SHAPE_SEGMENTS`] segments.
    #[error("the shape has {count} segments, more than the {MAX_SHAPE_SEGMENTS} a tile may have")]
    TooManySegments {
        /// How many it would have.
        count: usize,
    },
    /// A segment leaves the tile's rectangle `[0, w] × [0, h]`.
    #[error("segment {segment} leaves the tile's {w}×{h} rectangle")]
    OutsideTile {
        /// Index of the segment.
        segment: usize,
        /// Tile width.
        w: f32,
        /// Tile height.
        h: f32,
    },
}

/// The collision shape of one tile: segments with outward normals and flags, in tile-local
/// coordinates (`[0, w] × [0, h]` for a tile of size `w × h`).
///
/// ```
/// # use tileslide::{TileShape, Vec2};
/// // A ramp: the triangle (0,1)-(1,1)-(1,0) in a y-down unit tile.
/// let ramp = TileShape::polygon(&[Vec2::new(0.0, 1.0), Vec2::new(1.0, 1.0), Vec2::new(1.0, 0.0)])?;
/// assert_eq!(ramp.segments().len(), 3);
/// let slope = ramp.segments()[2];
/// assert!(slope.normal.x < 0.0 && slope.normal.y < 0.0); // faces up-left (y down)
/// assert!(ramp.contains_point(Vec2::new(0.9, 0.9)));
/// # Ok::<(), tileslide::ShapeError>(())
/// ```
#[derive(Clone, Debug, PartialEq, Default)]
pub struct TileShape {
    segments: Vec<TileSegment>,
    /// For each kept segment, its index in the input (duplicates are dropped), so errors
    /// name the segment the author wrote.
    input_index: Vec<usize>,
    closed: bool,
}

impl TileShape {
    /// A shape with no segments (a tile that blocks nothing).
    #[must_use]
    pub fn empty() -> Self {
        Self::default()
    }

    /// A solid closed polygon. Normals come from the winding (either winding works; concave
    /// polygons too): each edge's normal points away from the enclosed area.
    pub fn polygon(points: &[Vec2]) -> Result<Self, ShapeError> {
        Self::empty().with_polygon(points, SegmentFlags::SOLID)
    }

    /// This shape plus another closed polygon with the given flags.
    pub fn with_polygon(
        mut self,
        points: &[Vec2],
        flags: SegmentFlags,
    ) -> Result<Self, ShapeError> {
        let first = self.segments.len();
        if first + points.len() > MAX_SHAPE_SEGMENTS {
            return Err(ShapeError::TooManySegments {
                count: first + points.len(),
            });
        }
        let edges = polygon_edges(points, first)?;
        for (i, (a, b, normal)) in edges.into_iter().enumerate() {
            self.segments.push(TileSegment::new(a, b, normal, flags));
            self.input_index.push(first + i);
        }
        self.closed = outline_is_closed(&self.segments);
        Ok(self)
    }

    /// A shape from explicit segments with their own normals (normalised here, unless
    /// already of unit length to four ulps: then kept as given). Exact duplicates are kept
    /// once.
    pub fn from_segments(
        segments: impl IntoIterator<Item = TileSegment>,
    ) -> Result<Self, ShapeError> {
        let mut out: Vec<TileSegment> = Vec::new();
        let mut input_index = Vec::new();
        for (i, mut s) in segments.into_iter().enumerate() {
            if !(s.a.is_finite() && s.b.is_finite() && s.normal.is_finite()) {
                return Err(ShapeError::NonFinite { segment: i });
            }
            out_of_range(i, s.a)?;
            out_of_range(i, s.b)?;
            if s.a == s.b {
                return Err(ShapeError::ZeroLength { segment: i });
            }
            // A normal already of unit length (to four ulps) is kept as given, so that a
            // shape rebuilt from its own segments (a baked map) is the same bit for bit;
            // any other is normalised. (Finite here, so `None` means the zero vector.)
            s.normal = if (s.normal.length_squared() - 1.0).abs() <= 4.0 * f32::EPSILON {
                s.normal + Vec2::ZERO
            } else {
                unit_normal(s.normal).ok_or(ShapeError::ZeroNormal { segment: i })?
            };
            if !out.contains(&s) {
                if out.len() == MAX_SHAPE_SEGMENTS {
                    return Err(ShapeError::TooManySegments {
                        count: out.len() + 1,
                    });
                }
                out.push(s);
                input_index.push(i);
            }
        }
        let closed = outline_is_closed(&out);
        Ok(Self {
            segments: out,
            input_index,
            closed,
        })
    }

    /// The segments, in the order they were given.
    #[must_use]
    pub fn segments(&self) -> &[TileSegment] {
        &self.segments
    }

    /// True when the solid segments form closed outlines, so the shape has an inside.
    #[must_use]
    pub fn has_inside(&self) -> bool {
        self.closed
    }

    /// True when the tile-local point lies inside the solid outlines (crossing-number test;
    /// a point on an edge is decided by the half-open rule, so two tiles sharing an edge never
    /// both claim it). Always false for a shape without an inside.
    #[must_use]
    pub fn contains_point(&self, p: Vec2) -> bool {
        if !self.closed {
            return false;
        }
        let mut inside = false;
        for s in self
            .segments
            .iter()
            .filter(|s| s.flags.contains(SegmentFlags::SOLID))
        {
            if (s.a.y > p.y) != (s.b.y > p.y) {
                let x = s.a.x + (p.y - s.a.y) / (s.b.y - s.a.y) * (s.b.x - s.a.x);
                if p.x < x {
                    inside = !inside;
                }
            }
        }
        inside
    }

    /// Checks that every segment lies in the tile's rectangle `[0, w] × [0, h]` (with a
    /// tolerance of 1e-5 of the tile size on each axis).
    pub(crate) fn check_inside_tile(&self, size: Vec2) -> Result<(), ShapeError> {
        // 1e-5 of a cell on each axis: well inside the ray walk's 1e-4-cell touch tolerance,
        // which relies on every segment lying in its own cell.
        let tol = size * 1e-5;
        let lo = -tol;
        let hi = size + tol;
        for (i, s) in self.segments.iter().enumerate() {
            for p in [s.a, s.b] {
                if p.cmplt(lo).any() || p.cmpgt(hi).any() {
                    return Err(ShapeError::OutsideTile {
                        segment: self.input_index.get(i).copied().unwrap_or(i),
                        w: size.x,
                        h: size.y,
                    });
                }
            }
        }
        Ok(())
    }
}

/// An error naming `p` and its `segment` when it lies beyond [`MAX_COORD`](crate::limits::MAX_COORD).
fn out_of_range(segment: usize, p: Vec2) -> Result<(), ShapeError> {
    if in_range(p) {
        Ok(())
    } else {
        Err(ShapeError::OutOfRange {
            segment,
            x: p.x,
            y: p.y,
        })
    }
}

/// The edges of a closed polygon with normals from its winding, after validation.
fn polygon_edges(points: &[Vec2], first: usize) -> Result<Vec<(Vec2, Vec2, Vec2)>, ShapeError> {
    let n = points.len();
    if n < 3 {
        return Err(ShapeError::TooFewPoints { points: n });
    }
    for (i, p) in points.iter().enumerate() {
        if !p.is_finite() {
            return Err(ShapeError::NonFinite { segment: first + i });
        }
        out_of_range(first + i, *p)?;
    }
    let edge = |i: usize| (points[i], points[(i + 1) % n]);
    for i in 0..n {
        let (a, b) = edge(i);
        if a == b {
            return Err(ShapeError::ZeroLength { segment: first + i });
        }
    }
    // Shoelace: twice the signed area. Positive means counter-clockwise in a y-up frame, where
    // the inside lies to the left of every edge; the formula does not care which way y points.
    let twice_area: f32 = (0..n).map(|i| edge(i).0.perp_dot(edge(i).1)).sum();
    if twice_area == 0.0 || !twice_area.is_finite() {
        return Err(ShapeError::ZeroArea);
    }
    for i in 0..n {
        for j in (i + 1)..n {
            let adjacent = j == i + 1 || (i == 0 && j == n - 1);
            let (a0, a1) = edge(i);
            let (b0, b1) = edge(j);
            let crossing = if adjacent {
                // Adjacent edges share a corner; they are bad only if they fold back on
                // each other (collinear and overlapping beyond the corner).
                let (shared, p, q) = if a1 == b0 { (a1, a0, b1) } else { (a0, a1, b0) };
                (p - shared).perp_dot(q - shared) == 0.0 && (p - shared).dot(q - shared) > 0.0
            } else {
                segments_touch(a0, a1, b0, b1)
            };
            if crossing {
                return Err(ShapeError::SelfIntersecting {
                    first: first + i,
                    second: first + j,
                });
            }
        }
    }
    Ok((0..n)
        .map(|i| {
            let (a, b) = edge(i);
            let d = (b - a).normalize();
            // Right of the direction is outside for a counter-clockwise polygon.
            let normal = if twice_area > 0.0 {
                Vec2::new(d.y, -d.x)
            } else {
                Vec2::new(-d.y, d.x)
            } + Vec2::ZERO; // no `-0` components (see `from_segments`)
            (a, b, normal)
        })
        .collect())
}

/// True when two closed segments share a point (including collinear overlap).
fn segments_touch(a0: Vec2, a1: Vec2, b0: Vec2, b1: Vec2) -> bool {
    if cast_ray_segment(&Ray::between(a0, a1), &Segment::new(b0, b1)).is_some() {
        return true;
    }
    let d = a1 - a0;
    if d.perp_dot(b0 - a0) != 0.0 || d.perp_dot(b1 - a0) != 0.0 {
        return false;
    }
    // Collinear: overlap of the projections on the line.
    let proj = |p: Vec2| (p - a0).dot(d);
    let (lo, hi) = (proj(b0).min(proj(b1)), proj(b0).max(proj(b1)));
    hi >= 0.0 && lo <= d.dot(d)
}

/// True when the solid segments' end points pair up: every end point is shared by an even
/// number of solid segment ends, so the segments form closed outlines.
fn outline_is_closed(segments: &[TileSegment]) -> bool {
    let solid: Vec<&TileSegment> = segments
        .iter()
        .filter(|s| s.flags.contains(SegmentFlags::SOLID))
        .collect();
    if solid.is_empty() {
        return false;
    }
    let extent = solid
        .iter()
        .flat_map(|s| [s.a.abs().max_element(), s.b.abs().max_element()])
        .fold(0.0f32, f32::max);
    let tol = extent.max(1.0) * 1e-5;
    let ends: Vec<Vec2> = solid.iter().flat_map(|s| [s.a, s.b]).collect();
    ends.iter().all(|p| {
        let count = ends.iter().filter(|q| q.distance(*p) <= tol).count();
        count % 2 == 0
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f32, y: f32) -> Vec2 {
        Vec2::new(x, y)
    }

    #[test]
    fn polygon_normals_point_outward_for_either_winding() {
        let square = [v(0.0, 0.0), v(1.0, 0.0), v(1.0, 1.0), v(0.0, 1.0)];
        let mut reversed = square;
        reversed.reverse();
        for pts in [&square[..], &reversed[..]] {
            let shape = TileShape::polygon(pts).unwrap();
            for s in shape.segments() {
                let mid = (s.a + s.b) * 0.5;
                let outward = mid - v(0.5, 0.5);
                assert!(s.normal.dot(outward) > 0.0, "{s:?}");
                assert!((s.normal.length() - 1.0).abs() < 1e-6);
            }
        }
    }

    #[test]
    fn concave_polygon_normals_point_outward() {
        // An L shape: the reflex corner at (0.5, 0.5).
        let l = [
            v(0.0, 0.0),
            v(1.0, 0.0),
            v(1.0, 0.5),
            v(0.5, 0.5),
            v(0.5, 1.0),
            v(0.0, 1.0),
        ];
        let shape = TileShape::polygon(&l).unwrap();
        for s in shape.segments() {
            let mid = (s.a + s.b) * 0.5;
            // A point a little along the normal is outside, a little against it inside.
            assert!(!shape.contains_point(mid + s.normal * 0.01), "{s:?}");
            assert!(shape.contains_point(mid - s.normal * 0.01), "{s:?}");
        }
        assert!(!shape.contains_point(v(0.75, 0.75)));
    }

    #[test]
    fn invalid_polygons_are_refused_with_the_problem_named() {
        assert_eq!(
            TileShape::polygon(&[v(0.0, 0.0), v(1.0, 0.0)]),
            Err(ShapeError::TooFewPoints { points: 2 })
        );
        assert_eq!(
            TileShape::polygon(&[v(0.0, 0.0), v(1.0, 0.0), v(2.0, 0.0)]),
            Err(ShapeError::ZeroArea)
        );
        assert_eq!(
            TileShape::polygon(&[v(0.0, 0.0), v(f32::NAN, 0.0), v(1.0, 1.0)]),
            Err(ShapeError::NonFinite { segment: 1 })
        );
        assert_eq!(
            TileShape::polygon(&[v(0.0, 0.0), v(0.0, 0.0), v(1.0, 1.0)]),
            Err(ShapeError::ZeroLength { segment: 0 })
        );
        // A bow tie crosses itself.
        assert!(matches!(
            TileShape::polygon(&[v(0.0, 0.0), v(2.0, 2.0), v(2.0, 0.0), v(0.0, 1.0)]),
            Err(ShapeError::SelfIntersecting { .. })
        ));
        // Points so far out that the area would overflow are named, not called flat.
        let e = TileShape::polygon(&[v(0.0, 0.0), v(1e20, 0.0), v(1e20, 1e20)]).unwrap_err();
        assert_eq!(
            e,
            ShapeError::OutOfRange {
                segment: 1,
                x: 1e20,
                y: 0.0
            }
        );
        assert!(e.to_string().contains("100000000000000000000"), "{e}");
        let s = |a, b| TileSegment::new(a, b, v(0.0, -1.0), SegmentFlags::SOLID);
        assert!(matches!(
            TileShape::from_segments([s(v(0.0, 0.0), v(-3e38, 0.0))]),
            Err(ShapeError::OutOfRange { segment: 0, .. })
        ));
    }

    #[test]
    fn explicit_segments_are_validated_and_normalised() {
        let s = |a, b, n| TileSegment::new(a, b, n, SegmentFlags::SOLID);
        assert_eq!(
            TileShape::from_segments([s(v(0.0, 0.0), v(0.0, 0.0), v(1.0, 0.0))]),
            Err(ShapeError::ZeroLength { segment: 0 })
        );
        assert_eq!(
            TileShape::from_segments([
                s(v(0.0, 0.0), v(1.0, 0.0), v(0.0, 1.0)),
                s(v(0.0, 0.0), v(1.0, 0.0), v(0.0, 0.0))
            ]),
            Err(ShapeError::ZeroNormal { segment: 1 })
        );
        assert_eq!(
            TileShape::from_segments([s(v(0.0, f32::INFINITY), v(1.0, 0.0), v(0.0, 1.0))]),
            Err(ShapeError::NonFinite { segment: 0 })
        );
        let shape = TileShape::from_segments([s(v(0.0, 0.0), v(1.0, 0.0), v(0.0, 3.0))]).unwrap();
        assert_eq!(shape.segments()[0].normal, v(0.0, 1.0));
        assert!(!shape.has_inside());
    }

    #[test]
    fn duplicate_segments_are_kept_once() {
        let s = TileSegment::new(v(0.0, 0.0), v(1.0, 0.0), v(0.0, 1.0), SegmentFlags::SOLID);
        let shape = TileShape::from_segments([s, s]).unwrap();
        assert_eq!(shape.segments().len(), 1);
    }
}
