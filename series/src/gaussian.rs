//! Gaussian extension `R[i]`, i^2 = -1, of a coefficient ring `R` (Problem 2 works in Q(i)[eps, B, S]).

use crate::ring::Q;
use crate::Ring;

/// `re + im * i` with `re`, `im` in `R`. Canonical when `R` is.
///
/// ```
/// use exact_series::{Gaussian, Ring, Q};
/// let i = Gaussian::<Q>::i();
/// assert_eq!(i.mul(&i), Gaussian::from_int(-1));
/// let z = Gaussian::new(Q::from_integer(1.into()), Q::from_integer(1.into()));
/// assert_eq!(z.inv().unwrap().text(), "1/2 - 1/2*i");
/// ```
#[derive(Clone, PartialEq, Eq, Hash, Debug)]
pub struct Gaussian<R: Ring> {
    /// Real part.
    pub re: R,
    /// Imaginary part.
    pub im: R,
}

impl<R: Ring> Gaussian<R> {
    /// `re + im i`.
    pub fn new(re: R, im: R) -> Self {
        Gaussian { re, im }
    }
    /// The imaginary unit.
    pub fn i() -> Self {
        Gaussian { re: R::zero(), im: R::one() }
    }
    /// The embedding of `R`.
    pub fn real(re: R) -> Self {
        Gaussian { re, im: R::zero() }
    }
    /// Complex conjugate.
    pub fn conj(&self) -> Self {
        Gaussian { re: self.re.clone(), im: self.im.neg() }
    }
    /// Applies `f` to both parts (e.g. substitution of a symbol).
    pub fn map(&self, f: impl Fn(&R) -> R) -> Self {
        Gaussian { re: f(&self.re), im: f(&self.im) }
    }
}

fn wrap(s: String, paren: bool) -> String {
    if paren {
        format!("({s})")
    } else {
        s
    }
}

impl<R: Ring> Ring for Gaussian<R> {
    fn zero() -> Self {
        Gaussian { re: R::zero(), im: R::zero() }
    }
    fn one() -> Self {
        Gaussian { re: R::one(), im: R::zero() }
    }
    fn is_zero(&self) -> bool {
        self.re.is_zero() && self.im.is_zero()
    }
    fn add(&self, o: &Self) -> Self {
        Gaussian { re: self.re.add(&o.re), im: self.im.add(&o.im) }
    }
    fn sub(&self, o: &Self) -> Self {
        Gaussian { re: self.re.sub(&o.re), im: self.im.sub(&o.im) }
    }
    fn neg(&self) -> Self {
        Gaussian { re: self.re.neg(), im: self.im.neg() }
    }
    fn mul(&self, o: &Self) -> Self {
        if self.im.is_zero() {
            return Gaussian { re: self.re.mul(&o.re), im: self.re.mul(&o.im) };
        }
        if o.im.is_zero() {
            return Gaussian { re: self.re.mul(&o.re), im: self.im.mul(&o.re) };
        }
        Gaussian { re: self.re.mul(&o.re).sub(&self.im.mul(&o.im)), im: self.re.mul(&o.im).add(&self.im.mul(&o.re)) }
    }
    fn from_q(q: &Q) -> Self {
        Gaussian { re: R::from_q(q), im: R::zero() }
    }
    fn as_q(&self) -> Option<Q> {
        if self.im.is_zero() {
            self.re.as_q()
        } else {
            None
        }
    }
    fn inv(&self) -> Option<Self> {
        let norm = self.re.mul(&self.re).add(&self.im.mul(&self.im));
        let n_inv = norm.inv()?;
        Some(Gaussian { re: self.re.mul(&n_inv), im: self.im.neg().mul(&n_inv) })
    }
    fn text(&self) -> String {
        match (self.re.is_zero(), self.im.is_zero()) {
            (_, true) => self.re.text(),
            (true, false) => imag_text(&self.im),
            (false, false) => {
                let im = imag_text(&self.im);
                match im.strip_prefix('-') {
                    Some(rest) if !self.im.is_sum() => format!("{} - {rest}", self.re.text()),
                    _ => format!("{} + {im}", self.re.text()),
                }
            }
        }
    }
    fn latex(&self) -> String {
        let im_l = |im: &R| {
            if im.is_one() {
                r"\mathrm{i}".to_string()
            } else {
                format!(r"{} \mathrm{{i}}", wrap(im.latex(), im.is_sum()))
            }
        };
        match (self.re.is_zero(), self.im.is_zero()) {
            (_, true) => self.re.latex(),
            (true, false) => im_l(&self.im),
            (false, false) => {
                let im = im_l(&self.im);
                match im.strip_prefix('-') {
                    Some(rest) if !self.im.is_sum() => format!("{} - {rest}", self.re.latex()),
                    _ => format!("{} + {im}", self.re.latex()),
                }
            }
        }
    }
    fn is_sum(&self) -> bool {
        match (self.re.is_zero(), self.im.is_zero()) {
            (_, true) => self.re.is_sum(),
            (true, false) => false,
            (false, false) => true,
        }
    }
    fn scale(&self, q: &Q) -> Self {
        Gaussian { re: self.re.scale(q), im: self.im.scale(q) }
    }
}

fn imag_text<R: Ring>(im: &R) -> String {
    if im.is_one() {
        "i".to_string()
    } else if im.neg().is_one() {
        "-i".to_string()
    } else {
        format!("{}*i", wrap(im.text(), im.is_sum()))
    }
}
