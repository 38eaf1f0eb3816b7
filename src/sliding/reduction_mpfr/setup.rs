//! The inputs of one solve, built once: the problem's derived parameters
//! ([`SlidingParamsMpfr`], in units of E*, docs/theory.md sections 1 and 3) at the locating stage's
//! precision, plus what only this solver needs (the load in `f64` for that stage, the load as the
//! user wrote it for messages). The working-precision parameters are built once per run by
//! [`super::verify::solve_verified`] and [`super::solve::solve_at`].
//!
//! The problem was validated when it was built (the model); only the derived theta is checked
//! here, by [`SlidingParamsMpfr::new`].

use super::error::SlidingError;
use crate::model::OnPunchRow;
use crate::model::{SlidingLoad, SlidingProblem};
use crate::numerics::exact::to_f64;
use crate::params::sliding::SlidingParamsMpfr;

pub use crate::model::Convention;

/// Precision of the locating stage (bits).
pub const LOCATE_PREC: u32 = 64;

/// One solve's locating stage: the parameters at [`LOCATE_PREC`] bits and the given load.
#[derive(Debug, Clone)]
pub struct Setup {
    /// The problem's parameters at [`LOCATE_PREC`] bits (locating, screening of roots, the
    /// maximum-load search of error messages).
    pub locate: SlidingParamsMpfr,
    /// The given load P2/E* rounded once to `f64` from its exact value (None: half-length given).
    pub target: Option<f64>,
    /// The given load P2 as the user wrote it, readable (for messages; None: half-length given).
    pub load_text: Option<String>,
    /// The problem as given (for the refusals of a general profile on its contact,
    /// [`crate::params::sliding::check_profile_on_contact`]).
    pub problem: SlidingProblem,
}

impl Setup {
    /// Builds the locating stage of `problem`. Errors when |theta| is within
    /// [`crate::params::sliding::THETA_MARGIN`] of 1/2, or the load P2/E* is beyond the `f64` range.
    pub fn new(problem: &SlidingProblem) -> Result<Self, SlidingError> {
        let locate = SlidingParamsMpfr::new(problem, LOCATE_PREC)?;
        let (target, load_text) = match problem.load() {
            SlidingLoad::NormalLoad(p2) => {
                // Rounded once from the exact P2/E* (the same quotient the parameters round).
                let per_e_star = p2 / problem.material().contact_modulus();
                let t = to_f64(&per_e_star).filter(|v| v.is_finite() && *v > 0.0).ok_or_else(|| {
                    SlidingError::parameter(
                        "normal_load",
                        crate::model::readable(p2),
                        "P2/E* must lie in the f64 range (about 1e-308 to 1e308)",
                    )
                })?;
                (Some(t), Some(crate::model::readable(p2)))
            }
            SlidingLoad::HalfLength(_) => (None, None),
        };
        Ok(Setup { locate, target, load_text, problem: problem.clone() })
    }
}
