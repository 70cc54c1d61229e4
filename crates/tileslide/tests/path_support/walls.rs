//! Every blocking segment of a map, and exact (`f64`) distances from points and straight
//! moves to them: what "clear of the walls" means for the navigation grid, computed by
//! brute force over the whole map instead of the cells near the query.

use glam::DVec2;
use tileslide::{Cell, SegmentFlags, TileMap, Vec2};

/// The active segments with the SOLID flag of every cell, plus the map's four border edges
/// (the navigation grid never lets a circle leave the map).
#[derive(Clone, Debug)]
pub struct Walls {
    pub segments: Vec<(DVec2, DVec2)>,
}

impl Walls {
    /// The walls of `map`.
    pub fn of(map: &TileMap) -> Self {
        let mut segments = Vec::new();
        for row in 0..map.height() {
            for col in 0..map.width() {
                for s in map.active_segments(Cell::new(col, row)) {
                    if s.flags.intersects(SegmentFlags::SOLID) {
                        segments.push((s.segment.a.as_dvec2(), s.segment.b.as_dvec2()));
                    }
                }
            }
        }
        let lo = map.origin().as_dvec2();
        let size = map.cell_size().as_dvec2()
            * DVec2::new(f64::from(map.width()), f64::from(map.height()));
        let hi = lo + size;
        let corners = [lo, DVec2::new(hi.x, lo.y), hi, DVec2::new(lo.x, hi.y)];
        for k in 0..4 {
            segments.push((corners[k], corners[(k + 1) % 4]));
        }
        Self { segments }
    }

    /// The least distance from the straight move `a → b` to any wall.
    pub fn distance_to_move(&self, a: Vec2, b: Vec2) -> f64 {
        let (a, b) = (a.as_dvec2(), b.as_dvec2());
        self.segments
            .iter()
            .map(|&(c, d)| segment_distance(a, b, c, d))
            .fold(f64::INFINITY, f64::min)
    }

    /// The least distance from point `p` to any wall.
    pub fn distance_to_point(&self, p: Vec2) -> f64 {
        let p = p.as_dvec2();
        self.segments
            .iter()
            .map(|&(c, d)| point_segment_distance(p, c, d))
            .fold(f64::INFINITY, f64::min)
    }

    /// How wide a circle can make the straight move `a → b`: 0 if an end is inside a solid
    /// tile (`map.is_point_solid`), else the distance to the walls.
    pub fn clearance(&self, map: &TileMap, a: Vec2, b: Vec2) -> f64 {
        if map.is_point_solid(a) || map.is_point_solid(b) {
            0.0
        } else {
            self.distance_to_move(a, b)
        }
    }
}

/// Distance from `p` to the segment `a → b`.
pub fn point_segment_distance(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let ab = b - a;
    let len2 = ab.length_squared();
    let t = if len2 > 0.0 {
        ((p - a).dot(ab) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    p.distance(a + ab * t)
}

/// Distance between the segments `a → b` and `c → d`: 0 if they cross, else the least of
/// the four end-point distances (a touching or collinear overlap puts an end point on the
/// other segment, so that is 0 too).
pub fn segment_distance(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> f64 {
    let o1 = (b - a).perp_dot(c - a);
    let o2 = (b - a).perp_dot(d - a);
    let o3 = (d - c).perp_dot(a - c);
    let o4 = (d - c).perp_dot(b - c);
    if o1 * o2 < 0.0 && o3 * o4 < 0.0 {
        return 0.0;
    }
    point_segment_distance(a, c, d)
        .min(point_segment_distance(b, c, d))
        .min(point_segment_distance(c, a, b))
        .min(point_segment_distance(d, a, b))
}
