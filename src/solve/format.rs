//! Plain-text rendering of a solve result (the JSON's keys and strings, one per line).

use serde_json::Value;

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
