//! Errors of the adhesion solvers: each names the parameter, its value and the valid range, or
//! says why an iteration did not converge.

use crate::model::ModelError;

/// Why an adhesion computation could not return trustworthy digits.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum AdhesionError {
    /// Invalid problem statement.
    #[error(transparent)]
    Model(#[from] ModelError),
    /// An argument of a solver outside its valid range.
    #[error("invalid {parameter} = {value}: {expected}")]
    InvalidArgument {
        /// Parameter name.
        parameter: &'static str,
        /// Value as given.
        value: String,
        /// Valid range in words.
        expected: String,
    },
    /// The method cannot reach the requested accuracy here (too many nodes, series too slow).
    #[error("{method}: {parameter} = {value} is outside the range where this method is well conditioned ({valid}): {reason}")]
    IllConditioned {
        /// Method name.
        method: &'static str,
        /// Parameter responsible (e.g. "lambda").
        parameter: &'static str,
        /// Its value.
        value: String,
        /// The range in which the method works.
        valid: String,
        /// Why.
        reason: String,
    },
    /// An iteration (Newton for the half-width, a linear solve) failed.
    #[error("{what} did not converge: {reason}")]
    NotConverged {
        /// What was iterated.
        what: &'static str,
        /// Why it stopped.
        reason: String,
    },
}
