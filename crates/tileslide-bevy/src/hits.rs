//! Hit volumes: attack and vulnerability volumes on entities, tested each step by the core's
//! `HitWorld`, and tiles that hit what touches them.

use bevy::prelude::*;
use tileslide::{HitObject, HitTypes, HitWorld, TeamRule, Volume};

use crate::bodies::{entity_of, owner_of, spawn_order};
use crate::character::CharacterContacts;
use crate::map::CollisionMap;
use crate::messages::{Hit, TileslideError};
use crate::units::MapUnits;

/// The shape of a hit volume, relative to the entity's translation (world units, y up).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum HitShape {
    /// A circle.
    Circle {
        /// Its centre's offset from the entity.
        center: Vec2,
        /// Its radius.
        radius: f32,
    },
    /// An upright rectangle.
    Rect {
        /// Its centre's offset from the entity.
        center: Vec2,
        /// Its half width and half height.
        half: Vec2,
    },
}

/// One attack or vulnerability volume: a shape and the hit types it deals or accepts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HitVolume {
    /// Where it is.
    pub shape: HitShape,
    /// What it deals (attack) or accepts (vulnerability).
    pub hits: HitTypes,
}

impl HitVolume {
    /// A circle of `radius` at `center` (relative to the entity).
    #[must_use]
    pub fn circle(center: Vec2, radius: f32, hits: HitTypes) -> Self {
        Self {
            shape: HitShape::Circle { center, radius },
            hits,
        }
    }

    /// A rectangle of half extents `half` at `center` (relative to the entity).
    #[must_use]
    pub fn rect(center: Vec2, half: Vec2, hits: HitTypes) -> Self {
        Self {
            shape: HitShape::Rect { center, half },
            hits,
        }
    }

    /// The core's volume, in map units, mirrored left to right when `flip_x`.
    fn to_core(self, units: &MapUnits, flip_x: bool) -> Result<Volume, tileslide::VolumeError> {
        let mirror = |c: Vec2| if flip_x { Vec2::new(-c.x, c.y) } else { c };
        match self.shape {
            HitShape::Circle { center, radius } => Volume::circle(
                units.to_map(mirror(center)),
                units.length_to_map(radius),
                self.hits,
            ),
            HitShape::Rect { center, half } => Volume::rect(
                units.to_map(mirror(center)),
                units.to_map(half).abs(),
                self.hits,
            ),
        }
    }
}

/// An entity's attack and vulnerability volumes, its team and its state. Each step, after
/// everything has moved, the plugin tests every entity's attack volumes against the
/// others' vulnerability volumes along the step's move (so a fast projectile cannot pass
/// through), and sends a [`Hit`] for each; a victim takes hits from other teams while it is
/// not invulnerable. A character whose vulnerability accepts the hit types of a tile it
/// touches (see [`CollisionMap::tile_hits`]) is hit by that tile.
///
/// ```
/// # use bevy::prelude::*;
/// # use tileslide::HitTypes;
/// # use tileslide_bevy::{HitVolume, HitVolumes};
/// let hero = HitVolumes {
///     attack: vec![HitVolume::circle(Vec2::new(0.8, 0.0), 0.3, HitTypes::HIT)],
///     vulnerable: vec![HitVolume::rect(Vec2::ZERO, Vec2::new(0.3, 0.45), HitTypes::ANY)],
///     team: 1,
///     ..Default::default()
/// };
/// # let _ = hero;
/// ```
#[derive(Component, Clone, Debug, Default, PartialEq)]
#[require(Transform, HitLink)]
pub struct HitVolumes {
    /// Attack volumes; the first that meets a vulnerability volume accepting one of its
    /// types gives the hit.
    pub attack: Vec<HitVolume>,
    /// Vulnerability volumes.
    pub vulnerable: Vec<HitVolume>,
    /// Its team: hits within a team are refused.
    pub team: u32,
    /// Refuses every hit (a hero blinking after one).
    pub invulnerable: bool,
    /// The attack being made, if it should hit each victim once until it ends (the first
    /// step no entity registers it).
    pub swing: Option<u64>,
    /// Mirrors the volumes left to right (facing left).
    pub flip_x: bool,
}

impl HitVolumes {
    /// Every type its vulnerability volumes accept.
    #[must_use]
    pub fn accepts(&self) -> HitTypes {
        self.vulnerable
            .iter()
            .fold(HitTypes::NONE, |all, v| all | v.hits)
    }
}

/// Where an entity's volumes were registered last (map units): the start of their move.
#[derive(Component, Clone, Copy, Debug, Default, PartialEq)]
pub struct HitLink {
    last: Option<tileslide::Vec2>,
}

/// The core's hit world and its scratch buffers.
#[derive(Resource, Debug, Default)]
pub struct TileslideHits {
    world: HitWorld,
    attack: Vec<Volume>,
    vulnerable: Vec<Volume>,
    /// The entities registered this step, in spawn order.
    order: Vec<Entity>,
}

impl TileslideHits {
    /// The core's hit world (its last step's objects and events, map units).
    #[must_use]
    pub fn world(&self) -> &HitWorld {
        &self.world
    }
}

/// Registers every entity's volumes, finds the step's hits, then the tiles' hits on
/// characters, and sends them.
pub(crate) fn detect_hits(
    units: Res<MapUnits>,
    map: Res<CollisionMap>,
    mut hits: ResMut<TileslideHits>,
    mut objects: Query<(
        Entity,
        &HitVolumes,
        &Transform,
        &mut HitLink,
        Option<&CharacterContacts>,
    )>,
    mut out: MessageWriter<Hit>,
    mut errors: MessageWriter<TileslideError>,
    mut commands: Commands,
) {
    let hits = &mut *hits;
    hits.world.begin_frame();
    hits.order.clear();
    hits.order.extend(objects.iter().map(|(e, ..)| e));
    hits.order.sort_unstable_by_key(|&e| spawn_order(e));
    for &entity in &hits.order {
        let Ok((_, volumes, transform, mut link, _)) = objects.get_mut(entity) else {
            continue;
        };
        let at = units.to_map(transform.translation.truncate());
        let object = HitObject {
            motion: link.last.map_or(tileslide::Vec2::ZERO, |last| at - last),
            team: volumes.team,
            invulnerable: volumes.invulnerable,
            swing: volumes.swing,
            ..HitObject::new(owner_of(entity), at, tileslide::Vec2::ZERO)
        };
        link.last = Some(at);
        let converted = |list: &[HitVolume], out: &mut Vec<Volume>| {
            out.clear();
            for v in list {
                out.push(v.to_core(&units, volumes.flip_x)?);
            }
            Ok::<(), tileslide::VolumeError>(())
        };
        let registered = converted(&volumes.attack, &mut hits.attack)
            .and_then(|()| converted(&volumes.vulnerable, &mut hits.vulnerable))
            .and_then(|()| hits.world.register(object, &hits.attack, &hits.vulnerable));
        if let Err(e) = registered {
            errors.write(TileslideError {
                entity,
                message: e.to_string(),
            });
        }
    }
    for event in hits.world.detect(&mut TeamRule) {
        let (Some(victim), Some(attacker)) = (
            entity_of(event.victim_owner),
            entity_of(event.attacker_owner),
        ) else {
            continue;
        };
        let hit = Hit {
            victim,
            attacker: Some(attacker),
            tile: None,
            hit_type: event.hit_type,
            accepted: event.accepted,
            t: event.t,
            point: units.to_world(event.point),
        };
        out.write(hit);
        commands.trigger(hit);
    }
    // Tiles hit the characters touching them whose vulnerability accepts their types.
    for &entity in &hits.order {
        let Ok((_, volumes, _, _, Some(contacts))) = objects.get(entity) else {
            continue;
        };
        let accepts = volumes.accepts();
        for (_, touch) in contacts.touched() {
            let Some(tile) = touch.tile else {
                continue;
            };
            let dealt = map.tile_hits(tile.tile) & accepts;
            if dealt.is_empty() {
                continue;
            }
            let hit = Hit {
                victim: entity,
                attacker: None,
                tile: Some(tile),
                hit_type: dealt,
                accepted: !volumes.invulnerable,
                t: 0.0,
                point: touch.point,
            };
            out.write(hit);
            commands.trigger(hit);
        }
    }
}
