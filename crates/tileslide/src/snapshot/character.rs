//! A [`Character`] saved and restored with serde: what decides its next moves. Its
//! position, shape, up direction and settings, the ground it stands on (and whether that
//! ground is a rounded corner), and the moving platform it rides, so a restored character
//! walks, snaps, rides and drops through as it would have.

use glam::Vec2;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

use super::{SnapshotError, read_checked};
use crate::controller::character::side_of;
use crate::controller::platform::Riding;
use crate::controller::{Character, CharacterShape, Contact, ControllerConfig};
use crate::geometry::in_range;
use crate::owner::Owner;
use crate::query::SegmentSource;

/// How far a saved unit vector's squared length may be from 1 (a few rounding steps).
const UNIT_SLACK: f32 = 1e-5;

/// A character as it is written and read.
#[derive(Serialize, Deserialize)]
struct CharacterData {
    position: Vec2,
    shape: CharacterShape,
    /// Unit length, written as the character holds it (normalising it again could move its
    /// last bit).
    up: Vec2,
    config: ControllerConfig,
    ground: Option<Contact>,
    ground_corner: bool,
    riding: Option<RidingData>,
}

/// The platform a character rides: its owner, and its segment's midpoint and normal when
/// last seen.
#[derive(Serialize, Deserialize)]
struct RidingData {
    owner: Owner,
    middle: Vec2,
    normal: Vec2,
}

/// Written with the `serde` feature: everything that decides the character's later moves
/// (its buffers are not state, and are not written).
impl Serialize for Character {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        CharacterData {
            position: self.position,
            shape: self.shape,
            up: self.up,
            config: self.config,
            ground: self.ground,
            ground_corner: self.ground_corner,
            riding: self.riding.map(|r| RidingData {
                owner: r.owner,
                middle: r.middle,
                normal: r.normal,
            }),
        }
        .serialize(serializer)
    }
}

/// Read with the `serde` feature, and checked as [`Character::new`] checks a character,
/// its ground's and platform's vectors too (a [`SnapshotError`] message otherwise).
impl<'de> Deserialize<'de> for Character {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        read_checked::<D, CharacterData, Self>(deserializer)
    }
}

impl TryFrom<CharacterData> for Character {
    type Error = SnapshotError;

    fn try_from(data: CharacterData) -> Result<Self, SnapshotError> {
        let mut character = Character::new(data.shape, data.position, data.up, data.config)
            .map_err(SnapshotError::Character)?;
        unit("up", data.up)?;
        if let Some(ground) = &data.ground {
            unit("ground normal", ground.normal)?;
            if let SegmentSource::Temporary { velocity, .. } = ground.source {
                finite("ground velocity", velocity)?;
            }
        }
        let riding = match data.riding {
            Some(r) if data.ground.is_none() => {
                let Vec2 { x, y } = r.middle;
                return Err(SnapshotError::CharacterValue {
                    what: "platform",
                    x,
                    y,
                    must: "ridden only by a character on the ground",
                });
            }
            Some(r) => {
                finite("platform's middle", r.middle)?;
                unit("platform's normal", r.normal)?;
                Some(Riding {
                    owner: r.owner,
                    middle: r.middle,
                    normal: r.normal,
                })
            }
            None => None,
        };
        // `new` normalised `up` again: keep the saved bits, and the sideways axis of them.
        character.up = data.up;
        character.side = side_of(data.up);
        character.ground = data.ground;
        character.ground_corner = data.ground_corner;
        character.riding = riding;
        Ok(character)
    }
}

/// `Ok` when `v` is of unit length (so finite).
fn unit(what: &'static str, v: Vec2) -> Result<(), SnapshotError> {
    if (v.length_squared() - 1.0).abs() <= UNIT_SLACK {
        return Ok(());
    }
    let Vec2 { x, y } = v;
    Err(SnapshotError::CharacterValue {
        what,
        x,
        y,
        must: "of unit length",
    })
}

/// `Ok` when `v` is finite and within [`MAX_COORD`](crate::limits::MAX_COORD).
fn finite(what: &'static str, v: Vec2) -> Result<(), SnapshotError> {
    if v.is_finite() && in_range(v) {
        return Ok(());
    }
    let Vec2 { x, y } = v;
    Err(SnapshotError::CharacterValue {
        what,
        x,
        y,
        must: "finite and within MAX_COORD",
    })
}
