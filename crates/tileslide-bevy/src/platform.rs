//! Moving platforms and doors: entities whose segments the map holds as temporary segments,
//! submitted anew at the entity's place every step.

use bevy::prelude::*;
use tileslide::{Segment, SegmentFlags, TemporarySegment};

use crate::bodies::owner_of;
use crate::map::CollisionMap;
use crate::messages::TileslideError;
use crate::units::MapUnits;

/// One segment of a [`Platform`], relative to the entity's translation (world units).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlatformSegment {
    /// One end.
    pub a: Vec2,
    /// The other end.
    pub b: Vec2,
    /// The side it blocks from (world axes, any length but zero).
    pub normal: Vec2,
    /// What it is: `SOLID`, or `ONE_WAY` for a platform jumped up through.
    pub flags: SegmentFlags,
}

/// Segments that move with an entity: a moving platform, a lift, a door. Before each step
/// the plugin submits them to the map at the entity's translation, with the velocity it
/// moved at since the last step, so characters standing on them are carried and characters
/// they push into are pushed (or crushed), and bodies collide with them. Move the entity's
/// `Transform` in the fixed schedule, before [`TileslideSet::SyncIn`](crate::TileslideSet::SyncIn).
///
/// ```
/// # use bevy::prelude::*;
/// # use tileslide_bevy::Platform;
/// fn spawn(mut commands: Commands) {
///     // A one-way platform two units wide, its left end at the entity.
///     commands.spawn((
///         Platform::one_way(Vec2::ZERO, Vec2::new(2.0, 0.0)),
///         Transform::from_xyz(15.0, -7.0, 0.0),
///     ));
/// }
/// # let _ = spawn;
/// ```
#[derive(Component, Clone, Debug, PartialEq)]
#[require(Transform, PlatformLink)]
pub struct Platform {
    /// Its segments.
    pub segments: Vec<PlatformSegment>,
}

impl Platform {
    /// A one-way platform from `a` to `b` (relative to the entity) that holds from above
    /// (+y).
    #[must_use]
    pub fn one_way(a: Vec2, b: Vec2) -> Self {
        Self {
            segments: vec![PlatformSegment {
                a,
                b,
                normal: Vec2::Y,
                flags: SegmentFlags::ONE_WAY,
            }],
        }
    }

    /// A solid box of half extents `half` centred on the entity: four segments facing out.
    #[must_use]
    pub fn solid_box(half: Vec2) -> Self {
        let (x, y) = (half.x, half.y);
        let side = |a: Vec2, b: Vec2, normal: Vec2| PlatformSegment {
            a,
            b,
            normal,
            flags: SegmentFlags::SOLID,
        };
        Self {
            segments: vec![
                side(Vec2::new(-x, y), Vec2::new(x, y), Vec2::Y),
                side(Vec2::new(x, y), Vec2::new(x, -y), Vec2::X),
                side(Vec2::new(x, -y), Vec2::new(-x, -y), Vec2::NEG_Y),
                side(Vec2::new(-x, -y), Vec2::new(-x, y), Vec2::NEG_X),
            ],
        }
    }
}

/// Where a platform was submitted last (map units), for its velocity.
#[derive(Component, Clone, Copy, Debug, Default, PartialEq)]
pub struct PlatformLink {
    last: Option<tileslide::Vec2>,
}

/// Submits every platform's segments at its place, and clears those of removed platforms.
pub(crate) fn submit_platforms(
    units: Res<MapUnits>,
    time: Res<Time>,
    mut map: ResMut<CollisionMap>,
    mut removed: RemovedComponents<Platform>,
    mut platforms: Query<(Entity, &Platform, &Transform, &mut PlatformLink)>,
    mut errors: MessageWriter<TileslideError>,
) {
    let Some(map) = map.map_mut() else {
        return;
    };
    for entity in removed.read() {
        map.clear_temporaries_of(owner_of(entity));
    }
    let dt = time.delta_secs();
    for (entity, platform, transform, mut link) in &mut platforms {
        let owner = owner_of(entity);
        map.clear_temporaries_of(owner);
        let at = units.to_map(transform.translation.truncate());
        let velocity = match link.last {
            Some(last) if dt > 0.0 => (at - last) / dt,
            _ => tileslide::Vec2::ZERO,
        };
        link.last = Some(at);
        for s in &platform.segments {
            let segment = TemporarySegment {
                segment: Segment::new(at + units.to_map(s.a), at + units.to_map(s.b)),
                normal: units.direction_to_map(s.normal),
                flags: s.flags,
                owner,
                velocity,
            };
            if let Err(e) = map.add_temporary(segment) {
                errors.write(TileslideError {
                    entity,
                    message: e.to_string(),
                });
            }
        }
    }
}
