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

impl From<AdhesionError> for crate::error::Error {
    /// Keeps the kind: an invalid problem or argument is an input error (exit code 2); a method
    /// outside its well-conditioned range or an iteration that stopped is a failure to converge
    /// (the equations have a solution for every contact 0 <= lambda < pi/2 and every load).
    fn from(e: AdhesionError) -> Self {
        use crate::error::Error;
        match e {
            AdhesionError::Model(m) => Error::Input(m),
            AdhesionError::InvalidArgument { parameter, value, expected } => Error::input(parameter, value, expected),
            e @ (AdhesionError::IllConditioned { .. } | AdhesionError::NotConverged { .. }) => {
                Error::NoConvergence { what: e.to_string() }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::ErrorKind;

    #[test]
    fn adhesion_error_kinds_are_kept() {
        let input = AdhesionError::InvalidArgument { parameter: "points", value: "11/10".into(), expected: "x".into() };
        let e: crate::error::Error = input.into();
        assert_eq!(e.kind(), ErrorKind::Input);
        assert_eq!(e.to_string(), "invalid points = 11/10: x");
        let ill = AdhesionError::IllConditioned {
            method: "f64-series",
            parameter: "lambda",
            value: "0.8".into(),
            valid: "v".into(),
            reason: "r".into(),
        };
        let e: crate::error::Error = ill.into();
        assert_eq!(e.kind(), ErrorKind::NoConvergence);
        assert!(e.to_string().starts_with("no convergence: f64-series: lambda = 0.8 is outside"), "{e}");
        let nc = AdhesionError::NotConverged { what: "collocation solve", reason: "r".into() };
        assert_eq!(crate::error::Error::from(nc).kind(), ErrorKind::NoConvergence);
    }
}
