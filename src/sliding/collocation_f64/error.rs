//! Why the f64 method returns no solution, and how each reason maps to the project's
//! [`crate::error::Error`] kinds (input / no solution / not physical / no convergence).

use crate::numerics::accuracy::readable_f64;
use crate::numerics::gauss_jacobi_f64::QuadratureError;
use crate::numerics::roots::RootError;

/// Why no solution is returned.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SlidingF64Error {
    /// An input outside the range of the method: outside the `f64` range, or |theta| within
    /// [`crate::params::sliding::THETA_MARGIN`] of 1/2 (from
    /// [`crate::params::sliding::SlidingParamsF64::new`]; always [`crate::error::Error::Input`]).
    #[error(transparent)]
    Input(crate::error::Error),
    /// A requested output point outside (-1, 1).
    #[error("invalid point xh = {value}: must lie in (-1, 1)")]
    InvalidPoint {
        /// The point.
        value: f64,
    },
    /// No physical contact: the shared criterion's refusal with the admissible range
    /// ([`crate::sliding::physicality::refusal`]), in its own kind.
    #[error(transparent)]
    Refused(crate::error::Error),
    /// No root of the sinusoid's side conditions reaches this load on the scan of lambda (the
    /// largest load seen is `largest`). [`super::solve_sliding_f64`] turns it into a refusal
    /// with the admissible range ([`SlidingF64Error::Refused`]).
    #[error("no solution: no root reaches normal_load = {load} (largest load on the scan {largest})")]
    NoRoot {
        /// Requested P2.
        load: f64,
        /// Largest load on the scan (physical or not).
        largest: f64,
    },
    /// The iteration or the node refinement did not reach the accuracy.
    #[error("did not converge: {reason}")]
    NoConvergence {
        /// Why.
        reason: String,
    },
    /// The quadrature rule could not be built.
    #[error(transparent)]
    Quadrature(#[from] QuadratureError),
}

impl From<crate::error::Error> for SlidingF64Error {
    fn from(e: crate::error::Error) -> Self {
        SlidingF64Error::Input(e)
    }
}

/// Each reason keeps its kind: input errors stay [`crate::error::Error::Input`], a load above
/// the sinusoid's maximum is [`crate::error::Error::NoSolution`], a contact leaving the cell or no
/// physical root is [`crate::error::Error::NotPhysical`], the rest is
/// [`crate::error::Error::NoConvergence`]. Numbers are printed readably
/// ([`readable_f64`]: 7 significant digits).
impl From<SlidingF64Error> for crate::error::Error {
    fn from(e: SlidingF64Error) -> Self {
        use crate::error::Error;
        match e {
            SlidingF64Error::Input(e) => e,
            SlidingF64Error::InvalidPoint { value } => {
                Error::input("xh (output point)", readable_f64(value), "must lie in (-1, 1)")
            }
            SlidingF64Error::Refused(e) => e,
            SlidingF64Error::NoRoot { load, largest } => Error::NoSolution {
                why: format!(
                    "no root reaches normal_load = {} (largest load on the scan {})",
                    readable_f64(load),
                    readable_f64(largest)
                ),
            },
            SlidingF64Error::NoConvergence { reason } => Error::NoConvergence { what: reason },
            SlidingF64Error::Quadrature(q) => Error::NoConvergence { what: q.to_string() },
        }
    }
}

/// Result of the f64 method.
pub type Result<T> = std::result::Result<T, SlidingF64Error>;

/// A failure of [`crate::numerics::roots::brent`] on the scalar equation in lambda: the
/// function's own error passes through; a lost bracket or too many steps is non-convergence.
pub(super) fn root_error(e: RootError<SlidingF64Error>) -> SlidingF64Error {
    match e {
        RootError::Function(e) => e,
        other => SlidingF64Error::NoConvergence { reason: format!("lambda: {other}") },
    }
}
