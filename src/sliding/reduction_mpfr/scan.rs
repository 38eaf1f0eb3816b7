//! The sinusoid's load-curve scan of the locating stage: the relative load residual on both
//! centre branches at 48 sizes up to the stage's cap, whose changes of sign bracket the contact
//! sizes that `solve::locate_with` then refines. Only signs matter here (`SCAN_DIGITS`); the
//! values at a bracket's ends are passed on to Brent's method, so they are always the scan rule's.

use super::branches::branches_with;
use super::equation::ShiftSolution;
use super::error::SlidingError;
use super::nodes::{bucket, nodes_for};
use crate::numerics::gauss_jacobi_mpfr::GaussJacobiRule;
use crate::params::sliding::SlidingParamsMpfr;
use rug::Float;
use std::sync::Arc;

/// One curve per centre branch: (size, relative residual or None where the branch has no centre).
pub(super) type Curves = [Vec<(f64, Option<f64>)>; 2];

/// Sizes of the scan's grid (cap i/GRID, i = 1..=GRID).
const GRID: usize = 48;

/// Digits of the sinusoid's load-curve scan (signs only).
const SCAN_DIGITS: f64 = 8.0;

/// The rule for 1/omega with n nodes for the sinusoid's load-curve scan, which needs only the
/// signs of P2 - target (SCAN_DIGITS): the f64 Gauss–Jacobi rule rounded to the parameters'
/// precision ([`crate::numerics::gauss_jacobi_mpfr::gauss_jacobi_f64_lifted`], about 15 correct
/// digits). The MPFR rule at the locating precision costs O(n^2) MPFR operations per Newton pass,
/// and the scan up to the node cap needs rules of several hundred nodes (about 0.2 s in all, the
/// solver's former floor); brackets are then refined with MPFR rules (`solve::load_lo`). The rules come
/// from the process cache of the MPFR rules: the f64 rules of several hundred nodes are O(n^2)
/// each and were 40% of a repeated solve of the same problem (`cargo bench --bench solve --
/// mpfr_solve`, perf), e.g. the report's sweeps and maps, which scan one (alpha, beta) at several
/// loads.
fn scan_rule(params: &SlidingParamsMpfr, n: usize) -> Result<Arc<GaussJacobiRule>, SlidingError> {
    let (a, b) = params.inverse_weight_exponents();
    crate::numerics::gauss_jacobi_mpfr::gauss_jacobi_f64_lifted(&a, &b, n, params.prec)
        .map_err(|e| SlidingError::NoConvergence(format!("the scan's f64 rule: {e}")))
}

/// The pairs of node counts of [`scan_signs`], tried in turn (lifted f64 rules; 96 and 128 are
/// computed anyway for the grid's smaller sizes).
pub(super) const SIGN_NODES: [(usize, usize); 2] = [(96, 128), (128, 192)];

/// The relative load residuals `rel` on both centre branches at size `s` from two scan rules of
/// fewer nodes than the scan's own `n_full` (a pair of [`SIGN_NODES`], n1 < n2 < n_full), when
/// they settle every sign; None otherwise. The scan's rule at lambda near its cap has up to 384
/// nodes, and its f64 rules are O(n^2) to build: the 192- and 384-node ones took 5.6 ms of a 25 ms
/// cold solve of `scenes/sinusoid_friction.toml` (per-rule timing, a temporary trace), for two
/// grid points whose residuals are far from 0.
///
/// The quadrature error decreases geometrically with n, like rho^(2n), rho = tan(lambda/2)
/// (docs/theory.md section 3, [`nodes_for`]): from n1 to n2 by rho^(2 (n2 - n1)) <= 0.06 within the
/// scan's range (rho <= 0.957 at its cap). Whenever it at least halves, the error of the n2-node
/// value v2 is below |v2 - v1|, so |v2| > 16 |v2 - v1| + 1e-6 gives v2 the sign of the exact
/// residual and of the full scan rule's value (itself within 1e-8 of it). Measured at the cap of
/// `scenes/sinusoid_friction.toml` (lambda = 1.5258, the errors against 512 nodes): 1.55 at 64
/// nodes (a wrong sign there), 0.135 at 96, 0.0101 at 128, 4.8e-5 at 192 (the pair (96, 128) does
/// not settle it, (128, 192) does); at lambda = 1.4941: 5.0e-4, 5.0e-6, 4.0e-10 at 96, 128, 192.
/// Only without the adhesive shear (beta tau0 = 0), where the sinusoid always has both branches
/// ([`shift_solutions`]: none only if R < beta tau0); otherwise None (the caller uses the full rule).
pub(super) fn scan_signs(
    params: &SlidingParamsMpfr,
    s: f64,
    n_full: usize,
    rel: &dyn Fn(&ShiftSolution) -> f64,
) -> Result<Option<Vec<Option<f64>>>, SlidingError> {
    if !params.tau0.is_zero() {
        return Ok(None);
    }
    'pairs: for (n1, n2) in SIGN_NODES {
        if n2 >= n_full {
            break;
        }
        let (b1, b2) = (scan_values(params, s, n1, rel)?, scan_values(params, s, n2, rel)?);
        let mut out = vec![];
        for (x, y) in b1.into_iter().zip(b2) {
            let (Some(v1), Some(v2)) = (x, y) else { return Ok(None) };
            if !(v1.is_finite() && v2.is_finite() && v2.abs() > 16.0 * (v2 - v1).abs() + 1e-6) {
                continue 'pairs;
            }
            out.push(Some(v2));
        }
        return Ok(Some(out));
    }
    Ok(None)
}

/// The residuals `rel` on both centre branches (None: no centre on the branch) at size `s` with
/// the scan's n-node rule ([`scan_rule`]).
pub(super) fn scan_values(
    params: &SlidingParamsMpfr,
    s: f64,
    n: usize,
    rel: &dyn Fn(&ShiftSolution) -> f64,
) -> Result<Vec<Option<f64>>, SlidingError> {
    let b = branches_with(params, &Float::with_val(params.prec, s), &*scan_rule(params, n)?)?;
    Ok((0..2).map(|br| b.get(br).map(rel)).collect())
}

/// Sets the values of grid point `i` on both curves.
fn set(curves: &mut Curves, i: usize, values: &[Option<f64>]) {
    for (curve, v) in curves.iter_mut().zip(values) {
        curve[i].1 = *v;
    }
}

/// The residuals `rel` on both branches at the sizes cap i/GRID with the scan's rule for
/// [`SCAN_DIGITS`] ([`scan_values`]). With `sign_scan`, a point takes its signs from smaller rules
/// ([`scan_signs`]) where they settle them; such a point then gets the scan rule's values where
/// they are used: next to a change of sign (a bracket's end) or a missing branch. If one of them
/// disagreed in sign, every such point is recomputed (never observed; the curves are then as
/// without `sign_scan`).
///
/// Below the grid's first size the scan starts at `small` / 4 (`small`: the single-punch estimate
/// of lambda at the load, [3.10] with the osculating curvature) and climbs by factors of 4 to it:
/// a load carried by a contact below cap/GRID is bracketed there (issue 34: a load of 1.7e-27, lambda
/// ~ 1e-11, had no sign change on the grid and was refused as carried by no contact).
pub(super) fn load_curves(
    params: &SlidingParamsMpfr,
    cap: f64,
    small: f64,
    rel: &dyn Fn(&ShiftSolution) -> f64,
    sign_scan: bool,
) -> Result<Curves, SlidingError> {
    let exact = |s: f64| scan_values(params, s, bucket(nodes_for(s, SCAN_DIGITS)), rel);
    let sizes = scan_sizes(cap, small);
    let grid = sizes.len();
    let mut curves: Curves = [vec![], vec![]];
    let mut sign_only = vec![];
    for &s in &sizes {
        let cheap = match sign_scan {
            true => scan_signs(params, s, bucket(nodes_for(s, SCAN_DIGITS)), rel)?,
            false => None,
        };
        sign_only.push(cheap.is_some());
        let values = match cheap {
            Some(v) => v,
            None => exact(s)?,
        };
        for (br, curve) in curves.iter_mut().enumerate() {
            curve.push((s, values[br]));
        }
    }
    let differs = |curves: &Curves, i: usize, j: usize| {
        curves.iter().any(|c| match (c[i].1, c[j].1) {
            (Some(x), Some(y)) => (x < 0.0) != (y < 0.0) || x == 0.0 || y == 0.0,
            _ => true,
        })
    };
    let used: Vec<usize> = (0..grid)
        .filter(|&i| {
            sign_only[i] && ((i > 0 && differs(&curves, i - 1, i)) || (i + 1 < grid && differs(&curves, i, i + 1)))
        })
        .collect();
    let sign = |v: Option<f64>| v.map(|v| v.partial_cmp(&0.0));
    let mut disagreed = false;
    for i in used {
        let values = exact(curves[0][i].0)?;
        disagreed |= curves.iter().zip(&values).any(|(curve, v)| sign(*v) != sign(curve[i].1));
        set(&mut curves, i, &values);
        sign_only[i] = false;
    }
    if disagreed {
        for i in (0..grid).filter(|&i| sign_only[i]) {
            let values = exact(curves[0][i].0)?;
            set(&mut curves, i, &values);
        }
    }
    Ok(curves)
}

/// The sizes of the scan: `small`/4 times 4^j below the grid (while below cap/GRID; none when
/// `small` is not a positive number below it), then cap i/GRID, i = 1..=GRID.
pub(crate) fn scan_sizes(cap: f64, small: f64) -> Vec<f64> {
    let first = cap / GRID as f64;
    let mut sizes = vec![];
    if small.is_finite() && small > 0.0 {
        let mut s = small / 4.0;
        while s < first {
            sizes.push(s);
            s *= 4.0;
        }
    }
    sizes.extend((1..=GRID).map(|i| cap * i as f64 / GRID as f64));
    sizes
}
