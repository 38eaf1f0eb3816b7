//! `series OBJECT --pade`: the near-diagonal Padé approximants [L/M] (L + M = the number of
//! coefficients in w minus one, |L - M| <= [`SPREAD`]) of each derived part, in w = var^2 for an
//! even series (the Problem 1 expansions in `paper`, the kernel, Problem 2's load), else in w =
//! var, with their poles (docs/theory.md section 11).
//!
//! A part is resummed when its coefficients are numbers: exact rationals (every symbol substituted,
//! e.g. `series sliding --theta 0 --T 0`), built exactly over Q by [`exact_series::Pade`]; or,
//! for Problem 2 at `--nu`, the printed 30-digit values read back as exact decimals (the
//! approximant is then the exact one of those rounded values: its coefficients carry their
//! 30 digits at best). A part with symbols left says which.

use super::catalog::{Derived, VALUE_DIGITS};
use crate::numerics::pade::{complex_text, polynomial_roots, SPREAD};
use exact_series::{parse_rational, q_text, Pade, Ring, Series, Q};

/// Numbers of a part: the exact coefficients, else the values at nu (30 digits); with a word
/// on where they come from. `Err` names the symbols left.
fn numbers(d: &Derived) -> Result<(Vec<Q>, String), String> {
    let exact: Option<Vec<Q>> = d.series.coeffs().iter().map(|c| Some(c.numer().as_q()? / c.denom().as_q()?)).collect();
    if let Some(c) = exact {
        return Ok((c, "exact".into()));
    }
    if let Some((nu, values)) = &d.values {
        let mut c = vec![Q::from_integer(0.into()); d.series.prec()];
        for (k, v) in values {
            c[*k] = parse_rational(v).map_err(|e| e.to_string())?;
        }
        return Ok((c, format!("the {VALUE_DIGITS}-digit values at nu = {nu}, taken as exact decimals")));
    }
    let names: Vec<&str> = d.symbols.iter().map(|s| s.name()).collect();
    Err(format!("coefficients hold the symbols {} (substitute them to build Pade approximants)", names.join(", ")))
}

/// The near-diagonal pairs (L, M), L + M = n, M >= 1, diagonal first.
pub(crate) fn near_diagonal(n: usize) -> Vec<(usize, usize)> {
    let mut pairs: Vec<(usize, usize)> =
        (1..=n).map(|m| (n - m, m)).filter(|(l, m)| l.abs_diff(*m) <= SPREAD).collect();
    pairs.sort_by_key(|(l, m)| (l.abs_diff(*m), std::cmp::Reverse(*l)));
    pairs
}

/// Significant digits of the printed coefficients of an approximant built from numerical values
/// (the values carry 30; the approximant's own conditioning may leave fewer).
const NUMERIC_DIGITS: usize = 20;

fn poly_text(c: &[Q], var: &str, exact: bool) -> String {
    if c.is_empty() {
        return "0".into();
    }
    let text = |a: &Q| {
        if exact {
            q_text(a)
        } else {
            crate::numerics::accuracy::fmt_mpfr(&crate::numerics::exact::to_float(a, 128), NUMERIC_DIGITS)
        }
    };
    c.iter()
        .enumerate()
        .filter(|(_, a)| !a.is_zero())
        .map(|(k, a)| match k {
            0 => text(a),
            1 => format!("({}) {var}", text(a)),
            _ => format!("({}) {var}^{k}", text(a)),
        })
        .collect::<Vec<_>>()
        .join(" + ")
}

/// The text section of `--pade` for the derived parts (appended after their usual output).
pub fn pade_text(parts: &[Derived]) -> String {
    let mut s = String::from(
        "\nPade approximants (docs/theory.md section 11): [L/M] = P(w)/Q(w), Q(0) = 1, matching the series through w^(L+M); \
         poles = zeros of Q, to 6 digits\n",
    );
    for d in parts {
        s.push_str(&format!("pade: {}\n", d.object));
        if d.object == "jacobi" {
            s.push_str("  not built: j_n is a sequence, not a series\n");
            continue;
        }
        let (c, source) = match numbers(d) {
            Ok(x) => x,
            Err(why) => {
                s.push_str(&format!("  not built: {why}\n"));
                continue;
            }
        };
        let even = c.iter().skip(1).step_by(2).all(|a| a.is_zero());
        let (cw, var) = if even {
            (c.iter().step_by(2).cloned().collect::<Vec<_>>(), format!("w = {}^2", d.variable))
        } else {
            (c.clone(), format!("w = {}", d.variable))
        };
        let exact = source == "exact";
        s.push_str(&format!("  variable {var}; coefficients {source}; w^0 .. w^{}\n", cw.len() - 1));
        if !exact {
            s.push_str(&format!(
                "  (P and Q printed to {NUMERIC_DIGITS} significant digits; exact for the rounded values)\n"
            ));
        }
        let f = Series::from_coeffs(cw.clone());
        let pairs = near_diagonal(cw.len() - 1);
        if pairs.is_empty() {
            s.push_str("  not built: fewer than two coefficients in w\n");
        }
        for (l, m) in pairs {
            match Pade::new(&f, l, m) {
                Ok(p) => {
                    s.push_str(&format!("  [{l}/{m}] P = {}\n", poly_text(&p.numer, "w", exact)));
                    s.push_str(&format!("  [{l}/{m}] Q = {}\n", poly_text(&p.denom, "w", exact)));
                    let poles: Vec<String> = polynomial_roots(&p.denom).iter().map(complex_text).collect();
                    s.push_str(&format!(
                        "  [{l}/{m}] poles: {}\n",
                        if poles.is_empty() { "none".into() } else { poles.join(", ") }
                    ));
                }
                Err(e) => s.push_str(&format!("  [{l}/{m}] not built: {e}\n")),
            }
        }
    }
    s
}
