//! The number type of the spectral method (`spectral/mod.rs`): one trait over `f64` and MPFR
//! ([`Mp`], a `rug::Float` whose results keep the precision of the left operand), so the same
//! code runs in both and the two runs can be compared digit by digit.
//!
//! Only what the method needs: the four operations, powers with a real exponent, sqrt, exp, ln,
//! ln(1 + x), cos, sin, tan, atan, pi, and literals at the precision of a given number
//! ([`Real::lit`]). No equations of the physics here.
//!
//! In place, for the inner loops (an MPFR operation on owned values allocates, copies and frees;
//! in place it is 5 times cheaper at 160-200 bits): the assigning operators with a reference
//! (`+=`, `-=`, `*=`, `/=`), `set_*` (the left side's storage and precision reused) and
//! [`Real::add_mul`] / [`Real::sub_mul`] (the product in one reused value per thread). Each is
//! rounded as the operations it names, in `f64` and MPFR alike (no fused multiply-add: the `f64`
//! results do not move, and MPFR's `mpfr_fma` forms the exact product and adds at mixed
//! precision, twice as dear as a product and a sum at 160 bits). MPFR's e^x, ln, ln(1 + x) and x^a
//! are `numerics::mp_elementary`'s (within 1 ulp, faster than MPFR's).

use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

use crate::numerics::mp_elementary;

use rug::{Assign, Float};

/// A real number type: `f64` or [`Mp`].
pub trait Real:
    Clone
    + std::fmt::Debug
    + PartialOrd
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + for<'a> AddAssign<&'a Self>
    + for<'a> SubAssign<&'a Self>
    + for<'a> MulAssign<&'a Self>
    + for<'a> DivAssign<&'a Self>
{
    /// self = v, keeping self's precision.
    fn set(&mut self, v: &Self);
    /// self = a - b.
    fn set_sub(&mut self, a: &Self, b: &Self);
    /// self = a b.
    fn set_mul(&mut self, a: &Self, b: &Self);
    /// self = a b + c.
    fn set_mul_add(&mut self, a: &Self, b: &Self, c: &Self);
    /// self = a b - c.
    fn set_mul_sub(&mut self, a: &Self, b: &Self, c: &Self);
    /// self += a b.
    fn add_mul(&mut self, a: &Self, b: &Self);
    /// self -= a b.
    fn sub_mul(&mut self, a: &Self, b: &Self);
    /// `v` at the precision of `self`.
    fn lit(&self, v: f64) -> Self;
    /// The square root.
    fn sqrt(&self) -> Self;
    /// e^self.
    fn exp(&self) -> Self;
    /// The natural logarithm.
    fn ln(&self) -> Self;
    /// ln(1 + self), accurate for small self.
    fn ln_1p(&self) -> Self;
    /// self^e for self > 0.
    fn powr(&self, e: &Self) -> Self;
    /// The cosine.
    fn cos(&self) -> Self;
    /// The sine.
    fn sin(&self) -> Self;
    /// The tangent.
    fn tan(&self) -> Self;
    /// The arctangent.
    fn atan(&self) -> Self;
    /// pi at the precision of `self`.
    fn pi(&self) -> Self;
    /// |self|.
    fn abs(&self) -> Self;
    /// The nearest f64.
    fn to_f64(&self) -> f64;
    /// Working precision in bits (53 for f64).
    fn bits(&self) -> u32;
}

impl Real for f64 {
    fn set(&mut self, v: &f64) {
        *self = *v;
    }
    fn set_sub(&mut self, a: &f64, b: &f64) {
        *self = a - b;
    }
    fn set_mul(&mut self, a: &f64, b: &f64) {
        *self = a * b;
    }
    fn set_mul_add(&mut self, a: &f64, b: &f64, c: &f64) {
        *self = a * b + c;
    }
    fn set_mul_sub(&mut self, a: &f64, b: &f64, c: &f64) {
        *self = a * b - c;
    }
    fn add_mul(&mut self, a: &f64, b: &f64) {
        *self += a * b;
    }
    fn sub_mul(&mut self, a: &f64, b: &f64) {
        *self -= a * b;
    }
    fn lit(&self, v: f64) -> f64 {
        v
    }
    fn sqrt(&self) -> f64 {
        f64::sqrt(*self)
    }
    fn exp(&self) -> f64 {
        f64::exp(*self)
    }
    fn ln(&self) -> f64 {
        f64::ln(*self)
    }
    fn ln_1p(&self) -> f64 {
        f64::ln_1p(*self)
    }
    fn powr(&self, e: &f64) -> f64 {
        self.powf(*e)
    }
    fn cos(&self) -> f64 {
        f64::cos(*self)
    }
    fn sin(&self) -> f64 {
        f64::sin(*self)
    }
    fn tan(&self) -> f64 {
        f64::tan(*self)
    }
    fn atan(&self) -> f64 {
        f64::atan(*self)
    }
    fn pi(&self) -> f64 {
        std::f64::consts::PI
    }
    fn abs(&self) -> f64 {
        f64::abs(*self)
    }
    fn to_f64(&self) -> f64 {
        *self
    }
    fn bits(&self) -> u32 {
        53
    }
}

/// An MPFR number; arithmetic results take the precision of the left operand.
#[derive(Clone, Debug, PartialEq, PartialOrd)]
pub struct Mp(pub Float);

impl Mp {
    /// `v` with `prec` bits.
    pub fn new(prec: u32, v: f64) -> Mp {
        Mp(Float::with_val(prec, v))
    }
}

impl Add for Mp {
    type Output = Mp;
    fn add(self, o: Mp) -> Mp {
        Mp(self.0 + o.0)
    }
}
impl Sub for Mp {
    type Output = Mp;
    fn sub(self, o: Mp) -> Mp {
        Mp(self.0 - o.0)
    }
}
impl Mul for Mp {
    type Output = Mp;
    fn mul(self, o: Mp) -> Mp {
        Mp(self.0 * o.0)
    }
}
impl Div for Mp {
    type Output = Mp;
    fn div(self, o: Mp) -> Mp {
        Mp(self.0 / o.0)
    }
}
impl Neg for Mp {
    type Output = Mp;
    fn neg(self) -> Mp {
        Mp(-self.0)
    }
}

thread_local! {
    /// The product of [`Real::add_mul`] and [`Real::sub_mul`] (one per thread, reused).
    static PRODUCT: std::cell::RefCell<Float> = std::cell::RefCell::new(Float::new(64));
}

/// `f(a b)` with a b rounded to `prec` bits in the thread's reused storage.
fn with_product(prec: u32, a: &Mp, b: &Mp, f: impl FnOnce(&Float)) {
    PRODUCT.with(|p| {
        let mut p = p.borrow_mut();
        if p.prec() != prec {
            p.set_prec(prec);
        }
        p.assign(&a.0 * &b.0);
        f(&p);
    });
}

impl AddAssign<&Mp> for Mp {
    fn add_assign(&mut self, o: &Mp) {
        self.0 += &o.0;
    }
}
impl SubAssign<&Mp> for Mp {
    fn sub_assign(&mut self, o: &Mp) {
        self.0 -= &o.0;
    }
}
impl MulAssign<&Mp> for Mp {
    fn mul_assign(&mut self, o: &Mp) {
        self.0 *= &o.0;
    }
}
impl DivAssign<&Mp> for Mp {
    fn div_assign(&mut self, o: &Mp) {
        self.0 /= &o.0;
    }
}

impl Real for Mp {
    fn set(&mut self, v: &Mp) {
        self.0.assign(&v.0);
    }
    fn set_sub(&mut self, a: &Mp, b: &Mp) {
        self.0.assign(&a.0 - &b.0);
    }
    fn set_mul(&mut self, a: &Mp, b: &Mp) {
        self.0.assign(&a.0 * &b.0);
    }
    fn set_mul_add(&mut self, a: &Mp, b: &Mp, c: &Mp) {
        self.0.assign(&a.0 * &b.0);
        self.0 += &c.0;
    }
    fn set_mul_sub(&mut self, a: &Mp, b: &Mp, c: &Mp) {
        self.0.assign(&a.0 * &b.0);
        self.0 -= &c.0;
    }
    fn add_mul(&mut self, a: &Mp, b: &Mp) {
        with_product(self.0.prec(), a, b, |p| self.0 += p);
    }
    fn sub_mul(&mut self, a: &Mp, b: &Mp) {
        with_product(self.0.prec(), a, b, |p| self.0 -= p);
    }
    fn lit(&self, v: f64) -> Mp {
        Mp(Float::with_val(self.0.prec(), v))
    }
    fn sqrt(&self) -> Mp {
        Mp(self.0.clone().sqrt())
    }
    fn exp(&self) -> Mp {
        Mp(mp_elementary::exp(&self.0))
    }
    fn ln(&self) -> Mp {
        Mp(mp_elementary::ln(&self.0))
    }
    fn ln_1p(&self) -> Mp {
        Mp(mp_elementary::ln_1p(&self.0))
    }
    fn powr(&self, e: &Mp) -> Mp {
        Mp(mp_elementary::pow(&self.0, &e.0))
    }
    fn cos(&self) -> Mp {
        Mp(self.0.clone().cos())
    }
    fn sin(&self) -> Mp {
        Mp(self.0.clone().sin())
    }
    fn tan(&self) -> Mp {
        Mp(self.0.clone().tan())
    }
    fn atan(&self) -> Mp {
        Mp(self.0.clone().atan())
    }
    fn pi(&self) -> Mp {
        Mp(Float::with_val(self.0.prec(), rug::float::Constant::Pi))
    }
    fn abs(&self) -> Mp {
        Mp(self.0.clone().abs())
    }
    fn to_f64(&self) -> f64 {
        self.0.to_f64()
    }
    fn bits(&self) -> u32 {
        self.0.prec()
    }
}
