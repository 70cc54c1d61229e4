//! The objects a frame registers: where each is, how it moves, faces and aims, and who it
//! is.

use glam::Vec2;

use super::volume::{Facing, VolumeError, check_range};
use crate::owner::Owner;

/// An object registered for one frame: where it is, how it faces and aims, and who it is.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HitObject {
    /// The caller's entity (stable across frames: "hit once per swing" remembers it, and
    /// each [`HitEvent`](super::HitEvent) names it).
    pub owner: Owner,
    /// Its position at the end of the frame (its volumes' local origin).
    pub position: Vec2,
    /// How far it moved during the frame: its volumes are tested along the whole move, so
    /// a fast projectile cannot pass through a target between frames. Zero: a still test.
    pub motion: Vec2,
    /// Its size, about whose middle volumes are mirrored and attack volumes turned.
    pub size: Vec2,
    /// Which way it faces.
    pub facing: Facing,
    /// Where its attack volumes point, for a game that aims in any direction: `None` leaves
    /// them as drawn (for a game drawing them facing right, `+x`); `Some(direction)` (any
    /// length but zero) turns them, after mirroring by [`facing`](Self::facing), about the
    /// middle of [`size`](Self::size) so that the local `+x` points along `direction`. A
    /// rectangle turned by other than a quarter turn is tested as the turned rectangle it
    /// is. Vulnerability volumes are never turned. Turning needs the `aim` feature (on by
    /// default); without it [`HitWorld::register`](super::HitWorld::register) refuses an
    /// aim ([`VolumeError::AimUnsupported`]).
    pub aim: Option<Vec2>,
    /// Its team (see [`TeamRule`](super::TeamRule)).
    pub team: u32,
    /// Refuses every hit under [`TeamRule`](super::TeamRule) (a hero blinking after a hit).
    pub invulnerable: bool,
    /// The attack it is making, if it should hit each victim at most once until the attack
    /// ends: the swing ends at the first frame in which no object registers it.
    pub swing: Option<u64>,
}

impl HitObject {
    /// An object of `owner` at `position` of `size`: still, facing right and up, not
    /// aiming, team 0, no swing.
    #[must_use]
    pub fn new(owner: Owner, position: Vec2, size: Vec2) -> Self {
        Self {
            owner,
            position,
            motion: Vec2::ZERO,
            size,
            facing: Facing::default(),
            aim: None,
            team: 0,
            invulnerable: false,
            swing: None,
        }
    }

    /// Whether the object can be registered with its volumes: its position, where it
    /// starts the frame (`position − motion`) and its size finite and within
    /// [`MAX_COORD`](crate::limits::MAX_COORD), so that placing and sweeping its volumes cannot
    /// overflow, and its aim finite and not zero. [`HitWorld::register`](super::HitWorld::register)
    /// refuses an object this refuses.
    ///
    /// # Errors
    /// [`VolumeError::NonFinite`] or [`VolumeError::OutOfRange`] naming the value,
    /// [`VolumeError::ZeroAim`], or [`VolumeError::AimUnsupported`] (an aim without the
    /// `aim` feature).
    pub fn check(&self) -> Result<(), VolumeError> {
        self.checked_turn().map(|_| ())
    }

    /// What [`check`](Self::check) checks, and the unit vector the aim turns attack volumes
    /// by (`None` when it does not aim). (Always inlined with the `aim` feature, which
    /// otherwise leaves it out of line: registering calls it for every object.)
    #[cfg_attr(feature = "aim", inline(always))]
    pub(super) fn checked_turn(&self) -> Result<Option<Vec2>, VolumeError> {
        check_range("position", self.position)?;
        if !self.motion.is_finite() {
            let (x, y) = (self.motion.x, self.motion.y);
            return Err(VolumeError::NonFinite {
                what: "motion",
                x,
                y,
            });
        }
        check_range("start", self.position - self.motion)?;
        check_range("size", self.size)?;
        match self.aim {
            None => Ok(None),
            Some(aim) => turn(aim),
        }
    }
}

/// The unit vector `aim` turns attack volumes by: `None` for one pointing right (`+x`),
/// which is not turning. (Out of line: most objects do not aim.)
#[inline(never)]
fn turn(aim: Vec2) -> Result<Option<Vec2>, VolumeError> {
    if cfg!(not(feature = "aim")) {
        return Err(VolumeError::AimUnsupported);
    }
    let (x, y) = (aim.x, aim.y);
    if !aim.is_finite() {
        return Err(VolumeError::NonFinite { what: "aim", x, y });
    }
    // Scaled first so that its largest coordinate is ±1: the length then neither overflows
    // nor underflows, whatever the aim's magnitude.
    let largest = x.abs().max(y.abs());
    if largest == 0.0 {
        return Err(VolumeError::ZeroAim);
    }
    // Aiming right is not turning: those volumes are placed exactly as if not aiming.
    let unit = (aim / largest).normalize();
    Ok((unit != Vec2::X).then_some(unit))
}

/// An object's index in the frame's registrations: 0, 1, 2, … in the order
/// [`HitWorld::register`](super::HitWorld::register) accepted them, valid for that frame
/// (the next frame numbers its objects from 0 again; an [`Owner`] names the caller's
/// entity across frames).
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[cfg_attr(feature = "serde", serde(transparent))]
pub struct ObjectId(pub u32);
