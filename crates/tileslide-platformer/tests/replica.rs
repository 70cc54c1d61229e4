//! Replica Island levels with their objects: the player starts at the level's spawn, the
//! coins and the enemies stand where the level places them, walkers land and flyers keep
//! their height, and the scripted run collects and stomps on a real level without any
//! character entering solid (checked here with the map's own queries).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod support;

use std::path::Path;

use support::{inside_solid, replica_dir};
use tileslide::Vec2;
use tileslide::io::replica::{self, LevelObjects, ObjectKind};
use tileslide_platformer::{EnemyStart, Game, Input, Level, LevelError, MAX_STEPS, ReplicaRole};

fn load(dir: &Path, name: &str) -> (Level, LevelObjects) {
    let level = Level::load_replica(dir.join(name), dir.join("collision.bin")).unwrap();
    let objects = replica::load_objects(dir.join(name)).unwrap();
    (level, objects)
}

/// The objects of `objects` that the demo gives `role`, in the file's order.
fn with_role(objects: &LevelObjects, role: ReplicaRole) -> Vec<&replica::SpawnPoint> {
    (objects.objects.iter())
        .filter(|o| o.kind.and_then(ReplicaRole::of) == Some(role))
        .collect()
}

#[test]
fn a_real_level_starts_the_player_at_its_spawn_and_places_its_coins_and_enemies() {
    let Some(dir) = replica_dir() else { return };
    let (level, objects) = load(&dir, "level_1_1_island.bin");
    // The spawn is cell (5, 43): the player's feet a pixel above the middle of its bottom.
    assert_eq!(level.start, Vec2::new(5.0 * 32.0 + 16.0, 43.0 * 32.0 + 1.0));
    let game = Game::new(level.clone()).unwrap();
    assert!((game.player.feet() - level.start).length() < 0.1);

    // 32 coins, 3 rubies and the diary page, each at its cell's centre.
    let coins: Vec<Vec2> = with_role(&objects, ReplicaRole::Coin)
        .iter()
        .map(|o| o.center())
        .collect();
    assert_eq!(coins.len(), 36);
    assert_eq!(level.coins, coins);
    assert_eq!(game.coins.len(), 36);

    // Four brobots walk, two karaguins fly.
    let walkers = with_role(&objects, ReplicaRole::Walker);
    let flyers = with_role(&objects, ReplicaRole::Flyer);
    assert_eq!((walkers.len(), flyers.len()), (4, 2));
    assert!(walkers.iter().all(|o| o.kind == Some(ObjectKind::Brobot)));
    assert!(flyers.iter().all(|o| o.kind == Some(ObjectKind::Karaguin)));
    for w in &walkers {
        let start = EnemyStart {
            feet: w.bottom_middle() + Vec2::Y,
            flies: false,
        };
        assert!(level.enemies.contains(&start), "{start:?}");
    }
    for f in &flyers {
        let start = level
            .enemies
            .iter()
            .find(|e| e.flies && e.feet.x == f.center().x)
            .unwrap();
        assert!(start.feet.y > f.position.y && start.feet.y < f.center().y);
    }
    assert_eq!(level.enemies.len(), 6);
    assert_eq!(game.enemies.len(), 6);

    // The rest is ignored, counted by type number: Wanda, doors and buttons.
    let ignored: usize = level.ignored_objects.iter().map(|i| i.count).sum();
    assert_eq!(ignored, objects.objects.len() - 1 - 36 - 6);
    let wanda = level
        .ignored_objects
        .iter()
        .find(|i| i.kind == Some(ObjectKind::Wanda))
        .unwrap();
    assert_eq!((wanda.type_number, wanda.count), (10, 1));
}

#[test]
fn walkers_land_on_the_ground_and_flyers_keep_their_height() {
    let Some(dir) = replica_dir() else { return };
    let (level, _) = load(&dir, "level_1_1_island.bin");
    let mut game = Game::new(level).unwrap();
    let heights: Vec<f32> = game.enemies.iter().map(|e| e.body.position.y).collect();
    // The player stands still at its spawn, far from them.
    for _ in 0..120 {
        game.step_with(Input::default()).unwrap();
    }
    let mut flew = 0;
    for (e, y) in game.enemies.iter().zip(heights) {
        assert!(e.alive);
        if e.flies {
            flew += 1;
            assert_eq!(e.body.position.y, y, "a flyer changed height");
            assert!(e.body.ground().is_none());
        } else {
            assert!(
                e.body.ground().is_some(),
                "a walker at {} is not on the ground",
                e.body.position
            );
            assert!(e.body.position.y <= y);
        }
    }
    assert_eq!(flew, 2);
    assert!(game.summary().audit.is_clean(), "{:?}", game.summary());
}

#[test]
fn the_scripted_run_collects_coins_and_stomps_enemies_on_a_real_level_without_entering_solid() {
    let Some(dir) = replica_dir() else { return };
    let (level, _) = load(&dir, "level_3_6_sewer.bin");
    let mut game = Game::new(level).unwrap();
    let s = game.level.scale;
    while !game.is_over() && game.summary().steps < MAX_STEPS {
        game.step().unwrap();
        let map = &game.level.map;
        let p = &game.player;
        let step = game.summary().steps;
        assert!(
            !inside_solid(map, p.body.position, p.half(), s),
            "step {step}: the player is inside solid at {}",
            p.body.position
        );
        for e in game.enemies.iter().filter(|e| e.alive) {
            assert!(
                !inside_solid(map, e.body.position, e.half(), s),
                "step {step}: an enemy is inside solid at {}",
                e.body.position
            );
        }
    }
    let summary = game.summary();
    assert!(summary.reached_goal, "{summary:?}");
    assert!(summary.coins_collected > 0, "{summary:?}");
    assert!(summary.enemies_defeated > 0, "{summary:?}");
    assert_eq!(summary.coins_total, 40);
    assert_eq!(summary.enemies_total, 5);
    assert!(summary.audit.is_clean(), "{summary:?}");
}

#[test]
fn every_level_with_a_player_plays_with_its_objects_and_no_one_inside_solid() {
    let Some(dir) = replica_dir() else { return };
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with("level_") && n.ends_with(".bin"))
        .collect();
    names.sort();
    let mut played = 0;
    for name in names {
        let level = match Level::load_replica(dir.join(&name), dir.join("collision.bin")) {
            Ok(level) => level,
            // Three story levels place no player.
            Err(LevelError::NoStart(path)) => {
                assert!(name.starts_with("level_0_1_sewer"), "{}", path.display());
                continue;
            }
            Err(e) => panic!("{e}"),
        };
        let objects = replica::load_objects(dir.join(&name)).unwrap();
        let placed = level.coins.len()
            + level.enemies.len()
            + level.ignored_objects.iter().map(|i| i.count).sum::<usize>();
        assert_eq!(placed + 1, objects.objects.len(), "{name}");
        // Five seconds of the script: the walkers land and patrol, the flyers fly.
        let mut game = Game::new(level).unwrap();
        game.run(300).unwrap();
        assert!(
            game.summary().audit.is_clean(),
            "{name}: {:?}",
            game.summary()
        );
        played += 1;
    }
    assert_eq!(played, 42);
}

#[test]
fn a_level_without_a_player_spawn_is_refused_naming_the_file() {
    let Some(dir) = replica_dir() else { return };
    let path = dir.join("level_0_1_sewer.bin");
    let err = Level::load_replica(&path, dir.join("collision.bin")).unwrap_err();
    assert!(
        matches!(&err, LevelError::NoStart(p) if *p == path),
        "{err}"
    );
}
