//! Punch shape g(x) and the period L (docs/theory.md section 1).

use super::{error::ModelError, Exact};
use num_traits::{Signed, Zero};

/// Distance between neighbouring punches.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum Period {
    /// Period L > 0.
    Finite(Exact),
    /// A single punch (L = infinity).
    Infinite,
}

impl Period {
    /// A finite period, validated (> 0).
    pub fn finite(l: Exact) -> Result<Self, ModelError> {
        if !l.is_positive() {
            return Err(ModelError::new("period", super::readable(&l), "must be > 0 (or \"inf\" for a single punch)"));
        }
        Ok(Period::Finite(l))
    }

    /// Checks a period built from its variant directly (L > 0).
    pub fn validate(&self) -> Result<(), ModelError> {
        match self {
            Period::Finite(l) => Period::finite(l.clone()).map(|_| ()),
            Period::Infinite => Ok(()),
        }
    }
}

/// Shape of one punch, y = g(x), g(0) = 0.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum PunchShape {
    /// g = k x^2, k > 0.
    Parabolic {
        /// Curvature parameter k > 0 (g'' = 2k).
        k: Exact,
    },
    /// g = D (1 - cos(2 pi x / L)) [2.16], D > 0; needs a finite period.
    Sinusoidal {
        /// Amplitude D > 0.
        amplitude: Exact,
    },
    /// g = sum_j c_j x^j (docs/theory.md section 9): `coefficients[j]` is c_j (numpy's order),
    /// c_0 = 0 (g(0) = 0), at least one non-zero c_j with j >= 2. A non-zero c_1 tilts the punch;
    /// odd terms make Problem 1 asymmetric even without friction. Convexity on the contact is a
    /// property of the solution, checked by the solvers.
    Polynomial {
        /// c_0, c_1, ..., c_N (exact; trailing zeros allowed).
        coefficients: Vec<Exact>,
    },
    /// g = R - sqrt(R^2 - x^2), R > 0: the exact cylinder (docs/theory.md section 9); the contact must
    /// stay inside |x| < R (checked by the solvers).
    Circular {
        /// Radius R > 0.
        radius: Exact,
    },
}

impl PunchShape {
    /// Parabolic punch, validated.
    pub fn parabolic(k: Exact) -> Result<Self, ModelError> {
        if !k.is_positive() {
            return Err(ModelError::new("k", super::readable(&k), "must be > 0"));
        }
        Ok(PunchShape::Parabolic { k })
    }

    /// Checks a shape built from its variant directly (k > 0, D > 0).
    pub fn validate(&self) -> Result<(), ModelError> {
        match self {
            PunchShape::Parabolic { k } => PunchShape::parabolic(k.clone()).map(|_| ()),
            PunchShape::Sinusoidal { amplitude } => PunchShape::sinusoidal(amplitude.clone()).map(|_| ()),
            PunchShape::Polynomial { coefficients } => PunchShape::polynomial(coefficients.clone()).map(|_| ()),
            PunchShape::Circular { radius } => PunchShape::circular(radius.clone()).map(|_| ()),
        }
    }

    /// Sinusoidal punch, validated.
    pub fn sinusoidal(amplitude: Exact) -> Result<Self, ModelError> {
        if !amplitude.is_positive() {
            return Err(ModelError::new("amplitude", super::readable(&amplitude), "must be > 0"));
        }
        Ok(PunchShape::Sinusoidal { amplitude })
    }

    /// Polynomial punch g = sum_j c_j x^j, validated: at least three coefficients, c_0 = 0, and
    /// a non-zero c_j for some j >= 2 (a linear g is a tilted flat punch, not a convex one).
    pub fn polynomial(coefficients: Vec<Exact>) -> Result<Self, ModelError> {
        let text = polynomial_text(&coefficients);
        if coefficients.is_empty() {
            return Err(ModelError::new("coefficients", "[]", "must list c_0, c_1, c_2, ... (at least three)"));
        }
        if !coefficients[0].is_zero() {
            return Err(ModelError::new(
                "coefficients",
                text,
                format!("coefficients[0] = c_0 = {} must be 0 (g(0) = 0)", super::readable(&coefficients[0])),
            ));
        }
        if coefficients.iter().skip(2).all(|c| c.is_zero()) {
            return Err(ModelError::new(
                "coefficients",
                text,
                "needs a non-zero coefficient of degree >= 2 (index j >= 2; g must be curved to be convex)",
            ));
        }
        Ok(PunchShape::Polynomial { coefficients })
    }

    /// Circular punch g = R - sqrt(R^2 - x^2), validated (R > 0).
    pub fn circular(radius: Exact) -> Result<Self, ModelError> {
        if !radius.is_positive() {
            return Err(ModelError::new("radius", super::readable(&radius), "must be > 0"));
        }
        Ok(PunchShape::Circular { radius })
    }

    /// The name used in scenes and JSON: `parabolic`, `sinusoidal`, `polynomial`, `circular`.
    pub fn name(&self) -> &'static str {
        match self {
            PunchShape::Parabolic { .. } => "parabolic",
            PunchShape::Sinusoidal { .. } => "sinusoidal",
            PunchShape::Polynomial { .. } => "polynomial",
            PunchShape::Circular { .. } => "circular",
        }
    }

    /// The shape's exact parameters as (name, value) text pairs, for provenance and messages:
    /// `k`, `amplitude`, `coefficients` (`["0", "0", "1"]`) or `radius`.
    pub fn parameters(&self) -> Vec<(&'static str, String)> {
        match self {
            PunchShape::Parabolic { k } => vec![("k", k.to_string())],
            PunchShape::Sinusoidal { amplitude } => vec![("amplitude", amplitude.to_string())],
            PunchShape::Polynomial { coefficients } => vec![("coefficients", polynomial_text(coefficients))],
            PunchShape::Circular { radius } => vec![("radius", radius.to_string())],
        }
    }
}

/// `["0", "0", "1", "0", "1/10"]`: the coefficients as a scene writes them (readable values).
fn polynomial_text(coefficients: &[Exact]) -> String {
    let items: Vec<String> = coefficients.iter().map(|c| format!("\"{}\"", super::readable(c))).collect();
    format!("[{}]", items.join(", "))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(s: &str) -> Exact {
        exact_series::parse_rational(s).unwrap()
    }

    fn poly(c: &[&str]) -> Result<PunchShape, ModelError> {
        PunchShape::polynomial(c.iter().map(|s| q(s)).collect())
    }

    #[test]
    fn polynomial_validation_names_the_parameter_value_and_range() {
        assert!(poly(&["0", "0", "1", "0", "1/10"]).is_ok());
        assert!(poly(&["0", "1/5", "1"]).is_ok()); // tilted parabola
        let e = poly(&["1", "0", "1"]).unwrap_err();
        assert_eq!(e.parameter, "coefficients");
        assert!(e.value.contains("\"1\", \"0\", \"1\"") && e.expected.contains("must be 0"), "{e}");
        let e = poly(&["0", "2", "0", "0"]).unwrap_err();
        assert!(e.expected.contains("degree >= 2"), "{e}");
        let e = poly(&["0", "1"]).unwrap_err();
        assert!(e.expected.contains("degree >= 2"), "{e}");
        let e = poly(&[]).unwrap_err();
        assert!(e.to_string().contains("coefficients"), "{e}");
        assert_eq!(
            poly(&["0", "0", "1", "0", "1/10"]).unwrap().parameters(),
            vec![("coefficients", "[\"0\", \"0\", \"1\", \"0\", \"1/10\"]".to_string())]
        );
    }

    #[test]
    fn circle_needs_a_positive_radius() {
        assert!(PunchShape::circular(q("0.5")).is_ok());
        for r in ["0", "-1/2"] {
            let e = PunchShape::circular(q(r)).unwrap_err();
            assert_eq!(e.parameter, "radius");
            assert!(e.expected.contains("> 0"), "{e}");
        }
        assert_eq!(PunchShape::circular(q("1/2")).unwrap().name(), "circular");
    }
}
