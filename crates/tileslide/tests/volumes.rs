//! Attack and vulnerability volumes: Replica Island's scenarios (type matching, "any" on
//! either side, the first matching attack volume, mirroring, report order, refusal), the
//! corner case its bounding circle got wrong, swings, swept projectiles, and a model test of
//! both broadphases against an all-pairs reference written independently of the library.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

#[cfg(feature = "aim")]
use glam::DVec2;
use proptest::prelude::*;
use tileslide::{
    Facing, HitEvent, HitObject, HitTypes, HitWorld, ObjectId, Owner, TeamRule, Vec2, Volume,
    VolumeError, VolumeShape, broadphase::PairMethod,
};

fn circle(x: f32, y: f32, r: f32, hit: HitTypes) -> Volume {
    Volume::circle(Vec2::new(x, y), r, hit).unwrap()
}

/// The rectangle centred at (`x`, `y`) with half extents (`hx`, `hy`).
fn rect(x: f32, y: f32, hx: f32, hy: f32, hit: HitTypes) -> Volume {
    Volume::rect(Vec2::new(x, y), Vec2::new(hx, hy), hit).unwrap()
}

fn object(owner: u64, x: f32, y: f32) -> HitObject {
    HitObject {
        team: owner as u32,
        ..HitObject::new(Owner(owner), Vec2::new(x, y), Vec2::ONE)
    }
}

/// A unit body accepting `accepts`.
fn body(accepts: HitTypes) -> [Volume; 1] {
    [rect(0.5, 0.5, 0.5, 0.5, accepts)]
}

fn hits(world: &mut HitWorld) -> Vec<(u32, u32, HitTypes, bool)> {
    world
        .detect(&mut TeamRule)
        .iter()
        .map(|e| (e.attacker.0, e.victim.0, e.hit_type, e.accepted))
        .collect()
}

#[test]
fn an_attack_hits_only_a_vulnerability_that_accepts_its_type() {
    let mut world = HitWorld::new();
    world.begin_frame();
    let fist = [circle(1.2, 0.5, 0.3, HitTypes::HIT)];
    world.register(object(1, 0.0, 0.0), &fist, &[]).unwrap();
    world
        .register(object(2, 1.2, 0.0), &[], &body(HitTypes::COLLECT))
        .unwrap();
    assert!(hits(&mut world).is_empty(), "a coin does not take a punch");
    world.begin_frame();
    world.register(object(1, 0.0, 0.0), &fist, &[]).unwrap();
    world
        .register(
            object(2, 1.2, 0.0),
            &[],
            &body(HitTypes::HIT | HitTypes::DEATH),
        )
        .unwrap();
    assert_eq!(hits(&mut world), [(0, 1, HitTypes::HIT, true)]);
}

#[test]
fn any_matches_on_either_side_and_the_event_names_the_type_dealt() {
    let mut world = HitWorld::new();
    world.begin_frame();
    // A collector touching everything, and a coin.
    world
        .register(object(1, 0.0, 0.0), &body(HitTypes::ANY), &[])
        .unwrap();
    world
        .register(object(2, 0.5, 0.0), &[], &body(HitTypes::COLLECT))
        .unwrap();
    // A spike dealing HIT to a body accepting anything.
    world
        .register(object(3, 10.0, 0.0), &body(HitTypes::HIT), &[])
        .unwrap();
    world
        .register(object(4, 10.5, 0.0), &[], &body(HitTypes::ANY))
        .unwrap();
    assert_eq!(
        hits(&mut world),
        [(0, 1, HitTypes::COLLECT, true), (2, 3, HitTypes::HIT, true)]
    );
}

#[test]
fn the_first_attack_volume_in_list_order_that_matches_gives_the_hit() {
    let mut world = HitWorld::new();
    world.begin_frame();
    let attacks = [
        circle(5.0, 0.5, 0.2, HitTypes::DEATH),   // out of reach
        circle(1.1, 0.5, 0.2, HitTypes::COLLECT), // in reach, not accepted
        circle(1.2, 0.5, 0.3, HitTypes::LAUNCH),  // the first that counts
        circle(1.2, 0.5, 0.3, HitTypes::HIT),     // would count, but comes later
    ];
    world.register(object(1, 0.0, 0.0), &attacks, &[]).unwrap();
    world
        .register(
            object(2, 1.0, 0.0),
            &[],
            &body(HitTypes::HIT | HitTypes::LAUNCH | HitTypes::DEATH),
        )
        .unwrap();
    assert_eq!(hits(&mut world), [(0, 1, HitTypes::LAUNCH, true)]);
}

#[test]
fn volumes_are_mirrored_when_the_object_faces_the_other_way() {
    // A sword reaching right of a 1 × 1 hero; targets on both sides.
    let sword = [rect(1.5, 0.5, 0.5, 0.1, HitTypes::HIT)];
    for (flip_x, struck) in [(false, 2u32), (true, 1)] {
        let mut world = HitWorld::new();
        world.begin_frame();
        let hero = HitObject {
            facing: Facing {
                flip_x,
                flip_y: false,
            },
            ..object(1, 5.0, 0.0)
        };
        world.register(hero, &sword, &[]).unwrap();
        world
            .register(object(2, 3.5, 0.0), &[], &body(HitTypes::HIT))
            .unwrap(); // left
        world
            .register(object(3, 6.5, 0.0), &[], &body(HitTypes::HIT))
            .unwrap(); // right
        let got = hits(&mut world);
        assert_eq!(got.len(), 1, "facing left: {flip_x}: {got:?}");
        assert_eq!(got[0].1, struck);
    }
}

#[test]
fn events_come_pair_by_pair_in_registration_order_both_directions() {
    // Three brawlers overlapping, each punching and vulnerable; registered right to left,
    // so x order and registration order differ.
    let fist = body(HitTypes::HIT);
    let mut world = HitWorld::new();
    world.begin_frame();
    for (owner, x) in [(1, 1.0), (2, 0.5), (3, 0.0)] {
        world.register(object(owner, x, 0.0), &fist, &fist).unwrap();
    }
    let order: Vec<_> = hits(&mut world).iter().map(|h| (h.0, h.1)).collect();
    assert_eq!(order, [(0, 1), (1, 0), (0, 2), (2, 0), (1, 2), (2, 1)]);
}

#[test]
fn the_victim_decides_and_the_attacker_learns_it() {
    let fist = body(HitTypes::HIT);
    let mut world = HitWorld::new();
    world.begin_frame();
    let a = world.register(object(1, 0.0, 0.0), &fist, &[]).unwrap();
    let b = world
        .register(
            HitObject {
                invulnerable: true,
                ..object(2, 0.5, 0.0)
            },
            &[],
            &fist,
        )
        .unwrap();
    let c = world
        .register(
            HitObject {
                team: 1,
                ..object(3, 0.5, 0.5)
            },
            &[],
            &fist,
        )
        .unwrap();
    let d = world.register(object(4, 0.0, 0.5), &[], &fist).unwrap();
    // Team rule: invulnerable and same-team victims refuse.
    let got = world.detect(&mut TeamRule).to_vec();
    let accepted =
        |v: ObjectId, got: &[HitEvent]| got.iter().find(|e| e.victim == v).unwrap().accepted;
    assert!(!accepted(b, &got) && !accepted(c, &got) && accepted(d, &got));
    // A callback: the victim owned by 4 refuses, and is asked only about hits it received.
    let mut asked = Vec::new();
    let got = world
        .detect(
            &mut |attacker: &HitObject, victim: &HitObject, _: HitTypes| {
                asked.push((attacker.owner.0, victim.owner.0));
                victim.owner != Owner(4)
            },
        )
        .to_vec();
    assert_eq!(asked, [(1, 2), (1, 3), (1, 4)]);
    assert!(accepted(b, &got) && accepted(c, &got) && !accepted(d, &got));
    assert!(got.iter().all(|e| e.attacker == a));
}

#[test]
fn a_volume_reaching_into_the_corner_is_not_missed() {
    // Replica Island's bounding circle, radius max(w, h) / 2 about the object's centre,
    // misses this: a 1 × 1 object whose attack box sits at its top-right corner, beyond
    // the circle, touching a victim diagonally.
    let claw = [rect(1.25, 1.25, 0.25, 0.25, HitTypes::HIT)];
    let mut world = HitWorld::new();
    world.begin_frame();
    world.register(object(1, 0.0, 0.0), &claw, &[]).unwrap();
    world
        .register(object(2, 1.4, 1.4), &[], &body(HitTypes::HIT))
        .unwrap();
    assert_eq!(hits(&mut world), [(0, 1, HitTypes::HIT, true)]);
    let bounds = world.bounding_circle(ObjectId(0)).unwrap();
    for corner in [Vec2::new(1.0, 1.0), Vec2::new(1.5, 1.5)] {
        assert!(corner.distance(bounds.center) <= bounds.radius);
    }
}

#[test]
fn a_swing_hits_each_victim_once_until_it_ends() {
    let blade = body(HitTypes::HIT);
    let frame = |world: &mut HitWorld, swing: Option<u64>| {
        world.begin_frame();
        let hero = HitObject {
            swing,
            ..object(1, 0.0, 0.0)
        };
        world.register(hero, &blade, &[]).unwrap();
        world.register(object(2, 0.5, 0.0), &[], &blade).unwrap();
        hits(world).len()
    };
    let mut world = HitWorld::new();
    assert_eq!(frame(&mut world, Some(7)), 1);
    assert_eq!(frame(&mut world, Some(7)), 0, "same swing, same victim");
    assert_eq!(frame(&mut world, None), 1, "no swing: hits every frame");
    assert_eq!(frame(&mut world, Some(7)), 1, "swing 7 ended: a new one");
    assert_eq!(frame(&mut world, Some(8)), 1, "another swing");
}

#[test]
fn a_refused_hit_does_not_use_up_the_swing() {
    let blade = body(HitTypes::HIT);
    let mut world = HitWorld::new();
    for (invulnerable, expected) in [(true, false), (false, true), (false, false)] {
        world.begin_frame();
        let hero = HitObject {
            swing: Some(1),
            ..object(1, 0.0, 0.0)
        };
        world.register(hero, &blade, &[]).unwrap();
        let victim = HitObject {
            invulnerable,
            ..object(2, 0.5, 0.0)
        };
        world.register(victim, &[], &blade).unwrap();
        let accepted = hits(&mut world).iter().any(|h| h.3);
        assert_eq!(accepted, expected);
    }
}

#[test]
fn a_bullet_ten_times_its_size_per_frame_cannot_pass_through() {
    let bullet = [circle(0.0, 0.0, 0.05, HitTypes::HIT)];
    let mut world = HitWorld::new();
    world.begin_frame();
    // From x = -0.6 to x = 0.4 this frame (+1.0), through a target 0.1 thick at x = 0.
    let shot = HitObject {
        motion: Vec2::new(1.0, 0.0),
        ..HitObject::new(Owner(1), Vec2::new(0.4, 0.5), Vec2::ZERO)
    };
    world.register(shot, &bullet, &[]).unwrap();
    let wall = [rect(0.05, 0.5, 0.05, 0.5, HitTypes::HIT)];
    world
        .register(HitObject::new(Owner(2), Vec2::ZERO, Vec2::ONE), &[], &wall)
        .unwrap();
    assert_eq!(hits(&mut world).len(), 1);
    // The target moving too: they pass each other in the frame, meeting in the middle.
    world.begin_frame();
    world.register(shot, &bullet, &[]).unwrap();
    let dodging = HitObject {
        motion: Vec2::new(-1.0, 0.0),
        ..HitObject::new(Owner(2), Vec2::new(-0.9, 0.0), Vec2::ONE)
    };
    world.register(dodging, &[], &wall).unwrap();
    assert_eq!(hits(&mut world).len(), 1);
}

#[test]
fn volumes_and_objects_beyond_max_coord_are_refused_by_register_too() {
    use tileslide::{Aabb, Circle, limits::MAX_COORD};
    let far = |what: &'static str| move |e: VolumeError| matches!(e, VolumeError::OutOfRange { what: w, .. } if w == what);
    assert!(Volume::circle(Vec2::new(1e20, 0.0), 1.0, HitTypes::HIT).is_err_and(far("center")));
    assert!(Volume::circle(Vec2::ZERO, 3e38, HitTypes::HIT).is_err_and(far("radius")));
    assert!(
        Volume::rect(Vec2::ZERO, Vec2::splat(3e38), HitTypes::HIT).is_err_and(far("half extents"))
    );
    assert!(Volume::rect(Vec2::splat(3e38), Vec2::ONE, HitTypes::HIT).is_err_and(far("center")));
    assert!(
        Volume::rect(Vec2::splat(MAX_COORD), Vec2::splat(4.0), HitTypes::HIT)
            .is_err_and(far("max"))
    );
    assert!(Volume::rect(Vec2::ZERO, Vec2::splat(MAX_COORD), HitTypes::HIT).is_ok());
    // Built from the public fields, the check still applies.
    let huge = Volume {
        shape: VolumeShape::Circle(Circle::new(Vec2::ZERO, f32::MAX)),
        hit: HitTypes::HIT,
    };
    assert!(huge.check().is_err_and(far("radius")));
    let inside_out = Volume {
        shape: VolumeShape::Rect(Aabb {
            min: Vec2::ONE,
            max: Vec2::ZERO,
        }),
        hit: HitTypes::HIT,
    };
    assert!(matches!(
        inside_out.check(),
        Err(VolumeError::InvertedRect { .. })
    ));
    // Objects: position, start of the frame's move, size.
    let at = |x: f32| object(1, x, 0.0);
    assert!(at(3e38).check().is_err_and(far("position")));
    let flung = HitObject {
        motion: Vec2::new(-3e38, 0.0),
        ..at(0.0)
    };
    assert!(flung.check().is_err_and(far("start")));
    let wide = HitObject {
        size: Vec2::new(1e30, 1.0),
        ..at(0.0)
    };
    assert!(wide.check().is_err_and(far("size")));
    let nan = HitObject {
        motion: Vec2::new(f32::NAN, 0.0),
        ..at(0.0)
    };
    assert!(matches!(
        nan.check(),
        Err(VolumeError::NonFinite { what: "motion", .. })
    ));
    // At the edge of the range two overlapping boxes hit, whatever the broadphase (a move
    // across the whole range included); at 3e38 (where a box's centre overflowed and the
    // pair was missed) register refuses the object, naming the value, and the world is
    // unchanged.
    for broadphase in [PairMethod::SweepAndPrune, PairMethod::UniformGrid] {
        let mut world = HitWorld::with_broadphase(broadphase);
        world.begin_frame();
        let x = MAX_COORD - 1.0;
        world
            .register(object(1, x, 0.0), &body(HitTypes::HIT), &[])
            .unwrap();
        world
            .register(object(2, x, 0.0), &[], &body(HitTypes::HIT))
            .unwrap();
        assert_eq!(hits(&mut world).len(), 1, "{broadphase:?} at x = {x}");
        world.begin_frame();
        let refused = world.register(object(1, 3e38, 0.0), &body(HitTypes::HIT), &[]);
        assert!(refused.is_err_and(far("position")), "{broadphase:?}");
        let refused = world.register(object(2, 0.0, 0.0), &[], &[huge]);
        assert!(refused.is_err_and(far("radius")), "{broadphase:?}");
        assert!(hits(&mut world).is_empty(), "{broadphase:?}");
        world.begin_frame();
        let across = HitObject {
            motion: Vec2::new(2.0 * MAX_COORD - 2.0, 0.0),
            ..object(1, MAX_COORD - 1.0, 0.0)
        };
        let a = world.register(across, &body(HitTypes::HIT), &[]).unwrap();
        let b = world
            .register(object(2, 0.0, 0.0), &[], &body(HitTypes::HIT))
            .unwrap();
        // A refused object takes no id: the next one registered gets the one it would have.
        assert!(world.register(object(3, 0.0, 0.0), &[huge], &[]).is_err());
        let c = world.register(object(4, 5.0, 5.0), &[], &[]).unwrap();
        assert_eq!((a.0, b.0, c.0), (0, 1, 2));
        assert_eq!(
            hits(&mut world),
            [(0, 1, HitTypes::HIT, true)],
            "{broadphase:?}"
        );
    }
}

// ---- Model test: both broadphases against an independent all-pairs reference. ----

/// A volume placed in the world, for the reference.
#[derive(Clone, Copy, Debug)]
enum Shape {
    Circle(Vec2, f32),
    Box(Vec2, Vec2),
}

fn placed(v: &Volume, o: &HitObject) -> Shape {
    let m = |p: Vec2| {
        Vec2::new(
            if o.facing.flip_x { o.size.x - p.x } else { p.x },
            if o.facing.flip_y { o.size.y - p.y } else { p.y },
        )
    };
    match v.shape {
        VolumeShape::Circle(c) => Shape::Circle(o.position + m(c.center), c.radius),
        VolumeShape::Rect(b) => {
            let (a, c) = (m(b.min), m(b.max));
            Shape::Box(o.position + a.min(c), o.position + a.max(c))
        }
        // The model knows circles and rects only: a volume of another shape cannot be
        // checked against it.
        other => panic!("a volume shape the model does not know: {other:?}"),
    }
}

fn overlap(a: Shape, b: Shape) -> bool {
    match (a, b) {
        (Shape::Circle(p, r), Shape::Circle(q, s)) => p.distance_squared(q) <= (r + s) * (r + s),
        (Shape::Circle(p, r), Shape::Box(lo, hi)) | (Shape::Box(lo, hi), Shape::Circle(p, r)) => {
            p.clamp(lo, hi).distance_squared(p) <= r * r
        }
        (Shape::Box(a0, a1), Shape::Box(b0, b1)) => a0.cmple(b1).all() && b0.cmple(a1).all(),
    }
}

type Registered = (HitObject, Vec<Volume>, Vec<Volume>);

fn reference(objects: &[Registered]) -> Vec<(u32, u32, HitTypes)> {
    let mut out = Vec::new();
    let direction = |a: usize, v: usize| {
        let (oa, attacks, _) = &objects[a];
        let (ov, _, vulnerable) = &objects[v];
        attacks.iter().find_map(|x| {
            vulnerable.iter().find_map(|y| {
                let dealt = x.hit & y.hit;
                (!dealt.is_empty() && overlap(placed(x, oa), placed(y, ov))).then_some(dealt)
            })
        })
    };
    for i in 0..objects.len() {
        for j in i + 1..objects.len() {
            for (a, v) in [(i, j), (j, i)] {
                if let Some(t) = direction(a, v) {
                    out.push((a as u32, v as u32, t));
                }
            }
        }
    }
    out
}

fn hit_types() -> impl Strategy<Value = HitTypes> {
    prop_oneof![
        3 => (0u32..4).prop_map(|b| HitTypes::from_bits(1 << b)),
        1 => Just(HitTypes::ANY),
        1 => (1u32..16).prop_map(HitTypes::from_bits),
    ]
}

fn volume() -> impl Strategy<Value = Volume> {
    // Coordinates on a 1/8 lattice, so touching is exact and common.
    let q = || (-8i32..24).prop_map(|v| v as f32 / 8.0);
    prop_oneof![
        (q(), q(), 0u32..8, hit_types()).prop_map(|(x, y, r, t)| circle(x, y, r as f32 / 8.0, t)),
        // Corner (x, y), size (w/8, h/8): the centre and half extents are on a 1/16
        // lattice, so the corners are exact.
        (q(), q(), 0u32..12, 0u32..12, hit_types()).prop_map(|(x, y, w, h, t)| {
            let (hx, hy) = (w as f32 / 16.0, h as f32 / 16.0);
            rect(x + hx, y + hy, hx, hy, t)
        }),
    ]
}

fn objects() -> impl Strategy<Value = Vec<Registered>> {
    let one = (
        0i32..48,
        0i32..48,
        any::<bool>(),
        any::<bool>(),
        prop::collection::vec(volume(), 0..3),
        prop::collection::vec(volume(), 0..3),
    )
        .prop_map(|(x, y, fx, fy, attack, vulnerable)| {
            let o = HitObject {
                facing: Facing {
                    flip_x: fx,
                    flip_y: fy,
                },
                ..HitObject::new(
                    Owner(0),
                    Vec2::new(x as f32 / 8.0, y as f32 / 8.0),
                    Vec2::new(1.0, 2.0),
                )
            };
            (o, attack, vulnerable)
        });
    prop::collection::vec(one, 0..40)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 500, ..ProptestConfig::default() })]

    #[test]
    fn both_broadphases_find_exactly_the_all_pairs_hits(objects in objects()) {
        let expected = reference(&objects);
        for kind in [PairMethod::SweepAndPrune, PairMethod::UniformGrid] {
            let mut world = HitWorld::with_broadphase(kind);
            // Two frames, so the sweep order kept from the first is exercised too.
            for _ in 0..2 {
                world.begin_frame();
                for (o, a, v) in &objects {
                    world.register(*o, a, v).unwrap();
                }
                let got: Vec<_> = world
                    .detect(&mut |_: &HitObject, _: &HitObject, _: HitTypes| true)
                    .iter()
                    .map(|e| (e.attacker.0, e.victim.0, e.hit_type))
                    .collect();
                prop_assert_eq!(&got, &expected, "{:?}", kind);
            }
            for id in 0..objects.len() as u32 {
                let (o, a, v) = &objects[id as usize];
                if let Some(bounds) = world.bounding_circle(ObjectId(id)) {
                    for shape in a.iter().chain(v).map(|x| placed(x, o)) {
                        let far = match shape {
                            Shape::Circle(p, r) => p.distance(bounds.center) + r,
                            Shape::Box(lo, hi) => (lo - bounds.center).abs().max((hi - bounds.center).abs()).length(),
                        };
                        prop_assert!(far <= bounds.radius, "volume outside the bounding circle");
                    }
                }
            }
        }
    }

    /// A moving volume meets a still one exactly when some instant of the frame overlaps:
    /// never missed (every sampled overlap is reported) and never invented (a reported hit
    /// is within the sampling step of an overlap).
    #[test]
    fn swept_volumes_meet_what_some_instant_of_the_frame_overlaps(
        a in volume(),
        b in volume(),
        from in (-40i32..40, -40i32..40),
        motion in (-80i32..80, -80i32..80),
    ) {
        let (a, b) = (Volume { hit: HitTypes::HIT, ..a }, Volume { hit: HitTypes::HIT, ..b });
        let motion = Vec2::new(motion.0 as f32, motion.1 as f32) / 8.0;
        let end = Vec2::new(from.0 as f32, from.1 as f32) / 8.0 + motion;
        let shooter = HitObject { motion, ..HitObject::new(Owner(1), end, Vec2::ONE) };
        let target = HitObject { team: 1, ..HitObject::new(Owner(2), Vec2::ZERO, Vec2::ONE) };
        let mut world = HitWorld::new();
        world.begin_frame();
        world.register(shooter, &[a], &[]).unwrap();
        world.register(target, &[], &[b]).unwrap();
        let reported = !world.detect(&mut TeamRule).is_empty();
        const STEPS: usize = 2000;
        let tb = placed(&b, &target);
        let grown = |s: Shape, by: f32| match s {
            Shape::Circle(p, r) => Shape::Circle(p, r + by),
            Shape::Box(lo, hi) => Shape::Box(lo - Vec2::splat(by), hi + Vec2::splat(by)),
        };
        let step = motion.length() / STEPS as f32;
        let mut sampled = false;
        let mut near = false;
        for k in 0..=STEPS {
            let at = HitObject { position: end - motion + motion * (k as f32 / STEPS as f32), ..shooter };
            let ta = placed(&a, &at);
            sampled |= overlap(ta, tb);
            near |= overlap(grown(ta, step + 1e-4), tb);
        }
        if sampled {
            prop_assert!(reported, "an overlap during the frame was missed");
        }
        if reported {
            prop_assert!(near, "a hit was reported with no overlap near any instant");
        }
    }
}

// ---- When and where: times of impact and contact points. ----

/// `s` grown by `by` on every side.
fn grown(s: Shape, by: f32) -> Shape {
    match s {
        Shape::Circle(p, r) => Shape::Circle(p, r + by),
        Shape::Box(lo, hi) => Shape::Box(lo - Vec2::splat(by), hi + Vec2::splat(by)),
    }
}

/// Whether `p` lies in `s` grown by `by`.
fn holds(s: Shape, p: Vec2, by: f32) -> bool {
    match grown(s, by) {
        Shape::Circle(c, r) => c.distance(p) <= r,
        Shape::Box(lo, hi) => lo.cmple(p).all() && p.cmple(hi).all(),
    }
}

/// `o` where it is at time `s` of its move.
fn at_time(o: &HitObject, s: f32) -> HitObject {
    HitObject {
        position: o.position - o.motion + o.motion * s,
        ..*o
    }
}

#[test]
fn events_stay_until_the_next_detect_and_name_the_owners() {
    let fist = body(HitTypes::HIT);
    let mut world = HitWorld::new();
    world.begin_frame();
    world.register(object(7, 0.0, 0.0), &fist, &[]).unwrap();
    world.register(object(9, 0.5, 0.0), &[], &fist).unwrap();
    let got = world.detect(&mut TeamRule).to_vec();
    assert_eq!(got.len(), 1);
    assert_eq!(
        (got[0].attacker_owner, got[0].victim_owner),
        (Owner(7), Owner(9))
    );
    // A new frame keeps them (its ids would name new objects; the owners still say who).
    world.begin_frame();
    world.register(object(3, 50.0, 0.0), &[], &[]).unwrap();
    assert_eq!(world.events(), &got[..]);
    // Drained, they are gone; the next detect replaces them in any case.
    assert_eq!(world.drain_events().collect::<Vec<_>>(), got);
    assert!(world.events().is_empty());
    world.begin_frame();
    world.register(object(7, 0.0, 0.0), &fist, &[]).unwrap();
    world.register(object(9, 0.5, 0.0), &[], &fist).unwrap();
    world.detect(&mut TeamRule);
    world.begin_frame();
    world.detect(&mut TeamRule);
    assert!(
        world.events().is_empty(),
        "an empty frame's detect has no events"
    );
}

#[test]
fn the_least_t_names_the_first_victim_a_fireball_reaches() {
    // A fireball flying 12 to the right in one frame through three slimes of different
    // sizes, registered out of order along its path. Every slime is hit; their order
    // along the path is the order of `t`, and each point is on the slime's near side.
    let ball = [circle(0.0, 0.0, 0.25, HitTypes::HIT)];
    let shot = HitObject {
        team: 1,
        motion: Vec2::new(12.0, 0.0),
        ..HitObject::new(Owner(100), Vec2::new(12.0, 0.0), Vec2::ZERO)
    };
    let mut world = HitWorld::new();
    world.begin_frame();
    world.register(shot, &ball, &[]).unwrap();
    // Slime k: a disc of radius r at x; its near side at x − r.
    let slimes = [(1, 9.0, 0.5), (2, 3.0, 1.0), (3, 6.0, 2.5)];
    for (owner, x, r) in slimes {
        let slime = HitObject::new(Owner(owner), Vec2::new(x, 0.0), Vec2::ZERO);
        world
            .register(slime, &[], &[circle(0.0, 0.0, r, HitTypes::ANY)])
            .unwrap();
    }
    let hits = world.detect(&mut TeamRule).to_vec();
    assert_eq!(hits.len(), 3);
    let mut by_t = hits.clone();
    by_t.sort_by(|a, b| a.t.total_cmp(&b.t));
    let order: Vec<_> = by_t.iter().map(|h| h.victim_owner.0).collect();
    // Near sides at 2 (slime 2), 3.5 (slime 3), 8.5 (slime 1).
    assert_eq!(order, [2, 3, 1]);
    for h in &hits {
        let (_, x, r) = slimes[slimes.iter().position(|s| s.0 == h.victim_owner.0).unwrap()];
        // The ball's front (its centre + 0.25) reaches x − r at t = (x − r − 0.25) / 12.
        let t = (x - r - 0.25) / 12.0;
        assert!((h.t - t).abs() < 1e-6, "{h:?}: t should be {t}");
        assert!(h.point.distance(Vec2::new(x - r, 0.0)) < 1e-5, "{h:?}");
    }
}

#[test]
fn of_the_victims_volumes_the_first_touched_gives_the_hit() {
    // A bolt from the left meets the victim's shield (accepts HIT, on the left) before its
    // head (accepts DEATH, on the right), though the head is listed first: the event is the
    // shield's, with the shield's types.
    let bolt = [circle(0.0, 0.0, 0.1, HitTypes::HIT | HitTypes::DEATH)];
    let shot = HitObject {
        team: 1,
        motion: Vec2::new(10.0, 0.0),
        ..HitObject::new(Owner(1), Vec2::new(5.0, 0.5), Vec2::ZERO)
    };
    let victim = [
        rect(1.5, 0.5, 0.25, 0.5, HitTypes::DEATH), // head, x in [1.25, 1.75]
        rect(0.25, 0.5, 0.25, 0.5, HitTypes::HIT),  // shield, x in [0, 0.5]
    ];
    let mut world = HitWorld::new();
    world.begin_frame();
    world.register(shot, &bolt, &[]).unwrap();
    world
        .register(
            HitObject::new(Owner(2), Vec2::ZERO, Vec2::ONE),
            &[],
            &victim,
        )
        .unwrap();
    let hits = world.detect(&mut TeamRule).to_vec();
    assert_eq!(hits.len(), 1);
    assert_eq!(hits[0].hit_type, HitTypes::HIT);
    // The bolt's front reaches x = 0 when its centre is at −0.1: 4.9 of the 10.
    assert!((hits[0].t - 0.49).abs() < 1e-6, "{:?}", hits[0]);
    assert!(hits[0].point.distance(Vec2::new(0.0, 0.5)) < 1e-5);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    /// Both objects moving: the reported `t` is no later than the first overlap a fine
    /// sub-stepping of the frame finds, the volumes touch at `t` (to within rounding), and
    /// the point lies in both there. With no hit reported, no sample overlaps.
    #[test]
    fn the_time_of_impact_and_point_agree_with_sub_stepping(
        a in volume(),
        b in volume(),
        from in (-40i32..40, -40i32..40),
        motion in (-80i32..80, -80i32..80),
        target_motion in (-40i32..40, -40i32..40),
    ) {
        let (a, b) = (Volume { hit: HitTypes::HIT, ..a }, Volume { hit: HitTypes::HIT, ..b });
        let eighths = |(x, y): (i32, i32)| Vec2::new(x as f32, y as f32) / 8.0;
        let (motion, target_motion) = (eighths(motion), eighths(target_motion));
        let shooter = HitObject {
            motion,
            ..HitObject::new(Owner(1), eighths(from) + motion, Vec2::ONE)
        };
        let target = HitObject {
            team: 1,
            motion: target_motion,
            ..HitObject::new(Owner(2), target_motion, Vec2::ONE)
        };
        let mut world = HitWorld::new();
        world.begin_frame();
        world.register(shooter, &[a], &[]).unwrap();
        world.register(target, &[], &[b]).unwrap();
        let hit = world.detect(&mut TeamRule).first().copied();
        const STEPS: usize = 2000;
        let first_overlap = (0..=STEPS).map(|k| k as f32 / STEPS as f32).find(|&s| {
            overlap(placed(&a, &at_time(&shooter, s)), placed(&b, &at_time(&target, s)))
        });
        match hit {
            None => prop_assert!(first_overlap.is_none(), "missed an overlap at {:?}", first_overlap),
            Some(h) => {
                prop_assert!((0.0..=1.0).contains(&h.t), "{:?}", h);
                if let Some(s) = first_overlap {
                    prop_assert!(h.t <= s + 1e-5, "t {} after the sampled overlap at {}", h.t, s);
                }
                let (pa, pb) = (placed(&a, &at_time(&shooter, h.t)), placed(&b, &at_time(&target, h.t)));
                let tolerance = 1e-3;
                prop_assert!(overlap(grown(pa, tolerance), pb), "apart at t: {:?}", h);
                prop_assert!(
                    holds(pa, h.point, tolerance) && holds(pb, h.point, tolerance),
                    "point {:?} not in both at t = {}: {:?} {:?}", h.point, h.t, pa, pb
                );
            }
        }
    }
}

// ---- Aiming: turned rectangles and capsules against an independent reference. ----

/// The signed distance from `v`'s shape to `q`, in its object-local coordinates, in `f64`:
/// negative inside.
#[cfg(feature = "aim")]
fn signed_distance(v: &Volume, q: DVec2) -> f64 {
    match v.shape {
        VolumeShape::Circle(c) => (q - c.center.as_dvec2()).length() - f64::from(c.radius),
        VolumeShape::Rect(b) => {
            let (lo, hi) = (b.min.as_dvec2(), b.max.as_dvec2());
            let outside = (q - q.clamp(lo, hi)).length();
            if outside > 0.0 {
                outside
            } else {
                -(q.x - lo.x).min(hi.x - q.x).min(q.y - lo.y).min(hi.y - q.y)
            }
        }
        VolumeShape::Capsule { segment, radius } => {
            let (a, b) = (segment.a.as_dvec2(), segment.b.as_dvec2());
            let d = b - a;
            let s = if d.length_squared() > 0.0 {
                ((q - a).dot(d) / d.length_squared()).clamp(0.0, 1.0)
            } else {
                0.0
            };
            (q - (a + d * s)).length() - f64::from(radius)
        }
        other => panic!("a volume shape the reference does not know: {other:?}"),
    }
}

/// World point `p` in the object-local coordinates of `o`'s attack volumes: the inverse of
/// what placing does (move, turn by the aim's angle about the middle of the size, mirror),
/// in `f64` with the angle from `atan2`.
#[cfg(feature = "aim")]
fn attack_local(o: &HitObject, p: DVec2) -> DVec2 {
    let size = o.size.as_dvec2();
    let pivot = size * 0.5;
    let mut q = p - o.position.as_dvec2();
    if let Some(aim) = o.aim {
        let angle = f64::from(aim.y).atan2(f64::from(aim.x));
        let (sin, cos) = (-angle).sin_cos();
        let d = q - pivot;
        q = pivot + DVec2::new(cos * d.x - sin * d.y, sin * d.x + cos * d.y);
    }
    if o.facing.flip_x {
        q.x = size.x - q.x;
    }
    if o.facing.flip_y {
        q.y = size.y - q.y;
    }
    q
}

/// An attack volume to turn: a rectangle or a capsule, on a 1/8 lattice.
#[cfg(feature = "aim")]
fn aimed_volume() -> impl Strategy<Value = Volume> {
    let q = || (-16i32..24).prop_map(|v| v as f32 / 8.0);
    prop_oneof![
        (q(), q(), 1u32..16, 1u32..16).prop_map(|(x, y, w, h)| {
            rect(x, y, w as f32 / 16.0, h as f32 / 16.0, HitTypes::HIT)
        }),
        (q(), q(), q(), q(), 0u32..6).prop_map(|(ax, ay, bx, by, r)| {
            Volume::capsule(
                Vec2::new(ax, ay),
                Vec2::new(bx, by),
                r as f32 / 8.0,
                HitTypes::HIT,
            )
            .unwrap()
        }),
    ]
}

/// An aiming attacker at (`x`, `y`) of size 1 × 2 (or of size zero), facing and aiming as
/// drawn: an aim of any angle and length.
#[cfg(feature = "aim")]
fn aimer() -> impl Strategy<Value = HitObject> {
    (
        -8i32..8,
        -8i32..8,
        any::<bool>(),
        any::<bool>(),
        any::<bool>(),
        -180.0f32..180.0,
        prop_oneof![Just(1.0f32), Just(0.001), Just(250.0)],
    )
        .prop_map(|(x, y, sized, fx, fy, degrees, length)| HitObject {
            facing: Facing {
                flip_x: fx,
                flip_y: fy,
            },
            aim: Some(Vec2::from_angle(degrees.to_radians()) * length),
            ..HitObject::new(
                Owner(1),
                Vec2::new(x as f32, y as f32) / 4.0,
                if sized {
                    Vec2::new(1.0, 2.0)
                } else {
                    Vec2::ZERO
                },
            )
        })
}

#[cfg(feature = "aim")]
#[test]
fn a_quarter_turn_aims_a_sword_down_and_leaves_the_body_upright() {
    // A 1 × 1 hero at the origin with a sword reaching right (x in [1, 2], y in [0.4, 0.6])
    // and a body of its own size. Aimed down (+y), the sword hangs below the middle (0.5,
    // 0.5): x in [0.4, 0.6], y in [1, 2]. The body is not turned.
    let sword = [rect(1.5, 0.5, 0.5, 0.1, HitTypes::HIT)];
    let hero = HitObject {
        team: 1,
        aim: Some(Vec2::new(0.0, 3.0)),
        ..HitObject::new(Owner(1), Vec2::ZERO, Vec2::ONE)
    };
    let point =
        |owner: u64, x: f32, y: f32| HitObject::new(Owner(owner), Vec2::new(x, y), Vec2::ZERO);
    let dot = [circle(0.0, 0.0, 0.0, HitTypes::ANY)];
    let mut world = HitWorld::new();
    world.begin_frame();
    world.register(hero, &sword, &body(HitTypes::ANY)).unwrap();
    world.register(point(2, 0.5, 1.9), &[], &dot).unwrap(); // under: hit
    world.register(point(3, 1.9, 0.5), &[], &dot).unwrap(); // where the sword was drawn
    // A spike at (0.9, 0.1): inside the upright body, outside a body turned about the
    // middle (which would be the same square here): checks the body is still there.
    world
        .register(
            point(4, 0.9, 0.1),
            &[circle(0.0, 0.0, 0.0, HitTypes::HIT)],
            &[],
        )
        .unwrap();
    let got: Vec<_> = world
        .detect(&mut |_: &HitObject, _: &HitObject, _: HitTypes| true)
        .iter()
        .map(|e| (e.attacker_owner.0, e.victim_owner.0))
        .collect();
    assert_eq!(got, [(1, 2), (4, 1)]);
}

#[cfg(feature = "aim")]
#[test]
fn an_aim_of_zero_or_not_finite_is_refused() {
    let aiming = |aim: Vec2| HitObject {
        aim: Some(aim),
        ..HitObject::new(Owner(1), Vec2::ZERO, Vec2::ONE)
    };
    let mut world = HitWorld::new();
    world.begin_frame();
    let fist = [circle(1.0, 0.5, 0.2, HitTypes::HIT)];
    assert_eq!(
        world.register(aiming(Vec2::ZERO), &fist, &[]),
        Err(VolumeError::ZeroAim)
    );
    assert!(matches!(
        world.register(aiming(Vec2::new(f32::NAN, 1.0)), &fist, &[]),
        Err(VolumeError::NonFinite { what: "aim", .. })
    ));
    // Any other length is a direction, however large or small.
    for length in [1e-30f32, 1e30, f32::MAX] {
        assert!(
            world
                .register(aiming(Vec2::new(length, length)), &fist, &[])
                .is_ok()
        );
    }
}

#[cfg(feature = "aim")]
proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// A turned rectangle or capsule hits a point target exactly where the turned shape,
    /// computed independently (the inverse turn by the aim's angle, in `f64`), covers it:
    /// on a grid of points around it, every point more than 10⁻³ inside is hit and none
    /// more than 10⁻³ outside.
    #[test]
    fn a_turned_volume_hits_what_the_turned_shape_covers(
        attack in aimed_volume(),
        attacker in aimer(),
    ) {
        let dot = [circle(0.0, 0.0, 0.0, HitTypes::ANY)];
        let attacker = HitObject { team: 1, ..attacker };
        let mut world = HitWorld::new();
        world.begin_frame();
        world.register(attacker, &[attack], &[]).unwrap();
        let mut expected = Vec::new();
        let mut unsure = Vec::new();
        let mut owner = 1u64;
        for i in -24..=24 {
            for j in -24..=24 {
                owner += 1;
                let p = attacker.position + Vec2::new(i as f32, j as f32) * (3.0 / 24.0) + 0.01;
                let d = signed_distance(&attack, attack_local(&attacker, p.as_dvec2()));
                if d.abs() < 1e-3 {
                    unsure.push(owner);
                } else if d < 0.0 {
                    expected.push(owner);
                }
                world.register(HitObject::new(Owner(owner), p, Vec2::ZERO), &[], &dot).unwrap();
            }
        }
        let got: Vec<u64> = world
            .detect(&mut TeamRule)
            .iter()
            .map(|e| e.victim_owner.0)
            .filter(|o| !unsure.contains(o))
            .collect();
        prop_assert!(!expected.is_empty() || got.is_empty());
        prop_assert_eq!(got, expected);
    }

    /// A turned rectangle or capsule swept across a moving circle or upright rectangle: the
    /// reported `t` is no later than the first overlap fine sub-stepping finds (against the
    /// independent reference), they touch at `t`, and the point is in both.
    #[test]
    fn a_turned_volume_swept_into_a_target_agrees_with_sub_stepping(
        attack in aimed_volume(),
        attacker in aimer(),
        motion in (-64i32..64, -64i32..64),
        target in (-32i32..32, -32i32..32, 0u32..8, 0u32..8),
        is_rect in any::<bool>(),
        target_motion in (-16i32..16, -16i32..16),
    ) {
        let eighths = |x: i32, y: i32| Vec2::new(x as f32, y as f32) / 8.0;
        let motion = eighths(motion.0, motion.1);
        let attacker = HitObject { team: 1, motion, position: attacker.position + motion, ..attacker };
        let target_motion = eighths(target_motion.0, target_motion.1);
        let size = Vec2::new(target.2 as f32, target.3 as f32) / 8.0;
        let victim = HitObject {
            motion: target_motion,
            ..HitObject::new(Owner(2), eighths(target.0, target.1) + target_motion, Vec2::ZERO)
        };
        let volume = if is_rect {
            rect(0.0, 0.0, size.x, size.y, HitTypes::ANY)
        } else {
            circle(0.0, 0.0, size.x, HitTypes::ANY)
        };
        let mut world = HitWorld::new();
        world.begin_frame();
        world.register(attacker, &[attack], &[]).unwrap();
        world.register(victim, &[], &[volume]).unwrap();
        let hit = world.detect(&mut TeamRule).first().copied();
        // How far apart the two are at time `s` (negative: overlapping).
        let gap = |s: f32| {
            let (a, v) = (at_time(&attacker, s), at_time(&victim, s));
            let center = v.position.as_dvec2();
            if is_rect {
                attack_gap_to_box(&attack, &a, center, size.as_dvec2())
            } else {
                signed_distance(&attack, attack_local(&a, center)) - f64::from(size.x)
            }
        };
        const STEPS: usize = 2000;
        let first_overlap = (0..=STEPS).map(|k| k as f32 / STEPS as f32).find(|&s| gap(s) <= -1e-4);
        match hit {
            None => prop_assert!(first_overlap.is_none(), "missed an overlap at {:?}", first_overlap),
            Some(h) => {
                if let Some(s) = first_overlap {
                    prop_assert!(h.t <= s + 1e-5, "t {} after the sampled overlap at {}", h.t, s);
                }
                prop_assert!(gap(h.t) <= 1e-3, "apart at t: {:?}, gap {}", h, gap(h.t));
                let (a, v) = (at_time(&attacker, h.t), at_time(&victim, h.t));
                let p = h.point.as_dvec2();
                prop_assert!(signed_distance(&attack, attack_local(&a, p)) <= 1e-3, "{:?}", h);
                let (center, size) = (v.position.as_dvec2(), size.as_dvec2());
                let in_victim = if is_rect {
                    (p - center).abs().cmple(size + 1e-3).all()
                } else {
                    p.distance(center) <= size.x + 1e-3
                };
                prop_assert!(in_victim, "{:?}", h);
            }
        }
    }
}

/// How far `o`'s turned attack volume `v` is from the upright box centred at `center` with
/// half extents `half`, in `f64` (negative: overlapping): a turned rectangle's world corners
/// (turned by the aim's angle) against the box by separating axes; a capsule's world
/// segment's distance to the box, less its radius.
#[cfg(feature = "aim")]
fn attack_gap_to_box(v: &Volume, o: &HitObject, center: DVec2, half: DVec2) -> f64 {
    let size = o.size.as_dvec2();
    let pivot = size * 0.5;
    let angle = o
        .aim
        .map_or(0.0, |aim| f64::from(aim.y).atan2(f64::from(aim.x)));
    let (sin, cos) = angle.sin_cos();
    let world = |p: Vec2| {
        let mut q = p.as_dvec2();
        if o.facing.flip_x {
            q.x = size.x - q.x;
        }
        if o.facing.flip_y {
            q.y = size.y - q.y;
        }
        let d = q - pivot;
        o.position.as_dvec2() + pivot + DVec2::new(cos * d.x - sin * d.y, sin * d.x + cos * d.y)
    };
    let (lo, hi) = (center - half, center + half);
    match v.shape {
        VolumeShape::Rect(b) => {
            let corners = [
                b.min,
                Vec2::new(b.max.x, b.min.y),
                b.max,
                Vec2::new(b.min.x, b.max.y),
            ]
            .map(world);
            let boxed = [lo, DVec2::new(hi.x, lo.y), hi, DVec2::new(lo.x, hi.y)];
            let axes = [
                DVec2::X,
                DVec2::Y,
                DVec2::new(cos, sin),
                DVec2::new(-sin, cos),
            ];
            axes.iter()
                .map(|axis| {
                    let span = |ps: &[DVec2; 4]| {
                        ps.iter()
                            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), p| {
                                (l.min(p.dot(*axis)), h.max(p.dot(*axis)))
                            })
                    };
                    let ((a0, a1), (b0, b1)) = (span(&corners), span(&boxed));
                    (b0 - a1).max(a0 - b1)
                })
                .fold(f64::NEG_INFINITY, f64::max)
        }
        VolumeShape::Capsule { segment, radius } => {
            let (a, b) = (world(segment.a), world(segment.b));
            let to_box = |p: DVec2| (p - p.clamp(lo, hi)).length();
            let to_segment = |p: DVec2| {
                let d = b - a;
                let s = if d.length_squared() > 0.0 {
                    ((p - a).dot(d) / d.length_squared()).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                (p - (a + d * s)).length()
            };
            // The segment meets the box: its part within both slabs is not empty (Liang and
            // Barsky's clipping).
            let crosses = {
                let (mut t0, mut t1) = (0.0f64, 1.0f64);
                let d = b - a;
                for axis in 0..2 {
                    let (o, v) = (a[axis], d[axis]);
                    if v == 0.0 {
                        if o < lo[axis] || o > hi[axis] {
                            t0 = 2.0;
                        }
                    } else {
                        let (u, w) = ((lo[axis] - o) / v, (hi[axis] - o) / v);
                        t0 = t0.max(u.min(w));
                        t1 = t1.min(u.max(w));
                    }
                }
                t0 <= t1
            };
            let distance = if crosses {
                0.0
            } else {
                [a, b]
                    .map(to_box)
                    .into_iter()
                    .chain([lo, DVec2::new(hi.x, lo.y), hi, DVec2::new(lo.x, hi.y)].map(to_segment))
                    .fold(f64::INFINITY, f64::min)
            };
            distance - f64::from(radius)
        }
        other => panic!("a volume shape the reference does not know: {other:?}"),
    }
}

// ---- Traces: what `detect_traced` says it did with each pair. ----

/// A hero punching a row of neighbours, each of which the punch reaches for another
/// reason: hit, same team, invulnerable, a coin that takes no punches, a corner the fist
/// misses though the boxes overlap, and one far away.
#[test]
fn a_traced_detect_says_why_each_neighbour_was_hit_or_not() {
    let mut world = HitWorld::new();
    let fist = [circle(1.2, 0.5, 0.3, HitTypes::HIT)];
    let hero = HitObject {
        swing: Some(7),
        ..object(1, 0.0, 0.0)
    };
    let frame = |world: &mut HitWorld| {
        world.begin_frame();
        world.register(hero, &fist, &body(HitTypes::ANY)).unwrap();
        world
            .register(object(2, 1.2, 0.0), &[], &body(HitTypes::ANY))
            .unwrap();
        let ally = HitObject {
            team: 1,
            ..object(3, 1.2, 0.0)
        };
        world.register(ally, &[], &body(HitTypes::ANY)).unwrap();
        let ghost = HitObject {
            invulnerable: true,
            ..object(4, 1.2, 0.0)
        };
        world.register(ghost, &[], &body(HitTypes::ANY)).unwrap();
        world
            .register(object(5, 1.2, 0.0), &[], &body(HitTypes::COLLECT))
            .unwrap();
        // Its body's corner (1.45, 0.75) is 0.354 from the fist's centre: out of reach,
        // though its box overlaps the hero's.
        world
            .register(object(6, 1.45, 0.75), &[], &body(HitTypes::ANY))
            .unwrap();
        world
            .register(object(7, 9.0, 0.0), &[], &body(HitTypes::ANY))
            .unwrap();
    };
    frame(&mut world);
    let mut trace = tileslide::DetectTrace::of(Owner(1));
    let events = world.detect_traced(&mut TeamRule, &mut trace).to_vec();
    assert_eq!(
        events
            .iter()
            .map(|e| (e.victim_owner.0, e.accepted))
            .collect::<Vec<_>>(),
        [(2, true), (3, false), (4, false)]
    );
    use tileslide::{PairOutcome as O, Refusal};
    fn outcome_in(
        trace: &tileslide::DetectTrace,
        attacker: u64,
        victim: u64,
    ) -> (tileslide::PairOutcome, Vec<tileslide::VolumeTest>) {
        let found: Vec<_> = trace
            .pairs()
            .iter()
            .filter(|p| (p.attacker_owner.0, p.victim_owner.0) == (attacker, victim))
            .collect();
        assert_eq!(found.len(), 1, "{attacker} → {victim}: {:?}", trace.pairs());
        (found[0].outcome, found[0].tests.clone())
    }
    let outcome = |attacker, victim| outcome_in(&trace, attacker, victim);
    let tested = |dealt: HitTypes, met: bool| {
        vec![tileslide::VolumeTest {
            attack: 0,
            vulnerable: 0,
            dealt,
            met,
        }]
    };
    assert_eq!(
        outcome(1, 2),
        (O::Accepted { event: 0 }, tested(HitTypes::HIT, true))
    );
    assert_eq!(
        outcome(1, 3).0,
        O::Refused {
            event: 1,
            by: Refusal::SameTeam
        }
    );
    assert_eq!(
        outcome(1, 4).0,
        O::Refused {
            event: 2,
            by: Refusal::Invulnerable
        }
    );
    assert_eq!(
        outcome(1, 5),
        (O::NoTypeInCommon, tested(HitTypes::NONE, false))
    );
    assert_eq!(outcome(1, 6), (O::Missed, tested(HitTypes::HIT, false)));
    assert_eq!(outcome(1, 7), (O::BoxesApart, vec![]));
    // The neighbours have no attack volumes; the far one's box is apart both ways.
    for victim in 2..=6 {
        assert_eq!(outcome(victim, 1), (O::NoVolumes, vec![]));
    }
    assert_eq!(outcome(7, 1).0, O::BoxesApart);
    // Only pairs with the hero, both ways, in the events' order.
    assert_eq!(trace.pairs().len(), 12);
    let order: Vec<_> = trace
        .pairs()
        .iter()
        .map(|p| (p.attacker.0, p.victim.0))
        .collect();
    let expected: Vec<_> = (1..7).flat_map(|j| [(0, j), (j, 0)]).collect();
    assert_eq!(order, expected);
    // The next frame, the same swing skips the slime it hit; a rule of the game's own
    // refuses the ally.
    frame(&mut world);
    let mut rule = |_: &HitObject, v: &HitObject, _: HitTypes| v.owner != Owner(3);
    world.detect_traced(&mut rule, &mut trace);
    let outcome = |attacker, victim| outcome_in(&trace, attacker, victim);
    assert_eq!(outcome(1, 2).0, O::SwingAlreadyHit { swing: 7 });
    assert_eq!(
        outcome(1, 3).0,
        O::Refused {
            event: 0,
            by: Refusal::Rule
        }
    );
    // A trace of every pair lists the broadphase's pairs only: the neighbours overlap each
    // other too, and nothing reaches the far one.
    frame(&mut world);
    let mut all = tileslide::DetectTrace::new();
    world.detect_traced(&mut TeamRule, &mut all);
    assert!(all.pairs().iter().all(|p| p.outcome != O::BoxesApart));
    assert!(
        all.pairs()
            .iter()
            .all(|p| p.attacker_owner != Owner(7) && p.victim_owner != Owner(7))
    );
    // Neighbours 2 to 6 pair among themselves (10 pairs) and with the hero (5), both ways.
    assert_eq!(all.pairs().len(), 30);
}

/// What the all-pairs reference expects `detect_traced` to say of `a` attacking `v`
/// (objects standing still, every owner distinct, the team rule).
fn expected_outcome(
    objects: &[Registered],
    a: usize,
    v: usize,
    events: &mut usize,
) -> tileslide::PairOutcome {
    use tileslide::{PairOutcome as O, Refusal};
    let bounds = |(o, attack, vulnerable): &Registered| {
        attack
            .iter()
            .chain(vulnerable)
            .map(|x| match placed(x, o) {
                Shape::Circle(p, r) => (p - r, p + r),
                Shape::Box(lo, hi) => (lo, hi),
            })
            .reduce(|(a0, a1), (b0, b1)| (a0.min(b0), a1.max(b1)))
    };
    let apart = match (bounds(&objects[a]), bounds(&objects[v])) {
        (Some((a0, a1)), Some((b0, b1))) => !(a0.cmple(b1).all() && b0.cmple(a1).all()),
        _ => true,
    };
    let (oa, attacks, _) = &objects[a];
    let (ov, _, vulnerable) = &objects[v];
    let shared = |x: &Volume| vulnerable.iter().any(|y| !(x.hit & y.hit).is_empty());
    if apart {
        return O::BoxesApart;
    }
    if attacks.is_empty() || vulnerable.is_empty() {
        return O::NoVolumes;
    }
    if !attacks.iter().any(shared) {
        return O::NoTypeInCommon;
    }
    let hit = attacks.iter().any(|x| {
        vulnerable
            .iter()
            .any(|y| !(x.hit & y.hit).is_empty() && overlap(placed(x, oa), placed(y, ov)))
    });
    if !hit {
        return O::Missed;
    }
    let event = *events;
    *events += 1;
    if oa.team == ov.team {
        O::Refused {
            event,
            by: Refusal::SameTeam,
        }
    } else if ov.invulnerable {
        O::Refused {
            event,
            by: Refusal::Invulnerable,
        }
    } else {
        O::Accepted { event }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// For random frames, a trace of every pair and a trace of each owner say of every
    /// pair, in each direction, what an all-pairs reference says; the events are those an
    /// untraced `detect` finds.
    #[test]
    fn a_traced_detect_explains_every_pair_as_the_all_pairs_reference(
        objects in objects(),
        teams in prop::collection::vec((0u32..2, prop::bool::weighted(0.2)), 40),
    ) {
        let objects: Vec<Registered> = objects
            .into_iter()
            .zip(&teams)
            .enumerate()
            .map(|(i, ((o, a, v), &(team, invulnerable)))| {
                (HitObject { owner: Owner(i as u64), team, invulnerable, ..o }, a, v)
            })
            .collect();
        let n = objects.len();
        // The reference, over every ordered pair in the events' order.
        let mut events = 0;
        let mut expected = Vec::new();
        for i in 0..n {
            for j in i + 1..n {
                for (a, v) in [(i, j), (j, i)] {
                    let outcome = expected_outcome(&objects, a, v, &mut events);
                    expected.push((a as u32, v as u32, outcome));
                }
            }
        }
        let mut world = HitWorld::new();
        let frame = |world: &mut HitWorld| {
            world.begin_frame();
            for (o, a, v) in &objects {
                world.register(*o, a, v).unwrap();
            }
        };
        frame(&mut world);
        let untraced = world.detect(&mut TeamRule).to_vec();
        prop_assert_eq!(untraced.len(), events);
        frame(&mut world);
        let mut all = tileslide::DetectTrace::new();
        prop_assert_eq!(world.detect_traced(&mut TeamRule, &mut all), &untraced[..]);
        let got: Vec<_> = all.pairs().iter().map(|p| (p.attacker.0, p.victim.0, p.outcome)).collect();
        let found: Vec<_> = expected
            .iter()
            .copied()
            .filter(|e| e.2 != tileslide::PairOutcome::BoxesApart)
            .collect();
        prop_assert_eq!(got, found);
        for k in 0..n.min(6) {
            frame(&mut world);
            let mut one = tileslide::DetectTrace::of(Owner(k as u64));
            prop_assert_eq!(world.detect_traced(&mut TeamRule, &mut one), &untraced[..]);
            let got: Vec<_> = one.pairs().iter().map(|p| (p.attacker.0, p.victim.0, p.outcome)).collect();
            let mine: Vec<_> = expected
                .iter()
                .copied()
                .filter(|e| e.0 as usize == k || e.1 as usize == k)
                .collect();
            prop_assert_eq!(got, mine);
        }
    }
}

#[test]
fn an_object_with_more_volumes_than_the_limit_is_refused_and_nothing_is_registered() {
    use tileslide::limits::MAX_OBJECT_VOLUMES;
    let mut world = HitWorld::new();
    let many = vec![circle(0.0, 0.0, 0.5, HitTypes::HIT); MAX_OBJECT_VOLUMES + 1];
    for (attack, vulnerable, what) in [
        (&many[..], &[][..], "attack volumes"),
        (&[][..], &many[..], "vulnerable volumes"),
    ] {
        let refused = world.register(object(1, 0.0, 0.0), attack, vulnerable);
        assert_eq!(
            refused,
            Err(VolumeError::TooMany {
                what,
                count: MAX_OBJECT_VOLUMES + 1,
                max: MAX_OBJECT_VOLUMES
            })
        );
        assert!(
            refused
                .unwrap_err()
                .to_string()
                .contains(&format!("too many {what}: 1025, at most 1024"))
        );
    }
    // The limit itself is taken, and the refusals left nothing behind: the attacker and its
    // victim are the first two objects, and one hit comes of them.
    let attacker = world
        .register(object(1, 0.0, 0.0), &many[..MAX_OBJECT_VOLUMES], &[])
        .unwrap();
    let victim = world
        .register(object(2, 0.2, 0.0), &[], &body(HitTypes::HIT))
        .unwrap();
    assert_eq!((attacker, victim), (ObjectId(0), ObjectId(1)));
    assert_eq!(hits(&mut world), vec![(0, 1, HitTypes::HIT, true)]);
}

#[test]
fn a_frame_takes_at_most_the_limit_of_hit_objects_and_the_next_frame_starts_afresh() {
    use tileslide::limits::MAX_HIT_OBJECTS;
    let mut world = HitWorld::new();
    for _ in 0..MAX_HIT_OBJECTS {
        world.register(object(1, 0.0, 0.0), &[], &[]).unwrap();
    }
    assert_eq!(
        world.register(object(1, 0.0, 0.0), &[], &[]),
        Err(VolumeError::TooMany {
            what: "hit objects this frame",
            count: MAX_HIT_OBJECTS + 1,
            max: MAX_HIT_OBJECTS
        })
    );
    world.begin_frame();
    assert_eq!(
        world.register(object(1, 0.0, 0.0), &[], &[]),
        Ok(ObjectId(0))
    );
}

/// A melee of 3,000 objects, enough pairs that `detect` tests their volumes on several
/// threads (the `parallel` feature): on 1, 2, 3 and 8 threads, every frame's events are the
/// same, bit for bit and in the same order, and the rule is asked in the same order (a rule
/// that accepts every third hit it is asked about, and swings shared by several objects of
/// one owner, both of which depend on the order).
#[test]
fn a_melee_gives_the_same_events_in_the_same_order_on_any_number_of_threads() {
    let mut rand = tileslide_scenes::SplitMix64::new(0x00ae_1ee0_2026_1130);
    let objects: Vec<(HitObject, Vec<Volume>, Vec<Volume>)> = (0..3_000u64)
        .map(|k| {
            let position = Vec2::new(rand.f32() * 60.0, rand.f32() * 60.0);
            let motion = Vec2::new(rand.f32() - 0.5, rand.f32() - 0.5) * 0.8;
            let owner = k / 3;
            let o = HitObject {
                motion,
                team: (owner % 4) as u32,
                invulnerable: k % 17 == 0,
                swing: (k % 5 == 0).then_some(owner),
                ..HitObject::new(Owner(owner), position, Vec2::ONE)
            };
            let types = [HitTypes::HIT, HitTypes::ANY][(k % 2) as usize];
            let attack = vec![circle(0.5, 0.5, 0.3 + rand.f32() * 0.5, types)];
            let vulnerable = vec![rect(0.5, 0.5, 0.5, 0.5, HitTypes::ANY)];
            (o, attack, vulnerable)
        })
        .collect();
    let run = || {
        let mut world = HitWorld::new();
        let mut asked = 0u32;
        let mut frames = Vec::new();
        for frame in 0..3 {
            world.begin_frame();
            for (o, attack, vulnerable) in &objects {
                let o = HitObject {
                    position: o.position + o.motion * frame as f32,
                    ..*o
                };
                world.register(o, attack, vulnerable).unwrap();
            }
            let mut every_third = |a: &HitObject, v: &HitObject, _: HitTypes| {
                asked += 1;
                a.team != v.team && !asked.is_multiple_of(3)
            };
            let events: Vec<_> = world
                .detect(&mut every_third)
                .iter()
                .map(|e| {
                    (
                        e.attacker.0,
                        e.victim.0,
                        e.hit_type,
                        e.accepted,
                        e.t.to_bits(),
                        e.point.x.to_bits(),
                        e.point.y.to_bits(),
                    )
                })
                .collect();
            frames.push(events);
        }
        frames
    };
    let one = crate::generators::on_threads(1, run);
    assert!(
        one.iter().all(|events| events.len() > 2_000),
        "{}",
        one[0].len()
    );
    for threads in [2, 3, 8] {
        assert!(
            crate::generators::on_threads(threads, run) == one,
            "{threads} threads"
        );
    }
}
