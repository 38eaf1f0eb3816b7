//! Exact inputs (reduced rationals) to MPFR and `f64`, rounded once.
//!
//! The scene's numbers are exact rationals; they must reach MPFR without passing through `f64`
//! (a Jacobi exponent formed in `f64` and promoted silently loses digits, docs/theory.md section 7).

use num_rational::BigRational;
use rug::{Float, Integer, Rational};

/// Converts a num-bigint integer to a GMP integer exactly.
pub(crate) fn to_integer(n: &num_bigint::BigInt) -> Integer {
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
///
/// Numerator and denominator of at most 53 bits (every decimal input of a scene with up to 15
/// digits) take the fast path [`ratio_to_f64`]: both are exact `f64`, and IEEE division rounds
/// their quotient correctly to nearest-even, as MPFR does, so the result is the same (test
/// `the_fast_path_rounds_as_mpfr`).
pub fn to_f64(q: &BigRational) -> Option<f64> {
    use num_traits::ToPrimitive;
    if let (Some(n), Some(d)) = (q.numer().to_i128(), q.denom().to_i128())
        && let Some(v) = ratio_to_f64(n, d)
    {
        return Some(v);
    }
    let v = Float::with_val(53, to_rational(q)).to_f64();
    v.is_finite().then_some(v)
}

/// The exact order of the rational `q` against `pi` times the rational `m` (m > 0), decided by MPFR
/// bounds of pi rounded down and up at a precision doubled until they separate (pi is irrational,
/// so `q` never equals pi m and the loop ends: at about the bits of q's parts plus 64). Never
/// through `f64`: a load given to 20 digits below pi E* D is below it (issue 34).
///
/// # Panics
/// When `m <= 0` (a bug of the caller).
pub fn cmp_pi_times(q: &BigRational, m: &BigRational) -> std::cmp::Ordering {
    use num_traits::Signed;
    assert!(m.is_positive(), "cmp_pi_times: m must be > 0");
    let r = to_rational(&(q / m));
    let bits = |z: &Integer| z.significant_bits();
    let mut prec = 64 + bits(r.numer()).max(bits(r.denom()));
    loop {
        let (lo, _) = Float::with_val_round(prec, rug::float::Constant::Pi, rug::float::Round::Down);
        let (hi, _) = Float::with_val_round(prec, rug::float::Constant::Pi, rug::float::Round::Up);
        if lo > r {
            return std::cmp::Ordering::Less;
        }
        if hi < r {
            return std::cmp::Ordering::Greater;
        }
        prec *= 2;
    }
}

/// n/d correctly rounded to the nearest `f64` when |n| and d (d > 0) are at most 2^53, so both
/// are exact doubles and one IEEE division rounds once (the quotient's magnitude is then 0 or at
/// least 2^-53, far from the subnormal range); `None` otherwise.
pub fn ratio_to_f64(n: i128, d: i128) -> Option<f64> {
    const EXACT: i128 = 1 << 53;
    (d > 0 && d <= EXACT && n.abs() <= EXACT).then(|| n as f64 / d as f64)
}

/// An exact rational n/d (d > 0, reduced) in i128 parts: exact arithmetic that returns `None`
/// where a part would overflow, for inputs with small numerators and denominators (a scene's
/// decimals), where [`BigRational`]'s operations cost about 0.5 us each. Any result is the same
/// reduced rational the big-rational arithmetic gives (test `small_rationals_match_big_ones`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SmallRational {
    num: i128,
    den: i128,
}

fn gcd_u128(mut a: u128, mut b: u128) -> u128 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

impl SmallRational {
    /// n/d reduced (d != 0; `None` for d = 0 or an overflow of the sign change).
    pub fn new(n: i128, d: i128) -> Option<Self> {
        if d == 0 {
            return None;
        }
        let g = gcd_u128(n.unsigned_abs(), d.unsigned_abs()) as i128;
        let (n, d) = if d < 0 { (n.checked_neg()?, d.checked_neg()?) } else { (n, d) };
        Some(SmallRational { num: n / g, den: d / g })
    }

    /// The integer n.
    pub fn integer(n: i128) -> Self {
        SmallRational { num: n, den: 1 }
    }

    /// `q` when its numerator and denominator fit in i128.
    pub fn of(q: &BigRational) -> Option<Self> {
        use num_traits::ToPrimitive;
        Some(SmallRational { num: q.numer().to_i128()?, den: q.denom().to_i128()? })
    }

    /// self + o.
    pub fn add(self, o: Self) -> Option<Self> {
        let n = self.num.checked_mul(o.den)?.checked_add(o.num.checked_mul(self.den)?)?;
        Self::new(n, self.den.checked_mul(o.den)?)
    }

    /// self - o.
    pub fn sub(self, o: Self) -> Option<Self> {
        self.add(SmallRational { num: o.num.checked_neg()?, den: o.den })
    }

    /// self * o.
    pub fn mul(self, o: Self) -> Option<Self> {
        Self::new(self.num.checked_mul(o.num)?, self.den.checked_mul(o.den)?)
    }

    /// self / o (`None` for o = 0).
    pub fn div(self, o: Self) -> Option<Self> {
        Self::new(self.num.checked_mul(o.den)?, self.den.checked_mul(o.num)?)
    }

    /// The same value as a [`BigRational`].
    pub(crate) fn to_big(self) -> BigRational {
        BigRational::new_raw(self.num.into(), self.den.into())
    }

    /// Rounded once to the nearest `f64` ([`to_f64`]).
    pub fn to_f64(self) -> Option<f64> {
        ratio_to_f64(self.num, self.den).or_else(|| to_f64(&self.to_big()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn comparisons_with_pi_are_exact() {
        // See: issue 34 (a load of 0.03141592653589793238 < pi E* D, D = 0.01, refused as above it).
        use std::cmp::Ordering::{Greater, Less};
        let q = |s: &str| exact_series::parse_rational(s).unwrap();
        let d = q("0.01");
        assert_eq!(cmp_pi_times(&q("0.03141592653589793238"), &d), Less);
        assert_eq!(cmp_pi_times(&q("0.03141592653589793239"), &d), Greater);
        // pi to 60 digits on either side: 3.14159265358979323846264338327950288419716939937510582097494...
        let below = "3.141592653589793238462643383279502884197169399375105820974944";
        let above = "3.141592653589793238462643383279502884197169399375105820974945";
        assert_eq!(cmp_pi_times(&q(below), &q("1")), Less);
        assert_eq!(cmp_pi_times(&q(above), &q("1")), Greater);
        // The f64 nearest pi E* D is above the exact value here, and below it times 10/11.
        assert_eq!(cmp_pi_times(&q("355/113"), &q("1")), Greater);
        assert_eq!(cmp_pi_times(&q("22/7"), &q("10/11")), Greater);
        assert_eq!(cmp_pi_times(&q("1/1000000000000000000000000000000"), &q("1e-30")), Less);
    }
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

    /// MPFR's rounding of n/d, the reference of the fast path.
    fn mpfr_f64(n: i128, d: i128) -> f64 {
        let q = Rational::from((Integer::from(n), Integer::from(d)));
        Float::with_val(53, q).to_f64()
    }

    #[test]
    fn the_fast_path_rounds_as_mpfr() {
        // Decimals, ties and near-ties of the last bit, and the largest exact parts.
        let e = 1i128 << 53;
        let mut cases = vec![(3, 10), (-1, 3), (0, 7), (1, 1), (e, 3), (-e, e - 1), (e - 1, e), (1, e), (e, 1)];
        let mut x: u64 = 0x9e37_79b9_7f4a_7c15;
        for _ in 0..20000 {
            // xorshift: numerators and denominators of every size up to 2^53.
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let bits_n = 1 + (x % 53) as u32;
            let bits_d = 1 + ((x >> 8) % 53) as u32;
            let n = ((x >> 11) as i128) & ((1i128 << bits_n) - 1);
            let d = (((x >> 3) as i128) & ((1i128 << bits_d) - 1)).max(1);
            cases.push((if x & 1 == 1 { -n } else { n }, d));
        }
        for (n, d) in cases {
            let fast = ratio_to_f64(n, d).expect("parts of at most 53 bits");
            assert_eq!(fast.to_bits(), mpfr_f64(n, d).to_bits(), "{n}/{d}");
            let q = BigRational::new(BigInt::from(n), BigInt::from(d));
            assert_eq!(to_f64(&q).map(f64::to_bits), Some(mpfr_f64(n, d).to_bits()), "{n}/{d}");
        }
        // Beyond 53 bits the fast path declines and to_f64 goes through MPFR.
        assert_eq!(ratio_to_f64(e + 1, 3), None);
        let q = BigRational::new(BigInt::from(e + 1), BigInt::from(3));
        assert_eq!(to_f64(&q), Some(mpfr_f64(e + 1, 3)));
    }

    #[test]
    fn small_rationals_match_big_ones() {
        let vals = [(3, 10), (-7, 4), (0, 1), (1, 3), (22, 7), (-1, 1000000007), (123456789, 1000000)];
        let big = |(n, d): (i128, i128)| BigRational::new(BigInt::from(n), BigInt::from(d));
        for &a in &vals {
            for &b in &vals {
                let (sa, sb) = (SmallRational::new(a.0, a.1).unwrap(), SmallRational::new(b.0, b.1).unwrap());
                assert_eq!(sa.add(sb).unwrap().to_big(), big(a) + big(b));
                assert_eq!(sa.sub(sb).unwrap().to_big(), big(a) - big(b));
                assert_eq!(sa.mul(sb).unwrap().to_big(), big(a) * big(b));
                if b.0 != 0 {
                    assert_eq!(sa.div(sb).unwrap().to_big(), big(a) / big(b));
                } else {
                    assert_eq!(sa.div(sb), None);
                }
                assert_eq!(SmallRational::of(&big(a)), Some(sa));
                assert_eq!(sa.to_f64(), to_f64(&big(a)));
            }
        }
        // Overflow is None, not a wrong value.
        let huge = SmallRational::integer(i128::MAX / 2);
        assert_eq!(huge.mul(huge), None);
        assert_eq!(SmallRational::new(1, 0), None);
    }

    #[test]
    fn huge_values_leave_f64_range() {
        let q = BigRational::from_integer(BigInt::from(10).pow(400));
        assert_eq!(to_f64(&q), None);
        assert!(to_float(&q, 64).is_finite());
    }
}
