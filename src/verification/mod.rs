//! Verification: the exact series against the full solutions, term by term; closed forms computed
//! independently of the solvers.

pub mod closed_form_load;
pub mod convergence;
pub(crate) mod law_limits;
pub mod pade;
