//! General convex profiles in the exact reduction (docs/theory.md section 9): the polynomial
//! g = sum_j c_j x^j and the circle g = R - sqrt(R^2 - x^2).
//!
//! Section 3's reduction holds for any g: only g'(x(u)) changes. It is evaluated exactly at
//! working precision at every node, for every (lambda, c) (Horner's rule on the exact-then-rounded
//! coefficients of g'; x/sqrt(R^2 - x^2) for the circle). Without a slope basis the imaginary part
//! of [2.14] is not affine (parabola) or trigonometric (sinusoid) in c: the centre at a given size
//! is found by Newton's method ([`super::centre`]) with g'' from here.

use crate::params::sliding::{ShapeMpfr, SlidingParamsMpfr};
use rug::Float;

/// A polynomial or circular profile (evaluated directly; no slope basis).
pub(crate) fn is_general(shape: &ShapeMpfr) -> bool {
    matches!(shape, ShapeMpfr::Polynomial { .. } | ShapeMpfr::Circular { .. })
}

fn horner(c: &[Float], x: &Float, wp: u32) -> Float {
    let mut acc = Float::with_val(wp, 0);
    for v in c.iter().rev() {
        acc *= x;
        acc += v;
    }
    acc
}

/// g'(x) at precision `wp` (the analytic profile, not reduced to the cell): sum_j slope_j x^j,
/// or x/sqrt(R^2 - x^2) (NaN for |x| >= R, where the circle has no real continuation).
/// The parabola and the sinusoid use their slope basis ([`super::contact`]); here they give NaN.
pub(crate) fn profile_slope(shape: &ShapeMpfr, x: &Float, wp: u32) -> Float {
    match shape {
        ShapeMpfr::Polynomial { slope, .. } => horner(slope, x, wp),
        ShapeMpfr::Circular { r } => {
            let s = Float::with_val(wp, Float::with_val(wp, r - x) * Float::with_val(wp, r + x)).sqrt();
            Float::with_val(wp, x / s)
        }
        _ => Float::with_val(wp, rug::float::Special::Nan),
    }
}

/// g''(x) at precision `wp`: sum_j curvature_j x^j, or R^2/(R^2 - x^2)^(3/2) (NaN for |x| >= R).
pub(crate) fn profile_curvature(shape: &ShapeMpfr, x: &Float, wp: u32) -> Float {
    match shape {
        ShapeMpfr::Polynomial { curvature, .. } => horner(curvature, x, wp),
        ShapeMpfr::Circular { r } => {
            let d = Float::with_val(wp, Float::with_val(wp, r - x) * Float::with_val(wp, r + x));
            let d32 = Float::with_val(wp, &d * Float::with_val(wp, d.sqrt_ref()));
            Float::with_val(wp, r.square_ref()) / d32
        }
        _ => Float::with_val(wp, rug::float::Special::Nan),
    }
}

/// g' of the punch row at x, any shape (docs/theory.md sections 1, 9: the profile on the cell (-L/2, L/2) repeated
/// with period L): x is reduced to the cell first. For the circle, where the cell reaches beyond
/// |x| >= R there is no punch (its wall is vertical at |x| = R): +infinity for x >= R and
/// -infinity for x <= -R, so that a gap integrated outward from the contact becomes +infinity.
pub fn row_slope(params: &SlidingParamsMpfr, x: &Float, wp: u32) -> Float {
    let x = match &params.period {
        Some(big_l) => {
            let n = Float::with_val(wp, x / big_l).round();
            Float::with_val(wp, x - Float::with_val(wp, &n * big_l))
        }
        None => Float::with_val(wp, x),
    };
    match (&params.shape, &params.period) {
        (ShapeMpfr::Circular { r }, _) if Float::with_val(wp, x.abs_ref()) >= *r => {
            let inf = Float::with_val(wp, rug::float::Special::Infinity);
            if x.is_sign_negative() {
                -inf
            } else {
                inf
            }
        }
        // 2 k x (reduced), and (2 pi D/L) sin(2 pi x/L) [2.16].
        (ShapeMpfr::Parabolic { k }, _) => Float::with_val(wp, k * &x) * 2u32,
        (ShapeMpfr::Sinusoidal { d }, Some(big_l)) => {
            let w = Float::with_val(wp, &params.pi * 2u32) / big_l;
            Float::with_val(wp, Float::with_val(wp, &w * &x).sin() * &w) * d
        }
        _ => profile_slope(&params.shape, &x, wp),
    }
}
