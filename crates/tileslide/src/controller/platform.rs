//! Moving platforms: riding the temporary segments a game moves each frame, and being
//! pushed (or crushed) by them.
//!
//! A platform is an [`Owner`]'s temporary segments, submitted anew every frame at the
//! platform's new place (platforms move first, characters after). A character standing on
//! one remembers which (the owner, and the segment's rank among that owner's segments) and
//! where that segment's first end point was; on its next move it is first carried by
//! exactly as much as that point moved, swept against everything but the platform itself,
//! so it neither lags nor sinks, however fast the platform goes. Then any platform that
//! moved into the character pushes it out along its normal; a push the world blocks (a
//! platform pressing the character into a ceiling) is a crush, and the character stays on
//! the world's side: it never tunnels.

use glam::Vec2;

use super::{Character, Contact, Contacts, MoveOptions};
use crate::query::SegmentSource;
use crate::tiles::{Owner, SegmentFlags, TileMap};

/// The moving platform a character stands on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Riding {
    owner: Owner,
    /// The segment's rank among its owner's temporary segments.
    rank: usize,
    /// Where the segment's first end point was.
    anchor: Vec2,
}

impl Riding {
    /// The platform `ground` belongs to, if it is a temporary segment of `map`.
    pub(super) fn on(map: &TileMap, ground: &Contact) -> Option<Self> {
        let SegmentSource::Temporary { owner, index, .. } = ground.source else {
            return None;
        };
        let temporaries = map.temporaries();
        let segment = temporaries.get(index)?;
        Some(Self {
            owner,
            rank: temporaries[..index]
                .iter()
                .filter(|t| t.owner == owner)
                .count(),
            anchor: segment.segment.a,
        })
    }
}

impl Contact {
    /// The velocity of the surface touched: a temporary segment's (a moving platform's),
    /// zero for a tile. A game that wants a character to keep a platform's speed when it
    /// jumps off adds this to the character's velocity.
    #[must_use]
    pub fn platform_velocity(&self) -> Vec2 {
        match self.source {
            SegmentSource::Temporary { velocity, .. } => velocity,
            SegmentSource::Tile { .. } => Vec2::ZERO,
        }
    }
}

impl Character {
    /// Carries the character by the move of the platform it stood on (see the module's
    /// documentation). Off the platform when its owner has no such segment any more.
    pub(super) fn ride(&mut self, map: &TileMap, options: MoveOptions) {
        let Some(riding) = self.riding else {
            return;
        };
        let platform = map
            .temporaries()
            .iter()
            .filter(|t| t.owner == riding.owner)
            .nth(riding.rank);
        let Some(platform) = platform else {
            self.riding = None;
            self.ground = None;
            return;
        };
        let carried = platform.segment.a - riding.anchor;
        if carried != Vec2::ZERO {
            self.go(map, carried, options, Some(riding.owner));
        }
    }

    /// Pushes the character out of every temporary segment that overlaps it from the front,
    /// along that segment's normal, a skin clear; records a crush when the world stops the
    /// push.
    pub(super) fn push_out(
        &mut self,
        map: &TileMap,
        options: MoveOptions,
        contacts: &mut Contacts,
    ) {
        for (index, platform) in map.temporaries().iter().enumerate() {
            let one_way = platform.flags.contains(SegmentFlags::ONE_WAY)
                && !platform.flags.contains(SegmentFlags::SOLID);
            if !platform.flags.intersects(self.config().mask) || one_way && options.drop_through {
                continue;
            }
            let Some(depth) =
                self.shape()
                    .penetration(&platform.segment, platform.normal, self.position)
            else {
                continue;
            };
            let push = platform.normal * (depth + self.config().skin);
            if self.go(map, push, options, Some(platform.owner)).is_some() {
                contacts.crush = Some(Contact {
                    normal: platform.normal,
                    flags: platform.flags,
                    source: SegmentSource::Temporary {
                        owner: platform.owner,
                        index,
                        velocity: platform.velocity,
                    },
                });
            }
        }
    }
}
