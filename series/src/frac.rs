//! The field of fractions of [`Poly`]: `num/den`, reduced by a multivariate gcd.
//!
//! Canonical form: `gcd(num, den) = 1` and the leading coefficient of `den` (pure lex order,
//! symbols by name) is 1. Reduction uses [`Poly::gcd`] and [`Poly::div_exact`].

use crate::ring::Q;
use crate::{Monomial, Poly, Ring, Symbol};
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
        let (_, n, d) = num.gcd_cofactors(&den);
        Some(Frac::monic(n, d))
    }

    /// `num/den` for coprime `num`, `den` (den non-zero): only the leading coefficient of `den`
    /// made 1.
    fn monic(num: Poly, den: Poly) -> Frac {
        let lc = den.leading_coefficient_lex();
        if lc.is_one() {
            return Frac { num, den };
        }
        let inv = lc.recip();
        Frac { num: num.scale(&inv), den: den.scale(&inv) }
    }

    /// `num / base^e`, reduced, without forming the gcd of `num` and `base^e`. `base` is first
    /// split into squarefree pieces f_i with product `base` (f = gcd(p, dp/dx_1, ..., dp/dx_n)
    /// times p/f, recursively: p/f is squarefree over Q); then every piece is divided out of
    /// `num` while it divides exactly, and a piece that does not divide `num` but shares a factor
    /// with it (a non-constant gcd with that small piece: never with the power) is split into
    /// that gcd and its cofactor, which are coprime. At the end `num` is coprime to every
    /// piece, so to `base^e`. The same canonical form as [`Frac::new`]; `None` if `base = 0`.
    ///
    /// ```
    /// use exact_series::{Frac, Poly, Ring};
    /// let x = Poly::var("x").unwrap();
    /// let d = x.add(&Poly::one()); // x + 1
    /// let f = Frac::over_power(x.mul(&d), &d, 3).unwrap();
    /// assert_eq!(f, Frac::new(x.mul(&d), d.mul(&d).mul(&d)).unwrap());
    /// assert_eq!(f.text(), "(x)/(x^2 + 2*x + 1)");
    /// // A base with a repeated factor, a numerator sharing only part of it.
    /// let y = Poly::var("y").unwrap();
    /// let b = d.mul(&d).mul(&y.sub(&x)); // (x + 1)^2 (y - x)
    /// let n = y.sub(&x).mul(&d).mul(&y);
    /// assert_eq!(Frac::over_power(n.clone(), &b, 2), Frac::new(n, b.mul(&b)));
    /// ```
    pub fn over_power(num: Poly, base: &Poly, e: u32) -> Option<Frac> {
        if base.is_zero() {
            return None;
        }
        if num.is_zero() {
            return Some(Frac::zero());
        }
        if e == 0 || base.as_q().is_some() {
            return Frac::new(num, (0..e).fold(Poly::one(), |acc, _| acc.mul(base)));
        }
        let mut pieces: Vec<(Poly, u32)> = squarefree_pieces(base).into_iter().map(|f| (f, e)).collect();
        let mut num = num;
        let mut i = 0;
        while i < pieces.len() {
            let (f, m) = pieces[i].clone();
            if m == 0 || f.as_q().is_some() {
                i += 1;
                continue;
            }
            if let Some(q) = num.div_exact(&f) {
                num = q;
                pieces[i].1 -= 1;
                continue;
            }
            let g = num.gcd(&f);
            if g.as_q().is_none() {
                // gcd(num, f/g) = 1 (f is squarefree), and g is divided out when its turn comes.
                pieces[i].0 = f.div_exact(&g).expect("the gcd divides");
                pieces.push((g, m));
            }
            i += 1;
        }
        let den = pieces.iter().fold(Poly::one(), |acc, (f, m)| (0..*m).fold(acc, |a, _| a.mul(f)));
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
        if self.num.degree_in(s) == 0 && self.den.degree_in(s) == 0 {
            return Some(self.clone()); // s does not occur: already canonical
        }
        Frac::new(self.num.subs(s, v), self.den.subs(s, v))
    }
}

/// d p / d x.
fn derivative(p: &Poly, x: Symbol) -> Poly {
    Poly::from_rational_terms(p.terms().filter_map(|(m, q)| {
        let (rest, e) = m.remove(x);
        (e > 0).then(|| (rest.mul(&Monomial::power(x, e - 1)), q * Q::from_integer(e.into())))
    }))
}

/// Squarefree polynomials whose product is `p` (non-constant `p`; module doc of
/// [`Frac::over_power`]): with f = gcd(p, dp/dx over every symbol x), p/f is squarefree and f
/// holds every repeated factor once less.
fn squarefree_pieces(p: &Poly) -> Vec<Poly> {
    let f =
        p.symbols().into_iter().fold(p.clone(), |g, x| if g.as_q().is_some() { g } else { g.gcd(&derivative(p, x)) });
    if f.as_q().is_some() {
        return vec![p.clone()];
    }
    let mut out = squarefree_pieces(&f);
    out.push(p.div_exact(&f).expect("the gcd divides"));
    out
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
    /// Henrici's sum (P. Henrici, "A subroutine for computations with rational numbers", J. ACM
    /// 3, 1956; Knuth, TAOCP 2, sec. 4.5.1): with g = gcd(d1, d2), d1 = g e1, d2 = g e2, the
    /// numerator t = n1 e2 + n2 e1 is coprime to e1 e2, so only gcd(t, g) remains to be divided
    /// out; when g = 1 the sum is already reduced. Gcds of the denominators and of t with their
    /// common part, never of the full numerator with the full product.
    fn add(&self, o: &Self) -> Self {
        if self.num.is_zero() {
            return o.clone();
        }
        if o.num.is_zero() {
            return self.clone();
        }
        if self.den == o.den {
            return Frac::new(self.num.add(&o.num), self.den.clone()).expect("non-zero den");
        }
        if self.den.is_one() || o.den.is_one() {
            // n1 + n2 d2 over d2: gcd(n1 + n2 d2, d2) = gcd(n1, d2) = 1 (and symmetrically).
            let (p, f) = if self.den.is_one() { (self, o) } else { (o, self) };
            return Frac { num: f.num.add(&p.num.mul(&f.den)), den: f.den.clone() };
        }
        let (g, e1, e2) = self.den.gcd_cofactors(&o.den);
        let t = self.num.mul(&e2).add(&o.num.mul(&e1));
        if t.is_zero() {
            return Frac::zero();
        }
        // Monic g, d1, d2 make the cofactors and their products monic (lex is a monomial order).
        if g.is_one() {
            return Frac { num: t, den: self.den.mul(&o.den) };
        }
        let (_, num, g2) = t.gcd_cofactors(&g);
        Frac::monic(num, g2.mul(&e1).mul(&e2))
    }
    fn sub(&self, o: &Self) -> Self {
        self.add(&o.neg())
    }
    fn neg(&self) -> Self {
        Frac { num: self.num.neg(), den: self.den.clone() }
    }
    /// Henrici's product: (n1/d1)(n2/d2) = ((n1/g1)(n2/g2)) / ((d1/g2)(d2/g1)) with g1 =
    /// gcd(n1, d2), g2 = gcd(n2, d1): reduced, with no gcd of the full products.
    fn mul(&self, o: &Self) -> Self {
        if self.num.is_zero() || o.num.is_zero() {
            return Frac::zero();
        }
        if self.den.is_one() && o.den.is_one() {
            return Frac { num: self.num.mul(&o.num), den: Poly::one() };
        }
        let (_, n1, d2) = self.num.gcd_cofactors(&o.den);
        let (_, n2, d1) = o.num.gcd_cofactors(&self.den);
        Frac::monic(n1.mul(&n2), d1.mul(&d2))
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
        Some(Frac::monic(self.den.clone(), self.num.clone())) // already coprime
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
