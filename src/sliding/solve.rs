//! Solution of Problem 1 at a given precision: find the contact, then the pressure and the loads.
//!
//! 1. A low-precision stage (64 bits, node counts for ~16 digits) locates every contact size:
//!    the parabola's load P2(lambda) (or P2(l)) is increasing, bracketed from the single-punch /
//!    Kuznetsov estimate; the sinusoid's P2(lambda) is scanned on both branches of the centre
//!    (see [`super::equation::shift_solutions`]) because with theta != 0 it is not monotone.
//!    Every bracket is refined by the Illinois method.
//! 2. Each size is refined by the secant method at the working precision with a fixed rule, until the
//!    step is below 2^-(prec-8) relative.
//! 3. The pressure [2.13], the loads, F_def and the physicality checks follow.

use super::contact::{Contact, Size};
use super::equation::{equation_terms, shift_solutions, ShiftSolution};
use super::error::SlidingError;
use super::physical::{check_gap, check_pressure};
use super::pressure::Pressure;
use super::setup::{Convention, Setup, Shape};
use super::solution::{PressurePoint, SlidingSolution};
use crate::model::{Exact, SlidingLoad, SlidingProblem};
use crate::numerics::exact::{to_f64, to_float};
use crate::numerics::gauss_jacobi_mpfr::{gauss_jacobi, GaussJacobiRule};
use rug::Float;
use std::sync::Arc;

/// Most nodes the solver will use for one rule.
pub const NODE_CAP: usize = 3000;

/// Precision of the locating stage.
const LOCATE_PREC: u32 = 64;
/// Digits the locating stage aims at.
const LOCATE_DIGITS: f64 = 16.0;
/// Digits of the sinusoid's load-curve scan (signs only).
const SCAN_DIGITS: f64 = 8.0;
/// Most nodes of the locating stage.
const LOCATE_NODES: usize = 512;

/// How many nodes a run uses: `factor` times the error-model count for `digits`.
#[derive(Debug, Clone, Copy)]
pub struct NodeRule {
    /// Target digits of the quadrature.
    pub digits: f64,
    /// Multiplier (1 for the main run, 1.5 for the verification run).
    pub factor: f64,
}

/// Error model (THEORY.md section 3): the quadrature error behaves like tan(lambda/2)^(2n), so
/// n = (digits + 4) ln 10 / (-2 ln tan(lambda/2)), at least 8 (a single punch, lambda = 0, needs few:
/// the integrands are polynomials for the parabola). Heuristic margin of 4 digits for the constant.
pub fn nodes_for(lambda: f64, digits: f64) -> usize {
    if lambda <= 0.0 {
        return 8;
    }
    let r = -(lambda / 2.0).tan().ln();
    if r <= 0.0 {
        return usize::MAX;
    }
    let n = ((digits + 4.0) * std::f64::consts::LN_10 / (2.0 * r)).ceil();
    if n > 1e9 {
        usize::MAX
    } else {
        (n as usize).max(8)
    }
}

/// Largest lambda for which `nodes_for(lambda, digits) <= nmax`.
fn lambda_cap(digits: f64, nmax: usize) -> f64 {
    2.0 * (-(digits + 4.0) * std::f64::consts::LN_10 / (2.0 * nmax as f64)).exp().atan()
}

fn bucket(n: usize) -> usize {
    for b in [8usize, 16, 24, 32, 48, 64, 96, 128, 192, 256, 384, 512] {
        if n <= b {
            return b;
        }
    }
    n.div_ceil(64) * 64
}

/// Rule for 1/omega with n nodes at the setup's precision.
fn inverse_rule(setup: &Setup, n: usize) -> Result<Arc<GaussJacobiRule>, SlidingError> {
    let (a, b) = setup.inverse_weight_exponents();
    Ok(gauss_jacobi(&a, &b, n, setup.prec)?)
}

/// Rule for omega with n nodes.
fn weight_rule(setup: &Setup, n: usize) -> Result<Arc<GaussJacobiRule>, SlidingError> {
    let (a, b) = setup.weight_exponents();
    Ok(gauss_jacobi(&a, &b, n, setup.prec)?)
}

/// lambda of a size parameter (0 for a single punch).
fn lambda_of(setup: &Setup, s: f64) -> f64 {
    if setup.period.is_some() {
        s
    } else {
        0.0
    }
}

/// Centre solutions (all branches) at size s with n nodes.
fn branches(setup: &Setup, s: &Float, n: usize) -> Result<Vec<ShiftSolution>, SlidingError> {
    let rule = inverse_rule(setup, n)?;
    let size = Size::new(setup, s);
    Ok(shift_solutions(setup, &size, &equation_terms(setup, &size, &rule)))
}

/// Low-precision load on a branch at size s (None: no centre on this branch).
fn load_lo(setup: &Setup, s: f64, branch: usize) -> Result<Option<f64>, SlidingError> {
    let n = bucket(nodes_for(lambda_of(setup, s), LOCATE_DIGITS));
    let sf = Float::with_val(setup.prec, s);
    Ok(branches(setup, &sf, n)?.get(branch).map(|b| b.p2.to_f64()))
}

/// Illinois (modified regula falsi) on [lo, hi] with f(lo) < 0 < f(hi) or the reverse.
fn illinois(
    mut f: impl FnMut(f64) -> Result<Option<f64>, SlidingError>,
    mut lo: f64,
    mut flo: f64,
    mut hi: f64,
    mut fhi: f64,
) -> Result<f64, SlidingError> {
    let mut side = 0;
    for _ in 0..200 {
        let mut x = (lo * fhi - hi * flo) / (fhi - flo);
        if !(x > lo.min(hi) && x < lo.max(hi)) {
            x = 0.5 * (lo + hi);
        }
        let fx = match f(x)? {
            Some(v) => v,
            None => return Err(SlidingError::NoConvergence(format!("the load curve has a gap at size {x}"))),
        };
        // f is a relative load residual evaluated to ~16 digits: 1e-15 is at its noise level.
        if fx.abs() <= 1e-15 || (hi - lo).abs() <= 4.0 * f64::EPSILON * x.abs() {
            return Ok(x);
        }
        if (fx > 0.0) == (fhi > 0.0) {
            hi = x;
            fhi = fx;
            if side == 1 {
                flo *= 0.5;
            }
            side = 1;
        } else {
            lo = x;
            flo = fx;
            if side == -1 {
                fhi *= 0.5;
            }
            side = -1;
        }
    }
    Ok(0.5 * (lo + hi))
}

/// Contact sizes (with their centre branch) carrying the load `p2` (low precision), sorted by size.
fn locate(problem: &SlidingProblem, p2: &Exact, convention: Convention) -> Result<Vec<(f64, usize)>, SlidingError> {
    let setup = Setup::with_convention(problem, LOCATE_PREC, convention)?;
    let target = to_f64(p2).ok_or_else(|| SlidingError::parameter("normal_load", p2, "must be a finite number"))?;
    let cap = lambda_cap(LOCATE_DIGITS, LOCATE_NODES);
    let f = |s: f64, br: usize| -> Result<Option<f64>, SlidingError> {
        Ok(load_lo(&setup, s, br)?.map(|v| (v - target) / target))
    };
    let e_star = setup.e_star.to_f64();
    let theta = setup.theta.to_f64();
    match (&setup.shape, &setup.period) {
        (Shape::Parabolic { k }, period) => {
            // Single-punch estimate l_s = a0/sqrt(1 - 4 theta^2), a0 = sqrt(2 P2/(pi E* k)) [3.10].
            let k = k.to_f64();
            let ls = (2.0 * target / (std::f64::consts::PI * e_star * k)).sqrt() / (1.0 - 4.0 * theta * theta).sqrt();
            let (s0, smax) = match period {
                None => (ls, f64::INFINITY),
                Some(l) => {
                    // Kuznetsov [2.15]: cos(lambda) = exp(-pi^2 l_s^2/(2 L^2)).
                    let l = l.to_f64();
                    let x = std::f64::consts::PI * ls / l;
                    let lam = (-(x * x) / 2.0).exp().acos();
                    (lam.clamp(1e-300, cap * 0.99), cap)
                }
            };
            let f0 = f(s0, 0)?.unwrap_or(f64::NAN);
            let (mut lo, mut flo, mut hi, mut fhi);
            let mut step = 1e-4 * s0;
            if f0.abs() <= 1e-15 {
                return Ok(vec![(s0, 0)]);
            }
            if f0 < 0.0 {
                lo = s0;
                flo = f0;
                hi = s0;
                fhi = f0;
                let mut tries = 0;
                while fhi < 0.0 {
                    lo = hi;
                    flo = fhi;
                    // Geometric steps from the estimate (good to O(lambda^2)), capped by smax.
                    step *= 8.0;
                    hi = if smax.is_finite() { (hi + step).min(hi + 0.5 * (smax - hi)) } else { hi + step };
                    fhi = f(hi, 0)?.unwrap_or(f64::NAN);
                    tries += 1;
                    if tries > 60 || (smax.is_finite() && smax - hi < 1e-12) {
                        return Err(SlidingError::NoSolution {
                            load: p2.to_string(),
                            why: format!(
                                "the contact would exceed lambda = pi l/L = {cap:.4} (about {} nodes for {} digits; the periodic parabola also needs the contact inside (-L/2, L/2)); the load is too large for this method",
                                LOCATE_NODES, LOCATE_DIGITS
                            ),
                        });
                    }
                }
            } else if f0 > 0.0 {
                hi = s0;
                fhi = f0;
                lo = s0;
                flo = f0;
                let mut tries = 0;
                while flo > 0.0 {
                    hi = lo;
                    fhi = flo;
                    step *= 8.0;
                    lo = (lo - step).max(lo * 0.5);
                    flo = f(lo, 0)?.unwrap_or(f64::NAN);
                    tries += 1;
                    if tries > 2000 {
                        return Err(SlidingError::NoConvergence("no lower bracket for the contact size".into()));
                    }
                }
            } else if f0.abs() <= 1e-15 {
                return Ok(vec![(s0, 0)]);
            } else {
                return Err(SlidingError::NoConvergence(format!("load not computable at size {s0}")));
            }
            if !(flo.is_finite() && fhi.is_finite()) {
                return Err(SlidingError::NoConvergence("load not finite while bracketing".into()));
            }
            let s = illinois(|x| f(x, 0), lo, flo, hi, fhi)?;
            Ok(vec![(s, 0)])
        }
        (Shape::Sinusoidal { .. }, _) => {
            // Both centre branches come from the same two integrals: evaluate them once per point.
            let grid = 48;
            let mut curves: [Vec<(f64, Option<f64>)>; 2] = [vec![], vec![]];
            for i in 1..=grid {
                let s = cap * i as f64 / grid as f64;
                // The scan only needs signs: SCAN_DIGITS; brackets are refined with LOCATE_DIGITS.
                let n = bucket(nodes_for(s, SCAN_DIGITS));
                let b = branches(&setup, &Float::with_val(setup.prec, s), n)?;
                for (br, curve) in curves.iter_mut().enumerate() {
                    curve.push((s, b.get(br).map(|v| (v.p2.to_f64() - target) / target)));
                }
            }
            let mut found = vec![];
            for (br, curve) in curves.iter().enumerate() {
                for w in curve.windows(2) {
                    if let ((sp, Some(fp)), (s, Some(fv))) = (w[0], w[1]) {
                        if fp == 0.0 {
                            found.push((sp, br));
                        } else if (fp < 0.0) != (fv < 0.0) && fv != 0.0 {
                            found.push((illinois(|x| f(x, br), sp, fp, s, fv)?, br));
                        }
                    }
                }
            }
            found.sort_by(|x, y| x.0.partial_cmp(&y.0).unwrap_or(std::cmp::Ordering::Equal));
            Ok(found)
        }
    }
}

/// The largest load on a physical solution of the sinusoid (low precision, for error messages):
/// (P2_max, lambda) over a 64-point scan of both branches, refined by golden-section search.
pub fn sinusoid_max_physical_load(
    problem: &SlidingProblem,
    convention: Convention,
) -> Result<Option<(f64, f64)>, SlidingError> {
    let setup = Setup::with_convention(problem, LOCATE_PREC, convention)?;
    let cap = lambda_cap(LOCATE_DIGITS, LOCATE_NODES);
    let grid = 64;
    let mut best: Option<(f64, f64, usize)> = None;
    for br in 0..2 {
        for i in 1..=grid {
            let s = cap * i as f64 / grid as f64;
            let n = bucket(nodes_for(s, LOCATE_DIGITS));
            let sf = Float::with_val(setup.prec, s);
            let Some(sol) = branches(&setup, &sf, n)?.get(br).cloned() else { continue };
            if sol.p2 <= 0u32 {
                continue;
            }
            let v = sol.p2.to_f64();
            if best.map_or(true, |b| v > b.0) && physical_at(&setup, &sf, &sol, n).is_ok() {
                best = Some((v, s, br));
            }
        }
    }
    let Some((mut v, s, br)) = best else { return Ok(None) };
    // Golden section on (s - h, s + h), keeping physical points only.
    let h = cap / grid as f64;
    let (mut a, mut b) = ((s - h).max(1e-6), (s + h).min(cap));
    let mut arg = s;
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let eval = |x: f64| -> f64 {
        let n = bucket(nodes_for(x, LOCATE_DIGITS));
        let xf = Float::with_val(setup.prec, x);
        match branches(&setup, &xf, n).ok().and_then(|v| v.get(br).cloned()) {
            Some(sol) if physical_at(&setup, &xf, &sol, n).is_ok() => sol.p2.to_f64(),
            _ => f64::NEG_INFINITY,
        }
    };
    for _ in 0..40 {
        let x1 = b - g * (b - a);
        let x2 = a + g * (b - a);
        let (f1, f2) = (eval(x1), eval(x2));
        if f1 > v {
            v = f1;
            arg = x1;
        }
        if f2 > v {
            v = f2;
            arg = x2;
        }
        if f1 >= f2 {
            b = x2;
        } else {
            a = x1;
        }
    }
    Ok(Some((v, arg)))
}

fn physical_at(setup: &Setup, s: &Float, sol: &ShiftSolution, n: usize) -> Result<(), SlidingError> {
    let rule = inverse_rule(setup, n)?;
    let size = Size::new(setup, s);
    let contact = Contact::new(setup, &size, sol.c.clone());
    let pr = Pressure::new(setup, &contact, &rule);
    check_pressure(setup, &pr)?;
    check_gap(setup, &contact, &pr)
}

/// Secant refinement of a size `s0` on branch `br` so that the load equals `p2`, at the setup's
/// precision with `n` nodes.
fn refine(setup: &Setup, s0: f64, br: usize, p2: &Float, n: usize) -> Result<Float, SlidingError> {
    let p = setup.prec;
    let f = |s: &Float| -> Result<Float, SlidingError> {
        let b = branches(setup, s, n)?;
        let v =
            b.get(br).ok_or_else(|| SlidingError::NoConvergence(format!("the centre branch vanished at size {s}")))?;
        Ok(Float::with_val(p, &v.p2 - p2))
    };
    let mut x0 = Float::with_val(p, s0);
    let mut x1 = Float::with_val(p, s0 * (1.0 + 1e-12));
    let mut f0 = f(&x0)?;
    let mut f1 = f(&x1)?;
    let tol = Float::with_val(53, Float::i_exp(1, -(p as i32) + 8));
    for _ in 0..40 {
        let df = Float::with_val(p, &f1 - &f0);
        if df.is_zero() {
            return Ok(x1);
        }
        let step = Float::with_val(p, &f1 * Float::with_val(p, &x1 - &x0)) / df;
        let x2 = Float::with_val(p, &x1 - &step);
        if !x2.is_finite() || x2 <= 0u32 {
            return Err(SlidingError::NoConvergence(format!("secant left the admissible sizes near {s0}")));
        }
        if Float::with_val(53, step.abs_ref()) <= Float::with_val(53, &tol * Float::with_val(53, x2.abs_ref())) {
            return Ok(x2);
        }
        x0 = x1;
        f0 = f1;
        f1 = f(&x2)?;
        x1 = x2;
    }
    Err(SlidingError::NoConvergence(format!("secant refinement of the contact size did not converge (start {s0})")))
}

/// Solves Problem 1 at `prec` bits; the node count per solution is `nodes.factor` times the
/// error-model count for `nodes.digits` at its lambda. `points` are xh = (x - c)/l in (-1, 1).
/// `check` runs the physicality checks (the verification run skips them).
/// Returns every physical solution, sorted by contact size (smallest first).
pub fn solve_at(
    problem: &SlidingProblem,
    points: &[Exact],
    nodes: NodeRule,
    check: bool,
    prec: u32,
) -> Result<Vec<SlidingSolution>, SlidingError> {
    Ok(solve_located(problem, points, nodes, check, prec, None, Convention::Paper)?.into_iter().map(|x| x.0).collect())
}

/// Low-precision estimate of a contact size (lambda, or l for a single punch) and its centre branch.
pub type Located = (f64, usize);

/// [`solve_at`] that can reuse the sizes located by an earlier run (`located`, for the inverse
/// problem), and returns with each solution the located size it came from.
pub fn solve_located(
    problem: &SlidingProblem,
    points: &[Exact],
    nodes: NodeRule,
    check: bool,
    prec: u32,
    located: Option<&[Located]>,
    convention: Convention,
) -> Result<Vec<(SlidingSolution, Located)>, SlidingError> {
    let one = Exact::from_integer(1.into());
    for x in points {
        if !(x > &-one.clone() && x < &one) {
            return Err(SlidingError::parameter("points", x, "each point xh = (x - c)/l must lie in (-1, 1)"));
        }
    }
    let setup = Setup::with_convention(problem, prec, convention)?;
    let n_for = |lam: f64| -> Result<usize, SlidingError> {
        let n0 = nodes_for(lam, nodes.digits);
        let n = (n0 as f64 * nodes.factor).ceil();
        if n0 == usize::MAX || n > NODE_CAP as f64 {
            return Err(SlidingError::parameter(
                "lambda = pi l/L",
                format!("{lam:.6}"),
                format!(
                    "too close to pi/2 (full contact): {} digits would need more than {NODE_CAP} nodes",
                    nodes.digits
                ),
            ));
        }
        Ok((n as usize).div_ceil(4) * 4)
    };
    // Candidate (size, centre) pairs at working precision.
    let mut cands: Vec<(Float, ShiftSolution, usize, Located)> = vec![];
    let sinusoid = matches!(setup.shape, Shape::Sinusoidal { .. });
    match problem.load() {
        SlidingLoad::HalfLength(l) => {
            let lf = to_float(l, prec);
            let s = match &setup.period {
                Some(big_l) => Float::with_val(prec, &lf * &setup.pi) / big_l,
                None => lf,
            };
            let n = n_for(lambda_of(&setup, s.to_f64()))?;
            for (br, b) in branches(&setup, &s, n)?.into_iter().enumerate() {
                if b.p2 > 0u32 {
                    cands.push((s.clone(), b, n, (s.to_f64(), br)));
                }
            }
            if cands.is_empty() {
                return Err(SlidingError::NotPhysical {
                    why: "no centre of the contact gives a positive load at this half-length".into(),
                });
            }
        }
        SlidingLoad::NormalLoad(p2) => {
            let p2f = to_float(p2, prec);
            let found = match located {
                Some(v) => v.to_vec(),
                None => locate(problem, p2, convention)?,
            };
            for (s0, br) in found {
                // Sinusoid: screen the roots for physicality at the locating precision first, so
                // that non-physical roots (e.g. on the falling part of P2(lambda)) are not refined
                // at full precision. A root within the checks' tolerance of the physical boundary
                // could be misjudged here; such roots sit at the end of the physical range.
                if sinusoid && check && located.is_none() {
                    let lo = Setup::with_convention(problem, LOCATE_PREC, convention)?;
                    let n_lo = bucket(nodes_for(lambda_of(&lo, s0), LOCATE_DIGITS));
                    let s_lo = Float::with_val(LOCATE_PREC, s0);
                    if let Some(sol) = branches(&lo, &s_lo, n_lo)?.get(br) {
                        if physical_at(&lo, &s_lo, sol, n_lo).is_err() {
                            continue;
                        }
                    }
                }
                let n = n_for(lambda_of(&setup, s0))?;
                let s = refine(&setup, s0, br, &p2f, n)?;
                let b = branches(&setup, &s, n)?;
                let mut sol =
                    b.get(br).cloned().ok_or_else(|| SlidingError::NoConvergence("centre branch lost".into()))?;
                sol.p2 = p2f.clone();
                cands.push((s, sol, n, (s0, br)));
            }
            if cands.is_empty() {
                let why = match sinusoid_max_physical_load(problem, convention)? {
                    Some((v, lam)) => format!("the sinusoid carries at most P2 = {v:.6e} (at lambda = {lam:.4}) at these friction and wear values"),
                    None => "no physical contact exists at these friction and wear values".into(),
                };
                return Err(SlidingError::NoSolution { load: p2.to_string(), why });
            }
        }
    }
    let mut out = vec![];
    let mut first_err = None;
    for (s, sh, n, loc) in cands {
        match build(&setup, &s, sh, n, points, check) {
            Ok(sol) => out.push((sol, loc)),
            Err(e @ SlidingError::NotPhysical { .. }) if sinusoid => {
                first_err.get_or_insert(e);
            }
            Err(e) => return Err(e),
        }
    }
    if out.is_empty() {
        if let (SlidingLoad::NormalLoad(p2), true) = (problem.load(), sinusoid) {
            let why = match sinusoid_max_physical_load(problem, convention)? {
                Some((v, lam)) => format!(
                    "the solutions of the equations are not physical ({}); the sinusoid carries at most P2 = {v:.6e} (at lambda = {lam:.4}) at these friction and wear values",
                    first_err.map(|e| e.to_string()).unwrap_or_default()
                ),
                None => "no physical contact exists at these friction and wear values".into(),
            };
            return Err(SlidingError::NoSolution { load: p2.to_string(), why });
        }
        return Err(first_err.unwrap_or(SlidingError::NoConvergence("no solution".into())));
    }
    out.sort_by(|x, y| x.0.l.partial_cmp(&y.0.l).unwrap_or(std::cmp::Ordering::Equal));
    Ok(out)
}

/// Everything about one contact: validity, physicality, pressure, loads.
fn build(
    setup: &Setup,
    s: &Float,
    sh: ShiftSolution,
    n: usize,
    points: &[Exact],
    check: bool,
) -> Result<SlidingSolution, SlidingError> {
    let p = setup.prec;
    let size = Size::new(setup, s);
    let contact = Contact::new(setup, &size, sh.c.clone());
    let l = size.l.clone();
    let a = Float::with_val(p, &l - &sh.c);
    let b = Float::with_val(p, &l + &sh.c);
    if let (Shape::Parabolic { .. }, Some(big_l)) = (&setup.shape, &setup.period) {
        let half = Float::with_val(p, big_l / 2u32);
        if a >= half || b >= half {
            return Err(SlidingError::ContactOutsidePeriod {
                left: format!("{:.12}", (-a)),
                right: format!("{:.12}", b),
                half_period: format!("{:.12}", half),
            });
        }
    }
    let rule = inverse_rule(setup, n)?;
    let pressure = Pressure::new(setup, &contact, &rule);
    let max_pressure = if check {
        let m = check_pressure(setup, &pressure)?;
        check_gap(setup, &contact, &pressure)?;
        m
    } else {
        Float::with_val(p, 0)
    };
    let rule_w = weight_rule(setup, n)?;
    let (_, f_def) = pressure.load_and_deformation_force(&rule_w);
    let mut pts = vec![];
    for xh in points {
        let xh = to_float(xh, p);
        let u = match &size.m {
            Some(m) => Float::with_val(p, size.lambda.as_ref().expect("periodic") * &xh).tan() / m,
            None => xh.clone(),
        };
        let x = Float::with_val(p, &l * &xh) + &sh.c;
        pts.push(PressurePoint { p: pressure.p(&u), xh, x });
    }
    let p2 = sh.p2;
    let p1 = Float::with_val(p, &setup.mu * &p2) + Float::with_val(p, &l * &setup.tau0) * 2u32;
    let worn = Float::with_val(p, &setup.wear * &p2);
    let wear_per_distance = setup.period.as_ref().map(|big_l| Float::with_val(p, &worn / big_l));
    let wear_rate = match (&wear_per_distance, &setup.speed) {
        (Some(w), Some(v)) => Some(Float::with_val(p, w * v)),
        _ => None,
    };
    // Never return a non-finite number.
    let finite = [&l, &a, &b, &sh.c, &p1, &p2, &f_def, &max_pressure].iter().all(|v| v.is_finite())
        && pts.iter().all(|q| q.p.is_finite() && q.x.is_finite());
    if !finite {
        return Err(SlidingError::NoConvergence(format!(
            "a non-finite value arose for the contact of half-length {:.12}",
            l
        )));
    }
    Ok(SlidingSolution {
        theta: setup.theta.clone(),
        kappa: setup.kappa.clone(),
        lambda: size.lambda.clone(),
        l,
        a,
        b,
        c: sh.c,
        p1,
        p2,
        f_def,
        wear_per_distance,
        wear_rate,
        worn_area_per_distance: worn,
        pressure: pts,
        max_pressure,
        nodes: n,
        prec: p,
    })
}

#[cfg(test)]
pub(crate) fn locate_for_profile(problem: &SlidingProblem, p2: &Exact) -> Vec<Located> {
    locate(problem, p2, Convention::Paper).unwrap()
}
