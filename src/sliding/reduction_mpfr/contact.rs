//! The contact [-a, b] = [c - l, c + l] and the map u -> x(u) of docs/theory.md section 3.
//!
//! Periodic (period L): m = tan(lambda), lambda = pi l / L [2.1], t = tan(pi (x - c)/L) = m u,
//! x(u) = c + (L/pi) arctan(m u), x'(u) = (L/pi) m / (1 + m^2 u^2).
//! Single punch (L = infinity, the Cauchy-kernel limit): x(u) = c + l u, x'(u) = l.
//!
//! The slope of the punch along the contact is written g'(x(u)) = q0 B0(u) + q1 B1(u) with
//! coefficients depending only on c and basis functions depending only on the contact size:
//! - parabola, periodic: q = (2 k c, 2 k), B = (1, (L/pi) arctan(m u));
//! - parabola, single:   q = (2 k c, 2 k), B = (1, l u);
//! - sinusoid [2.16]: with phi = 2 pi c/L and s = m u, sin(2 pi x(u)/L) = sin(phi + 2 arctan s), so
//!   q = (2 pi D/L) (sin phi, cos phi), B = ((1 - s^2)/(1 + s^2), 2 s/(1 + s^2)).
//!
//! A polynomial or circular profile (docs/theory.md section 9) has no such basis: g'(x(u)) is
//! evaluated directly at each node for each (lambda, c) ([`super::profile`]), and the centre is
//! found by Newton's method there.

use super::profile::{is_general, profile_curvature, profile_slope};
use crate::params::sliding::{ShapeMpfr, SlidingParamsMpfr};
use rug::Float;

/// A contact of given size and centre, with the slope coefficients.
#[derive(Debug, Clone)]
pub struct Contact {
    /// Size: lambda, m (periodic) and the half-length l = (a + b)/2.
    pub size: Size,
    /// Centre c = (b - a)/2.
    pub c: Float,
    /// Coefficients (q0, q1) of g'(x(u)) = q0 B0(u) + q1 B1(u).
    pub q: [Float; 2],
}

/// Size-only part of a contact: lambda (periodic) or l (single punch).
#[derive(Debug, Clone)]
pub struct Size {
    /// lambda (periodic) or None.
    pub lambda: Option<Float>,
    /// m = tan(lambda) or None.
    pub m: Option<Float>,
    /// Half-length.
    pub l: Float,
}

impl Size {
    /// From the size parameter s: lambda for a periodic row, l for a single punch.
    pub fn new(params: &SlidingParamsMpfr, s: &Float) -> Self {
        let p = params.prec;
        match &params.period {
            Some(big_l) => {
                let l = Float::with_val(p, s * big_l) / &params.pi;
                Size { lambda: Some(Float::with_val(p, s)), m: Some(Float::with_val(p, s.tan_ref())), l }
            }
            None => Size { lambda: None, m: None, l: Float::with_val(p, s) },
        }
    }

    /// Basis values (B0, B1) at u, at precision `wp`.
    pub fn basis(&self, params: &SlidingParamsMpfr, u: &Float, wp: u32) -> [Float; 2] {
        match (&params.shape, &self.m) {
            (ShapeMpfr::Parabolic { .. }, Some(m)) => {
                let l = params.period.as_ref().expect("periodic");
                let at = Float::with_val(wp, m * u).atan();
                [Float::with_val(wp, 1), at * l / &params.pi]
            }
            (ShapeMpfr::Parabolic { .. }, None) => [Float::with_val(wp, 1), Float::with_val(wp, &self.l * u)],
            (ShapeMpfr::Sinusoidal { .. }, Some(m)) => {
                let s = Float::with_val(wp, m * u);
                let s2 = Float::with_val(wp, s.square_ref());
                let den = Float::with_val(wp, &s2 + 1u32);
                let b0 = Float::with_val(wp, 1u32 - &s2) / &den;
                let b1 = Float::with_val(wp, &s * 2u32) / den;
                [b0, b1]
            }
            (ShapeMpfr::Sinusoidal { .. }, None) => {
                unreachable!("a sinusoid needs a finite period (validated by the model)")
            }
            (ShapeMpfr::Polynomial { .. } | ShapeMpfr::Circular { .. }, _) => {
                unreachable!("general profiles are evaluated directly (Contact::f), not by a slope basis")
            }
        }
    }

    /// Derivatives (B0', B1') at u, at precision `wp`.
    pub(crate) fn basis_derivative(&self, params: &SlidingParamsMpfr, u: &Float, wp: u32) -> [Float; 2] {
        match (&params.shape, &self.m) {
            (ShapeMpfr::Parabolic { .. }, Some(m)) => {
                let l = params.period.as_ref().expect("periodic");
                let s = Float::with_val(wp, m * u);
                let den = Float::with_val(wp, s.square_ref()) + 1u32;
                [Float::with_val(wp, 0), Float::with_val(wp, l * m) / &params.pi / den]
            }
            (ShapeMpfr::Parabolic { .. }, None) => [Float::with_val(wp, 0), Float::with_val(wp, &self.l)],
            (ShapeMpfr::Sinusoidal { .. }, Some(m)) => {
                let s = Float::with_val(wp, m * u);
                let s2 = Float::with_val(wp, s.square_ref());
                let den = Float::with_val(wp, &s2 + 1u32);
                let den2 = Float::with_val(wp, den.square_ref());
                let b0 = -Float::with_val(wp, &s * m) * 4u32 / &den2;
                let b1 = Float::with_val(wp, 1u32 - &s2) * m * 2u32 / den2;
                [b0, b1]
            }
            (ShapeMpfr::Sinusoidal { .. }, None) => unreachable!("a sinusoid needs a finite period"),
            (ShapeMpfr::Polynomial { .. } | ShapeMpfr::Circular { .. }, _) => {
                unreachable!("general profiles are evaluated directly (Contact::f), not by a slope basis")
            }
        }
    }

    /// x(u) - c.
    pub(crate) fn offset(&self, params: &SlidingParamsMpfr, u: &Float, wp: u32) -> Float {
        match &self.m {
            Some(m) => {
                let l = params.period.as_ref().expect("periodic");
                Float::with_val(wp, m * u).atan() * l / &params.pi
            }
            None => Float::with_val(wp, &self.l * u),
        }
    }

    /// x'(u).
    pub fn jacobian(&self, params: &SlidingParamsMpfr, u: &Float, wp: u32) -> Float {
        match &self.m {
            Some(m) => {
                let l = params.period.as_ref().expect("periodic");
                let s = Float::with_val(wp, m * u);
                let den = Float::with_val(wp, s.square_ref()) + 1u32;
                Float::with_val(wp, l * m) / &params.pi / den
            }
            None => Float::with_val(wp, &self.l),
        }
    }

    /// Inverse map: u(x) = tan(pi (x - c)/L)/m (periodic) or (x - c)/l. For periodic rows
    /// x - c must lie in (-L/2, L/2).
    pub(crate) fn u_of(&self, params: &SlidingParamsMpfr, x_minus_c: &Float, wp: u32) -> Float {
        match &self.m {
            Some(m) => {
                let l = params.period.as_ref().expect("periodic");
                let t = Float::with_val(wp, x_minus_c * &params.pi) / l;
                t.tan() / m
            }
            None => Float::with_val(wp, x_minus_c / &self.l),
        }
    }
}

impl Contact {
    /// The contact of size `size` centred at `c`, with the slope coefficients of the shape.
    pub fn new(params: &SlidingParamsMpfr, size: &Size, c: Float) -> Self {
        let p = params.prec;
        let q = match &params.shape {
            ShapeMpfr::Parabolic { k } => [Float::with_val(p, k * &c) * 2u32, Float::with_val(p, k * 2u32)],
            ShapeMpfr::Sinusoidal { d } => {
                let l = params.period.as_ref().expect("periodic");
                let amp = Float::with_val(p, &params.pi * d) * 2u32 / l;
                let phi = Float::with_val(p, &params.pi * &c) * 2u32 / l;
                let (s, co) = phi.sin_cos(Float::new(p));
                [Float::with_val(p, &amp * &s), amp * co]
            }
            // Evaluated directly at x(u) (Contact::f); no basis coefficients.
            ShapeMpfr::Polynomial { .. } | ShapeMpfr::Circular { .. } => [Float::with_val(p, 0), Float::with_val(p, 0)],
        };
        Contact { size: size.clone(), c, q }
    }

    /// F(u) = (E*/2) g'(x(u)) at precision `wp` (the right-hand side of [2.8] without beta tau0), in
    /// units of E* (E* = 1 in the parameters): g'(x(u))/2.
    pub fn f(&self, params: &SlidingParamsMpfr, u: &Float, wp: u32) -> Float {
        if is_general(&params.shape) {
            let x = Float::with_val(wp, self.size.offset(params, u, wp) + &self.c);
            return profile_slope(&params.shape, &x, wp) / 2u32;
        }
        let b = self.size.basis(params, u, wp);
        let v = Float::with_val(wp, &self.q[0] * &b[0]) + Float::with_val(wp, &self.q[1] * &b[1]);
        v / 2u32
    }

    /// F'(u) at precision `wp`.
    pub(crate) fn f_prime(&self, params: &SlidingParamsMpfr, u: &Float, wp: u32) -> Float {
        if is_general(&params.shape) {
            let x = Float::with_val(wp, self.size.offset(params, u, wp) + &self.c);
            let g2 = profile_curvature(&params.shape, &x, wp);
            return g2 * self.size.jacobian(params, u, wp) / 2u32;
        }
        let b = self.size.basis_derivative(params, u, wp);
        let v = Float::with_val(wp, &self.q[0] * &b[0]) + Float::with_val(wp, &self.q[1] * &b[1]);
        v / 2u32
    }

    /// g'(x(u)).
    pub fn slope(&self, params: &SlidingParamsMpfr, u: &Float, wp: u32) -> Float {
        Float::with_val(wp, self.f(params, u, wp) * 2u32)
    }
}
