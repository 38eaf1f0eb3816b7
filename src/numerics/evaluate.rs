//! Evaluation of exact objects (rationals, polynomials in symbols, truncated series) at MPFR
//! precision and in `f64`. The exact engine (`exact_series`) has no floats; this is its only
//! bridge to them. Each exact coefficient is rounded once; sums are formed at the working
//! precision `prec` (an argument, never a global).

use crate::numerics::exact;
use exact_series::{Poly, Ring, Series, Symbol, Q};
use rug::{Assign, Float};

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

/// A truncated series `sum_k c_k x^k` with its coefficients evaluated once at given symbol values
/// (each `c_k` in Q\[symbols\] rounded to `prec` bits by [`poly_mpfr`], and that value rounded to
/// `f64`), for evaluating the same derived series at many points: Horner,
/// `((c_N x + c_(N-1)) x + ...) x + c_0`, N multiplications and N additions per point, in MPFR at
/// the prepared precision ([`PreparedSeries::at_mpfr`], the same value as [`series_mpfr`]) or in
/// `f64` ([`PreparedSeries::at_f64`]).
#[derive(Debug, Clone)]
pub struct PreparedSeries {
    mpfr: Vec<Float>,
    f64s: Vec<f64>,
    prec: u32,
}

impl PreparedSeries {
    /// The coefficients of `s` (its known ones) at `values`, at `prec` bits.
    pub fn new(s: &Series<Poly>, values: Bindings, prec: u32) -> Result<Self, UnboundSymbol> {
        let mpfr = s.coeffs().iter().map(|c| poly_mpfr(c, values, prec)).collect::<Result<Vec<_>, _>>()?;
        let f64s = mpfr.iter().map(Float::to_f64).collect();
        Ok(PreparedSeries { mpfr, f64s, prec })
    }

    /// The working precision in bits.
    pub fn prec(&self) -> u32 {
        self.prec
    }

    /// The number of coefficients (the series' order plus one).
    pub fn len(&self) -> usize {
        self.mpfr.len()
    }

    /// Whether there is no coefficient.
    pub fn is_empty(&self) -> bool {
        self.mpfr.is_empty()
    }

    /// The value at `x` into `acc` (which keeps its own precision; set it to [`Self::prec`] for
    /// the value of [`series_mpfr`]): no allocation when `acc` is reused.
    pub fn at_mpfr_into(&self, x: &Float, acc: &mut Float) {
        acc.assign(0);
        for c in self.mpfr.iter().rev() {
            *acc *= x;
            *acc += c;
        }
    }

    /// The value at `x`, at the prepared precision.
    pub fn at_mpfr(&self, x: &Float) -> Float {
        let mut acc = Float::new(self.prec);
        self.at_mpfr_into(x, &mut acc);
        acc
    }

    /// The value at `x` in `f64` from the coefficients rounded to `f64`.
    pub fn at_f64(&self, x: f64) -> f64 {
        self.f64s.iter().rev().fold(0.0, |acc, c| acc * x + c)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use exact_series::Symbol;

    /// sum_{k <= N} theta^k x^k at theta = 1/3, x = 1/2 is (1 - 6^-(N+1))/(5/6): the prepared
    /// series gives it in MPFR (the same bits as `series_mpfr`) and in f64.
    #[test]
    fn prepared_series_is_the_truncated_geometric_sum() {
        let n = 20;
        let theta = Poly::var("theta").unwrap();
        let mut c = vec![Poly::one()];
        for k in 1..=n {
            c.push(c[k - 1].mul(&theta));
        }
        let s = Series::from_coeffs(c);
        let prec = 200;
        let th = Symbol::new("theta").unwrap();
        let values = [(th, Float::with_val(prec, 1) / 3u32)];
        let p = PreparedSeries::new(&s, &values, prec).unwrap();
        assert_eq!(p.len(), n + 1);
        let x = Float::with_val(prec, 0.5);
        let v = p.at_mpfr(&x);
        assert_eq!(v, series_mpfr(&s, &x, &values, prec).unwrap());
        let tail = Float::with_val(prec, rug::ops::Pow::pow(Float::with_val(prec, 6u32), -(n as i32 + 1)));
        let exact = Float::with_val(prec, 1 - tail) * 6u32 / 5u32;
        let rel = Float::with_val(prec, &v - &exact).abs() / &exact;
        assert!(rel < 1e-58, "relative error {rel}");
        let f = p.at_f64(0.5);
        assert!((f - exact.to_f64()).abs() <= 4.0 * f64::EPSILON * exact.to_f64(), "f64 {f}");
        let unbound = PreparedSeries::new(&s, &[], prec).unwrap_err();
        assert_eq!(unbound.0, "theta");
    }
}
