//! `TileMap` for JavaScript: loading (ASCII, Tiled, baked, Replica Island), editing and ray
//! casts. Values are converted here; what they mean is in [`crate::rays`] and the core.

use std::sync::Arc;

use js_sys::{Array, Float32Array, Object, Reflect};
use tileslide::io::{ascii, baked, replica, tiled};
use tileslide::{Cell, QueryFilter, RayHit, TileId, Vec2};
use wasm_bindgen::prelude::*;

use crate::args::{self, error};
use crate::rays::{self, RayOptions};

#[wasm_bindgen(typescript_custom_section)]
const TS_TYPES: &str = r#"
/** A ray's nearest hit: `t` along the ray, the point, the unit normal, and the cell and
 * tile hit (`null` for a temporary segment). */
export interface RayHit {
    t: number;
    x: number;
    y: number;
    nx: number;
    ny: number;
    cell: [number, number] | null;
    tile: number | null;
}

/** Which faces a ray hits: front faces only (the default), both sides, or only faces
 * opposing a direction. */
export interface RayOptions {
    bothSides?: boolean;
    against?: [number, number];
}
"#;

/// A tile map: tiles of segments with seams culled, ready for queries.
#[wasm_bindgen]
pub struct TileMap {
    pub(crate) map: tileslide::TileMap,
}

impl TileMap {
    /// The core's map.
    pub(crate) fn inner(&self) -> &tileslide::TileMap {
        &self.map
    }

    /// The core's map, to edit.
    pub(crate) fn inner_mut(&mut self) -> &mut tileslide::TileMap {
        &mut self.map
    }
}

#[wasm_bindgen]
impl TileMap {
    /// The map drawn in ASCII (`#` solid, `/` and `\` ramps, `=` one-way platform, `.`
    /// empty; row 0 is the first line), with square cells of `cellSize` units (1 by
    /// default).
    #[wasm_bindgen(js_name = fromAscii)]
    pub fn from_ascii(text: &str, cell_size: Option<f32>) -> Result<TileMap, JsError> {
        let map = ascii::parse(text, "map.txt", cell_size.unwrap_or(1.0)).map_err(error)?;
        Ok(Self { map })
    }

    /// A Tiled map from its `.tmj` (JSON) or `.tmx` (XML) text, told apart by the text
    /// itself; `name` names it in errors. `files` gives its external tile sets (`.tsj`,
    /// `.tsx`) and templates by the name the map writes them with: an object or a `Map` of
    /// names to text or `Uint8Array`s.
    #[wasm_bindgen(js_name = fromTiled)]
    pub fn from_tiled(text: &str, name: &str, files: Option<JsValue>) -> Result<TileMap, JsError> {
        let mut options = tiled::TiledOptions::default();
        for (file, bytes) in external_files(files)? {
            options = options.with_file(file, bytes);
        }
        let level = if text.trim_start().starts_with('<') {
            tiled::parse_tmx(text, name, &options)
        } else {
            tiled::parse_tmj(text, name, &options)
        }
        .map_err(error)?;
        Ok(Self { map: level.map })
    }

    /// A map baked by `tileslide bake` (a `.tsm` file's bytes).
    #[wasm_bindgen(js_name = fromBaked)]
    pub fn from_baked(bytes: &[u8]) -> Result<TileMap, JsError> {
        let map = baked::parse(bytes, "map.tsm").map_err(error)?;
        Ok(Self { map })
    }

    /// A Replica Island level: the level file's bytes and the game's `collision.bin`.
    #[wasm_bindgen(js_name = fromReplicaIsland)]
    pub fn from_replica_island(level: &[u8], tile_set: &[u8]) -> Result<TileMap, JsError> {
        let tiles = replica::parse_tile_set(tile_set, "collision.bin").map_err(error)?;
        let map = replica::parse_level(level, "level.bin", Arc::new(tiles)).map_err(error)?;
        Ok(Self { map })
    }

    /// The map in tileslide's baked format (a `.tsm` file's bytes), which
    /// [`fromBaked`](Self::from_baked) reads back bit for bit.
    #[wasm_bindgen(js_name = toBaked)]
    pub fn to_baked(&self) -> Vec<u8> {
        baked::to_bytes(&self.map)
    }

    /// Columns.
    #[wasm_bindgen(getter)]
    pub fn width(&self) -> u32 {
        self.map.width()
    }

    /// Rows.
    #[wasm_bindgen(getter)]
    pub fn height(&self) -> u32 {
        self.map.height()
    }

    /// Puts tile `id` in cell (`col`, `row`), or empties it for `null`; the seams around
    /// it are culled again.
    #[wasm_bindgen(js_name = setTile)]
    pub fn set_tile(&mut self, col: f64, row: f64, id: Option<f64>) -> Result<(), JsError> {
        let cell = Cell::new(whole("setTile: col", col)?, whole("setTile: row", row)?);
        let id = id.map(|id| whole("setTile: id", id)).transpose()?;
        self.map.set_tile(cell, id.map(TileId)).map_err(error)
    }

    /// The nearest hit of the ray from (`x0`, `y0`) to (`x1`, `y1`), or `null`:
    /// `{t, x, y, nx, ny, cell: [col, row], tile}` (`cell` and `tile` are `null` for a
    /// temporary segment). `options`: `{bothSides: true}` or `{against: [dx, dy]}`.
    #[wasm_bindgen(js_name = castRay, unchecked_return_type = "RayHit | null")]
    pub fn cast_ray(
        &self,
        x0: f32,
        y0: f32,
        x1: f32,
        y1: f32,
        options: Option<Object>,
    ) -> Result<JsValue, JsError> {
        let filter = filter(options.as_ref())?;
        let ray = rays::ray("castRay", x0, y0, x1, y1).map_err(error)?;
        match self.map.cast_ray(ray, &filter) {
            Some(hit) => Ok(hit_object(&hit)?.into()),
            None => Ok(JsValue::NULL),
        }
    }

    /// Many rays at once: `rays` holds 4 floats a ray (`x0, y0, x1, y1`); the answer 5 a
    /// ray (`t, x, y, nx, ny`), all NaN for a miss. Each answer is `castRay`'s.
    #[wasm_bindgen(js_name = castRays)]
    pub fn cast_rays(
        &self,
        rays: &[f32],
        options: Option<Object>,
    ) -> Result<Float32Array, JsError> {
        let filter = filter(options.as_ref())?;
        let out = rays::cast_flat(&self.map, rays, &filter).map_err(error)?;
        Ok(Float32Array::from(out.as_slice()))
    }
}

/// `value` as a whole number from 0 to `u32::MAX` ([`args::whole`]), or an `Error`.
fn whole(what: &str, value: f64) -> Result<u32, JsError> {
    args::whole(what, value).map_err(error)
}

/// The `(name, bytes)` of `fromTiled`'s `files`: an object or a `Map` of names to text or
/// `Uint8Array`s (`undefined` or `null`: none).
fn external_files(files: Option<JsValue>) -> Result<Vec<(String, Vec<u8>)>, JsError> {
    let Some(files) = files.filter(|f| !f.is_undefined() && !f.is_null()) else {
        return Ok(Vec::new());
    };
    let entries: Array = if let Some(map) = files.dyn_ref::<js_sys::Map>() {
        Array::from(&map.entries())
    } else if files.is_object() {
        Object::entries(files.unchecked_ref())
    } else {
        return Err(error(
            "fromTiled: `files` must be an object or a Map of names to text or Uint8Arrays",
        ));
    };
    entries
        .iter()
        .map(|entry| {
            let pair = Array::from(&entry);
            let name = pair
                .get(0)
                .as_string()
                .ok_or_else(|| error("fromTiled: every name in `files` must be a string"))?;
            let value = pair.get(1);
            let bytes = if let Some(text) = value.as_string() {
                text.into_bytes()
            } else if let Some(array) = value.dyn_ref::<js_sys::Uint8Array>() {
                array.to_vec()
            } else {
                return Err(error(format!(
                    "fromTiled: files[\"{name}\"] must be text or a Uint8Array"
                )));
            };
            Ok((name, bytes))
        })
        .collect()
}

/// The query filter an options object asks for (`undefined` or `null`: front faces).
fn filter(options: Option<&Object>) -> Result<QueryFilter, JsError> {
    let Some(options) = options else {
        return Ok(QueryFilter::default());
    };
    let get =
        |key: &str| Reflect::get(options, &JsValue::from_str(key)).unwrap_or(JsValue::UNDEFINED);
    let both = get("bothSides");
    let both_sides = match both.as_bool() {
        Some(b) => b,
        None if both.is_undefined() || both.is_null() => false,
        None => return Err(error("ray options: `bothSides` must be true or false")),
    };
    let against = get("against");
    let against = if against.is_undefined() || against.is_null() {
        None
    } else {
        let pair = Array::from(&against);
        let x = pair.get(0).as_f64();
        let y = pair.get(1).as_f64();
        match (Array::is_array(&against) && pair.length() == 2, x, y) {
            (true, Some(x), Some(y)) => Some(Vec2::new(x as f32, y as f32)),
            _ => {
                return Err(error(
                    "ray options: `against` must be an array [dx, dy] of two numbers",
                ));
            }
        }
    };
    RayOptions {
        both_sides,
        against,
    }
    .filter()
    .map_err(error)
}

/// `{t, x, y, nx, ny, cell, tile}` for a hit.
fn hit_object(hit: &RayHit) -> Result<Object, JsError> {
    let object = Object::new();
    let set = |key: &str, value: JsValue| {
        Reflect::set(&object, &JsValue::from_str(key), &value)
            .map(|_| ())
            .map_err(|_| error("castRay: could not build the hit object"))
    };
    set("t", hit.t.into())?;
    set("x", hit.point.x.into())?;
    set("y", hit.point.y.into())?;
    set("nx", hit.normal.x.into())?;
    set("ny", hit.normal.y.into())?;
    let cell = hit.cell().map_or(JsValue::NULL, |c| {
        Array::of2(&c.col.into(), &c.row.into()).into()
    });
    set("cell", cell)?;
    set("tile", hit.tile().map_or(JsValue::NULL, |t| t.0.into()))?;
    Ok(object)
}
