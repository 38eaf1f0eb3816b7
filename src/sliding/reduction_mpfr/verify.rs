//! Verified solution: two runs, the second with [`VERIFY_EXTRA_BITS`] more bits and 1.5x the
//! nodes, compared under the project's accuracy rule ([`crate::numerics::accuracy`]).
//!
//! digits_verified = -log10(|difference| / scale) per quantity, with the scales of issue 3:
//! l for a, b, c; max p for p(x); P2 for P1 and P2; k l P2 for F_def (for the sinusoid the
//! osculating k = 2 pi^2 D/L^2). The headline is the minimum.

use super::error::SlidingError;
use super::setup::Setup;
use super::solution::{Accuracy, SlidingSolution, VerifiedSolution};
use super::solve::{check_points, solve_located, Checks, NodeRule};
use crate::model::{Exact, SlidingProblem};
use crate::numerics::accuracy::{agreement_mpfr, digits_cap_for_bits, readable_f64, readable_mpfr};
use crate::numerics::precision::VERIFY_EXTRA_BITS;
use crate::params::sliding::SlidingParamsMpfr;
use crate::params::sliding::SlidingScale;
use rug::Float;

pub use crate::numerics::precision::precision_for;

/// Accuracy of `s1` judged against `s2` (both in the same units; `params` of `s1`'s run).
pub fn compare(params: &SlidingParamsMpfr, s1: &SlidingSolution, s2: &SlidingSolution) -> Accuracy {
    let cap = digits_cap_for_bits(s2.prec);
    let mut digits = vec![];
    let scale = |q: SlidingScale| q.mpfr(&params.k, &s1.l, &s1.p2, &s1.max_pressure);
    let length = scale(SlidingScale::Length);
    for (name, x, y) in [("a", &s1.a, &s2.a), ("b", &s1.b, &s2.b), ("c", &s1.c, &s2.c)] {
        digits.push((name.to_string(), agreement_mpfr(x, y, &length, cap)));
    }
    let load = scale(SlidingScale::Load);
    for (name, x, y) in [("P1", &s1.p1, &s2.p1), ("P2", &s1.p2, &s2.p2)] {
        digits.push((name.to_string(), agreement_mpfr(x, y, &load, cap)));
    }
    let f_def = scale(SlidingScale::DeformationForce);
    digits.push(("F_def".into(), agreement_mpfr(&s1.f_def, &s2.f_def, &f_def, cap)));
    let pressure = scale(SlidingScale::Pressure);
    for (i, (q1, q2)) in s1.pressure.iter().zip(&s2.pressure).enumerate() {
        digits.push((format!("p[{i}]"), agreement_mpfr(&q1.p, &q2.p, &pressure, cap)));
    }
    let digits_verified = digits.iter().map(|d| d.1).fold(f64::INFINITY, f64::min);
    Accuracy { digits, digits_verified }
}

/// Solves Problem 1 to `digits` digits and verifies them: run 1 at [`precision_for`]`(digits)`
/// bits with the error-model node count, run 2 with [`VERIFY_EXTRA_BITS`] more bits and 1.5x the
/// nodes. The surface convention is the problem's. Returns every physical solution (smallest
/// contact first) with its accuracy, in the problem's units (the runs, and their comparison, are
/// in units of E*).
pub fn solve_verified(
    problem: &SlidingProblem,
    points: &[Exact],
    digits: u32,
) -> Result<Vec<VerifiedSolution>, SlidingError> {
    if digits == 0 || digits > 2000 {
        return Err(SlidingError::parameter("digits", digits, "must lie in 1..=2000"));
    }
    check_points(points)?;
    let setup = Setup::new(problem)?;
    let prec = precision_for(digits);
    let d = digits as f64;
    let params1 = SlidingParamsMpfr::new(problem, prec)?;
    let run1 = solve_located(&setup, &params1, points, NodeRule { digits: d, factor: 1.0 }, Checks::Physical, None)?;
    // Run 2 refines, independently at its own precision and rule, the sizes run 1 located.
    let located: Vec<_> = run1.iter().map(|x| x.1).collect();
    let params2 = SlidingParamsMpfr::new(problem, prec + VERIFY_EXTRA_BITS)?;
    let run2: Vec<SlidingSolution> =
        solve_located(&setup, &params2, points, NodeRule { digits: d, factor: 1.5 }, Checks::Skip, Some(&located))?
            .into_iter()
            .map(|x| x.0)
            .collect();
    // Run 2 skips the physicality checks, so it may list extra (non-physical) roots: each
    // solution of run 1 is paired with the run-2 solution nearest in (l, c).
    let mut out = vec![];
    for (s1, _) in run1 {
        let dist = |s2: &SlidingSolution| -> f64 {
            (Float::with_val(64, &s1.l - &s2.l).to_f64().abs() + Float::with_val(64, &s1.c - &s2.c).to_f64().abs())
                / s1.l.to_f64()
        };
        let s2 = run2
            .iter()
            .min_by(|x, y| dist(x).partial_cmp(&dist(y)).unwrap_or(std::cmp::Ordering::Equal))
            .ok_or_else(|| SlidingError::NoConvergence("the verification run found no solution".into()))?;
        if dist(s2) > 1e-6 {
            return Err(SlidingError::NoConvergence(format!(
                "the verification run found no solution near l = {} (nearest differs by {} relative)",
                readable_mpfr(&s1.l),
                readable_f64(dist(s2))
            )));
        }
        let accuracy = compare(&params1, &s1, s2);
        out.push(VerifiedSolution { solution: s1.in_units_of(&params1.unit), accuracy });
    }
    Ok(out)
}
