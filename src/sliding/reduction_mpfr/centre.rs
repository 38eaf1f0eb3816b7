//! The centre of a polynomial or circular punch's contact at a given size (docs/theory.md section 9).
//! The residual S(c) = Im[2.14] + beta tau0 (with the `periodic` convention's K,
//! [`super::equation::closed_terms`]) is linear in g', so
//!     dS/dc = the same integral with g''(x(u)) in place of g'(x(u)),
//! and one pass over the nodes gives both (g', g'' from [`super::profile`]). Odd terms move the
//! centre even without friction; Newton's method from c = 0 runs until the step is below
//! 2^-(prec-8) l (quadratic convergence).

use super::contact::Size;
use super::equation::{closed_terms, kernel_sums, ShiftSolution};
use super::profile::{profile_curvature, profile_slope};
use crate::numerics::gauss_jacobi_mpfr::GaussJacobiRule;
use crate::params::sliding::{ShapeMpfr, SlidingParamsMpfr};
use rug::Float;

/// Most Newton steps for the centre.
const CENTRE_STEPS: usize = 60;

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
    // The step's floor: 2^-(prec-8) of max(l, |c|). A centre far off the contact's own size (adhesive
    // friction at a tiny contact: c = -100 l) carries round-off of |c|, not of l; a floor of l
    // alone was never reached (issue 34, fuzzing: l = 2.2e-11, c = -2.5e-9 refused as "no centre").
    let tol = |c: &Float| {
        let big =
            if Float::with_val(p, c.abs_ref()) > size.l { Float::with_val(p, c.abs_ref()) } else { size.l.clone() };
        Float::with_val(p, big >> (p as i32 - 8).max(1))
    };
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
        if Float::with_val(p, step.abs_ref()) <= tol(&c) {
            let (t, _) = terms_at(&c);
            return t.re[0].is_finite().then(|| ShiftSolution { c, p2: t.re[0].clone() });
        }
    }
    None
}
