//! Temporary segments of a `TileMap` for JavaScript: doors and moving platforms that every
//! query, body and character sees until cleared.

use tileslide::{Owner, Segment, SegmentFlags, TemporarySegment, Vec2};
use wasm_bindgen::prelude::*;

use crate::args::{self, Options, error};
use crate::map::TileMap;

#[wasm_bindgen(typescript_custom_section)]
const TS_TYPES: &str = r#"
/** What a temporary segment is besides its ends and normal. */
export interface TemporaryOptions {
    /** Segment flags (default 1: solid; 2: one-way platform). */
    flags?: number;
    /** Who submitted it (default 0): `clearTemporariesOf(owner)` clears its segments. */
    owner?: number;
    /** How fast it moves, `[vx, vy]` (default `[0, 0]`): a character standing on it rides
     * it. */
    velocity?: [number, number];
}
"#;

#[wasm_bindgen]
impl TileMap {
    /// Adds a temporary segment from (`x0`, `y0`) to (`x1`, `y1`) facing (`nx`, `ny`)
    /// (normalised): a door or a moving platform, seen by every query until cleared.
    #[wasm_bindgen(js_name = addTemporary)]
    #[allow(clippy::too_many_arguments)]
    pub fn add_temporary(
        &mut self,
        x0: f64,
        y0: f64,
        x1: f64,
        y1: f64,
        nx: f64,
        ny: f64,
        #[wasm_bindgen(unchecked_optional_param_type = "TemporaryOptions")] options: Option<
            JsValue,
        >,
    ) -> Result<(), JsError> {
        let a = args::vec2("addTemporary: start", x0, y0).map_err(error)?;
        let b = args::vec2("addTemporary: end", x1, y1).map_err(error)?;
        let normal = args::vec2("addTemporary: normal", nx, ny).map_err(error)?;
        let mut o = Options::new("addTemporary: options", options).map_err(error)?;
        let flags = o.flags_or("flags", SegmentFlags::SOLID).map_err(error)?;
        let owner = o.owner_or("owner", Owner(0)).map_err(error)?;
        let velocity = o.pair("velocity").map_err(error)?.unwrap_or(Vec2::ZERO);
        o.finish().map_err(error)?;
        self.inner_mut()
            .add_temporary(TemporarySegment {
                segment: Segment::new(a, b),
                normal,
                flags,
                owner,
                velocity,
            })
            .map_err(error)
    }

    /// Removes every temporary segment.
    #[wasm_bindgen(js_name = clearTemporaries)]
    pub fn clear_temporaries(&mut self) {
        self.inner_mut().clear_temporaries();
    }

    /// Removes the temporary segments of `owner`.
    #[wasm_bindgen(js_name = clearTemporariesOf)]
    pub fn clear_temporaries_of(&mut self, owner: f64) -> Result<(), JsError> {
        let owner = args::owner("clearTemporariesOf: owner", owner).map_err(error)?;
        self.inner_mut().clear_temporaries_of(owner);
        Ok(())
    }

    /// Number of temporary segments.
    #[wasm_bindgen(getter, js_name = temporaryCount)]
    pub fn temporary_count(&self) -> usize {
        self.inner().temporaries().len()
    }
}
