//! The character's trace: what [`Character::move_by_traced`](crate::Character::move_by_traced)
//! records of a move, and the log the move's parts write to.
//!
//! Every part of a move takes a [`Log`]; `move_by` passes one that records nothing (a
//! `None` checked where an event would be built: a character moves a few times a frame, so
//! that check is all tracing costs when it is off). Probes that only look (is there ground
//! below this point of a walk?) always pass that one, so a trace holds what the character
//! did, not what it asked.

use glam::Vec2;

use super::contact::Surface;
use crate::geometry::SweepHit;
use crate::query::Wall;
use crate::tiles::{Owner, SegmentFlags, TileMap, WallSource};

/// What [`Character::move_by_traced`](crate::Character::move_by_traced) recorded of one
/// move: each sweep and what the move did with what it met, in order.
///
/// ```
/// use tileslide::{io::ascii, Character, CharacterShape, ControllerConfig, MoveEvent, MoveOptions, MoveTrace, Vec2};
/// let map = ascii::parse("\
/// #####
/// #...#
/// #####", "doc.txt", 1.0)?;
/// let shape = CharacterShape::rect(Vec2::new(0.25, 0.25))?;
/// let mut hero = Character::new(shape, Vec2::new(2.0, 1.5), Vec2::NEG_Y, ControllerConfig::default())?;
/// let mut trace = MoveTrace::default();
/// hero.move_by_traced(&map, Vec2::new(0.0, 1.0), MoveOptions::default(), &mut trace)?;
/// // A fall through the air onto the floor of cell (2, 2), and a landing.
/// let landed = trace.events.iter().any(|e| matches!(e, MoveEvent::Slide { response, .. }
///     if *response == tileslide::SlideResponse::Landed));
/// assert!(landed);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MoveTrace {
    /// Where the character started.
    pub start: Vec2,
    /// The displacement asked for.
    pub displacement: Vec2,
    /// Where it ended.
    pub end: Vec2,
    /// What happened, in order.
    pub events: Vec<MoveEvent>,
}

/// One thing that happened during a move.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum MoveEvent {
    /// Carried by the moving platform it stood on, by as much as the platform moved
    /// (swept: see the sweep that follows).
    Carried {
        /// The platform's owner.
        owner: Owner,
        /// How far the platform moved.
        by: Vec2,
    },
    /// The platform it stood on is gone (its owner submitted no such segment): off it.
    PlatformGone {
        /// The platform's owner.
        owner: Owner,
    },
    /// A temporary segment that moved into the character pushed it out.
    Pushed {
        /// The segment.
        source: WallSource,
        /// The way it pushed: its normal, or along it off its nearer end when the character
        /// reached less far past that end than into the segment.
        direction: Vec2,
        /// How deep it was in, that way.
        depth: f32,
        /// Whether the world stopped the push short: crushed.
        crushed: bool,
    },
    /// One exact sweep of the shape.
    Sweep(SweepTrace),
    /// What the move did with the surface a sweep met.
    Slide {
        /// The surface, for this character (walkable ground, ceiling, a wall on its left
        /// or right; a corner too high to step onto counts as a wall).
        surface: Surface,
        /// What the move did.
        response: SlideResponse,
        /// The move left to make.
        next: Vec2,
    },
    /// A one-way platform the sweep crossed did not hold the character.
    OneWay {
        /// The platform.
        source: WallSource,
        /// Why.
        pass: OneWayPass,
    },
    /// Stepped up onto a ledge no higher than the step height, instead of stopping at it.
    SteppedUp {
        /// How far the step moved it.
        by: Vec2,
    },
    /// A step up was tried and undone (no room, no progress, or no walkable ground low
    /// enough beyond).
    StepUpRefused,
    /// The walk left the ground at its edge: the rest of the move is through the air.
    LeftGround {
        /// Where.
        at: Vec2,
    },
    /// After the move, the character stands on this ground, moved down onto it (snapped
    /// when `drop` is more than zero).
    Grounded {
        /// The ground.
        source: WallSource,
        /// Its normal.
        normal: Vec2,
        /// How far the character dropped onto it.
        drop: f32,
    },
    /// After the move, no ground under the character: it is in the air.
    Airborne,
}

/// One exact sweep of the character's shape, and what it met.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SweepTrace {
    /// Why the character moved.
    pub purpose: SweepPurpose,
    /// Where it started.
    pub from: Vec2,
    /// The move swept.
    pub motion: Vec2,
    /// The first surface met, if any.
    pub hit: Option<MoveHit>,
    /// How far it moved: to a skin short of the surface met, or the whole move.
    pub moved: Vec2,
}

/// A surface a sweep met.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MoveHit {
    /// The segment.
    pub source: WallSource,
    /// Its flags.
    pub flags: SegmentFlags,
    /// Time of impact along the sweep (which looks a skin past the move), in [0, 1].
    pub t: f32,
    /// The point of the segment nearest to the shape's centre at contact.
    pub point: Vec2,
    /// The contact normal, towards the character.
    pub normal: Vec2,
    /// Whether it was met at a rounded end (a circle on a corner).
    pub rounded: bool,
}

/// Why the character swept.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum SweepPurpose {
    /// Carried by a platform.
    Carry,
    /// Pushed out of a platform.
    PushOut,
    /// Walking along the ground.
    Walk,
    /// Moving through the air.
    Air,
    /// Stepping up a ledge (up, forward, down).
    StepUp,
    /// Rolling a circle around a corner.
    Roll,
    /// Stepping down onto the ground where a walk leaves it.
    StepOff,
    /// Moving onto the ground below after the move.
    Settle,
}

/// What a move did with a surface it met.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum SlideResponse {
    /// Landed on walkable ground from the air: walks on along it with the rest of the
    /// sideways move.
    Landed,
    /// Walked onto walkable ground (a ramp up, or down onto a floor): on along it.
    WalkedOn,
    /// Slid along it with what is left of the move.
    SlidAlong,
    /// In the air against a steep surface: only the rise or fall slides on along it
    /// (sideways motion does not carry the character up).
    SlidDown,
    /// A walk into a wall or steep slope: stopped (a walk never climbs one).
    Stopped,
    /// A circle met a corner in the air: it rolls round it.
    Rolled,
}

/// Why a one-way platform did not hold the character.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum OneWayPass {
    /// The character's lowest point was below it: it passes (a jump up through it, a walk
    /// through its end).
    FromBelow,
    /// The move asked to drop through ([`MoveOptions::drop_through`](crate::MoveOptions)).
    DroppedThrough,
}

/// Where a move's events go: a trace, or nowhere.
pub(super) struct Log<'a> {
    trace: Option<&'a mut MoveTrace>,
    purpose: SweepPurpose,
}

impl<'a> Log<'a> {
    /// Records into `trace`, emptied.
    pub fn recording(trace: &'a mut MoveTrace, start: Vec2, displacement: Vec2) -> Self {
        trace.start = start;
        trace.displacement = displacement;
        trace.end = start;
        trace.events.clear();
        Self {
            trace: Some(trace),
            purpose: SweepPurpose::Air,
        }
    }

    /// Records nothing.
    pub fn off() -> Self {
        Self {
            trace: None,
            purpose: SweepPurpose::Air,
        }
    }

    /// Whether events are recorded (build them only then).
    pub fn is_on(&self) -> bool {
        self.trace.is_some()
    }

    /// The next sweeps are for `purpose`.
    pub fn purpose(&mut self, purpose: SweepPurpose) {
        self.purpose = purpose;
    }

    pub fn push(&mut self, event: MoveEvent) {
        if let Some(trace) = self.trace.as_deref_mut() {
            trace.events.push(event);
        }
    }

    /// A sweep from `from` by `motion` that met `met` (at `t` along `reach`), ending at
    /// `to`.
    pub fn sweep(
        &mut self,
        map: &TileMap,
        from: Vec2,
        motion: Vec2,
        met: Option<(SweepHit, &Wall, Vec2)>,
        to: Vec2,
    ) {
        if !self.is_on() {
            return;
        }
        let hit = met.and_then(|(hit, wall, reach)| {
            let at = from + reach * hit.t;
            Some(MoveHit {
                source: wall.source.wall_source(map)?,
                flags: wall.flags,
                t: hit.t,
                point: wall.capsule.segment.closest_point(at),
                normal: hit.normal,
                rounded: hit.normal != wall.capsule.normal,
            })
        });
        let purpose = self.purpose;
        self.push(MoveEvent::Sweep(SweepTrace {
            purpose,
            from,
            motion,
            hit,
            moved: to - from,
        }));
    }

    /// Where the move ended.
    pub fn end(&mut self, at: Vec2) {
        if let Some(trace) = self.trace.as_deref_mut() {
            trace.end = at;
        }
    }
}
