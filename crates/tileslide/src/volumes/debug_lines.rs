//! The hit world's debug lines: this frame's volumes, the boxes the broadphase sorted, and
//! the last `detect`'s hits.

#[cfg(feature = "aim")]
use glam::Vec2;

use super::HitWorld;
use super::placed::Placed;
use crate::debug::{DebugKind, DebugLines};
use crate::geometry::Circle;
#[cfg(feature = "aim")]
use crate::geometry::Segment;
use crate::owner::Owner;

impl HitWorld {
    /// Adds this frame's objects to `out`, in the order they were registered: each
    /// attack volume placed in the world (mirrored as the object faces, turned as it aims)
    /// as an [`AttackVolume`](DebugKind::AttackVolume) circle or box (a turned rectangle as
    /// its four sides, a capsule as its two end circles and two sides), each vulnerability
    /// volume as a [`VulnerabilityVolume`](DebugKind::VulnerabilityVolume), and the box of
    /// everything its volumes sweep during the frame (what the broadphase sorts) as a
    /// [`BroadphaseBox`](DebugKind::BroadphaseBox), each with the object's owner; then the
    /// last [`detect`](Self::detect)'s events where they happened (each event's `point`),
    /// as [`Hit`](DebugKind::Hit) or [`RefusedHit`](DebugKind::RefusedHit) points with the
    /// victim's owner.
    ///
    /// ```
    /// use tileslide::{
    ///     DebugKind, DebugLines, HitObject, HitTypes, HitWorld, Owner, TeamRule, Vec2, Volume,
    /// };
    ///
    /// let mut world = HitWorld::new();
    /// world.begin_frame();
    /// let sword = Volume::circle(Vec2::new(1.5, 0.5), 0.5, HitTypes::HIT)?;
    /// let body = Volume::rect(Vec2::splat(0.5), Vec2::splat(0.5), HitTypes::ANY)?;
    /// let mut hero = HitObject::new(Owner(1), Vec2::ZERO, Vec2::ONE);
    /// hero.team = 1;
    /// let slime = HitObject::new(Owner(2), Vec2::new(1.5, 0.0), Vec2::ONE);
    /// world.register(hero, &[sword], &[body])?;
    /// world.register(slime, &[], &[body])?;
    /// world.detect(&mut TeamRule);
    /// let mut lines = DebugLines::new();
    /// world.debug_lines(&mut lines);
    /// assert_eq!(lines.count(DebugKind::AttackVolume), 1);
    /// assert_eq!(lines.count(DebugKind::VulnerabilityVolume), 2);
    /// let hit = lines.points()[0];
    /// // Where the sword's circle meets the slime's body: the body's point nearest the
    /// // circle's centre, which lies inside it.
    /// assert_eq!((hit.kind, hit.owner, hit.point), (DebugKind::Hit, Owner(2), Vec2::new(1.5, 0.5)));
    /// # Ok::<(), tileslide::VolumeError>(())
    /// ```
    pub fn debug_lines(&self, out: &mut DebugLines) {
        for e in &self.entries {
            let owner = e.object.owner;
            let (a0, a1) = e.attack;
            let (v0, v1) = e.vulnerable;
            let sides = [
                (
                    DebugKind::AttackVolume,
                    &self.attack[a0 as usize..a1 as usize],
                ),
                (
                    DebugKind::VulnerabilityVolume,
                    &self.vulnerable[v0 as usize..v1 as usize],
                ),
            ];
            for (kind, volumes) in sides {
                if !out.wants(kind) {
                    continue;
                }
                for v in volumes {
                    let placed = if kind == DebugKind::AttackVolume {
                        e.attack_volume(v, e.object.position)
                    } else {
                        e.vulnerable_volume(v, e.object.position)
                    };
                    push_placed(out, kind, placed, owner);
                }
            }
            // An object without volumes has a NaN box, skipped rather than drawn.
            if out.wants(DebugKind::BroadphaseBox) && e.reach.is_valid() {
                out.push_box(DebugKind::BroadphaseBox, e.reach, owner);
            }
        }
        for event in &self.events {
            let kind = if event.accepted {
                DebugKind::Hit
            } else {
                DebugKind::RefusedHit
            };
            out.push_point(kind, event.point, event.victim_owner);
        }
    }
}

/// Adds a placed volume as a circle, a box, or the sides and circles of its outline.
fn push_placed(out: &mut DebugLines, kind: DebugKind, placed: Placed, owner: Owner) {
    match placed {
        Placed::Circle { center, radius } => {
            out.push_circle(kind, Circle::new(center, radius), owner);
        }
        Placed::Rect(b) => out.push_box(kind, b, owner),
        #[cfg(feature = "aim")]
        Placed::Turned { center, axis, half } => {
            let corner = |x: f32, y: f32| center + axis.rotate(Vec2::new(x, y) * half);
            let corners = [
                corner(-1.0, -1.0),
                corner(1.0, -1.0),
                corner(1.0, 1.0),
                corner(-1.0, 1.0),
            ];
            for i in 0..4 {
                out.push_segment(kind, Segment::new(corners[i], corners[(i + 1) % 4]), owner);
            }
        }
        #[cfg(feature = "aim")]
        Placed::Capsule { a, b, radius } => {
            let side = (b - a).perp().normalize_or_zero() * radius;
            for offset in [side, -side] {
                out.push_segment(kind, Segment::new(a + offset, b + offset), owner);
            }
            out.push_circle(kind, Circle::new(a, radius), owner);
            out.push_circle(kind, Circle::new(b, radius), owner);
        }
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;
    use crate::volumes::{Facing, HitObject, HitTypes, TeamRule, Volume};

    #[test]
    fn a_mirrored_object_draws_its_volumes_mirrored() {
        let mut world = HitWorld::new();
        world.begin_frame();
        let reach = Volume::rect(Vec2::new(1.5, 0.5), Vec2::splat(0.5), HitTypes::HIT).unwrap();
        let mut hero = HitObject::new(Owner(5), Vec2::new(10.0, 0.0), Vec2::ONE);
        hero.facing = Facing {
            flip_x: true,
            flip_y: false,
        };
        world.register(hero, &[reach], &[]).unwrap();
        let mut lines = DebugLines::new();
        world.debug_lines(&mut lines);
        let attack = lines.boxes()[0];
        assert_eq!(attack.kind, DebugKind::AttackVolume);
        // Facing left, the reach lies left of the object: x in [9, 10].
        assert_eq!((attack.aabb.min.x, attack.aabb.max.x), (9.0, 10.0));
        assert_eq!(attack.owner, Owner(5));
        let broad = lines.boxes()[1];
        assert_eq!(broad.kind, DebugKind::BroadphaseBox);
        assert!(broad.aabb.contains(&attack.aabb));
    }

    #[test]
    fn a_refused_hit_is_a_refused_hit_point() {
        struct Refuse;
        impl crate::volumes::HitRule for Refuse {
            fn accept(&mut self, _: &HitObject, _: &HitObject, _: HitTypes) -> bool {
                false
            }
        }
        let mut world = HitWorld::new();
        world.begin_frame();
        let hit = Volume::circle(Vec2::splat(0.5), 1.0, HitTypes::HIT).unwrap();
        let body = Volume::circle(Vec2::splat(0.5), 0.5, HitTypes::ANY).unwrap();
        let mut attacker = HitObject::new(Owner(1), Vec2::ZERO, Vec2::ONE);
        attacker.team = 1;
        world.register(attacker, &[hit], &[]).unwrap();
        world
            .register(HitObject::new(Owner(2), Vec2::X, Vec2::ONE), &[], &[body])
            .unwrap();
        world.detect(&mut Refuse);
        let mut lines = DebugLines::new();
        world.debug_lines(&mut lines);
        assert_eq!(lines.count(DebugKind::RefusedHit), 1);
        assert_eq!(lines.count(DebugKind::Hit), 0);
        world.detect(&mut TeamRule);
        lines.clear();
        world.debug_lines(&mut lines);
        assert_eq!(lines.count(DebugKind::Hit), 1);
    }
}
