//! What the C API's tests share: the last error as a Rust string, and maps made from ASCII
//! through the C API.

#![allow(dead_code, clippy::unwrap_used)]

use std::ffi::{CStr, CString};
use std::ptr;

use tileslide_capi::*;

/// This thread's last error message.
pub fn last_error() -> String {
    // SAFETY: the library's own NUL-terminated message.
    unsafe { CStr::from_ptr(ts_last_error_message()) }
        .to_str()
        .unwrap()
        .to_owned()
}

/// The map of `text` (unit cells) through `ts_map_from_ascii`, for `ts_map_free`.
pub fn ascii_map(text: &str) -> *mut ts_map {
    let text = CString::new(text).unwrap();
    let mut map = ptr::null_mut();
    // SAFETY: a valid string and out pointer.
    assert_eq!(
        unsafe { ts_map_from_ascii(text.as_ptr(), 1.0, &mut map) },
        ts_status::TS_OK
    );
    map
}

/// The same map through the core, as `ts_map_from_ascii` parses it.
pub fn core_map(text: &str) -> tileslide::TileMap {
    tileslide::io::ascii::parse(text, "<ascii>", 1.0).unwrap()
}

/// The core's navigation grid of `map` for circles up to `max_radius`.
pub fn core_nav(map: &tileslide::TileMap, max_radius: f32) -> tileslide::NavGrid {
    let config = tileslide::NavConfig {
        max_radius,
        ..tileslide::NavConfig::default()
    };
    tileslide::NavGrid::new(map, config).unwrap()
}

/// Asserts that `status` is `expected` and the last error mentions `words`.
#[track_caller]
pub fn assert_refused(status: ts_status, expected: ts_status, words: &str) {
    assert_eq!(status, expected, "{}", last_error());
    let message = last_error();
    assert!(message.contains(words), "{message:?} lacks {words:?}");
}
