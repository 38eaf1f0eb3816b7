//! The largest physical load of the sinusoid (the same meaning as the MPFR method's
//! `sinusoid_max_physical_load`): the load at which the physical branch of P2(lambda) ends.

use super::candidates::{candidates, state_of};
use super::error::{Result, SlidingF64Error};
use super::operator::collocation;
use super::outputs::outputs;
use super::physical::physicality;
use super::solution::SolverOptions;
use crate::params::sliding::{SlidingParamsF64, TargetF64};
use std::f64::consts::PI;

/// Largest P2 among the physical solutions of the direct problem at contact size lambda
/// (`None` if there is none).
fn physical_load_at(prm: &SlidingParamsF64, lam: f64, options: &SolverOptions) -> Result<Option<f64>> {
    let big_l = prm.period.unwrap_or(f64::INFINITY);
    let target = TargetF64::HalfLength(lam * big_l / PI);
    let mut best: Option<f64> = None;
    for (cand, n) in candidates(prm, target, options)? {
        let col = collocation(prm.theta, n)?;
        let st = state_of(prm, target, cand, n, false)?;
        let out = outputs(&col, prm, &st, &[]);
        if physicality(&col, prm, &st, &out).is_ok() && out.p2 > 0.0 {
            best = Some(best.map_or(out.p2, |b: f64| b.max(out.p2)));
        }
    }
    Ok(best)
}

/// The maximum physical load of the sinusoid and its lambda: scans lambda for the first loss of
/// physicality (p < 0 at an end, or a negative gap), then bisects it (40 steps). Assumes the
/// physical solutions form one interval (0, lambda*) on which P2 increases, as observed on the
/// charts of `cargo run --release --example collocation_f64_charts -- load-curve` [heuristic].
pub(super) fn sinusoid_max_physical_load(
    prm: &SlidingParamsF64,
    options: &SolverOptions,
) -> Result<Option<(f64, f64)>> {
    const STEPS: usize = 48;
    let mut last: Option<(f64, f64)> = None;
    let mut first_bad = None;
    for j in 1..=STEPS {
        let lam = 1.45 * j as f64 / STEPS as f64;
        match physical_load_at(prm, lam, options)? {
            Some(p) => last = Some((p, lam)),
            None => {
                if last.is_some() {
                    first_bad = Some(lam);
                    break;
                }
            }
        }
    }
    let (Some((mut p, mut lo)), Some(mut hi)) = (last, first_bad) else {
        return Ok(last);
    };
    for _ in 0..40 {
        let mid = 0.5 * (lo + hi);
        match physical_load_at(prm, mid, options)? {
            Some(pm) => {
                lo = mid;
                p = pm;
            }
            None => hi = mid,
        }
    }
    Ok(Some((p, lo)))
}

/// Replaces the scan's largest load in a [`SlidingF64Error::LoadExceedsMaximum`] by the largest
/// physical load and its contact fraction, when there is one; other errors pass unchanged.
pub(super) fn with_physical_maximum(
    prm: &SlidingParamsF64,
    options: &SolverOptions,
    e: SlidingF64Error,
) -> SlidingF64Error {
    let SlidingF64Error::LoadExceedsMaximum { load, .. } = e else { return e };
    match sinusoid_max_physical_load(prm, options) {
        Ok(Some((p, lam))) => SlidingF64Error::load_exceeds_maximum(prm, load, p, lam),
        Ok(None) => e,
        Err(err) => err,
    }
}
