//! The script that plays: it reads the world through ray casts and decides, each step,
//! whether to run, wait, jump or drop.

use tileslide::{QueryFilter, Ray, SegmentFlags, SegmentSource, Vec2};

use crate::coin::Coin;
use crate::enemy::Enemy;
use crate::fall;
use crate::hits::ENEMY_HALF;
use crate::input::Input;
use crate::level::Level;
use crate::platform::PLATFORM_OWNER;
use crate::player::{JUMP_SPEED, Player, RUN_SPEED};

/// What the player does next on `level`, among `enemies` and `coins`: the first of the
/// rules of [`next_input`](crate::next_input) that applies.
#[must_use]
pub(crate) fn decide(level: &Level, player: &Player, enemies: &[Enemy], coins: &[Coin]) -> Input {
    let run = Input {
        run: 1.0,
        ..Input::default()
    };
    let Some(ground) = player.contacts.ground else {
        return run;
    };
    let s = level.scale;
    let up = level.up;
    let feet = player.feet();
    let jump = Input { jump: true, ..run };
    let on_one_way_tile = ground.flags.contains(SegmentFlags::ONE_WAY)
        && matches!(ground.source, SegmentSource::Tile { .. });
    // Falling while running carries the player about a cell and a half sideways.
    let coin_below = coins.iter().any(|c| {
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
    if ground_below(level, edge, &QueryFilter::default()).is_none() {
        let far = edge + Vec2::X * 2.5 * s;
        let fixed = QueryFilter::default().excluding(PLATFORM_OWNER);
        if ground_below(level, far, &fixed).is_some() || level.platform.is_none() {
            return jump;
        }
        return Input::default();
    }
    // (A coin over solid ground within reach, on a hill, is walked to.)
    let solid = QueryFilter::default().with_mask(SegmentFlags::SOLID);
    let coin_above = coins.iter().any(|c| {
        let dx = c.center.x - feet.x;
        let height = (c.center - feet).dot(up);
        let below = Ray::between(c.center, c.center - up * 1.5 * s);
        let high = || level.map.cast_ray(below, &solid).is_none();
        !c.taken
            && (0.3 * s..=2.5 * s).contains(&dx)
            && (1.5 * s..=3.5 * s).contains(&height)
            && high()
    });
    if coin_above {
        return jump;
    }
    // Time from take-off until the feet come back down to an enemy's top.
    let g = fall::gravity(s);
    let top = 2.0 * ENEMY_HALF.y * s;
    let v = JUMP_SPEED * s;
    let landing = (v + (v * v - 2.0 * g * top).max(0.0).sqrt()) / g;
    let stomp = enemies.iter().any(|e| {
        let d = e.body.position.x - feet.x;
        let level = (e.feet() - feet).dot(up).abs();
        let closing = RUN_SPEED * s - e.velocity_x();
        e.alive && level < 0.5 * s && d > 0.3 * s && closing > 0.0 && d <= closing * landing
    });
    if stomp { jump } else { run }
}

/// The ground within two and a half cells below `p` (from over half a cell above it, so
/// that a ramp rising ahead is found too).
fn ground_below(level: &Level, p: Vec2, filter: &QueryFilter) -> Option<tileslide::RayHit> {
    let s = level.scale;
    let up = level.up;
    let from = p + up * 0.6 * s;
    level
        .map
        .cast_ray(Ray::between(from, from - up * 3.1 * s), filter)
}
