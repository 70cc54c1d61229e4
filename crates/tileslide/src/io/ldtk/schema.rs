//! The serde model of LDtk's JSON (`.ldtk` projects, `.ldtkl` level files): the fields
//! tileslide reads, as the official schema names them (stable since LDtk 1.5). Every field
//! the editor alone uses is left out and ignored; fields that older or hand-made files may
//! lack have defaults, so a file is refused only for what tileslide needs.
//!
//! Numbers that size or place things are read as `i64`, whatever the file holds, and checked
//! before use (`build.rs`), so an absurd value is an error naming it, never an overflow.

use serde::Deserialize;

/// The root of a project file.
#[derive(Clone, Debug, Deserialize)]
#[serde(rename_all = "camelCase")]
pub(super) struct ProjectJson {
    #[serde(default)]
    pub json_version: String,
    /// `Free`, `GridVania`, `LinearHorizontal`, `LinearVertical`; `null` in multi-world
    /// projects, whose worlds each have one.
    pub world_layout: Option<String>,
    pub default_grid_size: Option<i64>,
    #[serde(default)]
    pub flags: Vec<String>,
    #[serde(default)]
    pub defs: DefsJson,
    #[serde(default)]
    pub levels: Vec<LevelJson>,
    #[serde(default)]
    pub worlds: Vec<WorldJson>,
}

/// A world of a multi-world project.
#[derive(Clone, Debug, Deserialize)]
#[serde(rename_all = "camelCase")]
pub(super) struct WorldJson {
    #[serde(default)]
    pub identifier: String,
    pub world_layout: Option<String>,
    #[serde(default)]
    pub levels: Vec<LevelJson>,
}

/// The definitions: layers and tile sets (entities and enums are not needed: instances
/// repeat what tileslide reads of them).
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(rename_all = "camelCase")]
pub(super) struct DefsJson {
    #[serde(default)]
    pub layers: Vec<LayerDefJson>,
    #[serde(default)]
    pub tilesets: Vec<TilesetDefJson>,
}

/// A layer definition: the identifiers of its IntGrid values.
#[derive(Clone, Debug, Deserialize)]
#[serde(rename_all = "camelCase")]
pub(super) struct LayerDefJson {
    pub uid: i64,
    #[serde(default)]
    pub int_grid_values: Vec<IntGridValueJson>,
}

/// One IntGrid value of a layer definition.
#[derive(Clone, Debug, Deserialize)]
pub(super) struct IntGridValueJson {
    pub value: i64,
    pub identifier: Option<String>,
}

/// A tile set definition: its tiles' size and what its tiles are tagged with.
#[derive(Clone, Debug, Deserialize)]
#[serde(rename_all = "camelCase")]
pub(super) struct TilesetDefJson {
    pub uid: i64,
    #[serde(default)]
    pub identifier: String,
    pub tile_grid_size: i64,
    #[serde(default)]
    pub enum_tags: Vec<EnumTagJson>,
    #[serde(default)]
    pub custom_data: Vec<CustomDataJson>,
}

/// The tiles tagged with one value of the tile set's tag enum.
#[derive(Clone, Debug, Deserialize)]
#[serde(rename_all = "camelCase")]
pub(super) struct EnumTagJson {
    pub enum_value_id: String,
    #[serde(default)]
    pub tile_ids: Vec<i64>,
}

/// The custom data of one tile.
#[derive(Clone, Debug, Deserialize)]
#[serde(rename_all = "camelCase")]
pub(super) struct CustomDataJson {
    pub tile_id: i64,
    #[serde(default)]
    pub data: String,
}

/// A level, in the project (with or without its layers) or as a whole `.ldtkl` file.
#[derive(Clone, Debug, Deserialize)]
#[serde(rename_all = "camelCase")]
pub(super) struct LevelJson {
    pub identifier: String,
    #[serde(default)]
    pub iid: String,
    #[serde(default)]
    pub world_x: i64,
    #[serde(default)]
    pub world_y: i64,
    #[serde(default)]
    pub world_depth: i64,
    pub px_wid: i64,
    pub px_hei: i64,
    pub external_rel_path: Option<String>,
    #[serde(default)]
    pub field_instances: Vec<FieldInstanceJson>,
    /// `null` when the level is saved in its own file.
    pub layer_instances: Option<Vec<LayerInstanceJson>>,
}

/// A layer of a level.
#[derive(Clone, Debug, Deserialize)]
#[serde(rename_all = "camelCase")]
pub(super) struct LayerInstanceJson {
    #[serde(rename = "__identifier")]
    pub identifier: String,
    /// `IntGrid`, `Entities`, `Tiles` or `AutoLayer`.
    #[serde(rename = "__type")]
    pub kind: String,
    #[serde(rename = "__cWid")]
    pub columns: i64,
    #[serde(rename = "__cHei")]
    pub rows: i64,
    #[serde(rename = "__gridSize")]
    pub grid_size: i64,
    #[serde(default, rename = "__pxTotalOffsetX")]
    pub offset_x: i64,
    #[serde(default, rename = "__pxTotalOffsetY")]
    pub offset_y: i64,
    #[serde(default, rename = "__tilesetDefUid")]
    pub tileset_def_uid: Option<i64>,
    #[serde(default)]
    pub iid: String,
    #[serde(default)]
    pub layer_def_uid: i64,
    #[serde(default)]
    pub int_grid_csv: Vec<i64>,
    #[serde(default)]
    pub auto_layer_tiles: Vec<TileJson>,
    #[serde(default)]
    pub grid_tiles: Vec<TileJson>,
    #[serde(default)]
    pub entity_instances: Vec<EntityInstanceJson>,
}

/// A tile placed in a tile or auto-layer.
#[derive(Clone, Debug, Deserialize)]
pub(super) struct TileJson {
    /// Its pixel position in the layer.
    pub px: [i64; 2],
    /// Its id in the tile set.
    pub t: i64,
    /// Flip bits: 1 mirrors x, 2 mirrors y.
    #[serde(default)]
    pub f: i64,
}

/// An entity placed in an entity layer.
#[derive(Clone, Debug, Deserialize)]
#[serde(rename_all = "camelCase")]
pub(super) struct EntityInstanceJson {
    #[serde(rename = "__identifier")]
    pub identifier: String,
    #[serde(default = "default_pivot", rename = "__pivot")]
    pub pivot: [f64; 2],
    #[serde(default, rename = "__tags")]
    pub tags: Vec<String>,
    #[serde(default)]
    pub iid: String,
    #[serde(default)]
    pub width: i64,
    #[serde(default)]
    pub height: i64,
    /// The pivot's pixel position in the level.
    pub px: [i64; 2],
    #[serde(default)]
    pub field_instances: Vec<FieldInstanceJson>,
}

/// LDtk's default pivot for entities written without one: the top-left corner.
fn default_pivot() -> [f64; 2] {
    [0.0, 0.0]
}

/// The value of a custom field of a level or an entity.
#[derive(Clone, Debug, Deserialize)]
pub(super) struct FieldInstanceJson {
    #[serde(rename = "__identifier")]
    pub identifier: String,
    /// `Int`, `Float`, `Bool`, `String`, `Multilines`, `Color`, `FilePath`, `Point`,
    /// `EntityRef`, `Tile`, `LocalEnum.Name`, `ExternEnum.Name`, or `Array<…>` of one.
    #[serde(rename = "__type")]
    pub kind: String,
    #[serde(default, rename = "__value")]
    pub value: serde_json::Value,
}
