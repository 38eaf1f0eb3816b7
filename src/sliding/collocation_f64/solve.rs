//! The driver of the f64 method: parameters once, every candidate root, its physicality, the check
//! run, and the solutions sorted by contact size.

use super::admissible::{admissible_range, ranges_text};
use super::candidates::{candidates, state_of, Candidate};
use super::error::{Result, SlidingF64Error};
use super::operator::collocation;
use super::outputs::outputs;
use super::physical::physicality;
use super::solution::{SlidingSolutionF64, SlidingSolutionsF64, SolverOptions};
use super::verify::check_run;
use crate::model::SlidingProblem;
use crate::numerics::accuracy::readable_f64;
use crate::params::sliding::{check_profile_on_contact, SlidingParamsF64};
use crate::sliding::physicality::refusal_in_reach;

/// Every candidate root of the side conditions at the main run's nodes, before the physicality
/// check removes some (for the sinusoid with theta != 0 a load below the maximum is reached
/// twice). None reaching the load (the sinusoid's scan) is an empty list.
fn all_candidates(prm: &SlidingParamsF64, options: &SolverOptions) -> Result<Vec<(Candidate, usize)>> {
    match candidates(prm, prm.target, options) {
        Err(SlidingF64Error::NoRoot { .. }) => Ok(vec![]),
        other => other,
    }
}

/// Solves Problem 1 (docs/theory.md section 3) in f64 by Gauss–Jacobi collocation and returns every
/// physical solution, smallest contact first, with p at the requested `points` (xh = (x - c)/l in
/// (-1, 1)) and an accuracy estimate from a check run with n + max(8, n/4) nodes.
///
/// Errors: inputs that do not fit f64 or |theta| too close to 1/2
/// ([`SlidingF64Error::Input`]), points outside (-1, 1), the periodic parabola's contact
/// leaving (-L/2, L/2), a load above the sinusoid's maximum, no physical solution, no convergence
/// (including an estimated error above `options.accept`). `crate::error::Error::from` keeps
/// the kind of each.
pub fn solve_sliding_f64(
    problem: &SlidingProblem,
    points: &[f64],
    options: &SolverOptions,
) -> Result<SlidingSolutionsF64> {
    check_points(points)?;
    solve_sliding_f64_with(problem, &SlidingParamsF64::new(problem)?, points, options)
}

/// The requested points xh = (x - c)/l must lie in (-1, 1).
fn check_points(points: &[f64]) -> Result<()> {
    match points.iter().find(|p| !(p.abs() < 1.0)) {
        Some(&p) => Err(SlidingF64Error::InvalidPoint { value: p }),
        None => Ok(()),
    }
}

/// [`solve_sliding_f64`] with the problem's f64 parameters already derived (`prm` must be
/// `SlidingParamsF64::new(problem)`): for a caller that solves one problem several times (at
/// other points, node counts or tolerances, e.g. timing runs), which then derives them from the
/// exact inputs (kappa and beta in exact rational arithmetic, each input rounded once) only once.
/// Same errors, except the parameters' own.
pub fn solve_sliding_f64_with(
    problem: &SlidingProblem,
    prm: &SlidingParamsF64,
    points: &[f64],
    options: &SolverOptions,
) -> Result<SlidingSolutionsF64> {
    check_points(points)?;
    let target = prm.target;
    let cands = all_candidates(prm, options)?;
    let mut solutions = Vec::new();
    let mut reasons = Vec::new();
    for (cand, n) in cands {
        let col = collocation(prm.theta, n)?;
        let st = state_of(prm, target, cand, n, false)?;
        let out = outputs(&col, prm, &st, points);
        // Polynomial and circle: the contact inside |x| < R, convex, with a small slope.
        check_profile_on_contact(problem, -out.a, out.b)?;
        let gap = match physicality(&col, prm, &st, &out) {
            Ok(g) => g,
            Err(r) if r.is_physical() => {
                reasons.push(format!("lambda = {}: {}", readable_f64(out.lambda), r.why()));
                continue;
            }
            Err(r) => return Err(SlidingF64Error::NoConvergence { reason: r.why() }),
        };
        let accuracy = check_run(prm, target, cand, &out, n, points)?;
        let all = [out.lambda, out.l, out.a, out.b, out.c, out.p1, out.p2, out.f_def, out.max_p];
        if all.iter().any(|v| !v.is_finite()) || out.pressure.iter().any(|p| !p.p.is_finite()) {
            return Err(SlidingF64Error::NoConvergence { reason: format!("non-finite result at n = {n}") });
        }
        if !(accuracy.max() <= options.accept) {
            return Err(SlidingF64Error::NoConvergence {
                reason: format!(
                    "estimated relative error {} > {} at lambda = {} with {n} nodes (max_nodes = {})",
                    readable_f64(accuracy.max()),
                    readable_f64(options.accept),
                    readable_f64(out.lambda),
                    options.max_nodes
                ),
            });
        }
        let wear_per_distance = prm.period.map(|big_l| prm.wear * out.p2 / big_l);
        solutions.push(SlidingSolutionF64 {
            theta: prm.theta,
            kappa: prm.kappa,
            lambda: out.lambda,
            l: out.l,
            a: out.a,
            b: out.b,
            c: out.c,
            p1: out.p1,
            p2: out.p2,
            f_def: out.f_def,
            wear_per_distance,
            wear_rate: match (wear_per_distance, prm.speed) {
                (Some(w), Some(v)) => Some(w * v),
                _ => None,
            },
            worn_area_per_distance: prm.wear * out.p2,
            max_pressure: out.max_p,
            physicality: gap,
            pressure: out.pressure,
            nodes: n,
            accuracy,
        });
    }
    if solutions.is_empty() {
        let adm = admissible_range(prm, options)?;
        let ranges = ranges_text(prm, &adm);
        return Err(SlidingF64Error::Refused(refusal_in_reach(problem, &adm, 1.0, &reasons, &ranges)));
    }
    solutions.sort_by(|x, y| x.l.total_cmp(&y.l));
    Ok(SlidingSolutionsF64 { solutions })
}

/// One root of the side conditions at the main run's nodes, physical or not (for charts and
/// diagnostics; [`solve_sliding_f64`] returns the physical ones only).
#[derive(Debug, Clone, PartialEq)]
pub struct CandidateRoot {
    /// lambda = pi l/L (0 for a single punch).
    pub lambda: f64,
    /// Half-length l.
    pub l: f64,
    /// Centre c.
    pub c: f64,
    /// P2.
    pub p2: f64,
    /// Nodes.
    pub nodes: usize,
    /// The most negative gap when physical, or why not.
    pub physical: std::result::Result<f64, String>,
}

/// Every root of the side conditions of `problem` (without the check run), with its physicality.
pub fn candidate_roots(problem: &SlidingProblem, options: &SolverOptions) -> Result<Vec<CandidateRoot>> {
    let prm = SlidingParamsF64::new(problem)?;
    let mut roots = Vec::new();
    for (cand, n) in all_candidates(&prm, options)? {
        let col = collocation(prm.theta, n)?;
        let st = state_of(&prm, prm.target, cand, n, false)?;
        let out = outputs(&col, &prm, &st, &[]);
        let physical = physicality(&col, &prm, &st, &out).map(|g| g.min_gap).map_err(|r| r.why());
        roots.push(CandidateRoot { lambda: out.lambda, l: out.l, c: out.c, p2: out.p2, nodes: n, physical });
    }
    Ok(roots)
}
