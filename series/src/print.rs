//! Printing of series: plain text, LaTeX and JSON, all from the canonical coefficient forms, so
//! that the output is byte-stable (snapshot tests rely on it).

use crate::{Ring, Series, Symbol};
use serde_json::{json, Value};

fn power_text(var: &str, k: usize) -> String {
    match k {
        0 => String::new(),
        1 => var.to_string(),
        _ => format!("{var}^{k}"),
    }
}

fn power_latex(var: &str, k: usize) -> String {
    match k {
        0 => String::new(),
        1 => var.to_string(),
        _ => format!("{var}^{{{k}}}"),
    }
}

/// Joins signed terms: the first keeps its sign, later ones are joined with " + " / " - ".
fn join_terms(terms: Vec<(bool, String)>) -> String {
    let mut s = String::new();
    for (i, (neg, t)) in terms.into_iter().enumerate() {
        if i == 0 {
            if neg {
                s.push('-');
            }
        } else {
            s.push_str(if neg { " - " } else { " + " });
        }
        s.push_str(&t);
    }
    s
}

/// Splits a coefficient's printed form into (negative, magnitude) when it is a single term.
fn signed<R: Ring>(c: &R, printed: String) -> (bool, String) {
    if !c.is_sum() {
        if let Some(rest) = printed.strip_prefix('-') {
            return (true, rest.to_string());
        }
    }
    (false, printed)
}

impl<R: Ring> Series<R> {
    /// Plain text: `1 + (-1/6*theta - 1/12)*x^2 + O(x^4)`.
    pub fn text(&self, var: &str) -> String {
        let mut terms = Vec::new();
        for (k, c) in self.coeffs.iter().enumerate() {
            if c.is_zero() {
                continue;
            }
            let (neg, mag) = signed(c, c.text());
            let t = if k == 0 {
                mag
            } else if mag == "1" {
                power_text(var, k)
            } else if c.is_sum() {
                format!("({mag})*{}", power_text(var, k))
            } else {
                format!("{mag}*{}", power_text(var, k))
            };
            terms.push((neg, t));
        }
        terms.push((false, format!("O({})", power_text(var, self.prec()).replace("^0", "")).replace("O()", "O(1)")));
        join_terms(terms)
    }

    /// LaTeX: `1 + \left(-\frac{1}{6} \theta - \frac{1}{12}\right) x^{2} + O(x^{4})`.
    pub fn latex(&self, var: &str) -> String {
        let mut terms = Vec::new();
        for (k, c) in self.coeffs.iter().enumerate() {
            if c.is_zero() {
                continue;
            }
            let (neg, mag) = signed(c, c.latex());
            let t = if k == 0 {
                mag
            } else if mag == "1" {
                power_latex(var, k)
            } else if c.is_sum() {
                format!("\\left({mag}\\right) {}", power_latex(var, k))
            } else {
                format!("{mag} {}", power_latex(var, k))
            };
            terms.push((neg, t));
        }
        let o = if self.prec() == 0 { "O(1)".to_string() } else { format!("O({})", power_latex(var, self.prec())) };
        terms.push((false, o));
        join_terms(terms)
    }

    /// JSON: `{"object", "variable", "order", "symbols", "coefficients": [{"power", "text",
    /// "latex"}]}`. `order` is the highest power kept (`prec - 1`, THEORY.md section 5); only
    /// non-zero coefficients are listed (a power up to `order` that is absent is exactly zero);
    /// `symbols` are the names the coefficients use, sorted.
    pub fn to_json(&self, object: &str, var: &str, symbols: &[Symbol]) -> Value {
        let coefficients: Vec<Value> = self
            .coeffs
            .iter()
            .enumerate()
            .filter(|(_, c)| !c.is_zero())
            .map(|(k, c)| json!({"power": k, "text": c.text(), "latex": c.latex()}))
            .collect();
        let mut syms: Vec<&str> = symbols.iter().map(|s| s.name()).collect();
        syms.sort_unstable();
        syms.dedup();
        json!({
            "object": object,
            "variable": var,
            "order": self.order(),
            "symbols": syms,
            "coefficients": coefficients,
        })
    }
}
