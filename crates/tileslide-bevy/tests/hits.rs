//! Hits through the plugin: a tile that deals hit types hits the character touching it,
//! naming its cell and id; attack volumes hit other teams' vulnerability volumes; both come
//! as messages and as entity events.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod support;

use bevy::prelude::*;
use tileslide::io::ascii;
use tileslide::{Cell, HitTypes, TileId};
use tileslide_bevy::{
    CharacterController, CharacterInput, CollisionMap, Hit, HitVolume, HitVolumes, TileslideError,
    TileslidePlugin,
};

/// Hits an observer of one entity saw.
#[derive(Resource, Default)]
struct Observed(Vec<Hit>);

#[test]
fn spikes_in_a_tiled_map_hit_the_character_that_lands_on_them_naming_the_tile() {
    let mut app = support::app_reading(&support::maps_dir());
    support::collect::<Hit>(&mut app);
    support::collect::<TileslideError>(&mut app);
    let handle = support::load(&mut app, "cave.tmj");
    app.insert_resource(CollisionMap::from_asset(handle.clone()));
    support::assert_loaded(&mut app, &handle);
    // The cave is in pixels, 16 to a cell; the spikes are in cells (23, 12) and (24, 12).
    // A 10 × 12 character falls from cell (23, 10) onto them.
    let hero = app
        .world_mut()
        .spawn((
            CharacterController::rect(Vec2::new(5.0, 6.0)),
            CharacterInput {
                velocity: Vec2::new(0.0, -100.0),
                ..default()
            },
            HitVolumes {
                vulnerable: vec![HitVolume::rect(
                    Vec2::ZERO,
                    Vec2::new(5.0, 6.0),
                    HitTypes::ANY,
                )],
                team: 1,
                ..default()
            },
            Transform::from_xyz(23.5 * 16.0, -10.5 * 16.0, 0.0),
        ))
        .id();
    app.world_mut().init_resource::<Observed>();
    app.world_mut()
        .entity_mut(hero)
        .observe(|hit: On<Hit>, mut seen: ResMut<Observed>| seen.0.push(*hit));
    support::run_steps(&mut app, 60);
    assert!(support::collected::<TileslideError>(&app).is_empty());
    let hits = support::collected::<Hit>(&app);
    assert!(!hits.is_empty(), "no hit");
    let spikes = [Cell::new(23, 12), Cell::new(24, 12)];
    for hit in &hits {
        assert_eq!(hit.victim, hero);
        assert_eq!(hit.attacker, None);
        let tile = hit.tile.unwrap();
        assert!(spikes.contains(&tile.cell), "{:?}", tile.cell);
        assert_eq!(tile.tile, TileId(5));
        assert_eq!(hit.hit_type, HitTypes::DEATH);
        assert!(hit.accepted);
        // The point is on the spikes' cells, under the character.
        assert!(hit.point.y <= -12.0 * 16.0 + 1e-3 && hit.point.y >= -13.0 * 16.0);
    }
    assert_eq!(app.world().resource::<Observed>().0, hits);
}

#[test]
fn a_tile_deals_nothing_to_a_character_whose_vulnerability_does_not_accept_it() {
    let map = ascii::parse("#####\n#...#\n#####", "room.txt", 1.0).unwrap();
    let mut app = support::headless(TileslidePlugin::default());
    app.insert_resource(CollisionMap::new(map).with_tile_hits(ascii::SOLID, HitTypes::DEATH));
    support::collect::<Hit>(&mut app);
    let volumes = |hits| HitVolumes {
        vulnerable: vec![HitVolume::circle(Vec2::ZERO, 0.3, hits)],
        ..default()
    };
    let start = Transform::from_xyz(2.5, -1.5, 0.0);
    let fall = CharacterInput {
        velocity: Vec2::new(0.0, -10.0),
        ..default()
    };
    let safe = app
        .world_mut()
        .spawn((
            CharacterController::circle(0.3),
            fall,
            volumes(HitTypes::COLLECT),
            start,
        ))
        .id();
    let hurt = app
        .world_mut()
        .spawn((
            CharacterController::circle(0.3),
            fall,
            volumes(HitTypes::ANY),
            start,
        ))
        .id();
    support::run_steps(&mut app, 10);
    let hits = support::collected::<Hit>(&app);
    assert!(hits.iter().all(|h| h.victim == hurt && h.victim != safe));
    let floor = hits
        .iter()
        .find(|h| h.tile.is_some_and(|t| t.cell == Cell::new(2, 2)));
    assert!(floor.is_some_and(|h| h.hit_type == HitTypes::DEATH));
}

#[test]
fn an_attack_volume_hits_another_team_and_the_victim_observes_it() {
    let map = ascii::parse("##########\n#........#\n##########", "hall.txt", 1.0).unwrap();
    let mut app = support::headless(TileslidePlugin::default());
    app.insert_resource(CollisionMap::new(map));
    app.world_mut().init_resource::<Observed>();
    support::collect::<Hit>(&mut app);
    let fist = |team, flip_x| HitVolumes {
        attack: vec![HitVolume::circle(Vec2::new(0.8, 0.0), 0.3, HitTypes::HIT)],
        vulnerable: vec![HitVolume::rect(Vec2::ZERO, Vec2::splat(0.4), HitTypes::ANY)],
        team,
        flip_x,
        ..default()
    };
    let hero = app
        .world_mut()
        .spawn((fist(1, false), Transform::from_xyz(2.5, -1.5, 0.0)))
        .id();
    // On the hero's right, within reach of its fist; a friend behind it, facing away.
    let slime = app
        .world_mut()
        .spawn((fist(2, true), Transform::from_xyz(3.5, -1.5, 0.0)))
        .id();
    let friend = app
        .world_mut()
        .spawn((fist(1, true), Transform::from_xyz(1.5, -1.5, 0.0)))
        .id();
    app.world_mut()
        .entity_mut(slime)
        .observe(|hit: On<Hit>, mut seen: ResMut<Observed>| seen.0.push(*hit));
    support::run_steps(&mut app, 1);
    let hits = support::collected::<Hit>(&app);
    // The hero hits the slime; the slime (facing left) hits the hero back; the friend
    // faces away from the hero (its fist at x = 0.7) and hits nobody.
    let pairs: Vec<_> = hits
        .iter()
        .map(|h| (h.attacker.unwrap(), h.victim))
        .collect();
    assert_eq!(pairs, vec![(hero, slime), (slime, hero)]);
    assert!(
        hits.iter()
            .all(|h| h.accepted && h.tile.is_none() && h.hit_type == HitTypes::HIT)
    );
    assert!(!pairs.iter().any(|&(a, v)| a == friend || v == friend));
    let observed = &app.world().resource::<Observed>().0;
    assert_eq!(observed.as_slice(), &hits[..1]);
}
