//! Object layers: spawn points, regions, paths and tile objects, as Tiled placed them.

use glam::Vec2;

use super::properties::Properties;
use crate::HitTypes;

/// An object layer (`<objectgroup>` in `.tmx`, `"objectgroup"` in `.tmj`).
#[derive(Clone, Debug, PartialEq)]
pub struct ObjectLayer {
    /// The layer's name.
    pub name: String,
    /// The layer's class (`class`, formerly `type`); empty if none.
    pub class: String,
    /// The layer's custom properties.
    pub properties: Properties,
    /// The objects, in the file's order.
    pub objects: Vec<MapObject>,
}

impl ObjectLayer {
    /// The first object named `name`.
    #[must_use]
    pub fn object(&self, name: &str) -> Option<&MapObject> {
        self.objects.iter().find(|o| o.name == name)
    }
}

/// One object of an object layer, or one collision object of a tile.
///
/// Positions are map pixels, y down, as Tiled shows them, with the offsets of the object's
/// layer and its groups added. Collision objects of tiles are in the tile's own pixels.
#[derive(Clone, Debug, PartialEq)]
pub struct MapObject {
    /// The object's id (unique in a map; 0 in files older than Tiled 0.11).
    pub id: u32,
    /// The object's name; empty if none.
    pub name: String,
    /// The object's class (`class`, or `type` as objects still write it); empty if none.
    pub class: String,
    /// The object's position: the top-left corner of a rectangle or ellipse, the first
    /// reference point of a polygon or polyline, the bottom-left corner of a tile object.
    pub position: Vec2,
    /// Width and height (zero for points, polygons and polylines).
    pub size: Vec2,
    /// Clockwise rotation about [`position`](Self::position), in degrees.
    pub rotation: f32,
    /// Whether the object is shown in Tiled.
    pub visible: bool,
    /// The object's shape.
    pub shape: ObjectShape,
    /// For a tile object, the gid of its tile (with its flip bits).
    pub gid: Option<u32>,
    /// The object's custom properties.
    pub properties: Properties,
    /// The `hit_types` property, parsed ([`HitTypes::NONE`] when unset).
    pub hit_types: HitTypes,
}

/// The shape of a [`MapObject`]. Points of polygons and polylines are relative to the
/// object's position (before its rotation).
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum ObjectShape {
    /// A rectangle of the object's size (also the shape of tile objects).
    Rectangle,
    /// A point: the object's position.
    Point,
    /// An ellipse inscribed in the object's size.
    Ellipse,
    /// A capsule (a rectangle with round ends) of the object's size.
    Capsule,
    /// A closed polygon.
    Polygon(Vec<Vec2>),
    /// An open chain of segments.
    Polyline(Vec<Vec2>),
    /// A text box of the object's size, with its text.
    Text(String),
}
