//! The set of bodies: generational handles, add and remove, and each body's state.

use glam::Vec2;
use thiserror::Error;

use super::body::{BodyDesc, BodyFilter, BodyShape};
use super::config::ResolveConfig;
use super::resolve::{ResolveReport, Scratch};
use crate::geometry::{MAX_COORD, in_range};
use crate::tiles::TileMap;

/// A body's handle. Handles are generational: once a body is removed its handle is stale
/// for good, even after its slot is reused, and every call with it returns
/// [`BodyError::StaleHandle`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct BodyHandle {
    index: u32,
    generation: u32,
}

impl BodyHandle {
    /// The slot index (small, dense; reused after a removal). Bodies are resolved in slot
    /// order.
    #[must_use]
    pub fn index(self) -> u32 {
        self.index
    }
}

/// Errors from [`Bodies`] calls and body shapes.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum BodyError {
    /// The handle's body was removed.
    #[error("stale body handle (slot {}, generation {}): the body was removed", .0.index, .0.generation)]
    StaleHandle(BodyHandle),
    /// A shape without circles.
    #[error("a body shape needs at least one circle")]
    EmptyShape,
    /// A circle's radius is not positive, or beyond [`MAX_COORD`] (NaN and infinity
    /// included).
    #[error(
        "circle {index} of the body shape has radius {radius}: it must be positive and at most {max}",
        max = MAX_COORD
    )]
    InvalidRadius {
        /// The circle's index in the shape.
        index: usize,
        /// Its radius.
        radius: f32,
    },
    /// A circle's offset has a coordinate beyond [`MAX_COORD`] (NaN and infinity included).
    #[error(
        "circle {index} of the body shape has offset {offset}: each coordinate must be at most {max} in magnitude",
        max = MAX_COORD
    )]
    InvalidOffset {
        /// The circle's index in the shape.
        index: usize,
        /// Its offset.
        offset: Vec2,
    },
    /// A position or move with a NaN or infinite coordinate.
    #[error("the {what} {value} is not finite")]
    NonFinite {
        /// `"position"` or `"move"`.
        what: &'static str,
        /// The value given.
        value: Vec2,
    },
    /// A position, or the end point of a move (where the body would be after it), with a
    /// finite coordinate beyond [`MAX_COORD`].
    #[error("the {what} {value} is out of range: each coordinate must be at most {max} in magnitude", max = MAX_COORD)]
    OutOfRange {
        /// `"position"` or `"move's end point"`.
        what: &'static str,
        /// The value given (for a move, where it ends).
        value: Vec2,
    },
    /// A [`ResolveConfig`] field out of its range (see the field's documentation).
    #[error("resolve setting {field} = {value} is out of range")]
    BadConfig {
        /// The field's name.
        field: &'static str,
        /// The value given.
        value: f32,
    },
    /// All `u32::MAX` slots are in use.
    #[error("too many bodies (at most {max})")]
    TooMany {
        /// The limit.
        max: u32,
    },
}

/// A body's state.
#[derive(Clone, Debug, PartialEq)]
pub struct Body {
    pub(crate) position: Vec2,
    pub(crate) shape: BodyShape,
    pub(crate) filter: BodyFilter,
    pub(crate) user_data: u64,
    /// The move the caller proposed for this step.
    pub(crate) proposed: Vec2,
    /// The move `resolve` settled on (the proposed one until then).
    pub(crate) resolved: Vec2,
}

impl Body {
    /// Where the body is.
    #[must_use]
    pub fn position(&self) -> Vec2 {
        self.position
    }

    /// Its shape.
    #[must_use]
    pub fn shape(&self) -> &BodyShape {
        &self.shape
    }

    /// Its filter.
    #[must_use]
    pub fn filter(&self) -> BodyFilter {
        self.filter
    }

    /// The caller's data.
    #[must_use]
    pub fn user_data(&self) -> u64 {
        self.user_data
    }

    /// The move proposed for this step (zero: the body is an obstacle this step).
    #[must_use]
    pub fn proposed_move(&self) -> Vec2 {
        self.proposed
    }

    /// The move `resolve` settled on; before `resolve`, the proposed move.
    #[must_use]
    pub fn resolved_move(&self) -> Vec2 {
        self.resolved
    }
}

#[derive(Clone, Debug)]
struct Slot {
    generation: u32,
    body: Option<Body>,
}

/// Free-moving bodies (circles and compounds of circles) and the three loops of a step:
/// [`propose`](Self::propose) a move per body, [`resolve`](Self::resolve) the moves
/// against each other and the walls, [`integrate`](Self::integrate) them.
///
/// ```
/// # use tileslide::{io::ascii, Bodies, BodyDesc, BodyShape, Vec2};
/// let map = ascii::parse("\
/// ########
/// #......#
/// #......#
/// ########", "doc.txt", 1.0)?;
/// let mut bodies = Bodies::new();
/// let hero = bodies.add(BodyDesc::new(Vec2::new(1.5, 1.5), BodyShape::circle(0.4)?))?;
/// // A big move right and a little down: the wall at x = 7 stops the hero, and the rest
/// // of the move slides along it.
/// bodies.propose(hero, Vec2::new(10.0, 0.2))?;
/// bodies.step(&map);
/// let p = bodies.get(hero)?.position();
/// assert!(p.x <= 6.6 && p.x > 6.59);
/// assert!(p.y > 1.7); // slid down the wall
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug, Default)]
pub struct Bodies {
    slots: Vec<Slot>,
    free: Vec<u32>,
    len: usize,
    config: ResolveConfig,
    pub(crate) scratch: Scratch,
}

impl Bodies {
    /// No bodies, the default [`ResolveConfig`].
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// No bodies, with `config`.
    ///
    /// # Errors
    /// [`BodyError::BadConfig`] naming the first field out of its range (see
    /// [`ResolveConfig`]).
    pub fn with_config(config: ResolveConfig) -> Result<Self, BodyError> {
        config.check()?;
        Ok(Self {
            config,
            ..Self::default()
        })
    }

    /// The resolve settings.
    #[must_use]
    pub fn config(&self) -> &ResolveConfig {
        &self.config
    }

    /// Changes the resolve settings.
    ///
    /// # Errors
    /// [`BodyError::BadConfig`] naming the first field out of its range (see
    /// [`ResolveConfig`]); the settings are then unchanged.
    pub fn set_config(&mut self, config: ResolveConfig) -> Result<(), BodyError> {
        config.check()?;
        self.config = config;
        Ok(())
    }

    /// Adds a body; its proposed move is zero.
    ///
    /// # Errors
    /// [`BodyError::NonFinite`] for a non-finite position, [`BodyError::OutOfRange`] for
    /// one beyond [`MAX_COORD`], [`BodyError::TooMany`] when every slot is taken.
    pub fn add(&mut self, desc: BodyDesc) -> Result<BodyHandle, BodyError> {
        check_position(desc.position)?;
        let body = Body {
            position: desc.position,
            shape: desc.shape,
            filter: desc.filter,
            user_data: desc.user_data,
            proposed: Vec2::ZERO,
            resolved: Vec2::ZERO,
        };
        let index = match self.free.pop() {
            Some(index) => index,
            None => {
                let index = u32::try_from(self.slots.len())
                    .ok()
                    .filter(|&i| i < u32::MAX)
                    .ok_or(BodyError::TooMany { max: u32::MAX })?;
                self.slots.push(Slot {
                    generation: 0,
                    body: None,
                });
                index
            }
        };
        let slot = &mut self.slots[index as usize];
        slot.body = Some(body);
        self.len += 1;
        self.scratch.forget();
        Ok(BodyHandle {
            index,
            generation: slot.generation,
        })
    }

    /// Removes a body and returns it; its handle is stale from now on.
    ///
    /// # Errors
    /// [`BodyError::StaleHandle`] when it was already removed.
    pub fn remove(&mut self, handle: BodyHandle) -> Result<Body, BodyError> {
        self.get(handle)?;
        let slot = &mut self.slots[handle.index as usize];
        let body = slot.body.take().ok_or(BodyError::StaleHandle(handle))?;
        // A slot whose generation would wrap is retired rather than reused, so no handle
        // ever becomes valid again.
        if slot.generation < u32::MAX {
            slot.generation += 1;
            self.free.push(handle.index);
        }
        self.len -= 1;
        self.scratch.forget();
        Ok(body)
    }

    /// The body of `handle`.
    ///
    /// # Errors
    /// [`BodyError::StaleHandle`] when it was removed.
    pub fn get(&self, handle: BodyHandle) -> Result<&Body, BodyError> {
        self.slots
            .get(handle.index as usize)
            .filter(|s| s.generation == handle.generation)
            .and_then(|s| s.body.as_ref())
            .ok_or(BodyError::StaleHandle(handle))
    }

    fn get_mut(&mut self, handle: BodyHandle) -> Result<&mut Body, BodyError> {
        self.slots
            .get_mut(handle.index as usize)
            .filter(|s| s.generation == handle.generation)
            .and_then(|s| s.body.as_mut())
            .ok_or(BodyError::StaleHandle(handle))
    }

    /// True while `handle`'s body exists.
    #[must_use]
    pub fn contains(&self, handle: BodyHandle) -> bool {
        self.get(handle).is_ok()
    }

    /// Number of bodies.
    #[must_use]
    pub fn len(&self) -> usize {
        self.len
    }

    /// True without bodies.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The bodies with their handles, in slot order (the order `resolve` uses).
    pub fn iter(&self) -> impl Iterator<Item = (BodyHandle, &Body)> {
        self.slots.iter().enumerate().filter_map(|(index, s)| {
            s.body.as_ref().map(|b| {
                (
                    BodyHandle {
                        index: index as u32,
                        generation: s.generation,
                    },
                    b,
                )
            })
        })
    }

    pub(crate) fn bodies_mut(&mut self) -> impl Iterator<Item = &mut Body> {
        self.slots.iter_mut().filter_map(|s| s.body.as_mut())
    }

    /// Sets the move `handle`'s body wants to make this step (zero: it stays, and others
    /// slide around it).
    ///
    /// The move's end point (the body's position plus the move) must be within
    /// [`MAX_COORD`], so no move is longer than `2√2 · MAX_COORD` and no arithmetic of the
    /// resolve overflows. Bodies stay within `MAX_COORD` for good: `resolve` stops a body
    /// rather than slide it past (see [`resolve`](Self::resolve)).
    ///
    /// # Errors
    /// [`BodyError::StaleHandle`], [`BodyError::NonFinite`] for a NaN or infinite move, or
    /// [`BodyError::OutOfRange`] for a move whose end point is beyond [`MAX_COORD`]; the
    /// body's move is then unchanged.
    pub fn propose(&mut self, handle: BodyHandle, motion: Vec2) -> Result<(), BodyError> {
        finite("move", motion)?;
        let body = self.get_mut(handle)?;
        check_end(body.position, motion)?;
        body.proposed = motion;
        body.resolved = motion;
        Ok(())
    }

    /// Moves a body without collision (a teleport); its proposed move is kept.
    ///
    /// # Errors
    /// [`BodyError::StaleHandle`], [`BodyError::NonFinite`] for a non-finite position, or
    /// [`BodyError::OutOfRange`] for a position beyond [`MAX_COORD`] or one from which the
    /// proposed move would end beyond it; the body is then where it was.
    pub fn set_position(&mut self, handle: BodyHandle, position: Vec2) -> Result<(), BodyError> {
        check_position(position)?;
        let body = self.get_mut(handle)?;
        check_end(position, body.proposed)?;
        body.position = position;
        Ok(())
    }

    /// Changes a body's filter.
    ///
    /// # Errors
    /// [`BodyError::StaleHandle`].
    pub fn set_filter(&mut self, handle: BodyHandle, filter: BodyFilter) -> Result<(), BodyError> {
        self.get_mut(handle)?.filter = filter;
        self.scratch.forget();
        Ok(())
    }

    /// Changes a body's user data.
    ///
    /// # Errors
    /// [`BodyError::StaleHandle`].
    pub fn set_user_data(&mut self, handle: BodyHandle, user_data: u64) -> Result<(), BodyError> {
        self.get_mut(handle)?.user_data = user_data;
        Ok(())
    }

    /// The second loop: adjusts every proposed move so that, made together, no two bodies
    /// overlap and none crosses a wall (see [`ResolveConfig`] for the options). Bodies
    /// without a proposed move stay put and the others slide around them. Read the result
    /// with [`Body::resolved_move`]; [`integrate`](Self::integrate) applies it.
    ///
    /// Between calls it remembers what makes the next one cheaper (which bodies may meet,
    /// the walls near each, which bodies were blocked in place); none of it changes a
    /// result. Editing the map ([`TileMap::set_tile`], temporary segments) costs only near
    /// the change: bodies far from it keep what was remembered, and temporary segments
    /// cleared and submitted again unchanged cost nothing. Adding or removing a body,
    /// changing a filter or the settings, or passing another map makes the next call resolve
    /// every moving body again.
    ///
    /// Every body stays within [`MAX_COORD`]: positions and the end points of proposed
    /// moves are refused beyond it, and a slide that would end beyond it is not taken (the
    /// body stops at the contact, as with [`SlideMode::Stop`](crate::SlideMode::Stop)).
    pub fn resolve(&mut self, map: &TileMap) -> ResolveReport {
        let config = self.config;
        let mut scratch = std::mem::take(&mut self.scratch);
        let mut bodies: Vec<&mut Body> = self.bodies_mut().collect();
        let report = scratch.resolve(&mut bodies, &config, map);
        self.scratch = scratch;
        report
    }

    /// [`resolve`](Self::resolve) then [`integrate`](Self::integrate): one whole step.
    pub fn step(&mut self, map: &TileMap) -> ResolveReport {
        let report = self.resolve(map);
        self.integrate();
        report
    }

    /// The third loop: every body makes its resolved move; proposed moves are cleared.
    pub fn integrate(&mut self) {
        for body in self.bodies_mut() {
            body.position += body.resolved;
            body.proposed = Vec2::ZERO;
            body.resolved = Vec2::ZERO;
        }
    }
}

fn finite(what: &'static str, value: Vec2) -> Result<(), BodyError> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(BodyError::NonFinite { what, value })
    }
}

/// A body's position: finite and within [`MAX_COORD`].
fn check_position(position: Vec2) -> Result<(), BodyError> {
    finite("position", position)?;
    in_range(position)
        .then_some(())
        .ok_or(BodyError::OutOfRange {
            what: "position",
            value: position,
        })
}

/// Where a body at `position` ends after a (finite) `motion`: within [`MAX_COORD`].
fn check_end(position: Vec2, motion: Vec2) -> Result<(), BodyError> {
    let end = position + motion;
    in_range(end).then_some(()).ok_or(BodyError::OutOfRange {
        what: "move's end point",
        value: end,
    })
}
