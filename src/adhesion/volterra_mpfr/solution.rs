//! Method 1 (MPFR) in dimensional form: the solution of the exact problem (given a or P2,
//! period or single punch) at the requested points x/a, with the tension zones.
//! Scalings: [`crate::adhesion::scales`].

use super::right_side::RightSide;
use super::solve::{solve_rhs, solve_rhs_in, VolterraParams};
use super::volterra::{lambda_of, VolterraSolution};
use crate::adhesion::points::check_points;
use crate::adhesion::profile::{check_profile_on_contact, circle_cap_error, half_width_search, HalfWidthSearch};
use crate::adhesion::tension::{tension_report, TensionReport};
use crate::growing_contact::error::AdhesionError;
use crate::model::OnPunchRow;
use crate::model::{readable, AdhesionProblem, AdhesionSize, Exact, Period};
use crate::numerics::chebyshev;
use crate::numerics::exact::to_float;
use crate::params::adhesion::{AdhesionParamsF64, AdhesionParamsMpfr};
use rug::float::Constant;
use rug::Float;

/// Values at one requested point.
#[derive(Debug, Clone)]
pub struct PointValues {
    /// x/a, exact, in [0, 1].
    pub x_over_a: Exact,
    /// psi = phi' (tangential displacement slope frozen at entry).
    pub psi: Float,
    /// phi = int_0^x psi.
    pub phi: Float,
    /// q1 = shear traction.
    pub q1: Float,
    /// q2 = pressure (-sigma_yy).
    pub q2: Float,
}

/// One MPFR solution.
#[derive(Debug, Clone)]
pub struct AdhesionSolution {
    /// Working precision (bits).
    pub prec: u32,
    /// lambda = pi a/L (0 for a single punch).
    pub lambda: Float,
    /// Half-width a.
    pub half_width: Float,
    /// Load per punch P2.
    pub normal_load: Float,
    /// Requested points.
    pub points: Vec<PointValues>,
    /// Tension zones.
    pub tension: TensionReport,
    /// Chebyshev nodes used.
    pub nodes: usize,
    /// max |Re I - pi| off the collocation nodes (equation residual).
    pub residual: f64,
    /// Pivot ratio of the collocation matrix.
    pub pivot_ratio: f64,
}

/// Method 1 (MPFR) at the given discretisation, with the tension report.
pub fn solve_mpfr(
    problem: &AdhesionProblem,
    points: &[Exact],
    params: VolterraParams,
) -> Result<AdhesionSolution, AdhesionError> {
    solve_mpfr_with(problem, points, params, TensionZones::Locate)
}

/// Whether a solve locates the tension zones (q2 < 0 near the ends) by bisection.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TensionZones {
    /// Locate and refine them.
    Locate,
    /// Skip them (only the q2 at the requested points).
    Skip,
}

/// Method 1; `TensionZones::Skip` skips the (bisection-refined) tension zones, leaving only
/// the edge factor and the points with q2 < 0 (the verification run needs no zones).
pub fn solve_mpfr_with(
    problem: &AdhesionProblem,
    points: &[Exact],
    params: VolterraParams,
    tension: TensionZones,
) -> Result<AdhesionSolution, AdhesionError> {
    check_points(points)?;
    let prec = params.prec;
    let constants = AdhesionParamsMpfr::new(problem.material(), prec);
    let (e_star, k) = (to_float(problem.material().contact_modulus(), prec), to_float(problem.curvature(), prec));
    let pi = Float::with_val(prec, Constant::Pi);
    let zero = Float::with_val(prec, 0);
    let rhs_for_a = |a: &Exact| RightSide::new(problem, to_float(&(a * a), prec), prec);
    let (lambda, a, sol) = match (problem.size(), problem.period()) {
        (AdhesionSize::HalfWidth(a), Period::Infinite) => {
            check_profile_on_contact(problem, to_float(a, 64).to_f64())?;
            let sol = solve_rhs(&constants, &zero, params, &rhs_for_a(a))?;
            (zero.clone(), to_float(a, prec), sol)
        }
        (AdhesionSize::HalfWidth(a), Period::Finite(l)) => {
            check_profile_on_contact(problem, to_float(a, 64).to_f64())?;
            let lam = lambda_of(a, l, prec);
            let sol = solve_rhs_in(&constants, &lam, params, &rhs_for_a(a), problem.periodic_surface())?;
            (lam, to_float(a, prec), sol)
        }
        (AdhesionSize::NormalLoad(p2), Period::Infinite) => match half_width_search(problem) {
            // The parabola: self-similar, F constant.
            HalfWidthSearch::Parabola => {
                let sol = solve_rhs(&constants, &zero, params, &RightSide::Parabola)?;
                let p = to_float(p2, prec);
                let a = Float::with_val(prec, p / (sol.load_ratio() * &e_star * &k)).sqrt();
                (zero.clone(), a, sol)
            }
            search => {
                let (a_max, grow) = match search {
                    HalfWidthSearch::Capped { a_max } => (a_max, false),
                    HalfWidthSearch::Unbounded { start } => (start, true),
                    HalfWidthSearch::Parabola => unreachable!("matched above"),
                };
                let ek = Float::with_val(prec, &e_star * &k);
                let rhs_at = |a: &Float| RightSide::new(problem, Float::with_val(prec, a * a), prec);
                let p2_f64 = crate::numerics::exact::to_f64(p2).unwrap_or(f64::NAN);
                let guess = (p2_f64 / (first_guess_load_constant(problem) * ek.to_f64())).sqrt();
                let (a, sol) = single_punch_half_width(
                    &constants,
                    &rhs_at,
                    &ek,
                    p2,
                    (Float::with_val(prec, a_max), grow),
                    guess,
                    params,
                )?;
                check_profile_on_contact(problem, a.to_f64())?;
                (zero.clone(), a, sol)
            }
        },
        (AdhesionSize::NormalLoad(p2), Period::Finite(l)) => {
            let lf = to_float(l, prec);
            let target = Float::with_val(prec, to_float(p2, prec) * &pi * &pi)
                / (Float::with_val(prec, &lf * &lf) * &e_star * &k);
            // x = l sigma with l = L lambda/pi at the solved lambda.
            let rhs_at = |lam: &Float| {
                let ell = Float::with_val(prec, lam * &lf) / &pi;
                RightSide::new(problem, ell.square(), prec)
            };
            let cap = match half_width_search(problem) {
                HalfWidthSearch::Capped { a_max } => Some(std::f64::consts::PI * a_max / lf.to_f64()),
                _ => None,
            };
            let search = LoadSearch {
                cp: first_guess_load_constant(problem),
                period: lf.to_f64(),
                lambda_cap: cap,
                rhs_at: &rhs_at,
                periodic: problem.periodic_surface(),
            };
            let (lam, big) = lambda_for_load(&constants, &search, &target, p2, params)?;
            let sol = big.restrict(&lam);
            let a = Float::with_val(prec, &lam * &lf) / &pi;
            check_profile_on_contact(problem, a.to_f64())?;
            (lam, a, sol)
        }
    };
    let load = Float::with_val(prec, sol.load_ratio() * &e_star) * &k * &a * &a;
    let mut out = Vec::with_capacity(points.len());
    for p in points {
        let sigma = to_float(p, prec);
        let (q2, q1) = sol.stress_ratio(p);
        let s_ek = Float::with_val(prec, &e_star * &k) * &a;
        out.push(PointValues {
            x_over_a: p.clone(),
            psi: sol.psi_ratio(&sigma) * &k * &a,
            phi: sol.phi_ratio(&sigma) * &k * &a * &a,
            q1: q1 * &s_ek,
            q2: q2 * &s_ek,
        });
    }
    let at_points = out.iter().enumerate().filter(|(_, p)| p.q2 < 0).map(|(i, _)| i).collect();
    // The zones' ends need a few digits only: a 64-bit copy of the solution, made when needed.
    let mut low: Option<VolterraSolution> = None;
    let mut q2_near_edge = |ln_d: f64| {
        let low = low.get_or_insert_with(|| sol.reduced(64));
        let d = Float::with_val(low.prec, ln_d.min(0.0)).exp();
        low.stress_ratio_near_edge(&d).0.to_f64()
    };
    let tension = tension_report(
        sol.edge_stress_factor(),
        sol.eps.to_f64(),
        at_points,
        tension == TensionZones::Locate,
        &mut q2_near_edge,
        prec,
    );
    Ok(AdhesionSolution {
        prec,
        lambda,
        half_width: a,
        normal_load: load,
        points: out,
        tension,
        nodes: sol.f_coeffs.len(),
        residual: sol.residual,
        pivot_ratio: sol.pivot_ratio,
    })
}

/// What the search for the half-width of a given load needs beside the material: `cp` = C_P in
/// `f64` (first guess), the largest lambda searched (the circle's cap short of its wall,
/// [`half_width_search`]; None for the other profiles) and the right side at a solved lambda.
struct LoadSearch<'a> {
    cp: f64,
    period: f64,
    lambda_cap: Option<f64>,
    rhs_at: &'a dyn Fn(&Float) -> RightSide,
    /// The `periodic` convention (docs/theory.md section 8, Problem 2).
    periodic: bool,
}

/// Solves P(lambda) = target, P(lambda) = lambda^2 P2/(E* k a^2) = P2 pi^2/(E* k L^2), by
/// Newton on one Chebyshev solution over [0, Lambda] (f does not depend on lambda:
/// P(lambda) = (1/2) int_0^{lambda^2} f, P'(lambda) = lambda f(lambda^2)). `normal_load` (the
/// given P2) names the input in the error; `search.cp` = C_P in `f64` sets the first guess.
fn lambda_for_load(
    constants: &AdhesionParamsMpfr,
    search: &LoadSearch,
    target: &Float,
    normal_load: &Exact,
    params: VolterraParams,
) -> Result<(Float, VolterraSolution), AdhesionError> {
    let prec = params.prec;
    let cp = search.cp;
    let half_pi = std::f64::consts::FRAC_PI_2;
    // Kuznetsov-like first guess: P ~ 2 C_P ln sec(lambda).
    let t = target.to_f64();
    let mut lam0 = crate::numerics::elementary::acos_exp_neg(t / (2.0 * cp));
    if !(lam0.is_finite()) || lam0 <= 0.0 {
        lam0 = (t / cp).sqrt().min(1.0);
    }
    for _attempt in 0..6 {
        let mut big = (lam0 * 1.15 + 0.02).min(0.5 * (lam0 + half_pi));
        let capped = search.lambda_cap.is_some_and(|c| big >= c);
        if let Some(c) = search.lambda_cap {
            big = big.min(c);
        }
        let big_f = Float::with_val(prec, big);
        let sol = solve_rhs_in(constants, &big_f, params, &(search.rhs_at)(&big_f), search.periodic)?;
        let big2 = Float::with_val(prec, &big_f * &big_f);
        let p_of = |sol: &VolterraSolution, lam: &Float| -> (Float, Float) {
            if sol.periodic() {
                // P(lam) = Lambda^2 int_0^(lam/Lambda) s F(s) ds, P'(lam) = lam F(lam/Lambda).
                let sigma = Float::with_val(prec, lam / &big_f);
                let p = sol.load_ratio_to(&sigma) * &big2;
                let d = sol.f_at(&sigma) * lam;
                return (p, d);
            }
            let tau = Float::with_val(prec, lam * lam) / &big2;
            let p = chebyshev::integral(&sol.f_coeffs, &tau, prec) * &big2 / 2u32;
            let d = sol.f_at(&tau) * lam;
            (p, d)
        };
        let (pmax, _) = p_of(&sol, &big_f);
        if &pmax < target {
            if capped {
                let a_max = big * search.period / std::f64::consts::PI;
                return Err(circle_cap_error(normal_load, a_max, None));
            }
            lam0 = 0.5 * (big + half_pi);
            continue;
        }
        let mut lam = Float::with_val(prec, lam0.min(big));
        for _ in 0..200 {
            let (p, d) = p_of(&sol, &lam);
            let step = Float::with_val(prec, p - target) / d;
            let mut next = Float::with_val(prec, &lam - &step);
            if next > big_f {
                next = Float::with_val(prec, &lam + &big_f) / 2u32;
            }
            if next <= 0 {
                next = Float::with_val(prec, &lam / 2u32);
            }
            let done = Float::with_val(prec, &next - &lam).abs()
                <= Float::with_val(prec, Float::i_exp(1, -(prec as i32) + 4)) * &next;
            lam = next;
            if done {
                return Ok((lam, sol));
            }
        }
        return Err(AdhesionError::NotConverged { what: "Newton for the half-width", reason: "200 steps".into() });
    }
    Err(AdhesionError::IllConditioned {
        method: "mpfr-volterra",
        parameter: "normal_load",
        value: readable(normal_load),
        valid: "a load whose contact stays well below full contact (lambda < pi/2)".into(),
        reason: "the contact is too close to full contact".into(),
    })
}

/// C_P in `f64` for the first guess of the half-width: the f64 constants
/// ([`AdhesionParamsF64::load_constant`]), the same at every working precision (rounding the
/// MPFR constants of a run below 64 bits would move the guess, and with it the Chebyshev interval).
fn first_guess_load_constant(problem: &AdhesionProblem) -> f64 {
    AdhesionParamsF64::new(problem.material()).load_constant
}

/// The half-width of a single punch (period "inf") of a profile other than the parabola under
/// the given load P2: P2(a) = E* k a^2 P~(a) with P~ = (1/2) int_0^1 F (the right side, and so F,
/// depends on a), dP2/da = E* k a F(1) (docs/theory.md section 4 in the limit L -> infinity: f does
/// not depend on the contact size). Newton's method safeguarded by bisection on (0, a_max):
/// `bracket` = (a_max, grow) of [`half_width_search`]; with `grow` (a polynomial) a_max doubles
/// while P2(a_max) is short of the load, else (the circle's cap) such a load is refused naming
/// `normal_load`. Each step is one collocation solve at lambda = 0 (the right side's own size,
/// M + 2 nodes for an even polynomial of degree 2M).
fn single_punch_half_width(
    constants: &AdhesionParamsMpfr,
    rhs_at: &dyn Fn(&Float) -> RightSide,
    ek: &Float,
    normal_load: &Exact,
    bracket: (Float, bool),
    guess: f64,
    params: VolterraParams,
) -> Result<(Float, VolterraSolution), AdhesionError> {
    let (mut a_max, grow) = bracket;
    let prec = params.prec;
    let zero = Float::with_val(prec, 0);
    let one = Float::with_val(prec, 1);
    let target = to_float(normal_load, prec);
    let load_at = |a: &Float| -> Result<(Float, Float, VolterraSolution), AdhesionError> {
        let sol = solve_rhs(constants, &zero, params, &rhs_at(a))?;
        let p = Float::with_val(prec, ek * a) * a * sol.load_ratio();
        let d = Float::with_val(prec, ek * a) * sol.f_at(&one);
        Ok((p, d, sol))
    };
    let (mut p_max, _, _) = load_at(&a_max)?;
    // P2 grows at least like a^2 for a convex polynomial: 64 doublings reach any f64 load.
    for _ in 0..64 {
        if !(grow && p_max < target) {
            break;
        }
        a_max *= 2u32;
        p_max = load_at(&a_max)?.0;
    }
    if p_max < target {
        return Err(circle_cap_error(
            normal_load,
            a_max.to_f64(),
            Some(crate::numerics::accuracy::readable_mpfr(&p_max)),
        ));
    }
    let (mut lo, mut hi) = (zero.clone(), a_max.clone());
    let mut a = if guess.is_finite() && guess > 0.0 && guess < a_max.to_f64() {
        Float::with_val(prec, guess)
    } else {
        Float::with_val(prec, &a_max / 2u32)
    };
    let tol = Float::with_val(prec, Float::i_exp(1, -(prec as i32) + 6));
    for _ in 0..300 {
        let (p, d, sol) = load_at(&a)?;
        if p < target {
            lo = a.clone();
        } else {
            hi = a.clone();
        }
        let newton = Float::with_val(prec, &a - Float::with_val(prec, &p - &target) / &d);
        if Float::with_val(prec, &newton - &a).abs() <= Float::with_val(prec, &tol * &a) {
            return Ok((a, sol));
        }
        let next = if newton > lo && newton < hi { newton } else { Float::with_val(prec, &lo + &hi) / 2u32 };
        a = next;
    }
    Err(AdhesionError::NotConverged { what: "Newton for the single punch's half-width", reason: "300 steps".into() })
}
