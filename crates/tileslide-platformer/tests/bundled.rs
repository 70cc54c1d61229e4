//! The scripted run through the bundled level: it reaches the goal, collects every coin,
//! and no character is ever inside solid (checked here with the map's own queries,
//! independently of the game's audit); and the run is deterministic.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod support;

use support::inside_solid;
use tileslide::Vec2;
use tileslide_platformer::{Game, Level, MAX_STEPS, Summary};

fn run_checked() -> (Summary, Game) {
    let mut game = Game::new(Level::bundled().unwrap()).unwrap();
    while !game.is_over() && game.summary().steps < MAX_STEPS {
        game.step().unwrap();
        let p = &game.player;
        assert!(
            !inside_solid(&game.level.map, p.body.position, p.half(), 1.0),
            "step {}: the player is inside solid at {:?}",
            game.summary().steps,
            p.body.position
        );
        for e in game.enemies.iter().filter(|e| e.alive) {
            assert!(
                !inside_solid(&game.level.map, e.body.position, e.half(), 1.0),
                "step {}: an enemy is inside solid at {:?}",
                game.summary().steps,
                e.body.position
            );
        }
    }
    (game.summary().clone(), game)
}

#[test]
fn scripted_run_reaches_the_goal_with_every_coin_and_never_enters_solid() {
    let (summary, game) = run_checked();
    let left: Vec<Vec2> = (game.coins.iter().filter(|c| !c.taken))
        .map(|c| c.center)
        .collect();
    assert!(summary.reached_goal, "{summary:?}");
    assert_eq!(
        summary.coins_collected, summary.coins_total,
        "{summary:?}; coins left at {left:?}"
    );
    assert!(summary.coins_total >= 8);
    assert!(summary.audit.is_clean(), "{summary:?}");
    assert_eq!(summary.audit.max_penetration, 0.0);
    assert!(game.coins.iter().all(|c| c.taken));
}

#[test]
fn scripted_run_uses_every_feature_of_the_level() {
    let (summary, _) = run_checked();
    assert!(summary.steps_riding > 30, "rode the platform: {summary:?}");
    assert!(summary.enemies_defeated >= 1, "{summary:?}");
    assert!(summary.jumps >= 4, "{summary:?}");
}

#[test]
fn same_level_same_summary() {
    let (a, _) = run_checked();
    let (b, _) = run_checked();
    assert_eq!(a, b);
}
