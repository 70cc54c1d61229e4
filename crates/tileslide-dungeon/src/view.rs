//! What a renderer or a HUD reads of a game, as plain values: the fighters and the
//! fireballs (the components themselves stay inside the crate).

use tileslide::Vec2;

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
