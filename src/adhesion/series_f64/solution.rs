//! Method 2 in dimensional form: the solution of the exact problem (given a or P2, period or
//! single punch) at the requested points x/a. Scalings: [`crate::adhesion::scales`].

use super::series::UniversalSeries;
use super::solve::{solve, SERIES_LAMBDA_MAX};
use crate::adhesion::error::AdhesionError;
use crate::adhesion::scales::Digits;
use crate::model::{readable, AdhesionProblem, AdhesionSize, Exact, Period};
use crate::numerics::exact::to_f64;

/// f64 values at one point (method 2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointValuesF64 {
    /// x/a.
    pub x_over_a: f64,
    /// psi.
    pub psi: f64,
    /// phi.
    pub phi: f64,
    /// q1.
    pub q1: f64,
    /// q2.
    pub q2: f64,
}

/// Method 2 solution (f64).
#[derive(Debug, Clone, PartialEq)]
pub struct AdhesionSolutionF64 {
    /// lambda.
    pub lambda: f64,
    /// a.
    pub half_width: f64,
    /// P2.
    pub normal_load: f64,
    /// Points.
    pub points: Vec<PointValuesF64>,
    /// Series terms used.
    pub terms: usize,
    /// Digits per quantity estimated by a second, finer run ([`super::verify`]); never more than
    /// the true digits (tested against method 1).
    pub digits_estimated: Digits,
}

/// One run of method 2 (f64 power series in lambda^2) on the universal series of the problem's
/// material; `digits_estimated` is left at 0 (the estimate compares two runs: [`super::verify`]).
pub(super) fn solve_run(
    problem: &AdhesionProblem,
    points: &[Exact],
    universal: &UniversalSeries,
) -> Result<AdhesionSolutionF64, AdhesionError> {
    let conv = |q: &Exact, name: &'static str| {
        to_f64(q).ok_or(AdhesionError::InvalidArgument {
            parameter: name,
            value: readable(q),
            expected: "must fit in f64".into(),
        })
    };
    let e_star = conv(problem.material().contact_modulus(), "contact_modulus")?;
    let k = conv(problem.curvature(), "k")?;
    let pi = std::f64::consts::PI;
    let (lambda, a, sol) = match (problem.size(), problem.period()) {
        (AdhesionSize::HalfWidth(a), Period::Infinite) => (0.0, conv(a, "half_width")?, solve(universal, 0.0)?),
        (AdhesionSize::HalfWidth(a), Period::Finite(l)) => {
            let lam = pi * conv(&(a / l), "half_width")?;
            (lam, conv(a, "half_width")?, solve(universal, lam)?)
        }
        (AdhesionSize::NormalLoad(p2), Period::Infinite) => {
            let sol = solve(universal, 0.0)?;
            let a = (conv(p2, "normal_load")? / (sol.load_ratio() * e_star * k)).sqrt();
            (0.0, a, sol)
        }
        (AdhesionSize::NormalLoad(p2), Period::Finite(l)) => {
            let lf = conv(l, "period")?;
            let target = conv(p2, "normal_load")? * pi * pi / (e_star * k * lf * lf);
            // Newton on P(lambda) = lambda^2 P2~(lambda), re-solving the series each step.
            let cp = universal.constants.load_constant;
            let mut lam = (-target / (2.0 * cp)).exp().acos().min(SERIES_LAMBDA_MAX);
            let mut sol = solve(universal, lam)?;
            for it in 0..60 {
                let p = lam * lam * sol.load_ratio();
                let d = lam * sol.f_at(1.0);
                let next = (lam - (p - target) / d).clamp(0.5 * lam, SERIES_LAMBDA_MAX);
                let done = (next - lam).abs() <= 1e-15 * lam;
                lam = next;
                sol = solve(universal, lam)?;
                if done {
                    break;
                }
                if it == 59 {
                    return Err(AdhesionError::NotConverged {
                        what: "f64 Newton for the half-width",
                        reason: "60 steps".into(),
                    });
                }
            }
            (lam, lam * lf / pi, sol)
        }
    };
    let load = sol.load_ratio() * e_star * k * a * a;
    let pts = points
        .iter()
        .map(|p| {
            let s = to_f64(p).unwrap_or(0.0);
            let (q2, q1) = sol.stress_ratio(s);
            PointValuesF64 {
                x_over_a: s,
                psi: sol.psi_ratio(s) * k * a,
                phi: sol.phi_ratio(s) * k * a * a,
                q1: q1 * e_star * k * a,
                q2: q2 * e_star * k * a,
            }
        })
        .collect();
    Ok(AdhesionSolutionF64 {
        lambda,
        half_width: a,
        normal_load: load,
        points: pts,
        terms: sol.f.len(),
        digits_estimated: Digits::from_points(0.0, [], 0.0),
    })
}
