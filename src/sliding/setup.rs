//! The problem's numbers at working precision (THEORY.md sections 1 and 3).

use super::error::SlidingError;
use crate::model::{Period, PunchShape, SlidingProblem};
use crate::numerics::exact::to_float;
use rug::{float::Constant, Float};

/// Smallest allowed distance of |theta| from 1/2 (the end exponents 1/2 -+ theta reach 0 and the
/// quadrature needs ever more nodes; THEORY.md section 7).
pub const THETA_MARGIN: f64 = 1e-6;

/// Punch shape at working precision.
#[derive(Debug, Clone)]
pub enum Shape {
    /// g = k x^2.
    Parabolic {
        /// k.
        k: Float,
    },
    /// g = D (1 - cos(2 pi x / L)) [2.16].
    Sinusoidal {
        /// D.
        d: Float,
    },
}

pub use crate::model::Convention;

/// Every input of Problem 1 rounded once to `prec` bits, plus the derived constants.
#[derive(Debug, Clone)]
pub struct Setup {
    /// Working precision in bits.
    pub prec: u32,
    /// E* = E/(1 - nu^2).
    pub e_star: Float,
    /// beta = (1 - 2 nu)/(2 (1 - nu)).
    pub beta: Float,
    /// Coulomb friction mu.
    pub mu: Float,
    /// Adhesive friction tau0.
    pub tau0: Float,
    /// Wear coefficient cW.
    pub wear: Float,
    /// Sliding speed V, if given.
    pub speed: Option<Float>,
    /// kappa = E* cW/2 - beta mu [2.8], rounded once from its exact value.
    pub kappa: Float,
    /// theta = arctan(kappa)/pi, computed in MPFR.
    pub theta: Float,
    /// cos(pi theta).
    pub cos_pi_theta: Float,
    /// Period L (None: single punch).
    pub period: Option<Float>,
    /// Punch shape.
    pub shape: Shape,
    /// pi.
    pub pi: Float,
    /// Surface convention (periodic rows only).
    pub convention: Convention,
}

impl Setup {
    /// Rounds the exact inputs of `problem` once to `prec` bits and derives kappa and theta.
    /// Errors when |theta| is within [`THETA_MARGIN`] of 1/2.
    pub fn new(problem: &SlidingProblem, prec: u32) -> Result<Self, SlidingError> {
        Self::with_convention(problem, prec, Convention::Paper)
    }

    /// As [`Setup::new`], with the surface convention `convention`.
    pub fn with_convention(problem: &SlidingProblem, prec: u32, convention: Convention) -> Result<Self, SlidingError> {
        // The problem's fields are public: re-validate, so that no input can reach a panic or NaN.
        let m = problem.material();
        crate::model::Material::from_contact_modulus(m.poisson_ratio().clone(), m.contact_modulus().clone())
            .and_then(|_| match problem.shape() {
                PunchShape::Parabolic { k } => PunchShape::parabolic(k.clone()),
                PunchShape::Sinusoidal { amplitude } => PunchShape::sinusoidal(amplitude.clone()),
            })
            .and_then(|_| match problem.period() {
                Period::Finite(l) => Period::finite(l.clone()).map(|_| ()),
                Period::Infinite => Ok(()),
            })
            .and_then(|_| problem.to_builder().build())
            .map_err(|e| SlidingError::Parameter { parameter: e.parameter, value: e.value, expected: e.expected })?;
        let pi = Float::with_val(prec, Constant::Pi);
        let kappa = to_float(&problem.kappa(), prec);
        let theta = Float::with_val(prec, kappa.atan_ref()) / &pi;
        let gap = 0.5 - theta.to_f64().abs();
        if !(gap >= THETA_MARGIN) {
            return Err(SlidingError::parameter(
                "theta = arctan(kappa)/pi",
                format!("{} (kappa = {})", format!("{:.12}", theta), problem.kappa()),
                format!("|theta| must be <= 1/2 - {THETA_MARGIN:e}: friction or wear too large for the quadrature"),
            ));
        }
        let cos_pi_theta = Float::with_val(prec, &pi * &theta).cos();
        let period = match problem.period() {
            Period::Finite(l) => Some(to_float(l, prec)),
            Period::Infinite => None,
        };
        let shape = match problem.shape() {
            PunchShape::Parabolic { k } => Shape::Parabolic { k: to_float(k, prec) },
            PunchShape::Sinusoidal { amplitude } => Shape::Sinusoidal { d: to_float(amplitude, prec) },
        };
        Ok(Setup {
            prec,
            e_star: to_float(problem.material().contact_modulus(), prec),
            beta: to_float(&problem.material().beta(), prec),
            mu: to_float(problem.friction(), prec),
            tau0: to_float(problem.adhesive_friction(), prec),
            wear: to_float(problem.wear(), prec),
            speed: problem.speed().as_ref().map(|v| to_float(v, prec)),
            kappa,
            theta,
            cos_pi_theta,
            period,
            shape,
            pi,
            convention,
        })
    }

    /// Exponents (alpha, beta) of the Jacobi weight 1/omega = (1-u)^{theta-1/2} (1+u)^{-theta-1/2}.
    pub fn inverse_weight_exponents(&self) -> (Float, Float) {
        let a = Float::with_val(self.prec, &self.theta - 0.5f64);
        let b = Float::with_val(self.prec, -Float::with_val(self.prec, &self.theta + 0.5f64));
        (a, b)
    }

    /// Exponents (alpha, beta) of omega = (1-u)^{1/2-theta} (1+u)^{1/2+theta} (THEORY.md section 2).
    pub fn weight_exponents(&self) -> (Float, Float) {
        let a = Float::with_val(self.prec, 0.5f64 - Float::with_val(self.prec, &self.theta));
        let b = Float::with_val(self.prec, &self.theta + 0.5f64);
        (a, b)
    }

    /// Curvature of the (osculating) parabola: k, or 2 pi^2 D/L^2 for the sinusoid.
    pub fn osculating_k(&self) -> Float {
        match &self.shape {
            Shape::Parabolic { k } => k.clone(),
            Shape::Sinusoidal { d } => {
                let l = self.period.as_ref().expect("sinusoid has a period");
                Float::with_val(self.prec, &self.pi * &self.pi) * d * 2u32 / Float::with_val(self.prec, l * l)
            }
        }
    }
}
