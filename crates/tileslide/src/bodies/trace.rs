//! The resolver's trace: what [`Bodies::resolve_traced`](crate::Bodies::resolve_traced)
//! records of each body's passes, and the sink the resolver reports to.
//!
//! The resolver reports to a [`Sink`]: an `Option<&mut Recorder>`, `None` for `resolve`.
//! One sink type compiles the resolver once, whether or not a program also traces, so its
//! helpers keep a single caller each and are inlined as they are in a resolver without
//! tracing; an untraced resolve builds nothing to report and allocates nothing, and its
//! checks for `None` are branches the predictor always guesses. [`Recorder`] fills a
//! [`ResolveTrace`]; its methods are kept out of line and marked cold. It repeats work only
//! the trace needs (the graze test on the sweeps the resolver already made, the lookup of a
//! wall's source in the map), after the resolver has decided, so a traced resolve gives the
//! same bits as an untraced one.

use glam::Vec2;

use super::config::SlideMode;
use super::contact::{Obstacle, grazes, is_head_on};
use super::handle::BodyHandle;
use crate::geometry::{SweepHit, circle_circle};
use crate::query::{Capsule, QueryFilter, Wall};
use crate::tiles::{TileMap, WallSource};

/// What [`Bodies::resolve_traced`](crate::Bodies::resolve_traced) recorded: per body, per
/// pass, every contact the sweeps found, where it came from, and what the resolver did.
///
/// ```
/// # use tileslide::{io::ascii, Bodies, BodyDesc, BodyShape, ContactSource, Response, ResolveTrace, Vec2};
/// let map = ascii::parse("\
/// #####
/// #...#
/// #####", "doc.txt", 1.0)?;
/// let mut bodies = Bodies::new();
/// let ball = bodies.add(BodyDesc::new(Vec2::new(1.5, 1.5), BodyShape::circle(0.4)?))?;
/// bodies.propose(ball, Vec2::new(3.0, 0.05))?;
/// let mut trace = ResolveTrace::of(ball);
/// bodies.resolve_traced(&map, &mut trace);
/// let story = trace.body(ball).unwrap();
/// // The first pass meets the right wall (cell (4, 1)) and slides along it, the way the
/// // move leans (+y).
/// let pass = &story.passes[0];
/// let contact = pass.chosen().unwrap();
/// assert!(matches!(contact.source, ContactSource::Wall(tileslide::WallSource::Tile { segment, .. })
///     if segment.cell == tileslide::Cell::new(4, 1)));
/// assert_eq!(contact.normal, Vec2::new(-1.0, 0.0));
/// assert!(matches!(pass.response, Response::Slid { slide } if slide.y > 0.0));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ResolveTrace {
    /// The bodies to trace, sorted; `None` for every body.
    only: Option<Vec<BodyHandle>>,
    /// The bodies traced, in slot order (the order `resolve` takes them in).
    pub bodies: Vec<BodyTrace>,
}

impl ResolveTrace {
    /// A trace of every body.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// A trace of `handle`'s body alone.
    #[must_use]
    pub fn of(handle: BodyHandle) -> Self {
        Self {
            only: Some(vec![handle]),
            bodies: Vec::new(),
        }
    }

    /// A trace of the bodies `handles` alone (what an engine asks for the few bodies whose
    /// contacts it reports).
    #[must_use]
    pub fn of_bodies(handles: impl IntoIterator<Item = BodyHandle>) -> Self {
        let mut only: Vec<BodyHandle> = handles.into_iter().collect();
        only.sort_unstable();
        only.dedup();
        Self {
            only: Some(only),
            bodies: Vec::new(),
        }
    }

    /// What was recorded of `handle`'s body, if it was traced.
    #[must_use]
    pub fn body(&self, handle: BodyHandle) -> Option<&BodyTrace> {
        self.bodies.iter().find(|b| b.handle == handle)
    }

    fn wants(&self, handle: BodyHandle) -> bool {
        self.only
            .as_ref()
            .is_none_or(|only| only.binary_search(&handle).is_ok())
    }
}

/// One body's resolve.
#[derive(Clone, Debug, PartialEq)]
pub struct BodyTrace {
    /// The body.
    pub handle: BodyHandle,
    /// Where it started.
    pub start: Vec2,
    /// The move it proposed.
    pub proposed: Vec2,
    /// The move the resolve gave it.
    pub resolved: Vec2,
    /// Whether it was resolved, and if not, why.
    pub fate: BodyFate,
    /// Its passes of collide and slide, in order (none unless it was resolved).
    pub passes: Vec<PassTrace>,
}

/// Whether a body was resolved.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum BodyFate {
    /// It proposed no move: it stays, an obstacle the others slide round.
    Still,
    /// Skipped as settled: it was blocked in place last time and nothing it sees has
    /// changed, so it stays again (see `docs/resolver.md`, "Settled bodies").
    Settled,
    /// Resolved by collide and slide.
    Resolved,
}

/// One pass of collide and slide: a sweep of what is left of the move, its contacts, and
/// what the resolver did with the first.
#[derive(Clone, Debug, PartialEq)]
pub struct PassTrace {
    /// The pass's number, from 0.
    pub pass: u32,
    /// Where the body was when the pass began.
    pub from: Vec2,
    /// The move swept: what was left after the passes before.
    pub motion: Vec2,
    /// Every contact the sweeps found, walls near each circle then its neighbours, circle
    /// by circle (grazes included).
    pub contacts: Vec<ContactTrace>,
    /// The index in `contacts` of the contact the resolver acted on (the earliest; on equal
    /// `t` the first found, or among one circle's neighbours the lowest), `None` when the
    /// move was free.
    pub first: Option<usize>,
    /// How far the body moved in this pass.
    pub moved: Vec2,
    /// Whether the safe part up to the contact was taken: one shorter than an eighth of the
    /// gap is not (rounding would let a pressed body creep into a neighbour).
    pub step_taken: bool,
    /// What the resolver did.
    pub response: Response,
}

impl PassTrace {
    /// The contact the resolver acted on.
    #[must_use]
    pub fn chosen(&self) -> Option<&ContactTrace> {
        self.contacts.get(self.first?)
    }
}

/// A contact a sweep found.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactTrace {
    /// Which of the body's circles (its index in the body's shape).
    pub circle: u32,
    /// What it met.
    pub source: ContactSource,
    /// Which part of it.
    pub part: ContactPart,
    /// Time of impact, as a fraction `t` in [0, 1] of the pass's move.
    pub t: f32,
    /// The point met: on the wall, the nearest to the circle's centre at contact; on another
    /// body, the point of its circle facing the centre.
    pub point: Vec2,
    /// Unit contact normal, from the obstacle towards the circle's centre.
    pub normal: Vec2,
    /// Whether the resolver ignored it as a graze: a round obstacle (another body, a
    /// wall's rounded end) touched at `t = 0` by a move running along it to within rounding
    /// (see `docs/resolver.md`, "The gap band and the rounding traps"). A wall whose end is
    /// grazed may still be met further on, as a contact of its own.
    pub grazed: bool,
}

/// What a contact came from.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum ContactSource {
    /// A wall: a tile's segment or a temporary segment.
    Wall(WallSource),
    /// A circle of another body.
    Body {
        /// The body.
        handle: BodyHandle,
        /// Its circle's index in the body's shape.
        circle: u32,
    },
}

/// Which part of an obstacle a contact is on.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum ContactPart {
    /// A wall's flat front side.
    Face,
    /// A wall's rounded end (a convex corner, or an end nothing continues).
    RoundedEnd,
    /// Another body's circle.
    Circle,
}

/// What the resolver did with a pass's first contact.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum Response {
    /// No contact: the rest of the move was made.
    Free,
    /// Moved to the contact, and the blocked rest slid along the contact tangent, to the
    /// side its projection points: `slide` is the next pass's move.
    Slid {
        /// The slide.
        slide: Vec2,
    },
    /// Slid round a wall's rounded end: a convex corner rounded.
    RoundedCorner {
        /// The slide.
        slide: Vec2,
    },
    /// Met another body exactly head-on (no projection on the tangent): the write-up's
    /// tie-break turns the lower slot one way and the higher the other.
    TieBreak {
        /// The slide.
        slide: Vec2,
    },
    /// Met a wall straight on: stopped, without picking a side.
    StoppedHeadOn,
    /// Stopped in a concave corner: the slide along the last pass's wall ran straight into
    /// this one.
    StoppedInCorner,
    /// Stopped at the contact: the settings' [`SlideMode::Stop`].
    NoSlide,
    /// The last pass's contact: the move is cut there (the passes are used up).
    CutShort,
    /// Stopped at the contact because the slide would end beyond
    /// [`MAX_COORD`](crate::limits::MAX_COORD).
    OutOfRange,
}

impl Response {
    /// The slide this response starts, if any.
    #[must_use]
    pub fn slide(&self) -> Option<Vec2> {
        match *self {
            Response::Slid { slide }
            | Response::RoundedCorner { slide }
            | Response::TieBreak { slide } => Some(slide),
            _ => None,
        }
    }
}

/// What the resolver decided about a pass's first contact, for the trace.
pub(super) struct Decision {
    pub blocked: Vec2,
    pub normal: Vec2,
    pub obstacle: Obstacle,
    pub slide: Vec2,
    pub mode: SlideMode,
    pub last_pass: bool,
    pub out_of_range: bool,
}

/// What the resolver reports to while it works. Work indices: `b` is a body's index in slot
/// order among the bodies resolved, `circle` a circle's index in its body.
pub(super) trait Sink {
    /// Names a recorded contact, to say later which one the resolver acted on.
    type Id: Copy;
    /// Whether anything is recorded: when false, the resolver skips building what it would
    /// report.
    fn on(&self) -> bool;
    fn still(&mut self, b: u32, at: Vec2);
    fn settled(&mut self, b: u32, at: Vec2, motion: Vec2);
    fn begin(&mut self, b: u32, at: Vec2, motion: Vec2);
    fn pass(&mut self, pass: u32, from: Vec2, motion: Vec2);
    /// A wall within reach of circle `circle` at `center` (contact radius `radius`), and
    /// what the resolver's sweep of `motion` found.
    fn wall(
        &mut self,
        circle: u32,
        wall: &Capsule,
        center: Vec2,
        radius: f32,
        motion: Vec2,
        hit: Option<SweepHit>,
    ) -> Self::Id;
    /// A neighbour within reach: circle `other_circle` of body `other` at `at`, of radius
    /// `other_radius`.
    #[allow(clippy::too_many_arguments)]
    fn body(
        &mut self,
        circle: u32,
        other: (u32, u32),
        at: Vec2,
        other_radius: f32,
        center: Vec2,
        radius: f32,
        motion: Vec2,
        hit: Option<SweepHit>,
    ) -> Self::Id;
    /// The contact the pass acts on, whether the safe part was taken, and what was done.
    fn decide(&mut self, first: Self::Id, step_taken: bool, decision: Decision);
    /// The pass found no contact.
    fn free(&mut self);
    fn end(&mut self, b: u32, at: Vec2);
}

/// The sink of every resolve: a recorder when traced, `None` when not.
impl Sink for Option<&mut Recorder<'_>> {
    type Id = Option<usize>;
    #[inline(always)]
    fn still(&mut self, b: u32, at: Vec2) {
        if let Some(r) = self {
            r.still(b, at);
        }
    }
    #[inline(always)]
    fn settled(&mut self, b: u32, at: Vec2, motion: Vec2) {
        if let Some(r) = self {
            r.settled(b, at, motion);
        }
    }
    #[inline(always)]
    fn begin(&mut self, b: u32, at: Vec2, motion: Vec2) {
        if let Some(r) = self {
            r.begin(b, at, motion);
        }
    }
    #[inline(always)]
    fn pass(&mut self, pass: u32, from: Vec2, motion: Vec2) {
        if let Some(r) = self {
            r.pass(pass, from, motion);
        }
    }
    #[inline(always)]
    fn wall(
        &mut self,
        circle: u32,
        wall: &Capsule,
        center: Vec2,
        radius: f32,
        motion: Vec2,
        hit: Option<SweepHit>,
    ) -> Option<usize> {
        match self {
            Some(r) => r.wall(circle, wall, center, radius, motion, hit),
            None => None,
        }
    }
    #[inline(always)]
    fn body(
        &mut self,
        circle: u32,
        other: (u32, u32),
        at: Vec2,
        other_radius: f32,
        center: Vec2,
        radius: f32,
        motion: Vec2,
        hit: Option<SweepHit>,
    ) -> Option<usize> {
        match self {
            Some(r) => r.body(circle, other, at, other_radius, center, radius, motion, hit),
            None => None,
        }
    }
    #[inline(always)]
    fn decide(&mut self, first: Option<usize>, step_taken: bool, decision: Decision) {
        if let Some(r) = self {
            r.decide(first, step_taken, decision);
        }
    }
    #[inline(always)]
    fn free(&mut self) {
        if let Some(r) = self {
            r.free();
        }
    }
    #[inline(always)]
    fn end(&mut self, b: u32, at: Vec2) {
        if let Some(r) = self {
            r.end(b, at);
        }
    }
    #[inline(always)]
    fn on(&self) -> bool {
        self.is_some()
    }
}

/// The sink of a traced resolve: fills a [`ResolveTrace`].
pub(super) struct Recorder<'a> {
    trace: &'a mut ResolveTrace,
    map: &'a TileMap,
    /// Per work index, the body's handle.
    handles: &'a [BodyHandle],
    /// Whether the body being resolved is traced.
    on: bool,
    /// Scratch for looking up a wall's source.
    walls: Vec<Wall>,
}

impl<'a> Recorder<'a> {
    /// A recorder into `trace` (emptied) of the bodies whose handles are `handles`, in slot
    /// order, on `map`.
    pub fn new(trace: &'a mut ResolveTrace, map: &'a TileMap, handles: &'a [BodyHandle]) -> Self {
        trace.bodies.clear();
        Self {
            trace,
            map,
            handles,
            on: false,
            walls: Vec::new(),
        }
    }

    fn open(&mut self, b: u32, at: Vec2, motion: Vec2, fate: BodyFate) {
        let handle = self.handles[b as usize];
        self.on = self.trace.wants(handle);
        if self.on {
            self.trace.bodies.push(BodyTrace {
                handle,
                start: at,
                proposed: motion,
                resolved: Vec2::ZERO,
                fate,
                passes: Vec::new(),
            });
        }
    }

    fn current(&mut self) -> Option<&mut PassTrace> {
        if !self.on {
            return None;
        }
        self.trace.bodies.last_mut()?.passes.last_mut()
    }

    fn push(&mut self, contact: ContactTrace) -> Option<usize> {
        let pass = self.current()?;
        pass.contacts.push(contact);
        Some(pass.contacts.len() - 1)
    }

    /// Where `wall` comes from: the first of the map's walls with the very same capsule, in
    /// the order the resolver lists them (temporary segments, then cells row by row).
    fn source_of(&mut self, wall: &Capsule) -> Option<WallSource> {
        self.walls.clear();
        let region = wall.segment.aabb();
        self.map
            .walls_in(&region, &QueryFilter::both_sides(), &mut self.walls);
        let found = self.walls.iter().find(|w| w.capsule == *wall)?;
        found.source.wall_source(self.map)
    }
}

impl Sink for Recorder<'_> {
    type Id = Option<usize>;

    fn on(&self) -> bool {
        true
    }

    #[cold]
    #[inline(never)]
    fn still(&mut self, b: u32, at: Vec2) {
        self.open(b, at, Vec2::ZERO, BodyFate::Still);
    }

    #[cold]
    #[inline(never)]
    fn settled(&mut self, b: u32, at: Vec2, motion: Vec2) {
        self.open(b, at, motion, BodyFate::Settled);
    }

    #[cold]
    #[inline(never)]
    fn begin(&mut self, b: u32, at: Vec2, motion: Vec2) {
        self.open(b, at, motion, BodyFate::Resolved);
    }

    #[cold]
    #[inline(never)]
    fn pass(&mut self, pass: u32, from: Vec2, motion: Vec2) {
        if !self.on {
            return;
        }
        if let Some(body) = self.trace.bodies.last_mut() {
            body.passes.push(PassTrace {
                pass,
                from,
                motion,
                contacts: Vec::new(),
                first: None,
                moved: Vec2::ZERO,
                step_taken: true,
                response: Response::Free,
            });
        }
    }

    #[cold]
    #[inline(never)]
    fn wall(
        &mut self,
        circle: u32,
        wall: &Capsule,
        center: Vec2,
        radius: f32,
        motion: Vec2,
        hit: Option<SweepHit>,
    ) -> Option<usize> {
        if !self.on {
            return None;
        }
        // A rounded end the move only grazes: what `sweep_wall` drops before it sweeps again
        // without it.
        let graze = wall
            .sweep_ordinary(center, radius, motion)
            .filter(|&raw| raw.normal != wall.normal && grazes(raw, motion));
        if graze.is_none() && hit.is_none() {
            return None;
        }
        let source = ContactSource::Wall(self.source_of(wall)?);
        let contact = |hit: SweepHit, grazed: bool| ContactTrace {
            circle,
            source,
            part: if hit.normal == wall.normal {
                ContactPart::Face
            } else {
                ContactPart::RoundedEnd
            },
            t: hit.t,
            point: wall.segment.closest_point(center + motion * hit.t),
            normal: hit.normal,
            grazed,
        };
        if let Some(raw) = graze {
            self.push(contact(raw, true));
        }
        self.push(contact(hit?, false))
    }

    #[cold]
    #[inline(never)]
    fn body(
        &mut self,
        circle: u32,
        (other, other_circle): (u32, u32),
        at: Vec2,
        other_radius: f32,
        center: Vec2,
        radius: f32,
        motion: Vec2,
        hit: Option<SweepHit>,
    ) -> Option<usize> {
        if !self.on {
            return None;
        }
        // The exact sweep before `sweep_circle` drops a graze.
        let seen = hit.or_else(|| circle_circle(center - at, motion, radius))?;
        self.push(ContactTrace {
            circle,
            source: ContactSource::Body {
                handle: self.handles[other as usize],
                circle: other_circle,
            },
            part: ContactPart::Circle,
            t: seen.t,
            point: at + seen.normal * other_radius,
            normal: seen.normal,
            grazed: hit.is_none(),
        })
    }

    #[cold]
    #[inline(never)]
    fn decide(&mut self, first: Option<usize>, step_taken: bool, d: Decision) {
        let previous = self.current_previous_wall_slide();
        let Some(pass) = self.current() else {
            return;
        };
        pass.first = first;
        pass.step_taken = step_taken;
        pass.response = if d.last_pass {
            Response::CutShort
        } else if d.mode == SlideMode::Stop {
            Response::NoSlide
        } else if d.out_of_range {
            Response::OutOfRange
        } else {
            match d.obstacle {
                Obstacle::Wall { .. } if is_head_on(d.blocked, d.normal) => {
                    if previous {
                        Response::StoppedInCorner
                    } else {
                        Response::StoppedHeadOn
                    }
                }
                Obstacle::Body(_) if is_head_on(d.blocked, d.normal) => {
                    Response::TieBreak { slide: d.slide }
                }
                Obstacle::Wall { flat: false, .. } => Response::RoundedCorner { slide: d.slide },
                _ => Response::Slid { slide: d.slide },
            }
        };
    }

    #[cold]
    #[inline(never)]
    fn free(&mut self) {
        if let Some(pass) = self.current() {
            pass.response = Response::Free;
        }
    }

    #[cold]
    #[inline(never)]
    fn end(&mut self, _: u32, at: Vec2) {
        if !self.on {
            return;
        }
        if let Some(body) = self.trace.bodies.last_mut() {
            body.resolved = at - body.start;
            // Each pass moved the body from where it began to where the next began.
            let mut next = at;
            for pass in body.passes.iter_mut().rev() {
                pass.moved = next - pass.from;
                next = pass.from;
            }
        }
    }
}

impl Recorder<'_> {
    /// Whether the pass before the current one slid along a wall's face (so a head-on stop
    /// now is the slide running into a concave corner).
    fn current_previous_wall_slide(&self) -> bool {
        if !self.on {
            return false;
        }
        let Some(body) = self.trace.bodies.last() else {
            return false;
        };
        let n = body.passes.len();
        n >= 2 && {
            let before = &body.passes[n - 2];
            matches!(before.response, Response::Slid { .. })
                && before
                    .chosen()
                    .is_some_and(|c| matches!(c.source, ContactSource::Wall(_)))
        }
    }
}
