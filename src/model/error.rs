//! Errors of the problem statement: each names the parameter, the value and the valid range.

/// An input outside its valid range.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("invalid {parameter} = {value}: {expected}")]
pub struct ModelError {
    /// Name of the parameter as the user wrote it (scene key or CLI flag).
    pub parameter: String,
    /// The value as given.
    pub value: String,
    /// The valid range, in words (e.g. "must lie in [0, 1/2]").
    pub expected: String,
}

impl ModelError {
    /// Builds an error for `parameter` with value `value` and the valid range `expected`.
    pub fn new(parameter: impl Into<String>, value: impl ToString, expected: impl Into<String>) -> Self {
        ModelError { parameter: parameter.into(), value: value.to_string(), expected: expected.into() }
    }
}
