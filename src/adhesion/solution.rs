//! Dimensional solutions of Problem 2 (THEORY.md section 4) from the two methods: the contact
//! half-width and load, psi, phi, q1, q2 at requested points x/a, and the tension zones.
//!
//! Scalings (exact inputs rounded once): P2 = E* k a^2 P2~, psi = k a psi~, phi = k a^2 phi~,
//! q = E* k a q~, where the dimensionless ~ quantities depend on nu and lambda = pi a/L only
//! (lambda = 0 for a single punch: the self-similar solution of THEORY.md section 5).

use crate::params::adhesion as constants;
use super::error::AdhesionError;
use super::series_f64;
use super::volterra_mpfr::{self, VolterraParams, VolterraSolution};
use crate::model::{AdhesionProblem, AdhesionSize, Exact, Period};
use crate::numerics::exact::{to_f64, to_float};
use rug::float::Constant;
use rug::{Complex, Float};

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

/// A zone a < x/a < b near the edge where q2 < 0 (tension).
#[derive(Debug, Clone)]
pub struct TensionZone {
    /// Inner end (x/a).
    pub from_x_over_a: Float,
    /// Outer end (x/a).
    pub to_x_over_a: Float,
    /// 1 - x/a at the outer end (accurate even when x/a rounds to 1).
    pub delta_outer: Float,
    /// 1 - x/a at the inner end.
    pub delta_inner: Float,
    /// Whether the ends were refined on the full stress (else: the leading edge asymptote,
    /// relative error O(1 - x/a)).
    pub refined: bool,
}

/// Tension (q2 < 0) near the oscillating edges.
#[derive(Debug, Clone)]
pub struct TensionReport {
    /// C in (q2 + i q1)/(E* k a) ~ C (1 - x/a)^{1/2 - i eps} at the edge.
    pub edge_factor: Complex,
    /// The two outermost zones (infinitely many follow, each e^{2 pi/eps} times closer to the
    /// edge); empty when eps = 0 (nu = 1/2: no oscillation, no tension).
    pub zones: Vec<TensionZone>,
    /// Indices of requested points where the computed q2 < 0.
    pub at_points: Vec<usize>,
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

/// Validates the points (x/a in [0, 1]).
pub fn check_points(points: &[Exact]) -> Result<(), AdhesionError> {
    for p in points {
        if p < &Exact::from_integer(0.into()) || p > &Exact::from_integer(1.into()) {
            return Err(AdhesionError::InvalidArgument {
                parameter: "points",
                value: p.to_string(),
                expected: "x/a must lie in [0, 1] (the solution is symmetric: q2, psi even; q1, phi odd)".into(),
            });
        }
    }
    Ok(())
}

fn inputs(problem: &AdhesionProblem, prec: u32) -> (Float, Float) {
    (to_float(problem.material().contact_modulus(), prec), to_float(problem.curvature(), prec))
}

/// Method 1 (MPFR) at the given discretisation, with the tension report.
pub fn solve_mpfr(
    problem: &AdhesionProblem,
    points: &[Exact],
    params: VolterraParams,
) -> Result<AdhesionSolution, AdhesionError> {
    solve_mpfr_with(problem, points, params, true)
}

/// Method 1; `with_tension = false` skips the (bisection-refined) tension zones, leaving only
/// the edge factor and the points with q2 < 0 (the verification run needs no zones).
pub fn solve_mpfr_with(
    problem: &AdhesionProblem,
    points: &[Exact],
    params: VolterraParams,
    with_tension: bool,
) -> Result<AdhesionSolution, AdhesionError> {
    check_points(points)?;
    let prec = params.prec;
    let (e_star, k) = inputs(problem, prec);
    let pi = Float::with_val(prec, Constant::Pi);
    let zero = Float::with_val(prec, 0);
    let (lambda, a, sol) = match (problem.size(), problem.period()) {
        (AdhesionSize::HalfWidth(a), Period::Infinite) => {
            let sol = volterra_mpfr::solve(problem.material(), &zero, params)?;
            (zero.clone(), to_float(a, prec), sol)
        }
        (AdhesionSize::HalfWidth(a), Period::Finite(l)) => {
            let lam = volterra_mpfr::lambda_of(a, l, prec);
            let sol = volterra_mpfr::solve(problem.material(), &lam, params)?;
            (lam, to_float(a, prec), sol)
        }
        (AdhesionSize::NormalLoad(p2), Period::Infinite) => {
            let sol = volterra_mpfr::solve(problem.material(), &zero, params)?;
            let p = to_float(p2, prec);
            let a = Float::with_val(prec, p / (sol.load_ratio() * &e_star * &k)).sqrt();
            (zero.clone(), a, sol)
        }
        (AdhesionSize::NormalLoad(p2), Period::Finite(l)) => {
            let lf = to_float(l, prec);
            let target = Float::with_val(prec, to_float(p2, prec) * &pi * &pi)
                / (Float::with_val(prec, &lf * &lf) * &e_star * &k);
            let (lam, big) = lambda_for_load(problem, &target, params)?;
            let sol = big.restrict(&lam);
            let a = Float::with_val(prec, &lam * &lf) / &pi;
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
    let tension = tension_report(&sol, &out, with_tension);
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

/// Solves P(lambda) = target, P(lambda) = lambda^2 P2/(E* k a^2) = P2 pi^2/(E* k L^2), by
/// Newton on one Chebyshev solution over [0, Lambda] (f does not depend on lambda:
/// P(lambda) = (1/2) int_0^{lambda^2} f, P'(lambda) = lambda f(lambda^2)).
fn lambda_for_load(
    problem: &AdhesionProblem,
    target: &Float,
    params: VolterraParams,
) -> Result<(Float, VolterraSolution), AdhesionError> {
    let prec = params.prec;
    let cp = constants::single_punch_load_constant(problem.material(), 64).to_f64();
    let half_pi = std::f64::consts::FRAC_PI_2;
    // Kuznetsov-like first guess: P ~ 2 C_P ln sec(lambda).
    let t = target.to_f64();
    let mut lam0 = (-t / (2.0 * cp)).exp().acos();
    if !(lam0.is_finite()) || lam0 <= 0.0 {
        lam0 = (t / cp).sqrt().min(1.0);
    }
    for _attempt in 0..6 {
        let big = (lam0 * 1.15 + 0.02).min(0.5 * (lam0 + half_pi));
        let big_f = Float::with_val(prec, big);
        let sol = volterra_mpfr::solve(problem.material(), &big_f, params)?;
        let big2 = Float::with_val(prec, &big_f * &big_f);
        let p_of = |sol: &VolterraSolution, lam: &Float| -> (Float, Float) {
            let tau = Float::with_val(prec, lam * lam) / &big2;
            let p = crate::adhesion::chebyshev::integral(&sol.f_coeffs, &tau, prec) * &big2 / 2u32;
            let d = sol.f_at(&tau) * lam;
            (p, d)
        };
        let (pmax, _) = p_of(&sol, &big_f);
        if &pmax < target {
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
        value: format!("{t}"),
        valid: "a load whose contact stays well below full contact (lambda < pi/2)".into(),
        reason: "the contact is too close to full contact".into(),
    })
}

/// Tension zones from the edge asymptote q ~ C delta^{1/2 - i eps}: q2 < 0 where
/// cos(arg C - eps ln delta) < 0; the outermost zone is refined by bisection on the full q2
/// when it is not deep in the edge layer (delta > 1e-3).
fn tension_report(sol: &VolterraSolution, points: &[PointValues], zones_wanted: bool) -> TensionReport {
    let prec = sol.prec;
    let c = sol.edge_stress_factor();
    let at_points = points.iter().enumerate().filter(|(_, p)| p.q2 < 0).map(|(i, _)| i).collect();
    let eps = sol.eps.to_f64();
    let mut zones = Vec::new();
    if eps > 0.0 && zones_wanted {
        let arg = Float::with_val(64, c.imag().clone().atan2(c.real())).to_f64();
        let pi = std::f64::consts::PI;
        let m0 = ((arg - pi / 2.0) / (2.0 * pi)).floor() + 1.0;
        for m in [m0, m0 + 1.0] {
            let hi = (arg - pi / 2.0 - 2.0 * pi * m) / eps; // ln delta, outer end
            let lo = (arg - 1.5 * pi - 2.0 * pi * m) / eps; // ln delta, inner end
            let mut ends = [lo, hi];
            let mut refined = false;
            if zones.is_empty() && hi > (1e-3f64).ln() {
                refined = true;
                let low = sol.reduced(64);
                for e in ends.iter_mut() {
                    if let Some(r) = refine_sign_change(&low, *e, 0.6 * pi / eps) {
                        *e = r;
                    } else {
                        refined = false;
                    }
                }
            }
            let to_x = |ln_d: f64| {
                let d = Float::with_val(prec, ln_d).exp();
                Float::with_val(prec, 1u32) - d
            };
            // ends = [ln delta inner, ln delta outer]; x/a = 1 - delta.
            let delta = |ln_d: f64| Float::with_val(prec, ln_d.min(0.0)).exp();
            zones.push(TensionZone {
                from_x_over_a: to_x(ends[1].min(0.0)),
                to_x_over_a: to_x(ends[0].min(0.0)),
                delta_outer: delta(ends[1]),
                delta_inner: delta(ends[0]),
                refined,
            });
        }
    }
    TensionReport { edge_factor: c, zones, at_points }
}

/// Sign change of q2 in ln(delta) within +-half_width/2 of `guess`: Illinois (modified regula
/// falsi) to ~1e-9 in ln(delta), typically 6-10 stress evaluations.
fn refine_sign_change(sol: &VolterraSolution, guess: f64, half_width: f64) -> Option<f64> {
    let q2 = |ln_d: f64| -> f64 {
        let d = Float::with_val(sol.prec, ln_d.min(0.0)).exp();
        sol.stress_ratio_near_edge(&d).0.to_f64()
    };
    let (mut a, mut b) = (guess - 0.5 * half_width, (guess + 0.5 * half_width).min(0.0));
    let (mut fa, mut fb) = (q2(a), q2(b));
    if !(fa * fb < 0.0) {
        return None;
    }
    for _ in 0..40 {
        let m = (a * fb - b * fa) / (fb - fa);
        let fm = q2(m);
        if fm == 0.0 {
            return Some(m);
        }
        if fm * fb < 0.0 {
            a = b;
            fa = fb;
        } else {
            fa *= 0.5;
        }
        b = m;
        fb = fm;
        if (b - a).abs() < 1e-9 {
            return Some(b);
        }
    }
    Some(0.5 * (a + b))
}

/// f64 values at one point (method 2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointValuesF64 {
    /// x/a.
    pub x_over_a: f64,
    /// psi.
    pub psi: f64,
    /// phi.
    pub phi: f64,
    /// q1.
    pub q1: f64,
    /// q2.
    pub q2: f64,
}

/// Method 2 solution (f64).
#[derive(Debug, Clone, PartialEq)]
pub struct AdhesionSolutionF64 {
    /// lambda.
    pub lambda: f64,
    /// a.
    pub half_width: f64,
    /// P2.
    pub normal_load: f64,
    /// Points.
    pub points: Vec<PointValuesF64>,
    /// Series terms used.
    pub terms: usize,
}

/// Method 2 (f64 power series in lambda^2).
pub fn solve_f64(problem: &AdhesionProblem, points: &[Exact]) -> Result<AdhesionSolutionF64, AdhesionError> {
    check_points(points)?;
    let conv = |q: &Exact, name: &'static str| {
        to_f64(q).ok_or(AdhesionError::InvalidArgument {
            parameter: name,
            value: q.to_string(),
            expected: "must fit in f64".into(),
        })
    };
    let e_star = conv(problem.material().contact_modulus(), "contact_modulus")?;
    let k = conv(problem.curvature(), "k")?;
    let pi = std::f64::consts::PI;
    let (lambda, a, sol) = match (problem.size(), problem.period()) {
        (AdhesionSize::HalfWidth(a), Period::Infinite) => {
            (0.0, conv(a, "half_width")?, series_f64::solve(problem.material(), 0.0)?)
        }
        (AdhesionSize::HalfWidth(a), Period::Finite(l)) => {
            let lam = pi * conv(&(a / l), "half_width")?;
            (lam, conv(a, "half_width")?, series_f64::solve(problem.material(), lam)?)
        }
        (AdhesionSize::NormalLoad(p2), Period::Infinite) => {
            let sol = series_f64::solve(problem.material(), 0.0)?;
            let a = (conv(p2, "normal_load")? / (sol.load_ratio() * e_star * k)).sqrt();
            (0.0, a, sol)
        }
        (AdhesionSize::NormalLoad(p2), Period::Finite(l)) => {
            let lf = conv(l, "period")?;
            let target = conv(p2, "normal_load")? * pi * pi / (e_star * k * lf * lf);
            // Newton on P(lambda) = lambda^2 P2~(lambda), re-solving the series each step.
            let cp = constants::single_punch_load_constant(problem.material(), 64).to_f64();
            let mut lam = (-target / (2.0 * cp)).exp().acos().min(series_f64::SERIES_LAMBDA_MAX);
            let mut sol = series_f64::solve(problem.material(), lam)?;
            for it in 0..60 {
                let p = lam * lam * sol.load_ratio();
                let d = lam * sol.f_at(1.0);
                let next = (lam - (p - target) / d).clamp(0.5 * lam, series_f64::SERIES_LAMBDA_MAX);
                let done = (next - lam).abs() <= 1e-15 * lam;
                lam = next;
                sol = series_f64::solve(problem.material(), lam)?;
                if done {
                    break;
                }
                if it == 59 {
                    return Err(AdhesionError::NotConverged {
                        what: "f64 Newton for the half-width",
                        reason: "60 steps".into(),
                    });
                }
            }
            (lam, lam * lf / pi, sol)
        }
    };
    let load = sol.load_ratio() * e_star * k * a * a;
    let pts = points
        .iter()
        .map(|p| {
            let s = to_f64(p).unwrap_or(0.0);
            let (q2, q1) = sol.stress_ratio(s);
            PointValuesF64 {
                x_over_a: s,
                psi: sol.psi_ratio(s) * k * a,
                phi: sol.phi_ratio(s) * k * a * a,
                q1: q1 * e_star * k * a,
                q2: q2 * e_star * k * a,
            }
        })
        .collect();
    Ok(AdhesionSolutionF64 { lambda, half_width: a, normal_load: load, points: pts, terms: sol.f.len() })
}
