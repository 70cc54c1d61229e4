//! Smoothing: a lattice path pulled taut into straight runs.
//!
//! The lattice path turns only in steps of 45°; the shortest way runs at any angle. From
//! each corner kept, the path goes straight to the farthest later point that the circle
//! can reach in a straight line (greedy string pulling, as in Botea et al.'s HPA*
//! smoothing), checked with the map's own circle cast, so a body that follows the result
//! never touches a wall.

use glam::Vec2;

use crate::query::{Faces, RayFilter};
use crate::tiles::{SegmentFlags, TileMap};

/// True when a circle of `radius` moves from `a` to `b` without touching any segment with
/// one of `mask`'s flags, from either side.
pub(crate) fn is_clear(map: &TileMap, a: Vec2, b: Vec2, radius: f32, mask: SegmentFlags) -> bool {
    let filter = RayFilter {
        faces: Faces::Both,
        ..RayFilter::default()
    }
    .with_mask(mask);
    a == b || map.cast_circle(a, radius, b - a, &filter).is_none()
}

/// The corners of `points` (a path whose every straight piece is clear): drops points in
/// the middle of straight runs, then pulls the path taut.
pub(crate) fn smooth(map: &TileMap, points: &[Vec2], radius: f32, mask: SegmentFlags) -> Vec<Vec2> {
    let corners = turning_points(points);
    let Some((&first, _)) = corners.split_first() else {
        return Vec::new();
    };
    let mut out = vec![first];
    let mut anchor = 0;
    while anchor + 1 < corners.len() {
        // The farthest corner reachable straight from the anchor; the next one is always
        // reachable (it was a clear piece of the path).
        let mut next = anchor + 1;
        for k in anchor + 2..corners.len() {
            if is_clear(map, corners[anchor], corners[k], radius, mask) {
                next = k;
            } else {
                break;
            }
        }
        out.push(corners[next]);
        anchor = next;
    }
    out
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
