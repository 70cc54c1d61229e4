//! The moving platform: a one-way temporary segment sliding along its track and back,
//! submitted to the map anew every step.

use tileslide::{MapError, Owner, Segment, SegmentFlags, TemporarySegment, Vec2};

use crate::level::{Level, PlatformTrack};

/// The moving platform's speed, in cells per second.
const PLATFORM_SPEED: f32 = 2.0;
/// The owner of the moving platform's temporary segment.
pub const PLATFORM_OWNER: Owner = Owner(1);

/// Where the level's moving platform is along its track, and which way it goes.
#[derive(Clone, Copy, Debug)]
pub(crate) struct MovingPlatform {
    /// From 0 to the track's travel, in world units.
    at: f32,
    /// 1 or −1.
    dir: f32,
}

impl MovingPlatform {
    /// At the start of its track, going forward.
    pub(crate) fn new() -> Self {
        Self { at: 0.0, dir: 1.0 }
    }

    /// Puts its segment, moving at `velocity`, in `level`'s map in place of the last one
    /// (nothing when the level has no platform).
    pub(crate) fn submit(&self, level: &mut Level, velocity: Vec2) -> Result<(), MapError> {
        let Some(PlatformTrack { start, width, .. }) = level.platform else {
            return Ok(());
        };
        let s = level.scale;
        let a = start * s + Vec2::X * self.at;
        let map = &mut level.map;
        map.clear_temporaries_of(PLATFORM_OWNER);
        map.add_temporary(TemporarySegment {
            segment: Segment::new(a, a + Vec2::X * width * s),
            normal: level.up,
            flags: SegmentFlags::ONE_WAY,
            owner: PLATFORM_OWNER,
            velocity,
        })?;
        Ok(())
    }

    /// Slides it along its track for `dt` seconds, turning at either end, and re-submits
    /// its segment.
    pub(crate) fn slide(&mut self, level: &mut Level, dt: f32) -> Result<(), MapError> {
        let Some(track) = level.platform else {
            return Ok(());
        };
        let s = level.scale;
        let travel = track.travel * s;
        let before = self.at;
        let mut at = before + self.dir * PLATFORM_SPEED * s * dt;
        if !(0.0..=travel).contains(&at) {
            self.dir = -self.dir;
            at = at.clamp(0.0, travel);
        }
        self.at = at;
        self.submit(level, Vec2::X * (at - before) / dt)
    }
}
