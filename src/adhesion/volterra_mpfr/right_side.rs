//! The right side of the Volterra equation for a general even profile (docs/theory.md section 9):
//!   int_0^chi Re K(chi, eta) dP2/d eta d eta = (E* L/2) g'(L chi/pi).
//! With P2 = E* k (L/pi)^2 P (k = [`crate::model::AdhesionProblem::curvature`], the reference
//! curvature), P'(eta) = eta f(eta^2) and chi = lambda sigma (module doc of [`super`]), this is
//!   Re I(sigma) = pi g'(x)/(2 k x),   x = (L/pi) chi = l sigma,
//! with l = a at the solved lambda (the parabola's pi is g = k x^2). The ratio g'(x)/(2 k x) is
//! even in x, a function of tau = sigma^2:
//! - even polynomial g = sum_m c_2m x^(2m): sum_m (m c_2m/k) (l^2 tau)^(m-1) (the weights
//!   m c_2m/k exact, rounded once);
//! - circle g = R - sqrt(R^2 - x^2): g'(x)/(2 k x) = 1/(2 k sqrt(R^2 - l^2 tau)), singular at
//!   tau = R^2/l^2 > 1 (the contact stays inside |x| < R, [`crate::adhesion::profile`]).
//!
//! The parabola keeps the constant pi unchanged (bit-identical to the earlier solver); a
//! polynomial g = k x^2 has the single weight 1 and gives the same pi.

use crate::model::OnPunchRow;
use crate::model::{AdhesionProblem, Exact, PunchShape};
use crate::numerics::exact::to_float;
use rug::float::Constant;
use rug::Float;

/// pi g'(x)/(2 k x) as a function of tau = (x/l)^2.
#[derive(Debug, Clone)]
pub enum RightSide {
    /// g = k x^2: the constant pi.
    Parabola,
    /// Even polynomial: weights m c_2m/k (m = 1, 2, ...) and l^2.
    Polynomial {
        /// m c_2m/k, m = 1..=M.
        weights: Vec<Float>,
        /// l^2.
        ell2: Float,
    },
    /// Circle: 1/(2 k) and R^2, l^2.
    Circle {
        /// 1/(2k).
        half_over_k: Float,
        /// R^2.
        r2: Float,
        /// l^2.
        ell2: Float,
    },
}

impl RightSide {
    /// The right side of `problem` with x = l sigma, l^2 = `ell2` (at `prec` bits).
    pub fn new(problem: &AdhesionProblem, ell2: Float, prec: u32) -> Self {
        let k = problem.curvature();
        match problem.shape() {
            PunchShape::Polynomial { coefficients } => RightSide::Polynomial {
                weights: coefficients
                    .iter()
                    .enumerate()
                    .skip(2)
                    .step_by(2)
                    .map(|(j, c)| to_float(&(c * Exact::from_integer(((j / 2) as i64).into()) / k), prec))
                    .collect(),
                ell2,
            },
            PunchShape::Circular { radius } => RightSide::Circle {
                half_over_k: to_float(&(Exact::new(1.into(), 2.into()) / k), prec),
                r2: to_float(&(radius * radius), prec),
                ell2,
            },
            _ => RightSide::Parabola,
        }
    }

    /// pi g'(x)/(2 k x) at x^2 = l^2 tau.
    pub fn at(&self, tau: &Float, prec: u32) -> Float {
        let pi = Float::with_val(prec, Constant::Pi);
        match self {
            RightSide::Parabola => pi,
            RightSide::Polynomial { weights, ell2 } => {
                let t = Float::with_val(prec, ell2 * tau);
                let mut acc = Float::with_val(prec, 0);
                for w in weights.iter().rev() {
                    acc = acc * &t + w;
                }
                acc * pi
            }
            RightSide::Circle { half_over_k, r2, ell2 } => {
                let d = Float::with_val(prec, r2 - Float::with_val(prec, ell2 * tau));
                pi * half_over_k / d.sqrt()
            }
        }
    }

    /// Chebyshev nodes the right side needs on tau in [0, 1] for accuracy 2^-bits, beyond the
    /// full-contact estimate of [`super::chebyshev_size`]: at lambda = 0 the solution F is a
    /// polynomial of the degree of the right side in tau (the Abel operator maps tau^j to
    /// Re M_(2j+1) tau^j), so M + 2 nodes for a polynomial of degree 2M; the circle's square-root
    /// singularity at tau_s = R^2/l^2 gives the rate rho = z + sqrt(z^2 - 1), z = 2 tau_s - 1.
    pub fn min_nodes(&self, bits: u32, refine: f64) -> usize {
        match self {
            RightSide::Parabola => 2,
            RightSide::Polynomial { weights, .. } => weights.len() + 2,
            RightSide::Circle { r2, ell2, .. } => {
                let z = 2.0 * (r2.to_f64() / ell2.to_f64()) - 1.0;
                let rho = z + (z * z - 1.0).max(0.0).sqrt();
                if !(rho > 1.0) {
                    return usize::MAX;
                }
                ((bits as f64 * std::f64::consts::LN_2 / rho.ln()) * refine).ceil() as usize + 8
            }
        }
    }
}
