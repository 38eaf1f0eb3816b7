//! Errors of the high-precision sliding solver: each names the parameter, its value and the valid
//! range, or why a solver did not converge. Every variant converts into the project's
//! [`crate::error::Error`] with its kind (input, no solution, not physical, no convergence).

use crate::error::Error;
use crate::model::ModelError;
use crate::numerics::gauss_jacobi_mpfr::QuadratureError;

/// Why Problem 1 could not be solved (docs/theory.md section 3).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SlidingError {
    /// An input (or a derived parameter) outside the range the method handles.
    #[error("invalid {parameter} = {value}: {expected}")]
    Parameter {
        /// Name of the parameter (scene key or derived quantity such as "theta").
        parameter: String,
        /// Its value, printed readably.
        value: String,
        /// The valid range, in words.
        expected: String,
    },
    /// No physical contact carries the requested load.
    #[error("no physical contact carries normal_load = {load}: {why}")]
    NoSolution {
        /// The requested load P2 as given, readable (in the user's units).
        load: String,
        /// Why (e.g. the maximum load this sinusoid carries at these friction and wear values,
        /// in the user's units).
        why: String,
    },
    /// A root finder or rule did not converge.
    #[error("no convergence: {0}")]
    NoConvergence(String),
    /// The quadrature rule could not be built.
    #[error(transparent)]
    Quadrature(#[from] QuadratureError),
    /// A failure of a shared stage (e.g. the derived parameters), with its own kind.
    #[error(transparent)]
    Core(Error),
}

impl SlidingError {
    /// A parameter error.
    pub fn parameter(parameter: impl Into<String>, value: impl ToString, expected: impl Into<String>) -> Self {
        SlidingError::Parameter { parameter: parameter.into(), value: value.to_string(), expected: expected.into() }
    }
}

/// Kind-preserving conversion (the `Display` of [`Error`] adds the kind's prefix, so the text
/// carried here does not repeat it).
impl From<SlidingError> for Error {
    fn from(e: SlidingError) -> Self {
        match e {
            SlidingError::Parameter { parameter, value, expected } => {
                Error::Input(ModelError { parameter, value, expected })
            }
            SlidingError::NoSolution { load, why } => {
                Error::NoSolution { why: format!("no physical contact carries normal_load = {load}: {why}") }
            }
            SlidingError::NoConvergence(what) => Error::NoConvergence { what },
            SlidingError::Quadrature(q) => Error::NoConvergence { what: q.to_string() },
            SlidingError::Core(e) => e,
        }
    }
}

/// An input refused by a shared stage (the derived parameters, [`crate::params::sliding`]) is a
/// [`SlidingError::Parameter`]; any other kind is carried as it is.
impl From<Error> for SlidingError {
    fn from(e: Error) -> Self {
        match e {
            Error::Input(m) => SlidingError::Parameter { parameter: m.parameter, value: m.value, expected: m.expected },
            other => SlidingError::Core(other),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::ErrorKind;

    #[test]
    fn every_variant_keeps_its_kind_and_no_prefix_is_doubled() {
        let cases = [
            (SlidingError::parameter("points", "1", "must lie in (-1, 1)"), ErrorKind::Input),
            (SlidingError::NoSolution { load: "7/3".into(), why: "at most P2 = 1.5".into() }, ErrorKind::NoSolution),
            (SlidingError::NoConvergence("secant".into()), ErrorKind::NoConvergence),
        ];
        for (e, kind) in cases {
            let core = Error::from(e);
            assert_eq!(core.kind(), kind, "{core}");
            let text = core.to_string();
            for prefix in ["no solution: no solution", "not physical: not physical", "no convergence: no convergence"] {
                assert!(!text.starts_with(prefix), "{text}");
            }
        }
        let e = Error::from(SlidingError::NoSolution { load: "7/3".into(), why: "at most P2 = 1.5".into() });
        assert_eq!(e.to_string(), "no solution: no physical contact carries normal_load = 7/3: at most P2 = 1.5");
    }
}
