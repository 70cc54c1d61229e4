//! The serde model of Tiled's JSON formats (`.tmj` maps, `.tsj` tile sets): only the fields
//! tileslide reads, and the conversion of objects and properties to tileslide's types.

use std::fmt;

use glam::Vec2;
use serde::Deserialize;
use serde::de::{self, Deserializer, SeqAccess, Visitor};

use super::objects::{MapObject, ObjectShape};
use super::properties::{Properties, PropertyFault, PropertyValue, parse_color};
use crate::HitTypes;
use crate::io::{LoadErrorKind, Unsupported};

#[derive(Deserialize)]
pub(super) struct JsonMap {
    /// `"map"` since Tiled 1.2; older maps have no `type`.
    #[serde(rename = "type")]
    pub kind: Option<String>,
    pub orientation: Option<String>,
    pub width: Option<u32>,
    pub height: Option<u32>,
    pub tilewidth: u32,
    pub tileheight: u32,
    #[serde(default)]
    pub infinite: bool,
    #[serde(default)]
    pub tilesets: Vec<JsonTileSet>,
    #[serde(default)]
    pub layers: Vec<JsonLayer>,
    #[serde(default)]
    pub properties: Vec<JsonProperty>,
}

/// What a JSON file says it is, read without building anything: tells a Tiled JSON map from
/// a tile set or other JSON.
#[derive(Deserialize)]
pub(super) struct JsonKind {
    #[serde(rename = "type")]
    pub kind: Option<String>,
    pub orientation: Option<de::IgnoredAny>,
}

/// A tile set in a map (embedded, or a reference with `source`) or in a `.tsj` file.
#[derive(Deserialize)]
pub(super) struct JsonTileSet {
    pub firstgid: Option<u32>,
    pub source: Option<String>,
    #[serde(default)]
    pub name: String,
    pub tilewidth: Option<u32>,
    pub tileheight: Option<u32>,
    pub tilecount: Option<u32>,
    #[serde(default)]
    pub tiles: Vec<JsonTile>,
}

#[derive(Deserialize)]
pub(super) struct JsonTile {
    pub id: u32,
    #[serde(rename = "type")]
    pub kind: Option<String>,
    pub class: Option<String>,
    #[serde(default)]
    pub properties: Vec<JsonProperty>,
    pub objectgroup: Option<JsonObjectGroup>,
}

#[derive(Deserialize)]
pub(super) struct JsonObjectGroup {
    #[serde(default)]
    pub objects: Vec<JsonObject>,
}

#[derive(Deserialize)]
pub(super) struct JsonLayer {
    #[serde(rename = "type")]
    pub kind: String,
    #[serde(default)]
    pub name: String,
    #[serde(default)]
    pub class: String,
    pub width: Option<u32>,
    pub height: Option<u32>,
    pub data: Option<JsonData>,
    pub encoding: Option<String>,
    pub compression: Option<String>,
    pub chunks: Option<Vec<JsonChunk>>,
    #[serde(default)]
    pub objects: Vec<JsonObject>,
    #[serde(default)]
    pub layers: Vec<JsonLayer>,
    #[serde(default)]
    pub offsetx: f32,
    #[serde(default)]
    pub offsety: f32,
    #[serde(default)]
    pub properties: Vec<JsonProperty>,
}

#[derive(Deserialize)]
pub(super) struct JsonChunk {
    pub x: i32,
    pub y: i32,
    pub width: u32,
    pub height: u32,
    pub data: JsonData,
}

/// A layer's or chunk's `data`: an array of gids, or a base64 string.
pub(super) enum JsonData {
    Gids(Vec<u32>),
    Text(String),
}

impl<'de> Deserialize<'de> for JsonData {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct DataVisitor;
        impl<'de> Visitor<'de> for DataVisitor {
            type Value = JsonData;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("an array of tile gids or a base64 string")
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<JsonData, E> {
                Ok(JsonData::Text(v.to_owned()))
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<JsonData, A::Error> {
                let mut gids = Vec::new();
                while let Some(gid) = seq.next_element::<u32>()? {
                    gids.push(gid);
                }
                Ok(JsonData::Gids(gids))
            }
        }
        deserializer.deserialize_any(DataVisitor)
    }
}

#[derive(Deserialize)]
pub(super) struct JsonObject {
    #[serde(default)]
    pub id: u32,
    #[serde(default)]
    pub name: String,
    #[serde(rename = "type")]
    pub kind: Option<String>,
    pub class: Option<String>,
    #[serde(default)]
    pub x: f32,
    #[serde(default)]
    pub y: f32,
    #[serde(default)]
    pub width: f32,
    #[serde(default)]
    pub height: f32,
    #[serde(default)]
    pub rotation: f32,
    #[serde(default = "visible_by_default")]
    pub visible: bool,
    pub gid: Option<u32>,
    #[serde(default)]
    pub ellipse: bool,
    #[serde(default)]
    pub point: bool,
    #[serde(default)]
    pub capsule: bool,
    pub polygon: Option<Vec<JsonPoint>>,
    pub polyline: Option<Vec<JsonPoint>>,
    pub text: Option<JsonText>,
    pub template: Option<String>,
    #[serde(default)]
    pub properties: Vec<JsonProperty>,
}

fn visible_by_default() -> bool {
    true
}

#[derive(Deserialize)]
pub(super) struct JsonPoint {
    pub x: f32,
    pub y: f32,
}

#[derive(Deserialize)]
pub(super) struct JsonText {
    #[serde(default)]
    pub text: String,
}

#[derive(Deserialize)]
pub(super) struct JsonProperty {
    pub name: String,
    #[serde(rename = "type")]
    pub kind: Option<String>,
    #[serde(default)]
    pub propertytype: String,
    #[serde(default)]
    pub value: serde_json::Value,
}

/// The object `o`, moved by its layer's `offset`; an error for an object made from a
/// template (which only `.tmx` maps resolve) or with a property of the wrong type.
pub(super) fn object(o: &JsonObject, offset: Vec2) -> Result<MapObject, LoadErrorKind> {
    if let Some(template) = &o.template {
        return Err(Unsupported::TemplateInTmj {
            object: o.id,
            template: template.clone(),
        }
        .into());
    }
    let points = |list: &[JsonPoint]| list.iter().map(|p| Vec2::new(p.x, p.y)).collect();
    let size = Vec2::new(o.width, o.height);
    let (shape, size) = if o.point {
        (ObjectShape::Point, Vec2::ZERO)
    } else if o.ellipse {
        (ObjectShape::Ellipse, size)
    } else if o.capsule {
        (ObjectShape::Capsule, size)
    } else if let Some(p) = &o.polygon {
        (ObjectShape::Polygon(points(p)), Vec2::ZERO)
    } else if let Some(p) = &o.polyline {
        (ObjectShape::Polyline(points(p)), Vec2::ZERO)
    } else if let Some(t) = &o.text {
        (ObjectShape::Text(t.text.clone()), size)
    } else {
        (ObjectShape::Rectangle, size)
    };
    Ok(MapObject {
        id: o.id,
        name: o.name.clone(),
        class: o
            .class
            .clone()
            .or_else(|| o.kind.clone())
            .unwrap_or_default(),
        position: Vec2::new(o.x, o.y) + offset,
        size,
        rotation: o.rotation,
        visible: o.visible,
        shape,
        gid: o.gid,
        properties: properties(&o.properties)
            .map_err(|fault| fault.of(&format!("object {}", o.id)))?,
        hit_types: HitTypes::NONE,
    })
}

pub(super) fn properties(list: &[JsonProperty]) -> Result<Properties, PropertyFault> {
    list.iter()
        .map(|p| {
            let value = property(p.kind.as_deref(), &p.propertytype, &p.value)
                .map_err(|reason| PropertyFault::new(&p.name, reason))?;
            Ok((p.name.clone(), value))
        })
        .collect()
}

/// A property value of Tiled type `kind` (`string` when absent).
fn property(
    kind: Option<&str>,
    class: &str,
    value: &serde_json::Value,
) -> Result<PropertyValue, String> {
    use serde_json::Value;
    let kind = kind.unwrap_or("string");
    let mismatch = || format!("the value {value} is not a {kind}");
    Ok(match kind {
        "bool" => PropertyValue::Bool(value.as_bool().ok_or_else(mismatch)?),
        "int" => PropertyValue::Int(
            value
                .as_i64()
                .and_then(|i| i32::try_from(i).ok())
                .ok_or_else(mismatch)?,
        ),
        "float" => PropertyValue::Float(value.as_f64().ok_or_else(mismatch)? as f32),
        "string" => PropertyValue::String(value.as_str().ok_or_else(mismatch)?.to_owned()),
        "file" => PropertyValue::File(value.as_str().ok_or_else(mismatch)?.to_owned()),
        "color" => {
            let text = value.as_str().ok_or_else(mismatch)?;
            PropertyValue::Color(if text.is_empty() {
                0
            } else {
                parse_color(text).ok_or_else(mismatch)?
            })
        }
        "object" => PropertyValue::Object(
            value
                .as_u64()
                .and_then(|i| u32::try_from(i).ok())
                .ok_or_else(mismatch)?,
        ),
        "list" => {
            let items = value.as_array().ok_or_else(mismatch)?;
            let mut out = Vec::with_capacity(items.len());
            for item in items {
                let kind = item.get("type").and_then(Value::as_str);
                let class = item
                    .get("propertytype")
                    .and_then(Value::as_str)
                    .unwrap_or("");
                out.push(property(
                    kind,
                    class,
                    item.get("value").unwrap_or(&Value::Null),
                )?);
            }
            PropertyValue::List(out)
        }
        // A class's members carry no types in JSON: they are typed by their JSON values.
        "class" => PropertyValue::Class {
            class: class.to_owned(),
            properties: match value {
                Value::Object(members) => members
                    .iter()
                    .map(|(name, v)| Ok((name.clone(), untyped(v)?)))
                    .collect::<Result<_, String>>()?,
                Value::Null => Properties::new(),
                _ => return Err(mismatch()),
            },
        },
        other => return Err(format!("unknown property type {other:?}")),
    })
}

/// A class member's value, typed by its JSON value.
fn untyped(value: &serde_json::Value) -> Result<PropertyValue, String> {
    use serde_json::Value;
    Ok(match value {
        Value::Bool(b) => PropertyValue::Bool(*b),
        Value::Number(n) => match n.as_i64().and_then(|i| i32::try_from(i).ok()) {
            Some(i) => PropertyValue::Int(i),
            None => PropertyValue::Float(n.as_f64().unwrap_or(f64::NAN) as f32),
        },
        Value::String(s) => PropertyValue::String(s.clone()),
        Value::Array(items) => {
            PropertyValue::List(items.iter().map(untyped).collect::<Result<_, _>>()?)
        }
        Value::Object(members) => PropertyValue::Class {
            class: String::new(),
            properties: members
                .iter()
                .map(|(k, v)| Ok((k.clone(), untyped(v)?)))
                .collect::<Result<_, String>>()?,
        },
        Value::Null => return Err("a class member is null".into()),
    })
}
