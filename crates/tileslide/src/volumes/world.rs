//! The frame's objects and their hits: registration, broadphase, the attack-against-
//! vulnerability test, acceptance and "hit once per swing".

use std::collections::HashSet;

use glam::Vec2;

use super::HitTypes;
use super::contact::Contact;
use super::event::{HitEvent, HitRule};
use super::object::{HitObject, ObjectId};
use super::placed::Placed;
use super::trace::{DetectTrace, HitSink, NoTrace, PairOutcome, Recorder, VolumeTest};
use super::volume::{Volume, VolumeError};
use crate::broadphase::{PairFinder, PairMethod};
use crate::geometry::{Aabb, Circle};
use crate::owner::Owner;

/// The most attack volumes, and the most vulnerable volumes, one hit object may have.
pub const MAX_OBJECT_VOLUMES: usize = 1024;

/// The most hit objects a [`HitWorld`] takes in one frame.
pub const MAX_HIT_OBJECTS: usize = 1 << 20;

/// The most attack volumes, and the most vulnerable volumes, a [`HitWorld`] takes in one
/// frame, all objects together.
pub const MAX_FRAME_VOLUMES: usize = 1 << 24;

/// A registered object and where its volumes are.
#[derive(Clone, Copy, Debug)]
pub(super) struct Entry {
    pub(super) object: HitObject,
    /// The unit vector its attack volumes are turned by ([`HitObject::aim`] normalized).
    #[cfg(feature = "aim")]
    turn: Option<Vec2>,
    /// Ranges in `attack` and `vulnerable`.
    pub(super) attack: (u32, u32),
    pub(super) vulnerable: (u32, u32),
    /// Every point any of its volumes takes during the frame.
    pub(super) reach: Aabb,
}

impl Entry {
    /// Where the object's volumes' local origin is when the frame starts.
    #[cfg_attr(feature = "aim", inline)]
    fn start(&self) -> Vec2 {
        self.object.position - self.object.motion
    }

    /// Attack volume `v` with the object's local origin at `position`: mirrored by its
    /// facing, turned by its aim.
    #[cfg_attr(feature = "aim", inline)]
    pub(super) fn attack_volume(&self, v: &Volume, position: Vec2) -> Placed {
        let o = &self.object;
        match self.turn() {
            #[cfg(feature = "aim")]
            Some(turn) => Placed::turned(&v.shape, position, o.size, o.facing, turn),
            _ => Placed::new(&v.shape, position, o.size, o.facing),
        }
    }

    /// Vulnerability volume `v` with the object's local origin at `position`: mirrored by
    /// its facing.
    #[cfg_attr(feature = "aim", inline)]
    pub(super) fn vulnerable_volume(&self, v: &Volume, position: Vec2) -> Placed {
        let o = &self.object;
        Placed::new(&v.shape, position, o.size, o.facing)
    }

    /// The unit vector its attack volumes are turned by (`None`: not turned).
    #[cfg_attr(feature = "aim", inline)]
    fn turn(&self) -> Option<Vec2> {
        #[cfg(feature = "aim")]
        return self.turn;
        #[cfg(not(feature = "aim"))]
        None
    }
}

/// Calls `f` with each of `attack` (turned by `turn`), then each of `vulnerable`, of
/// `object` placed where the frame ends.
#[cfg_attr(feature = "aim", inline)]
#[cfg_attr(not(feature = "aim"), allow(unused_variables))]
fn each_placed(
    object: &HitObject,
    turn: Option<Vec2>,
    attack: &[Volume],
    vulnerable: &[Volume],
    mut f: impl FnMut(Placed),
) {
    let o = object;
    let upright = |v: &Volume| Placed::new(&v.shape, o.position, o.size, o.facing);
    // Without turning, one loop: `f` is built once (the web package counts its bytes).
    #[cfg(not(feature = "aim"))]
    for v in attack.iter().chain(vulnerable) {
        f(upright(v));
    }
    #[cfg(feature = "aim")]
    {
        for v in attack {
            f(match turn {
                Some(turn) => Placed::turned(&v.shape, o.position, o.size, o.facing, turn),
                None => upright(v),
            });
        }
        for v in vulnerable {
            f(upright(v));
        }
    }
}

/// Attack and vulnerability volumes of the objects of one frame, and the hits between them
/// (Replica Island's "moving objects vs each other", with its flaws fixed).
///
/// Each frame: [`begin_frame`](Self::begin_frame), [`register`](Self::register) every
/// object with the volumes of its current animation frame, then
/// [`detect`](Self::detect). A pair of objects is tested when the boxes of all their
/// volumes (over the frame's move) overlap, which never misses an overlap, unlike a
/// bounding circle of `max(w, h) / 2`. In each direction, the **first attack volume** (in
/// list order) that meets a vulnerability volume accepting one of its types gives one
/// hit, with the time and the point where it first touches such a vulnerability volume.
///
/// Events come in a fixed order, whatever the broadphase: by pair `(i, j)`, `i < j` in
/// registration order, then `i` hitting `j` before `j` hitting `i`. They stay readable
/// until the next `detect` ([`events`](Self::events)), or until taken
/// ([`drain_events`](Self::drain_events)).
///
/// ```
/// use tileslide::{HitObject, HitTypes, HitWorld, Owner, TeamRule, Vec2, Volume};
/// let mut world = HitWorld::new();
/// world.begin_frame();
/// let hero = HitObject { team: 1, ..HitObject::new(Owner(1), Vec2::ZERO, Vec2::new(1.0, 2.0)) };
/// let fist = [Volume::circle(Vec2::new(1.3, 1.0), 0.3, HitTypes::HIT)?];
/// let body = [Volume::rect(Vec2::new(0.5, 1.0), Vec2::new(0.5, 1.0), HitTypes::ANY)?];
/// let hero = world.register(hero, &fist, &body)?;
/// let slime = HitObject::new(Owner(2), Vec2::new(1.5, 0.0), Vec2::ONE);
/// let slime = world.register(slime, &[], &body[..1])?;
/// let hits = world.detect(&mut TeamRule);
/// assert_eq!(hits.len(), 1);
/// assert_eq!((hits[0].attacker, hits[0].victim), (hero, slime));
/// assert_eq!((hits[0].attacker_owner, hits[0].victim_owner), (Owner(1), Owner(2)));
/// assert_eq!(hits[0].hit_type, HitTypes::HIT);
/// assert!(hits[0].accepted);
/// // Nothing moved: they overlap from the start; the point is the body's point nearest
/// // the fist's centre.
/// assert_eq!((hits[0].t, hits[0].point), (0.0, Vec2::new(1.5, 1.0)));
/// # Ok::<(), tileslide::VolumeError>(())
/// ```
#[derive(Clone, Debug, Default)]
pub struct HitWorld {
    pub(crate) broadphase: PairMethod,
    pub(super) entries: Vec<Entry>,
    pub(super) attack: Vec<Volume>,
    pub(super) vulnerable: Vec<Volume>,
    finder: PairFinder,
    boxes: Vec<Aabb>,
    pairs: Vec<(u32, u32)>,
    /// The last `detect`'s events, kept until the next one.
    pub(crate) events: Vec<HitEvent>,
    /// Accepted hits per swing: `(swing, victim owner)`.
    pub(crate) swung: HashSet<(u64, Owner)>,
    /// Swings registered this frame and the last.
    pub(crate) swings_now: HashSet<u64>,
    swings_before: HashSet<u64>,
}

impl HitWorld {
    /// An empty world using sweep and prune on x, as Replica Island does.
    #[must_use]
    pub fn new() -> Self {
        Self::with_broadphase(PairMethod::SweepAndPrune)
    }

    /// An empty world using `broadphase` (the results are the same either way).
    #[must_use]
    pub fn with_broadphase(broadphase: PairMethod) -> Self {
        Self {
            broadphase,
            ..Self::default()
        }
    }

    /// Starts a frame: forgets the last frame's objects, and ends the swings nobody
    /// registered in it. The last [`detect`](Self::detect)'s events stay readable.
    pub fn begin_frame(&mut self) {
        self.entries.clear();
        self.attack.clear();
        self.vulnerable.clear();
        std::mem::swap(&mut self.swings_before, &mut self.swings_now);
        self.swings_now.clear();
        let live = &self.swings_before;
        self.swung.retain(|(swing, _)| live.contains(swing));
    }

    /// Registers an object for this frame with its attack and vulnerability volumes
    /// (copied).
    ///
    /// # Errors
    ///
    /// What [`HitObject::check`] or [`Volume::check`] says of the object or of its first
    /// bad volume (a NaN, infinite or out-of-range position, start, size, centre or
    /// corner, or an aim of zero); the world is unchanged. So every pair test computes
    /// within a few times [`MAX_COORD`](crate::limits::MAX_COORD), where nothing overflows
    /// (a box at 3·10³⁸ once missed a box it lay in, its centre overflowing to infinity).
    /// [`VolumeError::TooMany`] past [`MAX_OBJECT_VOLUMES`] volumes in a list,
    /// [`MAX_HIT_OBJECTS`] objects or [`MAX_FRAME_VOLUMES`] volumes of a kind this frame,
    /// checked before anything is copied.
    pub fn register(
        &mut self,
        object: HitObject,
        attack: &[Volume],
        vulnerable: &[Volume],
    ) -> Result<ObjectId, VolumeError> {
        if self.entries.len() >= MAX_HIT_OBJECTS {
            return Err(VolumeError::TooMany {
                what: "hit objects this frame",
                count: self.entries.len() + 1,
                max: MAX_HIT_OBJECTS,
            });
        }
        for (what, frame, list, before) in [
            (
                "attack volumes",
                "attack volumes this frame",
                attack,
                self.attack.len(),
            ),
            (
                "vulnerable volumes",
                "vulnerable volumes this frame",
                vulnerable,
                self.vulnerable.len(),
            ),
        ] {
            if list.len() > MAX_OBJECT_VOLUMES {
                return Err(VolumeError::TooMany {
                    what,
                    count: list.len(),
                    max: MAX_OBJECT_VOLUMES,
                });
            }
            if before + list.len() > MAX_FRAME_VOLUMES {
                return Err(VolumeError::TooMany {
                    what: frame,
                    count: before + list.len(),
                    max: MAX_FRAME_VOLUMES,
                });
            }
        }
        #[cfg_attr(not(feature = "aim"), allow(unused_variables))]
        let turn = object.checked_turn()?;
        for v in attack.iter().chain(vulnerable) {
            v.check()?;
        }
        let mut reach: Option<Aabb> = None;
        let mut add = |end: Aabb| {
            let start = Aabb {
                min: end.min - object.motion,
                max: end.max - object.motion,
            };
            let both = Aabb {
                min: start.min.min(end.min),
                max: start.max.max(end.max),
            };
            reach = Some(reach.map_or(both, |r| Aabb {
                min: r.min.min(both.min),
                max: r.max.max(both.max),
            }));
        };
        let o = &object;
        let upright = |v: &Volume| Placed::new_aabb(&v.shape, o.position, o.size, o.facing);
        // Without turning, one loop (the web package counts the bytes of each copy of `add`).
        #[cfg(not(feature = "aim"))]
        for v in attack.iter().chain(vulnerable) {
            add(upright(v));
        }
        #[cfg(feature = "aim")]
        {
            for v in attack {
                add(match turn {
                    Some(turn) => {
                        Placed::turned(&v.shape, o.position, o.size, o.facing, turn).aabb()
                    }
                    None => upright(v),
                });
            }
            for v in vulnerable {
                add(upright(v));
            }
        }
        if let Some(swing) = object.swing {
            self.swings_now.insert(swing);
        }
        let id = ObjectId(self.entries.len() as u32);
        let a0 = self.attack.len() as u32;
        self.attack.extend_from_slice(attack);
        let v0 = self.vulnerable.len() as u32;
        self.vulnerable.extend_from_slice(vulnerable);
        self.entries.push(Entry {
            object,
            #[cfg(feature = "aim")]
            turn,
            attack: (a0, self.attack.len() as u32),
            vulnerable: (v0, self.vulnerable.len() as u32),
            // An object without volumes gets a box that overlaps nothing (NaN compares
            // false), so it never reaches the exact test.
            reach: reach.unwrap_or(Aabb {
                min: Vec2::NAN,
                max: Vec2::NAN,
            }),
        });
        Ok(id)
    }

    /// The object registered as `id` this frame.
    #[must_use]
    pub fn object(&self, id: ObjectId) -> Option<&HitObject> {
        self.entries.get(id.0 as usize).map(|e| &e.object)
    }

    /// A circle holding every volume of `id` at the end of the frame: centred on the box of
    /// its volumes, as large as the farthest point of any of them. `None` without volumes.
    #[must_use]
    pub fn bounding_circle(&self, id: ObjectId) -> Option<Circle> {
        let e = self.entries.get(id.0 as usize)?;
        let (attack, vulnerable) = self.volumes_of(e);
        let mut bounds: Option<Aabb> = None;
        each_placed(&e.object, e.turn(), attack, vulnerable, |p| {
            let b = p.aabb();
            bounds = Some(bounds.map_or(b, |r| Aabb {
                min: r.min.min(b.min),
                max: r.max.max(b.max),
            }));
        });
        let center = (bounds?.min + bounds?.max) * 0.5;
        let mut radius = 0.0f32;
        each_placed(&e.object, e.turn(), attack, vulnerable, |p| {
            radius = radius.max(p.reach_from(center))
        });
        // One part in a million more, so rounding in the distances never leaves a volume's
        // edge outside.
        Some(Circle::new(center, radius * (1.0 + 1e-6) + f32::EPSILON))
    }

    /// The attack and vulnerability volumes registered with `e`.
    #[cfg_attr(feature = "aim", inline)]
    pub(super) fn volumes_of(&self, e: &Entry) -> (&[Volume], &[Volume]) {
        let (a0, a1) = e.attack;
        let (v0, v1) = e.vulnerable;
        (
            &self.attack[a0 as usize..a1 as usize],
            &self.vulnerable[v0 as usize..v1 as usize],
        )
    }

    /// Finds this frame's hits, asks `rule` whether each victim takes its hit, and returns
    /// the events (see the type's documentation for the order). An attack with a swing that
    /// already landed on a victim (accepted) does not hit it again until the swing ends.
    ///
    /// Each event says when and where the hit happened: `t`, the fraction of the frame's
    /// move at which the attack volume first touched a vulnerability volume it hits, exact
    /// for volumes that move (the time of impact along their relative move); and `point`,
    /// where they touched then. Of the vulnerability volumes the attack volume meets, the
    /// first it touches gives the event (on equal `t`, the first in list order). For
    /// volumes that already overlap where the frame starts, `t` is 0 and `point` is a
    /// point of the overlap: the middle of two upright rectangles' common rectangle; the
    /// rectangle's point nearest a circle's centre; for two circles, the middle of the
    /// stretch of the line between their centres that both cover; for a turned rectangle
    /// or a capsule, the middle of the part the shapes' cores (the rectangle, the capsule's
    /// segment, the circle's centre) share, or the middle of the stretch both cover between
    /// their cores' nearest points.
    pub fn detect(&mut self, rule: &mut impl HitRule) -> &[HitEvent] {
        self.detect_into(rule, &mut NoTrace);
        &self.events
    }

    /// [`detect`](Self::detect), writing into `trace` (cleared first) what it did with
    /// each pair, in each direction: the volumes it tested and whether they met, and the
    /// outcome: boxes apart (for a trace [`of`](DetectTrace::of) one owner), the swing had
    /// already hit, no volumes, no type in common, missed, or the event, accepted or
    /// refused and by which rule ([`HitRule::refusal`]). The events are the ones `detect`
    /// finds.
    pub fn detect_traced(
        &mut self,
        rule: &mut impl HitRule,
        trace: &mut DetectTrace,
    ) -> &[HitEvent] {
        trace.pairs.clear();
        let mut recorder = Recorder {
            trace,
            tests: Vec::new(),
        };
        self.detect_into(rule, &mut recorder);
        let trace = recorder.trace;
        if let Some(owner) = trace.owner() {
            // The objects whose boxes were apart from the owner's: both directions, then
            // every pair in the events' order.
            let n = self.entries.len() as u32;
            for (i, e) in (0..n).zip(&self.entries) {
                if e.object.owner != owner {
                    continue;
                }
                for j in (0..n).filter(|&j| j != i) {
                    let (lo, hi) = (i.min(j), i.max(j));
                    let pair_found = self.pairs.binary_search(&(lo, hi)).is_ok();
                    let other_listed = self.entries[j as usize].object.owner == owner && j < i;
                    if pair_found || other_listed {
                        continue;
                    }
                    for (a, v) in [(lo, hi), (hi, lo)] {
                        trace.pairs.push(self.apart(a, v));
                    }
                }
            }
            trace.pairs.sort_by_key(|p| {
                let (a, v) = (p.attacker.0, p.victim.0);
                (a.min(v), a.max(v), a > v)
            });
        }
        &self.events
    }

    /// The pair `a` attacking `v` when their boxes are apart.
    fn apart(&self, a: u32, v: u32) -> super::PairTrace {
        super::PairTrace {
            attacker: ObjectId(a),
            victim: ObjectId(v),
            attacker_owner: self.entries[a as usize].object.owner,
            victim_owner: self.entries[v as usize].object.owner,
            tests: Vec::new(),
            outcome: PairOutcome::BoxesApart,
        }
    }

    /// `detect`, telling `sink` what it does.
    fn detect_into(&mut self, rule: &mut impl HitRule, sink: &mut impl HitSink) {
        self.events.clear();
        self.boxes.clear();
        self.boxes.extend(self.entries.iter().map(|e| e.reach));
        self.pairs.clear();
        self.finder
            .find(self.broadphase, &self.boxes, &mut self.pairs);
        #[cfg(feature = "parallel")]
        if !sink.records()
            && self.pairs.len() >= 2 * PAIRS_PER_TASK
            && rayon::current_num_threads() > 1
        {
            self.detect_split(rule);
            return;
        }
        self.pairs.sort_unstable();
        for k in 0..self.pairs.len() {
            let (i, j) = self.pairs[k];
            self.hit(i, j, rule, sink);
            self.hit(j, i, rule, sink);
        }
    }

    /// The untraced `detect_into` with the volumes of every pair tested on the threads of
    /// the current rayon pool (the `parallel` feature), in both directions; then, in pair
    /// order on the calling thread, what depends on order: swings that already hit, the
    /// rule, the events. The tests are pure, so the events are those of one thread, in the
    /// same order (a pair a swing already hit is tested for nothing).
    #[cfg(feature = "parallel")]
    fn detect_split(&mut self, rule: &mut impl HitRule) {
        use rayon::prelude::*;
        self.pairs.par_sort_unstable();
        let this = &*self;
        let met: Vec<[Option<Meeting>; 2]> = self
            .pairs
            .par_iter()
            .with_min_len(PAIRS_PER_TASK)
            .map(|&(i, j)| {
                let mut none = NoTrace;
                [this.meeting(i, j, &mut none), this.meeting(j, i, &mut none)]
            })
            .collect();
        for (k, met) in met.into_iter().enumerate() {
            let (i, j) = self.pairs[k];
            for ((a, v), meeting) in [(i, j), (j, i)].into_iter().zip(met) {
                if !self.swing_already_hit(a, v, &mut NoTrace) {
                    self.record(a, v, meeting, rule, &mut NoTrace);
                }
            }
        }
    }

    /// The last [`detect`](Self::detect)'s events, readable until the next `detect` (a new
    /// frame keeps them; [`drain_events`](Self::drain_events) takes them).
    #[must_use]
    pub fn events(&self) -> &[HitEvent] {
        &self.events
    }

    /// Takes the last [`detect`](Self::detect)'s events, in order, leaving none.
    pub fn drain_events(&mut self) -> std::vec::Drain<'_, HitEvent> {
        self.events.drain(..)
    }

    /// `a` attacking `v`: the first attack volume of `a` that meets a vulnerability volume
    /// of `v` accepting one of its types, at the first of those it touches.
    fn hit(&mut self, a: u32, v: u32, rule: &mut impl HitRule, sink: &mut impl HitSink) {
        if self.swing_already_hit(a, v, sink) {
            return;
        }
        let meeting = self.meeting(a, v, sink);
        self.record(a, v, meeting, rule, sink);
    }

    /// Whether `a`'s swing (if it swings) already hit `v`'s owner: then `a` does not attack
    /// `v` again.
    fn swing_already_hit(&self, a: u32, v: u32, sink: &mut impl HitSink) -> bool {
        let (ea, ev) = (&self.entries[a as usize], &self.entries[v as usize]);
        let Some(swing) = ea.object.swing else {
            return false;
        };
        let hit = self.swung.contains(&(swing, ev.object.owner));
        let owners = (ea.object.owner, ev.object.owner);
        if hit && sink.wants(owners.0, owners.1) {
            let ids = (ObjectId(a), ObjectId(v));
            sink.outcome(ids, owners, PairOutcome::SwingAlreadyHit { swing });
        }
        hit
    }

    /// The volumes' part of `a` attacking `v`, which reads nothing but the two objects: the
    /// first attack volume of `a` that meets a vulnerability volume of `v` accepting one of
    /// its types, and when and where it first touches one; `None` (told to `sink`, with
    /// why) when none meets.
    fn meeting(&self, a: u32, v: u32, sink: &mut impl HitSink) -> Option<Meeting> {
        let (ea, ev) = (&self.entries[a as usize], &self.entries[v as usize]);
        let owners = (ea.object.owner, ev.object.owner);
        let traced = sink.wants(owners.0, owners.1);
        // Relative motion: in the victim's frame the attacker moves by the difference.
        let motion = ea.object.motion - ev.object.motion;
        let attacks = &self.attack[ea.attack.0 as usize..ea.attack.1 as usize];
        let vulnerable = &self.vulnerable[ev.vulnerable.0 as usize..ev.vulnerable.1 as usize];
        let found = attacks.iter().enumerate().find_map(|(i, attack)| {
            let from = ea.attack_volume(attack, ea.start());
            vulnerable.iter().enumerate().find_map(|(k, target)| {
                let dealt = attack.hit & target.hit;
                let met = !dealt.is_empty()
                    && from.meets(motion, &ev.vulnerable_volume(target, ev.start()));
                if traced {
                    sink.test(VolumeTest {
                        attack: i,
                        vulnerable: k,
                        dealt,
                        met,
                    });
                }
                met.then_some((attack, k, dealt))
            })
        });
        let Some((attack, k, dealt)) = found else {
            if traced {
                let ids = (ObjectId(a), ObjectId(v));
                sink.outcome(ids, owners, missed(attacks, vulnerable));
            }
            return None;
        };
        let (hit_type, contact) = first_contact(
            ea,
            attack,
            ev,
            (&vulnerable[k], dealt),
            &vulnerable[k + 1..],
        );
        Some(Meeting {
            hit_type,
            t: contact.t,
            point: contact.point,
        })
    }

    /// What follows `a` attacking `v` once its volumes met (or not): the rule's word, the
    /// swing's memory and the event.
    fn record(
        &mut self,
        a: u32,
        v: u32,
        meeting: Option<Meeting>,
        rule: &mut impl HitRule,
        sink: &mut impl HitSink,
    ) {
        let Some(Meeting { hit_type, t, point }) = meeting else {
            return;
        };
        let (ea, ev) = (&self.entries[a as usize], &self.entries[v as usize]);
        let owners = (ea.object.owner, ev.object.owner);
        let ids = (ObjectId(a), ObjectId(v));
        let accepted = rule.accept(&ea.object, &ev.object, hit_type);
        if sink.wants(owners.0, owners.1) {
            let event = self.events.len();
            let outcome = if accepted {
                PairOutcome::Accepted { event }
            } else {
                let by = rule.refusal(&ea.object, &ev.object, hit_type);
                PairOutcome::Refused { event, by }
            };
            sink.outcome(ids, owners, outcome);
        }
        if accepted && let Some(swing) = ea.object.swing {
            self.swung.insert((swing, ev.object.owner));
        }
        self.events.push(HitEvent {
            attacker: ids.0,
            victim: ids.1,
            attacker_owner: owners.0,
            victim_owner: owners.1,
            hit_type,
            accepted,
            t,
            point,
        });
    }
}

/// Where an attack met a victim: the type dealt, and when and where they first touch.
#[derive(Clone, Copy, Debug)]
struct Meeting {
    hit_type: HitTypes,
    t: f32,
    point: Vec2,
}

/// Pairs a task of [`HitWorld::detect`] tests at least, with the `parallel` feature (and
/// fewer than two tasks' worth stay on the calling thread).
#[cfg(feature = "parallel")]
const PAIRS_PER_TASK: usize = 512;

/// Why no attack volume of `attacks` met a volume of `vulnerable`.
fn missed(attacks: &[Volume], vulnerable: &[Volume]) -> PairOutcome {
    if attacks.is_empty() || vulnerable.is_empty() {
        PairOutcome::NoVolumes
    } else if attacks
        .iter()
        .all(|a| vulnerable.iter().all(|v| (a.hit & v.hit).is_empty()))
    {
        PairOutcome::NoTypeInCommon
    } else {
        PairOutcome::Missed
    }
}

/// When and where `attack` of `ea` first touches a vulnerability volume of `ev`: `target`,
/// the first it meets, dealing `dealt`, unless one of the `rest` that it meets and that
/// accepts one of its types is touched earlier. With the types dealt. (Out of `hit`, which
/// is built once per rule; placing the pair again costs less than carrying it out of the
/// search.)
fn first_contact(
    ea: &Entry,
    attack: &Volume,
    ev: &Entry,
    (target, dealt): (&Volume, HitTypes),
    rest: &[Volume],
) -> (HitTypes, Contact) {
    let (ma, mv) = (ea.object.motion, ev.object.motion);
    let from = ea.attack_volume(attack, ea.start());
    let mut first = (
        dealt,
        from.contact(ma, &ev.vulnerable_volume(target, ev.start()), mv),
    );
    for target in rest {
        if first.1.t == 0.0 {
            // Nothing touches earlier.
            break;
        }
        let dealt = attack.hit & target.hit;
        let to = ev.vulnerable_volume(target, ev.start());
        if dealt.is_empty() || !from.meets(ma - mv, &to) {
            continue;
        }
        let contact = from.contact(ma, &to, mv);
        if contact.t < first.1.t {
            first = (dealt, contact);
        }
    }
    first
}
