//! Typed errors of the engine: every precondition that is not met is reported, never panicked.

/// Why a series operation could not be carried out.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum SeriesError {
    /// The constant term must be invertible in the coefficient ring (inverse, division, log, sqrt).
    #[error("{operation}: the constant term {constant} is not invertible in the coefficient ring")]
    NonInvertibleConstantTerm {
        /// The operation that needed the inverse.
        operation: &'static str,
        /// The offending constant term, as text.
        constant: String,
    },
    /// The operation needs a specific constant term (exp needs 0, log and pow need 1).
    #[error("{operation}: the constant term must be {required}, got {constant}")]
    ConstantTermRequired {
        /// The operation.
        operation: &'static str,
        /// What the constant term must be.
        required: &'static str,
        /// What it is.
        constant: String,
    },
    /// Composition f(g) and the functions of a series need g(0) = 0; reversion needs f(0) = 0.
    #[error("{operation}: the inner series must have zero constant term, got {constant}")]
    NonZeroInnerConstant {
        /// The operation.
        operation: &'static str,
        /// The constant term found.
        constant: String,
    },
    /// Division by a series whose leading term is beyond the known precision or does not divide.
    #[error("division: the divisor's valuation {divisor} exceeds the dividend's valuation {dividend}")]
    ValuationMismatch {
        /// Valuation of the dividend.
        dividend: usize,
        /// Valuation of the divisor.
        divisor: usize,
    },
    /// Division of ring elements that has no exact result in this ring.
    #[error("{operation}: {value} has no inverse in this coefficient ring")]
    NotInvertible {
        /// The operation.
        operation: &'static str,
        /// The element, as text.
        value: String,
    },
    /// A square root that does not exist exactly in the coefficient ring.
    #[error("sqrt: the constant term {constant} is not a square in the coefficient ring")]
    NotASquare {
        /// The constant term.
        constant: String,
    },
    /// A symbol name that cannot be used (empty, or not an identifier).
    #[error("invalid symbol name {name:?}: must be a non-empty identifier (letters, digits, _)")]
    InvalidSymbol {
        /// The name as given.
        name: String,
    },
    /// A rational number that could not be parsed.
    #[error("invalid rational {text:?}: expected an integer, a ratio like 1/3, or a decimal like 0.25 or 1e-3")]
    InvalidRational {
        /// The text as given.
        text: String,
    },
    /// A Pade approximant [L/M] needs the coefficients of x^0 .. x^(L+M).
    #[error("Pade [{l}/{m}]: needs the coefficients through x^{} (L + M), the series knows {known}", .l + .m)]
    PadeOrder {
        /// Numerator degree bound L.
        l: usize,
        /// Denominator degree bound M.
        m: usize,
        /// The number of known coefficients.
        known: usize,
    },
    /// The [L/M] approximant does not exist (a degenerate block of the Pade table): the rational
    /// function of the Euclidean algorithm matches fewer than L + M + 1 coefficients.
    #[error("Pade [{l}/{m}] does not exist: the rational function of degrees <= ({l}, {m}) closest to the series matches only its first {matched} coefficients (singular block of the Pade table)")]
    PadeDoesNotExist {
        /// Numerator degree bound L.
        l: usize,
        /// Denominator degree bound M.
        m: usize,
        /// The number of leading coefficients the reduced approximant reproduces.
        matched: usize,
    },
}
