//! The field of fractions of [`Poly`]: `num/den`, reduced by a multivariate gcd.
//!
//! Canonical form: `gcd(num, den) = 1` and the leading coefficient of `den` (pure lex order,
//! symbols by name) is 1. Reduction uses [`Poly::gcd`] and [`Poly::div_exact`].

use crate::ring::Q;
use crate::{Poly, Ring, Symbol};
use num_traits::Zero;

/// A rational function `num/den` over Q in named symbols (canonical: reduced, `den` monic).
///
/// ```
/// use exact_series::{Frac, Poly, Ring};
/// let s = Poly::var("S").unwrap();
/// let eps = Poly::var("eps").unwrap();
/// let d = Poly::one().sub(&eps.mul(&s).mul_int(2)); // 1 - 2 eps S
/// let f = Frac::new(d.mul(&s), d.mul(&eps)).unwrap();
/// assert_eq!(f.text(), "(S)/(eps)");
/// assert_eq!(Frac::from_poly(d.clone()).inv().unwrap().text(), "(-1/2)/(S*eps - 1/2)");
/// ```
#[derive(Clone, PartialEq, Eq, Hash, Debug)]
pub struct Frac {
    num: Poly,
    den: Poly,
}

impl Frac {
    /// `num/den`, reduced; `None` if `den = 0`.
    pub fn new(num: Poly, den: Poly) -> Option<Frac> {
        if den.is_zero() {
            return None;
        }
        if num.is_zero() {
            return Some(Frac::zero());
        }
        let g = num.gcd(&den);
        let (n, d) = (num.div_exact(&g)?, den.div_exact(&g)?);
        let lc = d.leading_coefficient_lex();
        let inv = lc.recip();
        Some(Frac { num: n.scale(&inv), den: d.scale(&inv) })
    }
    /// `num / base^e`, reduced, without forming the gcd of `num` and `base^e`: factors `base`
    /// are first removed by exact division; if what is left of `num` is coprime to `base` (one
    /// gcd with `base`, not with its power), the pair is already reduced; otherwise this falls
    /// back to [`Frac::new`]. The same canonical form as [`Frac::new`]; `None` if `base = 0`.
    ///
    /// ```
    /// use exact_series::{Frac, Poly, Ring};
    /// let x = Poly::var("x").unwrap();
    /// let d = x.add(&Poly::one()); // x + 1
    /// let f = Frac::over_power(x.mul(&d), &d, 3).unwrap();
    /// assert_eq!(f, Frac::new(x.mul(&d), d.mul(&d).mul(&d)).unwrap());
    /// assert_eq!(f.text(), "(x)/(x^2 + 2*x + 1)");
    /// ```
    pub fn over_power(num: Poly, base: &Poly, e: u32) -> Option<Frac> {
        if base.is_zero() {
            return None;
        }
        let mut num = num;
        let mut e = e;
        while e > 0 && !num.is_zero() {
            match num.div_exact(base) {
                Some(q) => {
                    num = q;
                    e -= 1;
                }
                None => break,
            }
        }
        let den = (0..e).fold(Poly::one(), |acc, _| acc.mul(base));
        if num.is_zero() || e == 0 || base.as_q().is_some() || num.gcd(base).as_q().is_none() {
            return Frac::new(num, den);
        }
        let inv = den.leading_coefficient_lex().recip();
        Some(Frac { num: num.scale(&inv), den: den.scale(&inv) })
    }

    /// The polynomial `p` as a fraction `p/1`.
    pub fn from_poly(p: Poly) -> Frac {
        Frac { num: p, den: Poly::one() }
    }
    /// Numerator.
    pub fn numer(&self) -> &Poly {
        &self.num
    }
    /// Denominator (monic).
    pub fn denom(&self) -> &Poly {
        &self.den
    }
    /// Substitutes a rational for a symbol; `None` if the denominator vanishes there.
    pub fn subs(&self, s: Symbol, v: &Q) -> Option<Frac> {
        Frac::new(self.num.subs(s, v), self.den.subs(s, v))
    }
}

impl Ring for Frac {
    fn zero() -> Self {
        Frac { num: Poly::zero(), den: Poly::one() }
    }
    fn one() -> Self {
        Frac { num: Poly::one(), den: Poly::one() }
    }
    fn is_zero(&self) -> bool {
        self.num.is_zero()
    }
    fn add(&self, o: &Self) -> Self {
        if self.den == o.den {
            return Frac::new(self.num.add(&o.num), self.den.clone()).expect("non-zero den");
        }
        Frac::new(self.num.mul(&o.den).add(&o.num.mul(&self.den)), self.den.mul(&o.den)).expect("non-zero den")
    }
    fn sub(&self, o: &Self) -> Self {
        self.add(&o.neg())
    }
    fn neg(&self) -> Self {
        Frac { num: self.num.neg(), den: self.den.clone() }
    }
    fn mul(&self, o: &Self) -> Self {
        if self.den.is_one() && o.den.is_one() {
            return Frac { num: self.num.mul(&o.num), den: Poly::one() };
        }
        Frac::new(self.num.mul(&o.num), self.den.mul(&o.den)).expect("non-zero den")
    }
    fn from_q(q: &Q) -> Self {
        Frac { num: Poly::from_q(q), den: Poly::one() }
    }
    fn as_q(&self) -> Option<Q> {
        if self.den.is_one() {
            self.num.as_q()
        } else {
            None
        }
    }
    fn inv(&self) -> Option<Self> {
        if self.num.is_zero() {
            return None;
        }
        Frac::new(self.den.clone(), self.num.clone())
    }
    fn text(&self) -> String {
        if self.den.is_one() {
            self.num.text()
        } else {
            format!("({})/({})", self.num.text(), self.den.text())
        }
    }
    fn latex(&self) -> String {
        if self.den.is_one() {
            self.num.latex()
        } else {
            format!("\\frac{{{}}}{{{}}}", self.num.latex(), self.den.latex())
        }
    }
    fn is_sum(&self) -> bool {
        !self.den.is_one() || self.num.is_sum()
    }
    fn scale(&self, q: &Q) -> Self {
        if Zero::is_zero(q) {
            return Frac::zero();
        }
        Frac { num: self.num.scale(q), den: self.den.clone() }
    }
}
