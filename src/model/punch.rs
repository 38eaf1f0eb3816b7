//! Punch shape g(x) and the period L (THEORY.md section 1).

use super::{error::ModelError, Exact};
use num_traits::Signed;

/// Distance between neighbouring punches.
#[derive(Debug, Clone, PartialEq)]
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
#[derive(Debug, Clone, PartialEq)]
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
        }
    }

    /// Sinusoidal punch, validated.
    pub fn sinusoidal(amplitude: Exact) -> Result<Self, ModelError> {
        if !amplitude.is_positive() {
            return Err(ModelError::new("amplitude", super::readable(&amplitude), "must be > 0"));
        }
        Ok(PunchShape::Sinusoidal { amplitude })
    }
}
