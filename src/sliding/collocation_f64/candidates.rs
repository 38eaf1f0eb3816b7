//! Candidate solutions at the main run's accuracy: every root of the side conditions (contact
//! size and, for the sinusoid, the branch of (X, Y)) with its number of nodes, and the discrete
//! state of a candidate at any number of nodes.

use super::closure::tau0_side;
use super::error::{Result, SlidingF64Error};
use super::general::{map_of, profile_nodes, profile_size, profile_state, size_guess, size_of_half_length};
use super::interpolant::State;
use super::operator::{collocation, collocation_nodes};
use super::parabola::{kuznetsov_guess, parabola_lambda, parabola_state, periodic_parabola_state};
use super::sinusoid::{
    line_circle, refine_sinusoid_lambda, sinusoid_bases, sinusoid_scan, sinusoid_state, sinusoid_xy_at,
};
use super::solution::SolverOptions;
use super::tangent_map::Map;
use crate::params::sliding::{ShapeF64, SlidingParamsF64, TargetF64};
use std::f64::consts::PI;

/// Candidate contact sizes and centres: (lambda or l) for the main run.
#[derive(Debug, Clone, Copy)]
pub(super) enum Candidate {
    /// Parabola, periodic: lambda.
    ParabolaPeriodic(f64),
    /// Parabola, single punch (l is explicit).
    ParabolaSingle,
    /// Sinusoid: lambda and (X, Y) branch sign (which intersection of line and circle).
    Sinusoid { lambda: f64, branch: i8 },
    /// Polynomial or circle: the size (lambda, or l for a single punch; `general.rs`).
    Profile(f64),
}

/// Period L (infinite for a single punch).
fn period(prm: &SlidingParamsF64) -> f64 {
    prm.period.unwrap_or(f64::INFINITY)
}

/// Builds the state of a candidate at n nodes (re-solving the scalar equation when P2 is given).
/// With `resolve` the scalar equation in lambda is solved again at n nodes (check run); without
/// it the candidate's lambda (already solved at n nodes) is used.
pub(super) fn state_of(
    prm: &SlidingParamsF64,
    target: TargetF64,
    cand: Candidate,
    n: usize,
    resolve: bool,
) -> Result<State> {
    let col = collocation(prm.theta, n)?;
    match (cand, &prm.shape) {
        (Candidate::Profile(s0), ShapeF64::Polynomial { .. } | ShapeF64::Circular { .. }) => {
            let s = match target {
                TargetF64::HalfLength(l) => size_of_half_length(prm, l),
                TargetF64::NormalLoad(p2) if resolve => profile_size(prm, p2, n, Some(s0))?,
                TargetF64::NormalLoad(_) => s0,
            };
            profile_state(&col, prm, map_of(prm, s))
        }
        (Candidate::ParabolaSingle, ShapeF64::Parabolic { .. }) => {
            let l = match target {
                TargetF64::HalfLength(l) => l,
                TargetF64::NormalLoad(p2) => {
                    // P2 scales as l^2: P2 = E* k l^2 P2_1 (P2_1 at l = 1).
                    let unit = parabola_state(&col, prm, Map::Single { l: 1.0 })?;
                    (p2 / unit.p2).sqrt()
                }
            };
            parabola_state(&col, prm, Map::Single { l })
        }
        (Candidate::ParabolaPeriodic(lam0), ShapeF64::Parabolic { .. }) => {
            let big_l = period(prm);
            let lam = match target {
                TargetF64::HalfLength(l) => PI * l / big_l,
                TargetF64::NormalLoad(p2) if resolve => parabola_lambda(prm, big_l, p2, n, Some(lam0))?,
                TargetF64::NormalLoad(_) => lam0,
            };
            periodic_parabola_state(&col, prm, big_l, lam)
        }
        (Candidate::Sinusoid { lambda, branch }, ShapeF64::Sinusoidal { d }) => {
            let big_l = period(prm);
            let s = PI * prm.e_star * *d / big_l;
            match target {
                TargetF64::HalfLength(l) => {
                    let map = Map::periodic(big_l, PI * l / big_l);
                    let (bx, by) = sinusoid_bases(&col, prm, &map)?;
                    let pts = line_circle(bx.cond, by.cond, tau0_side(prm, &map) / s);
                    let (x, y) = pts.get(branch as usize).copied().ok_or_else(|| SlidingF64Error::NoConvergence {
                        reason: "the solution branch disappeared in the check run".into(),
                    })?;
                    Ok(sinusoid_state(map, big_l, s, &bx, &by, x, y))
                }
                TargetF64::NormalLoad(p2) => {
                    let lam = if resolve { refine_sinusoid_lambda(&col, prm, big_l, s, p2, lambda)? } else { lambda };
                    let map = Map::periodic(big_l, lam);
                    let (bx, by) = sinusoid_bases(&col, prm, &map)?;
                    let (x, y) = sinusoid_xy_at(&bx, &by, prm, &map, s, p2)?;
                    let r = x.hypot(y);
                    Ok(sinusoid_state(map, big_l, s, &bx, &by, x / r, y / r))
                }
            }
        }
        _ => unreachable!("candidate kind matches the shape"),
    }
}

/// All candidates of the problem (main-run accuracy), with the nodes to use for each. For the
/// sinusoid under a load no root may exist: [`SlidingF64Error::NoRoot`] with the
/// largest load of the scan.
pub(super) fn candidates(
    prm: &SlidingParamsF64,
    target: TargetF64,
    options: &SolverOptions,
) -> Result<Vec<(Candidate, usize)>> {
    let pick = |lam: f64| options.nodes.unwrap_or_else(|| collocation_nodes(lam, options));
    match (&prm.shape, prm.period) {
        (ShapeF64::Polynomial { .. } | ShapeF64::Circular { .. }, _) => {
            let pick = |s: f64| {
                options.nodes.unwrap_or_else(|| {
                    collocation_nodes(if prm.period.is_some() { s } else { 0.0 }, options)
                        .max(profile_nodes(prm, s, options))
                })
            };
            match target {
                TargetF64::HalfLength(l) => {
                    let s = size_of_half_length(prm, l);
                    Ok(vec![(Candidate::Profile(s), pick(s))])
                }
                TargetF64::NormalLoad(p2) => {
                    // As the periodic parabola: nodes for the guess, then for the solved size
                    // until the count settles (at most 3 more solves).
                    let mut n = pick(size_guess(prm, p2));
                    let mut s = profile_size(prm, p2, n, None)?;
                    if options.nodes.is_none() {
                        for _ in 0..3 {
                            let n_new = pick(s);
                            if n_new == n {
                                break;
                            }
                            n = n_new;
                            s = profile_size(prm, p2, n, Some(s))?;
                        }
                    }
                    Ok(vec![(Candidate::Profile(s), n)])
                }
            }
        }
        (ShapeF64::Parabolic { .. }, None) => Ok(vec![(Candidate::ParabolaSingle, options.nodes.unwrap_or(8))]),
        (ShapeF64::Parabolic { .. }, Some(big_l)) => {
            match target {
                TargetF64::HalfLength(l) => {
                    Ok(vec![(Candidate::ParabolaPeriodic(PI * l / big_l), pick(PI * l / big_l))])
                }
                TargetF64::NormalLoad(p2) => {
                    // Nodes for the Kuznetsov-type guess of lambda (parabola_lambda), then for the
                    // solved lambda until the node count settles (at most 3 more solves).
                    let mut n = options.nodes.unwrap_or_else(|| pick(kuznetsov_guess(prm, big_l, p2)));
                    if options.nodes.is_none() && n >= options.max_nodes {
                        // The guess (exact at theta = 0) needs all the nodes allowed or more: beyond
                        // this method's reach; the solver's refusal tells from the admissible scan
                        // whether the load is also beyond the physical range.
                        return Err(SlidingF64Error::NoRoot { load: p2, largest: f64::NAN });
                    }
                    let mut lam = parabola_lambda(prm, big_l, p2, n, None)?;
                    if options.nodes.is_none() {
                        for _ in 0..3 {
                            let n_new = pick(lam);
                            if n_new == n {
                                break;
                            }
                            n = n_new;
                            lam = parabola_lambda(prm, big_l, p2, n, Some(lam))?;
                        }
                    }
                    Ok(vec![(Candidate::ParabolaPeriodic(lam), n)])
                }
            }
        }
        (ShapeF64::Sinusoidal { d }, Some(big_l)) => {
            let s = PI * prm.e_star * *d / big_l;
            match target {
                TargetF64::HalfLength(l) => {
                    let lam = PI * l / big_l;
                    let n = pick(lam);
                    let col = collocation(prm.theta, n)?;
                    let map = Map::periodic(big_l, lam);
                    let (bx, by) = sinusoid_bases(&col, prm, &map)?;
                    let pts = line_circle(bx.cond, by.cond, tau0_side(prm, &map) / s);
                    Ok(pts
                        .iter()
                        .enumerate()
                        .filter(|(_, (x, y))| x * bx.p2 + y * by.p2 > 0.0)
                        .map(|(i, _)| (Candidate::Sinusoid { lambda: lam, branch: i as i8 }, n))
                        .collect())
                }
                TargetF64::NormalLoad(p2) => Ok(sinusoid_scan(prm, big_l, s, p2, options)?
                    .into_iter()
                    .map(|(lambda, n)| (Candidate::Sinusoid { lambda, branch: 0 }, n))
                    .collect()),
            }
        }
        (ShapeF64::Sinusoidal { .. }, None) => unreachable!("refused by the model: a sinusoid has a period"),
    }
}
