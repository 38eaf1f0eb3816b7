//! The command line, in two stages (ripgrep style): raw clap arguments ([`args`]) are validated
//! into a typed configuration ([`config`]) before any work; invalid input is an [`InvalidInput`]
//! naming the parameter, its value and the valid range (exit code 2).

pub mod args;
pub mod config;

/// Invalid user input: exit code 2.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("invalid {parameter} = {value}: {expected}")]
pub struct InvalidInput {
    /// The flag or scene key.
    pub parameter: String,
    /// The value as given.
    pub value: String,
    /// The valid range in words.
    pub expected: String,
}

impl InvalidInput {
    /// Builds the error.
    pub fn new(parameter: impl Into<String>, value: impl ToString, expected: impl Into<String>) -> Self {
        InvalidInput { parameter: parameter.into(), value: value.to_string(), expected: expected.into() }
    }
}

impl From<crate::model::ModelError> for InvalidInput {
    fn from(e: crate::model::ModelError) -> Self {
        InvalidInput { parameter: e.parameter, value: e.value, expected: e.expected }
    }
}
