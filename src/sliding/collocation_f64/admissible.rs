//! The admissible range of the load (or size) by the f64 method's own direct problem, judged by
//! the shared criterion ([`crate::sliding::physicality::admissible`]): quoted by its refusals.

use super::candidates::{candidates, state_of};
use super::error::{Result, SlidingF64Error};
use super::operator::collocation;
use super::outputs::outputs;
use super::physical::physicality;
use super::solution::SolverOptions;
use crate::params::sliding::{SlidingParamsF64, TargetF64};
use crate::sliding::physicality::admissible::{admissible, Admissible, SizeContacts, LAMBDA_SCAN_MAX};
use std::f64::consts::PI;

/// The size parameter's scan range: lambda up to [`LAMBDA_SCAN_MAX`] for a period; for a single
/// punch l up to 4 times the requested size (or the single-punch half-length at the load).
fn scan_max(prm: &SlidingParamsF64) -> f64 {
    match (prm.period, prm.target) {
        (Some(_), _) => LAMBDA_SCAN_MAX,
        (None, TargetF64::HalfLength(l)) => 4.0 * l,
        (None, TargetF64::NormalLoad(p2)) => 4.0 * prm.l_s(p2),
    }
}

/// The contacts of the direct problem at size parameter `s` with their verdicts. A size at which
/// the direct problem cannot be solved (e.g. no centre gives a positive load) has none.
fn contacts_at(prm: &SlidingParamsF64, s: f64, options: &SolverOptions) -> Result<SizeContacts> {
    let l = prm.period.map_or(s, |big_l| s * big_l / PI);
    let target = TargetF64::HalfLength(l);
    let cands = match candidates(prm, target, options) {
        Ok(c) => c,
        Err(SlidingF64Error::NoConvergence { .. } | SlidingF64Error::NoRoot { .. }) => return Ok(vec![]),
        Err(e) => return Err(e),
    };
    let mut out = Vec::new();
    for (cand, n) in cands {
        let col = collocation(prm.theta, n)?;
        let Ok(st) = state_of(prm, target, cand, n, false) else { continue };
        let o = outputs(&col, prm, &st, &[]);
        out.push((o.p2, physicality(&col, prm, &st, &o).is_ok()));
    }
    Ok(out)
}

/// The admissible sizes and loads of the problem at its other parameters.
pub(super) fn admissible_range(prm: &SlidingParamsF64, options: &SolverOptions) -> Result<Admissible> {
    admissible(scan_max(prm), |s| contacts_at(prm, s, options))
}

/// The admissible range in words, as the request is posed (loads for a given load, sizes for a
/// given half-length).
pub(super) fn ranges_text(prm: &SlidingParamsF64, adm: &Admissible) -> String {
    let to_length = |s: f64| prm.period.map_or(s, |big_l| s * big_l / PI);
    match prm.target {
        TargetF64::NormalLoad(_) => match prm.period {
            Some(_) => adm.loads_text(1.0, |s| 2.0 * s / PI, "contact fraction 2l/L"),
            None => adm.loads_text(1.0, |s| s, "half_length"),
        },
        TargetF64::HalfLength(_) => adm.sizes_text(to_length),
    }
}
