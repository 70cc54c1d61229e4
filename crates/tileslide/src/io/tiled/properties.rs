//! Tiled's custom properties, and the ones tileslide reads: `one_way`, `one_way_side`,
//! `flag0`…`flag23`, `hit_types` and `collision`.

use std::collections::BTreeMap;

use glam::Vec2;

use crate::HitTypes;
use crate::io::LoadErrorKind;
use crate::tiles::SegmentFlags;

/// Custom properties by name, in name order.
pub type Properties = BTreeMap<String, PropertyValue>;

/// The value of a custom property, typed as in Tiled.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum PropertyValue {
    /// `bool`.
    Bool(bool),
    /// `int` (32-bit, as Tiled stores it).
    Int(i32),
    /// `float`.
    Float(f32),
    /// `string` (also the type of a property saved without one).
    String(String),
    /// `color` as `0xAARRGGBB` (a colour written `#RRGGBB` is opaque).
    Color(u32),
    /// `file`: a path as written in the map.
    File(String),
    /// `object`: the id of an object of the map (0 for none).
    Object(u32),
    /// `list`: values in order.
    List(Vec<PropertyValue>),
    /// A custom class: its name and the members that were set.
    Class {
        /// The class name (`propertytype`).
        class: String,
        /// The members set.
        properties: Properties,
    },
}

impl PropertyValue {
    /// The value of a `bool` property.
    #[must_use]
    pub fn as_bool(&self) -> Option<bool> {
        match self {
            Self::Bool(b) => Some(*b),
            _ => None,
        }
    }

    /// The text of a `string` or `file` property.
    #[must_use]
    pub fn as_str(&self) -> Option<&str> {
        match self {
            Self::String(s) | Self::File(s) => Some(s),
            _ => None,
        }
    }

    /// The value of an `int` property.
    #[must_use]
    pub fn as_int(&self) -> Option<i32> {
        match self {
            Self::Int(i) => Some(*i),
            _ => None,
        }
    }

    /// The value of a `float` property (or an `int` one, converted).
    #[must_use]
    pub fn as_float(&self) -> Option<f32> {
        match self {
            Self::Float(f) => Some(*f),
            Self::Int(i) => Some(*i as f32),
            _ => None,
        }
    }

    /// Tiled's name of the value's type, for messages.
    pub(super) fn type_name(&self) -> &'static str {
        match self {
            Self::Bool(_) => "bool",
            Self::Int(_) => "int",
            Self::Float(_) => "float",
            Self::String(_) => "string",
            Self::Color(_) => "color",
            Self::File(_) => "file",
            Self::Object(_) => "object",
            Self::List(_) => "list",
            Self::Class { .. } => "class",
        }
    }
}

/// Parses a Tiled colour, `#AARRGGBB` or `#RRGGBB` (the `#` is optional), into `0xAARRGGBB`.
pub(super) fn parse_color(text: &str) -> Option<u32> {
    let hex = text.strip_prefix('#').unwrap_or(text);
    if !hex.bytes().all(|b| b.is_ascii_hexdigit()) {
        return None;
    }
    let value = u32::from_str_radix(hex, 16).ok()?;
    match hex.len() {
        6 => Some(0xFF00_0000 | value),
        8 => Some(value),
        _ => None,
    }
}

/// The names `hit_types` accepts, with their sets.
const HIT_TYPE_NAMES: [(&str, HitTypes); 7] = [
    ("HIT", HitTypes::HIT),
    ("DEATH", HitTypes::DEATH),
    ("COLLECT", HitTypes::COLLECT),
    ("POSSESS", HitTypes::POSSESS),
    ("DEPRESS", HitTypes::DEPRESS),
    ("LAUNCH", HitTypes::LAUNCH),
    ("ANY", HitTypes::ANY),
];

/// A property whose value is wrong: its name and why.
#[derive(Debug, PartialEq)]
pub(super) struct PropertyFault {
    pub property: String,
    pub reason: String,
}

impl PropertyFault {
    pub fn new(property: &str, reason: String) -> Self {
        Self {
            property: property.to_owned(),
            reason,
        }
    }
}

impl PropertyFault {
    /// The load error for this property of `owner` (`layer "walls"`, `object 3`).
    pub fn of(self, owner: &str) -> LoadErrorKind {
        LoadErrorKind::BadProperty {
            owner: owner.to_owned(),
            property: self.property,
            reason: self.reason,
        }
    }
}

impl std::fmt::Display for PropertyFault {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "property `{}`: {}", self.property, self.reason)
    }
}

/// The properties of a thing, with another's as the fallback (a collision object's, then its
/// tile's): a name set on the first wins.
#[derive(Clone, Copy)]
pub(super) struct Lookup<'a> {
    pub own: &'a Properties,
    pub inherited: Option<&'a Properties>,
}

impl<'a> Lookup<'a> {
    /// Properties without a fallback.
    pub fn of(own: &'a Properties) -> Self {
        Self {
            own,
            inherited: None,
        }
    }

    fn get(&self, name: &str) -> Option<&'a PropertyValue> {
        self.own
            .get(name)
            .or_else(|| self.inherited.and_then(|p| p.get(name)))
    }

    /// Every name set on either, own first.
    fn names(&self) -> impl Iterator<Item = (&'a String, &'a PropertyValue)> {
        self.own
            .iter()
            .chain(self.inherited.into_iter().flat_map(|p| p.iter()))
    }

    /// A `bool` property, `None` when unset; any other type is an error naming it.
    pub fn bool(&self, name: &str) -> Result<Option<bool>, PropertyFault> {
        match self.get(name) {
            None => Ok(None),
            Some(PropertyValue::Bool(b)) => Ok(Some(*b)),
            Some(other) => Err(PropertyFault::new(
                name,
                format!("must be a bool, not a {}", other.type_name()),
            )),
        }
    }

    /// A `string` property, `None` when unset.
    pub fn string(&self, name: &str) -> Result<Option<&'a str>, PropertyFault> {
        match self.get(name) {
            None => Ok(None),
            Some(PropertyValue::String(s)) => Ok(Some(s)),
            Some(other) => Err(PropertyFault::new(
                name,
                format!("must be a string, not a {}", other.type_name()),
            )),
        }
    }

    /// The user bits: `flagN = true` sets [`SegmentFlags::user`]`(N)` for N in 0..=23.
    pub fn user_flags(&self) -> Result<SegmentFlags, PropertyFault> {
        let mut flags = SegmentFlags::NONE;
        let mut seen: Vec<&str> = Vec::new();
        for (name, _) in self.names() {
            let Some(digits) = name.strip_prefix("flag") else {
                continue;
            };
            if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
                continue;
            }
            if seen.contains(&name.as_str()) {
                continue; // the object's own value hides its tile's
            }
            seen.push(name);
            let bit = digits
                .parse::<u32>()
                .ok()
                .and_then(SegmentFlags::user)
                .ok_or_else(|| {
                    PropertyFault::new(name, "the user bits are `flag0` to `flag23`".into())
                })?;
            if self.bool(name)? == Some(true) {
                flags |= bit;
            }
        }
        Ok(flags)
    }

    /// The side one-way segments face: `one_way_side` = `up` (the default), `down`, `left`
    /// or `right`, as a unit vector in y-down pixels.
    pub fn one_way_side(&self) -> Result<Vec2, PropertyFault> {
        match self.string("one_way_side")? {
            None | Some("up") => Ok(Vec2::NEG_Y),
            Some("down") => Ok(Vec2::Y),
            Some("left") => Ok(Vec2::NEG_X),
            Some("right") => Ok(Vec2::X),
            Some(other) => Err(PropertyFault::new(
                "one_way_side",
                format!("{other:?} is not up, down, left or right"),
            )),
        }
    }

    /// The `hit_types` property: a comma-separated list of HIT, DEATH, COLLECT, POSSESS,
    /// DEPRESS, LAUNCH and ANY (any case); [`HitTypes::NONE`] when unset.
    pub fn hit_types(&self) -> Result<HitTypes, PropertyFault> {
        let Some(text) = self.string("hit_types")? else {
            return Ok(HitTypes::NONE);
        };
        let mut types = HitTypes::NONE;
        for name in text.split(',').map(str::trim).filter(|n| !n.is_empty()) {
            let found = HIT_TYPE_NAMES
                .iter()
                .find(|(known, _)| known.eq_ignore_ascii_case(name))
                .ok_or_else(|| {
                    PropertyFault::new(
                        "hit_types",
                        format!(
                            "unknown hit type {name:?} (expected HIT, DEATH, COLLECT, POSSESS, \
                             DEPRESS, LAUNCH or ANY)"
                        ),
                    )
                })?;
            types |= found.1;
        }
        Ok(types)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn props(list: &[(&str, PropertyValue)]) -> Properties {
        list.iter()
            .map(|(k, v)| ((*k).to_string(), v.clone()))
            .collect()
    }

    #[test]
    fn colors_parse_with_and_without_alpha() {
        assert_eq!(parse_color("#ff102030"), Some(0xFF10_2030));
        assert_eq!(parse_color("#102030"), Some(0xFF10_2030));
        assert_eq!(parse_color("80102030"), Some(0x8010_2030));
        assert_eq!(parse_color("#12345"), None);
        assert_eq!(parse_color("#+1234567"), None);
    }

    #[test]
    fn user_flags_and_their_errors() {
        let own = props(&[
            ("flag0", PropertyValue::Bool(true)),
            ("flag23", PropertyValue::Bool(true)),
            ("flag5", PropertyValue::Bool(false)),
            ("flagship", PropertyValue::Bool(true)),
        ]);
        let inherited = props(&[
            ("flag5", PropertyValue::Bool(true)),
            ("flag1", PropertyValue::Bool(true)),
        ]);
        let flags = Lookup {
            own: &own,
            inherited: Some(&inherited),
        }
        .user_flags()
        .unwrap();
        let want = [0, 1, 23].into_iter().fold(SegmentFlags::NONE, |f, n| {
            f | SegmentFlags::user(n).unwrap()
        });
        assert_eq!(flags, want, "the object's flag5 = false hides its tile's");
        let bad = props(&[("flag24", PropertyValue::Bool(true))]);
        assert!(
            Lookup::of(&bad)
                .user_flags()
                .unwrap_err()
                .reason
                .contains("flag0")
        );
        let typed = props(&[("flag2", PropertyValue::Int(1))]);
        assert!(
            Lookup::of(&typed)
                .user_flags()
                .unwrap_err()
                .reason
                .contains("bool")
        );
    }

    #[test]
    fn hit_types_are_a_comma_list_of_names() {
        let p = props(&[(
            "hit_types",
            PropertyValue::String("hit, Collect,,".to_string()),
        )]);
        assert_eq!(
            Lookup::of(&p).hit_types().unwrap(),
            HitTypes::HIT | HitTypes::COLLECT
        );
        let p = props(&[("hit_types", PropertyValue::String("ANY".to_string()))]);
        assert_eq!(Lookup::of(&p).hit_types().unwrap(), HitTypes::ANY);
        let p = props(&[("hit_types", PropertyValue::String("HIT,BURN".to_string()))]);
        assert!(
            Lookup::of(&p)
                .hit_types()
                .unwrap_err()
                .to_string()
                .contains("\"BURN\"")
        );
        assert_eq!(
            Lookup::of(&Properties::new()).hit_types().unwrap(),
            HitTypes::NONE
        );
    }

    #[test]
    fn one_way_side_defaults_to_up() {
        assert_eq!(
            Lookup::of(&Properties::new()).one_way_side().unwrap(),
            Vec2::NEG_Y
        );
        let p = props(&[("one_way_side", PropertyValue::String("left".to_string()))]);
        assert_eq!(Lookup::of(&p).one_way_side().unwrap(), Vec2::NEG_X);
        let p = props(&[("one_way_side", PropertyValue::String("north".to_string()))]);
        assert!(Lookup::of(&p).one_way_side().is_err());
    }
}
