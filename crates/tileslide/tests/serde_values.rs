//! The `serde` feature: the public value types (shapes, configurations, filters, hits,
//! contacts, handles and ids) survive a trip through JSON unchanged, and a shape with
//! checks is read through them.

#![cfg(feature = "serde")]
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::fmt::Debug;

use serde::Serialize;
use serde::de::DeserializeOwned;
use tileslide::geometry::{EndCaps, sweep_circle_segment};
use tileslide::io::ascii;
use tileslide::{
    Aabb, Bodies, BodyDesc, BodyFilter, BodyShape, Cell, Character, CharacterShape, Circle,
    ControllerConfig, Faces, Facing, HitObject, HitTypes, HitWorld, MoveOptions, NavConfig, Owner,
    QueryFilter, Ray, ResolveConfig, Segment, SegmentFlags, SlideMode, TeamRule, TileId, Vec2,
    Volume, VolumeShape, broadphase::PairMethod,
};

const ROOM: &str = "\
##########
#........#
#...##...#
#........#
##########";

/// `value` written as JSON and read back: equal, and the JSON is what it was.
fn round_trip<T: Serialize + DeserializeOwned + PartialEq + Debug>(value: &T) -> String {
    let json = serde_json::to_string(value).unwrap();
    let back: T = serde_json::from_str(&json).unwrap();
    assert_eq!(&back, value, "{json}");
    assert_eq!(serde_json::to_string(&back).unwrap(), json);
    json
}

#[test]
fn shapes_configurations_and_filters_round_trip() {
    round_trip(&Aabb {
        min: Vec2::new(-1.0, 0.5),
        max: Vec2::new(2.0, 3.25),
    });
    round_trip(&Circle::new(Vec2::new(0.25, -4.0), 0.75));
    round_trip(&Segment::new(Vec2::ZERO, Vec2::new(1.0, 1.0)));
    round_trip(&Ray::between(Vec2::new(1.0, 2.0), Vec2::new(3.0, -4.0)));
    round_trip(
        &BodyShape::compound([Circle::new(Vec2::ZERO, 0.3), Circle::new(Vec2::X, 0.2)]).unwrap(),
    );
    round_trip(
        &BodyDesc::new(Vec2::new(3.5, 2.5), BodyShape::circle(0.3).unwrap()).with_owner(Owner(9)),
    );
    round_trip(&BodyFilter::default());
    round_trip(&CharacterShape::rect(Vec2::new(0.4, 0.9)).unwrap());
    round_trip(&CharacterShape::circle(0.45).unwrap());
    round_trip(&Volume::circle(Vec2::new(1.5, 1.0), 0.25, HitTypes::HIT).unwrap());
    round_trip(&VolumeShape::Rect(Aabb {
        min: Vec2::ZERO,
        max: Vec2::ONE,
    }));
    round_trip(&Volume::rect(Vec2::new(0.5, 1.0), Vec2::new(0.5, 1.0), HitTypes::ANY).unwrap());
    round_trip(&EndCaps { a: true, b: false });
    round_trip(&Facing::default());
    round_trip(&HitObject::new(
        Owner(7),
        Vec2::new(4.0, 1.0),
        Vec2::new(1.0, 2.0),
    ));
    round_trip(&ResolveConfig {
        slide: SlideMode::default(),
        ..ResolveConfig::default()
    });
    round_trip(&ControllerConfig::default());
    round_trip(&MoveOptions::default());
    round_trip(&NavConfig::default());
    round_trip(&PairMethod::SweepAndPrune);
    round_trip(&QueryFilter {
        faces: Faces::Against(Vec2::new(0.0, 1.0)),
        ..QueryFilter::default().excluding(Owner(3))
    });
}

#[test]
fn hits_contacts_and_reports_from_real_queries_round_trip() {
    let map = ascii::parse(ROOM, "room.txt", 1.0).unwrap();
    let filter = QueryFilter::default();
    let hit = map
        .cast_ray(
            Ray::between(Vec2::new(1.5, 1.5), Vec2::new(9.5, 1.5)),
            &filter,
        )
        .unwrap();
    round_trip(&hit);
    round_trip(&hit.source);
    let circle = map
        .cast_circle(Vec2::new(1.5, 2.5), 0.3, Vec2::new(8.0, 0.0), &filter)
        .unwrap()
        .unwrap();
    round_trip(&circle);
    round_trip(&map.active_segments(Cell::new(4, 2)).next().unwrap());
    let sweep = sweep_circle_segment(
        Vec2::new(0.0, -2.0),
        0.5,
        Vec2::new(0.0, 4.0),
        &Segment::new(Vec2::new(-1.0, 0.0), Vec2::new(1.0, 0.0)),
        Vec2::new(0.0, -1.0),
        EndCaps::BOTH,
    )
    .unwrap();
    round_trip(&sweep);

    let mut bodies = Bodies::new();
    let a = bodies
        .add(BodyDesc::new(
            Vec2::new(2.5, 1.5),
            BodyShape::circle(0.4).unwrap(),
        ))
        .unwrap();
    bodies.propose(a, Vec2::new(-3.0, 0.0)).unwrap();
    let report = bodies.resolve(&map);
    assert!(report.contact_count > 0, "{report:?}");
    round_trip(&report);
    round_trip(&a);

    let mut hero = Character::new(
        CharacterShape::rect(Vec2::new(0.3, 0.4)).unwrap(),
        Vec2::new(1.5, 3.0),
        Vec2::new(0.0, -1.0),
        ControllerConfig::default(),
    )
    .unwrap();
    let contacts = hero
        .move_by(&map, Vec2::new(0.0, 1.0), MoveOptions::default())
        .unwrap();
    assert!(contacts.ground.is_some(), "{contacts:?}");
    round_trip(&contacts);

    let mut world = HitWorld::new();
    let sword = Volume::circle(Vec2::new(1.0, 0.5), 0.5, HitTypes::HIT).unwrap();
    let body = Volume::circle(Vec2::new(0.5, 0.5), 0.5, HitTypes::ANY).unwrap();
    let mut hero = HitObject::new(Owner(1), Vec2::ZERO, Vec2::ONE);
    hero.team = 1;
    world.register(hero, &[sword], &[]).unwrap();
    world
        .register(
            HitObject::new(Owner(2), Vec2::new(1.0, 0.0), Vec2::ONE),
            &[],
            &[body],
        )
        .unwrap();
    let events = world.detect(&mut TeamRule).to_vec();
    assert_eq!(events.len(), 1, "{events:?}");
    round_trip(&events[0]);
}

#[test]
fn ids_and_flags_are_written_as_their_numbers() {
    assert_eq!(round_trip(&Owner(42)), "42");
    assert_eq!(round_trip(&TileId(7)), "7");
    assert_eq!(
        round_trip(&SegmentFlags::ONE_WAY),
        SegmentFlags::ONE_WAY.0.to_string()
    );
    assert_eq!(round_trip(&HitTypes::ANY), u32::MAX.to_string());
}

#[test]
fn a_saved_body_shape_is_checked_as_a_built_one_is() {
    let json = r#"[{"center":[0.0,0.0],"radius":-0.5}]"#;
    let err = serde_json::from_str::<BodyShape>(json)
        .unwrap_err()
        .to_string();
    assert!(err.contains("-0.5"), "{err}");
    let empty = serde_json::from_str::<BodyShape>("[]")
        .unwrap_err()
        .to_string();
    assert!(!empty.is_empty());
}
