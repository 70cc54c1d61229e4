//! Bodies through the plugin: the standard crowd moves exactly as the core moves it, and
//! navigation agents reach their goals along paths and down a shared flow field.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod support;

use bevy::prelude::*;
use tileslide::io::ascii;
use tileslide::{Bodies, BodyDesc, BodyShape};
use tileslide_bevy::{
    Body, CollisionMap, NavAgent, NavArrived, NavGoal, NavStatus, ProposedMove, TileslideError,
    TileslidePlugin, TileslideSet,
};
use tileslide_scenes::{CROWD_RADIUS, dungeon256, scene_crowd};

/// A crowd body's constant move per step (world units).
#[derive(Component)]
struct CrowdMove(Vec2);

fn propose_crowd(mut crowd: Query<(&CrowdMove, &mut ProposedMove)>) {
    for (step, mut proposed) in &mut crowd {
        proposed.0 = step.0;
    }
}

#[test]
fn the_crowd_moves_as_the_core_moves_it_bit_for_bit() {
    const N: usize = 600;
    const STEPS: usize = 40;
    let grid = dungeon256();
    let crowd = scene_crowd(&grid, N);
    // The core alone.
    let map = grid.to_tile_map().unwrap();
    let mut bodies = Bodies::new();
    let shape = BodyShape::circle(CROWD_RADIUS).unwrap();
    let handles: Vec<_> = crowd
        .iter()
        .map(|b| {
            bodies
                .add(BodyDesc::new(b.position, shape.clone()))
                .unwrap()
        })
        .collect();
    for _ in 0..STEPS {
        for (h, b) in handles.iter().zip(&crowd) {
            bodies.propose(*h, b.velocity).unwrap();
        }
        bodies.step(&map);
    }
    // The plugin (world y is the map's negated).
    let mut app = support::headless(TileslidePlugin::default());
    app.insert_resource(CollisionMap::new(grid.to_tile_map().unwrap()))
        .add_systems(FixedUpdate, propose_crowd.before(TileslideSet::SyncIn));
    support::collect::<TileslideError>(&mut app);
    let entities: Vec<Entity> = crowd
        .iter()
        .map(|b| {
            let (p, v) = (b.position, b.velocity);
            app.world_mut()
                .spawn((
                    Body::circle(CROWD_RADIUS),
                    CrowdMove(Vec2::new(v.x, -v.y)),
                    Transform::from_xyz(p.x, -p.y, 0.0),
                ))
                .id()
        })
        .collect();

    support::run_steps(&mut app, STEPS as u64);
    assert!(support::collected::<TileslideError>(&app).is_empty());
    let mut moved = 0;
    for ((entity, handle), start) in entities.iter().zip(&handles).zip(&crowd) {
        let at = app.world().get::<Transform>(*entity).unwrap().translation;
        let core = bodies.get(*handle).unwrap().position();
        let plugin = tileslide::Vec2::new(at.x, -at.y);
        assert_eq!(
            (plugin.x.to_bits(), plugin.y.to_bits()),
            (core.x.to_bits(), core.y.to_bits()),
            "plugin {plugin}, core {core}"
        );
        moved += usize::from(core != start.position);
    }
    assert!(moved > N / 2, "only {moved} bodies moved");
}

/// y down: two rooms joined by a corridor, the goal in the right room.
const ROOMS: &str = "\
####################
#......#...........#
#......#...........#
#..................#
#......#####.......#
#......#...........#
####################";

/// Agents that reach their goal leave the map (as monsters leaving by the exit).
fn leave(arrived: On<NavArrived>, mut commands: Commands) {
    commands.entity(arrived.entity).despawn();
}

#[test]
fn bodies_reach_their_goal_along_paths_and_down_a_flow_field() {
    let map = ascii::parse(ROOMS, "rooms.txt", 1.0).unwrap();
    let mut app = support::headless(TileslidePlugin::default());
    app.insert_resource(CollisionMap::new(map))
        .add_observer(leave);
    support::collect::<NavArrived>(&mut app);
    support::collect::<TileslideError>(&mut app);
    let goal = Vec2::new(16.5, -2.5);
    let mut agents = Vec::new();
    for (i, start) in [(1.5, 1.5), (2.5, 5.5), (5.5, 1.5), (1.5, 4.5)]
        .iter()
        .enumerate()
    {
        let at = Transform::from_xyz(start.0, -start.1, 0.0);
        // The first two follow paths to the goal, the others the goal's flow field.
        let target = if i < 2 {
            NavGoal::Path(goal)
        } else {
            NavGoal::Flow(goal)
        };
        let mut agent = NavAgent::new(0.3, 4.0).with_goal(target);
        agent.arrive_distance = 0.3;
        agents.push(app.world_mut().spawn((Body::circle(0.3), agent, at)).id());
    }
    for _ in 0..600 {
        support::run_steps(&mut app, 1);
        if agents.iter().all(|&a| app.world().get_entity(a).is_err()) {
            break;
        }
    }
    assert!(support::collected::<TileslideError>(&app).is_empty());
    let arrived = support::collected::<NavArrived>(&app);
    let mut who: Vec<Entity> = arrived.iter().map(|a| a.entity).collect();
    who.sort_unstable();
    let mut expected = agents.clone();
    expected.sort_unstable();
    assert_eq!(who, expected, "every agent arrives, once");
    assert!(arrived.iter().all(|a| a.goal == goal));
}

#[test]
fn an_agent_with_an_unreachable_goal_says_so_and_stays() {
    let map = ascii::parse(ROOMS, "rooms.txt", 1.0).unwrap();
    let mut app = support::headless(TileslidePlugin::default());
    app.insert_resource(CollisionMap::new(map));
    // Inside the wall between the rooms.
    let agent = NavAgent::new(0.3, 4.0).with_goal(NavGoal::Path(Vec2::new(7.5, -1.5)));
    let start = Transform::from_xyz(1.5, -1.5, 0.0);
    let id = app
        .world_mut()
        .spawn((Body::circle(0.3), agent, start))
        .id();
    support::run_steps(&mut app, 5);
    let agent = app.world().get::<NavAgent>(id).unwrap();
    assert_eq!(agent.status(), NavStatus::Unreachable);
    let at = app.world().get::<Transform>(id).unwrap().translation;
    assert_eq!((at.x, at.y), (1.5, -1.5));
}

#[test]
fn a_transform_moved_by_the_game_teleports_the_body() {
    let map = ascii::parse(ROOMS, "rooms.txt", 1.0).unwrap();
    let mut app = support::headless(TileslidePlugin::default());
    app.insert_resource(CollisionMap::new(map));
    let id = app
        .world_mut()
        .spawn((Body::circle(0.3), Transform::from_xyz(1.5, -1.5, 0.0)))
        .id();
    support::run_steps(&mut app, 2);
    app.world_mut()
        .get_mut::<Transform>(id)
        .unwrap()
        .translation
        .x = 10.5;
    app.world_mut().get_mut::<ProposedMove>(id).unwrap().0 = Vec2::new(0.5, 0.0);
    support::run_steps(&mut app, 1);
    let handle = app
        .world()
        .get::<tileslide_bevy::BodyLink>(id)
        .unwrap()
        .handle()
        .unwrap();
    let set = app.world().resource::<tileslide_bevy::TileslideBodies>();
    assert_eq!(
        set.bodies().get(handle).unwrap().position(),
        tileslide::Vec2::new(11.0, 1.5)
    );
    // Despawned: gone from the core too.
    app.world_mut().despawn(id);
    support::run_steps(&mut app, 1);
    let set = app.world().resource::<tileslide_bevy::TileslideBodies>();
    assert!(set.bodies().is_empty());
}
