//! Checks of what JavaScript passes in: numbers are floats there, so whole numbers, seeds
//! and step counts are checked here and refused with an error naming the argument, never
//! wrapped or truncated into another value.

use std::fmt::Display;

use wasm_bindgen::prelude::*;

/// The most steps one `step` call runs: an hour of game time at 30 steps a second.
pub const MAX_STEPS_PER_CALL: u32 = 108_000;

/// A JavaScript `Error` whose message is `message`.
pub fn error(message: impl Display) -> JsError {
    JsError::new(&message.to_string())
}

/// `value` as a whole number from 0 to `max`, or `None`.
#[must_use]
pub fn whole_number(value: f64, max: u32) -> Option<u32> {
    (value.fract() == 0.0 && (0.0..=f64::from(max)).contains(&value)).then_some(value as u32)
}

/// `value` as a whole number from 0 to `max`, or an error naming it (`what`).
pub fn whole(what: &str, value: f64, max: u32) -> Result<u32, JsError> {
    whole_number(value, max).ok_or_else(|| {
        error(format!(
            "{what} is {value}, not a whole number from 0 to {max}"
        ))
    })
}

/// How many steps a `step(n)` call runs: 1 when `n` is `undefined`.
pub fn step_count(what: &str, n: Option<f64>) -> Result<u32, JsError> {
    n.map_or(Ok(1), |n| whole(what, n, MAX_STEPS_PER_CALL))
}

/// A seed: a whole `number` from 0 to 2⁵³ − 1, or a `BigInt` from 0 to 2⁶⁴ − 1.
pub fn seed(value: &JsValue) -> Result<u64, JsError> {
    /// The largest whole number a JavaScript number holds exactly.
    const MAX_SAFE: f64 = 9_007_199_254_740_991.0;
    if let Some(n) = value.as_f64() {
        if n.fract() == 0.0 && (0.0..=MAX_SAFE).contains(&n) {
            return Ok(n as u64);
        }
    } else if value.is_bigint()
        && let Ok(n) = u64::try_from(value.clone())
    {
        return Ok(n);
    }
    Err(error(format!(
        "the seed is {value:?}, not a whole number from 0 to 2^53 - 1 or a BigInt from 0 to \
         2^64 - 1"
    )))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn whole_numbers_are_whole_and_in_range() {
        assert_eq!(whole_number(3.0, 10), Some(3));
        assert_eq!(whole_number(0.0, 10), Some(0));
        assert_eq!(whole_number(10.0, 10), Some(10));
        for bad in [-1.0, 3.5, 11.0, f64::NAN, f64::INFINITY, -0.5] {
            assert_eq!(whole_number(bad, 10), None, "{bad}");
        }
    }
}
