//! A ray cast's debug lines.

use crate::debug::{DebugKind, DebugLines};
use crate::geometry::{Ray, Segment};
use crate::owner::Owner;
use crate::query::RayHit;

impl DebugLines {
    /// Adds a ray cast and its answer: the [`Ray`](DebugKind::Ray) from its origin to the
    /// hit (or to its end when it hit nothing), and for a hit the
    /// [`RayHit`](DebugKind::RayHit) point with the hit's normal, `tick` long, as a
    /// [`Normal`](DebugKind::Normal).
    ///
    /// ```
    /// # use tileslide::{io::ascii, DebugKind, DebugLines, Owner, QueryFilter, Ray, Vec2};
    /// let map = ascii::parse("..#", "wall.txt", 1.0)?;
    /// let ray = Ray::between(Vec2::new(0.5, 0.5), Vec2::new(2.5, 0.5));
    /// let hit = map.cast_ray(ray, &QueryFilter::default());
    /// let mut lines = DebugLines::new();
    /// lines.push_ray(ray, hit.as_ref(), 0.25, Owner(0));
    /// assert_eq!(lines.segments()[0].segment.b, Vec2::new(2.0, 0.5));
    /// assert_eq!(lines.points()[0].kind, DebugKind::RayHit);
    /// # Ok::<(), tileslide::io::LoadError>(())
    /// ```
    pub fn push_ray(&mut self, ray: Ray, hit: Option<&RayHit>, tick: f32, owner: Owner) {
        let end = hit.map_or(ray.origin + ray.delta, |h| h.point);
        self.push_segment(DebugKind::Ray, Segment::new(ray.origin, end), owner);
        if let Some(h) = hit {
            self.push_point(DebugKind::RayHit, h.point, owner);
            let normal = Segment::new(h.point, h.point + h.normal * tick);
            self.push_segment(DebugKind::Normal, normal, owner);
        }
    }
}
