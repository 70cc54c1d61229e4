//! The resolve on many threads (the `parallel` feature), with the result of one thread, bit
//! for bit.
//!
//! Resolving a body reads the walls near it, its own start and move, and the positions of
//! its neighbours (the rows of `neighbours`: the bodies whose reach discs touch its own):
//! in slot order, those in lower slots where they ended, the others where they started.
//! Nothing else: two bodies that are not neighbours never read each other. So the bodies
//! are put in waves: a body's wave is one past the last wave of its candidates in lower
//! slots (wave 0 if it has none), the candidates being the superset of its rows that the
//! neighbours keep for several steps. Bodies of one wave are never neighbours, and when a
//! wave runs, each of its bodies' lower neighbours has ended (an earlier wave) and each
//! higher one has not started (a later wave): it reads exactly what it reads in slot order.
//! The moving bodies of a wave are resolved on every thread; the task that resolves a body
//! writes where it ended and what its resolve found (whether it moved, its contacts) into
//! the body's entry of an array every task reads ([`Shared`], relaxed atomics), which later
//! waves read. What no later body reads (the resolved moves, the report's counts, the settled
//! memory, the flags that disturb settled bodies next step) is written once every wave has
//! run, again on every thread.
//!
//! Made from the candidates rather than the rows, and for every body whether it moves or
//! not, the schedule holds for every step until the candidates are found again (about
//! every fifth step in the crowd scene), so it is made only then; it has more waves than
//! the rows would give, as the candidates chain further, and it reads only the
//! candidates, so it is made beside the filling of the rows. The walls near every moving
//! circle are gathered first, beside the neighbours, into the same memory the sequential
//! resolve keeps (`NearWalls::around_all`); the waves only read it.
//!
//! There are as many waves as the longest chain of candidates in increasing slot order.
//! Slots in no spatial order, as a crowd spawned at random has them, give short chains
//! (14 to 21 waves for the crowd scene's 50,000 circles, 6 to 8 for 10,000); bodies added
//! one after another along a packed queue give one body a wave, and the resolve then runs
//! one body at a time, with the same result, no faster than on one thread.

use std::ops::Range;
use std::sync::atomic::{AtomicU64, Ordering};

use glam::Vec2;
use rayon::prelude::*;

use super::{Mover, Resolver, Seen, Stand, find_neighbours, wake_where_changed};
use crate::bodies::body::Body;
use crate::bodies::config::{ResolveConfig, ResolveReport};
use crate::bodies::map_watch::MapChange;
use crate::bodies::neighbours::{CandidateRows, Neighbours};
use crate::bodies::trace::Recorder;
use crate::tiles::TileMap;

/// Bodies a task resolves at least: a task hand-over costs about as much as resolving a
/// free body.
const MIN_BODIES_PER_TASK: usize = 32;

/// Bodies a task resolves at most: a wave ends when its last task does, and a thread that
/// runs out of work can take only a task not yet started, so long tasks leave it waiting at
/// every wave's end (14 to 21 waves a step in the crowd scene). Measured on the crowd of
/// 50,000 on two threads of an EPYC, two worlds stepped alternately in one process against
/// tasks as long as rayon's splitting leaves them: 128 bodies 3.1-3.5 % faster a step, 96
/// 2.7-3.0 %, 192 2.5-2.8 %, 64 1.9 %, 256 2.1 %.
const MAX_BODIES_PER_TASK: usize = 128;

/// How many bodies ahead in its wave a task asks for a body's own entries (its start, move,
/// first circle and settled memory), for its circles' (their walls' range, shape and row's
/// place), for its circles' walls and rows, which need those read first, for its
/// neighbours' circles' entries (where each stands), which need the rows, and, for a body
/// blocked in place last time, whether its neighbours moved, which needs the circles'
/// bodies. A body left settled takes a few dozen nanoseconds, a
/// moving one a microsecond or more: far enough ahead for a run of settled bodies. Measured
/// on the crowd of 50,000 on two threads (docs/parallel.md): the first three stages made
/// the step 9 % faster, the neighbours' two another 10 %; 32, 16, 8, 4, 2 and 32, 12, 6,
/// 3, 1 did no better within this machine's noise.
const AHEAD: [usize; 5] = [32, 8, 4, 2, 1];

/// What resolving one body of a wave found.
#[derive(Clone, Copy, Debug)]
struct Outcome {
    /// Where it ended (its start is `position`).
    end: Vec2,
    contacts: u32,
    cut_short: bool,
    /// Skipped as blocked in place again (see `settled`): `end` is its start.
    stayed: bool,
}

/// The waves' buffers, kept between resolves.
#[derive(Debug, Default)]
pub(super) struct Waves {
    schedule: Schedule,
    /// Per circle, its range of `near`'s walls (`(0, 0)` for still bodies).
    ranges: Vec<(u32, u32)>,
    /// Per body, where it stands and, once its wave has run, what its resolve found.
    shared: Vec<Shared>,
    /// Per circle, where it stands, its radius and its body: what a neighbour reads of it.
    circles: Vec<SharedCircle>,
}

/// A copy keeps the schedule; the buffers are filled anew by every resolve.
impl Clone for Waves {
    fn clone(&self) -> Self {
        Self {
            schedule: self.schedule.clone(),
            ..Self::default()
        }
    }
}

/// A body's entry the tasks of the waves share: where it stands (its start, then its end
/// once its wave has run) and, once its wave has run, what its resolve found (see
/// [`Found`]). A body's entry is written by the task that resolves it, and read only by
/// bodies of later waves (after the join that ends its wave) or once every wave has run
/// (see the module doc), so relaxed loads and stores see exactly what the resolve in slot
/// order would read; on x86-64 they are plain moves. Neighbours read a body's circles'
/// entries ([`SharedCircle`]) for where it stands, and this entry for whether it moved
/// (a body blocked in place last time, to tell whether it was disturbed); the pass after
/// the waves reads these entries front to back.
#[derive(Debug, Default)]
struct Shared {
    at: AtomicU64,
    found: AtomicU64,
}

/// A point's coordinates' bits in 64 bits.
fn pack(at: Vec2) -> u64 {
    u64::from(at.x.to_bits()) | (u64::from(at.y.to_bits()) << 32)
}

/// The point [`pack`] packed.
fn unpack(bits: u64) -> Vec2 {
    Vec2::new(
        f32::from_bits(bits as u32),
        f32::from_bits((bits >> 32) as u32),
    )
}

impl Shared {
    fn get(&self) -> Vec2 {
        unpack(self.at.load(Ordering::Relaxed))
    }

    fn set(&self, at: Vec2) {
        self.at.store(pack(at), Ordering::Relaxed);
    }

    fn found(&self) -> Found {
        Found(self.found.load(Ordering::Relaxed))
    }

    fn set_found(&self, found: Found) {
        self.found.store(found.0, Ordering::Relaxed);
    }
}

/// What a body's resolve in its wave found, in 64 bits: whether it was resolved (it had
/// a move), moved, stayed as blocked in place again (see `settled`), was cut short, and its
/// contacts. Zero for a body without a move.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Found(u64);

impl Found {
    const RESOLVED: u64 = 1;
    const MOVED: u64 = 1 << 1;
    const STAYED: u64 = 1 << 2;
    const CUT_SHORT: u64 = 1 << 3;

    /// What `outcome` says, for a body that started at `start`.
    fn of(outcome: &Outcome, start: Vec2) -> Self {
        let flag = |yes: bool, bit: u64| if yes { bit } else { 0 };
        Self(
            Self::RESOLVED
                | flag(!outcome.stayed && outcome.end != start, Self::MOVED)
                | flag(outcome.stayed, Self::STAYED)
                | flag(outcome.cut_short, Self::CUT_SHORT)
                | (u64::from(outcome.contacts) << 32),
        )
    }

    fn resolved(self) -> bool {
        self.0 & Self::RESOLVED != 0
    }

    fn moved(self) -> bool {
        self.0 & Self::MOVED != 0
    }

    fn stayed(self) -> bool {
        self.0 & Self::STAYED != 0
    }

    fn cut_short(self) -> bool {
        self.0 & Self::CUT_SHORT != 0
    }

    fn contacts(self) -> usize {
        (self.0 >> 32) as usize
    }
}

/// A circle's entry the tasks of the waves share, what a neighbour reads of it: where it
/// stands (its body's start plus its offset, then its body's end plus its offset once its
/// body's wave has run, written by the task that resolves the body, under the same rules
/// as [`Shared`]), its radius and its body. One entry rather than the circle's and then
/// its body's: one cache line a neighbour.
#[derive(Debug, Default)]
struct SharedCircle {
    at: AtomicU64,
    radius: f32,
    body: u32,
}

impl SharedCircle {
    fn set(&self, at: Vec2) {
        self.at.store(pack(at), Ordering::Relaxed);
    }
}

impl Stand for [SharedCircle] {
    #[inline]
    fn circle(&self, c: usize) -> Seen {
        let circle = &self[c];
        Seen {
            at: unpack(circle.at.load(Ordering::Relaxed)),
            radius: circle.radius,
            body: circle.body,
        }
    }
}

impl Resolver {
    /// Resolves every body in waves, into `report`; `load` has run.
    ///
    /// First, side by side on the pool's threads, three pieces of work that read and write
    /// different things: finding the neighbours (the candidates, then the rows, beside
    /// which the waves' schedule is made when the candidates were found again: each body's
    /// wave follows from those of the bodies before it, so the schedule is one thread's
    /// work); the walls near each moving circle; the memories' start. The sequential
    /// resolve does the same work with the same inputs, the walls as each body comes.
    ///
    /// Each wave's tasks write where their bodies ended and whether each moved, for the
    /// later waves; what the sequential resolve writes as it goes and later bodies do not
    /// read (the resolved moves, the report's counts, the settled memory, the flags for the
    /// next step) is written at the end, on every thread. A body that moved disturbs its
    /// neighbours (see `settled`): the ones after it in slot order this step, which a body
    /// checks at its turn by reading whether its lower neighbours moved, and the ones
    /// before it next step, flagged at the end.
    pub(super) fn resolve_in_waves(
        &mut self,
        bodies: &mut [&mut Body],
        config: &ResolveConfig,
        map: &TileMap,
        report: &mut ResolveReport,
    ) {
        let gap = config.gap;
        let n = bodies.len();
        let mut waves = std::mem::take(&mut self.waves);
        let change = self.map_changes(map);
        let Self {
            circles,
            circle_body,
            first_circle,
            position,
            motion,
            filter,
            reach_discs,
            boxes,
            neighbours,
            near,
            watch,
            settled,
            ..
        } = self;
        let (schedule, ranges) = (&mut waves.schedule, &mut waves.ranges);
        let (circle_body, motion, filter) = (&*circle_body, &*motion, &*filter);
        let (reach_discs, boxes) = (&*reach_discs, &*boxes);
        let neighbours_and_schedule = || {
            find_neighbours(
                neighbours,
                config,
                map,
                reach_discs,
                boxes,
                circle_body,
                filter,
                |candidates| {
                    schedule.make(&Shape {
                        circle_body,
                        first_circle,
                        candidates,
                    });
                },
            );
        };
        let walls = || {
            near.around_all(
                reach_discs,
                |c| {
                    let b = circle_body[c] as usize;
                    (motion[b] != Vec2::ZERO).then_some(filter[b].walls)
                },
                gap,
                map,
                ranges,
            );
        };
        let (shared, shared_circles) = (&mut waves.shared, &mut waves.circles);
        let memories = || {
            // Where each body and circle stands when the waves start (a circle's reach
            // disc is centred there); what each found is written by its body's wave
            // before any body reads it.
            shared.resize_with(n, Shared::default);
            for (entry, &at) in shared.iter().zip(position.iter()) {
                entry.set(at);
            }
            shared_circles.resize_with(circles.len(), SharedCircle::default);
            for (entry, (c, disc)) in shared_circles
                .iter_mut()
                .zip(circles.iter().zip(reach_discs))
            {
                *entry.at.get_mut() = pack(disc.center);
                (entry.radius, entry.body) = (c.radius, c.body);
            }
            settled.begin(position, change != MapChange::Everything, config);
            wake_where_changed(settled, watch, change, boxes, circle_body);
            for (b, &motion) in motion.iter().enumerate() {
                if motion == Vec2::ZERO {
                    settled.remember_still(b, position[b]);
                }
            }
        };
        rayon::join(neighbours_and_schedule, || rayon::join(walls, memories));
        let schedule = &waves.schedule;
        for w in 0..schedule.starts.len().saturating_sub(1) {
            let wave =
                &schedule.order[schedule.starts[w] as usize..schedule.starts[w + 1] as usize];
            let (this, shared, circles) = (&*self, &waves.shared[..], &waves.circles[..]);
            wave.par_iter()
                .enumerate()
                .with_min_len(MIN_BODIES_PER_TASK)
                .with_max_len(MAX_BODIES_PER_TASK)
                .for_each(|(k, &b)| {
                    this.prefetch_ahead(wave, k, ranges, shared, circles);
                    let bi = b as usize;
                    let found = match this.outcome(b, ranges, shared, circles, config, gap) {
                        Some(o) => {
                            let found = Found::of(&o, this.position[bi]);
                            if found.moved() {
                                shared[bi].set(o.end);
                                let own = this.first_circle[bi] as usize
                                    ..this.first_circle[bi + 1] as usize;
                                for (entry, c) in
                                    circles[own.clone()].iter().zip(&this.circles[own])
                                {
                                    entry.set(o.end + c.offset);
                                }
                            }
                            found
                        }
                        None => Found::default(),
                    };
                    shared[bi].set_found(found);
                });
        }
        // What later bodies do not read, for every body at once.
        let shared = &waves.shared[..];
        let (moving, contacts, cut_short) = shared
            .par_iter()
            .with_min_len(4096)
            .map(|entry| entry.found())
            .filter(|f| f.resolved())
            .map(|f| (1, f.contacts(), usize::from(f.cut_short())))
            .reduce(|| (0, 0, 0), |a, b| (a.0 + b.0, a.1 + b.1, a.2 + b.2));
        report.moving += moving;
        report.contact_count += contacts;
        report.cut_short += cut_short;
        #[cfg(test)]
        {
            self.skipped += shared.iter().filter(|e| e.found().stayed()).count();
        }
        let (position, motion) = (&self.position, &self.motion);
        let (circle_body, first, neighbours) =
            (&self.circle_body, &self.first_circle, &self.neighbours);
        self.settled.remember_each(
            bodies,
            |b, body| {
                let found = shared[b].found();
                if !found.resolved() {
                    return None;
                }
                if found.stayed() {
                    body.resolved = Vec2::ZERO;
                    return None;
                }
                let (start, end) = (position[b], shared[b].get());
                body.resolved = end - start;
                Some((start, motion[b], end, found.contacts(), found.cut_short()))
            },
            |b| {
                let circles = first[b] as usize..first[b + 1] as usize;
                neighbour_moved(circles, circle_body, neighbours, shared, |a| a > b)
            },
        );
        self.waves = waves;
    }

    /// Asks the processor for what the bodies after the `k`th of `wave` will read (see
    /// [`AHEAD`]): the wave's bodies are far apart in slot order, so each one's entries are
    /// on cache lines of their own, and so are its neighbours'.
    fn prefetch_ahead(
        &self,
        wave: &[u32],
        k: usize,
        ranges: &[(u32, u32)],
        shared: &[Shared],
        circles: &[SharedCircle],
    ) {
        use crate::prefetch::prefetch;
        if let Some(&b) = wave.get(k + AHEAD[0]) {
            let b = b as usize;
            prefetch(&self.position, b);
            prefetch(&self.motion, b);
            prefetch(&self.first_circle, b);
            self.settled.prefetch(b);
        }
        if let Some(&b) = wave.get(k + AHEAD[1]) {
            let c = self.first_circle[b as usize] as usize;
            prefetch(ranges, c);
            prefetch(&self.circles, c);
            self.neighbours.prefetch_row_place(c);
        }
        if let Some(&b) = wave.get(k + AHEAD[2]) {
            let c = self.first_circle[b as usize] as usize;
            if let Some(&range) = ranges.get(c) {
                self.near.prefetch(c, range);
            }
            self.neighbours.prefetch_row(c);
        }
        if let Some(&b) = wave.get(k + AHEAD[3]) {
            self.each_neighbour(b as usize, |m| {
                prefetch(circles, m);
                prefetch(&self.circle_body, m);
            });
        }
        // Whether a neighbour moved is read only for a body blocked in place last time.
        if let Some(&b) = wave.get(k + AHEAD[4]) {
            let b = b as usize;
            if self
                .settled
                .kept(b, self.position[b], self.motion[b])
                .is_some()
            {
                self.each_neighbour(b, |m| prefetch(shared, self.circle_body[m] as usize));
            }
        }
    }

    /// Resolves body `b` against the bodies where `shared` has them now, as the sequential
    /// resolve does at its turn, without writing anything (`None` for a body without a
    /// move); `shared` also tells which bodies of earlier waves moved.
    fn outcome(
        &self,
        b: u32,
        ranges: &[(u32, u32)],
        shared: &[Shared],
        standing: &[SharedCircle],
        config: &ResolveConfig,
        gap: f32,
    ) -> Option<Outcome> {
        let bi = b as usize;
        let motion = self.motion[bi];
        if motion == Vec2::ZERO {
            return None;
        }
        let start = self.position[bi];
        let circles = self.first_circle[bi] as usize..self.first_circle[bi + 1] as usize;
        if let Some((contacts, cut_short)) = self.settled.kept(bi, start, motion) {
            // Disturbed when a neighbour resolved before it moved (the sequential resolve
            // flags it as that neighbour moves).
            let disturbed = neighbour_moved(
                circles.clone(),
                &self.circle_body,
                &self.neighbours,
                shared,
                |a| a < bi,
            );
            if !disturbed {
                return Some(Outcome {
                    end: start,
                    contacts: u32::try_from(contacts).unwrap_or(u32::MAX),
                    cut_short,
                    stayed: true,
                });
            }
        }
        let mut counts = ResolveReport::default();
        let mut sink: Option<&mut Recorder<'_>> = None;
        let mover = Mover {
            body: b,
            first_circle: self.first_circle[bi],
            start,
            motion,
        };
        let end = self.collide_and_slide(
            &mover,
            standing,
            &ranges[circles],
            config,
            gap,
            &mut counts,
            &mut sink,
        );
        Some(Outcome {
            end,
            contacts: u32::try_from(counts.contact_count).unwrap_or(u32::MAX),
            cut_short: counts.cut_short > 0,
            stayed: false,
        })
    }
}

/// Whether a neighbour of a body's `circles`, in a body for which `which` holds, moved.
fn neighbour_moved(
    mut circles: Range<usize>,
    circle_body: &[u32],
    neighbours: &Neighbours,
    shared: &[Shared],
    which: impl Fn(usize) -> bool,
) -> bool {
    circles.any(|c| {
        neighbours.row(c).iter().any(|&n| {
            let a = circle_body[n as usize] as usize;
            which(a) && shared[a].found().moved()
        })
    })
}

/// Which bodies are resolved in which wave: made from the neighbours' candidates, a
/// superset of every row until they are found again, so one schedule serves every step
/// until then, whichever bodies move.
#[derive(Clone, Debug, Default)]
struct Schedule {
    /// Per body, its wave.
    wave: Vec<u32>,
    /// The bodies by wave, in slot order within a wave.
    order: Vec<u32>,
    /// Per wave, where it starts in `order`; one more entry at the end.
    starts: Vec<u32>,
    /// Per wave, the next free place in `order` while filling it.
    next: Vec<u32>,
    /// The candidates' search the schedule was made for (see [`CandidateRows::searches`]).
    made_for: Option<u64>,
}

/// What the schedule reads of the resolver: the circles' bodies, the bodies' circles and
/// the neighbours' candidates.
struct Shape<'a> {
    circle_body: &'a [u32],
    first_circle: &'a [u32],
    candidates: CandidateRows<'a>,
}

impl Schedule {
    /// Puts the bodies in waves, unless the candidates are those it was made for.
    fn make(&mut self, shape: &Shape<'_>) {
        let n = shape.first_circle.len().saturating_sub(1);
        let searches = shape.candidates.searches();
        if self.made_for == Some(searches) && self.wave.len() == n {
            return;
        }
        self.made_for = Some(searches);
        self.wave.clear();
        self.wave.resize(n, 0);
        // Counts per wave first, one place to the right: the running sums are the starts.
        self.starts.clear();
        self.starts.push(0);
        for b in 0..n {
            let mut wave = 0;
            let circles = shape.first_circle[b] as usize..shape.first_circle[b + 1] as usize;
            for c in circles {
                for &other in shape.candidates.candidates(c) {
                    // Without a branch: whether a candidate comes before is a coin toss
                    // (the later ones' waves are not made yet, and are masked off).
                    let a = shape.circle_body[other as usize] as usize;
                    let after = self.wave[a] + 1;
                    wave = wave.max(if a < b { after } else { 0 });
                }
            }
            self.wave[b] = wave;
            let w = wave as usize;
            if self.starts.len() < w + 2 {
                self.starts.resize(w + 2, 0);
            }
            self.starts[w + 1] += 1;
        }
        for w in 1..self.starts.len() {
            self.starts[w] += self.starts[w - 1];
        }
        self.order.clear();
        self.order.resize(n, 0);
        // Filled in slot order, so each wave's bodies are in slot order.
        self.next.clear();
        self.next.extend_from_slice(&self.starts);
        for b in 0..n {
            let slot = &mut self.next[self.wave[b] as usize];
            self.order[*slot as usize] = b as u32;
            *slot += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bodies::neighbours::tests::uniform;
    use crate::io::ascii;
    use crate::{BodyDesc, BodyShape};

    /// 900 discs at random in a walled 32 × 32 room, each with a velocity of its own (under
    /// 0.09 cells a step) and still at random one step in four, stepped on two threads: after every
    /// resolve, whether its schedule was made for it or kept from an earlier step, no two
    /// neighbours share a wave and every body's lower neighbours come in earlier waves.
    #[test]
    fn a_kept_schedule_still_puts_lower_neighbours_first_and_neighbours_apart() {
        let text: Vec<String> = (0..32)
            .map(|y| {
                (0..32)
                    .map(|x| if x % 31 == 0 || y % 31 == 0 { '#' } else { '.' })
                    .collect()
            })
            .collect();
        let map = ascii::parse(&text.join("\n"), "room.txt", 1.0).unwrap_or_else(|e| panic!("{e}"));
        let mut rand = uniform(0x5eed_0f0a_07e5);
        let shape = BodyShape::circle(0.3).unwrap_or_else(|e| panic!("{e}"));
        let mut bodies: Vec<Body> = (0..900)
            .map(|_| {
                let at = Vec2::new(1.5 + 29.0 * rand(), 1.5 + 29.0 * rand());
                Body::new(BodyDesc::new(at, shape.clone()))
            })
            .collect();
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(2)
            .build()
            .unwrap_or_else(|e| panic!("{e}"));
        let mut resolver = Resolver::default();
        let config = ResolveConfig::default();
        let (mut made, mut kept) = (0, 0);
        let mut last = None;
        let velocity: Vec<Vec2> = (0..bodies.len())
            .map(|_| Vec2::new(rand() - 0.5, rand() - 0.5) * 0.12)
            .collect();
        for step in 0..40 {
            for (body, &v) in bodies.iter_mut().zip(&velocity) {
                body.proposed = if rand() < 0.25 { Vec2::ZERO } else { v };
            }
            let mut refs: Vec<&mut Body> = bodies.iter_mut().collect();
            pool.install(|| resolver.resolve(&mut refs, &config, &map));
            let schedule = &resolver.waves.schedule;
            if schedule.made_for == last {
                kept += 1;
            } else {
                made += 1;
            }
            last = schedule.made_for;
            let wave = &schedule.wave;
            for b in 0..bodies.len() {
                let circles =
                    resolver.first_circle[b] as usize..resolver.first_circle[b + 1] as usize;
                for c in circles {
                    for &n in resolver.neighbours.row(c) {
                        let a = resolver.circle_body[n as usize] as usize;
                        assert_ne!(wave[a], wave[b], "step {step}: neighbours {a} and {b}");
                        if a < b {
                            assert!(wave[a] < wave[b], "step {step}: {a} after {b}");
                        }
                    }
                }
            }
            for body in &mut bodies {
                body.position += body.resolved;
            }
        }
        assert!(
            made >= 2 && kept >= 10,
            "made {made} times, kept {kept} times"
        );
    }
}
