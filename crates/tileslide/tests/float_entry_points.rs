//! Every public entry point that takes a float, given NaN, an infinity and a finite value
//! too large (3e38, 1e20): refused with an error naming the value, or answered exactly.
//! (The queries' and the sweeps' absurd values have files of their own:
//! `query_absurd_rays.rs`, `query_absurd_circles.rs`, `geometry_absurd.rs`, `path_absurd.rs`.)

use std::fmt::Display;
use std::sync::Arc;

use tileslide::geometry::{
    EndCaps, cast_ray_segment, sweep_box_segment, sweep_circle_circle, sweep_circle_segment,
};
use tileslide::{
    Bodies, BodyDesc, BodyError, BodyShape, Character, CharacterShape, Circle, ControllerConfig,
    ControllerError, DebugKind, DebugLines, FlowField, HitObject, HitTypes, HitWorld, MapError,
    MoveOptions, NavConfig, NavError, NavGrid, ObjectId, Owner, QueryFilter, Ray, RayHit, Segment,
    SegmentFlags, TemporaryError, TemporarySegment, TileMap, TileSet, TileSetError, Vec2, Volume,
    VolumeError, VolumeShape,
};

/// NaN and the infinities: refused as not finite.
const NON_FINITE: [f32; 3] = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY];

/// Finite, and far past `MAX_COORD`: refused as out of range.
const FAR: [f32; 2] = [1e20, 3e38];

/// Every value refused where a coordinate is taken.
fn bad_values() -> impl Iterator<Item = f32> {
    NON_FINITE.into_iter().chain(FAR)
}

/// `bad` in each lane of a vector whose other lane is `other`.
fn in_each_lane(bad: f32, other: f32) -> [Vec2; 2] {
    [v(bad, other), v(other, bad)]
}

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

/// The message of `err` names `bad` as `f32`'s `Display` prints it ("NaN", "inf", "-inf",
/// "100000000000000000000"), and says `what` it is.
fn names(err: &impl Display, what: &str, bad: f32) {
    let message = err.to_string();
    for part in [what, &bad.to_string()] {
        assert!(message.contains(part), "{message:?} does not name {part:?}");
    }
}

/// Asserts that `$err` is `$ty::NonFinite` (for a NaN or infinite `$bad`) or
/// `$ty::OutOfRange` (for a finite one) of `what: $what`, and that its message names both.
/// (A macro: the error types share the two variants' names and `what`, not a trait.)
macro_rules! assert_refused {
    ($err:expr, $ty:ident, $what:expr, $bad:expr) => {{
        let (err, what, bad): (_, &str, f32) = ($err, $what, $bad);
        if bad.is_finite() {
            assert!(
                matches!(&err, $ty::OutOfRange { what: w, .. } if *w == what),
                "{err:?}"
            );
        } else {
            assert!(
                matches!(&err, $ty::NonFinite { what: w, .. } if *w == what),
                "{err:?}"
            );
        }
        names(&err, what, bad);
    }};
}

/// A room of 8 × 3 cells: inside x in (1, 9), y in (1, 4); its floor is at y = 4.
fn room() -> TileMap {
    crate::drawn::map(
        "
        ##########
        #........#
        #........#
        #........#
        ##########",
        "room.txt",
    )
}

#[test]
fn tile_set_new_refuses_a_nan_infinite_negative_or_zero_size_and_a_map_a_huge_one_naming_it() {
    for bad in NON_FINITE.into_iter().chain([-1.0, 0.0]) {
        for size in in_each_lane(bad, 1.0) {
            let err = TileSet::new(size).unwrap_err();
            assert!(
                matches!(err, TileSetError::InvalidTileSize { .. }),
                "{err:?}"
            );
            names(&err, "tile size", bad);
        }
    }
    // A huge finite size makes a tile set, which no map can use: its far corner is past
    // MAX_COORD, and the map names where it would reach.
    let set = Arc::new(TileSet::new(Vec2::splat(1e30)).unwrap());
    let far = v(4.0, 3.0) * 1e30;
    let refused = MapError::OutOfRange {
        width: 4,
        height: 3,
        x: 0.0,
        y: 0.0,
        far_x: far.x,
        far_y: far.y,
    };
    let built = TileMap::new(set.clone(), 4, 3, Vec2::ZERO);
    assert_eq!(built.as_ref().err(), Some(&refused));
    let filled = TileMap::from_tiles(set, 4, 3, Vec2::ZERO, &[None; 12]);
    assert_eq!(filled.as_ref().err(), Some(&refused));
    names(&refused, "MAX_COORD", far.x);
}

#[test]
fn tile_map_new_and_from_tiles_refuse_a_nan_infinite_or_far_origin_naming_it() {
    let set = Arc::new(TileSet::new(Vec2::ONE).unwrap());
    for bad in bad_values() {
        for origin in in_each_lane(bad, 0.5) {
            let built = TileMap::new(set.clone(), 4, 3, origin).unwrap_err();
            let filled = TileMap::from_tiles(set.clone(), 4, 3, origin, &[None; 12]);
            let filled = filled.unwrap_err();
            for err in [built, filled] {
                if bad.is_finite() {
                    assert!(matches!(err, MapError::OutOfRange { .. }), "{err:?}");
                    names(&err, "4×3 cells at", bad);
                } else {
                    assert!(matches!(err, MapError::NonFiniteOrigin { .. }), "{err:?}");
                    names(&err, "map origin", bad);
                }
            }
        }
    }
}

fn circle_body(at: Vec2) -> BodyDesc {
    BodyDesc::new(at, BodyShape::circle(0.3).unwrap())
}

#[test]
fn bodies_add_refuses_a_nan_infinite_or_far_position_naming_it() {
    let mut bodies = Bodies::new();
    let kept = bodies.add(circle_body(v(1.5, 1.5))).unwrap();
    for bad in bad_values() {
        for p in in_each_lane(bad, 1.5) {
            let err = bodies.add(circle_body(p)).unwrap_err();
            assert_refused!(err, BodyError, "position", bad);
        }
    }
    // No refusal took a slot: the next body takes the one after the first.
    assert_eq!(bodies.len(), 1);
    assert_eq!(bodies.get(kept).unwrap().position(), v(1.5, 1.5));
    assert_eq!(bodies.add(circle_body(v(3.5, 1.5))).unwrap().index(), 1);
}

#[test]
fn bodies_set_position_refuses_a_nan_infinite_or_far_position_naming_it() {
    let mut bodies = Bodies::new();
    let h = bodies.add(circle_body(v(1.5, 1.5))).unwrap();
    bodies.propose(h, v(0.25, 0.0)).unwrap();
    for bad in bad_values() {
        for p in in_each_lane(bad, 1.5) {
            let err = bodies.set_position(h, p).unwrap_err();
            assert_refused!(err, BodyError, "position", bad);
            let body = bodies.get(h).unwrap();
            assert_eq!(body.position(), v(1.5, 1.5), "the body is where it was");
            assert_eq!(body.proposed_move(), v(0.25, 0.0), "and its move is kept");
        }
    }
}

fn hero_at(at: Vec2, up: Vec2, config: ControllerConfig) -> Result<Character, ControllerError> {
    let shape = CharacterShape::rect(v(0.25, 0.4)).unwrap();
    Character::new(shape, at, up, config)
}

/// A character standing on the room's floor at x = 2.
fn grounded_hero(map: &TileMap) -> Character {
    let mut hero = hero_at(v(2.0, 2.0), Vec2::NEG_Y, ControllerConfig::default()).unwrap();
    hero.move_by(map, v(0.0, 2.0), MoveOptions::default())
        .unwrap();
    assert!(hero.ground().is_some());
    hero
}

#[test]
fn character_new_refuses_a_nan_infinite_or_far_position_and_a_nan_or_infinite_up_naming_it() {
    let config = ControllerConfig::default();
    for bad in bad_values() {
        for p in in_each_lane(bad, 2.0) {
            let err = hero_at(p, Vec2::NEG_Y, config).unwrap_err();
            assert_refused!(err, ControllerError, "position", bad);
        }
    }
    // (A finite up of any size is a direction: `controller_limits.rs`.)
    for bad in NON_FINITE {
        for up in in_each_lane(bad, -1.0) {
            let err = hero_at(v(2.0, 2.0), up, config).unwrap_err();
            assert_refused!(err, ControllerError, "up", bad);
        }
    }
}

#[test]
fn character_teleport_refuses_a_nan_infinite_or_far_position_naming_it() {
    let map = room();
    let mut hero = grounded_hero(&map);
    let (at, ground) = (hero.position, hero.ground().copied());
    for bad in bad_values() {
        for p in in_each_lane(bad, 2.0) {
            let err = hero.teleport(p).unwrap_err();
            assert_refused!(err, ControllerError, "position", bad);
            assert_eq!(hero.position, at, "the character is where it was");
            assert_eq!(hero.ground().copied(), ground, "on the ground it stood on");
        }
    }
}

/// Sets one field of a controller configuration.
type SetField = fn(&mut ControllerConfig, f32);

#[test]
fn character_new_refuses_a_controller_config_field_that_is_nan_infinite_or_far_naming_it() {
    let fields: [(&str, SetField); 4] = [
        ("max_slope_degrees", |c, x| c.max_slope_degrees = x),
        ("snap_distance", |c, x| c.snap_distance = x),
        ("skin", |c, x| c.skin = x),
        ("step_height", |c, x| c.step_height = x),
    ];
    for (field, set) in fields {
        for bad in bad_values() {
            let mut config = ControllerConfig::default();
            set(&mut config, bad);
            let err = hero_at(v(2.0, 2.0), Vec2::NEG_Y, config).unwrap_err();
            assert!(
                matches!(err, ControllerError::BadConfig { field: f, .. } if f == field),
                "{err:?}"
            );
            names(&err, field, bad);
            // `validate` refuses what `new` refuses.
            let validated = config.validate().unwrap_err();
            assert_eq!(validated.to_string(), err.to_string());
        }
    }
}

#[test]
fn character_move_and_slide_refuses_a_nan_or_infinite_time_step_or_velocity_naming_it() {
    let map = room();
    let mut hero = grounded_hero(&map);
    let at = hero.position;
    // Refused: the character stays, and the velocity is left as given.
    let mut refused = |velocity: Vec2, dt: f32| {
        let mut given = velocity;
        let err = hero
            .move_and_slide(&map, &mut given, dt, MoveOptions::default())
            .unwrap_err();
        assert_eq!(hero.position, at, "the character is where it was");
        assert!(hero.ground().is_some(), "on its ground");
        assert_eq!(
            given.to_array().map(f32::to_bits),
            velocity.to_array().map(f32::to_bits)
        );
        err
    };
    for bad in NON_FINITE {
        let err = refused(v(1.0, 0.0), bad);
        assert!(
            matches!(err, ControllerError::BadTimeStep { .. }),
            "{err:?}"
        );
        names(&err, "dt", bad);
        for velocity in in_each_lane(bad, 1.0) {
            assert_refused!(
                refused(velocity, 1.0 / 60.0),
                ControllerError,
                "velocity",
                bad
            );
        }
    }
    // A finite time step or velocity too large: the move, velocity × dt, is refused.
    for far in FAR {
        let err = refused(v(1.0, 0.0), far);
        assert_refused!(err, ControllerError, "velocity × dt", far);
        let err = refused(v(far, 0.0), 0.5);
        assert_refused!(err, ControllerError, "velocity × dt", far * 0.5);
    }
}

#[test]
fn flow_field_lattice_direction_refuses_a_nan_infinite_or_far_point_naming_it() {
    let map = room();
    let nav = NavGrid::new(&map, NavConfig::default()).unwrap();
    let field = FlowField::new(&nav, &map, v(8.5, 2.5), 0.3).unwrap();
    assert!(
        field
            .lattice_direction(&nav, &map, v(1.5, 2.5))
            .unwrap()
            .is_some()
    );
    for bad in bad_values() {
        for p in in_each_lane(bad, 2.5) {
            let err = field.lattice_direction(&nav, &map, p).unwrap_err();
            assert_refused!(err, NavError, "p", bad);
        }
    }
}

/// A world with one object registered (`ObjectId(0)`), and the volume it registered with.
fn world_of_one() -> (HitWorld, Volume) {
    let mut world = HitWorld::new();
    let body = Volume::rect(v(0.5, 0.5), v(0.5, 0.5), HitTypes::ANY).unwrap();
    let object = HitObject::new(Owner(1), v(2.0, 2.0), Vec2::ONE);
    assert_eq!(world.register(object, &[], &[body]), Ok(ObjectId(0)));
    (world, body)
}

/// After refusals, `world` holds its one object still: the next takes `ObjectId(1)`.
fn holds_one_object(world: &mut HitWorld, volume: Volume) {
    assert!(world.object(ObjectId(1)).is_none());
    let next = HitObject::new(Owner(2), v(4.0, 2.0), Vec2::ONE);
    assert_eq!(world.register(next, &[], &[volume]), Ok(ObjectId(1)));
}

#[test]
fn hit_world_register_refuses_an_object_whose_position_or_size_is_nan_infinite_or_far_naming_it() {
    let (mut world, body) = world_of_one();
    for bad in bad_values() {
        for value in in_each_lane(bad, 1.0) {
            let misplaced = HitObject::new(Owner(2), value, Vec2::ONE);
            let missized = HitObject::new(Owner(2), v(4.0, 2.0), value);
            for (what, object) in [("position", misplaced), ("size", missized)] {
                let err = world.register(object, &[], &[body]).unwrap_err();
                assert_refused!(err, VolumeError, what, bad);
            }
        }
    }
    holds_one_object(&mut world, body);
}

#[test]
fn volume_circle_refuses_a_nan_infinite_or_far_radius_naming_it() {
    let (mut world, body) = world_of_one();
    let center = v(0.5, 0.5);
    for bad in bad_values() {
        let err = Volume::circle(center, bad, HitTypes::HIT).unwrap_err();
        assert_refused!(err, VolumeError, "radius", bad);
        // Built from its public fields instead, `register` refuses it the same.
        let fist = Volume {
            shape: VolumeShape::Circle(Circle::new(center, bad)),
            hit: HitTypes::HIT,
        };
        let object = HitObject::new(Owner(2), v(4.0, 2.0), Vec2::ONE);
        let err = world.register(object, &[fist], &[body]).unwrap_err();
        assert_refused!(err, VolumeError, "radius", bad);
    }
    holds_one_object(&mut world, body);
}

/// A problem whose inputs are `inputs` (every coordinate and size, in one list), answered
/// by `hit` with the time of its hit: it hits as given, and with any one input NaN or
/// infinite it hits nothing (so no NaN time either), as the primitives' docs promise.
fn hits_nothing_with_a_bad_input<const N: usize>(
    inputs: [f32; N],
    hit: impl Fn([f32; N]) -> Option<f32>,
) {
    assert!(hit(inputs).is_some(), "the problem as given hits");
    for k in 0..N {
        for bad in NON_FINITE {
            let mut spoiled = inputs;
            spoiled[k] = bad;
            assert_eq!(hit(spoiled), None, "input {k} = {bad}: {spoiled:?}");
        }
    }
}

#[test]
fn sweep_circle_circle_hits_nothing_given_a_nan_or_infinite_input() {
    // A circle at 0 moving 10 right towards one 5 away, radius sum 2: t = 0.3.
    let head_on = [0.0, 0.0, 10.0, 0.0, 5.0, 0.0, 2.0];
    hits_nothing_with_a_bad_input(head_on, |[cx, cy, mx, my, ox, oy, r]| {
        sweep_circle_circle(v(cx, cy), v(mx, my), v(ox, oy), r).map(|h| h.t)
    });
}

#[test]
fn sweep_circle_segment_hits_nothing_given_a_nan_or_infinite_input() {
    // A circle of radius 0.5 falling from y = 3 onto a floor along y = 0: t = 0.5.
    let floor = [0.0, 3.0, 0.5, 0.0, -5.0, -5.0, 0.0, 5.0, 0.0, 0.0, 1.0];
    hits_nothing_with_a_bad_input(floor, |[cx, cy, r, mx, my, ax, ay, bx, by, nx, ny]| {
        let segment = Segment::new(v(ax, ay), v(bx, by));
        sweep_circle_segment(v(cx, cy), r, v(mx, my), &segment, v(nx, ny), EndCaps::BOTH)
            .map(|h| h.t)
    });
}

#[test]
fn sweep_box_segment_hits_nothing_given_a_nan_or_infinite_input() {
    // A 1 × 2 box falling from y = 3 onto a floor along y = 0: t = 0.5.
    let floor = [0.0, 3.0, 0.5, 1.0, 0.0, -4.0, -5.0, 0.0, 5.0, 0.0, 0.0, 1.0];
    hits_nothing_with_a_bad_input(floor, |[cx, cy, hx, hy, mx, my, ax, ay, bx, by, nx, ny]| {
        let segment = Segment::new(v(ax, ay), v(bx, by));
        sweep_box_segment(
            v(cx, cy),
            v(hx, hy),
            v(mx, my),
            &segment,
            v(nx, ny),
            EndCaps::BOTH,
        )
        .map(|h| h.t)
    });
}

/// The ray from `origin` by `delta`.
fn ray_by(origin: Vec2, delta: Vec2) -> Ray {
    Ray { origin, delta }
}

#[test]
fn cast_ray_segment_hits_nothing_given_a_nan_or_infinite_input() {
    // A ray from 0 to (4, 0) across a wall along x = 2: t = 0.5.
    let wall = [0.0, 0.0, 4.0, 0.0, 2.0, -1.0, 2.0, 1.0];
    hits_nothing_with_a_bad_input(wall, |[ox, oy, dx, dy, ax, ay, bx, by]| {
        let segment = Segment::new(v(ax, ay), v(bx, by));
        cast_ray_segment(&ray_by(v(ox, oy), v(dx, dy)), &segment).map(|h| h.t)
    });
}

/// What `push` put in a new buffer: the shapes taken, and those skipped.
fn taken_and_skipped(push: impl FnOnce(&mut DebugLines)) -> (usize, usize) {
    let mut lines = DebugLines::new();
    push(&mut lines);
    (lines.len(), lines.skipped())
}

#[test]
fn debug_lines_push_ray_skips_and_counts_a_nan_or_overflowing_ray_or_hit() {
    let map = room();
    let ray = Ray::between(v(2.0, 2.5), v(12.0, 2.5));
    let hit = map.cast_ray(ray, &QueryFilter::default()).unwrap();
    let push = |ray: Ray, hit: Option<_>, tick: f32| {
        taken_and_skipped(|lines| lines.push_ray(ray, hit.as_ref(), tick, Owner(0)))
    };
    // As cast: the ray, the hit point and its normal.
    assert_eq!(push(ray, Some(hit), 0.25), (3, 0));
    // The hit is on the right wall, its normal -x: a tick of 1e38 from x = -3e38 overflows.
    let nan_point = RayHit {
        point: v(f32::NAN, 2.5),
        ..hit
    };
    let far_point = RayHit {
        point: v(-3e38, 2.5),
        ..hit
    };
    // A NaN origin, an infinite delta, an end that overflows: the ray is skipped.
    for bad in [
        ray_by(v(f32::NAN, 2.5), ray.delta),
        ray_by(ray.origin, v(f32::INFINITY, 0.0)),
        ray_by(v(3e38, 0.0), v(3e38, 0.0)),
    ] {
        assert_eq!(push(bad, None, 0.25), (0, 1), "{bad:?}");
    }
    // A NaN hit point: the ray to it, the point and its normal are skipped.
    assert_eq!(push(ray, Some(nan_point), 0.25), (0, 3));
    // A NaN or infinite tick, a normal's tip that overflows: the normal is skipped.
    for (hit, tick) in [(hit, f32::NAN), (hit, f32::INFINITY), (far_point, 1e38)] {
        assert_eq!(push(ray, Some(hit), tick), (2, 1), "{hit:?}, tick {tick}");
    }
}

#[test]
fn debug_lines_push_with_normal_skips_and_counts_a_nan_or_overflowing_segment_or_normal() {
    let floor = Segment::new(v(1.0, 4.0), v(9.0, 4.0));
    let push = |segment: Segment, normal: Vec2, tick: f32| {
        taken_and_skipped(|lines| {
            lines.push_with_normal(DebugKind::ActiveSegment, segment, normal, tick, Owner(0));
        })
    };
    assert_eq!(push(floor, Vec2::NEG_Y, 0.25), (2, 0));
    // A NaN or infinite end: the segment and its normal, from its middle, are skipped.
    for end in [v(f32::NAN, 4.0), v(9.0, f32::INFINITY)] {
        let segment = Segment::new(floor.a, end);
        assert_eq!(push(segment, Vec2::NEG_Y, 0.25), (0, 2), "{segment:?}");
    }
    // A NaN or infinite normal or tick, a normal's tip that overflows (1e38 below a
    // segment at y = -3e38): the normal is skipped.
    let low = Segment::new(v(1.0, -3e38), v(9.0, -3e38));
    for (segment, normal, tick) in [
        (floor, v(0.0, f32::NAN), 0.25),
        (floor, v(0.0, f32::NEG_INFINITY), 0.25),
        (floor, Vec2::NEG_Y, f32::NAN),
        (floor, Vec2::NEG_Y, f32::INFINITY),
        (low, Vec2::NEG_Y, 1e38),
    ] {
        let pushed = push(segment, normal, tick);
        assert_eq!(pushed, (1, 1), "{segment:?}, normal {normal}, tick {tick}");
    }
}

/// A one-way platform's top along y = 3, from x = 6 to 8, of owner 9.
fn platform() -> TemporarySegment {
    TemporarySegment {
        segment: Segment::new(v(6.0, 3.0), v(8.0, 3.0)),
        normal: Vec2::NEG_Y,
        flags: SegmentFlags::ONE_WAY,
        owner: Owner(9),
        velocity: v(0.5, 0.0),
    }
}

/// The platform with `bad` in each coordinate of its segment's ends in turn.
fn spoiled_platforms(bad: f32) -> impl Iterator<Item = TemporarySegment> {
    let Segment { a, b } = platform().segment;
    in_each_lane(bad, a.y)
        .map(|a| Segment::new(a, b))
        .into_iter()
        .chain(in_each_lane(bad, b.y).map(|b| Segment::new(a, b)))
        .map(|segment| TemporarySegment {
            segment,
            ..platform()
        })
}

#[test]
fn tile_map_add_temporary_refuses_a_nan_or_infinite_end_point_naming_it() {
    let mut map = room();
    map.add_temporary(platform()).unwrap();
    for bad in NON_FINITE {
        for spoiled in spoiled_platforms(bad) {
            let err = map.add_temporary(spoiled).unwrap_err();
            assert!(
                matches!(
                    err,
                    MapError::Temporary(TemporaryError::NonFinite {
                        owner: Owner(9),
                        ..
                    })
                ),
                "{err:?}"
            );
            names(&err, "temporary segment", bad);
            assert_eq!(
                map.temporaries(),
                [platform()],
                "the map holds what it held"
            );
        }
    }
}

/// Snapshots read from CBOR, which holds NaN and the infinities (JSON holds neither).
#[cfg(feature = "serde")]
mod snapshots {
    use ciborium::Value;
    use serde::Serialize;
    use serde::de::DeserializeOwned;

    use super::*;

    /// The entry of `value` at `key`: a map's field, or an array's element (`"0"`, `"1"`…).
    fn at<'a>(value: &'a mut Value, key: &str) -> &'a mut Value {
        match value {
            Value::Array(items) => &mut items[key.parse::<usize>().unwrap()],
            Value::Map(entries) => entries
                .iter_mut()
                .find_map(|(k, v)| (k.as_text() == Some(key)).then_some(v))
                .unwrap_or_else(|| panic!("no field {key:?}")),
            other => panic!("{other:?} has no entry {key:?}"),
        }
    }

    /// `saved` written as CBOR with the number at `path` replaced by `bad`, read back as a
    /// `T`: the message of the error it is refused with.
    fn refused<T: Serialize + DeserializeOwned + std::fmt::Debug>(
        saved: &T,
        path: &[&str],
        bad: f32,
    ) -> String {
        let mut value = Value::serialized(saved).unwrap();
        let number = path.iter().fold(&mut value, |value, key| at(value, key));
        assert!(number.is_float(), "{number:?} at {path:?}");
        *number = Value::Float(f64::from(bad));
        let mut bytes = Vec::new();
        ciborium::into_writer(&value, &mut bytes).unwrap();
        match ciborium::from_reader::<T, _>(bytes.as_slice()) {
            Err(ciborium::de::Error::Semantic(_, message)) => message,
            read => panic!("{path:?} = {bad}: {read:?}"),
        }
    }

    #[test]
    fn a_character_deserialized_with_a_nan_infinite_or_far_position_is_refused_naming_it() {
        let hero = grounded_hero(&room());
        for bad in bad_values() {
            for lane in ["0", "1"] {
                let message = refused(&hero, &["position", lane], bad);
                names(&message, "the character: character position", bad);
            }
        }
    }

    /// The room's edits: the platform, and no tile changed.
    fn edits() -> tileslide::MapEdits {
        let mut map = room();
        map.add_temporary(platform()).unwrap();
        map.edits()
    }

    /// The paths to each coordinate of the saved platform's ends.
    const PLATFORM_ENDS: [[&str; 5]; 4] = [
        ["temporaries", "0", "segment", "a", "0"],
        ["temporaries", "0", "segment", "a", "1"],
        ["temporaries", "0", "segment", "b", "0"],
        ["temporaries", "0", "segment", "b", "1"],
    ];

    #[test]
    fn map_edits_deserialized_with_a_nan_infinite_or_far_temporary_end_point_are_refused() {
        let edits = edits();
        for path in PLATFORM_ENDS {
            for bad in NON_FINITE {
                let message = refused(&edits, &path, bad);
                for part in ["temporary segment 0", "non-finite end point"] {
                    assert!(message.contains(part), "{message:?} does not say {part:?}");
                }
            }
            for far in FAR {
                names(&refused(&edits, &path, far), "temporary segment 0", far);
            }
        }
    }

    #[test]
    fn map_edits_deserialized_with_a_nan_or_infinite_temporary_end_point_are_refused_naming_it() {
        let edits = edits();
        for path in PLATFORM_ENDS {
            for bad in NON_FINITE {
                names(&refused(&edits, &path, bad), "temporary segment 0", bad);
            }
        }
    }
}
