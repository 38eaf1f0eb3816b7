//! The sinusoid g = D (1 - cos(2 pi x/L)) [2.16]: the two unit bases at fixed lambda, (X, Y) =
//! (cos, sin)(2 pi c/L) from the side conditions, the scalar equation ln|(X, Y)| = 0 in lambda and
//! the scan for all its roots (P2(lambda) is not monotone for theta != 0).

use super::closure::{closed, tau0_side};
use super::error::{root_error, Result, SlidingF64Error};
use super::interpolant::{basis, Basis, Rhs, State};
use super::operator::{collocation, collocation_nodes, Collocation};
use super::solution::SolverOptions;
use super::tangent_map::{Map, LAMBDA_MAX};
use crate::numerics::accuracy::readable_f64;
use crate::numerics::roots::{brent, Bracket};
use crate::params::sliding::SlidingParamsF64;
use std::f64::consts::PI;

/// Largest lambda of the scan (contact fraction 2 lambda/pi = 0.92).
pub(super) const SCAN_MAX: f64 = crate::sliding::physicality::admissible::LAMBDA_SCAN_MAX;

/// Sinusoid at fixed lambda: F = s (X sin 2phi + Y cos 2phi), s = pi E* D/L, phi = atan(m u),
/// (X, Y) = (cos, sin)(2 pi c/L). Returns the two unit bases (sin 2phi, cos 2phi), with the load
/// part of K in their solvability functionals in the `periodic` convention (`closure.rs`).
pub(super) fn sinusoid_bases(col: &Collocation, prm: &SlidingParamsF64, map: &Map) -> Result<(Basis, Basis)> {
    let m = match *map {
        Map::Periodic { m, .. } => m,
        Map::Single { .. } => unreachable!("sinusoid needs a period"),
    };
    let bx = closed(prm, map, basis(col, map, |u| 2.0 * m * u / (1.0 + m * m * u * u))?);
    // cos 2phi = 1 - 2 m^2 u^2/(1 + m^2 u^2): the constant 1 is solved exactly by G = 0, K = 1
    // (cond = C0 - K = -1), so only the variable part is collocated. Collocated whole, the
    // rounding of 1 - m^2 u^2 (eps against a variation of m^2) put an error of about
    // eps |Y|/(X lambda) into P2 and F_def, and below m^2 = eps the variation vanished (issue 34,
    // fuzz seed 2026 cases 4397 and 9042: lambda = 2.7e-4 and 5.6e-9, 620 and 1460 eps in P2).
    let mut by = basis(col, map, |u| -2.0 * m * m * u * u / (1.0 + m * m * u * u))?;
    by.cond -= 1.0;
    let by = closed(prm, map, by);
    Ok((bx, by))
}

/// The state for (X, Y) on the unit circle: c = L atan2(Y, X)/(2 pi), G = s (X G_x + Y G_y).
pub(super) fn sinusoid_state(map: Map, big_l: f64, s: f64, bx: &Basis, by: &Basis, x: f64, y: f64) -> State {
    let c = big_l * y.atan2(x) / (2.0 * PI);
    let g = bx.g.iter().zip(&by.g).map(|(gx, gy)| s * (x * gx + y * gy)).collect();
    State { map, c, g, p2: s * (x * bx.p2 + y * by.p2), rhs: Rhs::Sinusoid { s, x, y } }
}

/// Intersections of a1 X + b1 Y = r with X^2 + Y^2 = 1, ordered (branch 0, branch 1) along the
/// direction (-b1, a1).
pub(super) fn line_circle(a1: f64, b1: f64, r: f64) -> Vec<(f64, f64)> {
    let nrm = a1.hypot(b1);
    if nrm == 0.0 {
        return vec![];
    }
    let (na, nb) = (a1 / nrm, b1 / nrm);
    let dist = r / nrm;
    if dist.abs() > 1.0 {
        return vec![];
    }
    let h = (1.0 - dist * dist).sqrt();
    let (fx, fy) = (dist * na, dist * nb);
    vec![(fx + nb * h, fy - na * h), (fx - nb * h, fy + na * h)]
}

/// (X, Y) from [[a1, b1], [a2, b2]] (X, Y) = (r1, r2): the two side conditions (solvability and
/// load) of the sinusoid, with r1 = beta tau0/s (`closure::tau0_side`), r2 = P2/s.
fn sinusoid_xy(bx: &Basis, by: &Basis, r1: f64, r2: f64) -> Option<(f64, f64)> {
    let det = bx.cond * by.p2 - bx.p2 * by.cond;
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    Some(((r1 * by.p2 - by.cond * r2) / det, (bx.cond * r2 - bx.p2 * r1) / det))
}

/// [`sinusoid_xy`] at the load `p2`, or non-convergence when the 2x2 system is singular.
pub(super) fn sinusoid_xy_at(
    bx: &Basis,
    by: &Basis,
    prm: &SlidingParamsF64,
    map: &Map,
    s: f64,
    p2: f64,
) -> Result<(f64, f64)> {
    sinusoid_xy(bx, by, tau0_side(prm, map) / s, p2 / s)
        .ok_or_else(|| SlidingF64Error::NoConvergence { reason: "singular 2x2 system for (cos, sin)(2 pi c/L)".into() })
}

/// ln|(X, Y)| for the sinusoid at load P2 (zero at a solution: X^2 + Y^2 = 1).
fn sinusoid_h(col: &Collocation, prm: &SlidingParamsF64, big_l: f64, s: f64, p2: f64, lam: f64) -> Result<f64> {
    let map = Map::periodic(big_l, lam);
    let (bx, by) = sinusoid_bases(col, prm, &map)?;
    let (x, y) = sinusoid_xy_at(&bx, &by, prm, &map, s, p2)?;
    Ok(x.hypot(y).ln())
}

/// Brent on a sign-changing bracket of [`sinusoid_h`].
fn root_in(f: impl FnMut(f64) -> Result<f64>, lo: f64, hi: f64, flo: f64, fhi: f64, xtol: f64) -> Result<f64> {
    brent(f, Bracket { a: lo, b: hi, fa: flo, fb: fhi }, xtol).map_err(root_error)
}

/// Refines a root of ln|(X, Y)| near `lam0` at the nodes of `col`.
pub(super) fn refine_sinusoid_lambda(
    col: &Collocation,
    prm: &SlidingParamsF64,
    big_l: f64,
    s: f64,
    p2: f64,
    lam0: f64,
) -> Result<f64> {
    let f = |lam: f64| sinusoid_h(col, prm, big_l, s, p2, lam);
    let f0 = f(lam0)?;
    if f0 == 0.0 {
        return Ok(lam0);
    }
    let mut step = 1e-6 * lam0.max(1e-3);
    for _ in 0..40 {
        let lo = (lam0 - step).max(lam0 * 0.5);
        let hi = (lam0 + step).min(LAMBDA_MAX);
        let (flo, fhi) = (f(lo)?, f(hi)?);
        if flo * f0 <= 0.0 {
            return root_in(f, lo, lam0, flo, f0, 1e-16 * lam0);
        }
        if fhi * f0 <= 0.0 {
            return root_in(f, lam0, hi, f0, fhi, 1e-16 * lam0);
        }
        step *= 4.0;
    }
    Err(SlidingF64Error::NoConvergence {
        reason: format!("lost the sinusoid root near lambda = {} when adding nodes", readable_f64(lam0)),
    })
}

/// A root of the sinusoid's scalar equation at load P2: lambda and the nodes it was solved at.
pub(super) type Root = (f64, usize);

/// Scans lambda in (0, [`SCAN_MAX`]] for sign changes of ln|(X, Y)| (Soldatenkov's P2(lambda) is not
/// monotone for theta != 0, so there may be several), refines each with Brent at the nodes for
/// that lambda. When there is none, returns [`SlidingF64Error::NoRoot`] with the
/// largest load seen on the scan (physical or not; the solver replaces it by the admissible range).
pub(super) fn sinusoid_scan(
    prm: &SlidingParamsF64,
    big_l: f64,
    s: f64,
    p2: f64,
    options: &SolverOptions,
) -> Result<Vec<Root>> {
    const STEPS: usize = 64;
    // Signs only: 48 nodes, or more near full contact for an error ~ 1e-8 (in steps of 16, so
    // few operators are factored).
    let scan_options = SolverOptions { target: 1e-8, ..*options };
    let n_scan =
        |lam: f64| options.nodes.unwrap_or_else(|| collocation_nodes(lam, &scan_options).max(48).div_ceil(16) * 16);
    let mut out = Vec::new();
    let mut max_load: f64 = 0.0;
    let mut prev: Option<(f64, f64)> = None;
    // Denser near 0 (small loads): lambda_j = SCAN_MAX (j/STEPS)^1.5; below the first, from a
    // quarter of the single-punch estimate of lambda ([3.10], osculating k) by factors of 4
    // (issue 34: a load carried by a contact with lambda ~ 1e-11 had no sign change on the grid
    // and was refused as carried by none).
    let first = SCAN_MAX * (1.0 / STEPS as f64).powf(1.5);
    let small = std::f64::consts::PI * prm.l_s(p2) / big_l;
    let below = std::iter::successors((small.is_finite() && small > 0.0).then_some(small / 4.0), |x| Some(x * 4.0))
        .take_while(|&x| x < first);
    let grid = (1..=STEPS).map(|j| SCAN_MAX * (j as f64 / STEPS as f64).powf(1.5));
    for lam in below.chain(grid) {
        let col = collocation(prm.theta, n_scan(lam))?;
        let map = Map::periodic(big_l, lam);
        let (bx, by) = sinusoid_bases(&col, prm, &map)?;
        let r1 = tau0_side(prm, &map) / s;
        for (x, y) in line_circle(bx.cond, by.cond, r1) {
            max_load = max_load.max(s * (x * bx.p2 + y * by.p2));
        }
        let h = match sinusoid_xy(&bx, &by, r1, p2 / s) {
            Some((x, y)) => x.hypot(y).ln(),
            None => continue,
        };
        if let Some((lp, hp)) = prev
            && hp * h <= 0.0
        {
            let n = options.nodes.unwrap_or_else(|| collocation_nodes(lam, options));
            let colr = collocation(prm.theta, n)?;
            let f = |x: f64| sinusoid_h(&colr, prm, big_l, s, p2, x);
            let (flo, fhi) = (f(lp)?, f(lam)?);
            let root = if flo * fhi <= 0.0 {
                root_in(f, lp, lam, flo, fhi, 1e-16 * lam)?
            } else {
                refine_sinusoid_lambda(&colr, prm, big_l, s, p2, 0.5 * (lp + lam))?
            };
            out.push((root, n));
        }
        prev = Some((lam, h));
    }
    if out.is_empty() {
        return Err(SlidingF64Error::NoRoot { load: p2, largest: max_load });
    }
    // One root found from two neighbouring intervals (h = 0 at a scan point, or the refinement
    // from the midpoint of each reaching the same root) is one solution (issue 34, fuzz seed 2026
    // case 1249: the same contact printed twice at lambda = 4.1e-8); distinct roots of P2(lambda)
    // lie apart by far more than the refinement's tolerance.
    out.sort_by(|x, y| x.0.total_cmp(&y.0));
    out.dedup_by(|x, y| (x.0 - y.0).abs() <= SAME_ROOT * x.0.abs().max(y.0.abs()));
    Ok(out)
}

/// Roots of the scan closer than this, relative, are one root ([`sinusoid_scan`]).
const SAME_ROOT: f64 = 1e-8;
