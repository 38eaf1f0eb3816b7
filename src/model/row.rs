//! The punch row every problem stands on: the half-plane's material, the period L (or a single
//! punch) and the punch profile g (docs/theory.md sections 1 and 9), validated once when built.
//! Problems 1, 2 and the loading law each hold one and read it through [`OnPunchRow`].
//! Tests: the validation messages in `tests/all/scene.rs`.

use super::{ModelError, Period, PunchShape};
use crate::model::Material;

/// Material, period and punch shape of a row of punches.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct PunchRow {
    material: Material,
    period: Period,
    shape: PunchShape,
}

impl PunchRow {
    /// Validates the shape's parameters, the period, and that a sinusoidal punch has a finite
    /// period (the error names the parameter, its value and the valid range).
    pub fn new(material: Material, period: Period, shape: PunchShape) -> Result<Self, ModelError> {
        shape.validate()?;
        period.validate()?;
        if let (PunchShape::Sinusoidal { .. }, Period::Infinite) = (&shape, &period) {
            return Err(ModelError::new("period", "inf", "a sinusoidal punch needs a finite period"));
        }
        Ok(PunchRow { material, period, shape })
    }

    /// The half-plane's material.
    pub fn material(&self) -> &Material {
        &self.material
    }

    /// The period L, or a single punch.
    pub fn period(&self) -> &Period {
        &self.period
    }

    /// The punch profile.
    pub fn shape(&self) -> &PunchShape {
        &self.shape
    }
}

/// A problem posed on a [`PunchRow`]: its material, period and shape, read the same way in all
/// three problems.
pub trait OnPunchRow {
    /// The row.
    fn row(&self) -> &PunchRow;

    /// The half-plane's material.
    fn material(&self) -> &Material {
        self.row().material()
    }

    /// The period L, or a single punch.
    fn period(&self) -> &Period {
        self.row().period()
    }

    /// The punch profile.
    fn shape(&self) -> &PunchShape {
        self.row().shape()
    }
}
