//! The number type of the spectral method (`spectral.rs`): one trait over `f64` and MPFR
//! ([`Mp`], a `rug::Float` whose results keep the precision of the left operand), so the same
//! code runs in both and the two runs can be compared digit by digit.
//!
//! Only what the method needs: the four operations, powers with a real exponent, sqrt, exp, ln,
//! ln(1 + x), cos, sin, atan, pi, and literals at the precision of a given number
//! ([`Real::lit`]). No equations of the physics here.

use std::ops::{Add, Div, Mul, Neg, Sub};

use rug::ops::Pow;
use rug::Float;

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
{
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

impl Real for Mp {
    fn lit(&self, v: f64) -> Mp {
        Mp(Float::with_val(self.0.prec(), v))
    }
    fn sqrt(&self) -> Mp {
        Mp(self.0.clone().sqrt())
    }
    fn exp(&self) -> Mp {
        Mp(self.0.clone().exp())
    }
    fn ln(&self) -> Mp {
        Mp(self.0.clone().ln())
    }
    fn ln_1p(&self) -> Mp {
        Mp(self.0.clone().ln_1p())
    }
    fn powr(&self, e: &Mp) -> Mp {
        Mp(self.0.clone().pow(&e.0))
    }
    fn cos(&self) -> Mp {
        Mp(self.0.clone().cos())
    }
    fn sin(&self) -> Mp {
        Mp(self.0.clone().sin())
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
