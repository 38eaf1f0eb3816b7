//! The centre solutions (every branch) of the MPFR reduction at one contact size: the shift
//! equation of [`super::equation`] for the parabola and the sinusoid, Newton's method of
//! [`super::centre`] for general profiles; with a given rule for 1/omega or one of n nodes.
//! Tested through the solver (`tests.rs`).

use super::centre::centre;
use super::contact::Size;
use super::equation::{equation_terms, shift_solutions, ShiftSolution};
use super::error::SlidingError;
use super::profile::is_general;
use crate::numerics::gauss_jacobi_mpfr::{gauss_jacobi, GaussJacobiRule};
use crate::params::sliding::SlidingParamsMpfr;
use rug::Float;
use std::sync::Arc;

/// Rule for 1/omega with n nodes at the parameters' precision.
pub(super) fn inverse_rule(params: &SlidingParamsMpfr, n: usize) -> Result<Arc<GaussJacobiRule>, SlidingError> {
    let (a, b) = params.inverse_weight_exponents();
    Ok(gauss_jacobi(&a, &b, n, params.prec)?)
}

/// Centre solutions (all branches) at size s with n nodes.
pub(super) fn branches(params: &SlidingParamsMpfr, s: &Float, n: usize) -> Result<Vec<ShiftSolution>, SlidingError> {
    branches_with(params, s, &*inverse_rule(params, n)?)
}

/// Centre solutions (all branches) at size s with the rule `rule` for 1/omega.
pub(super) fn branches_with(
    params: &SlidingParamsMpfr,
    s: &Float,
    rule: &GaussJacobiRule,
) -> Result<Vec<ShiftSolution>, SlidingError> {
    let size = Size::new(params, s);
    if is_general(&params.shape) {
        return Ok(centre(params, &size, rule).into_iter().collect());
    }
    Ok(shift_solutions(params, &size, &equation_terms(params, &size, rule)))
}
