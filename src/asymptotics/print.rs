//! Machine-readable and paper forms of the derived series ([`super::catalog::Derived`]): SymPy,
//! Mathematica and LaTeX (docs/theory.md section 16). The plain text form stays the engine's own
//! (`Frac::text`); the others are rendered from it or from the exact coefficients:
//!
//! - SymPy: `^` becomes `**`, and the names that SymPy's `sympify` reads as something else get a
//!   trailing underscore ([`SYMPY_RENAMED`]: `S` is SymPy's singleton registry, `Lambda` its
//!   lambda class, `lambda` a Python keyword, ...), so `sympify(text)` reads the output back.
//! - Mathematica: underscores dropped from names (`_` is a pattern there): `rho_4` -> `rho4`.
//! - LaTeX: one equation per object, `LHS &= c_0 + c_1 v + ... + O(v^{N+1})`, each coefficient
//!   a single fraction of polynomials with integer coefficients (no nested `\frac`).

use super::catalog::Derived;
use exact_series::{Frac, Poly, Ring, Q};
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

/// Names that `sympy.sympify` does not read as a plain symbol of the same name; printed with a
/// trailing underscore (`S` -> `S_`). `tests/all/sympy_roundtrip.rs` checks every printed name.
pub const SYMPY_RENAMED: [&str; 12] = ["S", "Lambda", "lambda", "E", "I", "N", "O", "Q", "beta", "gamma", "pi", "zeta"];

/// Applies `rename` to every identifier of an expression in the engine's text form.
fn map_identifiers(text: &str, rename: impl Fn(&str) -> String) -> String {
    let mut out = String::with_capacity(text.len() + 8);
    let mut word = String::new();
    let flush = |word: &mut String, out: &mut String| {
        if word.starts_with(|c: char| c.is_ascii_alphabetic()) {
            out.push_str(&rename(word));
        } else {
            out.push_str(word);
        }
        word.clear();
    };
    for c in text.chars() {
        if c.is_ascii_alphanumeric() || c == '_' {
            word.push(c);
        } else {
            flush(&mut word, &mut out);
            out.push(c);
        }
    }
    flush(&mut word, &mut out);
    out
}

/// A name as SymPy's `sympify` must see it.
pub(crate) fn sympy_name(name: &str) -> String {
    if SYMPY_RENAMED.contains(&name) {
        format!("{name}_")
    } else {
        name.to_string()
    }
}

/// A name as Mathematica must see it (no underscores).
pub(crate) fn mathematica_name(name: &str) -> String {
    name.replace('_', "")
}

/// An expression in the engine's text form, as SymPy reads it.
pub(crate) fn sympy_text(text: &str) -> String {
    map_identifiers(text, sympy_name).replace('^', "**")
}

/// An expression in the engine's text form, as Mathematica reads it.
pub(crate) fn mathematica_text(text: &str) -> String {
    map_identifiers(text, mathematica_name)
}

/// lcm of the denominators and gcd of the numerators of a polynomial's coefficients.
fn content(p: &Poly, lcm: &mut num_bigint::BigInt, gcd: &mut num_bigint::BigInt) {
    for (_, q) in p.terms() {
        *lcm = lcm.lcm(q.denom());
        *gcd = gcd.gcd(q.numer());
    }
}

/// A coefficient as a paper prints it: a polynomial with rational coefficients when the
/// denominator is a constant; else one fraction of two polynomials with coprime integer
/// coefficients, the sign in front.
pub(crate) fn coefficient_latex(c: &Frac) -> String {
    let (num, den) = (c.numer(), c.denom());
    if let Some(d) = den.as_q() {
        return num.scale(&d.recip()).latex();
    }
    let (mut lcm, mut gcd) = (num_bigint::BigInt::one(), num_bigint::BigInt::zero());
    content(num, &mut lcm, &mut gcd);
    content(den, &mut lcm, &mut gcd);
    // Scale both by lcm/gcd' where gcd' is the gcd of the scaled numerators.
    let scaled = |p: &Poly| p.scale(&Q::from_integer(lcm.clone()));
    let (n1, d1) = (scaled(num), scaled(den));
    let mut g = num_bigint::BigInt::zero();
    for p in [&n1, &d1] {
        for (_, q) in p.terms() {
            g = g.gcd(q.numer());
        }
    }
    let mut f = Q::new(num_bigint::BigInt::one(), if g.is_zero() { num_bigint::BigInt::one() } else { g });
    // Denominator's leading coefficient positive.
    if den.leading_coefficient_lex().is_negative() {
        f = -f;
    }
    let (n2, d2) = (n1.scale(&f), d1.scale(&f));
    let negative =
        n2.as_q().is_some_and(|q| q.is_negative()) || (!n2.is_sum() && n2.leading_coefficient_lex().is_negative());
    if negative {
        format!("-\\frac{{{}}}{{{}}}", n2.scale(&-<Q as One>::one()).latex(), d2.latex())
    } else {
        format!("\\frac{{{}}}{{{}}}", n2.latex(), d2.latex())
    }
}

/// One term `c v^k` of a series in LaTeX, with its sign as a separate `+`/`-` (first term: no
/// `+`). Sums in parentheses.
pub(crate) fn term_latex(c: &Frac, var: &str, k: usize, first: bool) -> String {
    let power = match k {
        0 => String::new(),
        1 => var.to_string(),
        _ => format!("{var}^{{{k}}}"),
    };
    let mut body = coefficient_latex(c);
    let mut sign = "+";
    if c.numer().is_sum() && c.denom().as_q().is_some() && k > 0 {
        body = format!("\\left({body}\\right)");
    } else if let Some(rest) = body.strip_prefix('-') {
        sign = "-";
        body = rest.trim_start().to_string();
    }
    if k > 0 && body == "1" {
        body.clear();
    }
    let sep = if body.is_empty() || power.is_empty() { "" } else { " " };
    let t = format!("{body}{sep}{power}");
    match (first, sign) {
        (true, "+") => t,
        (true, _) => format!("-{t}"),
        (false, s) => format!("{s} {t}"),
    }
}

/// The left-hand side of an object's equation in LaTeX.
fn lhs(object: &str) -> &'static str {
    match object {
        "kernel" => "Z(z)",
        "weight" => r"Y(\hat{x}; \lambda)",
        "l_over_ls" => "l/l_s",
        "rbar_minus_rbar_s" => r"\bar{r} - \bar{r}_s",
        "F_def_over_F_def_s" => r"F_{\mathrm{def}}/F_{\mathrm{def},s}",
        "F_def_scaled" => r"\tilde{F}_{\mathrm{def}}",
        "pressure_pi" => r"p/(E^* k l \cos(\pi\theta)\,\omega(\hat{x})) - 1",
        "pressure_B" => r"p/(E^* c_r l^{r-1} \cos(\pi\theta)\,\omega(\hat{x}))",
        "Tb_single" => r"\bar{T}_s",
        "m0s_single" => "m_{0s}",
        "Delta" => r"\Delta",
        "C_P_over_pi" => r"C_P/\pi",
        "load_c" => r"P_2/(C_P E^* k a^2)",
        "slope_A" => r"\hat{\psi}(\chi)",
        "load_P_over_pi" => r"P(\lambda)/\pi",
        _ => r"\mathrm{?}",
    }
}

/// Whether the object is a plain sequence (printed as a list, not a series).
fn is_sequence(d: &Derived) -> bool {
    d.object == "jacobi"
}

/// The truncation order N (every term through v^N kept); 0 for a single exact value.
fn order(d: &Derived) -> usize {
    d.series.order().unwrap_or(0)
}

impl Derived {
    /// The object as one SymPy expression (`sympify` reads it back): the series with `+ O(v**(N+1))`
    /// (none for a single exact value), or a list for a sequence.
    pub fn sympy(&self) -> String {
        let v = sympy_name(self.variable);
        let coeffs = self.series.coeffs();
        if is_sequence(self) {
            let items: Vec<String> = coeffs.iter().map(|c| sympy_text(&c.text())).collect();
            return format!("[{}]", items.join(", "));
        }
        let mut terms: Vec<String> = coeffs
            .iter()
            .enumerate()
            .filter(|(_, c)| !c.is_zero())
            .map(|(k, c)| {
                let c = sympy_text(&c.text());
                match k {
                    0 => format!("({c})"),
                    1 => format!("({c})*{v}"),
                    _ => format!("({c})*{v}**{k}"),
                }
            })
            .collect();
        if terms.is_empty() {
            terms.push("0".into());
        }
        let n = order(self);
        if n > 0 {
            terms.push(format!("O({v}**{})", n + 1));
        }
        terms.join(" + ")
    }

    /// The object as one Mathematica expression (`O[v]^(N+1)` makes it a series).
    pub fn mathematica(&self) -> String {
        let v = mathematica_name(self.variable);
        let coeffs = self.series.coeffs();
        if is_sequence(self) {
            let items: Vec<String> = coeffs.iter().map(|c| mathematica_text(&c.text())).collect();
            return format!("{{{}}}", items.join(", "));
        }
        let mut terms: Vec<String> = coeffs
            .iter()
            .enumerate()
            .filter(|(_, c)| !c.is_zero())
            .map(|(k, c)| format!("({})*{v}^{k}", mathematica_text(&c.text())))
            .collect();
        if terms.is_empty() {
            terms.push("0".into());
        }
        let n = order(self);
        if n > 0 {
            terms.push(format!("O[{v}]^{}", n + 1));
        }
        terms.join(" + ")
    }

    /// LaTeX as a paper prints it: `LHS &= c_0 + c_1 v + ... + O(v^{N+1})` in an `align*` block,
    /// short coefficients four terms a line, long ones one a line; a sequence one `j_{n} &= ...`
    /// row per index. Preceded by `%` comment lines (formula, source, notes).
    pub fn latex(&self) -> String {
        let mut s = format!("% {}: {} ({})\n", self.object, self.formula, self.source);
        for n in &self.notes {
            s.push_str(&format!("% {n}\n"));
        }
        s.push_str("\\begin{align*}\n");
        let coeffs = self.series.coeffs();
        if is_sequence(self) {
            let rows: Vec<String> = coeffs
                .iter()
                .enumerate()
                .filter(|(_, c)| !c.is_zero())
                .map(|(k, c)| format!("j_{{{k}}} &= {}", coefficient_latex(c)))
                .collect();
            s.push_str(&rows.join(" \\\\\n"));
            s.push_str("\n\\end{align*}\n");
            return s;
        }
        let v = exact_series::Symbol::new(self.variable).map_or_else(|_| self.variable.to_string(), |x| x.latex());
        let nonzero: Vec<(usize, &Frac)> = coeffs.iter().enumerate().filter(|(_, c)| !c.is_zero()).collect();
        let long = nonzero.iter().any(|(_, c)| c.numer().is_sum() || c.denom().as_q().is_none());
        let mut terms: Vec<String> =
            nonzero.iter().enumerate().map(|(i, (k, c))| term_latex(c, &v, *k, i == 0)).collect();
        if terms.is_empty() {
            terms.push("0".into());
        }
        let n = order(self);
        if n > 0 {
            terms.push(format!("+ O({v}^{{{}}})", n + 1));
        }
        let per_line = if long { 1 } else { 4 };
        let lines: Vec<String> = terms.chunks(per_line).map(|c| c.join(" ")).collect();
        s.push_str(&format!("{} &= {}", lhs(self.object), lines[0]));
        for l in &lines[1..] {
            s.push_str(&format!(" \\\\\n  &\\quad {l}"));
        }
        s.push_str("\n\\end{align*}\n");
        s
    }

    /// One part in the JSON schema of every series object (docs/theory.md section 16):
    /// `{"object", "formula", "source", "variable", "order", "symbols", ["notes"], "sympy",
    /// "mathematica", "coefficients": [{"power", "text", "latex", "sympy"}], ["nu", "values"]}`.
    pub fn json(&self) -> serde_json::Value {
        let coefficients: Vec<serde_json::Value> = self
            .series
            .coeffs()
            .iter()
            .enumerate()
            .filter(|(_, c)| !c.is_zero())
            .map(|(k, c)| {
                let t = c.text();
                serde_json::json!({"power": k, "text": t, "latex": coefficient_latex(c), "sympy": sympy_text(&t)})
            })
            .collect();
        let mut v = serde_json::json!({
            "object": self.object,
            "formula": self.formula,
            "source": self.source,
            "variable": self.variable,
            "order": order(self),
            "symbols": self.symbols.iter().map(|s| s.name()).collect::<Vec<_>>(),
        });
        if !self.notes.is_empty() {
            v["notes"] = serde_json::json!(self.notes);
        }
        v["sympy"] = serde_json::json!(self.sympy());
        v["mathematica"] = serde_json::json!(self.mathematica());
        v["coefficients"] = serde_json::Value::Array(coefficients);
        if let Some((nu, vals)) = &self.values {
            v["nu"] = serde_json::json!(nu);
            v["values"] = serde_json::Value::Array(
                vals.iter().map(|(k, x)| serde_json::json!({"power": k, "value": x})).collect(),
            );
        }
        v
    }
}

/// The whole `series` output in one format: text (the parts' text joined), LaTeX (the parts'
/// blocks), SymPy (a dict literal `{"part": expr, ...}` that `sympify` reads), Mathematica (an
/// association `<|"part" -> expr, ...|>`), JSON (`{"object", "parts": [part, ...]}`).
pub fn render(object: &str, parts: &[Derived], format: SeriesFormat) -> String {
    match format {
        SeriesFormat::Text => parts.iter().map(|d| d.text()).collect::<Vec<_>>().join("\n"),
        SeriesFormat::Latex => parts.iter().map(|d| d.latex()).collect::<Vec<_>>().join("\n"),
        SeriesFormat::Sympy => {
            let items: Vec<String> = parts.iter().map(|d| format!(" \"{}\": {}", d.object, d.sympy())).collect();
            format!("{{\n{}\n}}\n", items.join(",\n"))
        }
        SeriesFormat::Mathematica => {
            let items: Vec<String> =
                parts.iter().map(|d| format!(" \"{}\" -> {}", d.object, d.mathematica())).collect();
            format!("<|\n{}\n|>\n", items.join(",\n"))
        }
        SeriesFormat::Json => {
            let v = serde_json::json!({"object": object, "parts": parts.iter().map(Derived::json).collect::<Vec<_>>()});
            format!("{}\n", serde_json::to_string_pretty(&v).unwrap_or_default())
        }
    }
}

/// Output formats of `periodic-contact series`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SeriesFormat {
    /// The engine's text.
    Text,
    /// LaTeX `align*` blocks.
    Latex,
    /// A SymPy dict literal.
    Sympy,
    /// A Mathematica association.
    Mathematica,
    /// JSON.
    Json,
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frac(n: &str, d: &str) -> Frac {
        let p = |t: &str| -> Poly {
            // Tiny parser for the tests: sums of `q*sym` and `q` terms.
            let s = exact_series::Symbol::new("x").unwrap();
            t.split('+').fold(Poly::zero(), |acc, term| {
                let term = term.trim();
                let (q, sym) = term.split_once("*x").map_or((term, false), |(q, _)| (q, true));
                let q = exact_series::parse_rational(q).unwrap();
                let m = if sym { Poly::symbol(s) } else { Poly::one() };
                acc.add(&m.scale(&q))
            })
        };
        Frac::new(p(n), p(d)).unwrap()
    }

    #[test]
    fn sympy_names_are_renamed_and_powers_pythonic() {
        assert_eq!(sympy_text("(-1/4)/(S*eps - 1/2)"), "(-1/4)/(S_*eps - 1/2)");
        assert_eq!(sympy_text("Lambda^2*rho_4 + lambda"), "Lambda_**2*rho_4 + lambda_");
        assert_eq!(mathematica_text("rho_4*rbar_s^2"), "rho4*rbars^2");
    }

    #[test]
    fn no_nested_fractions() {
        // (-1/4)/(x - 1/2) = -1/(4 x - 2).
        assert_eq!(coefficient_latex(&frac("-1/4", "1*x + -1/2")), "-\\frac{1}{4 x - 2}");
        // (1/2 x + 1/3)/(x + 1) = (3 x + 2)/(6 x + 6).
        assert_eq!(coefficient_latex(&frac("1/2*x + 1/3", "1*x + 1")), "\\frac{3 x + 2}{6 x + 6}");
        assert_eq!(coefficient_latex(&frac("-1/3", "1")), "-\\frac{1}{3}");
    }

    #[test]
    fn terms_carry_their_sign() {
        assert_eq!(term_latex(&frac("-1/3", "1"), "z", 2, false), "- \\frac{1}{3} z^{2}");
        assert_eq!(term_latex(&frac("1", "1"), "z", 0, true), "1");
        assert_eq!(term_latex(&frac("1", "1"), "z", 1, false), "+ z");
        assert_eq!(term_latex(&frac("1*x + 1", "1"), "z", 2, false), "+ \\left(x + 1\\right) z^{2}");
    }
}

/// One part of an expansion computed numerically and verified by a second run (the loading
/// law's [`super::loading_law::LawSeries`] and the adhesion series' numerical route
/// [`super::adhesion_numeric::AdhesionNumeric`]): its name, formula in words, expansion variable and
/// non-zero coefficients (power, value, verified digits).
pub(crate) struct VerifiedPart<'a> {
    pub(crate) object: &'a str,
    pub(crate) formula: &'a str,
    pub(crate) variable: &'a str,
    pub(crate) coefficients: &'a [(usize, rug::Float, f64)],
}

impl VerifiedPart<'_> {
    /// A value with its verified digits (at most `asked`), on the scale of its own magnitude.
    fn value_text(v: &rug::Float, digits: f64, asked: u32) -> String {
        let scale = rug::Float::with_val(v.prec(), v.abs_ref());
        crate::numerics::accuracy::print_mpfr(v, &scale, digits, asked)
    }

    /// `part:`, `formula:`, `variable` lines, then `[var^k] value` per coefficient.
    pub(crate) fn text(&self, asked: u32) -> String {
        let mut s = format!("\npart: {}\nformula: {}\nvariable {}\n", self.object, self.formula, self.variable);
        for (k, v, d) in self.coefficients {
            s.push_str(&format!("[{}^{k}] {}\n", self.variable, Self::value_text(v, *d, asked)));
        }
        s
    }

    /// `{"object", "formula", "variable", "coefficients": [{"power", "value", "digits"}]}` (values
    /// as strings, digits to 0.1).
    pub(crate) fn json(&self, asked: u32) -> serde_json::Value {
        serde_json::json!({
            "object": self.object,
            "formula": self.formula,
            "variable": self.variable,
            "coefficients": self.coefficients.iter().map(|(k, v, d)| serde_json::json!({
                "power": k,
                "value": Self::value_text(v, *d, asked),
                "digits": (d * 10.0).round() / 10.0,
            })).collect::<Vec<_>>(),
        })
    }
}
