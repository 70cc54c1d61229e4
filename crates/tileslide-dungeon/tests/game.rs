//! The game's promises: determinism, a clean collision audit, and a reachable treasure.
#![allow(clippy::unwrap_used)]

use tileslide_dungeon::{Game, GameConfig, Party};

fn run(config: GameConfig, steps: u32) -> Game {
    let mut game = Game::with_config(config).unwrap();
    for _ in 0..steps {
        game.step().unwrap();
    }
    game
}

#[test]
fn same_seed_same_summary_and_state_hash() {
    let config = GameConfig::new(7);
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
            defenders: false,
            ..GameConfig::new(1)
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
    let game = run(GameConfig::new(2), 300);
    assert!(!game.dug().is_empty());
    assert!(game.dug().iter().all(|&c| game.map().tile(c).is_none()));
    assert!(
        game.dug()
            .iter()
            .all(|&c| game.initial_map().tile(c).is_some())
    );
}

/// One hero of 5 hit points a wave.
const WEAK_PARTY: Party = Party {
    min_heroes: 1,
    max_heroes: 1,
    hero_hp: 5,
};

/// Issue 8: "the defence kills a weak party". One hero of 5 hit points a wave against the
/// keeper's skeletons and imps: by the time the second party is due, the first is dead
/// and took nothing.
#[test]
fn the_defence_kills_a_weak_party() {
    let mut game = Game::with_config(GameConfig {
        party: WEAK_PARTY,
        ..GameConfig::new(1)
    })
    .unwrap();
    let mut died_at = None;
    // The second wave is due at 42 s; stop just before.
    for step in 0..41 * 30 {
        game.step().unwrap();
        let s = game.summary();
        if died_at.is_none() && s.heroes_lost == 1 {
            died_at = Some(step);
        }
    }
    let s = game.summary();
    assert_eq!(s.waves, 1, "{s:?}");
    assert_eq!(
        (s.heroes_lost, s.heroes_escaped, s.treasure_taken),
        (1, 0, 0),
        "{s:?}"
    );
    assert!(s.creatures_summoned > 0, "{s:?}");
    assert!(died_at.is_some());
}

/// The same weak heroes in an undefended dungeon live and take the treasure: the defence,
/// not the weakness, is what kills them.
#[test]
fn a_weak_party_survives_an_undefended_dungeon() {
    let mut game = Game::with_config(GameConfig {
        defenders: false,
        party: WEAK_PARTY,
        ..GameConfig::new(1)
    })
    .unwrap();
    for _ in 0..60 * 30 {
        game.step().unwrap();
    }
    let s = game.summary();
    assert_eq!(s.heroes_lost, 0, "{s:?}");
    assert!(s.treasure_taken >= 1, "{s:?}");
}

/// The README's main job shows this run (`tileslide demo dungeon`: seed 1, two minutes):
/// its summary and final state hash, the same in debug and release builds. A change that
/// alters the game must update the README's output with this.
#[test]
fn the_default_run_is_the_one_the_readme_shows() {
    let game = run(GameConfig::new(1), 2 * 60 * 30);
    let s = game.summary();
    assert_eq!(
        (s.waves, s.heroes_lost, s.heroes_escaped),
        (4, 3, 15),
        "{s:?}"
    );
    assert_eq!((s.creatures_summoned, s.creatures_lost), (8, 4), "{s:?}");
    assert_eq!(
        (
            s.treasure_left,
            s.treasure_taken,
            s.treasure_stolen,
            s.squares_dug
        ),
        (0, 5, 5, 128),
        "{s:?}"
    );
    assert_eq!(
        (s.audit.overlapping_pairs, s.audit.wall_penetrations),
        (0, 0)
    );
    assert_eq!(format!("{:016x}", game.state_hash()), "4f2b136cc1bbdb42");
}

/// Issue 8: heroes "explore squares they have not seen". The first party does not know
/// where the treasure is: it sees more and more of the dungeon, sees the treasure, and
/// only then takes it.
#[test]
fn heroes_explore_until_they_see_the_treasure_and_only_then_take_it() {
    let mut game = Game::with_config(GameConfig {
        defenders: false,
        ..GameConfig::new(1)
    })
    .unwrap();
    let (mut first_seen, mut treasure_seen_at, mut taken_at) = (None, None, None);
    for step in 0..60 * 30 {
        game.step().unwrap();
        let explored = &game.level().explored;
        if first_seen.is_none() && explored.seen_count() > 0 {
            first_seen = Some((step, explored.seen_count()));
        }
        if treasure_seen_at.is_none() && explored.treasure_seen() {
            treasure_seen_at = Some((step, explored.seen_count()));
        }
        if taken_at.is_none() && game.summary().treasure_taken > 0 {
            taken_at = Some(step);
        }
    }
    let (first, seen_then) = first_seen.unwrap();
    let (found, seen_when_found) = treasure_seen_at.unwrap();
    let taken = taken_at.unwrap();
    assert!(first < found && found < taken, "{first} {found} {taken}");
    assert!(
        seen_when_found > seen_then + 20,
        "explored {seen_then} squares at first, {seen_when_found} when the treasure came into sight"
    );
}
