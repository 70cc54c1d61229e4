//! Arguments from JavaScript, checked at the boundary: numbers (a JavaScript number is an
//! `f64`; NaN, infinities, fractions and out-of-range values are refused with an error
//! naming the argument), owners, and options objects read key by key.
//!
//! The checks return `String` errors so that they are tested natively; the JavaScript layer
//! turns them into `Error`s with [`error`].

use js_sys::{Array, Object, Reflect};
use tileslide::{Owner, SegmentFlags, Vec2};
use wasm_bindgen::prelude::*;

/// The largest integer a JavaScript number holds exactly (`Number.MAX_SAFE_INTEGER`).
pub const MAX_SAFE_INTEGER: f64 = 9_007_199_254_740_991.0;

/// A JavaScript `Error` with `message`.
pub fn error(message: impl std::fmt::Display) -> JsError {
    JsError::new(&message.to_string())
}

/// `value` as an `f32` coordinate, distance or time, or an error naming it (`what`) when it
/// is NaN or infinite, or too large for an `f32` (it would become infinite).
pub fn finite(what: &str, value: f64) -> Result<f32, String> {
    let single = value as f32;
    if value.is_finite() && single.is_finite() {
        Ok(single)
    } else if value.is_finite() {
        Err(format!("{what} is {value}, too large for a 32-bit float"))
    } else {
        Err(format!("{what} is {value}, not a finite number"))
    }
}

/// The point or vector (`x`, `y`), each coordinate checked by [`finite`] and named
/// `{what}.x` / `{what}.y`.
pub fn vec2(what: &str, x: f64, y: f64) -> Result<Vec2, String> {
    // The names are formatted only for an error: a game calls this every frame.
    let (sx, sy) = (x as f32, y as f32);
    if sx.is_finite() && sy.is_finite() {
        return Ok(Vec2::new(sx, sy));
    }
    Ok(Vec2::new(
        finite(&format!("{what}.x"), x)?,
        finite(&format!("{what}.y"), y)?,
    ))
}

/// `value` as a whole number from 0 to `u32::MAX`, or an error naming it (`what`): a
/// JavaScript number is a float, and wrapping -1 to 4294967295 would name the wrong thing.
pub fn whole(what: &str, value: f64) -> Result<u32, String> {
    if value.fract() == 0.0 && (0.0..=f64::from(u32::MAX)).contains(&value) {
        Ok(value as u32)
    } else {
        Err(format!(
            "{what} is {value}, not a whole number from 0 to {}",
            u32::MAX
        ))
    }
}

/// `value` as an [`Owner`]: a whole number from 0 to `Number.MAX_SAFE_INTEGER` (larger
/// numbers are not exact in JavaScript, so two owners could not be told apart).
pub fn owner(what: &str, value: f64) -> Result<Owner, String> {
    if value.fract() == 0.0 && (0.0..=MAX_SAFE_INTEGER).contains(&value) {
        Ok(Owner(value as u64))
    } else {
        Err(format!(
            "{what} is {value}, not a whole number from 0 to Number.MAX_SAFE_INTEGER"
        ))
    }
}

/// An options object from JavaScript, read key by key: each getter names the option in its
/// error, and [`finish`](Self::finish) refuses keys nobody read (a misspelt option is an
/// error, not a silent default).
pub struct Options {
    /// What the object is, for errors (`"resolve config"`).
    what: String,
    object: Option<Object>,
    read: Vec<&'static str>,
}

impl Options {
    /// The options in `value`: an object, or `undefined`/`null` for none.
    pub fn new(what: impl Into<String>, value: Option<JsValue>) -> Result<Self, String> {
        let what = what.into();
        let object = match value {
            None => None,
            Some(v) if v.is_undefined() || v.is_null() => None,
            Some(v) if v.is_object() && !Array::is_array(&v) => Some(v.unchecked_into()),
            Some(_) => return Err(format!("{what} must be an object")),
        };
        Ok(Self {
            what,
            object,
            read: Vec::new(),
        })
    }

    /// The value of `key`, or `None` when it is missing, `undefined` or `null`.
    fn get(&mut self, key: &'static str) -> Option<JsValue> {
        self.read.push(key);
        let object = self.object.as_ref()?;
        let value = Reflect::get(object, &JsValue::from_str(key)).ok()?;
        (!value.is_undefined() && !value.is_null()).then_some(value)
    }

    /// The number at `key`, or `None` when missing.
    pub fn number(&mut self, key: &'static str) -> Result<Option<f64>, String> {
        match self.get(key) {
            None => Ok(None),
            Some(v) => v
                .as_f64()
                .map(Some)
                .ok_or_else(|| format!("{}: `{key}` must be a number", self.what)),
        }
    }

    /// The `f32` at `key`, checked by [`finite`], or `default`.
    pub fn f32_or(&mut self, key: &'static str, default: f32) -> Result<f32, String> {
        match self.number(key)? {
            None => Ok(default),
            Some(v) => finite(&format!("{}: `{key}`", self.what), v),
        }
    }

    /// The whole number at `key`, checked by [`whole`], or `default`.
    pub fn u32_or(&mut self, key: &'static str, default: u32) -> Result<u32, String> {
        match self.number(key)? {
            None => Ok(default),
            Some(v) => whole(&format!("{}: `{key}`", self.what), v),
        }
    }

    /// The owner at `key`, checked by [`owner`], or `default`.
    pub fn owner_or(&mut self, key: &'static str, default: Owner) -> Result<Owner, String> {
        match self.number(key)? {
            None => Ok(default),
            Some(v) => owner(&format!("{}: `{key}`", self.what), v),
        }
    }

    /// The segment flags at `key` (a whole number of bits), or `default`.
    pub fn flags_or(
        &mut self,
        key: &'static str,
        default: SegmentFlags,
    ) -> Result<SegmentFlags, String> {
        Ok(SegmentFlags(self.u32_or(key, default.0)?))
    }

    /// The boolean at `key`, or `default`.
    pub fn bool_or(&mut self, key: &'static str, default: bool) -> Result<bool, String> {
        match self.get(key) {
            None => Ok(default),
            Some(v) => v
                .as_bool()
                .ok_or_else(|| format!("{}: `{key}` must be true or false", self.what)),
        }
    }

    /// The string at `key`, or `None` when missing.
    pub fn string(&mut self, key: &'static str) -> Result<Option<String>, String> {
        match self.get(key) {
            None => Ok(None),
            Some(v) => v
                .as_string()
                .map(Some)
                .ok_or_else(|| format!("{}: `{key}` must be a string", self.what)),
        }
    }

    /// The pair `[x, y]` of numbers at `key`, checked by [`finite`], or `None` when missing.
    pub fn pair(&mut self, key: &'static str) -> Result<Option<Vec2>, String> {
        let Some(value) = self.get(key) else {
            return Ok(None);
        };
        let what = format!("{}: `{key}`", self.what);
        pair(&what, &value).map(Some)
    }

    /// The object at `key` as options of its own, named `{what}.{key}`.
    pub fn nested(&mut self, key: &'static str) -> Result<Options, String> {
        let value = self.get(key);
        Options::new(format!("{}.{key}", self.what), value)
    }

    /// Refuses keys that no getter read, naming the first.
    pub fn finish(self) -> Result<(), String> {
        let Some(object) = self.object else {
            return Ok(());
        };
        for key in Object::keys(&object).iter() {
            let key = key.as_string().unwrap_or_default();
            if !self.read.iter().any(|k| *k == key) {
                return Err(format!(
                    "{}: unknown option `{key}` (known: {})",
                    self.what,
                    self.read.join(", ")
                ));
            }
        }
        Ok(())
    }
}

/// `value` as an array `[x, y]` of two finite numbers, or an error naming it (`what`).
pub fn pair(what: &str, value: &JsValue) -> Result<Vec2, String> {
    let array = Array::from(value);
    let (x, y) = (array.get(0).as_f64(), array.get(1).as_f64());
    match (Array::is_array(value) && array.length() == 2, x, y) {
        (true, Some(x), Some(y)) => vec2(what, x, y),
        _ => Err(format!("{what} must be an array [x, y] of two numbers")),
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;

    #[test]
    fn numbers_are_refused_with_their_name_and_value() {
        assert_eq!(finite("x", 1.5), Ok(1.5));
        assert!(finite("dx", f64::NAN).unwrap_err().contains("dx is NaN"));
        assert!(
            finite("dy", f64::INFINITY)
                .unwrap_err()
                .contains("dy is inf")
        );
        assert!(finite("r", 1e39).unwrap_err().contains("too large"));
        assert!(
            vec2("to", 0.0, f64::NAN)
                .unwrap_err()
                .contains("to.y is NaN")
        );
        assert_eq!(whole("col", 3.0), Ok(3));
        assert!(whole("col", -1.0).is_err() && whole("col", 1.5).is_err());
        assert_eq!(
            owner("owner", MAX_SAFE_INTEGER),
            Ok(Owner(MAX_SAFE_INTEGER as u64))
        );
        assert!(owner("owner", MAX_SAFE_INTEGER + 2.0).is_err());
        assert!(owner("owner", f64::NAN).is_err());
    }
}
