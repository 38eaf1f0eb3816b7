//! The f64 answer of section 4's Problem 2: the lambda^2 series ([`super::series_f64`]) where its
//! estimate reaches [`SERIES_ENOUGH`] digits, else the collocation in eta
//! ([`super::collocation_f64`]), whichever estimates more digits; both are independent of the
//! MPFR method. The single punch and the circle stay with the series (the collocation does not
//! serve them). When both refuse, the collocation's refusal is returned if the series refused
//! for its radius (the collocation reaches further, so its reason is the binding one), else the
//! series'. The `periodic` convention (docs/theory.md section 8, Problem 2) has odd powers of
//! lambda that the lambda^2 series does not carry: a periodic row in that convention is solved by
//! the collocation only.

use super::collocation_f64::solve_collocation_f64;
use super::error::AdhesionError;
use super::series_f64::solution::AdhesionSolutionF64;
use crate::model::OnPunchRow;
use crate::model::{AdhesionProblem, Exact, Period, PunchShape};

/// Estimated digits above which the series' answer is kept without trying the collocation.
pub const SERIES_ENOUGH: f64 = 13.0;

/// The f64 method of Problem 2 with estimated digits (module doc).
pub fn solve_f64(problem: &AdhesionProblem, points: &[Exact]) -> Result<AdhesionSolutionF64, AdhesionError> {
    let s = solve_f64_routes(problem, points)?;
    // Fewer than three estimated digits is no answer: the finer run's agreement no longer estimates
    // the error (issue 34, fuzzing: at lambda = 2.5e-9 P2 off by more than its scale estimating 0
    // digits; at lambda = 3.9e-9 a off by 30% estimating 1.1).
    if !(s.digits_estimated.headline >= 3.0) {
        return Err(AdhesionError::NotConverged {
            what: "the f64 method",
            reason: format!(
                "it estimates {} digits (< 3) at these parameters; the verified MPFR method (--method mpfr) reaches them",
                crate::numerics::accuracy::readable_f64((s.digits_estimated.headline * 10.0).floor() / 10.0)
            ),
        });
    }
    Ok(s)
}

/// The route of [`solve_f64`] (series, or collocation beyond its radius; the collocation alone in
/// the `periodic` convention), whatever its digits.
fn solve_f64_routes(problem: &AdhesionProblem, points: &[Exact]) -> Result<AdhesionSolutionF64, AdhesionError> {
    if problem.periodic_surface() {
        return solve_collocation_f64(problem, points);
    }
    let series = super::series_f64::verify::solve_f64(problem, points);
    if let Ok(s) = &series
        && s.digits_estimated.headline >= SERIES_ENOUGH
    {
        return series;
    }
    let served =
        matches!(problem.period(), Period::Finite(_)) && !matches!(problem.shape(), PunchShape::Circular { .. });
    if !served {
        return series;
    }
    match (series, solve_collocation_f64(problem, points)) {
        (Ok(s), Ok(c)) => Ok(if s.digits_estimated.headline >= c.digits_estimated.headline { s } else { c }),
        (Ok(s), Err(_)) => Ok(s),
        (Err(_), Ok(c)) => Ok(c),
        (Err(se), Err(ce)) => Err(match se {
            AdhesionError::IllConditioned { .. } => ce,
            other => other,
        }),
    }
}
