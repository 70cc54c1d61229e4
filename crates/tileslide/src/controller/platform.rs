//! Moving platforms: riding the temporary segments a game moves each frame, and being
//! pushed (or crushed) by them.
//!
//! A platform is an [`Owner`]'s temporary segments, submitted anew every frame at the
//! platform's new place (platforms move first, characters after). A character standing on
//! one remembers which (the owner, and the segment's midpoint and normal); on its next move
//! it finds that segment again (the owner's segment facing the same way whose midpoint is
//! nearest) and is first carried by exactly as much as its midpoint moved, swept against
//! everything but the platform itself, so it neither lags nor sinks, however fast the
//! platform goes. Platforms translate; a rotating one carries its riders by its midpoint. Then any platform that
//! moved into the character pushes it out along its normal; a push the world blocks (a
//! platform pressing the character into a ceiling) is a crush, and the character stays on
//! the world's side: it never tunnels.

use glam::Vec2;

use super::trace::{Log, MoveEvent, SweepPurpose};
use super::{Character, Contact, Contacts, MoveOptions};
use crate::geometry::Segment;
use crate::query::{Capsule, SegmentSource};
use crate::tiles::{Owner, SegmentFlags, TileMap, WallSource};

/// The moving platform a character stands on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Riding {
    pub(crate) owner: Owner,
    /// The segment stood on: its midpoint and (corrected) normal when last seen.
    pub(crate) middle: Vec2,
    pub(crate) normal: Vec2,
}

impl Riding {
    /// The platform `ground` belongs to, if it is a temporary segment of `map`.
    pub(super) fn on(map: &TileMap, ground: &Contact) -> Option<Self> {
        let SegmentSource::Temporary { owner, index, .. } = ground.source else {
            return None;
        };
        let platform = map.temporaries().get(index)?;
        let capsule = Capsule::new(platform.segment, platform.normal, [true; 2]);
        Some(Self {
            owner,
            middle: midpoint(&platform.segment),
            normal: capsule.normal,
        })
    }

    /// Where the segment stood on is now: of the owner's segments facing about the same
    /// way, the one whose midpoint is nearest to where it was (so an owner may submit its
    /// segments in any order, either way round). `None` when the owner has none.
    fn find(&self, map: &TileMap) -> Option<Vec2> {
        map.temporaries()
            .iter()
            .filter(|t| t.owner == self.owner)
            .filter(|t| {
                Capsule::new(t.segment, t.normal, [true; 2])
                    .normal
                    .dot(self.normal)
                    > 0.9
            })
            .map(|t| midpoint(&t.segment))
            .min_by(|a, b| {
                a.distance_squared(self.middle)
                    .total_cmp(&b.distance_squared(self.middle))
            })
    }
}

fn midpoint(segment: &Segment) -> Vec2 {
    (segment.a + segment.b) * 0.5
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
    pub(super) fn ride(&mut self, map: &TileMap, options: MoveOptions, log: &mut Log<'_>) {
        let Some(riding) = self.riding else {
            return;
        };
        let owner = riding.owner;
        let Some(middle) = riding.find(map) else {
            log.push(MoveEvent::PlatformGone { owner });
            self.riding = None;
            self.ground = None;
            return;
        };
        let carried = middle - riding.middle;
        if carried != Vec2::ZERO {
            log.push(MoveEvent::Carried { owner, by: carried });
            log.purpose(SweepPurpose::Carry);
            self.go(map, carried, options, Some(owner), log);
        }
    }

    /// Pushes the character out of every temporary segment that overlaps it from the front,
    /// a skin clear: along that segment's normal, or off its end when the character
    /// reaches less far past the end than into the segment (a box beside a platform's end
    /// is not lifted by it); records a crush when the world stops the push short.
    ///
    /// A one-way platform pushes only a character whose lowest point is on or above its
    /// line (as it holds only those): one rising into a character from below passes
    /// through it, as a jump passes up through one.
    pub(super) fn push_out(
        &mut self,
        map: &TileMap,
        options: MoveOptions,
        contacts: &mut Contacts,
        log: &mut Log<'_>,
    ) {
        let skin = self.config().skin;
        for (index, platform) in map.temporaries().iter().enumerate() {
            let one_way = platform.flags.contains(SegmentFlags::ONE_WAY)
                && !platform.flags.contains(SegmentFlags::SOLID);
            if !platform.flags.intersects(self.config().mask) || one_way && options.drop_through {
                continue;
            }
            let capsule = Capsule::new(platform.segment, platform.normal, [true; 2]);
            let Some((direction, depth)) = self.shape().penetration(&capsule, self.position) else {
                continue;
            };
            if one_way && (direction != capsule.normal || depth > 2.0 * skin) {
                continue;
            }
            let before = self.position;
            log.purpose(SweepPurpose::PushOut);
            self.go(
                map,
                direction * (depth + skin),
                options,
                Some(platform.owner),
                log,
            );
            // Short of the depth (not of the extra skin): the world is in the way.
            let crushed = (self.position - before).dot(direction) < depth - 0.5 * skin;
            let owner = platform.owner;
            log.push(MoveEvent::Pushed {
                source: WallSource::Temporary { owner, index },
                direction,
                depth,
                crushed,
            });
            if crushed {
                contacts.crush = Some(Contact {
                    normal: direction,
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
