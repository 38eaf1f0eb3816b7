//! The coefficient rings: every ring here is a Q-algebra (it contains the rationals), so the
//! recurrences of the engine may divide by integers.
//!
//! Implementations: [`Q`] (exact rationals), [`crate::Poly`] (multivariate polynomials over Q in
//! named symbols), [`crate::Gaussian`] (`R[i]`, i^2 = -1, over any of these rings) and
//! [`crate::Frac`] (the field of fractions of the polynomials).

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::fmt::Debug;

/// Exact rational numbers (num-rational 0.4, reduced, denominator > 0).
pub type Q = BigRational;

/// A commutative ring that contains Q, with exact arithmetic and a canonical form.
///
/// Canonical form means: two equal elements have identical internal representations, so derived
/// `PartialEq` is mathematical equality and printing is stable (snapshot tests rely on it).
pub trait Ring: Clone + PartialEq + Debug + Send + Sync + 'static {
    /// The additive identity.
    fn zero() -> Self;
    /// The multiplicative identity.
    fn one() -> Self;
    /// Whether this is 0.
    fn is_zero(&self) -> bool;
    /// `self + other`.
    fn add(&self, other: &Self) -> Self;
    /// `self - other`.
    fn sub(&self, other: &Self) -> Self;
    /// `-self`.
    fn neg(&self) -> Self;
    /// `self * other`.
    fn mul(&self, other: &Self) -> Self;
    /// The image of a rational.
    fn from_q(q: &Q) -> Self;
    /// The rational value, if this is a rational constant.
    fn as_q(&self) -> Option<Q>;
    /// The inverse, if this is a unit of the ring.
    fn inv(&self) -> Option<Self>;
    /// Plain-text form (parseable style: `49/1296*theta^3 - 1/2`).
    fn text(&self) -> String;
    /// LaTeX form.
    fn latex(&self) -> String;
    /// Whether the printed form is a sum of several terms (needs parentheses in a product).
    fn is_sum(&self) -> bool;

    /// `self * q` for a rational `q`.
    fn scale(&self, q: &Q) -> Self {
        self.mul(&Self::from_q(q))
    }
    /// `self * n`.
    fn mul_int(&self, n: i64) -> Self {
        self.scale(&Q::from_integer(BigInt::from(n)))
    }
    /// `self / n` for a non-zero integer `n`.
    ///
    /// # Panics
    /// When `n == 0` (a bug in the caller: the engine only divides by positive indices).
    fn div_int(&self, n: i64) -> Self {
        assert!(n != 0, "div_int by zero");
        self.scale(&Q::new(BigInt::one(), BigInt::from(n)))
    }
    /// The image of an integer.
    fn from_int(n: i64) -> Self {
        Self::from_q(&Q::from_integer(BigInt::from(n)))
    }
    /// Whether this is 1.
    fn is_one(&self) -> bool {
        *self == Self::one()
    }
    /// `self += other`.
    fn add_assign(&mut self, other: &Self) {
        *self = self.add(other);
    }
    /// `self += a * b`, possibly leaving `self` in a non-canonical intermediate form (e.g. a
    /// polynomial whose content is not reduced): a run of these must end with [`Ring::canonicalize`].
    /// Lets accumulation loops skip a content gcd per step.
    fn fma_lazy(&mut self, a: &Self, b: &Self) {
        self.add_assign(&a.mul(b));
    }
    /// Restores the canonical form after [`Ring::fma_lazy`].
    fn canonicalize(&mut self) {}
    /// An exact square root, if one exists in the ring (used for the constant term of sqrt).
    fn sqrt_exact(&self) -> Option<Self> {
        self.as_q().and_then(|q| rational_sqrt(&q)).map(|r| Self::from_q(&r))
    }
}

/// The exact square root of a non-negative rational that is a perfect square, else `None`.
pub fn rational_sqrt(q: &Q) -> Option<Q> {
    if q.is_negative() {
        return None;
    }
    let n = num_integer::Roots::sqrt(q.numer());
    let d = num_integer::Roots::sqrt(q.denom());
    (&n * &n == *q.numer() && &d * &d == *q.denom()).then(|| Q::new(n, d))
}

/// Plain text of a rational: `3`, `-1/6`.
pub fn q_text(q: &Q) -> String {
    if q.denom().is_one() {
        q.numer().to_string()
    } else {
        format!("{}/{}", q.numer(), q.denom())
    }
}

/// LaTeX of a rational: `3`, `-\frac{1}{6}`.
pub fn q_latex(q: &Q) -> String {
    if q.denom().is_one() {
        q.numer().to_string()
    } else {
        let sign = if q.is_negative() { "-" } else { "" };
        format!("{sign}\\frac{{{}}}{{{}}}", q.numer().abs(), q.denom())
    }
}

impl Ring for Q {
    fn zero() -> Self {
        Zero::zero()
    }
    fn one() -> Self {
        One::one()
    }
    fn is_zero(&self) -> bool {
        Zero::is_zero(self)
    }
    fn add(&self, other: &Self) -> Self {
        self + other
    }
    fn sub(&self, other: &Self) -> Self {
        self - other
    }
    fn neg(&self) -> Self {
        -self
    }
    fn mul(&self, other: &Self) -> Self {
        self * other
    }
    fn from_q(q: &Q) -> Self {
        q.clone()
    }
    fn as_q(&self) -> Option<Q> {
        Some(self.clone())
    }
    fn inv(&self) -> Option<Self> {
        (!Zero::is_zero(self)).then(|| self.recip())
    }
    fn text(&self) -> String {
        q_text(self)
    }
    fn latex(&self) -> String {
        q_latex(self)
    }
    fn is_sum(&self) -> bool {
        false
    }
    fn scale(&self, q: &Q) -> Self {
        self * q
    }
    fn add_assign(&mut self, other: &Self) {
        *self += other;
    }
    /// Accumulates `a b` with one gcd (of the denominators) per step and no reduction; the
    /// reduction happens once in [`Ring::canonicalize`].
    fn fma_lazy(&mut self, a: &Self, b: &Self) {
        let n = a.numer() * b.numer();
        let d = a.denom() * b.denom();
        if Zero::is_zero(self.numer()) {
            *self = Q::new_raw(n, d);
            return;
        }
        let (sn, sd) = (self.numer(), self.denom());
        *self = if *sd == d {
            Q::new_raw(sn + n, d)
        } else {
            let g = crate::gmp::gcd(sd, &d);
            let (fd, fs) = (&d / &g, sd / &g);
            Q::new_raw(sn * &fd + n * fs, sd * fd)
        };
    }
    fn canonicalize(&mut self) {
        let v = std::mem::replace(self, <Q as Zero>::zero());
        let (n, d) = v.into_raw();
        *self = Q::new(n, d);
    }
}

/// Parses an exact rational from text: an integer (`-3`), a ratio (`1/3`, `-2/10`), or a decimal
/// with an optional exponent (`0.25`, `-1.5e-3`, `2E+4`). The value is exact: `0.1` is 1/10.
///
/// ```
/// use exact_series::{parse_rational, Q};
/// use num_bigint::BigInt;
/// assert_eq!(parse_rational("0.25").unwrap(), Q::new(BigInt::from(1), BigInt::from(4)));
/// assert_eq!(parse_rational("-1/3").unwrap(), Q::new(BigInt::from(-1), BigInt::from(3)));
/// assert!(parse_rational("1/0").is_err());
/// assert!(parse_rational("abc").is_err());
/// ```
pub fn parse_rational(text: &str) -> Result<Q, crate::SeriesError> {
    let err = || crate::SeriesError::InvalidRational { text: text.to_string() };
    let s = text.trim();
    if s.is_empty() || s.len() > 100_000 {
        return Err(err());
    }
    if let Some((n, d)) = s.split_once('/') {
        let n = parse_integer(n.trim()).ok_or_else(err)?;
        let d = parse_integer(d.trim()).ok_or_else(err)?;
        if d.is_zero() {
            return Err(err());
        }
        return Ok(Q::new(n, d));
    }
    let (mantissa, exponent) = match s.find(['e', 'E']) {
        Some(i) => {
            let e: i64 = s[i + 1..].parse().map_err(|_| err())?;
            (&s[..i], e)
        }
        None => (s, 0),
    };
    if exponent.unsigned_abs() > 100_000 {
        return Err(err());
    }
    let (neg, digits) = match mantissa.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, mantissa.strip_prefix('+').unwrap_or(mantissa)),
    };
    let (int_part, frac_part) = digits.split_once('.').unwrap_or((digits, ""));
    if (int_part.is_empty() && frac_part.is_empty())
        || !int_part.chars().all(|c| c.is_ascii_digit())
        || !frac_part.chars().all(|c| c.is_ascii_digit())
    {
        return Err(err());
    }
    let all: String = format!("{int_part}{frac_part}");
    let mut n: BigInt = all.parse().map_err(|_| err())?;
    if neg {
        n = -n;
    }
    let scale = exponent - frac_part.len() as i64;
    let ten = BigInt::from(10);
    let p = num_traits::pow(ten, scale.unsigned_abs().to_usize().ok_or_else(err)?);
    Ok(if scale >= 0 { Q::from_integer(n * p) } else { Q::new(n, p) })
}

fn parse_integer(s: &str) -> Option<BigInt> {
    let body = s.strip_prefix(['-', '+']).unwrap_or(s);
    if body.is_empty() || !body.chars().all(|c| c.is_ascii_digit()) {
        return None;
    }
    s.parse().ok()
}
