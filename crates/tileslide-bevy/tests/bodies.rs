//! Bodies through the plugin: the standard crowd moves exactly as the core moves it, and
//! navigation agents reach their goals along paths and down a shared flow field.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod support;

use bevy::prelude::*;
use tileslide::io::ascii;
use tileslide::{Bodies, BodyDesc, BodyShape};
use tileslide_bevy::{
    Body, BodyContact, CollisionMap, NavAgent, NavArrived, NavGoal, NavStatus, ProposedMove,
    ReportContacts, TileRef, TileslideError, TileslidePlugin, TileslideSet, Velocity,
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
    support::collect::<BodyContact>(&mut app);
    // Every tenth body reports its contacts: their resolve is traced, which must change
    // no move.
    let entities: Vec<Entity> = crowd
        .iter()
        .enumerate()
        .map(|(k, b)| {
            let (p, v) = (b.position, b.velocity);
            let mut body = app.world_mut().spawn((
                Body::circle(CROWD_RADIUS),
                CrowdMove(Vec2::new(v.x, -v.y)),
                Transform::from_xyz(p.x, -p.y, 0.0),
            ));
            if k % 10 == 0 {
                body.insert(ReportContacts);
            }
            body.id()
        })
        .collect();

    support::run_steps(&mut app, STEPS as u64);
    assert!(support::collected::<TileslideError>(&app).is_empty());
    let contacts = support::collected::<BodyContact>(&app);
    assert!(contacts.len() > 10, "{} contacts", contacts.len());
    for contact in &contacts {
        let k = entities.iter().position(|e| *e == contact.entity).unwrap();
        assert_eq!(k % 10, 0, "a body without ReportContacts reported");
    }
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

#[test]
fn an_interpolated_body_is_shown_between_its_last_two_steps() {
    // Frames a quarter of a fixed step long: a step runs every fourth frame, and in between
    // the interpolated body is shown a quarter further each frame from where the step before
    // left it to where the last step did, while its twin (not interpolated) jumps a whole
    // step every fourth frame. Both are where the core puts them at each step.
    let room = "##########\n#........#\n#........#\n#........#\n#........#\n##########";
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, TileslidePlugin::default()))
        .insert_resource(CollisionMap::new(
            ascii::parse(room, "room.txt", 1.0).unwrap(),
        ))
        .insert_resource(Time::<Fixed>::from_duration(support::STEP))
        .insert_resource(bevy::time::TimeUpdateStrategy::ManualDuration(
            support::STEP / 4,
        ));
    let spawn = |app: &mut App, y: f32, smooth: bool| {
        let mut e = app.world_mut().spawn((
            Body::circle(0.3),
            tileslide_bevy::Velocity(Vec2::new(3.0, 0.0)),
            Transform::from_xyz(1.5, y, 0.0),
        ));
        if smooth {
            e.insert(tileslide_bevy::Interpolated);
        }
        e.id()
    };
    let smooth = spawn(&mut app, -1.5, true);
    let twin = spawn(&mut app, -3.5, false);
    let x = |app: &App, e: Entity| app.world().get::<Transform>(e).unwrap().translation.x;
    let mut last_shown = x(&app, smooth);
    let mut moved = 0;
    for frame in 0..48 {
        app.update();
        let position = *app
            .world()
            .get::<tileslide_bevy::StepPosition>(smooth)
            .unwrap();
        if !position.placed {
            // No step yet (an app's first update runs none).
            continue;
        }
        let f = app.world().resource::<Time<Fixed>>().overstep_fraction();
        let shown = x(&app, smooth);
        // The true position is the twin's, and the one shown lies between the last two.
        assert_eq!(position.current.x, x(&app, twin), "frame {frame}");
        assert_eq!(
            shown,
            position.previous.lerp(position.current, f).x,
            "frame {frame}"
        );
        assert!(shown <= position.current.x, "frame {frame}");
        if shown > last_shown {
            moved += 1;
        } else {
            assert_eq!(shown, last_shown, "frame {frame}: shown moving back");
        }
        last_shown = shown;
    }
    // Once moving it moves every frame (three frames of four the twin stands still): 12
    // steps of 0.05.
    assert!(moved >= 36, "moved in {moved} of 48 frames");
    assert!(x(&app, twin) > 1.9, "{}", x(&app, twin));
}

#[test]
fn agents_find_their_way_on_a_map_in_pixels_without_a_nav_config() {
    // The rooms in 16-pixel cells, drawn a world unit a cell: an agent of radius 0.3 is
    // 4.8 map units wide, which the core's default grid (circles up to 1 map unit) refuses;
    // the plugin's default serves circles up to a cell.
    let map = ascii::parse(ROOMS, "rooms.txt", 16.0).unwrap();
    let mut app = support::headless(TileslidePlugin::default().with_scale(1.0 / 16.0));
    app.insert_resource(CollisionMap::new(map));
    support::collect::<NavArrived>(&mut app);
    support::collect::<TileslideError>(&mut app);
    let goal = Vec2::new(16.5, -2.5);
    let mut agent = NavAgent::new(0.3, 4.0).with_goal(NavGoal::Flow(goal));
    agent.arrive_distance = 0.3;
    let id = app
        .world_mut()
        .spawn((
            Body::circle(0.3),
            agent,
            Transform::from_xyz(1.5, -1.5, 0.0),
        ))
        .id();
    support::run_steps(&mut app, 600);
    assert!(support::collected::<TileslideError>(&app).is_empty());
    let arrived = support::collected::<NavArrived>(&app);
    assert_eq!(arrived.iter().map(|a| a.entity).collect::<Vec<_>>(), [id]);
}

/// The contacts of `entity` kept by the observer.
#[derive(Resource, Default)]
struct Observed(Vec<BodyContact>);

#[test]
fn a_body_reporting_contacts_names_the_tile_and_the_body_it_met() {
    // y down: a wall at column 6; a still body at (2.5, 3.5).
    let map = ascii::parse(
        "########\n#.....##\n#.....##\n#.....##\n#.....##\n########",
        "walls.txt",
        1.0,
    )
    .unwrap();
    let mut app = support::headless(TileslidePlugin::default());
    app.insert_resource(CollisionMap::new(map))
        .init_resource::<Observed>();
    support::collect::<BodyContact>(&mut app);
    let world = app.world_mut();
    // Runs right into the wall (its face at x = 6).
    let runner = world
        .spawn((
            Body::circle(0.4),
            ReportContacts,
            Velocity(Vec2::new(120.0, 0.0)),
            Transform::from_xyz(3.5, -1.5, 0.0),
        ))
        .observe(|contact: On<BodyContact>, mut seen: ResMut<Observed>| {
            seen.0.push(*contact);
        })
        .id();
    // Runs up into the still body above it.
    let climber = world
        .spawn((
            Body::circle(0.4),
            ReportContacts,
            Velocity(Vec2::new(0.0, 60.0)),
            Transform::from_xyz(2.5, -4.5, 0.0),
        ))
        .id();
    let still = world
        .spawn((Body::circle(0.4), Transform::from_xyz(2.5, -3.2, 0.0)))
        .id();
    // Runs into the wall too, but does not ask.
    world.spawn((
        Body::circle(0.4),
        Velocity(Vec2::new(120.0, 0.0)),
        Transform::from_xyz(3.5, -2.5, 0.0),
    ));
    support::run_steps(&mut app, 3);

    let contacts = support::collected::<BodyContact>(&app);
    let wall: Vec<&BodyContact> = contacts.iter().filter(|c| c.entity == runner).collect();
    assert!(!wall.is_empty(), "{contacts:?}");
    for c in &wall {
        assert_eq!(
            c.tile,
            Some(TileRef {
                cell: tileslide::Cell::new(6, 1),
                tile: ascii::SOLID,
            })
        );
        assert_eq!((c.platform, c.other), (None, None));
        assert_eq!(c.normal, Vec2::new(-1.0, 0.0));
        assert_eq!(c.point.x, 6.0);
    }
    assert_eq!(
        app.world().resource::<Observed>().0,
        wall.into_iter().copied().collect::<Vec<_>>()
    );
    let bump: Vec<&BodyContact> = contacts.iter().filter(|c| c.entity == climber).collect();
    assert!(!bump.is_empty(), "{contacts:?}");
    assert!(
        bump.iter()
            .all(|c| c.other == Some(still) && c.tile.is_none())
    );
    // First head-on, on the line of the centres; then round the still body's side.
    assert_eq!(bump[0].normal, Vec2::new(0.0, -1.0));
    assert_eq!(bump[0].point.x, 2.5);
    assert!((bump[0].point.y - -3.6).abs() < 1e-5, "{bump:?}");
    assert!(
        contacts
            .iter()
            .all(|c| c.entity == runner || c.entity == climber)
    );
}

#[test]
fn a_scale_the_plugin_cannot_use_is_reported_and_one_is_used() {
    for bad in [0.0, -16.0, f32::NAN, f32::INFINITY, 1e-30] {
        let mut app = support::headless(TileslidePlugin::default().with_scale(bad));
        support::collect::<TileslideError>(&mut app);
        app.update();
        let errors = support::collected::<TileslideError>(&app);
        assert_eq!(errors.len(), 1, "{bad}: {errors:?}");
        assert!(
            errors[0].message.starts_with(&format!(
                "TileslidePlugin: the scale {bad} is not a number of world units per map unit"
            )) && errors[0].message.ends_with("a scale of 1 is used"),
            "{}",
            errors[0].message
        );
        assert_eq!(
            app.world().resource::<tileslide_bevy::MapUnits>().scale(),
            1.0
        );
    }
}
