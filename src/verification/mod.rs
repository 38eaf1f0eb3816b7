//! Verification: the exact series against the full solutions, term by term.

pub mod convergence;
mod mpfr_error;
