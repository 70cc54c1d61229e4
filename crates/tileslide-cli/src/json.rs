//! JSON output helpers.

use serde_json::Value;

/// An `f32` as a JSON number written with the shortest digits that read back as the same
/// `f32` (`0.68`, not the `0.6800000071525574` of widening to `f64` first). `-0` is written
/// as `0`; non-finite values (which no command produces) as `null`.
pub fn number(v: f32) -> Value {
    if !v.is_finite() {
        return Value::Null;
    }
    let v = if v == 0.0 { 0.0 } else { v };
    v.to_string()
        .parse::<f64>()
        .map_or(Value::Null, Value::from)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_keep_their_f32_digits() {
        assert_eq!(number(0.68).to_string(), "0.68");
        assert_eq!(number(-0.0).to_string(), "0.0");
        assert_eq!(number(176.0).to_string(), "176.0");
        assert_eq!(number(f32::NAN), Value::Null);
    }
}
