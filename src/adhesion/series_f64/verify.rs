//! `solve_f64`: method 2 with its own accuracy estimate. The values are those of the nominal run
//! ([`SeriesParams::NOMINAL`]); a second run with a 1.5 times finer tanh-sinh rule (moments and
//! stresses) and a truncation of the lambda^2 series 1000 times further out
//! ([`SeriesParams::refined`]) is more accurate, so the difference of the two measures the error
//! of the first: estimated digits = -log10(|difference| / scale)
//! ([`crate::numerics::accuracy::verified_digits`], capped at [`F64_DIGITS_CAP`]) with the scales
//! of [`crate::adhesion::scales`]. The test `adhesion::tests::f64_estimate_never_overclaims`
//! checks over a grid of (nu, lambda) that the estimate never exceeds the true digits against
//! method 1 by more than 0.3.

use super::series::{SeriesParams, UniversalSeries};
use super::solution::{solve_run, AdhesionSolutionF64};
use crate::adhesion::points::check_points;
use crate::adhesion::scales::{Digits, ScalesF64};
use crate::growing_contact::error::AdhesionError;
use crate::model::OnPunchRow;
use crate::model::{AdhesionProblem, AdhesionSize, Exact};
use crate::numerics::accuracy::{f64_digits, F64_DIGITS_CAP};
use crate::params::adhesion::AdhesionParamsF64;

/// Method 2 (f64 power series in lambda^2) with estimated digits per quantity (module doc).
pub fn solve_f64(problem: &AdhesionProblem, points: &[Exact]) -> Result<AdhesionSolutionF64, AdhesionError> {
    check_points(points)?;
    let constants = AdhesionParamsF64::new(problem.material());
    let nominal = UniversalSeries::new(&constants, SeriesParams::NOMINAL)?;
    let mut sol = solve_run(problem, points, &nominal)?;
    let fine =
        UniversalSeries::new(&constants, SeriesParams::NOMINAL.refined()).and_then(|u| solve_run(problem, points, &u));
    sol.digits_estimated = match fine {
        Ok(fine) => estimate(problem, &sol, &fine),
        // The finer run is outside its range where the nominal one is not: nothing is confirmed.
        Err(_) => Digits::from_points(0.0, sol.points.iter().map(|_| [0.0; 4]), 0.0),
    };
    Ok(sol)
}

/// Digits of `sol` from its difference to the finer run `fine` (module doc); shared with the
/// collocation in eta ([`crate::adhesion::collocation_f64`]), whose check run is its `fine`.
pub(crate) fn estimate(problem: &AdhesionProblem, sol: &AdhesionSolutionF64, fine: &AdhesionSolutionF64) -> Digits {
    let cap = F64_DIGITS_CAP;
    let scales = ScalesF64::new(problem, fine.half_width, fine.normal_load);
    let (size, value) = match problem.size() {
        AdhesionSize::HalfWidth(_) => (sol.normal_load - fine.normal_load, sol.normal_load),
        AdhesionSize::NormalLoad(_) => (sol.half_width - fine.half_width, sol.half_width),
    };
    // The f64 round-off floor (issue 34): the finer run does not see it.
    let dig = |u: f64, v: f64, scale: f64| f64_digits(u - v, u, scale);
    let size = f64_digits(size, value, scales.size(problem.size()));
    let [psi, phi, q1, q2] = scales.point_scales();
    Digits::from_points(
        size,
        sol.points
            .iter()
            .zip(&fine.points)
            .map(|(u, v)| [dig(u.psi, v.psi, psi), dig(u.phi, v.phi, phi), dig(u.q1, v.q1, q1), dig(u.q2, v.q2, q2)]),
        cap,
    )
}
