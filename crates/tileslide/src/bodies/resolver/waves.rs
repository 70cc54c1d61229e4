//! The resolve on many threads (the `parallel` feature), with the result of one thread, bit
//! for bit.
//!
//! Resolving a body reads the walls near it, its own start and move, and the positions of
//! its neighbours (the rows of `neighbours`: the bodies whose reach discs touch its own):
//! in slot order, those in lower slots where they ended, the others where they started.
//! Nothing else: two bodies that are not neighbours never read each other. So the moving
//! bodies are put in waves: a body's wave is one past the last wave of its moving
//! neighbours in lower slots (wave 0 if it has none). Bodies of one wave are never
//! neighbours, and when a wave runs, each of its bodies' lower neighbours has ended (an
//! earlier wave) and each higher one has not started (a later wave): it reads exactly what
//! it reads in slot order. The bodies of a wave are resolved on every thread, each into an
//! [`Outcome`]; the calling thread then writes each one's end and the report's counts.
//! What no later body reads (the resolved moves, the settled memory, the flags that disturb
//! settled bodies next step) is written once every wave has run, again on every thread.
//!
//! The walls near every moving circle are gathered first, on the other threads, into the
//! same memory the sequential resolve keeps (`NearWalls::around_all`), while the calling
//! thread schedules the waves; the waves only read it.
//!
//! There are as many waves as the longest chain of neighbours in increasing slot order.
//! Slots in no spatial order, as a crowd spawned at random has them, give short chains
//! (8 or 9 waves a step for the crowd scene's 50,000 circles, 4 or 5 for
//! 10,000); bodies added one after another along a
//! packed queue give one body a wave, and the resolve then runs one body at a time, with
//! the same result, no faster than on one thread.

use glam::Vec2;
use rayon::prelude::*;

use std::ops::Range;

use super::{Mover, Resolver};
use crate::bodies::body::Body;
use crate::bodies::config::{ResolveConfig, ResolveReport};
use crate::bodies::neighbours::Neighbours;
use crate::bodies::settled::Settled;
use crate::bodies::trace::Recorder;
use crate::tiles::TileMap;

/// Bodies a task resolves at least: a task hand-over costs about as much as resolving a
/// free body.
const MIN_BODIES_PER_TASK: usize = 32;

/// Wave of a body that does not move.
const STILL: u32 = u32::MAX;

/// What resolving one body of a wave found.
#[derive(Clone, Copy, Debug, Default)]
struct Outcome {
    start: Vec2,
    end: Vec2,
    contacts: usize,
    cut_short: bool,
    /// Skipped as blocked in place again (see `settled`): `end` is its start.
    stayed: bool,
}

/// The waves' buffers, kept between resolves.
#[derive(Clone, Debug, Default)]
pub(super) struct Waves {
    schedule: Schedule,
    /// Per circle, its range of `near`'s walls (`(0, 0)` for still bodies).
    ranges: Vec<(u32, u32)>,
    /// The outcomes of the wave under way, in its order.
    outcomes: Vec<Outcome>,
    /// Per body, its outcome (for moving bodies), and whether it moved.
    done: Vec<Outcome>,
    moved: Vec<bool>,
}

impl Resolver {
    /// Resolves every body in waves, into `report`; `load`, the neighbours and the memories'
    /// `begin` have run.
    ///
    /// Between waves, the calling thread only writes each body's end and whether it moved;
    /// what the sequential resolve writes as it goes and later bodies do not read (the
    /// resolved moves, the settled memory, the flags for the next step) is written at the
    /// end, on every thread. A body that moved disturbs its neighbours (see `settled`): the
    /// ones after it in slot order this step, which a body checks at its turn by reading its
    /// lower neighbours' `moved`, and the ones before it next step, flagged at the end.
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
        for (b, &motion) in self.motion.iter().enumerate() {
            if motion == Vec2::ZERO {
                self.settled.remember_still(b, self.position[b]);
            }
        }
        // The walls near each moving circle, and the waves' schedule from the rows: the
        // schedule runs on this thread (each body's wave follows from those of the bodies
        // before it) while the other threads gather walls.
        let (circle_body, motion, filter) = (&self.circle_body, &self.motion, &self.filter);
        let shape = Shape {
            circle_body,
            first_circle: &self.first_circle,
            position: &self.position,
            motion,
            neighbours: &self.neighbours,
            settled: &self.settled,
        };
        let near = &mut self.near;
        let reach_discs = &self.reach_discs;
        let (schedule, ranges) = (&mut waves.schedule, &mut waves.ranges);
        rayon::join(
            || schedule.make(&shape),
            || {
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
            },
        );
        waves.moved.clear();
        waves.moved.resize(n, false);
        waves.done.resize(n, Outcome::default());
        let (starts, jobs) = (&waves.schedule.starts, &waves.schedule.jobs);
        for w in 0..starts.len().saturating_sub(1) {
            let wave = &jobs[starts[w] as usize..starts[w + 1] as usize];
            let this = &*self;
            let (ranges, moved) = (&waves.ranges, &waves.moved);
            wave.par_iter()
                .with_min_len(MIN_BODIES_PER_TASK)
                .map(|job| this.outcome(job, ranges, moved, config, gap))
                .collect_into_vec(&mut waves.outcomes);
            for (job, outcome) in wave.iter().zip(&waves.outcomes) {
                let b = job.mover.body as usize;
                report.moving += 1;
                report.contact_count += outcome.contacts;
                report.cut_short += usize::from(outcome.cut_short);
                self.position[b] = outcome.end;
                waves.moved[b] = outcome.end != outcome.start;
                waves.done[b] = *outcome;
            }
            #[cfg(test)]
            {
                self.skipped += waves.outcomes.iter().filter(|o| o.stayed).count();
            }
        }
        // What later bodies do not read, for every body at once.
        let (done, moved, motion) = (&waves.done, &waves.moved, &self.motion);
        bodies
            .par_iter_mut()
            .enumerate()
            .with_min_len(1024)
            .for_each(|(b, body)| {
                if motion[b] != Vec2::ZERO {
                    let o = &done[b];
                    body.resolved = if o.stayed {
                        Vec2::ZERO
                    } else {
                        o.end - o.start
                    };
                }
            });
        let (circle_body, first, neighbours) =
            (&self.circle_body, &self.first_circle, &self.neighbours);
        self.settled.remember_each(
            |b| {
                let o = &done[b];
                (motion[b] != Vec2::ZERO && !o.stayed).then_some((
                    o.start,
                    motion[b],
                    o.end,
                    o.contacts,
                    o.cut_short,
                ))
            },
            |b| {
                let circles = first[b] as usize..first[b + 1] as usize;
                neighbour_moved(circles, circle_body, neighbours, moved, |a| a > b)
            },
        );
        self.waves = waves;
    }

    /// Resolves `job`'s body against what stands now, as the sequential resolve does at its
    /// turn, without writing anything; `moved` tells which bodies of earlier waves moved.
    fn outcome(
        &self,
        job: &Job,
        ranges: &[(u32, u32)],
        moved: &[bool],
        config: &ResolveConfig,
        gap: f32,
    ) -> Outcome {
        let Job {
            ref mover,
            circles_end,
            kept,
        } = *job;
        let (b, start) = (mover.body as usize, mover.start);
        let circles = mover.first_circle as usize..circles_end as usize;
        if let Some((contacts, cut_short)) = kept {
            // Disturbed when a neighbour resolved before it moved (the sequential resolve
            // flags it as that neighbour moves).
            let disturbed = neighbour_moved(
                circles.clone(),
                &self.circle_body,
                &self.neighbours,
                moved,
                |a| a < b,
            );
            if !disturbed {
                return Outcome {
                    start,
                    end: start,
                    contacts: contacts as usize,
                    cut_short,
                    stayed: true,
                };
            }
        }
        let mut counts = ResolveReport::default();
        let mut sink: Option<&mut Recorder<'_>> = None;
        let end =
            self.collide_and_slide(mover, &ranges[circles], config, gap, &mut counts, &mut sink);
        Outcome {
            start,
            end,
            contacts: counts.contact_count,
            cut_short: counts.cut_short > 0,
            stayed: false,
        }
    }
}

/// Whether a neighbour of a body's `circles`, in a body for which `which` holds, moved.
fn neighbour_moved(
    mut circles: Range<usize>,
    circle_body: &[u32],
    neighbours: &Neighbours,
    moved: &[bool],
    which: impl Fn(usize) -> bool,
) -> bool {
    circles.any(|c| {
        neighbours.row(c).iter().any(|&n| {
            let a = circle_body[n as usize] as usize;
            which(a) && moved[a]
        })
    })
}

/// A moving body, with what resolving it reads of its own: copied by the schedule, in slot
/// order into each wave's run, so that a wave reads its bodies' starts, moves and memories
/// front to back rather than a few entries per cache line of every per-body array.
#[derive(Clone, Copy, Debug, Default)]
struct Job {
    mover: Mover,
    /// One past its last circle.
    circles_end: u32,
    /// If the settled memory keeps it where it is unless a lower neighbour moves: its last
    /// resolve's contacts, and whether it was cut short.
    kept: Option<(u32, bool)>,
}

/// Which bodies are resolved in which wave.
#[derive(Clone, Debug, Default)]
struct Schedule {
    /// Per body, its wave ([`STILL`] for a body without a move).
    wave: Vec<u32>,
    /// The moving bodies by wave, in slot order within a wave.
    jobs: Vec<Job>,
    /// Per wave, where it starts in `jobs`; one more entry at the end.
    starts: Vec<u32>,
    /// Per wave, the next free place in `jobs` while filling it.
    next: Vec<u32>,
}

/// What the schedule reads of the resolver: the circles' bodies, the bodies' circles,
/// positions, moves and neighbours, and the settled memory.
struct Shape<'a> {
    circle_body: &'a [u32],
    first_circle: &'a [u32],
    position: &'a [Vec2],
    motion: &'a [Vec2],
    neighbours: &'a Neighbours,
    settled: &'a Settled,
}

impl Schedule {
    /// Puts the moving bodies in waves.
    fn make(&mut self, shape: &Shape<'_>) {
        let n = shape.motion.len();
        self.wave.clear();
        self.wave.extend(
            shape
                .motion
                .iter()
                .map(|&m| if m == Vec2::ZERO { STILL } else { 0 }),
        );
        // Counts per wave first, one place to the right: the running sums are the starts.
        self.starts.clear();
        self.starts.push(0);
        for b in 0..n {
            if self.wave[b] == STILL {
                continue;
            }
            let mut wave = 0;
            let circles = shape.first_circle[b] as usize..shape.first_circle[b + 1] as usize;
            for c in circles {
                for &n in shape.neighbours.row(c) {
                    let a = shape.circle_body[n as usize] as usize;
                    let w = self.wave[a];
                    if a < b && w != STILL {
                        wave = wave.max(w + 1);
                    }
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
        let total = self.starts.last().copied().unwrap_or(0) as usize;
        self.jobs.clear();
        self.jobs.resize(total, Job::default());
        // Filled in slot order, so each wave's bodies are in slot order (and each per-body
        // array is read front to back).
        self.next.clear();
        self.next.extend_from_slice(&self.starts);
        for b in 0..n {
            if self.wave[b] != STILL {
                let slot = &mut self.next[self.wave[b] as usize];
                let (start, motion) = (shape.position[b], shape.motion[b]);
                let kept = shape.settled.kept(b, start, motion);
                self.jobs[*slot as usize] = Job {
                    mover: Mover {
                        body: b as u32,
                        first_circle: shape.first_circle[b],
                        start,
                        motion,
                    },
                    circles_end: shape.first_circle[b + 1],
                    kept: kept.map(|(contacts, cut_short)| {
                        (u32::try_from(contacts).unwrap_or(u32::MAX), cut_short)
                    }),
                };
                *slot += 1;
            }
        }
    }
}
