//! A character's debug lines: its shape and the surfaces it touched.

use glam::Vec2;

use super::{Character, CharacterShape, Contacts};
use crate::debug::{DebugKind, DebugLines};
use crate::geometry::{Aabb, Circle, Segment};
use crate::owner::Owner;

impl Character {
    /// Adds the character to `out` with `owner`: its shape where it is now, as a
    /// [`Character`](DebugKind::Character) circle or box, and each surface of `contacts`
    /// (what its last move returned) as a [`Contact`](DebugKind::Contact) line from the
    /// shape's edge along the surface's normal, half the shape's smaller extent long.
    ///
    /// ```
    /// use tileslide::{
    ///     io::ascii, Character, CharacterShape, ControllerConfig, DebugKind, DebugLines,
    ///     MoveOptions, Owner, Vec2,
    /// };
    ///
    /// let map = ascii::parse("\
    /// ......
    /// ......
    /// ######", "floor.txt", 1.0)?;
    /// let shape = CharacterShape::rect(Vec2::new(0.25, 0.5))?;
    /// let mut hero = Character::new(shape, Vec2::new(2.5, 1.4), Vec2::NEG_Y, ControllerConfig::default())?;
    /// let contacts = hero.move_by(&map, Vec2::new(0.0, 0.5), MoveOptions::default())?;
    /// let mut lines = DebugLines::new();
    /// hero.debug_lines(Some(&contacts), Owner(1), &mut lines);
    /// assert_eq!(lines.boxes()[0].kind, DebugKind::Character);
    /// // Standing on the floor (y = 2): the ground contact starts at the feet, pointing up.
    /// let ground = lines.segments()[0].segment;
    /// assert!((ground.a.y - 2.0).abs() < 0.01 && ground.b.y < ground.a.y);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn debug_lines(&self, contacts: Option<&Contacts>, owner: Owner, out: &mut DebugLines) {
        let center = self.position;
        let extent = match self.shape() {
            CharacterShape::Circle { radius } => {
                out.push_circle(DebugKind::Character, Circle::new(center, radius), owner);
                radius
            }
            CharacterShape::Rect { half } => {
                out.push_box(DebugKind::Character, Aabb::from_center(center, half), owner);
                half.min_element()
            }
        };
        let Some(contacts) = contacts else {
            return;
        };
        if !out.wants(DebugKind::Contact) {
            return;
        }
        let touched = [
            contacts.ground,
            contacts.ceiling,
            contacts.left,
            contacts.right,
            contacts.crush,
        ];
        for contact in touched.into_iter().flatten() {
            let n = contact.normal;
            let edge = center - n * self.reach_along(-n);
            let line = Segment::new(edge, edge + n * extent * 0.5);
            out.push_segment(DebugKind::Contact, line, owner);
        }
    }

    /// How far the shape reaches from its centre in the unit direction `d`.
    fn reach_along(&self, d: Vec2) -> f32 {
        match self.shape() {
            CharacterShape::Circle { radius } => radius,
            // Where the ray from the centre along `d` leaves the box.
            CharacterShape::Rect { half } => {
                let t = |h: f32, c: f32| if c == 0.0 { f32::INFINITY } else { h / c.abs() };
                t(half.x, d.x).min(t(half.y, d.y))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;
    use crate::controller::{Contact, ControllerConfig};
    use crate::query::SegmentSource;
    use crate::tiles::SegmentFlags;

    fn contact(normal: Vec2) -> Contact {
        Contact {
            normal,
            flags: SegmentFlags::SOLID,
            source: SegmentSource::Temporary {
                owner: Owner(0),
                index: 0,
                velocity: Vec2::ZERO,
            },
        }
    }

    #[test]
    fn a_circle_character_is_a_circle_and_its_contacts_start_on_its_edge() {
        let shape = CharacterShape::circle(0.5).unwrap();
        let hero = Character::new(
            shape,
            Vec2::new(3.0, 3.0),
            Vec2::NEG_Y,
            ControllerConfig::default(),
        )
        .unwrap();
        let contacts = Contacts {
            left: Some(contact(Vec2::X)),
            ceiling: Some(contact(Vec2::Y)),
            ..Contacts::default()
        };
        let mut lines = DebugLines::new();
        hero.debug_lines(Some(&contacts), Owner(2), &mut lines);
        let c = lines.circles()[0];
        assert_eq!(
            (c.kind, c.circle.center, c.circle.radius),
            (DebugKind::Character, Vec2::new(3.0, 3.0), 0.5)
        );
        let starts: Vec<Vec2> = lines.segments().iter().map(|s| s.segment.a).collect();
        // The ceiling above (normal down, +y) touches at the top; the left wall at the left.
        assert_eq!(starts, [Vec2::new(3.0, 2.5), Vec2::new(2.5, 3.0)]);
        assert!(
            lines
                .segments()
                .iter()
                .all(|s| s.kind == DebugKind::Contact)
        );
        lines.clear();
        hero.debug_lines(None, Owner(2), &mut lines);
        assert_eq!(lines.len(), 1);
    }
}
