//! A path found on a navigation grid: the smoothed straight runs and what it needs to know
//! whether an edit affects it.

use glam::Vec2;

use super::NavChange;
#[cfg(doc)]
use super::NavGrid;
use crate::geometry::Aabb;

/// A path found by [`NavGrid::find_path`]: straight runs from the start point to the goal
/// point, each clear for the radius it was found for.
#[derive(Clone, Debug, PartialEq)]
pub struct NavPath {
    points: Vec<Vec2>,
    length: f32,
    radius: f32,
    /// Clearance steps the radius needs (for [`NavPath::is_affected_by`]).
    need: u16,
    bounds: Aabb,
}

impl NavPath {
    pub(super) fn new(points: Vec<Vec2>, radius: f32, need: u16) -> Self {
        let length = points.windows(2).map(|w| w[0].distance(w[1])).sum();
        let mut bounds = Aabb::from_corners(points[0], points[0]);
        for &p in &points {
            bounds = bounds.union(&Aabb::from_corners(p, p));
        }
        Self {
            points,
            length,
            radius,
            need,
            bounds: bounds.expand(radius),
        }
    }

    /// The corners, from the start point to the goal point.
    #[must_use]
    pub fn points(&self) -> &[Vec2] {
        &self.points
    }

    /// Total length (map units).
    #[must_use]
    pub fn length(&self) -> f32 {
        self.length
    }

    /// The radius the path was found for.
    #[must_use]
    pub fn radius(&self) -> f32 {
        self.radius
    }

    /// True when `change` may have blocked this path or opened a shorter way near it: an
    /// edit changed moves within reach of the path, and opened or closed some move for its
    /// radius, or an edited cell lies within the radius of one of its runs. Far-away edits
    /// and edits that only change clearances no circle of this radius notices do not
    /// affect it; a grid rebuilt from scratch ([`NavChange::is_rebuild`]) affects every
    /// path.
    #[must_use]
    pub fn is_affected_by(&self, change: &NavChange) -> bool {
        change.affects(&self.bounds, self.need) || change.touches_runs(&self.points, self.radius)
    }
}
