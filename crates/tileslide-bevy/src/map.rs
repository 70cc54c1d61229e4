//! The collision map: an asset loaded from a file, and the resource every step reads.

use std::collections::BTreeMap;

use bevy::prelude::*;
use tileslide::io::ldtk::{EntityLayer, LdtkLevel};
use tileslide::io::tiled::ObjectLayer;
use tileslide::{HitTypes, TileId, TileMap};

/// A collision map loaded from a file: `.txt` (ASCII), `.tmx` / `.tmj` (Tiled), `.ldtk`
/// (LDtk) or `.tsm` (baked), by [`TileMapLoader`](crate::TileMapLoader).
///
/// ```no_run
/// # use bevy::prelude::*;
/// # use tileslide_bevy::{CollisionMap, TileMapAsset};
/// fn load_level(mut commands: Commands, assets: Res<AssetServer>) {
///     let level: Handle<TileMapAsset> = assets.load("levels/cave.tmj");
///     commands.insert_resource(CollisionMap::from_asset(level));
/// }
/// ```
#[derive(Asset, TypePath, Clone, Debug)]
pub struct TileMapAsset {
    /// The map, y down, in the file's units (cells for ASCII maps, pixels for Tiled).
    pub map: TileMap,
    /// The hit types each tile deals (a Tiled tile's `hit_types` property: spikes that
    /// kill). Tiles not listed deal none.
    pub tile_hits: BTreeMap<TileId, HitTypes>,
    /// A Tiled map's object layers (spawn points, regions), in map coordinates; empty for
    /// other formats.
    pub object_layers: Vec<ObjectLayer>,
    /// An LDtk level's entity layers (type, position, size, fields), in map coordinates
    /// (world pixels); empty for other formats.
    pub entity_layers: Vec<EntityLayer>,
    /// The LDtk level loaded (its identifier, world position, size and fields); `None` for
    /// other formats.
    pub level: Option<LdtkLevel>,
}

impl TileMapAsset {
    /// An asset of `map`, with no tile hit types and no objects.
    #[must_use]
    pub fn new(map: TileMap) -> Self {
        Self {
            map,
            tile_hits: BTreeMap::new(),
            object_layers: Vec::new(),
            entity_layers: Vec::new(),
            level: None,
        }
    }
}

/// The map the plugin collides against: built from code, or kept in step with a
/// [`TileMapAsset`] (its first load, and every reload when the file changes).
///
/// The steps run only while it holds a map. A game edits the map in place
/// ([`map_mut`](Self::map_mut): digging, building); bodies, characters and navigation catch
/// up from the map's own change journal. A reload replaces the map, edits included.
///
/// ```
/// # use bevy::prelude::*;
/// # use tileslide_bevy::CollisionMap;
/// let map = tileslide::io::ascii::parse("####\n#..#\n####", "room.txt", 1.0)?;
/// let mut app = App::new();
/// app.insert_resource(CollisionMap::new(map));
/// assert!(app.world().resource::<CollisionMap>().map().is_some());
/// # Ok::<(), tileslide::io::LoadError>(())
/// ```
#[derive(Resource, Debug, Default)]
pub struct CollisionMap {
    map: Option<TileMap>,
    source: Option<Handle<TileMapAsset>>,
    tile_hits: BTreeMap<TileId, HitTypes>,
    /// How many times the map was put in place (built, loaded, reloaded).
    generation: u64,
}

impl CollisionMap {
    /// The map `map`, built in code.
    #[must_use]
    pub fn new(map: TileMap) -> Self {
        Self {
            map: Some(map),
            generation: 1,
            ..Self::default()
        }
    }

    /// The map of the asset `handle`, once it has loaded (and again each time it reloads).
    #[must_use]
    pub fn from_asset(handle: Handle<TileMapAsset>) -> Self {
        Self {
            source: Some(handle),
            ..Self::default()
        }
    }

    /// The same map, with the hit types `hits` for the tile `tile` (replacing the asset's).
    #[must_use]
    pub fn with_tile_hits(mut self, tile: TileId, hits: HitTypes) -> Self {
        self.set_tile_hits(tile, hits);
        self
    }

    /// The map, once there is one.
    #[must_use]
    pub fn map(&self) -> Option<&TileMap> {
        self.map.as_ref()
    }

    /// The map, to edit (set and clear tiles).
    pub fn map_mut(&mut self) -> Option<&mut TileMap> {
        self.map.as_mut()
    }

    /// The asset the map comes from, if it comes from one.
    #[must_use]
    pub fn source(&self) -> Option<&Handle<TileMapAsset>> {
        self.source.as_ref()
    }

    /// How many times a map was put in place: 0 while its asset loads, then 1, and one more
    /// with each reload.
    #[must_use]
    pub fn generation(&self) -> u64 {
        self.generation
    }

    /// The hit types tile `tile` deals to what touches it (none by default).
    #[must_use]
    pub fn tile_hits(&self, tile: TileId) -> HitTypes {
        self.tile_hits.get(&tile).copied().unwrap_or(HitTypes::NONE)
    }

    /// Sets the hit types tile `tile` deals ([`HitTypes::NONE`] to deal none).
    pub fn set_tile_hits(&mut self, tile: TileId, hits: HitTypes) {
        if hits.is_empty() {
            self.tile_hits.remove(&tile);
        } else {
            self.tile_hits.insert(tile, hits);
        }
    }

    /// Puts `map`, built from a tile-map layer, in place of any map (an asset's included),
    /// keeping the tile hit types.
    pub(crate) fn put_layer_map(&mut self, map: TileMap) {
        self.map = Some(map);
        self.source = None;
        self.generation += 1;
    }

    /// Puts `asset`'s map and tile hit types in place.
    fn replace_with(&mut self, asset: &TileMapAsset) {
        self.map = Some(asset.map.clone());
        self.tile_hits = asset.tile_hits.clone();
        self.generation += 1;
    }
}

/// Puts the map of the [`CollisionMap`]'s asset in place when it loads or changes.
pub(crate) fn follow_map_asset(
    mut events: MessageReader<AssetEvent<TileMapAsset>>,
    assets: Res<Assets<TileMapAsset>>,
    map: Option<ResMut<CollisionMap>>,
) {
    let Some(mut map) = map else {
        events.clear();
        return;
    };
    let Some(id) = map.source.as_ref().map(Handle::id) else {
        events.clear();
        return;
    };
    // A map inserted after its asset loaded missed the event: take the asset as it is.
    let mut changed = map.map.is_none() && assets.contains(id);
    for event in events.read() {
        changed |= matches!(
            event,
            AssetEvent::LoadedWithDependencies { id: e } | AssetEvent::Modified { id: e }
                if *e == id
        );
    }
    if changed && let Some(asset) = assets.get(id) {
        map.replace_with(asset);
    }
}

/// True while the [`CollisionMap`] holds a map: the steps' run condition.
pub(crate) fn has_map(map: Option<Res<CollisionMap>>) -> bool {
    map.is_some_and(|m| m.map.is_some())
}
