//! Why the f64 method returns no solution, and how each reason maps to the project's
//! [`crate::error::Error`] kinds (input / no solution / not physical / no convergence).

use crate::numerics::accuracy::readable_f64;
use crate::numerics::gauss_jacobi_f64::QuadratureError;
use crate::numerics::roots::RootError;
use crate::params::sliding::SlidingParamsF64;
use std::f64::consts::PI;

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
    /// The periodic parabola's contact leaves the cell (-L/2, L/2) (its periodic extension has
    /// kinks at +-L/2; THEORY.md section 3, Validity).
    #[error("the contact [-a, b] = [{neg_a}, {b}] leaves the cell (-L/2, L/2) = (-{half_period}, {half_period}) of the periodic profile (a parabola, polynomial or circle repeated with period L has kinks at +-L/2); reduce normal_load (or half_length)")]
    ContactLeavesCell {
        /// -a.
        neg_a: f64,
        /// b.
        b: f64,
        /// L/2.
        half_period: f64,
    },
    /// The sinusoid cannot carry this load at these friction and wear values: either P2(lambda)
    /// never reaches it, or the solutions that reach it are not physical (p < 0 at an end or a
    /// negative gap). `max_load` is the largest (physical, when known) load, reached at the
    /// contact fraction `max_fraction` = 2 l/L.
    #[error("no solution: normal_load = {load} exceeds the maximum load {max_load} this sinusoid carries with a physical contact at theta = {theta}, tau0 = {tau0} (reached at contact fraction 2l/L = {max_fraction})")]
    LoadExceedsMaximum {
        /// Requested P2.
        load: f64,
        /// Largest load found (physical or not).
        max_load: f64,
        /// theta.
        theta: f64,
        /// tau0.
        tau0: f64,
        /// Largest contact fraction scanned.
        max_fraction: f64,
    },
    /// Solutions exist but none is physical.
    #[error("no physical solution: {reason}")]
    NotPhysical {
        /// What failed (p < 0 inside or gap < 0 outside, where).
        reason: String,
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

impl SlidingF64Error {
    /// [`SlidingF64Error::LoadExceedsMaximum`]: the load `load` is above `max_load`, reached at
    /// lambda (contact fraction 2 lambda/pi).
    pub(super) fn load_exceeds_maximum(prm: &SlidingParamsF64, load: f64, max_load: f64, lambda: f64) -> Self {
        SlidingF64Error::LoadExceedsMaximum {
            load,
            max_load,
            theta: prm.theta,
            tau0: prm.tau0,
            max_fraction: 2.0 * lambda / PI,
        }
    }
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
            SlidingF64Error::ContactLeavesCell { neg_a, b, half_period } => Error::NotPhysical {
                why: format!(
                    "the contact [-a, b] = [{}, {}] leaves the cell (-L/2, L/2) = (-{h}, {h}) of the periodic profile (a parabola, polynomial or circle repeated with period L has kinks at +-L/2); reduce normal_load (or half_length)",
                    readable_f64(neg_a),
                    readable_f64(b),
                    h = readable_f64(half_period)
                ),
            },
            SlidingF64Error::LoadExceedsMaximum { load, max_load, theta, tau0, max_fraction } => Error::NoSolution {
                why: format!(
                    "normal_load = {} exceeds the maximum load {} this sinusoid carries with a physical contact at theta = {}, tau0 = {} (reached at contact fraction 2l/L = {})",
                    readable_f64(load),
                    readable_f64(max_load),
                    readable_f64(theta),
                    readable_f64(tau0),
                    readable_f64(max_fraction)
                ),
            },
            SlidingF64Error::NotPhysical { reason } => Error::NotPhysical { why: reason },
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
