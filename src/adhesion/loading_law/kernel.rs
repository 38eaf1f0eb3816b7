//! The increments of the asymmetric incremental method (THEORY.md section 10) in MPFR: the
//! unit-load adhesive flat punch on an off-centre contact and its surface slopes outside it.
//!
//! Variables: chi = pi x/L; the earlier contact has centre gamma = pi c/L and half-length
//! eta = pi l/L; chi' = chi - gamma. Inside (|chi'| < eta), the unit complex load gives
//!   sigma_flat = (cosh(pi eps)/L) cos(chi' - 2 i eps eta) (sin(eta + chi')/sin(eta - chi'))^(i eps)
//!                / sqrt(sin^2 eta - sin^2 chi')                                   (THEORY 4)
//! and a load dP = dP2 + i dP1 gives d sigma = dP sigma_flat (the operator H + i beta of [2.19]
//! is complex-linear). Outside (|chi'| > eta), (E*/2)(dv' - i du') = dP K/L with
//!   K = s cos(chi' - 2 i eps eta) (sin d_far/sin d_near)^(s i eps) / sqrt(sin d_near sin d_far),
//! s = +1 right of the contact (chi' > eta), -1 left of it; d_near = |chi'| - eta > 0 and
//! d_far = |chi'| + eta the distances to the nearer and farther end. For s = +1 this is THEORY
//! 4's K(chi', eta); the left side is its continuation, K(-chi') = -conj K(chi') (Re v' odd, u'
//! even), which THEORY 4 does not state: checked against the direct quadrature of the cot
//! kernel [1.8] in this module's test (and first in mpmath, 30 digits, session 4 notes).
//! Passing d_near (not chi') keeps the singular factor accurate next to the end, where the
//! incremental method evaluates it.

use rug::{Complex, Float};

/// Which side of the earlier contact the point lies on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    /// chi' > eta (toward the leading end b).
    Right,
    /// chi' < -eta (toward the trailing end -a).
    Left,
}

/// L K as a complex number (module doc) at distance `d_near` > 0 from the nearer end of a
/// contact of half-length `eta`, on `side`; `eps` of the material.
pub fn outside_kernel(side: Side, d_near: &Float, eta: &Float, eps: &Float, prec: u32) -> Complex {
    let d_far = Float::with_val(prec, d_near + eta) + eta;
    let chi = match side {
        Side::Right => Float::with_val(prec, d_near + eta),
        Side::Left => -Float::with_val(prec, d_near + eta),
    };
    let (s_near, s_far) = (Float::with_val(prec, d_near.sin_ref()), Float::with_val(prec, d_far.sin_ref()));
    // cos(chi' - 2 i eps eta).
    let arg = Complex::with_val(prec, (chi, Float::with_val(prec, eps * eta) * -2i32));
    let cos = Complex::with_val(prec, arg.cos_ref());
    // (sin d_far/sin d_near)^(+- i eps) = exp(+- i eps ln(ratio)).
    let mut theta = Float::with_val(prec, Float::with_val(prec, &s_far / &s_near).ln_ref()) * eps;
    let mut mag = Float::with_val(prec, &s_near * &s_far).sqrt().recip();
    if side == Side::Left {
        theta = -theta;
        mag = -mag;
    }
    let phase =
        Complex::with_val(prec, (Float::with_val(prec, theta.cos_ref()), Float::with_val(prec, theta.sin_ref())));
    cos * phase * mag
}

/// L sigma_flat (module doc) for the unit complex load at the point whose distances to the
/// trailing and leading ends are `d_left` = eta + chi' and `d_right` = eta - chi' (both > 0, given
/// separately so the end singularities keep their accuracy).
pub fn flat_punch_stress(
    d_left: &Float,
    d_right: &Float,
    eta: &Float,
    eps: &Float,
    cosh_pi_eps: &Float,
    prec: u32,
) -> Complex {
    let chi = Float::with_val(prec, d_left - d_right) / 2u32;
    let (sp, sm) = (Float::with_val(prec, d_left.sin_ref()), Float::with_val(prec, d_right.sin_ref()));
    // sin^2 eta - sin^2 chi' = sin(eta + chi') sin(eta - chi').
    let mag = Float::with_val(prec, &sp * &sm).sqrt().recip() * cosh_pi_eps;
    let theta = Float::with_val(prec, Float::with_val(prec, &sp / &sm).ln_ref()) * eps;
    let arg = Complex::with_val(prec, (chi, Float::with_val(prec, eps * eta) * -2i32));
    let cos = Complex::with_val(prec, arg.cos_ref());
    let phase =
        Complex::with_val(prec, (Float::with_val(prec, theta.cos_ref()), Float::with_val(prec, theta.sin_ref())));
    cos * phase * mag
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::tanh_sinh::TanhSinh;
    use rug::float::Constant;

    const PREC: u32 = 160;

    fn f(v: f64) -> Float {
        Float::with_val(PREC, v)
    }

    /// eps of nu = 0.3: ln(3 - 4 nu)/(2 pi).
    fn eps() -> Float {
        let pi = Float::with_val(PREC, Constant::Pi);
        Float::with_val(PREC, Float::with_val(PREC, 1.8).ln_ref()) / (pi * 2u32)
    }

    /// int over the contact (-eta, eta) of L sigma_flat(xi) w(xi) by tanh-sinh on each half
    /// (the ends are inverse-square-root singular), with chi' = eta (1 - 2 u) mapping.
    fn integrate(eta: &Float, w: impl Fn(&Float) -> Complex) -> Complex {
        let e = eps();
        let ch = Float::with_val(PREC, Float::with_val(PREC, Constant::Pi) * &e).cosh();
        let rule = TanhSinh::new(150, 3.0, PREC);
        let mut acc = Complex::new(PREC);
        // Right half chi' = eta c (c = 1 - s): d_right = eta s, d_left = eta (1 + c); the left
        // half mirrored. s -> 0 is the end, s -> 1 the centre.
        for q in 0..rule.s.len() {
            let near = Float::with_val(PREC, eta * &rule.s[q]);
            let far = Float::with_val(PREC, Float::with_val(PREC, &rule.c[q] + 1u32) * eta);
            for (d_left, d_right, sign) in [(&far, &near, 1i32), (&near, &far, -1)] {
                let chi = Float::with_val(PREC, eta * &rule.c[q]) * sign;
                let sigma = flat_punch_stress(d_left, d_right, eta, &e, &ch, PREC);
                acc += sigma * w(&chi) * Float::with_val(PREC, &rule.w[q] * eta);
            }
        }
        acc
    }

    /// The flat punch carries the unit load, and outside it the direct quadrature of the cot
    /// kernel [1.8], H[sigma_flat](x) = (1/L) int sigma_flat(xi) cot(pi (x - xi)/L) d xi (here
    /// L = pi), equals K/L on both sides (sigma = 0 there, so (E*/2)(v' - i u') = H[sigma]),
    /// near an end (d = 0.01) and far from it, to 1e-40 (a tanh-sinh step 3 times finer than
    /// nominal: the cot factor is nearly singular at d = 0.01).
    #[test]
    fn outside_kernel_equals_direct_quadrature_on_both_sides() {
        let eta = f(0.6);
        // L = pi, so x = chi and int sigma dx = (1/pi) int (L sigma) d chi'.
        let load = integrate(&eta, |_| Complex::with_val(PREC, 1)) / Float::with_val(PREC, Constant::Pi);
        assert!(Float::with_val(PREC, load.real() - 1u32).abs() < 1e-40, "load {load}");
        assert!(load.imag().clone().abs() < 1e-40, "load {load}");
        let e = eps();
        for (side, d) in [(Side::Right, 0.3), (Side::Right, 0.01), (Side::Left, 0.3), (Side::Left, 0.7)] {
            let d = f(d);
            let chi = match side {
                Side::Right => Float::with_val(PREC, &d + &eta),
                Side::Left => -Float::with_val(PREC, &d + &eta),
            };
            // H = (1/L) int sigma(xi) cot(x - xi) d xi = (1/pi^2) int (L sigma) cot d chi' (L = pi).
            let pi = Float::with_val(PREC, Constant::Pi);
            let h = integrate(&eta, |xi| {
                let z = Float::with_val(PREC, &chi - xi);
                Complex::with_val(PREC, Float::with_val(PREC, z.tan_ref()).recip())
            }) / Float::with_val(PREC, &pi * &pi);
            let k = outside_kernel(side, &d, &eta, &e, PREC) / &pi;
            let diff = Float::with_val(PREC, Complex::with_val(PREC, &h - &k).abs_ref());
            assert!(diff < 1e-40, "{side:?} d {d}: {h} vs {k}");
        }
    }
}
