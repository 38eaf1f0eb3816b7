//! General convex profiles in the exact reduction (THEORY.md section 9): the polynomial
//! g = sum_j c_j x^j and the circle g = R - sqrt(R^2 - x^2).
//!
//! Section 3's reduction holds for any g: only g'(x(u)) changes. It is evaluated exactly at
//! working precision at every node, for every (lambda, c) (Horner's rule on the exact-then-rounded
//! coefficients of g'; x/sqrt(R^2 - x^2) for the circle). Without a slope basis the imaginary part
//! of [2.14] is not affine (parabola) or trigonometric (sinusoid) in c, so the centre at a given
//! size is found by Newton's method: the residual S(c) = Im[2.14] + beta tau0 (with the `periodic`
//! convention's K, [`super::equation::closed_terms`]) is linear in g', so
//!     dS/dc = the same integral with g''(x(u)) in place of g'(x(u)),
//! and one pass over the nodes gives both. Odd terms move the centre even without friction; the
//! start c = 0 is refined until the step is below 2^-(prec-8) l (quadratic convergence).

use super::contact::Size;
use super::equation::{closed_terms, kernel_sums, ShiftSolution};
use crate::numerics::gauss_jacobi_mpfr::GaussJacobiRule;
use crate::params::sliding::{ShapeMpfr, SlidingParamsMpfr};
use rug::Float;

/// Most Newton steps for the centre.
const CENTRE_STEPS: usize = 60;

/// A polynomial or circular profile (evaluated directly; no slope basis).
pub fn is_general(shape: &ShapeMpfr) -> bool {
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
pub fn profile_slope(shape: &ShapeMpfr, x: &Float, wp: u32) -> Float {
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
pub fn profile_curvature(shape: &ShapeMpfr, x: &Float, wp: u32) -> Float {
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

/// g' of the punch row at x (THEORY.md section 9: the profile on the cell (-L/2, L/2) repeated
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
    if let ShapeMpfr::Circular { r } = &params.shape {
        if Float::with_val(wp, x.abs_ref()) >= *r {
            let inf = Float::with_val(wp, rug::float::Special::Infinity);
            return if x.is_sign_negative() { -inf } else { inf };
        }
    }
    profile_slope(&params.shape, &x, wp)
}

/// The contact [c - l, c + l] lies where the profile is defined (the circle: |x| < R).
fn defined_at(params: &SlidingParamsMpfr, l: &Float, c: &Float) -> bool {
    match &params.shape {
        ShapeMpfr::Circular { r } => Float::with_val(params.prec, c.abs_ref()) + l < *r,
        _ => true,
    }
}

/// The centre c solving the imaginary part of [2.14] at this size, and the load it carries
/// (Newton's method from c = 0, module doc). None when the iteration leaves the region where the
/// profile is defined (the circle: the contact would reach |x| = R) or does not converge.
pub fn centre(params: &SlidingParamsMpfr, size: &Size, rule: &GaussJacobiRule) -> Option<ShiftSolution> {
    let p = params.prec;
    let terms_at = |c: &Float| {
        let raw = kernel_sums(params, size, rule, |u, wp| {
            let x = Float::with_val(wp, size.offset(params, u, wp) + c);
            [profile_slope(&params.shape, &x, wp), profile_curvature(&params.shape, &x, wp)]
        });
        closed_terms(params, size, &raw)
    };
    let tol = Float::with_val(p, Float::with_val(p, &size.l) >> (p as i32 - 8).max(1));
    let mut c = Float::with_val(p, 0);
    if !defined_at(params, &size.l, &c) {
        return None;
    }
    for _ in 0..CENTRE_STEPS {
        let (t, bt) = terms_at(&c);
        let s = Float::with_val(p, &t.im[0] + &bt);
        let ds = &t.im[1];
        if !(s.is_finite() && ds.is_finite()) || ds.is_zero() {
            return None;
        }
        let mut step = Float::with_val(p, &s / ds);
        // Halve a step that would leave the region where g is defined.
        let mut next = Float::with_val(p, &c - &step);
        let mut halvings = 0;
        while !defined_at(params, &size.l, &next) {
            step /= 2u32;
            next = Float::with_val(p, &c - &step);
            halvings += 1;
            if halvings > 60 {
                return None;
            }
        }
        c = next;
        if Float::with_val(p, step.abs_ref()) <= tol {
            let (t, _) = terms_at(&c);
            return t.re[0].is_finite().then(|| ShiftSolution { c, p2: t.re[0].clone() });
        }
    }
    None
}
