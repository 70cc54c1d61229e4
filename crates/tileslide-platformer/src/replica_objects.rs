//! What the demo makes of a Replica Island level's objects (read by
//! `tileslide::io::replica::parse_objects`): the player's start, coins, and the enemies
//! that walk or fly back and forth. Everything else the level places is counted as ignored.

use std::collections::BTreeMap;

use tileslide::Vec2;
use tileslide::io::replica::{LevelObjects, ObjectKind, SpawnPoint};

use crate::hits::ENEMY_HALF;

/// What the demo makes of an object of a Replica Island level.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ReplicaRole {
    /// The player's start (`PLAYER`).
    Start,
    /// A coin: `COIN`, `RUBY` and `DIARY` (the game's pearls, gems and diary pages) are
    /// all collected the same way.
    Coin,
    /// An enemy that walks back and forth on the ground: `BROBOT`, `SNAILBOMB`,
    /// `SHADOWSLIME`, `MUDMAN`, `SKELETON`, `ONION`.
    Walker,
    /// An enemy that flies back and forth along its row, without gravity: `BAT`, `STING`,
    /// `KARAGUIN`.
    Flyer,
}

impl ReplicaRole {
    /// The demo's role for objects of `kind`, or `None` for the kinds it ignores (story
    /// characters, bosses, turrets, doors, buttons, cannons, spawners, breakable blocks,
    /// signs, effects, the game's special objects).
    #[must_use]
    pub const fn of(kind: ObjectKind) -> Option<Self> {
        use ObjectKind as K;
        match kind {
            K::Player => Some(Self::Start),
            K::Coin | K::Ruby | K::Diary => Some(Self::Coin),
            K::Brobot | K::SnailBomb | K::ShadowSlime | K::Mudman | K::Skeleton | K::Onion => {
                Some(Self::Walker)
            }
            K::Bat | K::Sting | K::Karaguin => Some(Self::Flyer),
            _ => None,
        }
    }
}

/// Where an enemy starts, and how it moves.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EnemyStart {
    /// The middle of its bottom side at the start.
    pub feet: Vec2,
    /// It flies (no gravity, no turning at edges) instead of walking.
    pub flies: bool,
}

/// Objects of one type number that the demo leaves out of a level.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct IgnoredObjects {
    /// The type number in the level file.
    pub type_number: u8,
    /// The game's kind for it, when it defines one.
    pub kind: Option<ObjectKind>,
    /// How many the level places.
    pub count: usize,
}

/// What the demo places from a level's objects, in the level's pixels (y up).
pub(crate) struct Placed {
    /// The player's feet at the start.
    pub start: Vec2,
    pub coins: Vec<Vec2>,
    pub enemies: Vec<EnemyStart>,
    /// By increasing type number.
    pub ignored: Vec<IgnoredObjects>,
}

/// Places the player, coins and enemies of `objects` on a map of `scale`-wide cells, or
/// `None` when the level has no player spawn.
///
/// The game centres an object across its cell, stands one at least a tile tall on the
/// cell's bottom and centres a shorter one in it: the player and walkers stand a pixel
/// above the cell's bottom (resting, not touching, so that the first step settles them);
/// coins and flyers are centred in their cell.
pub(crate) fn place(objects: &LevelObjects, scale: f32) -> Option<Placed> {
    let feet = |o: &SpawnPoint| o.bottom_middle() + Vec2::Y;
    let start = feet(objects.player_spawn()?);
    let mut coins = Vec::new();
    let mut enemies = Vec::new();
    let mut ignored = BTreeMap::<u8, IgnoredObjects>::new();
    for o in &objects.objects {
        match o.kind.and_then(ReplicaRole::of) {
            Some(ReplicaRole::Start) => {}
            Some(ReplicaRole::Coin) => coins.push(o.center()),
            Some(ReplicaRole::Walker) => enemies.push(EnemyStart {
                feet: feet(o),
                flies: false,
            }),
            Some(ReplicaRole::Flyer) => enemies.push(EnemyStart {
                feet: o.center() - Vec2::Y * ENEMY_HALF.y * scale,
                flies: true,
            }),
            None => {
                ignored
                    .entry(o.type_number)
                    .or_insert(IgnoredObjects {
                        type_number: o.type_number,
                        kind: o.kind,
                        count: 0,
                    })
                    .count += 1;
            }
        }
    }
    Some(Placed {
        start,
        coins,
        enemies,
        ignored: ignored.into_values().collect(),
    })
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use tileslide::Cell;

    use super::*;

    fn level(objects: &[(u8, u32, u32)]) -> LevelObjects {
        LevelObjects {
            width: 8,
            height: 8,
            objects: objects
                .iter()
                .map(|&(n, col, row)| SpawnPoint::new(n, Cell::new(col, row)))
                .collect(),
            hot_spots: None,
            cut_short: None,
        }
    }

    #[test]
    fn each_understood_kind_is_placed_and_the_rest_counted_by_type_number() {
        // Player, coin, ruby, bat, brobot, two red doors, a hint sign, a number the game
        // does not define.
        let objects = level(&[
            (0, 1, 1),
            (1, 2, 3),
            (2, 3, 3),
            (6, 4, 5),
            (16, 5, 1),
            (32, 6, 1),
            (32, 7, 1),
            (43, 0, 0),
            (4, 0, 7),
        ]);
        let placed = place(&objects, 32.0).unwrap();
        assert_eq!(placed.start, Vec2::new(48.0, 33.0));
        assert_eq!(
            placed.coins,
            [Vec2::new(80.0, 112.0), Vec2::new(112.0, 112.0)]
        );
        let flyer_feet = 5.0 * 32.0 + 16.0 - ENEMY_HALF.y * 32.0;
        assert_eq!(
            placed.enemies,
            [
                EnemyStart {
                    feet: Vec2::new(144.0, flyer_feet),
                    flies: true
                },
                EnemyStart {
                    feet: Vec2::new(176.0, 33.0),
                    flies: false
                },
            ]
        );
        let ignored: Vec<(u8, Option<ObjectKind>, usize)> = placed
            .ignored
            .iter()
            .map(|i| (i.type_number, i.kind, i.count))
            .collect();
        assert_eq!(
            ignored,
            [
                (4, None, 1),
                (32, Some(ObjectKind::DoorRed), 2),
                (43, Some(ObjectKind::HintSign), 1)
            ]
        );
    }

    #[test]
    fn a_level_without_a_player_spawn_places_nothing() {
        assert!(place(&level(&[(1, 0, 0)]), 32.0).is_none());
    }

    #[test]
    fn every_kind_has_the_role_its_documentation_gives() {
        let roles: Vec<(&str, ReplicaRole)> = ObjectKind::ALL
            .iter()
            .filter_map(|&k| Some((k.name(), ReplicaRole::of(k)?)))
            .collect();
        assert_eq!(
            roles,
            [
                ("PLAYER", ReplicaRole::Start),
                ("COIN", ReplicaRole::Coin),
                ("RUBY", ReplicaRole::Coin),
                ("DIARY", ReplicaRole::Coin),
                ("BAT", ReplicaRole::Flyer),
                ("STING", ReplicaRole::Flyer),
                ("ONION", ReplicaRole::Walker),
                ("BROBOT", ReplicaRole::Walker),
                ("SNAILBOMB", ReplicaRole::Walker),
                ("SHADOWSLIME", ReplicaRole::Walker),
                ("MUDMAN", ReplicaRole::Walker),
                ("SKELETON", ReplicaRole::Walker),
                ("KARAGUIN", ReplicaRole::Flyer),
            ]
        );
    }
}
