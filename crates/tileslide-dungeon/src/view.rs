//! What a renderer or a HUD reads of a game, as plain values: the fighters and the
//! fireballs (the components themselves stay inside the crate).

use tileslide::{BodyHandle, BodyTrace, ResolveTrace, Vec2};

use crate::components::{Body, Carrying, Fireball, Health, Id, Kind, Team};
use crate::game::Game;

/// A fighter as it is now.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fighter {
    /// Its number, in spawn order (stable for the game).
    pub id: u64,
    /// What it is.
    pub kind: Kind,
    /// Its side.
    pub team: Team,
    /// Its centre.
    pub position: Vec2,
    /// Its circle's radius.
    pub radius: f32,
    /// Hit points left.
    pub hp: i32,
    /// Hit points it started with.
    pub max_hp: i32,
    /// Whether it carries a piece of the treasure.
    pub carrying: bool,
}

impl Game {
    /// Starts (`true`) or stops tracing the bodies' steps, for
    /// [`body_trace`](Self::body_trace) (off by default: an untraced step records nothing;
    /// tracing changes no move).
    pub fn trace_bodies(&mut self, on: bool) {
        if on != self.trace.is_some() {
            self.trace = on.then(ResolveTrace::new);
        }
    }

    /// What the resolver did with fighter `id`'s body in the last step: `None` when steps
    /// are not traced, no fighter `id` is alive, or it came after the step.
    #[must_use]
    pub fn body_trace(&self, id: u64) -> Option<&BodyTrace> {
        let trace = self.trace.as_ref()?;
        let mut query = self.world.query::<(&Id, &Body)>();
        let handle = query
            .iter()
            .find(|(i, _)| i.0 == id)
            .map(|(_, body)| body.0)?;
        trace.body(handle)
    }

    /// The fighter alive whose body is `handle`: its id and kind.
    #[must_use]
    pub fn fighter_with_body(&self, handle: BodyHandle) -> Option<(u64, Kind)> {
        let mut query = self.world.query::<(&Id, &Body, &Kind)>();
        query
            .iter()
            .find(|(_, body, _)| body.0 == handle)
            .map(|(id, _, kind)| (id.0, *kind))
    }

    /// Every fighter alive, in spawn order.
    #[must_use]
    pub fn fighters(&self) -> Vec<Fighter> {
        let mut all: Vec<Fighter> = self
            .world
            .query::<(&Id, &Body, &Kind, &Team, &Health, Option<&Carrying>)>()
            .iter()
            .filter_map(|(id, body, kind, team, health, carrying)| {
                let b = self.bodies.get(body.0).ok()?;
                Some(Fighter {
                    id: id.0,
                    kind: *kind,
                    team: *team,
                    position: b.position(),
                    radius: kind.radius(),
                    hp: health.hp,
                    max_hp: health.max,
                    carrying: carrying.is_some(),
                })
            })
            .collect();
        all.sort_unstable_by_key(|f| f.id);
        all
    }

    /// The centres of the fireballs in flight (each of [`crate::FIREBALL_RADIUS`]), in
    /// the order they were shot.
    #[must_use]
    pub fn fireballs(&self) -> Vec<Vec2> {
        let mut balls: Vec<(u64, Vec2)> = self
            .world
            .query::<&Fireball>()
            .iter()
            .map(|ball| (ball.key, ball.position))
            .collect();
        balls.sort_unstable_by_key(|b| b.0);
        balls.into_iter().map(|b| b.1).collect()
    }
}
