//! A character's velocity after a move: what the surfaces it touched leave of it
//! (`move_and_slide`), so that a game keeps a velocity without writing the clipping itself.
//!
//! Gravity, jumps, coyote time and the like are the game's rules; what every game repeats,
//! and easily gets wrong, is taking out of its velocity what the move could not make:
//! landing zeroes the fall, a ceiling the rise, a wall the speed into it. The rules here
//! are the move's own (`character.rs`), applied to a velocity instead of a displacement.

use glam::Vec2;

use super::character::finite;
use super::{Character, Contacts, ControllerError, MoveOptions};
use crate::tiles::TileMap;

/// Passes over the contacts before giving up on a velocity that two of them keep sending
/// into each other (a wedge), which is then stopped.
const CLIP_PASSES: usize = 3;

impl Character {
    /// What is left of `velocity` after a move that touched `contacts`: the velocity to
    /// keep for the next step. Pure; [`move_and_slide`](Self::move_and_slide) is the move
    /// and this together.
    ///
    /// The move's own rules, applied to the velocity:
    ///
    /// - **Ground** (walkable, under the character after the move): the fall is dropped
    ///   (landing zeroes the downward speed); the sideways speed is kept, since the next
    ///   move walks it along the ground, up or down a ramp at the same sideways speed.
    /// - **Ceiling**: the speed into it is dropped; the rest slides along it.
    /// - **Wall** (left or right, a steep slope included): the speed into it is dropped
    ///   and the rest slides along it, but sliding never lifts the character more than
    ///   the velocity did: where it would (running into a steep slope), only the rise or
    ///   fall slides on, as in the move, so pushing never climbs a steep slope.
    /// - A **crush** is left to the game.
    ///
    /// So the velocity returned never points into a ceiling or a wall it touched (its dot
    /// product with their normals is not negative, but for rounding), nor down into its
    /// ground. Velocities squeezed between two surfaces that leave no way on (a wedge)
    /// become zero.
    ///
    /// A moving platform under the character carries it by the platform's own move (see
    /// [`move_by`](Self::move_by)), so its velocity is not added here; a game that wants a
    /// character to keep the platform's speed when it jumps off adds
    /// [`Contact::platform_velocity`](crate::Contact::platform_velocity) to the jump.
    ///
    /// A velocity of any finite size is clipped by the same rules (a result past `f32`'s
    /// range, from a velocity near it, saturates at `±f32::MAX`).
    ///
    /// # Errors
    /// [`ControllerError::NonFinite`] naming the `"velocity"` when it is not finite.
    pub fn clip_velocity(
        &self,
        velocity: Vec2,
        contacts: &Contacts,
    ) -> Result<Vec2, ControllerError> {
        finite("velocity", velocity)?;
        Ok(self.clipped(velocity, contacts))
    }

    /// [`clip_velocity`](Self::clip_velocity) of a finite velocity.
    fn clipped(&self, velocity: Vec2, contacts: &Contacts) -> Vec2 {
        // Clipping is linear in the velocity, and so is its tolerance: a velocity so large
        // that its length or a product with a normal could overflow is clipped at 2⁻⁸⁰ of
        // its size (exact: a power of two; what it rounds away is far below the tolerance)
        // and scaled back.
        const HUGE: f32 = 1.1529215e18; // 2⁶⁰
        if velocity.abs().max_element() > HUGE {
            let scale = 2f32.powi(-80);
            let v = self.clip(velocity * scale, contacts) / scale;
            return v.clamp(Vec2::splat(-f32::MAX), Vec2::splat(f32::MAX));
        }
        self.clip(velocity, contacts)
    }

    /// [`clip_velocity`](Self::clip_velocity) of a finite velocity whose length does not
    /// overflow.
    fn clip(&self, velocity: Vec2, contacts: &Contacts) -> Vec2 {
        let up = self.up();
        // Speeds into a surface smaller than this are rounding, left alone: a velocity slid
        // along a surface stays slid along it.
        let tolerance = 1e-6 * velocity.length();
        let mut v = velocity;
        for _ in 0..CLIP_PASSES {
            let mut clipped = false;
            let fall = v.dot(up);
            if contacts.ground.is_some() && fall < 0.0 {
                v -= up * fall;
                clipped |= fall < -tolerance;
            }
            for contact in [contacts.ceiling, contacts.left, contacts.right]
                .iter()
                .flatten()
            {
                if v.dot(contact.normal) < -tolerance {
                    v = slide_off(v, contact.normal, up);
                    clipped = true;
                }
            }
            if !clipped {
                return v;
            }
        }
        // Still clipped on the last pass: two surfaces send it into each other (a wedge).
        Vec2::ZERO
    }

    /// Moves the character by `velocity × dt` ([`move_by`](Self::move_by)) and then
    /// keeps in `velocity` what the surfaces it touched leave of it
    /// ([`clip_velocity`](Self::clip_velocity)), as Godot's `move_and_slide` does. The
    /// game adds gravity and jumps to `velocity` before the call.
    ///
    /// ```
    /// use tileslide::{Character, CharacterShape, ControllerConfig, MoveOptions, Vec2, io::ascii};
    /// let map = ascii::parse("\
    /// ########
    /// #......#
    /// #......#
    /// ########", "doc.txt", 1.0)?;
    /// // ASCII maps are y-down: up is -y, gravity +y.
    /// let shape = CharacterShape::rect(Vec2::new(0.25, 0.4))?;
    /// let mut hero = Character::new(shape, Vec2::new(2.0, 1.5), Vec2::NEG_Y, ControllerConfig::default())?;
    /// let mut velocity = Vec2::new(6.0, 0.0);
    /// let dt = 1.0 / 60.0;
    /// for _ in 0..60 {
    ///     velocity.y += 30.0 * dt; // gravity: the game's rule
    ///     hero.move_and_slide(&map, &mut velocity, dt, MoveOptions::default())?;
    /// }
    /// // Landed (the fall is gone) and ran into the right wall (the speed into it is gone).
    /// assert!(hero.ground().is_some());
    /// assert_eq!(velocity, Vec2::ZERO);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// [`ControllerError::NonFinite`] naming the `"velocity"` when it is not finite,
    /// [`ControllerError::BadTimeStep`] when `dt` is negative or not finite, and what
    /// [`move_by`](Self::move_by) refuses, a displacement being named `"velocity × dt"`
    /// (a product that overflows, a move that would end out of range); the character and
    /// `velocity` are then unchanged.
    pub fn move_and_slide(
        &mut self,
        map: &TileMap,
        velocity: &mut Vec2,
        dt: f32,
        options: MoveOptions,
    ) -> Result<Contacts, ControllerError> {
        finite("velocity", *velocity)?;
        if !(dt.is_finite() && dt >= 0.0) {
            return Err(ControllerError::BadTimeStep { dt });
        }
        // A finite velocity and dt whose product overflows, or ends the move out of range,
        // is named as what the caller gave.
        let contacts = self
            .move_by(map, *velocity * dt, options)
            .map_err(|e| match e {
                ControllerError::NonFinite {
                    what: "displacement",
                    value,
                } => ControllerError::NonFinite {
                    what: "velocity × dt",
                    value,
                },
                ControllerError::OutOfRange {
                    what: "displacement",
                    value,
                } => ControllerError::OutOfRange {
                    what: "velocity × dt",
                    value,
                },
                e => e,
            })?;
        *velocity = self.clipped(*velocity, &contacts);
        Ok(contacts)
    }
}

/// `v`, which points into a ceiling or wall of unit normal `n`, slid along it; or, where
/// the slide would lift the character more than `v` does (a steep slope run into), only
/// `v`'s rise or fall slid along it (the move's rule in the air; a walk, whose velocity
/// neither rises nor falls, stops).
fn slide_off(v: Vec2, n: Vec2, up: Vec2) -> Vec2 {
    let slid = v - n * v.dot(n);
    if slid.dot(up) <= v.dot(up) {
        return slid;
    }
    let vertical = up * v.dot(up);
    vertical - n * vertical.dot(n).min(0.0)
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;
    use crate::io::ascii;
    use crate::query::SegmentSource;
    use crate::tiles::{Owner, SegmentFlags};
    use crate::{CharacterShape, Contact, ControllerConfig};

    fn contact(normal: Vec2) -> Contact {
        Contact {
            normal: normal.normalize(),
            flags: SegmentFlags::SOLID,
            source: SegmentSource::Temporary {
                owner: Owner(1),
                index: 0,
                velocity: Vec2::ZERO,
            },
        }
    }

    fn hero() -> Character {
        let shape = CharacterShape::circle(0.3).unwrap();
        Character::new(
            shape,
            Vec2::new(2.0, 2.0),
            Vec2::NEG_Y,
            ControllerConfig::default(),
        )
        .unwrap()
    }

    #[test]
    fn ground_drops_the_fall_and_keeps_the_sideways_speed() {
        let contacts = Contacts {
            ground: Some(contact(Vec2::new(-1.0, -1.0))),
            ..Contacts::default()
        };
        let v = hero()
            .clip_velocity(Vec2::new(3.0, 5.0), &contacts)
            .unwrap();
        assert_eq!(v, Vec2::new(3.0, 0.0));
    }

    #[test]
    fn a_velocity_into_a_wedge_points_into_neither_surface() {
        // A slanted ceiling and a wall meeting above the character, pushed into both.
        let contacts = Contacts {
            ceiling: Some(contact(Vec2::new(-0.3, 1.0))),
            right: Some(contact(Vec2::new(-1.0, 0.2))),
            ..Contacts::default()
        };
        let v = hero()
            .clip_velocity(Vec2::new(4.0, -4.0), &contacts)
            .unwrap();
        for c in [contacts.ceiling, contacts.right].iter().flatten() {
            assert!(v.dot(c.normal) >= -1e-5, "{v} into {}", c.normal);
        }
    }

    #[test]
    fn running_into_a_steep_slope_does_not_climb_it() {
        let contacts = Contacts {
            right: Some(contact(Vec2::new(-1.0, -0.4))),
            ..Contacts::default()
        };
        let v = hero()
            .clip_velocity(Vec2::new(5.0, 0.0), &contacts)
            .unwrap();
        assert!(v.y >= 0.0, "{v} rises");
        assert!(v.dot(contacts.right.unwrap().normal) >= -1e-6);
    }

    #[test]
    fn a_velocity_of_any_finite_size_is_clipped_as_a_small_one() {
        let contacts = Contacts {
            ceiling: Some(contact(Vec2::new(-0.3, 1.0))),
            right: Some(contact(Vec2::new(-1.0, 0.2))),
            ground: Some(contact(Vec2::new(0.6, -0.8))),
            ..Contacts::default()
        };
        let h = hero();
        for small in [
            Vec2::new(4.0, -4.0),
            Vec2::new(5.0, 0.5),
            Vec2::new(-3.0, 2.0),
            Vec2::new(0.25, -1.0),
        ] {
            let want = h.clip_velocity(small, &contacts).unwrap();
            // Powers of two scale exactly, so the answer scales exactly too, up to the
            // largest finite velocities (whose squared length overflows).
            for k in [40, 62, 100, 125] {
                let scale = 2f32.powi(k);
                let got = h.clip_velocity(small * scale, &contacts).unwrap();
                assert!(got.is_finite(), "{small} × 2^{k}: {got}");
                assert_eq!(got / scale, want, "{small} × 2^{k}");
            }
        }
        // Near f32::MAX the answer saturates rather than overflowing.
        let v = h
            .clip_velocity(Vec2::new(f32::MAX, -f32::MAX), &contacts)
            .unwrap();
        assert!(v.is_finite(), "{v}");
        for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
            let e = h.clip_velocity(Vec2::new(1.0, bad), &contacts);
            assert!(
                matches!(
                    e,
                    Err(ControllerError::NonFinite {
                        what: "velocity",
                        ..
                    })
                ),
                "{e:?}"
            );
        }
    }

    #[test]
    fn move_and_slide_refuses_a_bad_time_step_and_a_non_finite_velocity() {
        let map = ascii::parse("#####\n#...#\n#...#\n#####", "m.txt", 1.0).unwrap();
        let mut h = hero();
        let mut v = Vec2::new(1.0, 0.0);
        let e = h.move_and_slide(&map, &mut v, -0.1, MoveOptions::default());
        assert_eq!(e, Err(ControllerError::BadTimeStep { dt: -0.1 }));
        let mut nan = Vec2::new(f32::NAN, 0.0);
        let e = h.move_and_slide(&map, &mut nan, 0.1, MoveOptions::default());
        assert!(matches!(
            e,
            Err(ControllerError::NonFinite {
                what: "velocity",
                ..
            })
        ));
        assert_eq!(v, Vec2::new(1.0, 0.0));
        assert_eq!(h.position, Vec2::new(2.0, 2.0));
    }
}
