//! Exact inputs (reduced rationals) to MPFR and `f64`, rounded once.
//!
//! The scene's numbers are exact rationals; they must reach MPFR without passing through `f64`
//! (a Jacobi exponent formed in `f64` and promoted silently loses digits, docs/theory.md section 7).

use num_rational::BigRational;
use rug::{Float, Integer, Rational};

/// Converts a num-bigint integer to a GMP integer exactly.
pub fn to_integer(n: &num_bigint::BigInt) -> Integer {
    let (sign, digits) = n.to_u32_digits();
    let mut z = Integer::from_digits(&digits, rug::integer::Order::Lsf);
    if sign == num_bigint::Sign::Minus {
        z = -z;
    }
    z
}

/// Converts an exact rational to a GMP rational exactly.
pub fn to_rational(q: &BigRational) -> Rational {
    Rational::from((to_integer(q.numer()), to_integer(q.denom())))
}

/// Rounds an exact rational once to an MPFR float of `prec` bits (round to nearest).
pub fn to_float(q: &BigRational, prec: u32) -> Float {
    Float::with_val(prec, to_rational(q))
}

/// Rounds an exact rational once to the nearest `f64` (correctly rounded through MPFR).
/// Returns `None` when the value is outside the finite `f64` range.
pub fn to_f64(q: &BigRational) -> Option<f64> {
    let v = Float::with_val(53, to_rational(q)).to_f64();
    v.is_finite().then_some(v)
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_bigint::BigInt;

    #[test]
    fn one_third_rounds_once() {
        let q = BigRational::new(BigInt::from(1), BigInt::from(3));
        let f = to_float(&q, 200);
        let exact = Rational::from((1, 3));
        let err = Float::with_val(400, &f - &exact).abs();
        // Round to nearest: |err| <= ulp/2 = 2^(-2-200) for a value in [1/4, 1/2).
        assert!(err <= Float::with_val(53, Float::i_exp(1, -202)));
        assert_eq!(to_f64(&q), Some(1.0 / 3.0));
    }

    #[test]
    fn huge_values_leave_f64_range() {
        let q = BigRational::from_integer(BigInt::from(10).pow(400));
        assert_eq!(to_f64(&q), None);
        assert!(to_float(&q, 64).is_finite());
    }
}
