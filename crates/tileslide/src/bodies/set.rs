//! The set of bodies: add and remove by generational handles, proposed moves, and the
//! three loops of a step.

use glam::Vec2;

use super::body::{Body, BodyDesc, BodyFilter};
use super::config::{ResolveConfig, ResolveReport};
use super::error::BodyError;
use super::handle::BodyHandle;
use super::resolver::Resolver;
use super::trace::{Recorder, ResolveTrace};
use crate::geometry::in_range;
use crate::owner::Owner;
use crate::tiles::TileMap;

/// Slots one task integrates at least (the `parallel` feature): a body's move is a few
/// nanoseconds.
#[cfg(feature = "parallel")]
const INTEGRATE_PER_TASK: usize = 4096;

/// A slot of a set: its body, if any, and its generation (the generation of its next
/// handle once the body is removed).
#[derive(Clone, Debug)]
pub(crate) struct Slot {
    pub(crate) generation: u32,
    pub(crate) body: Option<Body>,
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
    pub(crate) slots: Vec<Slot>,
    /// Empty slots to reuse, the last first.
    pub(crate) free: Vec<u32>,
    pub(crate) len: usize,
    pub(crate) config: ResolveConfig,
    pub(super) resolver: Resolver,
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
    /// [`BodyError::BadConfig`] naming the first field out of its range, as
    /// [`ResolveConfig::validate`] does.
    pub fn with_config(config: ResolveConfig) -> Result<Self, BodyError> {
        config.validate()?;
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
    /// [`BodyError::BadConfig`] naming the first field out of its range, as
    /// [`ResolveConfig::validate`] does; the settings are then unchanged.
    pub fn set_config(&mut self, config: ResolveConfig) -> Result<(), BodyError> {
        config.validate()?;
        self.config = config;
        Ok(())
    }

    /// Adds a body; its proposed move is zero.
    ///
    /// # Errors
    /// [`BodyError::NonFinite`] for a non-finite position, [`BodyError::OutOfRange`] for
    /// one beyond [`MAX_COORD`](crate::limits::MAX_COORD), [`BodyError::TooMany`] when every slot
    /// is taken.
    pub fn add(&mut self, desc: BodyDesc) -> Result<BodyHandle, BodyError> {
        check_position(desc.position)?;
        let body = Body::new(desc);
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
        self.resolver.forget();
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
        self.resolver.forget();
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

    fn bodies_mut(&mut self) -> impl Iterator<Item = &mut Body> {
        self.slots.iter_mut().filter_map(|s| s.body.as_mut())
    }

    /// The bodies in slot order, for the resolver, in a list allocated at their number
    /// (one grown as it fills is moved to a larger allocation a dozen times or more on the
    /// way to 100,000 bodies).
    fn body_list(&mut self) -> Vec<&mut Body> {
        let mut list = Vec::with_capacity(self.len);
        list.extend(self.bodies_mut());
        list
    }

    /// Sets the move `handle`'s body wants to make this step (zero: it stays, and others
    /// slide around it).
    ///
    /// The move's end point (the body's position plus the move) must be within
    /// [`MAX_COORD`](crate::limits::MAX_COORD), so no move is longer than `2√2 · MAX_COORD` and no
    /// arithmetic of the resolve overflows. Bodies stay within `MAX_COORD` for good:
    /// `resolve` stops a body rather than slide it past (see [`resolve`](Self::resolve)).
    ///
    /// # Errors
    /// [`BodyError::StaleHandle`], [`BodyError::NonFinite`] for a NaN or infinite move, or
    /// [`BodyError::OutOfRange`] for a move whose end point is beyond
    /// [`MAX_COORD`](crate::limits::MAX_COORD); the body's move is then unchanged.
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
    /// [`BodyError::OutOfRange`] for a position beyond [`MAX_COORD`](crate::limits::MAX_COORD) or
    /// one from which the proposed move would end beyond it; the body is then where it was.
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
        self.resolver.forget();
        Ok(())
    }

    /// Changes a body's owner.
    ///
    /// # Errors
    /// [`BodyError::StaleHandle`].
    pub fn set_owner(&mut self, handle: BodyHandle, owner: Owner) -> Result<(), BodyError> {
        self.get_mut(handle)?.owner = owner;
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
    /// Every body stays within [`MAX_COORD`](crate::limits::MAX_COORD): positions and the end
    /// points of proposed moves are refused beyond it, and a slide that would end beyond it
    /// is not taken (the body stops at the contact, as with
    /// [`SlideMode::Stop`](crate::SlideMode::Stop)).
    pub fn resolve(&mut self, map: &TileMap) -> ResolveReport {
        let config = self.config;
        let mut resolver = std::mem::take(&mut self.resolver);
        let mut bodies = self.body_list();
        let report = resolver.resolve(&mut bodies, &config, map);
        self.resolver = resolver;
        report
    }

    /// [`resolve`](Self::resolve), recording into `trace` what happened to the bodies it
    /// traces ([`ResolveTrace::new`]: every body; [`ResolveTrace::of`]: one): per pass, every
    /// contact the sweeps found with its source (a tile's cell, tile and segment; a temporary
    /// segment's owner and index; another body's handle and circle), its time of impact,
    /// point and normal, and what the resolver did (slid and which way, stopped, rounded a
    /// corner, took the tie-break, ignored a graze), or that a body was skipped as
    /// settled. The result is bit for bit what `resolve` gives.
    ///
    /// Tracing costs only when asked for: `resolve` passes no recorder, builds nothing to
    /// record and allocates nothing; the resolver is compiled once for both, so a program
    /// that traces runs its untraced resolves as fast as one that never does.
    pub fn resolve_traced(&mut self, map: &TileMap, trace: &mut ResolveTrace) -> ResolveReport {
        let config = self.config;
        let handles: Vec<BodyHandle> = self.iter().map(|(handle, _)| handle).collect();
        let mut resolver = std::mem::take(&mut self.resolver);
        let mut bodies = self.body_list();
        let mut recorder = Recorder::new(trace, map, &handles);
        let report = resolver.resolve_traced(&mut bodies, &config, map, &mut recorder);
        self.resolver = resolver;
        report
    }

    /// [`resolve_traced`](Self::resolve_traced) then [`integrate`](Self::integrate).
    pub fn step_traced(&mut self, map: &TileMap, trace: &mut ResolveTrace) -> ResolveReport {
        let report = self.resolve_traced(map, trace);
        self.integrate();
        report
    }

    /// [`resolve`](Self::resolve) then [`integrate`](Self::integrate): one whole step.
    pub fn step(&mut self, map: &TileMap) -> ResolveReport {
        let report = self.resolve(map);
        self.integrate();
        report
    }

    /// The third loop: every body makes its resolved move; proposed moves are cleared.
    ///
    /// With the `parallel` feature, many bodies are moved on the threads of the current
    /// rayon pool (each on its own: the same result).
    pub fn integrate(&mut self) {
        let make_move = |body: &mut Body| {
            body.position += body.resolved;
            body.proposed = Vec2::ZERO;
            body.resolved = Vec2::ZERO;
        };
        #[cfg(feature = "parallel")]
        if self.slots.len() >= 2 * INTEGRATE_PER_TASK && rayon::current_num_threads() > 1 {
            use rayon::prelude::*;
            self.slots
                .par_iter_mut()
                .with_min_len(INTEGRATE_PER_TASK)
                .filter_map(|slot| slot.body.as_mut())
                .for_each(make_move);
            return;
        }
        self.bodies_mut().for_each(make_move);
    }
}

fn finite(what: &'static str, value: Vec2) -> Result<(), BodyError> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(BodyError::NonFinite { what, value })
    }
}

/// A body's position: finite and within [`MAX_COORD`](crate::limits::MAX_COORD).
fn check_position(position: Vec2) -> Result<(), BodyError> {
    finite("position", position)?;
    in_range(position)
        .then_some(())
        .ok_or(BodyError::OutOfRange {
            what: "position",
            value: position,
        })
}

/// Where a body at `position` ends after a (finite) `motion`: within
/// [`MAX_COORD`](crate::limits::MAX_COORD).
fn check_end(position: Vec2, motion: Vec2) -> Result<(), BodyError> {
    let end = position + motion;
    in_range(end).then_some(()).ok_or(BodyError::OutOfRange {
        what: "move's end point",
        value: end,
    })
}
