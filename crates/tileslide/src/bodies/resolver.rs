//! The resolver: the second loop of a step, with the memories that make the next step
//! cheaper. Moves are checked against each other and the walls at the exact time of impact,
//! and the blocked remainder is slid along the contact tangent.
//!
//! Bodies are resolved one after another, in slot order (Gauss–Seidel). Each one moves by
//! *collide and slide* against a still picture of everything else: the walls, the bodies
//! already resolved at their new positions, and the others where they stand. It sweeps its
//! move to the first contact (exact time of impact), keeps that part, redirects the blocked
//! remainder along the contact tangent (the write-up's slide and tie-break), and sweeps
//! again, up to `passes` times; a remainder still blocked after that is cut at its first
//! contact. Every sweep is exact against obstacles that do not move while it runs, so:
//!
//! - no pair overlaps afterwards: a pair's later-resolved body checked its whole path
//!   against the other's final position, and the earlier one against the later one's start;
//! - nothing crosses a wall front at any speed, whatever the passes;
//! - a body without a move never moves; the result depends only on the inputs and the slot
//!   order, so identical inputs give bit-identical positions.
//!
//! Moving bodies keep a small gap (see [`ResolveConfig::gap`]) from what they touch: a sweep
//! stops at the radius plus the gap, and a body already inside that band may still close in
//! to half the gap. So rounding never leaves anything overlapping, and a circle sliding along
//! a wall with a remainder that leans into it by a rounding error is not stopped ("snag").
//! Against a round obstacle (another body, a wall's rounded end) a body already inside the
//! band is still free to move along the contact tangent, to within rounding: that is where
//! its slide goes, and taking rounding for an approach would block the slide at `t = 0` on
//! every pass (see `grazes` in `contact`).

use glam::Vec2;

use super::body::{Body, BodyFilter};
use super::config::{ResolveConfig, ResolveReport};
use super::contact::{Obstacle, band, slide, sweep_circle, sweep_wall};
use super::map_watch::{MapChange, MapWatch};
use super::near_walls::NearWalls;
use super::neighbours::{CandidateRows, Neighbours};
use super::settled::Settled;
use super::trace::{Decision, Recorder, Sink};
use crate::geometry::{Aabb, Circle, Segment, SweepHit, in_range};
use crate::query::Capsule;
use crate::tiles::TileMap;

#[cfg(feature = "parallel")]
mod waves;

/// Bodies one task copies in at least (the `parallel` feature).
#[cfg(feature = "parallel")]
const LOAD_PER_TASK: usize = 4096;

/// How many bodies ahead the resolve in slot order asks for the neighbours' circles, and
/// then for their positions (see `Resolver::prefetch_neighbours`).
const NEIGHBOURS_AHEAD: [usize; 2] = [8, 3];

/// Shortest safe part of a move that is taken, as a fraction of the gap (see
/// `collide_and_slide`).
const MIN_STEP: f32 = 0.125;

/// A circle of a body, for the duration of a resolve.
#[derive(Clone, Copy, Debug)]
struct WorkCircle {
    body: u32,
    offset: Vec2,
    radius: f32,
}

/// A circle as the resolve in slot order sees it when it reads a neighbour: where it
/// stands (its body's start plus its offset, its body's end plus its offset once resolved),
/// its radius and its body. One entry a circle, so a neighbour is one read rather than its
/// circle's and then its body's, which lie anywhere in memory.
#[derive(Clone, Copy, Debug, Default)]
struct Seen {
    at: Vec2,
    radius: f32,
    body: u32,
}

/// The resolver of a [`Bodies`](crate::Bodies) set: its buffers, kept between resolves so
/// that a step allocates nothing once warm, and its memories of the last resolve (which
/// bodies may meet, the walls near each, which bodies were blocked in place), kept so that
/// the next one costs less; none of them changes a result.
#[derive(Clone, Debug, Default)]
pub(super) struct Resolver {
    circles: Vec<WorkCircle>,
    /// Per circle, its body (`circles[c].body`), packed for the passes that read only that:
    /// a fifth of the memory to bring in.
    circle_body: Vec<u32>,
    /// Per body, its first circle; one more entry at the end.
    first_circle: Vec<u32>,
    position: Vec<Vec2>,
    motion: Vec<Vec2>,
    filter: Vec<BodyFilter>,
    /// Per body, how far its circles reach past their radius this step: its move and the
    /// gap.
    reach: Vec<f32>,
    /// Per circle, its reach disc (where it starts, its radius grown by its body's reach:
    /// everywhere it can be this step) and the disc's box.
    reach_discs: Vec<Circle>,
    boxes: Vec<Aabb>,
    /// Per circle, how the resolve in slot order sees it (filled only for that resolve).
    seen: Vec<Seen>,
    /// Whether `circles` and `first_circle` still describe the bodies (see `load`).
    shapes_known: bool,
    /// Per circle, the circles it may meet.
    neighbours: Neighbours,
    /// The walls near each circle, kept between steps (statements about the map, so they
    /// stay true whichever circle they end up with).
    near: NearWalls,
    /// The map as the last resolve saw it, to tell the memories what changed since.
    watch: MapWatch,
    /// Per circle of the body being resolved, its range of `near`'s walls.
    wall_ranges: Vec<(u32, u32)>,
    /// The last resolve, to skip bodies blocked in place again.
    settled: Settled,
    /// The resolve on many threads.
    #[cfg(feature = "parallel")]
    waves: waves::Waves,
    /// Bodies the last resolve skipped (blocked in place again), for the tests below.
    #[cfg(test)]
    skipped: usize,
}

impl Resolver {
    /// Resolves the proposed moves of `bodies` (in slot order) on `map`, writing each
    /// body's resolved move.
    pub fn resolve(
        &mut self,
        bodies: &mut [&mut Body],
        config: &ResolveConfig,
        map: &TileMap,
    ) -> ResolveReport {
        self.resolve_into(bodies, config, map, None)
    }

    /// [`resolve`](Self::resolve), reporting every pass to `recorder`.
    pub fn resolve_traced(
        &mut self,
        bodies: &mut [&mut Body],
        config: &ResolveConfig,
        map: &TileMap,
        recorder: &mut Recorder<'_>,
    ) -> ResolveReport {
        self.resolve_into(bodies, config, map, Some(recorder))
    }

    /// The resolve, reporting to `sink` (with `None`, nothing is built to report). Kept out
    /// of line: inlined into `Bodies::resolve`, the crowd's step took 0.6 % more
    /// instructions.
    #[inline(never)]
    fn resolve_into(
        &mut self,
        bodies: &mut [&mut Body],
        config: &ResolveConfig,
        map: &TileMap,
        mut sink: Option<&mut Recorder<'_>>,
    ) -> ResolveReport {
        let gap = config.gap;
        #[cfg(feature = "parallel")]
        let in_waves = sink.is_none() && rayon::current_num_threads() > 1;
        #[cfg(not(feature = "parallel"))]
        let in_waves = false;
        self.load(bodies, gap, !in_waves);
        let mut report = ResolveReport::default();
        #[cfg(test)]
        {
            self.skipped = 0;
        }
        // On many threads, in waves of bodies that do not meet (see `waves`), which finds
        // the neighbours and starts the memories itself, beside other work: the same
        // result. A traced resolve stays on the calling thread, in slot order.
        #[cfg(feature = "parallel")]
        if in_waves {
            self.resolve_in_waves(bodies, config, map, &mut report);
            return report;
        }
        let change = self.neighbours_and_memories(config, map);
        wake_where_changed(
            &mut self.settled,
            &self.watch,
            change,
            &self.boxes,
            &self.circle_body,
        );
        for (b, body) in bodies.iter_mut().enumerate() {
            self.prefetch_neighbours(b);
            let (start, motion) = (self.position[b], self.motion[b]);
            if motion == Vec2::ZERO {
                sink.still(b as u32, start);
                self.settled.remember_still(b, start);
                continue;
            }
            if self.settled.stays(b, start, motion, &mut report) {
                sink.settled(b as u32, start, motion);
                body.resolved = Vec2::ZERO;
                #[cfg(test)]
                {
                    self.skipped += 1;
                }
                continue;
            }
            let before = report;
            sink.begin(b as u32, start, motion);
            let mut ranges = std::mem::take(&mut self.wall_ranges);
            self.walls_near(b, gap, map, &mut ranges);
            let mover = Mover {
                body: b as u32,
                first_circle: self.first_circle[b],
                start,
                motion,
            };
            let stand = &self.seen[..];
            let end =
                self.collide_and_slide(&mover, stand, &ranges, config, gap, &mut report, &mut sink);
            self.wall_ranges = ranges;
            self.position[b] = end;
            sink.end(b as u32, end);
            body.resolved = end - start;
            report.moving += 1;
            let contacts = report.contact_count - before.contact_count;
            let cut_short = report.cut_short > before.cut_short;
            self.settled
                .remember(b, start, motion, end, contacts, cut_short);
            if end != start {
                self.moved(b, end);
            }
        }
        report
    }

    /// Per circle of the bodies in slot order, the box the broadphase last filed it
    /// under, or `None` when the bodies changed since the last resolve.
    pub fn broadphase_boxes(&self) -> Option<&[Aabb]> {
        self.neighbours.grown()
    }

    /// Forgets the last resolve: the bodies changed in a way their positions do not show.
    pub fn forget(&mut self) {
        self.settled.forget();
        self.neighbours.forget();
        self.shapes_known = false;
    }

    /// In the resolve in slot order, before body `b`: asks the processor for what the
    /// bodies a little further on will read of their neighbours, which are anywhere in the
    /// per-circle and per-body arrays (slot order is not spatial order; the rows themselves
    /// are in slot order, and the hardware brings those). Two stages, as the second needs
    /// what the first asked for: the neighbours' entries of `seen` for body
    /// `b + NEIGHBOURS_AHEAD[0]`, then their bodies' disturbed flags for body
    /// `b + NEIGHBOURS_AHEAD[1]`. Bodies without a move are left out: they read nothing.
    #[inline]
    fn prefetch_neighbours(&self, b: usize) {
        let [far, near] = NEIGHBOURS_AHEAD;
        if b + far < self.position.len() {
            self.each_neighbour(b + far, |m| {
                crate::prefetch::prefetch(&self.seen, m);
            });
        }
        if b + near < self.position.len() {
            self.each_neighbour(b + near, |m| {
                self.settled.prefetch_flags(self.seen[m].body as usize);
            });
        }
    }

    /// Calls `f` with every neighbour circle of body `b` (none for a body without a move).
    #[inline]
    fn each_neighbour(&self, b: usize, mut f: impl FnMut(usize)) {
        if self.motion[b] == Vec2::ZERO {
            return;
        }
        for c in self.first_circle[b]..self.first_circle[b + 1] {
            for &m in self.neighbours.row(c as usize) {
                f(m as usize);
            }
        }
    }

    /// In the resolve in slot order, body `b` moved to `end`: its circles are seen there
    /// from now on, and the bodies whose reach discs touch its own are flagged as
    /// disturbed.
    fn moved(&mut self, b: usize, end: Vec2) {
        let circles = self.first_circle[b] as usize..self.first_circle[b + 1] as usize;
        for c in circles {
            self.seen[c].at = end + self.circles[c].offset;
            for &n in self.neighbours.row(c) {
                let other = self.seen[n as usize].body as usize;
                self.settled.disturb(b, other);
            }
        }
    }

    /// Copies the bodies into flat arrays; `in_slot_order` for the resolve in slot order,
    /// which also reads `seen`.
    fn load(&mut self, bodies: &[&mut Body], gap: f32, in_slot_order: bool) {
        // The circles change only when bodies are added or removed, which calls `forget`:
        // otherwise they are kept, and the bodies' shapes (each a list of its own, on the
        // heap) are not read again.
        if !self.shapes_known || self.first_circle.len() != bodies.len() + 1 {
            self.circles.clear();
            self.first_circle.clear();
            for (b, body) in bodies.iter().enumerate() {
                self.first_circle.push(self.circles.len() as u32);
                self.circles
                    .extend(body.shape.circles().iter().map(|c| WorkCircle {
                        body: b as u32,
                        offset: c.center,
                        radius: c.radius,
                    }));
            }
            self.first_circle.push(self.circles.len() as u32);
            self.circle_body.clear();
            self.circle_body.extend(self.circles.iter().map(|c| c.body));
            self.shapes_known = true;
        }
        let n = bodies.len();
        self.position.resize(n, Vec2::ZERO);
        self.motion.resize(n, Vec2::ZERO);
        self.filter.resize(n, BodyFilter::default());
        self.reach.resize(n, 0.0);
        let m = self.circles.len();
        self.reach_discs.resize(m, Circle::new(Vec2::ZERO, 0.0));
        self.boxes
            .resize(m, Aabb::from_corners(Vec2::ZERO, Vec2::ZERO));
        self.seen
            .resize(if in_slot_order { m } else { 0 }, Seen::default());
        // Each body, then each circle, on its own: on many threads for many bodies.
        let copy = |body: &Body,
                    position: &mut Vec2,
                    motion: &mut Vec2,
                    filter: &mut BodyFilter,
                    reach: &mut f32| {
            *position = body.position;
            *motion = body.proposed;
            *filter = body.filter;
            // Everywhere a circle can be during the step: its whole move, grown by the
            // radius and the gap.
            *reach = body.proposed.length() + gap;
        };
        let disc = |c: &WorkCircle, position: &[Vec2], reach: &[f32]| {
            let b = c.body as usize;
            Circle::new(position[b] + c.offset, c.radius + reach[b])
        };
        // Where a circle stands is its reach disc's centre.
        let see = |c: &WorkCircle, d: &Circle| Seen {
            at: d.center,
            radius: c.radius,
            body: c.body,
        };
        #[cfg(feature = "parallel")]
        if n >= 2 * LOAD_PER_TASK && rayon::current_num_threads() > 1 {
            use rayon::prelude::*;
            (
                bodies.par_iter(),
                self.position.par_iter_mut(),
                self.motion.par_iter_mut(),
                self.filter.par_iter_mut(),
                self.reach.par_iter_mut(),
            )
                .into_par_iter()
                .with_min_len(LOAD_PER_TASK)
                .for_each(|(body, position, motion, filter, reach)| {
                    copy(body, position, motion, filter, reach);
                });
            let (position, reach) = (&self.position[..], &self.reach[..]);
            (
                self.circles.par_iter(),
                self.reach_discs.par_iter_mut(),
                self.boxes.par_iter_mut(),
            )
                .into_par_iter()
                .with_min_len(LOAD_PER_TASK)
                .for_each(|(c, d, bounds)| {
                    *d = disc(c, position, reach);
                    *bounds = d.aabb();
                });
            let (circles, discs) = (&self.circles[..], &self.reach_discs[..]);
            (
                self.seen.par_iter_mut(),
                circles.par_iter(),
                discs.par_iter(),
            )
                .into_par_iter()
                .with_min_len(LOAD_PER_TASK)
                .for_each(|(seen, c, d)| *seen = see(c, d));
            return;
        }
        for ((((body, position), motion), filter), reach) in bodies
            .iter()
            .zip(&mut self.position)
            .zip(&mut self.motion)
            .zip(&mut self.filter)
            .zip(&mut self.reach)
        {
            copy(body, position, motion, filter, reach);
        }
        let (position, reach) = (&self.position[..], &self.reach[..]);
        let mut seen = self.seen.iter_mut();
        for ((c, d), bounds) in self
            .circles
            .iter()
            .zip(&mut self.reach_discs)
            .zip(&mut self.boxes)
        {
            *d = disc(c, position, reach);
            *bounds = d.aabb();
            if let Some(seen) = seen.next() {
                *seen = see(c, d);
            }
        }
    }

    /// Finds the circles each circle may meet: pairs of different bodies that collide by
    /// filter and whose reach discs overlap (a row is read only for a moving body, so the
    /// rows may also pair bodies that both stay). Then tells the memories what changed on
    /// the map since the last resolve and starts them; returns that change. (The waves do
    /// the same work, side by side: see `resolve_in_waves`.)
    fn neighbours_and_memories(&mut self, config: &ResolveConfig, map: &TileMap) -> MapChange {
        find_neighbours(
            &mut self.neighbours,
            config,
            map,
            &self.reach_discs,
            &self.boxes,
            &self.circle_body,
            &self.filter,
            |_| {},
        );
        let change = self.map_changes(map);
        self.settled
            .begin(&self.position, change != MapChange::Everything, config);
        change
    }

    /// What changed on the map since the last resolve, told to the walls kept near each
    /// circle (which drop what the change touches).
    fn map_changes(&mut self, map: &TileMap) -> MapChange {
        let change = self.watch.update(map);
        self.near.begin(self.circles.len(), change, &self.watch);
        change
    }

    /// The walls near each circle of body `b`, into `ranges` (one range of `near` per
    /// circle): once a step, as the reach disc holds every position the body can take this
    /// step (slides never lengthen the remainder).
    fn walls_near(&mut self, b: usize, gap: f32, map: &TileMap, ranges: &mut Vec<(u32, u32)>) {
        ranges.clear();
        let mask = self.filter[b].walls;
        for c in self.first_circle[b] as usize..self.first_circle[b + 1] as usize {
            ranges.push(self.near.around(c, &self.reach_discs[c], mask, gap, map));
        }
    }

    /// Where `mover` ends when it moves by its proposed move with collide and slide from
    /// where it stands, against the walls at `ranges` of `near` (one range per circle) and
    /// its neighbours where `stand` has them.
    #[allow(clippy::too_many_arguments)]
    fn collide_and_slide<S: Sink, P: Stand + ?Sized>(
        &self,
        mover: &Mover,
        stand: &P,
        ranges: &[(u32, u32)],
        config: &ResolveConfig,
        gap: f32,
        report: &mut ResolveReport,
        sink: &mut S,
    ) -> Vec2 {
        let b = mover.body;
        let first = mover.first_circle as usize;
        let walls = WallsNear::new(&self.near, first, ranges);
        let mut position = mover.start;
        let mut remaining = mover.motion;
        // The contact the remaining motion slides along (none for the move as proposed).
        let mut along: Option<Along> = None;
        for pass in 0..=config.passes {
            if remaining == Vec2::ZERO {
                break;
            }
            sink.pass(pass, position, remaining);
            let Some((hit, obstacle, id)) =
                self.first_contact(mover, stand, position, &walls, remaining, gap, sink)
            else {
                sink.free();
                return off_contact(position, remaining, along);
            };
            report.contact_count += 1;
            // A safe part shorter than a fraction of the gap is not taken: rounding the
            // position can lose one coordinate of so small a step (at x = 232 the float
            // spacing is 1.5e-5) and keep the other, and a body pressed into a wall and a
            // neighbour would creep into the neighbour a few ulps per pass.
            let step = remaining * hit.t;
            let taken = step.length() >= gap * MIN_STEP;
            let kept = Vec2::new(keep_if(taken, step.x), keep_if(taken, step.y));
            position = off_contact(position, kept, along);
            if pass == config.passes {
                if sink.on() {
                    let decision = Decision {
                        blocked: remaining * (1.0 - hit.t),
                        normal: hit.normal,
                        obstacle,
                        slide: Vec2::ZERO,
                        mode: config.slide,
                        last_pass: true,
                        out_of_range: false,
                    };
                    sink.decide(id, taken, decision);
                }
                report.cut_short += 1;
                return position;
            }
            let blocked = remaining * (1.0 - hit.t);
            remaining = slide(blocked, hit.normal, obstacle, b, config.slide);
            along = Some(Along {
                normal: hit.normal,
                wall: match obstacle {
                    Obstacle::Wall { circle, wall, .. } => {
                        let c = &self.circles[first + circle as usize];
                        Some(Touch {
                            segment: walls.of(circle as usize)[wall as usize].segment,
                            offset: c.offset,
                            radius: c.radius,
                        })
                    }
                    Obstacle::Body(_) => None,
                },
            });
            // A slide that would end past MAX_COORD is not taken, so every body stays in
            // range: a move ends within it (checked by `propose`), and every later position
            // lies on a straight path between two points within it (the square is convex,
            // and rounding is monotone).
            let out_of_range = !in_range(position + remaining);
            if sink.on() {
                let decision = Decision {
                    blocked,
                    normal: hit.normal,
                    obstacle,
                    slide: remaining,
                    mode: config.slide,
                    last_pass: false,
                    out_of_range,
                };
                sink.decide(id, taken, decision);
            }
            if out_of_range {
                remaining = Vec2::ZERO;
            }
        }
        position
    }

    /// The first contact of `mover` moving by `motion` from `origin`, against `walls` and
    /// its neighbours where `stand` has them.
    #[allow(clippy::too_many_arguments)]
    fn first_contact<S: Sink, P: Stand + ?Sized>(
        &self,
        mover: &Mover,
        stand: &P,
        origin: Vec2,
        walls: &WallsNear<'_>,
        motion: Vec2,
        gap: f32,
        sink: &mut S,
    ) -> Option<(SweepHit, Obstacle, S::Id)> {
        // Obstacles farther than the move's length plus the contact radius are out of reach:
        // the cheap test that lets a free body skip almost every sweep.
        let reach = motion.length();
        let mut best: Option<(SweepHit, Obstacle, S::Id)> = None;
        let mut keep = |hit: SweepHit, obstacle: Obstacle, id: S::Id| {
            if best.is_none_or(|(b, _, _)| hit.t < b.t) {
                best = Some((hit, obstacle, id));
            }
        };
        let first = mover.first_circle as usize;
        for (k, c) in self.circles[first..first + walls.ranges.len()]
            .iter()
            .enumerate()
        {
            let center = origin + c.offset;
            for (w, wall) in (0..).zip(walls.of(k)) {
                let distance2 = wall.segment.distance_squared_to(center);
                let radius = band(distance2, c.radius, gap);
                if distance2 > (radius + reach) * (radius + reach) {
                    continue;
                }
                let hit = sweep_wall(wall, center, radius, motion);
                let id = sink.wall(k as u32, wall, center, radius, motion, hit);
                if let Some(hit) = hit {
                    keep(
                        hit,
                        Obstacle::Wall {
                            flat: hit.normal == wall.normal,
                            circle: k as u32,
                            wall: w,
                        },
                        id,
                    );
                }
            }
            let ci = first + k;
            let neighbours = self.neighbours.row(ci);
            // The nearest neighbour contact, lowest circle index first on equal `t` (the
            // row is in broadphase order).
            let mut nearest: Option<(SweepHit, u32, u32, S::Id)> = None;
            for &n in neighbours {
                let other = stand.circle(n as usize);
                let at = other.at;
                let distance2 = center.distance_squared(at);
                let radius = band(distance2, c.radius + other.radius, gap);
                if distance2 > (radius + reach) * (radius + reach) {
                    continue;
                }
                let hit = sweep_circle(center, motion, at, radius);
                // (Which circle of its body, for the trace only: no lookup otherwise.)
                let who = if sink.on() {
                    (other.body, n - self.first_circle[other.body as usize])
                } else {
                    (0, 0)
                };
                let id = sink.body(k as u32, who, at, other.radius, center, radius, motion, hit);
                if let Some(hit) = hit
                    && nearest.is_none_or(|(h, m, _, _)| hit.t < h.t || (hit.t == h.t && n < m))
                {
                    nearest = Some((hit, n, other.body, id));
                }
            }
            if let Some((hit, _, body, id)) = nearest {
                keep(hit, Obstacle::Body(body), id);
            }
        }
        best
    }
}

/// The walls near each circle of a body (one range of `near` per circle), with the first
/// circle's looked up once for all the body's passes: most bodies are one circle, and a
/// lookup finds the circle's pool first.
struct WallsNear<'a> {
    near: &'a NearWalls,
    first_circle: usize,
    ranges: &'a [(u32, u32)],
    first: &'a [Capsule],
}

impl<'a> WallsNear<'a> {
    fn new(near: &'a NearWalls, first_circle: usize, ranges: &'a [(u32, u32)]) -> Self {
        let first = match ranges.first() {
            Some(&range) => near.walls(first_circle, range),
            None => &[],
        };
        Self {
            near,
            first_circle,
            ranges,
            first,
        }
    }

    /// The walls near the body's circle `k` (from its first).
    #[inline]
    fn of(&self, k: usize) -> &'a [Capsule] {
        if k == 0 {
            self.first
        } else {
            self.near.walls(self.first_circle + k, self.ranges[k])
        }
    }
}

/// Where the circles stand while a body is resolved: those of the bodies resolved before
/// it where they ended, the others where they started.
trait Stand {
    /// Circle `c` as the body being resolved sees it.
    fn circle(&self, c: usize) -> Seen;
}

/// The resolve in slot order keeps them in `seen`, each circle's entry moved as its body
/// is resolved.
impl Stand for [Seen] {
    #[inline]
    fn circle(&self, c: usize) -> Seen {
        self[c]
    }
}

/// A body about to be resolved: what its sweeps read of it.
#[derive(Clone, Copy, Debug)]
struct Mover {
    body: u32,
    /// Its first circle (its others follow).
    first_circle: u32,
    /// Where it stands, and its proposed move.
    start: Vec2,
    motion: Vec2,
}

/// The contact a slide goes along: its normal, and for a wall the circle that touches it.
#[derive(Clone, Copy)]
struct Along {
    normal: Vec2,
    wall: Option<Touch>,
}

/// A wall a body's circle touches: the wall, and the circle's offset and radius.
#[derive(Clone, Copy)]
struct Touch {
    segment: Segment,
    offset: Vec2,
    radius: f32,
}

/// The circles each circle may meet ([`Neighbours::update`]), for the resolve's bodies;
/// `beside` runs with the candidates while the rows are filled.
#[allow(clippy::too_many_arguments)]
pub(super) fn find_neighbours(
    neighbours: &mut Neighbours,
    config: &ResolveConfig,
    map: &TileMap,
    reach_discs: &[Circle],
    boxes: &[Aabb],
    circle_body: &[u32],
    filter: &[BodyFilter],
    beside: impl FnOnce(CandidateRows<'_>) + Send,
) {
    neighbours.update(
        config.broadphase,
        reach_discs,
        boxes,
        map.cell_size().min_element(),
        |i| circle_body[i as usize] as usize,
        |a, b| filter[a].collides(&filter[b]),
        beside,
    );
}

/// After a local change of the map, wakes the settled bodies with a circle whose box
/// `watch` finds the change touches.
pub(super) fn wake_where_changed(
    settled: &mut Settled,
    watch: &MapWatch,
    change: MapChange,
    boxes: &[Aabb],
    circle_body: &[u32],
) {
    if change != MapChange::Local {
        return;
    }
    for (c, area) in boxes.iter().enumerate() {
        if watch.touches(area) {
            settled.wake(circle_body[c] as usize);
        }
    }
}

/// Where a step from `from` ends, when it slides along the contact `along`: at
/// `from + step`, unless rounding that sum moved the body towards the contact. A slide is
/// tangent to the contact, but each coordinate of the end is rounded to its own float
/// spacing, and the same slide from nearly the same place rounds the same way step after
/// step. Two cases are moved back:
///
/// - A step that lost one of its coordinates whole (at x = 135 the spacing is 1.5·10⁻⁵): a
///   body pressed into a wall and a neighbour lost the part of each step that kept it off the
///   neighbour, and crept into it by 6·10⁻⁶ a step. The end moves along the coordinate the
///   normal leans on most.
/// - A step along a wall whose rounded end takes the circle into the wall, nearer than its
///   radius: a body sliding down a ramp at (110, 42), where x's spacing is twice y's, crept
///   into it by 2.7·10⁻⁶ a step. The end moves along the coordinate whose unit moves it
///   furthest from the wall (one unit is then enough, as each coordinate rounded by at most
///   half a unit). Rounding towards a wall the circle is still clear of is left alone: a
///   crowd pressing through a gap leans on how its near-touches round
///   (`a_crowd_following_lattice_directions…` in tests/path.rs jams when every such end is
///   moved), which deserves a look of its own.
///
/// The end is moved by at most three units in the last place, or the body stays where it is
/// (as it does where the move would take it past `MAX_COORD`).
fn off_contact(from: Vec2, step: Vec2, along: Option<Along>) -> Vec2 {
    let to = from + step;
    let Some(Along { normal, wall }) = along else {
        return to;
    };
    let lost = (step.x != 0.0 && to.x == from.x) || (step.y != 0.0 && to.y == from.y);
    // Only what rounding did: a step that goes into the wall by more than its rounding (an
    // approach, not a slide) is left as it is.
    let into_wall = !lost
        && (to - from).dot(normal) < 0.0
        && step.dot(normal) >= -1e-6 * step.abs().max_element()
        && wall.is_some_and(|t| t.segment.distance_squared_to(to + t.offset) < t.radius * t.radius);
    if !(lost || into_wall) {
        return to;
    }
    let mut end = to;
    for _ in 0..3 {
        if (end - from).dot(normal) >= 0.0 {
            // (Nudged past MAX_COORD, it stays: every body stays in range.)
            return if in_range(end) { end } else { from };
        }
        let (x, y) = (next_toward(end.x, normal.x), next_toward(end.y, normal.y));
        let along_x = if into_wall {
            (x - end.x).abs() * normal.x.abs() >= (y - end.y).abs() * normal.y.abs()
        } else {
            normal.x.abs() >= normal.y.abs()
        };
        if along_x {
            end.x = x;
        } else {
            end.y = y;
        }
    }
    from
}

/// The float next to `x` in the direction of `sign`'s sign (`x` itself for a zero `sign`).
fn next_toward(x: f32, sign: f32) -> f32 {
    if sign > 0.0 {
        x.next_up()
    } else if sign < 0.0 {
        x.next_down()
    } else {
        x
    }
}

/// `x` when `yes`, else `-0.0` (which added to anything leaves it bit for bit as it was,
/// `-0.0` included), by masking bits: no branch for a condition the predictor cannot guess.
fn keep_if(yes: bool, x: f32) -> f32 {
    let keep = u32::from(yes).wrapping_neg();
    f32::from_bits((x.to_bits() & keep) | (!keep & (-0.0f32).to_bits()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::ascii::{self, TEST_ROOM};
    use crate::{BodyDesc, BodyShape, Cell};

    fn room() -> TileMap {
        ascii::parse(TEST_ROOM, "room.txt", 1.0).unwrap()
    }

    /// Bodies of radius 0.4 and their resolver, stepped as `Bodies` steps them (in slot
    /// order; adding a body forgets the last resolve).
    #[derive(Default)]
    struct Crowd {
        bodies: Vec<Body>,
        resolver: Resolver,
    }

    impl Crowd {
        fn add(&mut self, at: Vec2) {
            let circle = BodyShape::circle(0.4).unwrap();
            self.bodies.push(Body::new(BodyDesc::new(at, circle)));
            self.resolver.forget();
        }

        /// Steps with the same proposed moves; the number of bodies skipped by each.
        fn skips(&mut self, map: &TileMap, moves: &[Vec2], steps: usize) -> Vec<usize> {
            (0..steps)
                .map(|_| {
                    for (body, &motion) in self.bodies.iter_mut().zip(moves) {
                        body.proposed = motion;
                    }
                    let mut bodies: Vec<&mut Body> = self.bodies.iter_mut().collect();
                    let config = ResolveConfig::default();
                    self.resolver.resolve(&mut bodies, &config, map);
                    for body in &mut self.bodies {
                        body.position += body.resolved;
                    }
                    self.resolver.skipped
                })
                .collect()
        }
    }

    #[test]
    fn a_body_pressed_into_a_corner_is_skipped_until_something_changes() {
        let mut map = room();
        let mut crowd = Crowd::default();
        crowd.add(Vec2::new(6.2, 1.6));
        let push = [Vec2::new(0.3, -0.3)];
        // Into the corner in a few steps, then blocked in place (resolved once more: it
        // stays, remembered), then skipped every step.
        let skipped = crowd.skips(&map, &push, 6);
        assert_eq!(skipped[..2], [0, 0]);
        assert_eq!(skipped[3..], [1, 1, 1], "{skipped:?}");
        let corner = crowd.bodies[0].position;
        assert!(corner.x > 6.59 && corner.y < 1.41, "{corner}");
        // A map edit far away does not wake it (the region an edit changes is its cell
        // grown by two cells, here x < 5.25; the hero reaches x > 5.7) ...
        let wall = Some(ascii::tile_for_char('#').unwrap().unwrap());
        map.set_tile(Cell::new(2, 3), wall).unwrap();
        assert_eq!(crowd.skips(&map, &push, 3), [1, 1, 1]);
        // ... one near it does.
        map.set_tile(Cell::new(5, 2), wall).unwrap();
        assert_eq!(crowd.skips(&map, &push, 3), [0, 1, 1]);
        assert_eq!(crowd.bodies[0].position, corner);
        // So does a body walking up to it (it is resolved first: a lower slot).
        crowd.bodies.clear();
        crowd.add(Vec2::new(4.0, 1.6));
        crowd.add(corner);
        let moves = [Vec2::new(0.5, 0.0), Vec2::new(0.3, -0.3)];
        let skipped = crowd.skips(&map, &moves, 8);
        // Forgotten on add; the hero is skipped while the walker is far, woken while it
        // closes in, and both settle in the end.
        assert_eq!(skipped[..3], [0, 1, 0], "{skipped:?}");
        assert_eq!(*skipped.last().unwrap(), 2, "{skipped:?}");
        assert_eq!(crowd.bodies[1].position, corner);
        assert!(crowd.bodies[0].position.distance(corner) >= 0.8);
    }
}
