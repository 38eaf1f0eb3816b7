//! The right side of method 2's Volterra equation for a general even profile (docs/theory.md
//! section 9; the MPFR method's [`crate::adhesion::volterra_mpfr::right_side`] states it):
//!   Re I(sigma) = pi g'(x)/(2 k x),   x = a sigma, tau = sigma^2,
//! as a power series in tau, r(tau) = sum_n r_n tau^n (the factor pi is applied by the
//! recursion of [`super::solve`](mod@super::solve)):
//! - parabola g = k x^2: r = 1;
//! - even polynomial g = sum_m c_2m x^(2m): r_(m-1) = (m c_2m/k) a^(2m-2), a polynomial;
//! - circle g = R - sqrt(R^2 - x^2): g'(x)/(2 k x) = (1/(2 k R)) (1 - (a/R)^2 tau)^(-1/2), so
//!   r_n = (1/(2 k R)) binom(2n, n) 4^(-n) (a/R)^(2n), which converges at tau = 1 because the
//!   contact stays inside |x| < R ([`crate::adhesion::profile`]).
//!
//! The coefficients are rounded once from the exact profile (`f64`); k is the problem's reference
//! curvature ([`crate::model::AdhesionProblem::curvature`]).

use crate::growing_contact::error::AdhesionError;
use crate::model::OnPunchRow;
use crate::model::{readable, AdhesionProblem, PunchShape};
use crate::numerics::exact::to_f64;

/// The profile's part of the right side, independent of the contact size.
#[derive(Debug, Clone, PartialEq)]
pub enum RightSeries {
    /// g = k x^2.
    Parabola,
    /// Even polynomial: the weights m c_2m/k, m = 1..=M.
    Polynomial {
        /// m c_2m/k.
        weights: Vec<f64>,
    },
    /// Circle: 1/(2 k R) and R.
    Circle {
        /// 1/(2 k R).
        scale: f64,
        /// R.
        radius: f64,
    },
}

impl RightSeries {
    /// The right side of `problem`'s profile (a parabola, even polynomial or circle).
    pub fn new(problem: &AdhesionProblem) -> Result<Self, AdhesionError> {
        let conv = |q: &crate::model::Exact, name: &'static str| {
            to_f64(q).filter(|v| v.is_finite()).ok_or_else(|| AdhesionError::InvalidArgument {
                parameter: name,
                value: readable(q),
                expected: "must fit in f64 (|value| < 1.8e308) for the f64 method".into(),
            })
        };
        let k = conv(problem.curvature(), "k")?;
        Ok(match problem.shape() {
            PunchShape::Polynomial { coefficients } => RightSeries::Polynomial {
                weights: coefficients
                    .iter()
                    .enumerate()
                    .skip(2)
                    .step_by(2)
                    .map(|(j, c)| conv(c, "coefficients").map(|c| c * (j / 2) as f64 / k))
                    .collect::<Result<_, _>>()?,
            },
            PunchShape::Circular { radius } => {
                let r = conv(radius, "radius")?;
                RightSeries::Circle { scale: 1.0 / (2.0 * k * r), radius: r }
            }
            _ => RightSeries::Parabola,
        })
    }

    /// r_n, n < `terms`, at the half-width `a` (module doc).
    pub fn coefficients(&self, a: f64, terms: usize) -> Vec<f64> {
        match self {
            RightSeries::Parabola => vec![1.0],
            RightSeries::Polynomial { weights } => {
                let a2 = a * a;
                let mut pow = 1.0;
                weights
                    .iter()
                    .take(terms)
                    .map(|w| {
                        let v = w * pow;
                        pow *= a2;
                        v
                    })
                    .collect()
            }
            RightSeries::Circle { scale, radius } => {
                let q = (a / radius) * (a / radius);
                let mut v = *scale;
                let mut out = Vec::with_capacity(terms);
                for n in 0..terms {
                    out.push(v);
                    // binom(2n+2, n+1)/4^(n+1) = binom(2n, n)/4^n (2n+1)/(2n+2).
                    v *= q * (2 * n + 1) as f64 / (2 * n + 2) as f64;
                }
                out
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{AdhesionSize, Exact, Material, Period};

    fn q(n: i64, d: i64) -> Exact {
        Exact::new(n.into(), d.into())
    }

    fn problem(shape: PunchShape) -> AdhesionProblem {
        let m = Material::from_contact_modulus(q(3, 10), q(1, 1)).unwrap();
        AdhesionProblem::new(m, Period::Finite(q(1, 1)), shape, AdhesionSize::HalfWidth(q(1, 5))).unwrap()
    }

    /// The series reproduce g'(x)/(2 k x) at x = a sigma (sum at tau = sigma^2 against the closed
    /// form; k the problem's reference curvature).
    #[test]
    fn right_series_sum_to_the_profile_slope() {
        let quartic =
            problem(PunchShape::Polynomial { coefficients: vec![q(0, 1), q(0, 1), q(1, 1), q(0, 1), q(1, 10)] });
        let circle = problem(PunchShape::Circular { radius: q(1, 2) });
        for (p, slope) in [
            (&quartic, Box::new(|x: f64| 2.0 * x + 0.4 * x * x * x) as Box<dyn Fn(f64) -> f64>),
            (&circle, Box::new(|x: f64| x / (0.25 - x * x).sqrt())),
        ] {
            let k = to_f64(p.curvature()).unwrap();
            let r = RightSeries::new(p).unwrap();
            let a = 0.2;
            let c = r.coefficients(a, 90);
            for sigma in [0.1, 0.5, 0.9, 1.0] {
                let t: f64 = sigma * sigma;
                let sum = c.iter().rev().fold(0.0, |acc, v| acc * t + v);
                let x = a * sigma;
                let want = slope(x) / (2.0 * k * x);
                assert!((sum - want).abs() < 1e-15 * want, "{sum} vs {want}");
            }
        }
        let parabola = problem(PunchShape::Parabolic { k: q(1, 1) });
        assert_eq!(RightSeries::new(&parabola).unwrap().coefficients(0.2, 90), vec![1.0]);
    }
}
