//! The game's promises: determinism, a clean collision audit, and a reachable treasure.
#![allow(clippy::unwrap_used)]

use tileslide_dungeon::{Game, GameConfig};

fn run(config: GameConfig, steps: u32) -> Game {
    let mut game = Game::with_config(config).unwrap();
    for _ in 0..steps {
        game.step().unwrap();
    }
    game
}

#[test]
fn same_seed_same_summary_and_state_hash() {
    let config = GameConfig {
        seed: 7,
        defenders: true,
    };
    let (a, b) = (run(config, 900), run(config, 900));
    assert_eq!(a.summary(), b.summary());
    assert_eq!(a.state_hash(), b.state_hash());
    assert!(a.summary().waves >= 1, "{:?}", a.summary());
}

#[test]
fn audit_stays_zero_every_step() {
    let mut game = Game::new(3).unwrap();
    for step in 0..1200 {
        game.step().unwrap();
        let audit = game.summary().audit;
        assert_eq!(
            (audit.overlapping_pairs, audit.wall_penetrations),
            (0, 0),
            "step {step}"
        );
    }
    assert!(game.summary().squares_dug > 0);
    assert!(game.bodies().len() > 1);
}

#[test]
fn heroes_reach_the_treasure_of_an_undefended_dungeon() {
    let game = run(
        GameConfig {
            seed: 1,
            defenders: false,
        },
        1800,
    );
    let summary = game.summary();
    assert_eq!(summary.creatures_summoned, 0);
    assert!(summary.treasure_taken >= 1, "{summary:?}");
    assert_eq!(summary.heroes_lost, 0);
}

#[test]
fn dug_squares_are_empty_on_the_map() {
    let game = run(
        GameConfig {
            seed: 2,
            defenders: true,
        },
        300,
    );
    assert!(!game.dug().is_empty());
    assert!(game.dug().iter().all(|&c| game.map().tile(c).is_none()));
    assert!(
        game.dug()
            .iter()
            .all(|&c| game.initial_map().tile(c).is_some())
    );
}
