//! Evaluation of exact objects (rationals, polynomials in symbols, truncated series) at MPFR
//! precision and in `f64`. The exact engine (`exact_series`) has no floats; this is its only
//! bridge to them. Each exact coefficient is rounded once; sums are formed at the working
//! precision `prec` (an argument, never a global).

use crate::numerics::exact;
use exact_series::{Poly, Ring, Series, Symbol, Q};
use rug::Float;

/// A symbol with no value in an evaluation.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("no value given for the symbol {0}")]
pub struct UnboundSymbol(pub String);

/// Values of the symbols of an evaluation.
pub type Bindings<'a> = &'a [(Symbol, Float)];

/// A polynomial at the given symbol values, at `prec` bits.
pub fn poly_mpfr(p: &Poly, values: Bindings, prec: u32) -> Result<Float, UnboundSymbol> {
    let mut sum = Float::with_val(prec, 0);
    for (q, factors) in p.rational_terms() {
        let mut t = exact::to_float(&q, prec);
        for (s, e) in factors {
            let v = values
                .iter()
                .find(|(t, _)| *t == s)
                .map(|(_, v)| v)
                .ok_or_else(|| UnboundSymbol(s.name().to_string()))?;
            t *= Float::with_val(prec, rug::ops::Pow::pow(v, e));
        }
        sum += t;
    }
    Ok(sum)
}

/// A truncated series `sum_k c_k x^k` (its known coefficients) at `x`, coefficients in Q\[symbols\],
/// at `prec` bits (Horner).
pub fn series_mpfr(s: &Series<Poly>, x: &Float, values: Bindings, prec: u32) -> Result<Float, UnboundSymbol> {
    let mut acc = Float::with_val(prec, 0);
    for c in s.coeffs().iter().rev() {
        acc *= x;
        if !c.is_zero() {
            acc += poly_mpfr(c, values, prec)?;
        }
    }
    Ok(acc)
}

/// A truncated series over Q at `x`, at `prec` bits (Horner).
pub fn series_q_mpfr(s: &Series<Q>, x: &Float, prec: u32) -> Float {
    let mut acc = Float::with_val(prec, 0);
    for c in s.coeffs().iter().rev() {
        acc *= x;
        acc += exact::to_float(c, prec);
    }
    acc
}

/// A polynomial at `f64` symbol values; `None` for an unbound symbol or a coefficient outside the
/// `f64` range.
pub fn poly_f64(p: &Poly, values: &[(Symbol, f64)]) -> Option<f64> {
    let mut sum = 0.0;
    for (q, factors) in p.rational_terms() {
        let mut t = exact::to_f64(&q)?;
        for (s, e) in factors {
            let v = values.iter().find(|(t, _)| *t == s)?.1;
            t *= v.powi(e as i32);
        }
        sum += t;
    }
    Some(sum)
}
