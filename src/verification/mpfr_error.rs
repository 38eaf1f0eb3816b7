//! TEMPORARY bridge: `SlidingError -> crate::error::Error`, kind-preserving, so that this branch
//! builds before the branch that moves the MPFR solver to `sliding/reduction_mpfr/` (which
//! defines the same `impl From<SlidingError> for Error` in `sliding/reduction_mpfr/error.rs`) is
//! merged. On merging that branch, delete this file and its `mod mpfr_error;` line in
//! `verification/mod.rs` (the two impls conflict).

use crate::error::Error;
use crate::model::ModelError;
use crate::sliding::SlidingError;

impl From<SlidingError> for Error {
    fn from(e: SlidingError) -> Self {
        match e {
            SlidingError::Parameter { parameter, value, expected } => {
                Error::Input(ModelError { parameter, value, expected })
            }
            e @ SlidingError::ContactOutsidePeriod { .. } => Error::NotPhysical { why: e.to_string() },
            SlidingError::NotPhysical { why } => Error::NotPhysical { why },
            e @ SlidingError::NoSolution { .. } => Error::NoSolution { why: e.to_string() },
            SlidingError::NoConvergence(what) => Error::NoConvergence { what },
            SlidingError::Quadrature(q) => Error::NoConvergence { what: q.to_string() },
        }
    }
}
