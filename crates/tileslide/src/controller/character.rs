//! A platformer character and its move: collide and slide against the tile world and its
//! temporary segments, walk along slopes, snap to the ground, one-way platforms.

mod edge;
mod roll;

use glam::Vec2;

use edge::Footing;

use super::contact::{Contact, Contacts, Surface};
use super::platform::Riding;
use super::trace::{Log, MoveEvent, MoveTrace, OneWayPass, SlideResponse, SweepPurpose};
use super::{CharacterShape, ControllerError};
use crate::geometry::{Aabb, MAX_COORD, Segment, SweepHit, in_range};
use crate::query::{Capsule, QueryFilter, SegmentSource, Wall};
use crate::tiles::{ActiveSegment, Owner, SegmentFlags, TileMap};

/// How a character moves: slope limit, ground snapping, the gap it keeps from surfaces.
/// Distances are in map units; the defaults suit maps with cells of size 1 (scale them with
/// the cell size, e.g. ×32 for Replica Island's pixels).
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ControllerConfig {
    /// The steepest walkable slope, in degrees from level: steeper surfaces are walls.
    /// Default 50.
    pub max_slope_degrees: f32,
    /// How far below its feet a grounded character that is not moving up looks for ground
    /// to stay on (walking down a ramp, over a small step down). Default 0.3.
    pub snap_distance: f32,
    /// The gap kept between the character and every surface it stops against, so that the
    /// next move does not start in contact. Default 0.001.
    pub skin: f32,
    /// How many times one move may hit a surface and slide on. Default 4.
    pub max_slides: u32,
    /// The highest ledge a walking character steps up onto instead of stopping at it (its
    /// top must be walkable), measured from the ground it walks on, for every shape: a
    /// circle does not roll up a corner higher than this either. Default 0: no stepping up.
    pub step_height: f32,
    /// Segments block the character when they have one of these flags. Default
    /// `SOLID | ONE_WAY`.
    pub mask: SegmentFlags,
}

impl Default for ControllerConfig {
    fn default() -> Self {
        Self {
            max_slope_degrees: 50.0,
            snap_distance: 0.3,
            skin: 1e-3,
            max_slides: 4,
            step_height: 0.0,
            mask: SegmentFlags::SOLID | SegmentFlags::ONE_WAY,
        }
    }
}

impl ControllerConfig {
    /// Whether the configuration can be used: the slope limit from 0 up to (not including) 90
    /// degrees, every distance from 0 to [`MAX_COORD`], at least one slide. [`Character::new`]
    /// refuses what this refuses.
    ///
    /// ```
    /// # use tileslide::{ControllerConfig, ControllerError};
    /// assert_eq!(ControllerConfig::default().validate(), Ok(()));
    /// let skin = ControllerConfig { skin: -1e-3, ..ControllerConfig::default() };
    /// assert_eq!(skin.validate(), Err(ControllerError::BadConfig { field: "skin", value: -1e-3 }));
    /// ```
    ///
    /// # Errors
    /// [`ControllerError::BadConfig`] naming the first field out of its range and its value (a
    /// NaN included).
    pub fn validate(&self) -> Result<(), ControllerError> {
        check_config(self)
    }
}

/// Requests for one move.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MoveOptions {
    /// Fall through one-way platforms during this move (hold it for as many moves as it
    /// takes the character to clear the platform).
    pub drop_through: bool,
}

/// A platformer character: a shape at a position, with an `up` direction, moved by a
/// desired displacement per step.
///
/// [`move_by`](Self::move_by) takes the displacement the game wants this step (velocity ×
/// dt, gravity included) and moves the character as far as the world lets it:
///
/// - Walking (sideways, while on the ground) follows the ground: up and down ramps no
///   steeper than the slope limit, keeping its sideways progress, and over tile seams
///   without a bump. A steeper surface is a wall.
/// - Downward motion while on the ground only presses the character onto it: standing on a
///   ramp it does not creep down.
/// - A walk that leaves the ground (none within the snap distance below it) goes only to
///   where the ground ends under it, even if there is ground again further on in the same
///   step; the rest of the step, fall included, is a move through the air from there, so
///   the fall starts at the edge whatever the frame rate, and a gap is not stepped over. A
///   circle walking over a rounded corner stays on it until its contact normal there is
///   steeper than the slope limit.
/// - In the air the whole displacement is swept at once, so the frame rate does not decide
///   whether a ledge is caught. Landing on walkable ground walks on along it with the rest
///   of the move's sideways part; falling along a wall or a steep slope slides down it;
///   rising into a ceiling stops (or slides along a slanted one); a circle meeting a corner
///   rolls around it exactly.
/// - After the move, a character that was on the ground and is not moving up looks
///   [`snap_distance`](ControllerConfig::snap_distance) below its feet and stays on any
///   walkable ground there.
/// - One-way platforms (`ONE_WAY` segments) block only a character whose lowest point is
///   on or above them: it jumps up through them, walks through their ends, lands on them,
///   and drops through on request ([`MoveOptions::drop_through`]).
///
/// Every part of a move is an exact sweep (see [`sweep_circle_segment`] and
/// [`sweep_box_segment`]), so no speed passes through a wall.
///
/// The character has no velocity of its own: gravity, jumps, coyote time and variable
/// jump height are the game's rules, kept in the game's velocity.
/// [`move_and_slide`](Self::move_and_slide) moves by that velocity × dt and takes out of it
/// what the surfaces touched stopped (landing zeroes the fall, a ceiling the rise, a wall
/// the speed into it), the part every game would otherwise write
/// ([`clip_velocity`](Self::clip_velocity) alone, for a displacement made otherwise).
///
/// ```
/// use tileslide::{Character, CharacterShape, ControllerConfig, MoveOptions, Vec2, io::ascii};
/// let map = ascii::parse("\
/// #######
/// #.....#
/// #.....#
/// #######", "doc.txt", 1.0)?;
/// // ASCII maps are y-down: up is -y.
/// let shape = CharacterShape::rect(Vec2::new(0.25, 0.4))?;
/// let mut hero = Character::new(shape, Vec2::new(2.0, 1.5), Vec2::NEG_Y, ControllerConfig::default())?;
/// // Fall: lands on the floor at y = 3, its bottom a skin above it.
/// let contacts = hero.move_by(&map, Vec2::new(0.0, 2.0), MoveOptions::default())?;
/// assert!(contacts.is_grounded());
/// assert!((hero.position.y - (3.0 - 0.4 - 0.001)).abs() < 1e-5);
/// // Walk right into the wall at x = 6.
/// let contacts = hero.move_by(&map, Vec2::new(10.0, 0.5), MoveOptions::default())?;
/// assert!(contacts.right.is_some() && contacts.is_grounded());
/// assert!((hero.position.x - (6.0 - 0.25 - 0.001)).abs() < 1e-4);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// [`sweep_circle_segment`]: crate::geometry::sweep_circle_segment
/// [`sweep_box_segment`]: crate::geometry::sweep_box_segment
#[derive(Clone, Debug)]
pub struct Character {
    /// The shape's centre, in world coordinates.
    pub position: Vec2,
    pub(crate) shape: CharacterShape,
    pub(crate) up: Vec2,
    /// The sideways axis (towards higher x, perpendicular to `up`).
    pub(crate) side: Vec2,
    pub(crate) config: ControllerConfig,
    /// Cosine of the slope limit.
    walkable: f32,
    /// The ground under the character after its last move.
    pub(crate) ground: Option<Contact>,
    /// Whether that ground is a rounded corner (a circle on a segment's end).
    pub(crate) ground_corner: bool,
    /// The moving platform it stands on, if its ground is one.
    pub(crate) riding: Option<Riding>,
    /// Scratch: the segments near the current sweep.
    walls: Vec<Wall>,
    /// Scratch: where whether a walk has ground below it can change (see
    /// [`edge`](Self::edge)).
    events: Vec<f32>,
}

/// The sideways axis of a character whose unit up is `up`: the map's x axis made
/// perpendicular to up (so "left" and "right" are the screen's whichever way y points);
/// for an up along x, up turned a quarter.
pub(crate) fn side_of(up: Vec2) -> Vec2 {
    (Vec2::X - up * up.x).try_normalize().unwrap_or(up.perp())
}

/// Moves shorter than this are not swept (they are rounding, not motion).
const MIN_MOVE: f32 = 1e-7;

/// A neighbour turns away from a segment's end (a convex corner) when its normal leans
/// along the segment's outward direction there by more than this cosine (as seam culling
/// decides it, `tiles::continuity`).
const CONVEX_COSINE: f32 = 1e-4;

/// How a move is being swept: a walk along the ground, or a move through the air (which
/// becomes a walk where it lands).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Phase {
    Walk,
    Air,
}

/// A surface a sweep met: the hit and its segment.
type Met = (SweepHit, Wall);

/// The line of the ground a walk follows: a point on it and its unit normal. The height of
/// a corner above it is what stepping onto that corner climbs.
#[derive(Clone, Copy, Debug)]
struct GroundLine {
    point: Vec2,
    normal: Vec2,
}

impl GroundLine {
    /// How far `point` is above the line, along its normal.
    fn height_of(&self, point: Vec2) -> f32 {
        (point - self.point).dot(self.normal)
    }
}

impl Character {
    /// A character of `shape` centred at `position`, with unit-length-or-not `up` (it is
    /// normalized), moving by `config`; an error naming the bad value when the position is
    /// not finite or beyond [`MAX_COORD`], `up` is zero or not finite, the shape's size is
    /// not positive or beyond `MAX_COORD`, or the configuration is out of range.
    pub fn new(
        shape: CharacterShape,
        position: Vec2,
        up: Vec2,
        config: ControllerConfig,
    ) -> Result<Self, ControllerError> {
        placed("position", position)?;
        let shape = shape.validated()?;
        let up = unit(up).ok_or(ControllerError::NonFinite {
            what: "up",
            value: up,
        })?;
        config.validate()?;
        Ok(Self {
            position,
            shape,
            up,
            side: side_of(up),
            walkable: config.max_slope_degrees.to_radians().cos(),
            config,
            ground: None,
            ground_corner: false,
            riding: None,
            walls: Vec::new(),
            events: Vec::new(),
        })
    }

    /// The character's shape.
    #[must_use]
    pub fn shape(&self) -> CharacterShape {
        self.shape
    }

    /// The unit up direction.
    #[must_use]
    pub fn up(&self) -> Vec2 {
        self.up
    }

    /// The configuration it moves by.
    #[must_use]
    pub fn config(&self) -> &ControllerConfig {
        &self.config
    }

    /// The ground under the character after its last move, if it stands on any.
    #[must_use]
    pub fn ground(&self) -> Option<&Contact> {
        self.ground.as_ref()
    }

    /// Moves the character to `position` (a teleport: no sweep), forgetting its ground; an
    /// error when it is not finite or beyond [`MAX_COORD`] (the character does not move).
    pub fn teleport(&mut self, position: Vec2) -> Result<(), ControllerError> {
        placed("position", position)?;
        self.position = position;
        self.ground = None;
        self.riding = None;
        Ok(())
    }

    /// Moves the character by `displacement` (velocity × dt) through `map` and its
    /// temporary segments, as described on the type, and returns what it touched. An error
    /// when the displacement is not finite or would end beyond [`MAX_COORD`] (the character
    /// does not move): within that range no length or product inside the move overflows.
    pub fn move_by(
        &mut self,
        map: &TileMap,
        displacement: Vec2,
        options: MoveOptions,
    ) -> Result<Contacts, ControllerError> {
        self.move_logged(map, displacement, options, &mut Log::off())
    }

    /// [`move_by`](Self::move_by), recording into `trace` what the move did: each sweep
    /// with the surface it met (a tile's cell, tile and segment, or a temporary segment's
    /// owner and index), time of impact, point and normal; what the move did with it
    /// (landed, walked on, slid, stopped, rolled round a corner); steps up, one-way
    /// platforms passed from below or dropped through, the platform carry and pushes,
    /// crushes, where a walk left the ground, and the ground it ends on. The character moves
    /// exactly as `move_by` moves it.
    ///
    /// # Errors
    /// What [`move_by`](Self::move_by) refuses (the trace then holds no event).
    pub fn move_by_traced(
        &mut self,
        map: &TileMap,
        displacement: Vec2,
        options: MoveOptions,
        trace: &mut MoveTrace,
    ) -> Result<Contacts, ControllerError> {
        let mut log = Log::recording(trace, self.position, displacement);
        self.move_logged(map, displacement, options, &mut log)
    }

    /// [`move_by`](Self::move_by), telling `log`.
    fn move_logged(
        &mut self,
        map: &TileMap,
        displacement: Vec2,
        options: MoveOptions,
        log: &mut Log<'_>,
    ) -> Result<Contacts, ControllerError> {
        finite("displacement", displacement)?;
        // (`position` is a public field: checked here too.)
        placed("position", self.position)?;
        if !in_range(self.position + displacement) {
            return Err(ControllerError::OutOfRange {
                what: "displacement",
                value: displacement,
            });
        }
        let mut contacts = Contacts::default();
        // Platforms moved first (the game submitted their new segments): go along with the
        // one stood on, and out of any that moved into the character.
        self.ride(map, options, log);
        self.push_out(map, options, &mut contacts, log);
        let rise = displacement.dot(self.up);
        let sideways = displacement.dot(self.side);
        // On the ground and neither jumping nor dropping through it: walk along it, and let
        // gravity only press.
        let walking = self.ground.filter(|ground| {
            rise <= 0.0 && !(options.drop_through && ground.flags.contains(SegmentFlags::ONE_WAY))
        });
        // In the air the whole displacement is swept at once: the path a smaller step would
        // take is the same straight line, so where it lands (or meets a ledge's face) does
        // not depend on the frame rate.
        let start = self.position;
        let (mut ends, last, mut left) = if let Some(ground) = walking {
            let walk = along(ground.normal, self.side, sideways);
            let line = self.ground_line(ground.normal, self.ground_corner);
            self.slide(map, walk, Some(line), None, options, &mut contacts, log)
        } else {
            self.slide(map, displacement, None, None, options, &mut contacts, log)
        };
        // Find the ground under the character: within the snap distance when it walked (so
        // it follows ramps down and steps down small ledges; a landing walks on, as the
        // next step would), within two skins otherwise (touching, not snapping).
        if left.is_none() {
            contacts.ground = self.settle(map, self.reach(ends), options, log);
            // No ground at the end of a walk whose last leg seemed to have some all along
            // (rounding at an edge): the walk ends where it does along that leg.
            if contacts.ground.is_none()
                && ends == Phase::Walk
                && let Some((from, leg)) = last
                && let Some((f, footing)) = self.edge(map, from, leg, false, options)
            {
                self.step_off(map, from + leg * f, &footing, options, log);
                left = Some(footing);
            }
        }
        // Walked off the ground's edge, or over a gap: the walk ends where the ground did,
        // on it, and the rest of the step (its share of the whole displacement, fall
        // included) is a move through the air from there, so where the fall starts does
        // not depend on the frame rate.
        if let Some(footing) = left
            && sideways != 0.0
        {
            let made = (self.position - start).dot(self.side) / sideways;
            let mut rest = displacement * (1.0 - made).clamp(0.0, 1.0);
            // A circle leaving a rounded corner is still on it: it rolls on around it as far
            // as the move presses it there, as a circle meeting it in the air does.
            let mut first = None;
            if let Some(corner) = footing.corner {
                (rest, first) = self.roll(map, corner, rest, options, log);
            }
            (ends, _, _) = self.slide(map, rest, None, first, options, &mut contacts, log);
            contacts.ground = self.settle(map, self.reach(ends), options, log);
        }
        if contacts.ground.is_none() {
            log.push(MoveEvent::Airborne);
        }
        log.end(self.position);
        self.ground = contacts.ground;
        self.riding = contacts.ground.and_then(|ground| Riding::on(map, &ground));
        Ok(contacts)
    }

    /// How far below its feet the character looks for ground after a move that ended in
    /// `phase`.
    fn reach(&self, phase: Phase) -> f32 {
        if phase == Phase::Walk {
            self.config.snap_distance
        } else {
            2.0 * self.config.skin
        }
    }

    /// The walkable ground up to `reach` below the character, and how far it drops onto it
    /// (to a skin above it; 0 when it is closer): the first surface it meets moving down
    /// when that is walkable, or else walkable ground met within two skins of it, which it
    /// stands on as well (a circle that rolled around a corner down onto the floor touches
    /// both, the corner first); the drop then stops a skin short of the first surface.
    fn ground_hit(
        &mut self,
        map: &TileMap,
        reach: f32,
        options: MoveOptions,
    ) -> Option<(SweepHit, Wall, f32)> {
        let down = -self.up * reach;
        let probe = &mut Log::off();
        let ((first, _), (hit, wall)) = match self.first_hits(map, down, options, None, probe) {
            (Some(first), Some(ground)) => (first, ground),
            _ => return None,
        };
        let (gap, limit) = (reach * hit.t, reach * first.t);
        if gap - limit > 2.0 * self.config.skin {
            return None;
        }
        let mut drop = gap - self.config.skin / self.up.dot(hit.normal);
        if first.t < hit.t {
            drop = drop.min(limit - self.config.skin);
        }
        Some((hit, wall, drop.max(0.0)))
    }

    /// Sweeps `motion` with collide and slide, recording contacts: a walk along the ground
    /// `line` when there is one, a move through the air otherwise, `first` being the surface
    /// it meets first when that is known (a roll stopped by it). Returns the phase it
    /// ended in (a move through the air that lands walks on); when its last leg was swept
    /// clear to its end, that leg (its start and motion); and when a walk left the ground
    /// (see [`edge`](Self::edge)), the ground just before, the character having stopped
    /// there.
    #[allow(clippy::too_many_arguments)]
    fn slide(
        &mut self,
        map: &TileMap,
        motion: Vec2,
        mut line: Option<GroundLine>,
        mut first: Option<Met>,
        options: MoveOptions,
        contacts: &mut Contacts,
        log: &mut Log<'_>,
    ) -> (Phase, Option<(Vec2, Vec2)>, Option<Footing>) {
        let mut remaining = motion;
        for _ in 0..self.config.max_slides {
            let phase = if line.is_some() {
                Phase::Walk
            } else {
                Phase::Air
            };
            let from = self.position;
            log.purpose(if phase == Phase::Walk {
                SweepPurpose::Walk
            } else {
                SweepPurpose::Air
            });
            let gone = match first.take() {
                Some((hit, wall)) => Some((hit, wall, remaining)),
                None => self.go(map, remaining, options, None, log),
            };
            // The walk leaves the ground where the ground ends under this leg, even if there
            // is ground again further on: a gap is not stepped over, however long the step.
            if phase == Phase::Walk
                && let leg = self.position - from
                && let Some((f, footing)) = self.edge(map, from, leg, true, options)
            {
                self.step_off(map, from + leg * f, &footing, options, log);
                return (phase, None, Some(footing));
            }
            let Some((hit, wall, rest)) = gone else {
                return (phase, Some((from, remaining)), None);
            };
            let mut surface = Surface::of(hit.normal, self.up, self.side, self.walkable);
            // A corner (a segment's end, met by a circle's rounded side) higher above the
            // ground than the step height is a ledge's edge: a wall to a walk, however
            // walkable its normal, so a circle climbs no more than a box does.
            if let Some(line) = line
                && surface == Surface::Ground
                && hit.normal != wall.capsule.normal
                && self.climb(&line, hit.normal) > self.config.step_height + self.slack()
            {
                surface = if rest.dot(self.side) > 0.0 {
                    Surface::Right
                } else {
                    Surface::Left
                };
            }
            // A ledge low enough to step onto: stepped over, not a wall.
            if let Some(line) = line
                && self.config.step_height > 0.0
                && matches!(surface, Surface::Left | Surface::Right)
                && self.step_up(map, rest, &line, options, log)
            {
                return (Phase::Walk, None, None);
            }
            let contact = Contact {
                normal: hit.normal,
                flags: wall.flags,
                source: wall.source,
            };
            match surface {
                Surface::Ground => contacts.ground = Some(contact),
                Surface::Ceiling => contacts.ceiling = Some(contact),
                Surface::Left => contacts.left = Some(contact),
                Surface::Right => contacts.right = Some(contact),
            }
            let mut landing =
                surface == Surface::Ground && (phase == Phase::Walk || rest.dot(self.up) <= 0.0);
            // A fall that meets the ground's end beside it (a box's bottom corner on a
            // ledge's edge, stopped before its side is over the ledge) is not standing on it:
            // a walk from there would leave the ground where it starts and fly the step
            // again, stuck on the edge. It slides on along the ground through the air, and
            // stands on it once over it.
            if landing
                && phase == Phase::Air
                && self
                    .ground_hit(map, 2.0 * self.config.skin, options)
                    .is_none()
            {
                landing = false;
            }
            if phase == Phase::Air && !landing && self.at_rounded_corner(&hit, &wall) {
                let corner = nearest_end(&wall.capsule.segment, self.position);
                (remaining, first) = self.roll(map, corner, rest, options, log);
                if log.is_on() {
                    let (response, next) = (SlideResponse::Rolled, remaining);
                    log.push(MoveEvent::Slide {
                        surface,
                        response,
                        next,
                    });
                }
                continue;
            }
            let slid = rest - hit.normal * rest.dot(hit.normal);
            let response;
            (remaining, response) = match (phase, surface) {
                // Walking onto walkable ground (a ramp up, or down onto a floor), or landing
                // on it: on along it, keeping the sideways progress still to make (a smaller
                // step would walk on from there in its next steps).
                (_, Surface::Ground) if landing => {
                    line = Some(self.ground_line(hit.normal, self.at_rounded_corner(&hit, &wall)));
                    let on = along(hit.normal, self.side, rest.dot(self.side));
                    if phase == Phase::Air {
                        (on, SlideResponse::Landed)
                    } else {
                        (on, SlideResponse::WalkedOn)
                    }
                }
                // A wall or steep slope: slide along it, but a walk never climbs it.
                (Phase::Walk, Surface::Left | Surface::Right) => {
                    if slid.dot(self.up) > 0.0 {
                        (Vec2::ZERO, SlideResponse::Stopped)
                    } else {
                        (slid, SlideResponse::SlidAlong)
                    }
                }
                // In the air, sideways motion does not carry the character up a steep slope
                // either: where sliding would rise more than the move does, only the move's
                // rise or fall slides on.
                (Phase::Air, Surface::Left | Surface::Right)
                    if slid.dot(self.up) > rest.dot(self.up) =>
                {
                    let vertical = self.up * rest.dot(self.up);
                    let into = vertical.dot(hit.normal).min(0.0);
                    (vertical - hit.normal * into, SlideResponse::SlidDown)
                }
                _ => (slid, SlideResponse::SlidAlong),
            };
            if log.is_on() {
                let next = remaining;
                log.push(MoveEvent::Slide {
                    surface,
                    response,
                    next,
                });
            }
        }
        let phase = if line.is_some() {
            Phase::Walk
        } else {
            Phase::Air
        };
        (phase, None, None)
    }

    /// The line of the ground with `normal` that the character stands on where it is (a
    /// skin below it). On a rounded `corner` it is level through the corner: a circle
    /// rolling over a crack between two floors as high as each other climbs nothing to roll
    /// out of it, though the far corner is above the tangent it rolls along.
    fn ground_line(&self, normal: Vec2, corner: bool) -> GroundLine {
        GroundLine {
            point: self.ground_point(normal),
            normal: if corner { self.up } else { normal },
        }
    }

    /// The point of a surface with `normal` that the character, a skin away from it, would
    /// touch: for a corner met by a circle, the corner itself.
    fn ground_point(&self, normal: Vec2) -> Vec2 {
        self.position - normal * (self.shape.support(normal) + self.config.skin)
    }

    /// How high above `line` the surface the character touches with `normal` is: what
    /// standing on it climbs.
    fn climb(&self, line: &GroundLine, normal: Vec2) -> f32 {
        line.height_of(self.ground_point(normal))
    }

    /// The rounding allowed in comparing a climb with the step height: a few units in the
    /// last place of the coordinates.
    fn slack(&self) -> f32 {
        8.0 * f32::EPSILON * self.position.abs().max_element().max(1.0)
    }

    /// Moves by `motion` up to the first surface in the way (ignoring `exclude`'s temporary
    /// segments), stopping a skin short of it (measured along its normal). Returns that
    /// surface and the part of `motion` not made, or `None` when the whole move was made
    /// clear of every surface (or it was too short, or absurdly long, to sweep).
    ///
    /// The sweep looks a skin further than the move, so a move that ends just short of a
    /// surface head-on also stops a skin short of it (and reports it). A move that only
    /// grazes a surface may end closer to it (down to the skin times the cosine of the
    /// angle of approach), never inside it.
    pub(super) fn go(
        &mut self,
        map: &TileMap,
        motion: Vec2,
        options: MoveOptions,
        exclude: Option<Owner>,
        log: &mut Log<'_>,
    ) -> Option<(SweepHit, Wall, Vec2)> {
        let length = motion.length();
        // (Not finite only for absurd displacements scaled up along a steep ramp.)
        if length <= MIN_MOVE || !length.is_finite() {
            return None;
        }
        let dir = motion / length;
        let reach = length + self.config.skin;
        let from = self.position;
        let Some((hit, wall)) = self.first_hit(map, dir * reach, options, exclude, log) else {
            self.position += motion;
            log.sweep(map, from, motion, None, self.position);
            return None;
        };
        let approach = -dir.dot(hit.normal);
        let back = if approach > 0.0 {
            self.config.skin / approach
        } else {
            0.0
        };
        let mut advance = (reach * hit.t - back).clamp(0.0, length);
        // An advance within the rounding of the position is not made: rounded, it would not
        // move the character along `dir` but a unit in the last place along one axis and
        // none along the other, off its way (a character pinned in a wedge between a ramp
        // and a ceiling, pushing on, crept into the ramp by that every step).
        if advance <= self.slack() {
            advance = 0.0;
        }
        self.position += dir * advance;
        log.sweep(
            map,
            from,
            motion,
            Some((hit, &wall, dir * reach)),
            self.position,
        );
        Some((hit, wall, motion - dir * advance))
    }

    /// Tries to step over the ledge a walk on `line` just met: up by the step height (as far
    /// as there is room), forward by the walk's sideways remainder `rest`, then down onto
    /// walkable ground no lower than where it started and no higher above `line` than the
    /// step height. Undone (false) when it makes no progress or finds no such ground.
    ///
    /// The height is checked where the character lands, not only by how far it was lifted:
    /// a circle lifted by the step height can come down on a higher ledge's rounded corner
    /// (as much as `radius · (1 − cos max_slope)` higher) with a walkable normal.
    fn step_up(
        &mut self,
        map: &TileMap,
        rest: Vec2,
        line: &GroundLine,
        options: MoveOptions,
        log: &mut Log<'_>,
    ) -> bool {
        let start = self.position;
        let forward = self.side * rest.dot(self.side);
        if forward.length() <= MIN_MOVE {
            return false;
        }
        log.purpose(SweepPurpose::StepUp);
        self.go(map, self.up * self.config.step_height, options, None, log);
        let raised = (self.position - start).dot(self.up);
        let lifted = self.position;
        self.go(map, forward, options, None, log);
        let progress = (self.position - lifted).dot(self.side).abs();
        let landed = progress > self.config.skin
            && self
                .go(
                    map,
                    -self.up * (raised + self.config.skin),
                    options,
                    None,
                    log,
                )
                .is_some_and(|(hit, _, _)| {
                    Surface::of(hit.normal, self.up, self.side, self.walkable) == Surface::Ground
                        && self.climb(line, hit.normal) <= self.config.step_height + self.slack()
                });
        if landed {
            log.push(MoveEvent::SteppedUp {
                by: self.position - start,
            });
        } else {
            self.position = start;
            log.push(MoveEvent::StepUpRefused);
        }
        landed
    }

    /// Looks up to `reach` below the character for walkable ground (see
    /// [`ground_hit`](Self::ground_hit)); if found, moves onto it (a skin above) and
    /// returns it.
    fn settle(
        &mut self,
        map: &TileMap,
        reach: f32,
        options: MoveOptions,
        log: &mut Log<'_>,
    ) -> Option<Contact> {
        let (hit, wall, drop) = self.ground_hit(map, reach, options)?;
        self.position -= self.up * drop;
        self.ground_corner = self.at_rounded_corner(&hit, &wall);
        if log.is_on()
            && let Some(source) = wall.source.wall_source(map)
        {
            let normal = hit.normal;
            log.push(MoveEvent::Grounded {
                source,
                normal,
                drop,
            });
        }
        Some(Contact {
            normal: hit.normal,
            flags: wall.flags,
            source: wall.source,
        })
    }

    /// The first surface the character meets moving by `motion` from where it is: every
    /// segment near the move (but `exclude`'s temporary segments), swept exactly; on equal
    /// `t`, the one ranked first by [`meets_before`](Self::meets_before), whatever order
    /// the segments come in.
    fn first_hit(
        &mut self,
        map: &TileMap,
        motion: Vec2,
        options: MoveOptions,
        exclude: Option<Owner>,
        log: &mut Log<'_>,
    ) -> Option<Met> {
        self.first_hits(map, motion, options, exclude, log).0
    }

    /// [`first_hit`](Self::first_hit), and the first walkable ground met (ranked alike).
    fn first_hits(
        &mut self,
        map: &TileMap,
        motion: Vec2,
        options: MoveOptions,
        exclude: Option<Owner>,
        log: &mut Log<'_>,
    ) -> (Option<Met>, Option<Met>) {
        let (start, end) = (
            self.shape.bounds(self.position),
            self.shape.bounds(self.position + motion),
        );
        let region = Aabb::from_corners(start.min.min(end.min), start.max.max(end.max))
            .expand(self.config.skin);
        let mut filter = QueryFilter::default().with_mask(self.config.mask);
        filter.exclude_owner = exclude;
        self.walls.clear();
        map.walls_in(&region, &filter, &mut self.walls);
        let mut best: Option<Met> = None;
        let mut ground: Option<Met> = None;
        for wall in &self.walls {
            let capsule = &wall.capsule;
            if !self.held_by(wall.flags, capsule.segment.a, capsule.normal, options) {
                if log.is_on() {
                    self.log_one_way(map, wall, motion, options, log);
                }
                continue;
            }
            let Some(mut hit) = self.shape.sweep(capsule, self.position, motion) else {
                continue;
            };
            // Met at a rounded end: unless the surface goes on there for this character.
            if hit.normal != capsule.normal {
                let caps = self.caps_needed(map, wall, options);
                if caps != capsule.caps {
                    let bare = Capsule { caps, ..*capsule };
                    let Some(face) = self.shape.sweep(&bare, self.position, motion) else {
                        continue;
                    };
                    hit = face;
                }
            }
            let before = |kept: &Option<Met>| {
                kept.is_none_or(|(b, w)| self.meets_before(motion, (&hit, wall), (&b, &w)))
            };
            if Surface::of(hit.normal, self.up, self.side, self.walkable) == Surface::Ground
                && before(&ground)
            {
                ground = Some((hit, *wall));
            }
            if before(&best) {
                best = Some((hit, *wall));
            }
        }
        (best, ground)
    }

    /// Whether the surface `a` (a hit and its segment) stops a move by `motion` before
    /// `b`: at a smaller `t`; on equal `t` (a concave corner reached exactly: a floor and a
    /// wall, each its own normal), the one the motion meets more head-on (larger
    /// `−normal·motion`), which takes the skin along the motion while the other is slid
    /// into; then walkable ground before a wall or ceiling (larger `normal·up`); then by the
    /// normal's coordinates; then a temporary segment before a tile's (a moving platform
    /// flush with the floor is the ground ridden); then by the segment's coordinates and
    /// the flags, so that the choice never depends on the order the segments are found in.
    /// Only segments alike in kind, place, normal and flags remain tied, and they stop the
    /// character alike (their contacts differ in source only).
    fn meets_before(&self, motion: Vec2, a: (&SweepHit, &Wall), b: (&SweepHit, &Wall)) -> bool {
        let key = |(hit, wall): (&SweepHit, &Wall)| {
            let segment = &wall.capsule.segment;
            [
                hit.t,
                hit.normal.dot(motion),
                -hit.normal.dot(self.up),
                hit.normal.x,
                hit.normal.y,
                f32::from(u8::from(matches!(wall.source, SegmentSource::Tile { .. }))),
                segment.a.x,
                segment.a.y,
                segment.b.x,
                segment.b.y,
            ]
        };
        let (ka, kb) = (key(a), key(b));
        match ka.iter().zip(&kb).find(|(x, y)| x != y) {
            Some((x, y)) => x < y,
            None => a.1.flags.0 < b.1.flags.0,
        }
    }

    /// Whether a segment with `flags`, through `point` with unit `normal`, can stop the
    /// character on this move: any segment the mask takes, but a one-way platform only
    /// when the character's lowest point (towards the platform) is on or above it, give or
    /// take two skins, and it is not dropping through.
    fn held_by(
        &self,
        flags: SegmentFlags,
        point: Vec2,
        normal: Vec2,
        options: MoveOptions,
    ) -> bool {
        if !flags.intersects(self.config.mask) {
            return false;
        }
        if flags.contains(SegmentFlags::ONE_WAY) && !flags.contains(SegmentFlags::SOLID) {
            return !options.drop_through && self.is_on_or_above(point, normal);
        }
        true
    }

    /// Whether the character's lowest point towards a line through `point` with unit
    /// `normal` is on or above it, give or take two skins: where a one-way platform holds
    /// it.
    fn is_on_or_above(&self, point: Vec2, normal: Vec2) -> bool {
        let height = (self.position - point).dot(normal) - self.shape.support(normal);
        height >= -2.0 * self.config.skin
    }

    /// Records a one-way platform `wall` (which [`held_by`](Self::held_by) just let the
    /// move by `motion` through) if the move crosses it, from either side, and why it let
    /// the character through.
    fn log_one_way(
        &self,
        map: &TileMap,
        wall: &Wall,
        motion: Vec2,
        options: MoveOptions,
        log: &mut Log<'_>,
    ) {
        let capsule = &wall.capsule;
        if !wall.flags.contains(SegmentFlags::ONE_WAY) || !wall.flags.intersects(self.config.mask) {
            return;
        }
        let segment = Segment::new(capsule.segment.b, capsule.segment.a);
        let back = Capsule::new(segment, -capsule.normal, [capsule.caps[1], capsule.caps[0]]);
        let crossed = [capsule, &back]
            .into_iter()
            .any(|c| self.shape.sweep(c, self.position, motion).is_some());
        let Some(source) = wall.source.wall_source(map).filter(|_| crossed) else {
            return;
        };
        let pass = if options.drop_through && self.is_on_or_above(capsule.segment.a, capsule.normal)
        {
            OneWayPass::DroppedThrough
        } else {
            OneWayPass::FromBelow
        };
        log.push(MoveEvent::OneWay { source, pass });
    }

    /// `wall`'s rounded ends, less those its neighbours cover for this character on this
    /// move: an end where the surface continues, flat or turning concave, into a neighbour
    /// that stops the character too; and an end (a side face's top, say) on a seam of a
    /// floor that goes on flat or concave past it on both sides, both halves stopping the
    /// character, which is in front of both.
    ///
    /// Seam culling keeps these caps where a one-way platform meets another or a solid tile
    /// (and where flags change), and keeps a solid tile's side face beside a one-way
    /// platform (the platform hides nothing): a body coming from below a platform must meet
    /// them. A character the platform holds is above them, where the floor's faces cover
    /// them: through rounding they tilted a rolling circle's ground normal by 2e-4 and moved
    /// it by 1e-5 of a cell. So for it they are flat, as on an all-solid floor.
    fn caps_needed(&self, map: &TileMap, wall: &Wall, options: MoveOptions) -> [bool; 2] {
        let mut caps = wall.capsule.caps;
        let SegmentSource::Tile { segment, .. } = wall.source else {
            return caps;
        };
        let Some(this) = map.active_segment(segment) else {
            return caps;
        };
        for (end, cap) in caps.iter_mut().enumerate() {
            let point = end_point(&this.segment, end);
            let Some(next) = this.continues[end].and_then(|r| map.active_segment(r)) else {
                continue;
            };
            if !*cap || !self.held_by(next.flags, next.segment.a, next.normal, options) {
                continue;
            }
            if next.normal.dot(outward(&this.segment, end)) <= CONVEX_COSINE {
                *cap = false;
                continue;
            }
            // A convex end: is it a seam inside a floor that holds the character?
            let far = usize::from(
                next.segment.b.distance_squared(point) < next.segment.a.distance_squared(point),
            );
            let Some(beyond) = next.continues[far].and_then(|r| map.active_segment(r)) else {
                continue;
            };
            let in_front = |s: &ActiveSegment| (self.position - s.segment.a).dot(s.normal) >= 0.0;
            if beyond.normal.dot(outward(&next.segment, far)) <= CONVEX_COSINE
                && self.held_by(beyond.flags, beyond.segment.a, beyond.normal, options)
                && in_front(&next)
                && in_front(&beyond)
            {
                *cap = false;
            }
        }
        caps
    }
}

/// `value`, or an error naming it (`what`) when it is not finite.
pub(super) fn finite(what: &'static str, value: Vec2) -> Result<Vec2, ControllerError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(ControllerError::NonFinite { what, value })
    }
}

/// The position `value`, or an error naming it (`what`) when it is not finite or is beyond
/// [`MAX_COORD`].
fn placed(what: &'static str, value: Vec2) -> Result<Vec2, ControllerError> {
    finite(what, value)?;
    if in_range(value) {
        Ok(value)
    } else {
        Err(ControllerError::OutOfRange { what, value })
    }
}

/// `v` scaled to unit length, `None` when it is zero or not finite. Scaled by its largest
/// component first, so a finite direction whose length squared overflows (or underflows)
/// still has one.
fn unit(v: Vec2) -> Option<Vec2> {
    let largest = v.abs().max_element();
    if largest > 0.0 && largest.is_finite() {
        (v / largest).try_normalize()
    } else {
        None
    }
}

/// The move along a surface with `normal` that makes `sideways` progress along `side`: the
/// surface's tangent scaled so that its sideways part is `sideways`. Zero for a surface
/// with no sideways extent (a vertical one).
fn along(normal: Vec2, side: Vec2, sideways: f32) -> Vec2 {
    let tangent = normal.perp();
    let across = tangent.dot(side);
    if across.abs() <= 1e-6 || sideways == 0.0 {
        return Vec2::ZERO;
    }
    tangent * (sideways / across)
}

/// An error naming the field when a configuration is out of range.
fn check_config(config: &ControllerConfig) -> Result<(), ControllerError> {
    let checks = [
        (
            "max_slope_degrees",
            config.max_slope_degrees,
            (0.0..90.0).contains(&config.max_slope_degrees),
        ),
        (
            "snap_distance",
            config.snap_distance,
            distance(config.snap_distance),
        ),
        ("skin", config.skin, distance(config.skin)),
        (
            "step_height",
            config.step_height,
            distance(config.step_height),
        ),
    ];
    for (field, value, ok) in checks {
        if !ok {
            return Err(ControllerError::BadConfig { field, value });
        }
    }
    if config.max_slides == 0 {
        return Err(ControllerError::BadConfig {
            field: "max_slides",
            value: 0.0,
        });
    }
    Ok(())
}

/// Whether a configured distance is in range: not negative, at most [`MAX_COORD`].
fn distance(value: f32) -> bool {
    (0.0..=MAX_COORD).contains(&value)
}

/// The end of `segment` nearest to `point`.
fn nearest_end(segment: &Segment, point: Vec2) -> Vec2 {
    if segment.a.distance_squared(point) <= segment.b.distance_squared(point) {
        segment.a
    } else {
        segment.b
    }
}

/// `segment`'s end `end` (0: `a`, 1: `b`).
fn end_point(segment: &Segment, end: usize) -> Vec2 {
    if end == 0 { segment.a } else { segment.b }
}

/// The direction out of `segment` at its end `end`: back along it at `a`, on along it at
/// `b`.
fn outward(segment: &Segment, end: usize) -> Vec2 {
    let along = segment.delta().normalize_or_zero();
    if end == 0 { -along } else { along }
}
