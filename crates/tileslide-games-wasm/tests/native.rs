//! What the JavaScript classes hand over, computed natively: the Node tests
//! (`web/test/games.test.mjs`) assert the same constants against the wasm build, so wasm
//! and native agree bit for bit.
#![allow(clippy::unwrap_used)]

use tileslide::{Cell, Vec2};
use tileslide_dungeon::{Game, GameConfig, Kind};
use tileslide_games_wasm::draw::{self, FIGHTER_STRIDE, SEGMENT_STRIDE, Square};
use tileslide_games_wasm::platformer::input_from_keys;

/// The scripted keeper's game of seed 3 after 900 steps (30 s): its state hash, as
/// `DungeonGame.stateHash()` gives it. `web/test/games.test.mjs` asserts the same.
const SCRIPTED_SEED_3_900_STEPS: &str = "8205ccf86cfaa4a0";

/// A player's game of seed 1: square (31, 20) dug and an imp summoned at (32.5, 20.5)
/// before the first step, then 600 steps. `web/test/games.test.mjs` asserts the same.
const PLAYED_SEED_1_600_STEPS: &str = "9bf34ef5bf9a5aea";

#[test]
fn the_scripted_game_of_seed_3_has_the_hash_the_node_test_asserts() {
    let mut game = Game::new(3).unwrap();
    for _ in 0..900 {
        game.step().unwrap();
    }
    assert_eq!(
        format!("{:016x}", game.state_hash()),
        SCRIPTED_SEED_3_900_STEPS
    );
}

#[test]
fn a_played_game_of_seed_1_has_the_hash_the_node_test_asserts() {
    let mut game = Game::with_config(GameConfig::player(1)).unwrap();
    game.dig(Cell::new(31, 20)).unwrap();
    game.summon(Kind::Imp, Vec2::new(32.5, 20.5)).unwrap();
    for _ in 0..600 {
        game.step().unwrap();
    }
    assert_eq!(
        format!("{:016x}", game.state_hash()),
        PLAYED_SEED_1_600_STEPS
    );
}

#[test]
fn squares_mark_rock_earth_diggable_and_unseen_ground() {
    let mut game = Game::with_config(GameConfig::player(1)).unwrap();
    let squares = draw::squares(&game);
    let map = game.map();
    assert_eq!(squares.len(), (map.width() * map.height()) as usize);
    let at = |col: u32, row: u32| squares[(row * map.width() + col) as usize];
    assert_eq!(at(0, 0), Square::Rock as u8);
    assert_eq!(at(31, 20), Square::Diggable as u8);
    assert_eq!(at(20, 20), Square::Earth as u8);
    // Nobody has seen anything yet.
    assert_eq!(at(32, 20), Square::Unseen as u8);
    let diggable = squares
        .iter()
        .filter(|&&s| s == Square::Diggable as u8)
        .count();
    assert_eq!(diggable, game.diggable().len());
    assert_eq!(draw::cell_pairs(&game.diggable()).len(), 2 * diggable);
    game.dig(Cell::new(31, 20)).unwrap();
    let after = draw::squares(&game);
    assert_eq!(after[(20 * 64 + 31) as usize], Square::Unseen as u8);
    assert_eq!(after[(20 * 64 + 30) as usize], Square::Diggable as u8);
}

#[test]
fn fighters_are_seven_floats_each() {
    let mut game = Game::with_config(GameConfig::player(1)).unwrap();
    game.summon(Kind::Imp, Vec2::new(32.5, 20.5)).unwrap();
    let flat = draw::fighters(&game.fighters());
    assert_eq!(flat.len(), FIGHTER_STRIDE);
    assert_eq!(flat, [32.5, 20.5, Kind::Imp.radius(), 2.0, 1.0, 1.0, 0.0]);
}

#[test]
fn segments_are_the_maps_active_segments() {
    let game = Game::new(1).unwrap();
    let flat = draw::segments(game.map());
    assert_eq!(
        flat.len(),
        game.map().active_segment_count() * SEGMENT_STRIDE
    );
    // Every segment is a unit edge of a square with an axis normal, solid.
    for s in flat.chunks_exact(SEGMENT_STRIDE) {
        let length = (s[2] - s[0]).abs() + (s[3] - s[1]).abs();
        assert!(length > 0.0 && length <= 1.0, "{s:?}");
        assert_eq!(s[4].abs() + s[5].abs(), 1.0, "{s:?}");
        assert_eq!(s[6], 1.0, "{s:?}");
    }
}

#[test]
fn keys_make_the_platformers_input() {
    let right_jump = input_from_keys(false, true, true, false);
    assert_eq!(
        (right_jump.run, right_jump.jump, right_jump.drop),
        (1.0, true, false)
    );
    let drop = input_from_keys(false, false, true, true);
    assert_eq!((drop.run, drop.jump, drop.drop), (0.0, false, true));
    assert_eq!(input_from_keys(true, true, false, false).run, 0.0);
    assert_eq!(input_from_keys(true, false, false, true).run, -1.0);
}
