//! The bodies' debug lines: their circles, and the boxes the broadphase filed them under.

use super::Bodies;
use crate::debug::{DebugKind, DebugLines};
use crate::geometry::Circle;

impl Bodies {
    /// Adds every body to `out`, in slot order: each circle of its shape where it is now,
    /// as a [`Body`](DebugKind::Body) circle with the body's owner, and (once a resolve
    /// has run and no body was added, removed or changed since) the box the broadphase
    /// filed that circle under, as a [`BroadphaseBox`](DebugKind::BroadphaseBox).
    ///
    /// ```
    /// use tileslide::{Bodies, BodyDesc, BodyShape, DebugKind, DebugLines, Owner, Vec2};
    ///
    /// let mut bodies = Bodies::new();
    /// let desc = BodyDesc::new(Vec2::new(2.0, 3.0), BodyShape::circle(0.5)?);
    /// bodies.add(desc.with_owner(Owner(7)))?;
    /// let mut lines = DebugLines::new();
    /// bodies.debug_lines(&mut lines);
    /// let c = lines.circles()[0];
    /// assert_eq!((c.kind, c.owner), (DebugKind::Body, Owner(7)));
    /// assert_eq!((c.circle.center, c.circle.radius), (Vec2::new(2.0, 3.0), 0.5));
    /// # Ok::<(), tileslide::BodyError>(())
    /// ```
    pub fn debug_lines(&self, out: &mut DebugLines) {
        let circles: usize = self.iter().map(|(_, b)| b.shape().circles().len()).sum();
        let broadphase = out
            .wants(DebugKind::BroadphaseBox)
            .then(|| self.resolver.broadphase_boxes())
            .flatten()
            .filter(|boxes| boxes.len() == circles);
        let mut k = 0;
        for (_, body) in self.iter() {
            let owner = body.owner();
            for c in body.shape().circles() {
                let placed = Circle::new(body.position() + c.center, c.radius);
                out.push_circle(DebugKind::Body, placed, owner);
                if let Some(b) = broadphase.and_then(|boxes| boxes.get(k)) {
                    out.push_box(DebugKind::BroadphaseBox, *b, owner);
                }
                k += 1;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use glam::Vec2;

    use super::*;
    use crate::io::ascii;
    use crate::{BodyDesc, BodyShape, Owner};

    #[test]
    fn a_compound_gives_one_circle_per_part_at_the_body() {
        let mut bodies = Bodies::new();
        let shape = BodyShape::compound([
            Circle::new(Vec2::new(-0.5, 0.0), 0.25),
            Circle::new(Vec2::new(0.5, 0.0), 0.3),
        ])
        .unwrap();
        bodies
            .add(BodyDesc::new(Vec2::new(4.0, 2.0), shape).with_owner(Owner(3)))
            .unwrap();
        let mut lines = DebugLines::new();
        bodies.debug_lines(&mut lines);
        let centers: Vec<(Vec2, f32)> = lines
            .circles()
            .iter()
            .map(|c| (c.circle.center, c.circle.radius))
            .collect();
        assert_eq!(
            centers,
            [(Vec2::new(3.5, 2.0), 0.25), (Vec2::new(4.5, 2.0), 0.3)]
        );
        // No resolve yet: no broadphase boxes.
        assert!(lines.boxes().is_empty());
    }

    #[test]
    fn after_a_resolve_each_circle_has_a_broadphase_box_holding_it() {
        let map = ascii::parse("......\n......\n......", "open.txt", 1.0).unwrap();
        let mut bodies = Bodies::new();
        for x in [1.0, 2.5, 4.0] {
            let desc = BodyDesc::new(Vec2::new(x, 1.5), BodyShape::circle(0.4).unwrap());
            let h = bodies.add(desc).unwrap();
            bodies.propose(h, Vec2::new(0.1, 0.0)).unwrap();
        }
        bodies.resolve(&map);
        let mut lines = DebugLines::new();
        bodies.debug_lines(&mut lines);
        assert_eq!(lines.circles().len(), 3);
        assert_eq!(lines.boxes().len(), 3);
        for (c, b) in lines.circles().iter().zip(lines.boxes()) {
            assert_eq!(b.kind, DebugKind::BroadphaseBox);
            assert!(b.aabb.contains(&c.circle.aabb()), "{b:?} {c:?}");
        }
        // A body added since: the boxes describe other circles, so none is given.
        let desc = BodyDesc::new(Vec2::new(5.0, 1.5), BodyShape::circle(0.4).unwrap());
        bodies.add(desc).unwrap();
        lines.clear();
        bodies.debug_lines(&mut lines);
        assert_eq!((lines.circles().len(), lines.boxes().len()), (4, 0));
    }
}
