//! The project's one error type, end to end: every library failure is one of four kinds, and the
//! command line maps each kind to its exit code in one place (`main.rs`): invalid input -> 2,
//! everything else -> 1.

use crate::model::ModelError;

/// Why a problem could not be answered.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// An input (or a parameter derived from the inputs alone) outside its valid range: names the
    /// parameter, its value and the valid range.
    #[error(transparent)]
    Input(#[from] ModelError),
    /// The equations have no solution at these inputs (e.g. no contact carries the load).
    #[error("no solution: {why}")]
    NoSolution {
        /// Why, with the limit that was computed (e.g. the largest load the punch carries).
        why: String,
    },
    /// A solution of the equations exists but is not physical (negative pressure, the contact
    /// leaving the cell, a negative gap).
    #[error("not physical: {why}")]
    NotPhysical {
        /// What failed, where, and the admissible range of the load or size when it is known.
        why: String,
    },
    /// A method did not converge to the accuracy asked.
    #[error("no convergence: {what}")]
    NoConvergence {
        /// What did not converge, and what would help.
        what: String,
    },
}

/// Which kind of failure an [`Error`] is (for the exit code and for tests).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ErrorKind {
    /// [`Error::Input`].
    Input,
    /// [`Error::NoSolution`].
    NoSolution,
    /// [`Error::NotPhysical`].
    NotPhysical,
    /// [`Error::NoConvergence`].
    NoConvergence,
}

impl Error {
    /// An input error naming `parameter`, its `value` and the valid range `expected`.
    pub fn input(parameter: impl Into<String>, value: impl ToString, expected: impl Into<String>) -> Self {
        Error::Input(ModelError::new(parameter, value, expected))
    }

    /// The kind of this error.
    pub fn kind(&self) -> ErrorKind {
        match self {
            Error::Input(_) => ErrorKind::Input,
            Error::NoSolution { .. } => ErrorKind::NoSolution,
            Error::NotPhysical { .. } => ErrorKind::NotPhysical,
            Error::NoConvergence { .. } => ErrorKind::NoConvergence,
        }
    }
}
