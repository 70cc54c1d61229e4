//! What a body is: its shape (one circle or several at fixed offsets), its collision filter,
//! the caller's data, and its state in a [`Bodies`](crate::Bodies) set.

use glam::Vec2;

use super::error::BodyError;
use crate::geometry::{Circle, MAX_COORD, in_range};
use crate::owner::Owner;
use crate::tiles::SegmentFlags;

/// The most circles a compound [`BodyShape`] may have.
pub const MAX_COMPOUND_CIRCLES: usize = 1024;

/// A body's shape: circles at fixed offsets from the body's position (a compound body, for
/// an object a single circle fits badly). Bodies do not rotate.
///
/// ```
/// # use tileslide::{BodyShape, Circle, Vec2};
/// let knight = BodyShape::circle(0.3)?;
/// assert_eq!(knight.bounding_radius(), 0.3);
/// // A cart: two wheels.
/// let cart = BodyShape::compound([
///     Circle::new(Vec2::new(-0.4, 0.0), 0.25),
///     Circle::new(Vec2::new(0.4, 0.0), 0.25),
/// ])?;
/// assert_eq!(cart.circles().len(), 2);
/// assert!((cart.bounding_radius() - 0.65).abs() < 1e-6);
/// assert!(BodyShape::circle(0.0).is_err());
/// # Ok::<(), tileslide::BodyError>(())
/// ```
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Debug, PartialEq)]
// Read through `compound`, so a saved shape is checked as a built one is.
#[cfg_attr(
    feature = "serde",
    serde(try_from = "Vec<Circle>", into = "Vec<Circle>")
)]
pub struct BodyShape {
    circles: Vec<Circle>,
}

impl TryFrom<Vec<Circle>> for BodyShape {
    type Error = BodyError;

    /// [`BodyShape::compound`] of the circles.
    fn try_from(circles: Vec<Circle>) -> Result<Self, BodyError> {
        Self::compound(circles)
    }
}

impl From<BodyShape> for Vec<Circle> {
    /// The shape's circles, offsets from the body's position.
    fn from(shape: BodyShape) -> Self {
        shape.circles
    }
}

impl BodyShape {
    /// One circle of `radius`, centred on the body's position.
    ///
    /// # Errors
    /// [`BodyError::InvalidRadius`] unless the radius is positive and at most
    /// [`MAX_COORD`].
    pub fn circle(radius: f32) -> Result<Self, BodyError> {
        Self::compound([Circle::new(Vec2::ZERO, radius)])
    }

    /// Circles whose centres are offsets from the body's position.
    ///
    /// # Errors
    /// [`BodyError::EmptyShape`] without circles, [`BodyError::TooManyCircles`] past
    /// [`MAX_COMPOUND_CIRCLES`] (found before the rest is collected),
    /// [`BodyError::InvalidRadius`] for a radius that is not positive and at most
    /// [`MAX_COORD`], [`BodyError::InvalidOffset`] for an offset with a coordinate beyond it
    /// or not finite (each naming the circle's index).
    pub fn compound(circles: impl IntoIterator<Item = Circle>) -> Result<Self, BodyError> {
        let circles: Vec<Circle> = circles.into_iter().take(MAX_COMPOUND_CIRCLES + 1).collect();
        if circles.len() > MAX_COMPOUND_CIRCLES {
            return Err(BodyError::TooManyCircles {
                max: MAX_COMPOUND_CIRCLES,
            });
        }
        if circles.is_empty() {
            return Err(BodyError::EmptyShape);
        }
        for (index, c) in circles.iter().enumerate() {
            // Written so that NaN fails.
            if !(c.radius > 0.0 && c.radius <= MAX_COORD) {
                return Err(BodyError::InvalidRadius {
                    index,
                    radius: c.radius,
                });
            }
            if !in_range(c.center) {
                return Err(BodyError::InvalidOffset {
                    index,
                    offset: c.center,
                });
            }
        }
        Ok(Self { circles })
    }

    /// The circles, centres relative to the body's position.
    #[must_use]
    pub fn circles(&self) -> &[Circle] {
        &self.circles
    }

    /// The radius of the smallest circle around the body's position that holds the shape.
    #[must_use]
    pub fn bounding_radius(&self) -> f32 {
        self.circles
            .iter()
            .map(|c| c.center.length() + c.radius)
            .fold(0.0, f32::max)
    }
}

/// Which bodies a body collides with, and which wall segments stop it.
///
/// Two bodies collide when each one's `groups` meets the other's `collides_with`.
///
/// ```
/// # use tileslide::{BodyFilter, SegmentFlags};
/// const HEROES: u32 = 1 << 0;
/// const GHOSTS: u32 = 1 << 1;
/// let hero = BodyFilter { groups: HEROES, ..BodyFilter::default() };
/// // Ghosts pass through heroes and walls, but not through each other.
/// let ghost = BodyFilter { groups: GHOSTS, collides_with: GHOSTS, walls: SegmentFlags::NONE };
/// assert!(!hero.collides(&ghost));
/// assert!(ghost.collides(&ghost));
/// assert!(hero.collides(&hero));
/// ```
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BodyFilter {
    /// The groups the body belongs to (bits).
    pub groups: u32,
    /// The groups it collides with.
    pub collides_with: u32,
    /// A wall segment stops the body when it has one of these flags.
    pub walls: SegmentFlags,
}

impl Default for BodyFilter {
    /// Group 1, collides with every group and every wall segment.
    fn default() -> Self {
        Self {
            groups: 1,
            collides_with: u32::MAX,
            walls: SegmentFlags::ALL,
        }
    }
}

impl BodyFilter {
    /// True when bodies with these two filters collide.
    #[must_use]
    pub fn collides(&self, other: &BodyFilter) -> bool {
        self.groups & other.collides_with != 0 && other.groups & self.collides_with != 0
    }
}

/// Everything needed to add a body.
///
/// ```
/// # use tileslide::{BodyDesc, BodyFilter, BodyShape, Owner, Vec2};
/// let desc = BodyDesc::new(Vec2::new(3.5, 2.5), BodyShape::circle(0.3)?).with_owner(Owner(42));
/// assert_eq!(desc.owner, Owner(42));
/// assert_eq!(desc.filter, BodyFilter::default());
/// # Ok::<(), tileslide::BodyError>(())
/// ```
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Debug, PartialEq)]
pub struct BodyDesc {
    /// Where the body is.
    pub position: Vec2,
    /// Its shape.
    pub shape: BodyShape,
    /// What it collides with.
    pub filter: BodyFilter,
    /// The caller's entity; tileslide never reads it.
    pub owner: Owner,
}

impl BodyDesc {
    /// A body at `position` with `shape`, the default filter and owner 0.
    #[must_use]
    pub fn new(position: Vec2, shape: BodyShape) -> Self {
        Self {
            position,
            shape,
            filter: BodyFilter::default(),
            owner: Owner(0),
        }
    }

    /// The same, with `filter`.
    #[must_use]
    pub fn with_filter(self, filter: BodyFilter) -> Self {
        Self { filter, ..self }
    }

    /// The same, with `owner`.
    #[must_use]
    pub fn with_owner(self, owner: Owner) -> Self {
        Self { owner, ..self }
    }
}

/// A body's state.
#[derive(Clone, Debug, PartialEq)]
pub struct Body {
    pub(crate) position: Vec2,
    pub(crate) shape: BodyShape,
    pub(crate) filter: BodyFilter,
    pub(crate) owner: Owner,
    /// The move the caller proposed for this step.
    pub(crate) proposed: Vec2,
    /// The move `resolve` settled on (the proposed one until then).
    pub(crate) resolved: Vec2,
}

impl Body {
    /// The body `desc` describes, without a move.
    pub(super) fn new(desc: BodyDesc) -> Self {
        Self {
            position: desc.position,
            shape: desc.shape,
            filter: desc.filter,
            owner: desc.owner,
            proposed: Vec2::ZERO,
            resolved: Vec2::ZERO,
        }
    }

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

    /// The caller's entity.
    #[must_use]
    pub fn owner(&self) -> Owner {
        self.owner
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
