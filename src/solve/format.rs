//! Number formatting that never shows more digits than were verified.

use rug::Float;
use serde_json::{Map, Value};

/// Significant digits of `value` that are covered by `digits_verified` digits relative to `scale`
/// (|error| <= 10^-d * scale), capped at `requested` and at least 1:
/// `floor(d - log10(scale / |value|))`.
pub fn digits_in_value(value: &Float, scale: &Float, digits_verified: f64, requested: u32) -> usize {
    if value.is_zero() || scale.is_zero() || !digits_verified.is_finite() {
        return (requested as usize).max(1);
    }
    let ratio = Float::with_val(64, scale / value.clone()).abs();
    let extra = ratio.log10().to_f64().max(0.0);
    ((digits_verified - extra).floor() as i64).clamp(1, requested as i64) as usize
}

/// `value` with `sig` significant digits (scientific notation, e.g. `3.3333e-1`).
pub fn fmt_float(value: &Float, sig: usize) -> String {
    if value.is_zero() {
        return "0".to_string();
    }
    value.to_string_radix(10, Some(sig.max(1)))
}

/// An `f64` with `sig` significant digits.
pub fn fmt_f64(value: f64, sig: usize) -> String {
    if value == 0.0 {
        return "0".to_string();
    }
    format!("{:.*e}", sig.max(1) - 1, value)
}

/// Per-quantity verified digits, in the order given.
#[derive(Debug, Clone, Default)]
pub struct AccuracyTable(Vec<(String, f64)>);

impl AccuracyTable {
    /// From `(name, digits)` pairs.
    pub fn from_pairs(pairs: &[(String, f64)]) -> Self {
        AccuracyTable(pairs.to_vec())
    }
    /// Digits of `name`.
    pub fn get(&self, name: &str) -> Option<f64> {
        self.0.iter().find(|(n, _)| n == name).map(|(_, d)| *d)
    }
    /// `{"a": "41.2", ...}`.
    pub fn to_json(&self) -> Value {
        let mut m = Map::new();
        for (n, d) in &self.0 {
            m.insert(n.clone(), Value::String(format!("{d:.1}")));
        }
        Value::Object(m)
    }
}

/// Plain-text rendering of a solve result: `key: value` lines, nested keys joined by dots.
pub fn text(v: &Value) -> String {
    fn walk(prefix: &str, v: &Value, out: &mut String) {
        match v {
            Value::Object(m) => {
                for (k, x) in m {
                    let p = if prefix.is_empty() { k.clone() } else { format!("{prefix}.{k}") };
                    walk(&p, x, out);
                }
            }
            Value::Array(a) => {
                for (i, x) in a.iter().enumerate() {
                    walk(&format!("{prefix}[{i}]"), x, out);
                }
            }
            Value::String(s) => out.push_str(&format!("{prefix}: {s}\n")),
            Value::Null => out.push_str(&format!("{prefix}: (none)\n")),
            other => out.push_str(&format!("{prefix}: {other}\n")),
        }
    }
    let mut out = String::new();
    walk("", v, &mut out);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn digits_shrink_when_the_value_is_small_against_its_scale() {
        let v = Float::with_val(128, 1e-5);
        let scale = Float::with_val(128, 1.0);
        assert_eq!(digits_in_value(&v, &scale, 30.0, 40), 25);
        assert_eq!(digits_in_value(&scale, &scale, 30.4, 20), 20);
        assert_eq!(digits_in_value(&v, &scale, 3.0, 20), 1);
        assert_eq!(fmt_float(&Float::with_val(128, 0.25), 3), "2.50e-1");
        assert_eq!(fmt_f64(0.25, 3), "2.50e-1");
    }
}
