//! Verified solution: two runs, the second with more bits and 1.5x the nodes.
//!
//! digits_verified = -log10(|difference| / scale) per quantity, with the scales of issue 3:
//! l for a, b, c; max p for p(x); P2 for P1 and P2; k l P2 for F_def (for the sinusoid the
//! osculating k = 2 pi^2 D/L^2). The headline is the minimum.

use super::error::SlidingError;
use super::setup::{Convention, Setup};
use super::solution::{Accuracy, SlidingSolution, VerifiedSolution};
use super::solve::{solve_located, NodeRule};
use crate::model::{Exact, SlidingProblem};
use rug::Float;

/// Guard bits added to the bits of the requested digits.
pub const GUARD_BITS: u32 = 32;
/// Extra bits of the verification run.
pub const VERIFY_EXTRA_BITS: u32 = 32;

/// Working precision for `digits` decimal digits: ceil(digits log2 10) + GUARD_BITS.
pub fn precision_for(digits: u32) -> u32 {
    (digits as f64 * std::f64::consts::LOG2_10).ceil() as u32 + GUARD_BITS
}

fn digits_of(x: &Float, y: &Float, scale: &Float, cap: f64) -> f64 {
    let d = Float::with_val(x.prec().max(y.prec()), x - y).abs();
    if d.is_zero() || scale.is_zero() {
        return cap;
    }
    let r = Float::with_val(64, &d / scale);
    (-r.log10().to_f64()).min(cap)
}

/// Accuracy of `s1` judged against `s2`.
pub fn compare(setup: &Setup, s1: &SlidingSolution, s2: &SlidingSolution) -> Accuracy {
    let cap = s2.prec as f64 * std::f64::consts::LOG10_2;
    let mut digits = vec![];
    for (name, x, y) in [("a", &s1.a, &s2.a), ("b", &s1.b, &s2.b), ("c", &s1.c, &s2.c)] {
        digits.push((name.to_string(), digits_of(x, y, &s1.l, cap)));
    }
    for (name, x, y) in [("P1", &s1.p1, &s2.p1), ("P2", &s1.p2, &s2.p2)] {
        digits.push((name.to_string(), digits_of(x, y, &s1.p2, cap)));
    }
    let kl = Float::with_val(s1.prec, setup.osculating_k() * &s1.l) * &s1.p2;
    digits.push(("F_def".into(), digits_of(&s1.f_def, &s2.f_def, &kl, cap)));
    for (i, (q1, q2)) in s1.pressure.iter().zip(&s2.pressure).enumerate() {
        digits.push((format!("p[{i}]"), digits_of(&q1.p, &q2.p, &s1.max_pressure, cap)));
    }
    let digits_verified = digits.iter().map(|d| d.1).fold(f64::INFINITY, f64::min);
    Accuracy { digits, digits_verified }
}

/// Solves Problem 1 to `digits` digits and verifies them: run 1 at [`precision_for`]`(digits)`
/// bits with the error-model node count, run 2 with [`VERIFY_EXTRA_BITS`] more bits and 1.5x the
/// nodes. Returns every physical solution (smallest contact first) with its accuracy.
pub fn solve_verified(
    problem: &SlidingProblem,
    points: &[Exact],
    digits: u32,
) -> Result<Vec<VerifiedSolution>, SlidingError> {
    solve_verified_with(problem, points, digits, Convention::Paper)
}

/// [`solve_verified`] with the surface convention `convention` (see [`Convention`]).
pub fn solve_verified_with(
    problem: &SlidingProblem,
    points: &[Exact],
    digits: u32,
    convention: Convention,
) -> Result<Vec<VerifiedSolution>, SlidingError> {
    if digits == 0 || digits > 2000 {
        return Err(SlidingError::parameter("digits", digits, "must lie in 1..=2000"));
    }
    let prec = precision_for(digits);
    let d = digits as f64;
    let run1 = solve_located(problem, points, NodeRule { digits: d, factor: 1.0 }, true, prec, None, convention)?;
    // Run 2 refines, independently at its own precision and rule, the sizes run 1 located.
    let located: Vec<_> = run1.iter().map(|x| x.1).collect();
    let run2: Vec<SlidingSolution> = solve_located(
        problem,
        points,
        NodeRule { digits: d, factor: 1.5 },
        false,
        prec + VERIFY_EXTRA_BITS,
        Some(&located),
        convention,
    )?
    .into_iter()
    .map(|x| x.0)
    .collect();
    let run1: Vec<SlidingSolution> = run1.into_iter().map(|x| x.0).collect();
    // Run 2 skips the physicality checks, so it may list extra (non-physical) roots: each
    // solution of run 1 is paired with the run-2 solution nearest in (l, c).
    let setup = Setup::new(problem, prec)?;
    let mut out = vec![];
    for s1 in run1 {
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
                "the verification run found no solution near l = {:.12} (nearest differs by {:.1e} relative)",
                s1.l,
                dist(s2)
            )));
        }
        let accuracy = compare(&setup, &s1, s2);
        out.push(VerifiedSolution { solution: s1, accuracy });
    }
    Ok(out)
}
