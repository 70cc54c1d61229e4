//! bevy_ecs_tilemap's layers as the collision map (feature `ecs_tilemap`): their components
//! read into the grid and tiles that [`tilemap`](crate::tilemap) turns into the map.

use bevy::ecs::entity::EntityHashSet;
use bevy::prelude::*;
use bevy_ecs_tilemap::anchor::TilemapAnchor;
use bevy_ecs_tilemap::map::{
    TilemapGridSize, TilemapId, TilemapSize, TilemapTileSize, TilemapType,
};
use bevy_ecs_tilemap::tiles::{TileFlip, TileStorage, TileTextureIndex};

use crate::map::CollisionMap;
use crate::messages::TileslideError;
use crate::tilemap::{LayerGrid, LayerTile, TileFlips, TilemapCollision, apply_layer};
use crate::units::MapUnits;

/// The layer the map follows, and what it last saw.
#[derive(Default)]
pub(crate) struct Following {
    /// The layer the map is built from.
    layer: Option<Entity>,
    /// The map's generation when the layer was last applied (or failed to be).
    generation: u64,
    /// Layers refused as a second collision layer, so each is reported once.
    refused: EntityHashSet,
}

/// The parts of a layer the map is built from.
type LayerParts<'a> = (
    Entity,
    Ref<'a, TilemapCollision>,
    Ref<'a, TileStorage>,
    Ref<'a, TilemapSize>,
    Ref<'a, TilemapGridSize>,
    Ref<'a, TilemapTileSize>,
    Ref<'a, TilemapType>,
    Option<Ref<'a, TilemapAnchor>>,
);

/// Builds the [`CollisionMap`] from the layer with a [`TilemapCollision`], and edits it when
/// the layer's tiles change (a tile added, removed, retextured or flipped); builds it anew
/// when the layer's size, grid, place or collisions change. Runs before the step's
/// [`SyncIn`](crate::TileslideSet::SyncIn), so tiles edited before it count in that step.
pub(crate) fn follow_tilemap_layer(
    mut commands: Commands,
    layers: Query<LayerParts>,
    transforms: Query<(Ref<Transform>, Option<&ChildOf>)>,
    tiles: Query<(&TileTextureIndex, Option<&TileFlip>)>,
    changed_tiles: Query<
        &TilemapId,
        Or<(
            Changed<TileTextureIndex>,
            Changed<TileFlip>,
            Changed<TilemapId>,
        )>,
    >,
    mut removed: RemovedComponents<TileTextureIndex>,
    map: Option<ResMut<CollisionMap>>,
    units: Res<MapUnits>,
    mut following: Local<Following>,
    mut errors: MessageWriter<TileslideError>,
) {
    // The layer in charge: the one followed while it lasts, else the first by entity order.
    let mut candidates: Vec<Entity> = layers.iter().map(|l| l.0).collect();
    candidates.sort_unstable_by_key(|e| (e.index_u32(), e.generation().to_bits()));
    let chosen = following
        .layer
        .filter(|e| candidates.contains(e))
        .or_else(|| candidates.first().copied());
    for &other in &candidates {
        if Some(other) != chosen && following.refused.insert(other) {
            errors.write(TileslideError {
                entity: other,
                message: format!(
                    "TilemapCollision: the collision map already follows layer {}; one layer a \
                     world is the collision map",
                    chosen.map_or_else(String::new, |e| e.to_string())
                ),
            });
        }
    }
    let Some(chosen) = chosen else {
        following.layer = None;
        return;
    };
    let Ok((entity, rules, storage, size, grid_size, tile_size, kind, anchor)) = layers.get(chosen)
    else {
        return;
    };
    let (translation, scale, moved, rotated) = world_placement(entity, &transforms);
    let tiles_changed = removed.read().count() > 0 || changed_tiles.iter().any(|id| id.0 == entity);
    let generation = map.as_ref().map_or(0, |m| m.generation());
    let dirty = following.layer != Some(entity)
        || following.generation != generation
        || rules.is_changed()
        || storage.is_changed()
        || size.is_changed()
        || grid_size.is_changed()
        || tile_size.is_changed()
        || kind.is_changed()
        || anchor.as_ref().is_some_and(Ref::is_changed)
        || moved
        || tiles_changed;
    if !dirty {
        return;
    }
    following.layer = Some(entity);
    following.generation = generation;
    let fail = |message: String| TileslideError {
        entity,
        message: format!("TilemapCollision: {message}"),
    };
    if *kind != TilemapType::Square {
        errors.write(fail(format!(
            "the layer is {:?}: only square tilemaps are collision maps",
            *kind
        )));
        return;
    }
    if rotated {
        errors.write(fail(
            "the layer (or a parent) is rotated: a collision map may be moved and scaled, not \
             turned"
                .into(),
        ));
        return;
    }
    let anchor = anchor.as_deref().copied().unwrap_or_default();
    let offset = anchor.as_offset(&size, &grid_size, &tile_size, &kind);
    let layer = LayerGrid {
        width: size.x,
        height: size.y,
        cell: Vec2::new(grid_size.x, grid_size.y) * scale,
        first_centre: translation + offset * scale,
    };
    let cells: Vec<Option<LayerTile>> = storage
        .iter()
        .map(|tile| {
            let (texture, flip) = tiles.get((*tile)?).ok()?;
            let flip = flip.copied().unwrap_or_default();
            Some(LayerTile {
                texture: texture.0,
                flip: TileFlips {
                    x: flip.x,
                    y: flip.y,
                    d: flip.d,
                },
            })
        })
        .collect();
    // Without a CollisionMap yet, the layer's is built aside and inserted.
    let mut inserted = None;
    let target = match map {
        Some(m) => m.into_inner(),
        None => inserted.insert(CollisionMap::default()),
    };
    match apply_layer(target, &rules, rules.is_changed(), &layer, &cells, &units) {
        Ok(applied) => {
            for why in applied.refused {
                errors.write(fail(why));
            }
        }
        Err(why) => {
            errors.write(fail(why));
        }
    }
    following.generation = target.generation();
    if let Some(built) = inserted
        && built.map().is_some()
    {
        commands.insert_resource(built);
    }
}

/// Where the layer lies in the world: the translation and scale (x, y) of its transform
/// composed with its parents', whether any of them changed, and whether they turn it.
fn world_placement(
    entity: Entity,
    transforms: &Query<(Ref<Transform>, Option<&ChildOf>)>,
) -> (Vec2, Vec2, bool, bool) {
    let mut global = Transform::IDENTITY;
    let mut moved = false;
    let mut at = Some(entity);
    // A hierarchy is a tree, so the walk ends; the bound is for a world that lies.
    for _ in 0..1024 {
        let Some(e) = at else { break };
        let Ok((transform, parent)) = transforms.get(e) else {
            break;
        };
        moved |= transform.is_changed();
        global = transform.mul_transform(global);
        at = parent.map(ChildOf::parent);
    }
    let rotated = global.rotation.z != 0.0 || global.rotation.x != 0.0 || global.rotation.y != 0.0;
    (
        global.translation.truncate(),
        global.scale.truncate(),
        moved,
        rotated,
    )
}
