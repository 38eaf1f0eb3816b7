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

/// An exact value for a message: its own text when short (`7/3`, `0.25` as `1/4`), otherwise 7
/// significant digits (`1.000000e-400`), never a 400-digit expansion.
pub fn readable(q: &super::Exact) -> String {
    let text = q.to_string();
    if text.len() <= 24 {
        return text;
    }
    let r = rug::Rational::from((
        rug::Integer::from_str_radix(&q.numer().to_str_radix(16), 16).unwrap_or_default(),
        rug::Integer::from_str_radix(&q.denom().to_str_radix(16), 16).unwrap_or_else(|_| rug::Integer::from(1)),
    ));
    rug::Float::with_val(64, r).to_string_radix(10, Some(7))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_values_are_shortened() {
        let tiny = exact_series::parse_rational("1e-400").unwrap();
        assert_eq!(readable(&tiny), "1.000000e-400");
        assert_eq!(readable(&exact_series::parse_rational("7/3").unwrap()), "7/3");
    }
}
