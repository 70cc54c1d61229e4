//! Entity layers and custom fields: spawn points, platforms and their paths, as LDtk placed
//! them, in world pixels.

use std::collections::BTreeMap;

use glam::Vec2;
use serde_json::Value;

use super::schema::{EntityInstanceJson, FieldInstanceJson};
use crate::io::LdtkFault;

/// Custom field values by identifier (a level's or an entity's), in identifier order.
pub type Fields = BTreeMap<String, FieldValue>;

/// The value of a custom field, typed by its `__type`.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum FieldValue {
    /// A field without a value (`null`).
    Null,
    /// `Int`.
    Int(i64),
    /// `Float`.
    Float(f64),
    /// `Bool`.
    Bool(bool),
    /// `String` and `Multilines`.
    String(String),
    /// `Color`, `#rrggbb` as `0xFFRRGGBB` (opaque, as Tiled's colours read).
    Color(u32),
    /// A value of an enum (`LocalEnum.Name` or `ExternEnum.Name`): the value's id.
    Enum(String),
    /// `FilePath`: a path as written in the project (never opened by the loader).
    FilePath(String),
    /// `Point`: a cell of the grid, and where its centre is in world pixels.
    Point(FieldPoint),
    /// `EntityRef`: the entity referred to, by its iid.
    EntityRef(String),
    /// `Tile`: a rectangle of a tile set's image.
    Tile(TileRect),
    /// An array field (`Array<…>`): its values in order.
    Array(Vec<FieldValue>),
}

/// A `Point` field's value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FieldPoint {
    /// The cell's column, in the grid of the entity's layer (of the project's default grid
    /// for a level's fields).
    pub cx: i64,
    /// The cell's row.
    pub cy: i64,
    /// The centre of the cell, in world pixels.
    pub position: Vec2,
    /// The cell's top-left corner, in world pixels.
    pub corner: Vec2,
}

/// A `Tile` field's value: a rectangle of a tile set's image, in its pixels.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TileRect {
    /// The tile set's uid.
    pub tileset_uid: i64,
    /// Left edge.
    pub x: i64,
    /// Top edge.
    pub y: i64,
    /// Width.
    pub w: i64,
    /// Height.
    pub h: i64,
}

impl FieldValue {
    /// The value of an `Int` field.
    #[must_use]
    pub fn as_int(&self) -> Option<i64> {
        match self {
            Self::Int(i) => Some(*i),
            _ => None,
        }
    }

    /// The value of a `Float` field (or an `Int` one, converted).
    #[must_use]
    pub fn as_float(&self) -> Option<f64> {
        match self {
            Self::Float(f) => Some(*f),
            Self::Int(i) => Some(*i as f64),
            _ => None,
        }
    }

    /// The value of a `Bool` field.
    #[must_use]
    pub fn as_bool(&self) -> Option<bool> {
        match self {
            Self::Bool(b) => Some(*b),
            _ => None,
        }
    }

    /// The text of a `String`, `Multilines`, enum or `FilePath` field.
    #[must_use]
    pub fn as_str(&self) -> Option<&str> {
        match self {
            Self::String(s) | Self::Enum(s) | Self::FilePath(s) => Some(s),
            _ => None,
        }
    }

    /// The position of a `Point` field, in world pixels.
    #[must_use]
    pub fn as_point(&self) -> Option<Vec2> {
        match self {
            Self::Point(p) => Some(p.position),
            _ => None,
        }
    }

    /// The values of an array field.
    #[must_use]
    pub fn as_array(&self) -> Option<&[FieldValue]> {
        match self {
            Self::Array(values) => Some(values),
            _ => None,
        }
    }

    /// The positions of an `Array<Point>` field (a path), in world pixels; `None` if it is
    /// not one or holds a `null`.
    #[must_use]
    pub fn as_points(&self) -> Option<Vec<Vec2>> {
        self.as_array()?.iter().map(Self::as_point).collect()
    }
}

/// An entity layer of a level.
#[derive(Clone, Debug, PartialEq)]
pub struct EntityLayer {
    /// The layer's identifier.
    pub identifier: String,
    /// The layer's iid.
    pub iid: String,
    /// The layer's cell size in pixels (the grid its `Point` fields count in).
    pub grid_size: u32,
    /// The entities, in the file's order.
    pub entities: Vec<LdtkEntity>,
}

impl EntityLayer {
    /// The first entity whose identifier (its definition's name) is `identifier`.
    #[must_use]
    pub fn entity(&self, identifier: &str) -> Option<&LdtkEntity> {
        self.entities.iter().find(|e| e.identifier == identifier)
    }

    /// Every entity whose identifier is `identifier`, in the file's order.
    pub fn entities_of<'a>(&'a self, identifier: &'a str) -> impl Iterator<Item = &'a LdtkEntity> {
        self.entities
            .iter()
            .filter(move |e| e.identifier == identifier)
    }
}

/// One entity of an entity layer.
///
/// Positions are world pixels, y down: the level's world position, plus the layer's offset,
/// plus the entity's place in the level.
#[derive(Clone, Debug, PartialEq)]
pub struct LdtkEntity {
    /// The identifier of the entity's definition (its type: `PlayerStart`, `Platform`).
    pub identifier: String,
    /// The entity's iid (unique in the project).
    pub iid: String,
    /// Where its pivot is, in world pixels.
    pub position: Vec2,
    /// Its width and height, in pixels.
    pub size: Vec2,
    /// Its pivot, from (0, 0) (top-left corner) to (1, 1) (bottom-right).
    pub pivot: Vec2,
    /// Its definition's tags.
    pub tags: Vec<String>,
    /// Its custom fields.
    pub fields: Fields,
}

impl LdtkEntity {
    /// The top-left corner of the entity's rectangle, in world pixels.
    #[must_use]
    pub fn top_left(&self) -> Vec2 {
        self.position - self.pivot * self.size
    }

    /// The centre of the entity's rectangle, in world pixels.
    #[must_use]
    pub fn center(&self) -> Vec2 {
        self.top_left() + self.size * 0.5
    }

    /// The field `identifier`, if the entity has it.
    #[must_use]
    pub fn field(&self, identifier: &str) -> Option<&FieldValue> {
        self.fields.get(identifier)
    }
}

/// A fault at a JSON path below the one being read.
pub(super) type Fault = (String, LdtkFault);

/// The grid a layer's `Point` fields count in: its cell size and its world origin.
#[derive(Clone, Copy)]
pub(super) struct PointGrid {
    pub size: f64,
    pub origin: Vec2,
}

/// The entity of `json`, whose layer's grid is `grid`; `at` is its JSON path.
pub(super) fn entity(
    json: &EntityInstanceJson,
    grid: PointGrid,
    at: &str,
) -> Result<LdtkEntity, Fault> {
    let [px, py] = json.px;
    Ok(LdtkEntity {
        identifier: json.identifier.clone(),
        iid: json.iid.clone(),
        position: grid.origin + Vec2::new(px as f32, py as f32),
        size: Vec2::new(json.width as f32, json.height as f32),
        pivot: Vec2::new(json.pivot[0] as f32, json.pivot[1] as f32),
        tags: json.tags.clone(),
        fields: fields(&json.field_instances, grid, &format!("{at}.fieldInstances"))?,
    })
}

/// The fields of `json`; `at` is the JSON path of the array.
pub(super) fn fields(
    json: &[FieldInstanceJson],
    grid: PointGrid,
    at: &str,
) -> Result<Fields, Fault> {
    let mut out = Fields::new();
    for (i, field) in json.iter().enumerate() {
        let bad = |reason: String| {
            (
                format!("{at}[{i}].__value"),
                LdtkFault::BadField {
                    field: field.identifier.clone(),
                    kind: field.kind.clone(),
                    reason,
                },
            )
        };
        let kind = field.kind.as_str();
        let value = match kind
            .strip_prefix("Array<")
            .and_then(|k| k.strip_suffix('>'))
        {
            Some(element) => match &field.value {
                Value::Array(values) => values
                    .iter()
                    .enumerate()
                    .map(|(j, v)| {
                        value(element, v, grid).map_err(|r| bad(format!("element {j}: {r}")))
                    })
                    .collect::<Result<Vec<_>, _>>()
                    .map(FieldValue::Array)?,
                Value::Null => FieldValue::Null,
                other => return Err(bad(format!("{} for an array", json_kind(other)))),
            },
            None => value(kind, &field.value, grid).map_err(bad)?,
        };
        out.insert(field.identifier.clone(), value);
    }
    Ok(out)
}

/// The value `v` of a field of type `kind` (not an array).
fn value(kind: &str, v: &Value, grid: PointGrid) -> Result<FieldValue, String> {
    if v.is_null() {
        return Ok(FieldValue::Null);
    }
    let wrong = |expected: &str| format!("{} where {expected} was expected", json_kind(v));
    let text = || {
        v.as_str()
            .map(str::to_owned)
            .ok_or_else(|| wrong("a string"))
    };
    Ok(match kind {
        "Int" => FieldValue::Int(v.as_i64().ok_or_else(|| wrong("an integer"))?),
        "Float" => FieldValue::Float(v.as_f64().ok_or_else(|| wrong("a number"))?),
        "Bool" => FieldValue::Bool(v.as_bool().ok_or_else(|| wrong("true or false"))?),
        "String" | "Multilines" | "Text" => FieldValue::String(text()?),
        "FilePath" => FieldValue::FilePath(text()?),
        "Color" => {
            let s = text()?;
            FieldValue::Color(
                color(&s).ok_or_else(|| format!("{s:?} is not a colour \"#rrggbb\""))?,
            )
        }
        "Point" => {
            let cell = |key: &str| v.get(key).and_then(Value::as_i64);
            let (Some(cx), Some(cy)) = (cell("cx"), cell("cy")) else {
                return Err(wrong("an object with integers `cx` and `cy`"));
            };
            let at = |c: i64, within: f64| ((c as f64 + within) * grid.size) as f32;
            FieldValue::Point(FieldPoint {
                cx,
                cy,
                position: grid.origin + Vec2::new(at(cx, 0.5), at(cy, 0.5)),
                corner: grid.origin + Vec2::new(at(cx, 0.0), at(cy, 0.0)),
            })
        }
        "EntityRef" => FieldValue::EntityRef(
            v.get("entityIid")
                .and_then(Value::as_str)
                .map(str::to_owned)
                .ok_or_else(|| wrong("an object with a string `entityIid`"))?,
        ),
        "Tile" => {
            let n = |key: &str| v.get(key).and_then(Value::as_i64);
            let (Some(tileset_uid), Some(x), Some(y), Some(w), Some(h)) =
                (n("tilesetUid"), n("x"), n("y"), n("w"), n("h"))
            else {
                return Err(wrong("a tile rectangle (`tilesetUid`, `x`, `y`, `w`, `h`)"));
            };
            FieldValue::Tile(TileRect {
                tileset_uid,
                x,
                y,
                w,
                h,
            })
        }
        k if k.starts_with("LocalEnum.") || k.starts_with("ExternEnum.") => {
            FieldValue::Enum(text()?)
        }
        // A type this version does not know: kept as text when it is text, else refused
        // rather than silently dropped.
        _ => FieldValue::String(text().map_err(|_| format!("unknown field type {kind:?}"))?),
    })
}

/// `#rrggbb` as `0xFFRRGGBB`.
fn color(text: &str) -> Option<u32> {
    let hex = text.strip_prefix('#')?;
    if hex.len() != 6 || !hex.bytes().all(|b| b.is_ascii_hexdigit()) {
        return None;
    }
    u32::from_str_radix(hex, 16).ok().map(|c| 0xFF00_0000 | c)
}

/// What kind of JSON value `v` is, for messages.
fn json_kind(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;

    fn field(kind: &str, value: Value) -> FieldInstanceJson {
        FieldInstanceJson {
            identifier: "f".into(),
            kind: kind.into(),
            value,
        }
    }

    const GRID: PointGrid = PointGrid {
        size: 16.0,
        origin: Vec2::new(100.0, 0.0),
    };

    #[test]
    fn each_field_type_reads_as_its_value() {
        let read =
            |kind: &str, v: Value| fields(&[field(kind, v)], GRID, "x").unwrap()["f"].clone();
        assert_eq!(read("Int", 3.into()), FieldValue::Int(3));
        assert_eq!(read("Float", 1.5.into()), FieldValue::Float(1.5));
        assert_eq!(read("Bool", true.into()), FieldValue::Bool(true));
        assert_eq!(
            read("Multilines", "a\nb".into()),
            FieldValue::String("a\nb".into())
        );
        assert_eq!(
            read("Color", "#D181E8".into()),
            FieldValue::Color(0xFFD1_81E8)
        );
        assert_eq!(
            read("LocalEnum.Item", "Gem".into()),
            FieldValue::Enum("Gem".into())
        );
        assert_eq!(read("Int", Value::Null), FieldValue::Null);
        let path = read(
            "Array<Point>",
            serde_json::json!([{"cx": 0, "cy": 0}, {"cx": 2, "cy": 1}]),
        );
        assert_eq!(
            path.as_points().unwrap(),
            vec![Vec2::new(108.0, 8.0), Vec2::new(140.0, 24.0)]
        );
        assert_eq!(
            read(
                "EntityRef",
                serde_json::json!({"entityIid": "e1", "layerIid": "l"})
            ),
            FieldValue::EntityRef("e1".into())
        );
    }

    #[test]
    fn a_value_of_the_wrong_type_names_the_field_and_element() {
        let e = fields(
            &[
                field("Int", 1.into()),
                field("Array<Int>", serde_json::json!([1, "two"])),
            ],
            GRID,
            "levels[0].fieldInstances",
        )
        .unwrap_err();
        assert_eq!(e.0, "levels[0].fieldInstances[1].__value");
        assert_eq!(
            e.1.to_string(),
            "field \"f\" of type \"Array<Int>\": element 1: a string where an integer was expected"
        );
        let e = fields(&[field("Color", "red".into())], GRID, "x").unwrap_err();
        assert!(
            e.1.to_string().contains("\"red\" is not a colour"),
            "{}",
            e.1
        );
    }
}
