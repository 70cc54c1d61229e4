//! The script that plays: it reads the world through ray casts and decides, each step,
//! whether to run, wait, jump or drop.

use tileslide::{QueryFilter, Ray, SegmentFlags, SegmentSource, Vec2};

use crate::game::{Game, JUMP_SPEED, PLATFORM_OWNER, RUN_SPEED};
use crate::hits::ENEMY_HALF;

/// What the player does this step.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Input {
    /// Sideways run, −1 (left) to 1 (right).
    pub run: f32,
    /// Start a jump (only on the ground).
    pub jump: bool,
    /// Drop through the one-way platform stood on.
    pub drop: bool,
}

/// The run's rules, in order; the first that applies decides. Only a player on the ground
/// decides anything; in the air it keeps running right.
///
/// 1. A coin below and a little ahead of the one-way platform it stands on: drop through.
/// 2. A wall ahead: jump.
/// 3. The ground ends ahead: jump if there is ground to land on within a jump (moving
///    platforms are not counted, they move), else wait for the moving platform if the
///    level has one (or jump anyway).
/// 4. A coin above and ahead within a jump's reach, not over solid ground it can walk to:
///    jump.
/// 5. An enemy ahead on the same level, close enough to land on: jump (a stomp).
/// 6. Otherwise run right.
#[must_use]
pub fn next_input(game: &Game) -> Input {
    let run = Input {
        run: 1.0,
        ..Input::default()
    };
    let player = &game.player;
    let Some(ground) = player.contacts.ground else {
        return run;
    };
    let s = game.level.scale;
    let up = game.level.up;
    let feet = player.feet();
    let jump = Input { jump: true, ..run };
    let on_one_way_tile = ground.flags.contains(SegmentFlags::ONE_WAY)
        && matches!(ground.source, SegmentSource::Tile { .. });
    // Falling while running carries the player about a cell and a half sideways.
    let coin_below = game.coins.iter().any(|c| {
        let depth = (feet - c.center).dot(up);
        let dx = c.center.x - feet.x;
        !c.taken && (1.0 * s..=1.8 * s).contains(&dx) && depth > 0.0 && depth < 3.0 * s
    });
    if on_one_way_tile && coin_below {
        return Input { drop: true, ..run };
    }
    if player.contacts.right.is_some() {
        return jump;
    }
    let edge = feet + Vec2::new(player.half().x + 0.2 * s, 0.0);
    if ground_below(game, edge, &QueryFilter::default()).is_none() {
        let far = edge + Vec2::X * 2.5 * s;
        let fixed = QueryFilter::default().excluding(PLATFORM_OWNER);
        if ground_below(game, far, &fixed).is_some() || game.level.platform.is_none() {
            return jump;
        }
        return Input::default();
    }
    // (A coin over solid ground within reach, on a hill, is walked to.)
    let solid = QueryFilter::default().with_mask(SegmentFlags::SOLID);
    let coin_above = game.coins.iter().any(|c| {
        let dx = c.center.x - feet.x;
        let height = (c.center - feet).dot(up);
        let below = Ray::between(c.center, c.center - up * 1.5 * s);
        let high = || game.level.map.cast_ray(below, &solid).is_none();
        !c.taken
            && (0.3 * s..=2.5 * s).contains(&dx)
            && (1.5 * s..=3.5 * s).contains(&height)
            && high()
    });
    if coin_above {
        return jump;
    }
    // Time from take-off until the feet come back down to an enemy's top.
    let g = game.gravity();
    let top = 2.0 * ENEMY_HALF.y * s;
    let v = JUMP_SPEED * s;
    let landing = (v + (v * v - 2.0 * g * top).max(0.0).sqrt()) / g;
    let stomp = game.enemies.iter().any(|e| {
        let d = e.body.position.x - feet.x;
        let level = (e.feet() - feet).dot(up).abs();
        let closing = RUN_SPEED * s - e.velocity_x();
        e.alive && level < 0.5 * s && d > 0.3 * s && closing > 0.0 && d <= closing * landing
    });
    if stomp { jump } else { run }
}

/// The ground within two and a half cells below `p` (from over half a cell above it, so
/// that a ramp rising ahead is found too).
fn ground_below(game: &Game, p: Vec2, filter: &QueryFilter) -> Option<tileslide::RayHit> {
    let s = game.level.scale;
    let up = game.level.up;
    let from = p + up * 0.6 * s;
    game.level
        .map
        .cast_ray(Ray::between(from, from - up * 3.1 * s), filter)
}
