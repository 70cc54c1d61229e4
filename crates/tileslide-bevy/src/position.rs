//! Where the plugin last put an entity: the `Transform` written back after each step,
//! teleports noticed, and the optional interpolation between fixed steps.

use bevy::prelude::*;

/// Where the plugin put a body or a character, in world units: at the end of the last step,
/// at the end of the step before, and the translation it last wrote into the `Transform`.
///
/// The core keeps the true position; the `Transform` shows it. A `Transform` whose x and y
/// are no longer what the plugin [`shown`](Self::shown) was moved by the game: the next
/// step teleports the entity there (no sweep), which is how a game places a body.
#[derive(Component, Clone, Copy, Debug, Default, PartialEq)]
pub struct StepPosition {
    /// Where the last step left the entity.
    pub current: Vec2,
    /// Where the step before left it (the start of the interpolation).
    pub previous: Vec2,
    /// The translation the plugin last wrote (x and y).
    pub shown: Vec2,
    /// Whether the plugin has placed the entity yet.
    pub placed: bool,
}

impl StepPosition {
    /// Where the game put the entity if it moved it since the plugin last wrote its
    /// `Transform` (or if the plugin never did); `None` otherwise.
    #[must_use]
    pub fn moved_by_game(&self, transform: &Transform) -> Option<Vec2> {
        let at = transform.translation.truncate();
        (!self.placed || at != self.shown).then_some(at)
    }

    /// Records a teleport to `at`: nothing to interpolate from.
    pub fn teleported(&mut self, at: Vec2) {
        *self = Self {
            current: at,
            previous: at,
            shown: at,
            placed: true,
        };
    }

    /// Records where a step left the entity and writes it into `transform` (its z kept). The
    /// `Transform` is marked changed only if it moved.
    pub fn step_to(&mut self, at: Vec2, transform: &mut Mut<'_, Transform>) {
        self.previous = self.current;
        self.current = at;
        self.show(at, transform);
    }

    /// Writes `at` into `transform`'s x and y, marking it changed only if it differs.
    pub fn show(&mut self, at: Vec2, transform: &mut Mut<'_, Transform>) {
        self.shown = at;
        self.placed = true;
        if transform.translation.truncate() != at {
            transform.translation.x = at.x;
            transform.translation.y = at.y;
        }
    }
}

/// Shows a body or a character between its last two fixed steps, so motion is smooth at
/// any frame rate: its `Transform` is set, after `Update`, to the point between
/// [`StepPosition::previous`] and [`StepPosition::current`] that the time left over after
/// the last fixed step says. The step itself always starts from the true position.
#[derive(Component, Clone, Copy, Debug, Default)]
pub struct Interpolated;

/// Moves each [`Interpolated`] entity's `Transform` between its last two steps.
pub(crate) fn interpolate(
    time: Res<Time<Fixed>>,
    mut moving: Query<(&mut StepPosition, &mut Transform), With<Interpolated>>,
) {
    let f = time.overstep_fraction().clamp(0.0, 1.0);
    for (mut position, mut transform) in &mut moving {
        if !position.placed {
            continue;
        }
        let at = position.previous.lerp(position.current, f);
        position.show(at, &mut transform);
    }
}
