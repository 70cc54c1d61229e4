//! A person playing: the player moved by given input instead of the script, and a Replica
//! Island level loaded from bytes (as a browser game gets it) equal to the one loaded from
//! files.
#![allow(clippy::unwrap_used, clippy::panic)]

mod support;

use support::replica_dir;
use tileslide_platformer::{Game, Input, Level};

const RIGHT: Input = Input {
    run: 1.0,
    jump: false,
    drop: false,
};

#[test]
fn holding_right_then_jumping_moves_the_player_up_and_it_lands_again() {
    let mut game = Game::new(Level::bundled().unwrap()).unwrap();
    let start = game.player.body.position;
    for _ in 0..20 {
        game.step_with(RIGHT).unwrap();
    }
    let ran = game.player.body.position;
    assert!(ran.x > start.x + 1.0, "{start} → {ran}");
    assert!(game.player.contacts.is_grounded());
    game.step_with(Input {
        jump: true,
        ..RIGHT
    })
    .unwrap();
    assert_eq!(game.summary().jumps, 1);
    let mut highest = game.player.body.position.y;
    let mut landed = None;
    for step in 0..120 {
        game.step_with(RIGHT).unwrap();
        // y grows downwards in an ASCII level.
        highest = highest.min(game.player.body.position.y);
        if game.player.contacts.is_grounded() {
            landed = Some(step);
            break;
        }
    }
    assert!(highest < ran.y - 1.0, "rose to {highest} from {}", ran.y);
    assert!(landed.is_some(), "never landed");
    assert!(game.player.body.position.x > ran.x);
}

#[test]
fn a_run_of_nan_stands_still_and_a_run_beyond_one_is_a_run_of_one() {
    let level = Level::bundled().unwrap();
    let (mut fast, mut one, mut nan) = (
        Game::new(level.clone()).unwrap(),
        Game::new(level.clone()).unwrap(),
        Game::new(level).unwrap(),
    );
    let start = nan.player.body.position;
    for _ in 0..10 {
        fast.step_with(Input { run: 1e9, ..RIGHT }).unwrap();
        one.step_with(RIGHT).unwrap();
        nan.step_with(Input {
            run: f32::NAN,
            ..RIGHT
        })
        .unwrap();
    }
    assert_eq!(fast.player.body.position, one.player.body.position);
    assert_eq!(nan.player.body.position.x, start.x);
}

#[test]
fn a_replica_island_level_from_bytes_is_the_one_from_files() {
    let Some(dir) = replica_dir() else { return };
    let (level, tiles) = (dir.join("level_1_1_island.bin"), dir.join("collision.bin"));
    let from_files = Level::load_replica(&level, &tiles).unwrap();
    let from_bytes = Level::parse_replica(
        &std::fs::read(&level).unwrap(),
        "level_1_1_island.bin",
        &std::fs::read(&tiles).unwrap(),
        "collision.bin",
    )
    .unwrap();
    assert_eq!(from_bytes.name, from_files.name);
    assert_eq!(from_bytes.start, from_files.start);
    assert_eq!(from_bytes.goal, from_files.goal);
    assert_eq!(from_bytes.coins, from_files.coins);
    assert_eq!(from_bytes.enemies, from_files.enemies);
    assert_eq!(from_bytes.ignored_objects, from_files.ignored_objects);
    assert_eq!(
        tileslide::io::baked::to_bytes(&from_bytes.map),
        tileslide::io::baked::to_bytes(&from_files.map)
    );
    let err = Level::parse_replica(
        &[96, 1],
        "cut.bin",
        &std::fs::read(&tiles).unwrap(),
        "c.bin",
    )
    .unwrap_err();
    assert!(err.to_string().starts_with("cut.bin"), "{err}");
}
