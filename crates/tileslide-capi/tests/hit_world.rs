//! Hit volumes through the C API as C calls it: a seeded crowd of objects moving, turning,
//! swinging, being added and removed for 40 steps gives the core `HitWorld`'s events bit
//! for bit; ids go stale when their object is removed; a buffer too small gets the count;
//! bad input gets a status and a message naming it.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic, unsafe_code)]

mod support;

use std::ptr;

use support::{assert_refused, last_error};
use tileslide::{Facing, HitObject, HitTypes, HitWorld, Owner, TeamRule, Vec2, Volume};
use tileslide_capi::*;
use tileslide_scenes::SplitMix64;

fn new_world() -> *mut ts_hit_world {
    let mut w = ptr::null_mut();
    // SAFETY: a writable out pointer.
    assert_eq!(unsafe { ts_hit_world_create(&mut w) }, ts_status::TS_OK);
    w
}

fn add(w: *mut ts_hit_world, def: &ts_hit_object_def) -> ts_hit_object_id {
    let mut id = ts_hit_object_id {
        index: 0,
        generation: 0,
    };
    // SAFETY: a live world, a definition whose lists are as long as it says.
    let status = unsafe { ts_hit_world_add(w, def, &mut id) };
    assert_eq!(status, ts_status::TS_OK, "{}", last_error());
    id
}

fn events(w: *const ts_hit_world) -> Vec<ts_hit_event> {
    let mut n = 0;
    // SAFETY: a live world; capacity 0 asks how many.
    unsafe {
        let status = ts_hit_world_events(w, ptr::null_mut(), 0, &mut n);
        assert!(matches!(
            status,
            ts_status::TS_OK | ts_status::TS_ERROR_BUFFER_TOO_SMALL
        ));
        let mut out = Vec::with_capacity(n);
        assert_eq!(
            ts_hit_world_events(w, out.as_mut_ptr(), n, &mut n),
            ts_status::TS_OK
        );
        out.set_len(n);
        out
    }
}

fn circle(x: f32, y: f32, radius: f32, hit: u32) -> ts_volume {
    ts_volume {
        shape: TS_SHAPE_CIRCLE,
        x,
        y,
        radius,
        half_width: 0.0,
        half_height: 0.0,
        hit,
    }
}

fn rect(x: f32, y: f32, half_width: f32, half_height: f32, hit: u32) -> ts_volume {
    ts_volume {
        shape: TS_SHAPE_RECT,
        x,
        y,
        radius: 0.0,
        half_width,
        half_height,
        hit,
    }
}

/// One object of the scene, as both sides are told it.
#[derive(Clone, Debug)]
struct Thing {
    id: ts_hit_object_id,
    position: Vec2,
    last: Vec2,
    size: Vec2,
    flip_x: bool,
    team: u32,
    invulnerable: bool,
    swing: u64,
    attack: Vec<ts_volume>,
    vulnerable: Vec<ts_volume>,
}

impl Thing {
    fn random(rng: &mut SplitMix64) -> Self {
        let position = Vec2::new(rng.range(0.0, 30.0), rng.range(0.0, 30.0));
        let volume = |rng: &mut SplitMix64| {
            let hit = [
                TS_HIT_TYPE_HIT,
                TS_HIT_TYPE_COLLECT,
                TS_HIT_TYPE_HIT | TS_HIT_TYPE_DEATH,
                TS_HIT_TYPE_ANY,
            ][rng.below(4) as usize];
            let (x, y) = (rng.range(-1.0, 2.0), rng.range(-1.0, 2.0));
            if rng.below(2) == 0 {
                circle(x, y, rng.range(0.1, 1.0), hit)
            } else {
                rect(x, y, rng.range(0.1, 1.0), rng.range(0.1, 1.0), hit)
            }
        };
        let attack = (0..rng.below(3)).map(|_| volume(rng)).collect();
        let vulnerable = (0..rng.below(3)).map(|_| volume(rng)).collect();
        Thing {
            id: ts_hit_object_id {
                index: 0,
                generation: 0,
            },
            position,
            last: position,
            size: Vec2::new(rng.range(0.0, 2.0), rng.range(0.0, 2.0)),
            flip_x: rng.below(2) == 0,
            team: rng.below(3) as u32,
            invulnerable: rng.below(8) == 0,
            swing: if rng.below(3) == 0 {
                rng.below(4)
            } else {
                TS_NO_SWING
            },
            attack,
            vulnerable,
        }
    }

    fn def(&self) -> ts_hit_object_def {
        ts_hit_object_def {
            x: self.position.x,
            y: self.position.y,
            width: self.size.x,
            height: self.size.y,
            flip_x: self.flip_x,
            team: self.team,
            invulnerable: self.invulnerable,
            swing: self.swing,
            attack: self.attack.as_ptr(),
            attack_count: self.attack.len(),
            vulnerable: self.vulnerable.as_ptr(),
            vulnerable_count: self.vulnerable.len(),
            ..ts_default_hit_object_def()
        }
    }

    /// The core's object, its volumes, registered with the id as its owner.
    fn core(&self) -> (HitObject, Vec<Volume>, Vec<Volume>) {
        let core_volume = |v: &ts_volume| {
            let c = Vec2::new(v.x, v.y);
            let hit = HitTypes::from_bits(v.hit);
            if v.shape == TS_SHAPE_CIRCLE {
                Volume::circle(c, v.radius, hit).unwrap()
            } else {
                Volume::rect(c, Vec2::new(v.half_width, v.half_height), hit).unwrap()
            }
        };
        let owner = Owner(u64::from(self.id.generation) << 32 | u64::from(self.id.index));
        let object = HitObject {
            motion: self.position - self.last,
            facing: Facing {
                flip_x: self.flip_x,
                flip_y: false,
            },
            team: self.team,
            invulnerable: self.invulnerable,
            swing: (self.swing != TS_NO_SWING).then_some(self.swing),
            ..HitObject::new(owner, self.position, self.size)
        };
        (
            object,
            self.attack.iter().map(core_volume).collect(),
            self.vulnerable.iter().map(core_volume).collect(),
        )
    }
}

#[test]
fn a_seeded_crowd_through_c_hits_as_the_core_does_bit_for_bit() {
    let mut rng = SplitMix64::new(0x5eed_4175);
    let w = new_world();
    let mut core = HitWorld::new();
    // The scene's objects by slot, as the C world numbers them.
    let mut slots: Vec<Option<Thing>> = Vec::new();
    let mut total = 0;
    let mut moved = 0;
    for step in 0..40 {
        // Add a few, remove a few, move the rest (some fast), retune some.
        for _ in 0..if step == 0 { 150 } else { 4 } {
            let mut thing = Thing::random(&mut rng);
            thing.id = add(w, &thing.def());
            let slot = thing.id.index as usize;
            if slot >= slots.len() {
                slots.resize(slot + 1, None);
            }
            assert!(slots[slot].is_none());
            slots[slot] = Some(thing);
        }
        for slot in slots.iter_mut() {
            let Some(thing) = slot else { continue };
            match rng.below(10) {
                0 => {
                    // SAFETY: a live world and id.
                    assert_eq!(
                        unsafe { ts_hit_world_remove(w, thing.id) },
                        ts_status::TS_OK
                    );
                    *slot = None;
                }
                1 => {
                    let fresh = Thing::random(&mut rng);
                    *thing = Thing {
                        id: thing.id,
                        position: fresh.position,
                        last: thing.last,
                        ..fresh
                    };
                    // SAFETY: a live world and id, a definition as long as it says.
                    assert_eq!(
                        unsafe { ts_hit_world_set(w, thing.id, &thing.def()) },
                        ts_status::TS_OK
                    );
                }
                _ => {
                    let speed = if rng.below(5) == 0 { 8.0 } else { 0.5 };
                    thing.position += Vec2::new(rng.range(-speed, speed), rng.range(-speed, speed));
                    // SAFETY: a live world and id.
                    let status = unsafe {
                        ts_hit_world_move(w, thing.id, thing.position.x, thing.position.y)
                    };
                    assert_eq!(status, ts_status::TS_OK);
                    moved += 1;
                }
            }
        }
        // SAFETY: a live world.
        assert_eq!(unsafe { ts_hit_world_step(w) }, ts_status::TS_OK);
        core.begin_frame();
        for thing in slots.iter_mut().flatten() {
            let (object, attack, vulnerable) = thing.core();
            core.register(object, &attack, &vulnerable).unwrap();
            thing.last = thing.position;
        }
        let expected: Vec<_> = core
            .detect(&mut TeamRule)
            .iter()
            .map(|e| {
                let id = |o: Owner| (o.0 as u32, (o.0 >> 32) as u32);
                (
                    id(e.attacker_owner),
                    id(e.victim_owner),
                    e.hit_type.bits(),
                    e.accepted,
                    [e.t, e.point.x, e.point.y].map(f32::to_bits),
                )
            })
            .collect();
        let got: Vec<_> = events(w)
            .iter()
            .map(|e| {
                (
                    (e.attacker.index, e.attacker.generation),
                    (e.victim.index, e.victim.generation),
                    e.hit_type,
                    e.accepted,
                    [e.t, e.x, e.y].map(f32::to_bits),
                )
            })
            .collect();
        assert_eq!(got, expected, "step {step}");
        total += got.len();
        // SAFETY: a live world.
        assert_eq!(
            unsafe { ts_hit_world_count(w) },
            slots.iter().flatten().count()
        );
    }
    assert!(total > 200 && moved > 1000, "{total} events, {moved} moves");
    // SAFETY: freed once.
    unsafe { ts_hit_world_free(w) };
}

#[test]
fn a_fast_bullet_hits_what_it_passes_and_a_swing_hits_once() {
    let w = new_world();
    let body = [rect(0.0, 0.0, 0.5, 0.5, TS_HIT_TYPE_ANY)];
    let target = add(
        w,
        &ts_hit_object_def {
            x: 10.0,
            y: 0.0,
            team: 1,
            vulnerable: body.as_ptr(),
            vulnerable_count: 1,
            ..ts_default_hit_object_def()
        },
    );
    let shot = [circle(0.0, 0.0, 0.1, TS_HIT_TYPE_HIT)];
    let bullet = add(
        w,
        &ts_hit_object_def {
            attack: shot.as_ptr(),
            attack_count: 1,
            swing: 7,
            ..ts_default_hit_object_def()
        },
    );
    // SAFETY: a live world and ids throughout.
    unsafe {
        assert_eq!(ts_hit_world_step(w), ts_status::TS_OK);
        assert!(events(w).is_empty());
        // From 0 to 20 in one step: through the target at 10.
        assert_eq!(ts_hit_world_move(w, bullet, 20.0, 0.0), ts_status::TS_OK);
        assert_eq!(ts_hit_world_step(w), ts_status::TS_OK);
        let hits = events(w);
        assert_eq!(hits.len(), 1);
        let e = hits[0];
        assert_eq!(
            (e.attacker, e.victim, e.hit_type, e.accepted),
            (bullet, target, TS_HIT_TYPE_HIT, true)
        );
        assert!(
            (e.t - 0.47).abs() < 1e-5 && (e.x - 9.5).abs() < 1e-4,
            "{e:?}"
        );
        // Back over the target with the same swing: no second hit.
        assert_eq!(ts_hit_world_move(w, bullet, 10.0, 0.0), ts_status::TS_OK);
        assert_eq!(ts_hit_world_step(w), ts_status::TS_OK);
        assert!(events(w).is_empty());
        // Removed: the last step's events stay; the id is stale, even once its slot is
        // reused.
        assert_eq!(ts_hit_world_remove(w, target), ts_status::TS_OK);
        let again = add(w, &ts_default_hit_object_def());
        assert_eq!(again.index, target.index);
        assert_ne!(again.generation, target.generation);
        assert_refused(
            ts_hit_world_move(w, target, 1.0, 1.0),
            ts_status::TS_ERROR_STALE_HANDLE,
            "stale hit object id",
        );
        assert_refused(
            ts_hit_world_remove(w, target),
            ts_status::TS_ERROR_STALE_HANDLE,
            "stale",
        );
        let def = ts_default_hit_object_def();
        assert_refused(
            ts_hit_world_set(w, target, &def),
            ts_status::TS_ERROR_STALE_HANDLE,
            "stale",
        );
        let made_up = ts_hit_object_id {
            index: 99,
            generation: 0,
        };
        assert_refused(
            ts_hit_world_move(w, made_up, 1.0, 1.0),
            ts_status::TS_ERROR_STALE_HANDLE,
            "index 99",
        );
        assert_eq!(ts_hit_world_count(w), 2);
        ts_hit_world_free(w);
    }
}

#[test]
fn teams_refuse_and_a_small_buffer_gets_the_count() {
    let w = new_world();
    let both = [circle(0.0, 0.0, 1.0, TS_HIT_TYPE_HIT)];
    let body = [circle(0.0, 0.0, 1.0, TS_HIT_TYPE_ANY)];
    let def = ts_hit_object_def {
        attack: both.as_ptr(),
        attack_count: 1,
        vulnerable: body.as_ptr(),
        vulnerable_count: 1,
        ..ts_default_hit_object_def()
    };
    let a = add(w, &def);
    let b = add(w, &ts_hit_object_def { x: 1.0, ..def });
    let c = add(
        w,
        &ts_hit_object_def {
            x: 0.5,
            team: 2,
            ..def
        },
    );
    // SAFETY: a live world; buffers as long as said.
    unsafe {
        assert_eq!(ts_hit_world_step(w), ts_status::TS_OK);
        let all = events(w);
        // Three pairs, both ways: a and b are on one team, so refuse each other.
        assert_eq!(all.len(), 6);
        for e in &all {
            let same_team = [e.attacker, e.victim].iter().all(|id| *id == a || *id == b);
            assert_eq!(e.accepted, !same_team, "{e:?}");
            assert!([a, b, c].contains(&e.attacker) && [a, b, c].contains(&e.victim));
        }
        let mut few = [all[0]; 2];
        let mut n = 0;
        assert_refused(
            ts_hit_world_events(w, few.as_mut_ptr(), 2, &mut n),
            ts_status::TS_ERROR_BUFFER_TOO_SMALL,
            "6 events do not fit in a buffer of 2",
        );
        assert_eq!(n, 6);
        assert_eq!(few, [all[0]; 2], "nothing written");
        assert_refused(
            ts_hit_world_events(w, few.as_mut_ptr(), 2, ptr::null_mut()),
            ts_status::TS_ERROR_NULL_POINTER,
            "count",
        );
        assert_refused(
            ts_hit_world_events(w, ptr::null_mut(), 6, &mut n),
            ts_status::TS_ERROR_NULL_POINTER,
            "out",
        );
        ts_hit_world_free(w);
    }
}

#[test]
fn bad_definitions_moves_and_pointers_are_refused_by_name() {
    use ts_status::*;
    let w = new_world();
    let good = [circle(0.0, 0.0, 0.5, TS_HIT_TYPE_HIT)];
    let negative = [good[0], circle(0.0, 0.0, -0.5, TS_HIT_TYPE_HIT)];
    let unknown = [ts_volume {
        shape: 5,
        ..good[0]
    }];
    let bad_rect = [rect(0.0, 0.0, 0.5, f32::NAN, TS_HIT_TYPE_HIT)];
    let many = vec![good[0]; tileslide::limits::MAX_OBJECT_VOLUMES + 1];
    let base = ts_default_hit_object_def();
    let cases = [
        (
            ts_hit_object_def {
                attack: many.as_ptr(),
                attack_count: many.len(),
                ..base
            },
            INVALID,
            "def.attack: 1025 volumes, at most 1024",
        ),
        // A count no memory could hold is refused before anything is read.
        (
            ts_hit_object_def {
                vulnerable: good.as_ptr(),
                vulnerable_count: usize::MAX,
                ..base
            },
            INVALID,
            "def.vulnerable: 18446744073709551615 volumes, at most 1024",
        ),
        (
            ts_hit_object_def {
                x: f32::NAN,
                ..base
            },
            INVALID,
            "def.x is NaN",
        ),
        (ts_hit_object_def { y: 1e30, ..base }, INVALID, "def.y is"),
        (
            ts_hit_object_def {
                width: f32::INFINITY,
                ..base
            },
            INVALID,
            "def.width",
        ),
        (
            ts_hit_object_def {
                attack: negative.as_ptr(),
                attack_count: 2,
                ..base
            },
            INVALID,
            "def.attack[1]: volume has a negative radius",
        ),
        (
            ts_hit_object_def {
                vulnerable: unknown.as_ptr(),
                vulnerable_count: 1,
                ..base
            },
            INVALID,
            "def.vulnerable[0].shape is 5",
        ),
        (
            ts_hit_object_def {
                attack: bad_rect.as_ptr(),
                attack_count: 1,
                ..base
            },
            INVALID,
            "def.attack[0]: volume has a non-finite half extents",
        ),
        (
            ts_hit_object_def {
                attack_count: 1,
                ..base
            },
            NULL,
            "def.attack is a null pointer",
        ),
        (
            ts_hit_object_def {
                vulnerable_count: 3,
                ..base
            },
            NULL,
            "def.vulnerable is a null pointer",
        ),
    ];
    const INVALID: ts_status = TS_ERROR_INVALID_ARGUMENT;
    const NULL: ts_status = TS_ERROR_NULL_POINTER;
    // SAFETY: each call gets one bad argument on purpose; the rest are valid.
    unsafe {
        let mut id = ts_hit_object_id {
            index: 7,
            generation: 7,
        };
        for (def, status, words) in cases {
            assert_refused(ts_hit_world_add(w, &def, &mut id), status, words);
            assert_eq!((id.index, id.generation), (7, 7), "out written on failure");
        }
        assert_eq!(ts_hit_world_count(w), 0);
        assert_refused(
            ts_hit_world_add(w, ptr::null(), &mut id),
            NULL,
            "def is a null pointer",
        );
        assert_refused(
            ts_hit_world_add(w, &base, ptr::null_mut()),
            NULL,
            "out is a null pointer",
        );
        assert_refused(
            ts_hit_world_add(ptr::null_mut(), &base, &mut id),
            NULL,
            "world is a null pointer",
        );
        let id = add(w, &base);
        assert_refused(ts_hit_world_move(w, id, f32::NAN, 0.0), INVALID, "x is NaN");
        assert_refused(ts_hit_world_move(w, id, 0.0, -1e20), INVALID, "y is");
        let bad = ts_hit_object_def {
            x: f32::NEG_INFINITY,
            ..base
        };
        assert_refused(ts_hit_world_set(w, id, &bad), INVALID, "def.x");
        assert_refused(ts_hit_world_set(w, id, ptr::null()), NULL, "def");
        assert_refused(ts_hit_world_step(ptr::null_mut()), NULL, "world");
        let mut n = 0;
        assert_refused(
            ts_hit_world_events(ptr::null(), ptr::null_mut(), 0, &mut n),
            NULL,
            "world",
        );
        assert_refused(ts_hit_world_create(ptr::null_mut()), NULL, "out");
        assert_eq!(ts_hit_world_count(ptr::null()), 0);
        ts_hit_world_free(w);
        ts_hit_world_free(ptr::null_mut());
    }
}
