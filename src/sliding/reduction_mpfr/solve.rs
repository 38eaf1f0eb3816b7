//! Solution of Problem 1 at a given precision: find the contact, then the pressure and the loads.
//!
//! 1. A low-precision stage (64 bits, node counts for ~16 digits) locates every contact size:
//!    the parabola's load P2(lambda) (or P2(l)) is increasing, bracketed from the single-punch /
//!    Kuznetsov estimate; the sinusoid's P2(lambda) is scanned on both branches of the centre
//!    (see [`super::equation::shift_solutions`]) because with theta != 0 it is not monotone.
//!    Every bracket is refined by Brent's method ([`crate::numerics::roots::brent`]).
//! 2. Each size is refined by the secant method at the working precision with a fixed rule, until the
//!    step is below 2^-(prec-8) relative.
//! 3. The pressure [2.13], the loads, F_def and the physicality checks follow.
//!
//! Everything here works in units of E* ([`SlidingParamsMpfr`]); [`solve_at`] and
//! [`super::verify::solve_verified`] return the solutions in the problem's units.

pub use super::bracket::Located;
use super::bracket::{root_in, LOCATE_DIGITS, LOCATE_NODES, RESIDUAL_NOISE};
use super::branches::{branches, inverse_rule};
use super::contact::{Contact, Size};
use super::equation::ShiftSolution;
use super::error::SlidingError;
use super::locate_profile::{locate_profile, profile_nodes};
pub use super::nodes::nodes_for;
use super::nodes::{bucket, lambda_cap};
use super::physical::{max_pressure, physicality, physicality_with};
use super::pressure::Pressure;
use super::scan::load_curves;
use super::setup::{Setup, LOCATE_PREC};
use super::solution::{PressurePoint, SlidingSolution};
use crate::model::{Exact, SlidingProblem};
use crate::numerics::accuracy::{readable_f64, readable_mpfr};
use crate::numerics::exact::to_float;
use crate::numerics::gauss_jacobi_mpfr::{gauss_jacobi, GaussJacobiRule};
use crate::params::sliding::{check_profile_on_contact, ShapeMpfr, SlidingParamsMpfr, TargetMpfr};
use crate::sliding::physicality::admissible::{admissible, Admissible, SizeContacts, LAMBDA_SCAN_MAX};
use crate::sliding::physicality::CLOSURE_TOL;
use crate::sliding::physicality::{refusal_in_reach, Assessment, Refusal};
use rug::Float;
use std::sync::Arc;

/// Most nodes the solver will use for one rule.
pub const NODE_CAP: usize = 3000;

/// How many nodes a run uses: `factor` times the error-model count for `digits`.
#[derive(Debug, Clone, Copy)]
pub struct NodeRule {
    /// Target digits of the quadrature.
    pub digits: f64,
    /// Multiplier (1 for the main run, 1.5 for the verification run).
    pub factor: f64,
}

/// Rule for omega with n nodes.
fn weight_rule(params: &SlidingParamsMpfr, n: usize) -> Result<Arc<GaussJacobiRule>, SlidingError> {
    let (a, b) = params.weight_exponents();
    Ok(gauss_jacobi(&a, &b, n, params.prec)?)
}

/// lambda of a size parameter (0 for a single punch).
fn lambda_of(params: &SlidingParamsMpfr, s: f64) -> f64 {
    if params.period.is_some() {
        s
    } else {
        0.0
    }
}

/// Low-precision load on a branch at size s (None: no centre on this branch).
fn load_lo(params: &SlidingParamsMpfr, s: f64, branch: usize) -> Result<Option<f64>, SlidingError> {
    // Capped: near the circle's radius the profile's rule would grow without bound (the solve
    // stage refuses such sizes with a message; here they only need a sign).
    let n = bucket(nodes_for(lambda_of(params, s), LOCATE_DIGITS).max(profile_nodes(params, s, LOCATE_DIGITS)))
        .min(NODE_CAP);
    let sf = Float::with_val(params.prec, s);
    Ok(branches(params, &sf, n)?.get(branch).map(|b| b.p2.to_f64()))
}

/// Contact sizes (with their centre branch) carrying the given load P2/E* (low precision, at the
/// locating stage's parameters), sorted by size.
fn locate(setup: &Setup) -> Result<Vec<Located>, SlidingError> {
    locate_with(setup, true)
}

/// [`locate`], the sinusoid's scan taking signs from rules of fewer nodes
/// ([`super::scan::scan_signs`]) when
/// `sign_scan` (the same sizes, bit for bit: test `sign_scan_locates_the_same_sizes`).
pub(super) fn locate_with(setup: &Setup, sign_scan: bool) -> Result<Vec<Located>, SlidingError> {
    let params = &setup.locate;
    let target = setup.target.expect("Setup::new keeps the f64 load of a given load");
    let cap = lambda_cap(LOCATE_DIGITS, LOCATE_NODES);
    let f = |s: f64, br: usize| -> Result<Option<f64>, SlidingError> {
        Ok(load_lo(params, s, br)?.map(|v| (v - target) / target))
    };
    match (&params.shape, &params.period, &params.target) {
        (ShapeMpfr::Parabolic { .. }, period, TargetMpfr::NormalLoad(p2)) => {
            // Single-punch estimate l_s = a0/sqrt(1 - 4 theta^2) [3.10] (osculating k).
            let ls = params.l_s(p2).to_f64();
            let (s0, smax) = match period {
                None => (ls, f64::INFINITY),
                Some(l) => {
                    // Kuznetsov [2.15]: cos(lambda) = exp(-pi^2 l_s^2/(2 L^2)), without the
                    // cancellation of acos(exp(.)) (issue 34: P2 = 1e-20 at E* = k = L = 1 gave
                    // acos(1) = 0, the bracket started at 1e-300 and never reached lambda ~ 1e-10).
                    let l = l.to_f64();
                    let x = std::f64::consts::PI * ls / l;
                    let lam = crate::numerics::elementary::acos_exp_neg(x * x / 2.0);
                    (lam.clamp(1e-300, cap * 0.99), cap)
                }
            };
            let f0 = f(s0, 0)?.unwrap_or(f64::NAN);
            if f0.abs() <= RESIDUAL_NOISE {
                return Ok(vec![(s0, 0)]);
            }
            let (mut lo, mut flo, mut hi, mut fhi) = (s0, f0, s0, f0);
            let mut step = 1e-4 * s0;
            if f0 < 0.0 {
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
                        // Beyond this stage's reach (about LOCATE_NODES nodes for LOCATE_DIGITS
                        // digits): the admissible scan tells whether the load is out of the
                        // physical range (the contact leaves the cell) or only out of reach.
                        return Err(refused(setup, &[])?);
                    }
                }
            } else if f0 > 0.0 {
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
            } else {
                return Err(SlidingError::NoConvergence(format!("load not computable at size {}", readable_f64(s0))));
            }
            if !(flo.is_finite() && fhi.is_finite()) {
                return Err(SlidingError::NoConvergence("load not finite while bracketing".into()));
            }
            Ok(vec![(root_in(|x| f(x, 0), (lo, flo), (hi, fhi))?, 0)])
        }
        (ShapeMpfr::Sinusoidal { .. }, period, TargetMpfr::NormalLoad(p2)) => {
            // Both centre branches come from the same two integrals: one scan gives both curves.
            let rel = |v: &ShiftSolution| (v.p2.to_f64() - target) / target;
            // The single-punch estimate of lambda (osculating k), where the scan starts below its
            // grid.
            let small =
                period.as_ref().map_or(f64::NAN, |l| std::f64::consts::PI * params.l_s(p2).to_f64() / l.to_f64());
            let curves = load_curves(params, cap, small, &rel, sign_scan)?;
            let mut found = vec![];
            for (br, curve) in curves.iter().enumerate() {
                for w in curve.windows(2) {
                    if let ((sp, Some(fp)), (s, Some(fv))) = (w[0], w[1]) {
                        if fp == 0.0 {
                            found.push((sp, br));
                        } else if (fp < 0.0) != (fv < 0.0) && fv != 0.0 {
                            found.push((root_in(|x| f(x, br), (sp, fp), (s, fv))?, br));
                        }
                    }
                }
            }
            found.sort_by(|x, y| x.0.partial_cmp(&y.0).unwrap_or(std::cmp::Ordering::Equal));
            Ok(found)
        }
        (ShapeMpfr::Polynomial { .. } | ShapeMpfr::Circular { .. }, _, TargetMpfr::NormalLoad(p2)) => {
            locate_profile(setup, params, p2, cap, f)
        }
        (_, _, TargetMpfr::HalfLength(_)) => unreachable!("locate is called for a given load only"),
    }
}

/// The size parameter's scan range for [`admissible_range`]: lambda up to [`LAMBDA_SCAN_MAX`] for
/// a period; for a single punch l up to 4 times the requested size (or the single-punch
/// half-length at the load).
pub(super) fn scan_max(params: &SlidingParamsMpfr) -> f64 {
    match (&params.period, &params.target) {
        (Some(_), _) => LAMBDA_SCAN_MAX,
        (None, TargetMpfr::HalfLength(l)) => 4.0 * l.to_f64(),
        (None, TargetMpfr::NormalLoad(p2)) => 4.0 * params.l_s(p2).to_f64(),
    }
}

/// The admissible sizes and loads (P2/E*) by the direct problem at `params`' precision (the
/// locating stage's), judged by the shared criterion; once per process for each (parameters
/// without their target, scan range), since the scan solves the direct problem only (issue 14:
/// the report's stability maps refuse several loads of one problem, each quoting the same range,
/// and the scan takes about 0.5 s).
pub(super) fn admissible_range(params: &SlidingParamsMpfr) -> Result<Admissible, SlidingError> {
    let s_max = scan_max(params);
    admissible_memo().get_or(admissible_key(params, s_max), || admissible_scan(params, s_max))
}

/// The key of [`admissible_range`]: every parameter the scan reads, exactly (each MPFR value as
/// its integer mantissa and exponent, the precision, the shape's kind, the convention), without
/// the target (the scan never reads it; [`scan_max`] does, for a single punch, and is keyed apart
/// by `s_max`).
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub(super) struct AdmissibleKey {
    prec: u32,
    shape: &'static str,
    convention: crate::model::Convention,
    values: Vec<Option<(rug::Integer, i32)>>,
    s_max: u64,
}

pub(super) fn admissible_key(params: &SlidingParamsMpfr, s_max: f64) -> AdmissibleKey {
    let p = params;
    let mut floats: Vec<&Float> =
        vec![&p.pi, &p.unit, &p.beta, &p.mu, &p.tau0, &p.wear, &p.kappa, &p.theta, &p.cos_pi_theta, &p.k];
    floats.extend(p.speed.iter().chain(&p.period));
    let shape = match &p.shape {
        ShapeMpfr::Parabolic { k } => {
            floats.push(k);
            "parabolic"
        }
        ShapeMpfr::Sinusoidal { d } => {
            floats.push(d);
            "sinusoidal"
        }
        ShapeMpfr::Circular { r } => {
            floats.push(r);
            "circular"
        }
        ShapeMpfr::Polynomial { slope, curvature } => {
            floats.extend(slope.iter().chain(curvature));
            "polynomial"
        }
    };
    // The counts keep (speed, period) and (slope, curvature) apart.
    let counts = [p.speed.is_some() as usize, p.period.is_some() as usize, floats.len()];
    let mut values: Vec<_> = floats.into_iter().map(Float::to_integer_exp).collect();
    values.extend(counts.map(|n| Some((rug::Integer::from(n), 0))));
    AdmissibleKey { prec: p.prec, shape, convention: p.convention, values, s_max: s_max.to_bits() }
}

/// Most entries the memo of [`admissible_range`] keeps (it is emptied when full: a long sweep over
/// friction or wear makes a new entry per value).
const ADMISSIBLE_MEMO_CAP: usize = 4096;

/// A memo of one value per key, computed once (a second thread asking the same key waits for the
/// first one's value).
struct Memo<V>(std::sync::Mutex<std::collections::HashMap<AdmissibleKey, Arc<std::sync::OnceLock<V>>>>);

impl<V: Clone> Memo<V> {
    fn get_or(&self, key: AdmissibleKey, f: impl FnOnce() -> V) -> V {
        let slot = {
            let mut map = self.0.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
            if map.len() >= ADMISSIBLE_MEMO_CAP && !map.contains_key(&key) {
                map.clear();
            }
            map.entry(key).or_default().clone()
        };
        slot.get_or_init(f).clone()
    }
}

fn admissible_memo() -> &'static Memo<Result<Admissible, SlidingError>> {
    static MEMO: std::sync::OnceLock<Memo<Result<Admissible, SlidingError>>> = std::sync::OnceLock::new();
    MEMO.get_or_init(|| Memo(Default::default()))
}

/// The scan of [`admissible_range`] up to `s_max`, computed afresh.
pub(super) fn admissible_scan(params: &SlidingParamsMpfr, s_max: f64) -> Result<Admissible, SlidingError> {
    admissible(s_max, |s| -> Result<SizeContacts, SlidingError> {
        let n = bucket(nodes_for(lambda_of(params, s), LOCATE_DIGITS));
        let sf = Float::with_val(params.prec, s);
        let mut out = vec![];
        for sol in branches(params, &sf, n)? {
            if sol.p2 > 0u32 {
                out.push((sol.p2.to_f64(), matches!(physical_at(params, &sf, &sol, n)?, Ok(_))));
            }
        }
        Ok(out)
    })
}

/// The refusal when no contact is returned: `reasons` for each refused contact (empty: none
/// carries the load), with the admissible range in the problem's units (`setup.locate` at the
/// locating precision).
fn refused(setup: &Setup, reasons: &[String]) -> Result<SlidingError, SlidingError> {
    let lo = &setup.locate;
    let adm = admissible_range(lo)?;
    let unit = lo.unit.to_f64();
    let ranges = match (&lo.target, &lo.period) {
        (TargetMpfr::NormalLoad(_), Some(_)) => {
            adm.loads_text(unit, |s| 2.0 * s / std::f64::consts::PI, "contact fraction 2l/L")
        }
        (TargetMpfr::NormalLoad(_), None) => adm.loads_text(unit, |s| s, "half_length"),
        (TargetMpfr::HalfLength(_), Some(big_l)) => {
            let big_l = big_l.to_f64();
            adm.sizes_text(|s| s * big_l / std::f64::consts::PI)
        }
        (TargetMpfr::HalfLength(_), None) => adm.sizes_text(|s| s),
    };
    Ok(SlidingError::Core(refusal_in_reach(&setup.problem, &adm, unit, reasons, &ranges)))
}

/// The shared criterion for the contact of branch solution `sol` at size `s` (the loads P1 =
/// mu P2 + 2 l tau0 from it), a solution of the equations (closure to [`CLOSURE_TOL`]).
fn physical_at(
    params: &SlidingParamsMpfr,
    s: &Float,
    sol: &ShiftSolution,
    n: usize,
) -> Result<Result<Assessment, Refusal>, SlidingError> {
    physical_at_tol(params, s, sol, n, CLOSURE_TOL)
}

/// [`physical_at`] with the closure check's relative tolerance `closure_tol`.
fn physical_at_tol(
    params: &SlidingParamsMpfr,
    s: &Float,
    sol: &ShiftSolution,
    n: usize,
    closure_tol: f64,
) -> Result<Result<Assessment, Refusal>, SlidingError> {
    let rule = inverse_rule(params, n)?;
    let size = Size::new(params, s);
    let contact = Contact::new(params, &size, sol.c.clone());
    let pr = Pressure::new(params, &contact, &rule);
    let p1 = p1_of(params, &size.l, &sol.p2);
    Ok(physicality_with(params, &contact, &pr, &p1, &sol.p2, closure_tol))
}

/// P1 = mu P2 + 2 l tau0.
fn p1_of(params: &SlidingParamsMpfr, l: &Float, p2: &Float) -> Float {
    let p = params.prec;
    Float::with_val(p, &params.mu * p2) + Float::with_val(p, l * &params.tau0) * 2u32
}

/// A refusal of the criterion as a reason (physics) or an error (numerics).
fn reason_or_error(lambda: f64, r: Refusal) -> Result<String, SlidingError> {
    if r.is_physical() {
        Ok(format!("lambda = {}: {}", readable_f64(lambda), r.why()))
    } else {
        Err(SlidingError::NoConvergence(r.why()))
    }
}

/// Secant refinement of a size `s0` on branch `br` so that the load equals `p2`, at the
/// parameters' precision with `n` nodes.
fn refine(params: &SlidingParamsMpfr, s0: f64, br: usize, p2: &Float, n: usize) -> Result<Float, SlidingError> {
    let p = params.prec;
    let f = |s: &Float| -> Result<Float, SlidingError> {
        let b = branches(params, s, n)?;
        let v = b.get(br).ok_or_else(|| {
            SlidingError::NoConvergence(format!("the centre branch vanished at size {}", readable_mpfr(s)))
        })?;
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
            return Err(SlidingError::NoConvergence(format!(
                "secant left the admissible sizes near {}",
                readable_f64(s0)
            )));
        }
        if Float::with_val(53, step.abs_ref()) <= Float::with_val(53, &tol * Float::with_val(53, x2.abs_ref())) {
            return Ok(x2);
        }
        x0 = x1;
        f0 = f1;
        f1 = f(&x2)?;
        x1 = x2;
    }
    Err(SlidingError::NoConvergence(format!(
        "secant refinement of the contact size did not converge (start {})",
        readable_f64(s0)
    )))
}

/// Whether a run checks its solutions for physicality (p >= 0, gap >= 0; [`super::physical`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Checks {
    /// Keep only physical solutions (the main run).
    Physical,
    /// Keep every root of the equations (the verification run, which pairs its roots with the
    /// main run's; explorations of the load curve).
    Skip,
}

/// Refuses points outside (-1, 1), compared exactly (a point that rounds to 1 is still inside).
pub(super) fn check_points(points: &[Exact]) -> Result<(), SlidingError> {
    let one = Exact::from_integer(1.into());
    for x in points {
        if !(x > &-one.clone() && x < &one) {
            return Err(SlidingError::parameter(
                "points",
                crate::model::readable(x),
                "each point xh = (x - c)/l must lie in (-1, 1)",
            ));
        }
    }
    Ok(())
}

/// Solves Problem 1 at `prec` bits; the node count per solution is `nodes.factor` times the
/// error-model count for `nodes.digits` at its lambda. `points` are xh = (x - c)/l in (-1, 1).
/// `checks` selects whether non-physical roots are dropped. Returns every solution, sorted by
/// contact size (smallest first), in the problem's units.
pub fn solve_at(
    problem: &SlidingProblem,
    points: &[Exact],
    nodes: NodeRule,
    checks: Checks,
    prec: u32,
) -> Result<Vec<SlidingSolution>, SlidingError> {
    check_points(points)?;
    let setup = Setup::new(problem)?;
    let params = SlidingParamsMpfr::new(problem, prec)?;
    let sols = solve_located(&setup, &params, points, nodes, checks, None)?;
    Ok(sols.into_iter().map(|(s, _)| s.in_units_of(&params.unit)).collect())
}

/// [`solve_at`] with the parameters `params` of the working precision, in units of E* (the
/// solutions too), reusing the sizes located by an earlier run when `located` is given (inverse
/// problem); returns with each solution the located size it came from. `points` are checked.
pub(super) fn solve_located(
    setup: &Setup,
    params: &SlidingParamsMpfr,
    points: &[Exact],
    nodes: NodeRule,
    checks: Checks,
    located: Option<&[Located]>,
) -> Result<Vec<(SlidingSolution, Located)>, SlidingError> {
    let prec = params.prec;
    let check = checks == Checks::Physical;
    let n_for = |size: f64| -> Result<usize, SlidingError> {
        let lam = lambda_of(params, size);
        let n0 = nodes_for(lam, nodes.digits).max(profile_nodes(params, size, nodes.digits));
        let n = (n0 as f64 * nodes.factor).ceil();
        if n0 == usize::MAX || n > NODE_CAP as f64 {
            return Err(SlidingError::NoConvergence(format!(
                "lambda = pi l/L = {} is too close to pi/2 (full contact) for {} digits: the quadrature would need \
                 more than {NODE_CAP} nodes; ask fewer digits or a smaller contact",
                readable_f64(lam),
                nodes.digits
            )));
        }
        Ok((n as usize).div_ceil(4) * 4)
    };
    // Candidate (size, centre) pairs at working precision, and why roots were refused.
    let mut cands: Vec<(Float, ShiftSolution, usize, Located)> = vec![];
    let mut reasons: Vec<String> = vec![];
    match &params.target {
        TargetMpfr::HalfLength(lf) => {
            let s = match &params.period {
                Some(big_l) => Float::with_val(prec, lf * &params.pi) / big_l,
                None => lf.clone(),
            };
            let n = n_for(s.to_f64())?;
            for (br, b) in branches(params, &s, n)?.into_iter().enumerate() {
                if b.p2 > 0u32 {
                    cands.push((s.clone(), b, n, (s.to_f64(), br)));
                }
            }
        }
        TargetMpfr::NormalLoad(p2f) => {
            let found = match located {
                Some(v) => v.to_vec(),
                None => locate(setup)?,
            };
            for (s0, br) in found {
                // Screen the roots for physicality at the locating precision first, so that
                // non-physical roots (e.g. on the falling part of the sinusoid's P2(lambda)) are
                // not refined at full precision. A root within the checks' tolerance of the
                // physical boundary could be misjudged here; such roots sit at the end of the
                // physical range.
                if check && located.is_none() {
                    let lo = &setup.locate;
                    let n_lo = bucket(nodes_for(lambda_of(lo, s0), LOCATE_DIGITS));
                    let s_lo = Float::with_val(LOCATE_PREC, s0);
                    if let Some(sol) = branches(lo, &s_lo, n_lo)?.get(br)
                        && let Err(r) = physical_at(lo, &s_lo, sol, n_lo)?
                    {
                        reasons.push(reason_or_error(lambda_of(lo, s0), r)?);
                        continue;
                    }
                }
                let n = n_for(s0)?;
                let s = refine(params, s0, br, p2f, n)?;
                let b = branches(params, &s, n)?;
                let mut sol =
                    b.get(br).cloned().ok_or_else(|| SlidingError::NoConvergence("centre branch lost".into()))?;
                sol.p2 = p2f.clone();
                cands.push((s, sol, n, (s0, br)));
            }
        }
    }
    let mut out = vec![];
    for (s, sh, n, loc) in cands {
        // A polynomial or circle: inside |x| < R, convex and with a small slope on the contact,
        // before the physicality checks (an input the theory does not cover, not a solution).
        if check {
            let l = Size::new(params, &s).l;
            let left = Float::with_val(53, &sh.c - &l).to_f64();
            let right = Float::with_val(53, &sh.c + &l).to_f64();
            check_profile_on_contact(&setup.problem, left, right)?;
        }
        match build(params, &s, sh, n, points, check)? {
            Ok(sol) => out.push((sol, loc)),
            Err(r) => reasons.push(reason_or_error(lambda_of(params, s.to_f64()), r)?),
        }
    }
    if out.is_empty() {
        return Err(refused(setup, &reasons)?);
    }
    out.sort_by(|x, y| x.0.l.partial_cmp(&y.0.l).unwrap_or(std::cmp::Ordering::Equal));
    Ok(out)
}

/// Everything about one contact: validity, physicality, pressure, loads (in units of E*).
fn build(
    params: &SlidingParamsMpfr,
    s: &Float,
    sh: ShiftSolution,
    n: usize,
    points: &[Exact],
    check: bool,
) -> Result<Result<SlidingSolution, Refusal>, SlidingError> {
    let p = params.prec;
    let size = Size::new(params, s);
    let contact = Contact::new(params, &size, sh.c.clone());
    let l = size.l.clone();
    let a = Float::with_val(p, &l - &sh.c);
    let b = Float::with_val(p, &l + &sh.c);
    let rule = inverse_rule(params, n)?;
    let pressure = Pressure::new(params, &contact, &rule);
    let p2 = sh.p2;
    let p1 = p1_of(params, &l, &p2);
    let assessment = if check {
        match physicality(params, &contact, &pressure, &p1, &p2) {
            Ok(a) => Some(a),
            Err(r) => return Ok(Err(r)),
        }
    } else {
        None
    };
    let max_pressure = if check { max_pressure(params, &pressure) } else { Float::with_val(p, 0) };
    let rule_w = weight_rule(params, n)?;
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
    let worn = Float::with_val(p, &params.wear * &p2);
    let wear_per_distance = params.period.as_ref().map(|big_l| Float::with_val(p, &worn / big_l));
    let wear_rate = match (&wear_per_distance, &params.speed) {
        (Some(w), Some(v)) => Some(Float::with_val(p, w * v)),
        _ => None,
    };
    // Never return a non-finite number.
    let finite = [&l, &a, &b, &sh.c, &p1, &p2, &f_def, &max_pressure].iter().all(|v| v.is_finite())
        && pts.iter().all(|q| q.p.is_finite() && q.x.is_finite());
    if !finite {
        return Err(SlidingError::NoConvergence(format!(
            "a non-finite value arose for the contact of half-length {}",
            readable_mpfr(&l)
        )));
    }
    Ok(Ok(SlidingSolution {
        theta: params.theta.clone(),
        kappa: params.kappa.clone(),
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
        k: params.k.clone(),
        nodes: n,
        prec: p,
        physicality: assessment,
    }))
}

/// The shared physicality criterion at a contact given from outside (e.g. by the series method):
/// half-length `l` and centre `c` (the problem's lengths), load `p2` in the problem's units; the
/// pressure [2.13] and the gap slope at that contact are evaluated with the node count for 16
/// digits at `params`' precision. `rel_error` is the contact's own relative accuracy: the closure
/// of the gap holds only to it (it follows from the equations), so the closure check allows
/// max(CLOSURE_TOL, 100 rel_error). `Err` for a failure of the evaluation itself.
pub fn physicality_at_contact(
    problem: &SlidingProblem,
    (l, c): (&Float, &Float),
    p2: &Float,
    rel_error: f64,
    prec: u32,
) -> Result<Result<Assessment, Refusal>, SlidingError> {
    let params = SlidingParamsMpfr::new(problem, prec)?;
    let s = match &params.period {
        Some(big_l) => Float::with_val(prec, l * &params.pi) / big_l,
        None => l.clone(),
    };
    let n = bucket(nodes_for(lambda_of(&params, s.to_f64()), LOCATE_DIGITS));
    let sol = ShiftSolution { c: c.clone(), p2: Float::with_val(prec, p2 / &params.unit) };
    physical_at_tol(&params, &s, &sol, n, CLOSURE_TOL.max(100.0 * rel_error))
}

/// The refusal of a contact of `problem` for `reasons` (empty: no contact carries the load), with
/// the admissible range computed by this method's direct problem at the locating precision.
pub fn refusal_for(problem: &SlidingProblem, reasons: &[String]) -> crate::error::Error {
    let err = Setup::new(problem).and_then(|setup| refused(&setup, reasons));
    crate::error::Error::from(match err {
        Ok(e) | Err(e) => e,
    })
}
