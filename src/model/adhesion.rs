//! Problem 2: monotone indentation of periodic punches with complete adhesion
//! (THEORY.md section 4; the paper's (1.4), (2.18)-(2.26)).

use super::{error::readable, error::ModelError, Exact, Material, Period, PunchShape};
use num_traits::Signed;

/// What fixes the state of the monotone indentation.
#[derive(Debug, Clone, PartialEq)]
pub enum AdhesionSize {
    /// Given contact half-width a > 0 (the direct problem).
    HalfWidth(Exact),
    /// Given normal load per punch P2 > 0 (find a).
    NormalLoad(Exact),
}

/// A validated statement of Problem 2 (symmetric case, b = a, P1 = 0).
#[derive(Debug, Clone, PartialEq)]
pub struct AdhesionProblem {
    material: Material,
    period: Period,
    shape: PunchShape,
    size: AdhesionSize,
}

impl AdhesionProblem {
    /// Validates the statement: parabolic punch only, positive sizes, 2a < L for a given a.
    /// (For a given load every P2 > 0 has a solution with 2a < L, since P2(a) -> infinity as
    /// 2a -> L.)
    pub fn new(material: Material, period: Period, shape: PunchShape, size: AdhesionSize) -> Result<Self, ModelError> {
        if !matches!(shape, PunchShape::Parabolic { .. }) {
            return Err(ModelError::new(
                "shape",
                shape.name(),
                "the adhesion problem supports only the parabolic punch g = k x^2",
            ));
        }
        shape.validate()?;
        period.validate()?;
        match &size {
            AdhesionSize::HalfWidth(a) if !a.is_positive() => {
                return Err(ModelError::new("half_width", readable(a), "must be > 0"))
            }
            AdhesionSize::NormalLoad(p) if !p.is_positive() => {
                return Err(ModelError::new("normal_load", readable(p), "must be > 0"))
            }
            _ => {}
        }
        if let (AdhesionSize::HalfWidth(a), Period::Finite(l)) = (&size, &period) {
            if (a + a) >= *l {
                return Err(ModelError::new(
                    "half_width",
                    readable(a),
                    format!("must satisfy 2 a < L = {}", readable(l)),
                ));
            }
        }
        Ok(AdhesionProblem { material, period, shape, size })
    }

    /// Half-plane material.
    pub fn material(&self) -> &Material {
        &self.material
    }
    /// Period L, or a single punch.
    pub fn period(&self) -> &Period {
        &self.period
    }
    /// Punch shape (only the parabola g = k x^2 is supported).
    pub fn shape(&self) -> &PunchShape {
        &self.shape
    }
    /// Half-width or load.
    pub fn size(&self) -> &AdhesionSize {
        &self.size
    }

    /// Curvature k of the parabola g = k x^2.
    pub fn curvature(&self) -> &Exact {
        match &self.shape {
            PunchShape::Parabolic { k } => k,
            // Unreachable after validation (parabolic only).
            PunchShape::Sinusoidal { amplitude } => amplitude,
            PunchShape::Polynomial { coefficients } => &coefficients[2],
            PunchShape::Circular { radius } => radius,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    fn q(n: i64, d: i64) -> Exact {
        Exact::new(n.into(), d.into())
    }
    fn mat() -> Material {
        Material::from_contact_modulus(q(3, 10), q(1, 1)).unwrap()
    }

    #[test]
    fn adhesion_problem_validation() {
        let k = PunchShape::parabolic(q(1, 1)).unwrap();
        let l = Period::finite(q(1, 1)).unwrap();
        assert!(AdhesionProblem::new(mat(), l.clone(), k.clone(), AdhesionSize::HalfWidth(q(1, 4))).is_ok());
        let e = AdhesionProblem::new(mat(), l.clone(), k.clone(), AdhesionSize::HalfWidth(q(1, 2))).unwrap_err();
        assert_eq!(e.parameter, "half_width");
        let e = AdhesionProblem::new(mat(), l.clone(), k.clone(), AdhesionSize::NormalLoad(q(0, 1))).unwrap_err();
        assert_eq!(e.parameter, "normal_load");
        let s = PunchShape::sinusoidal(q(1, 1)).unwrap();
        let e = AdhesionProblem::new(mat(), l, s, AdhesionSize::HalfWidth(q(1, 4))).unwrap_err();
        assert_eq!(e.parameter, "shape");
        assert!(AdhesionProblem::new(mat(), Period::Infinite, k, AdhesionSize::HalfWidth(q(7, 1))).is_ok());
    }
}
