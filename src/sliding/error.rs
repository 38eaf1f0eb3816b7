//! Errors of the high-precision sliding solver: each names the parameter, its value and the valid
//! range, or why a solver did not converge.

use crate::numerics::gauss_jacobi_mpfr::QuadratureError;

/// Why Problem 1 could not be solved (THEORY.md section 3).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SlidingError {
    /// An input (or a derived parameter) outside the range the method handles.
    #[error("invalid {parameter} = {value}: {expected}")]
    Parameter {
        /// Name of the parameter (scene key or derived quantity such as "theta").
        parameter: String,
        /// Its value, printed.
        value: String,
        /// The valid range, in words.
        expected: String,
    },
    /// The periodic parabola's contact would leave (-L/2, L/2), where the periodic extension of
    /// g = k x^2 has kinks (THEORY.md section 3, "Validity").
    #[error("the contact [{left}, {right}] leaves (-L/2, L/2) = (-{half_period}, {half_period}): the periodic parabola is not valid there (reduce the load or the contact size)")]
    ContactOutsidePeriod {
        /// -a.
        left: String,
        /// b.
        right: String,
        /// L/2.
        half_period: String,
    },
    /// The solution of the equations is not physical.
    #[error("the solution is not physical: {why}")]
    NotPhysical {
        /// What failed (negative pressure at a point, or a negative gap outside the contact).
        why: String,
    },
    /// No physical contact carries the requested load.
    #[error("no physical solution at normal_load = {load}: {why}")]
    NoSolution {
        /// The requested load P2.
        load: String,
        /// Why (e.g. the maximum load this sinusoid carries at these friction and wear values).
        why: String,
    },
    /// A root finder or rule did not converge.
    #[error("no convergence: {0}")]
    NoConvergence(String),
    /// The quadrature rule could not be built.
    #[error(transparent)]
    Quadrature(#[from] QuadratureError),
}

impl SlidingError {
    /// A parameter error.
    pub fn parameter(parameter: impl Into<String>, value: impl ToString, expected: impl Into<String>) -> Self {
        SlidingError::Parameter { parameter: parameter.into(), value: value.to_string(), expected: expected.into() }
    }
}
