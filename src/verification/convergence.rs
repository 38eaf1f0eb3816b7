//! Term-by-term verification of the Problem 1 series against the high-precision solution
//! (sliding issue): at fixed load P2 and varying period L, the remainder of the series truncated
//! after m corrections (every term through Lambda^(2m)) must scale like Lambda^(2m+2). The
//! observed order is the least-squares slope of log(remainder) against log(Lambda).
//!
//! In the `periodic` convention (docs/theory.md section 8; [`sliding_convergence`] on a problem of that
//! convention) the series hold every power of Lambda: row m keeps every term through Lambda^m
//! (m = 1..=2 max_corrections) and the remainder scales like Lambda^(m+1) (`predicted` = m + 1;
//! for the parabola this is the centre's order, its l/l_s being even: Lambda^(m+1) for odd m and
//! Lambda^(m+2) for even m, `predicted_l`).
//!
//! Varying P2 at fixed L would make T = beta tau0/(E* k l_s) change with the load and spoil the
//! slope; fixing P2 keeps theta and T fixed while Lambda = pi l_s / L varies.

use crate::asymptotics::sliding::{sliding_expansion_with, SlidingShape};
use crate::error::Error;
use crate::model::{Convention, Exact, Period, PunchShape, SlidingProblem};
use crate::numerics::precision::precision_for;
use crate::sliding::{self, series};
use exact_series::Q;
use rug::Float;

/// One row of a convergence table.
#[derive(Debug, Clone, PartialEq)]
pub struct OrderRow {
    /// Number of corrections m (series through Lambda^(2m); `periodic`: through Lambda^m).
    pub corrections: usize,
    /// Predicted order 2m + 2 (`periodic`: m + 1).
    pub predicted: f64,
    /// Predicted order for l (= `predicted`, except the `periodic` parabola: module doc).
    pub predicted_l: f64,
    /// Observed least-squares slope for the contact half-length l.
    pub observed_l: f64,
    /// Observed slope for the centre c (relative to l_s); `None` when c vanishes (symmetric case).
    pub observed_c: Option<f64>,
    /// Smallest and largest remainder seen for l (relative to l_s).
    pub remainder_range: (f64, f64),
}

/// A convergence study of one case.
#[derive(Debug, Clone)]
pub struct ConvergenceStudy {
    /// Case label.
    pub label: String,
    /// theta and T of the case.
    pub theta: f64,
    /// T = beta tau0/(E* k l_s).
    pub t: f64,
    /// The Lambda values used.
    pub lambdas: Vec<f64>,
    /// One row per number of corrections.
    pub rows: Vec<OrderRow>,
}

/// Least-squares slope of y against x.
pub fn slope(x: &[f64], y: &[f64]) -> f64 {
    let n = x.len() as f64;
    let mx = x.iter().sum::<f64>() / n;
    let my = y.iter().sum::<f64>() / n;
    let sxy: f64 = x.iter().zip(y).map(|(a, b)| (a - mx) * (b - my)).sum();
    let sxx: f64 = x.iter().map(|a| (a - mx) * (a - mx)).sum();
    sxy / sxx
}

/// Runs the study for `base` (its period is replaced), at the target Lambda values, for
/// m = 1..=max_corrections, with the high-precision solution at `digits` digits.
pub fn sliding_convergence(
    label: &str,
    base: &SlidingProblem,
    target_lambdas: &[f64],
    max_corrections: usize,
    digits: u32,
) -> Result<ConvergenceStudy, Error> {
    let order = 2 * max_corrections;
    let periodic = base.convention() == Convention::PeriodicSurface;
    let shape = series::expansion_shape(base)?;
    // (truncation order, predicted order, predicted order of l) per row.
    let rows_of: Vec<(usize, f64, f64)> = if periodic {
        (1..=order)
            .map(|m| {
                let even_l = shape == SlidingShape::Parabolic && m % 2 == 0;
                (m, (m + 1) as f64, if even_l { (m + 2) as f64 } else { (m + 1) as f64 })
            })
            .collect()
    } else {
        (1..=max_corrections).map(|m| (2 * m, (2 * m + 2) as f64, (2 * m + 2) as f64)).collect()
    };
    let n_rows = rows_of.len();
    let expansion = sliding_expansion_with(shape, order, base.convention())
        .map_err(|e| Error::NoConvergence { what: format!("the series through Lambda^{order}: {e}") })?;
    let prec = precision_for(digits);
    // l_s does not depend on L: take it from a single-punch statement of the same load.
    let single = base.to_builder().period(Period::Infinite).build()?;
    let sp_inf = l_s_of(&single, prec)?;
    let mut lambdas = Vec::new();
    let mut rem_l: Vec<Vec<f64>> = vec![Vec::new(); n_rows + 1];
    let mut rem_c: Vec<Vec<f64>> = vec![Vec::new(); n_rows + 1];
    let (mut theta, mut t) = (0.0, 0.0);
    for &target in target_lambdas {
        // L = pi l_s / Lambda, rounded to an exact rational (Lambda is then recomputed exactly).
        let l_period = std::f64::consts::PI * sp_inf / target;
        let big_l = Q::new(((l_period * 1e6).round() as i64).into(), 1_000_000.into());
        let p = base.to_builder().period(Period::Finite(big_l)).build()?;
        let sol = sliding::solve_verified(&p, &[], digits)?.into_iter().next().ok_or_else(|| Error::NoSolution {
            why: format!("the MPFR solver returned no physical contact at Lambda = {target} in the convergence study"),
        })?;
        let sp = series::series_point(&p, prec)?;
        theta = sp.theta.to_f64();
        t = sp.t.to_f64();
        lambdas.push(sp.big_lambda.to_f64());
        for (m, row) in rows_of.iter().enumerate().map(|(i, r)| (i + 1, r)) {
            let (l, c) = sp.contact(&expansion, row.0);
            let el = Float::with_val(prec, &l - &sol.solution.l).abs() / &sp.l_s;
            let ec = Float::with_val(prec, &c - &sol.solution.c).abs() / &sp.l_s;
            rem_l[m].push(el.to_f64());
            rem_c[m].push(ec.to_f64());
        }
    }
    let logx: Vec<f64> = lambdas.iter().map(|x| x.ln()).collect();
    let rows = (1..=n_rows)
        .map(|m| {
            let (_, predicted, predicted_l) = rows_of[m - 1];
            let ly: Vec<f64> = rem_l[m].iter().map(|e| e.ln()).collect();
            let c_ok = rem_c[m].iter().all(|e| *e > 1e-3_f64.powi(digits as i32 / 3) && e.is_finite());
            let observed_c = c_ok.then(|| slope(&logx, &rem_c[m].iter().map(|e| e.ln()).collect::<Vec<_>>()));
            let lo = rem_l[m].iter().cloned().fold(f64::INFINITY, f64::min);
            let hi = rem_l[m].iter().cloned().fold(0.0, f64::max);
            OrderRow {
                corrections: m,
                predicted,
                predicted_l,
                observed_l: slope(&logx, &ly),
                observed_c,
                remainder_range: (lo, hi),
            }
        })
        .collect();
    Ok(ConvergenceStudy { label: label.to_string(), theta, t, lambdas, rows })
}

fn l_s_of(single: &SlidingProblem, prec: u32) -> Result<f64, Error> {
    let s = sliding::solve_verified(single, &[], (prec as f64 * 0.3) as u32)?;
    Ok(s.first().map(|v| v.solution.l.to_f64()).unwrap_or(f64::NAN))
}

/// A sliding problem on a parabola with the given material and friction data, load P2, period 1
/// (replaced by the study).
pub fn parabola_case(nu: Exact, mu: Exact, tau0: Exact, wear: Exact, p2: Exact) -> SlidingProblem {
    let material = crate::model::Material::from_contact_modulus(nu, Q::from_integer(1.into())).expect("valid nu");
    SlidingProblem::builder()
        .material(material)
        .period(Period::Finite(Q::from_integer(1.into())))
        .shape(PunchShape::Parabolic { k: Q::from_integer(1.into()) })
        .friction(mu)
        .adhesive_friction(tau0)
        .wear(wear)
        .normal_load(p2)
        .build()
        .expect("valid case")
}
