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
    if !c.is_sum()
        && let Some(rest) = printed.strip_prefix('-')
    {
        return (true, rest.to_string());
    }
    (false, printed)
}

impl<R: Ring> Series<R> {
    /// Plain text: `1 + (-1/6*theta - 1/12)*x^2 + O(x^4)`.
    pub fn text(&self, var: &str) -> String {
        self.render(var, R::text, power_text, |m| format!("({m})"), "*")
    }

    /// LaTeX: `1 + \left(-\frac{1}{6} \theta - \frac{1}{12}\right) x^{2} + O(x^{4})`.
    pub fn latex(&self, var: &str) -> String {
        self.render(var, R::latex, power_latex, |m| format!("\\left({m}\\right)"), " ")
    }

    /// The non-zero terms `c<sep>x^k` (a sum coefficient wrapped by `wrap`, a unit one omitted),
    /// signs pulled out as " + " / " - ", then the order term `O(x^prec)`.
    fn render(
        &self,
        var: &str,
        coeff: fn(&R) -> String,
        power: fn(&str, usize) -> String,
        wrap: fn(&str) -> String,
        sep: &str,
    ) -> String {
        let mut terms = Vec::new();
        for (k, c) in self.coeffs.iter().enumerate() {
            if c.is_zero() {
                continue;
            }
            let (neg, mag) = signed(c, coeff(c));
            let t = if k == 0 {
                mag
            } else if mag == "1" {
                power(var, k)
            } else if c.is_sum() {
                format!("{}{sep}{}", wrap(&mag), power(var, k))
            } else {
                format!("{mag}{sep}{}", power(var, k))
            };
            terms.push((neg, t));
        }
        let o = if self.prec() == 0 { "O(1)".to_string() } else { format!("O({})", power(var, self.prec())) };
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
