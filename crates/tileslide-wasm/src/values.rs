//! Values for JavaScript: the plain objects and arrays the API returns.

use js_sys::{Array, Object, Reflect};
use tileslide::{SegmentSource, Vec2};
use wasm_bindgen::prelude::*;

use crate::args::error;

/// A plain object with these keys and values, in order.
pub fn object(entries: &[(&str, JsValue)]) -> Result<Object, JsError> {
    let object = Object::new();
    for (key, value) in entries {
        Reflect::set(&object, &JsValue::from_str(key), value)
            .map_err(|_| error(format!("could not set `{key}` on a result object")))?;
    }
    Ok(object)
}

/// `[x, y]`.
pub fn pair(v: Vec2) -> JsValue {
    Array::of2(&v.x.into(), &v.y.into()).into()
}

/// An owner as a JavaScript number (owners come from JavaScript numbers, so are exact).
pub fn owner_number(owner: tileslide::Owner) -> JsValue {
    JsValue::from_f64(owner.0 as f64)
}

/// Where a segment comes from, as the fields `cell` (`[col, row]` or `null`), `tile` (or
/// `null`), `owner` (a temporary segment's, or `null`) and `velocity` (`[vx, vy]`; zero
/// for a tile).
pub fn source_fields(source: &SegmentSource) -> [(&'static str, JsValue); 4] {
    match *source {
        SegmentSource::Tile { segment, tile } => [
            (
                "cell",
                Array::of2(&segment.cell.col.into(), &segment.cell.row.into()).into(),
            ),
            ("tile", tile.0.into()),
            ("owner", JsValue::NULL),
            ("velocity", pair(Vec2::ZERO)),
        ],
        SegmentSource::Temporary {
            owner, velocity, ..
        } => [
            ("cell", JsValue::NULL),
            ("tile", JsValue::NULL),
            ("owner", owner_number(owner)),
            ("velocity", pair(velocity)),
        ],
        // A source the core adds later: reported without a cell, tile or owner.
        #[allow(unreachable_patterns)]
        _ => [
            ("cell", JsValue::NULL),
            ("tile", JsValue::NULL),
            ("owner", JsValue::NULL),
            ("velocity", pair(Vec2::ZERO)),
        ],
    }
}
