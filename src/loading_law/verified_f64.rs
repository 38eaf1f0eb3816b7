//! The loading-law problem by the f64 marching method ([`crate::growing_contact::march`]) in dimensional form,
//! with digits from a second run: the nominal march ([`MarchOptions::NOMINAL`]) and a check run
//! discretised differently ([`MarchOptions::check`]: blocks twice as long, two more points per
//! block, finer rules); digits = -log10 of their difference over the quantity's scale, capped at
//! [`F64_DIGITS_CAP`], with the scales of [`super::verified`] (l for a, b, c; P2 for the loads;
//! k l for psi, k l^2 for phi, E* k l for the stresses). The values are the nominal run's.
//! Scalings (chi = pi x/L): P2 = E* k (L/pi)^2 P(Lambda), P1 = N(P2), l = L Lambda/pi,
//! c = (L/pi) gamma(Lambda), psi = -(2 k L/pi^2) psi_hat, q2 + i q1 = E* k (L/pi^2) sigma_hat,
//! phi = -(2 k L^2/pi^3) int_0^chi psi_hat.
//! The single punch (no period) is the same march with S(d) = d and cos -> 1
//! ([`crate::growing_contact::kernel_f64`]) at a nominal L (the answer does not depend on it).

use super::verified::LawDigits;
use crate::growing_contact::error::AdhesionError;
use crate::growing_contact::kernel_f64::KernelF64;
use crate::growing_contact::march::{march, March, MarchEnd, MarchOptions, MarchSetting};
use crate::model::OnPunchRow;
use crate::model::{readable, Convention, Exact, LawSize, LoadingLaw, LoadingLawProblem};
use crate::numerics::accuracy::{f64_digits_nodes, verified_digits, F64_DIGITS_CAP};
use crate::numerics::exact::to_f64;
use crate::params::adhesion::AdhesionParamsF64;
use num_traits::Signed;
use std::f64::consts::PI;

/// Values at one point x = c + l xh of the final contact.
#[derive(Debug, Clone)]
pub struct LawPointF64 {
    /// xh in (-1, 1).
    pub xh: Exact,
    /// x.
    pub x: f64,
    /// psi = u' frozen at entry.
    pub psi: f64,
    /// phi = int_0^x psi.
    pub phi: f64,
    /// Shear traction q1.
    pub q1: f64,
    /// Pressure q2.
    pub q2: f64,
}

/// One state of the loading path.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LawPathPoint {
    /// lambda = pi l/L.
    pub lambda: f64,
    /// Trailing end a (the contact is [-a, b]).
    pub a: f64,
    /// Leading end b.
    pub b: f64,
    /// Normal load P2.
    pub p2: f64,
    /// Tangential load P1 = N(P2).
    pub p1: f64,
}

/// One run's dimensional values.
#[derive(Debug, Clone)]
pub struct LawValuesF64 {
    /// lambda = pi l/L (for the single punch, at the nominal period).
    pub lambda: f64,
    /// Trailing end.
    pub a: f64,
    /// Leading end.
    pub b: f64,
    /// Centre (b - a)/2.
    pub c: f64,
    /// Half-length (a + b)/2.
    pub l: f64,
    /// Normal load per punch.
    pub p2: f64,
    /// Tangential load per punch.
    pub p1: f64,
    /// Points.
    pub points: Vec<LawPointF64>,
    /// The loading path at the block ends and the final size.
    pub path: Vec<LawPathPoint>,
    /// Blocks of the march.
    pub blocks: usize,
    /// Collocation points per block.
    pub nodes: usize,
}

/// The f64 solution: the nominal run's values and the digits the finer run confirmed.
#[derive(Debug, Clone)]
pub struct LawSolutionF64 {
    /// Values (nominal run).
    pub values: LawValuesF64,
    /// Digits per group, as [`super::verified::LawSolution`].
    pub digits: LawDigits,
}

/// The problem's inputs in `f64`, and the period (None for the single punch).
struct Inputs {
    period: Option<f64>,
    k: f64,
    e_star: f64,
    law: Vec<f64>,
}

fn f64_of(q: &Exact) -> f64 {
    to_f64(q).unwrap_or(f64::NAN)
}

impl Inputs {
    fn new(p: &LoadingLawProblem) -> Self {
        let law = match p.law() {
            LoadingLaw::Linear(n) => vec![0.0, f64_of(n)],
            LoadingLaw::Polynomial(c) => c.iter().map(f64_of).collect(),
        };
        Inputs {
            period: match p.period() {
                crate::model::Period::Finite(l) => Some(f64_of(l)),
                crate::model::Period::Infinite => None,
            },
            k: f64_of(p.k()),
            e_star: f64_of(p.material().contact_modulus()),
            law,
        }
    }
}

/// N(P2).
fn law_at(law: &[f64], p2: f64) -> f64 {
    law.iter().rev().fold(0.0, |acc, c| acc * p2 + c)
}

/// One march of `problem` with `options`, in dimensional form.
fn run(problem: &LoadingLawProblem, xh: &[Exact], options: &MarchOptions) -> Result<LawValuesF64, AdhesionError> {
    let inp = Inputs::new(problem);
    let constants = AdhesionParamsF64::new(problem.material());
    // The single punch's nominal period: Lambda near 1.
    let big_l = match (inp.period, problem.size()) {
        (Some(l), _) => l,
        (None, LawSize::HalfLength(l)) => PI * f64_of(l),
        (None, LawSize::NormalLoad(p2)) => PI * (f64_of(p2) / (inp.e_star * inp.k * constants.load_constant)).sqrt(),
    };
    let single = inp.period.is_none();
    let p2_per_p = inp.e_star * inp.k * big_l * big_l / (PI * PI);
    let setting = MarchSetting {
        kernel: KernelF64 { eps: constants.eps, cosh_pi_eps: constants.cosh_pi_eps, beta: constants.beta, single },
        tilt: problem.convention() == Convention::PeriodicSurface && !single,
        slope: problem.law().derivative().iter().map(f64_of).collect(),
        p2_per_p,
        profile: vec![0.0, PI],
        start: 2.0 * constants.load_constant,
        law_key: problem.law().key(),
        law_text: problem.law().text(),
    };
    let end = match problem.size() {
        LawSize::HalfLength(l) => MarchEnd::Size(PI * f64_of(l) / big_l),
        LawSize::NormalLoad(p2) => {
            MarchEnd::Load { load: f64_of(p2) / p2_per_p, limit: if single { 8.0 } else { 1.45 } }
        }
    };
    let mar = march(&setting, options, end)?;
    values(&mar, &inp, big_l, xh)
}

fn values(mar: &March, inp: &Inputs, big_l: f64, xh: &[Exact]) -> Result<LawValuesF64, AdhesionError> {
    let l_over_pi = big_l / PI;
    let lambda = mar.end;
    let gamma = mar.gamma(lambda);
    let (l, c) = (l_over_pi * lambda, l_over_pi * gamma);
    let p2 = mar.load(lambda) * mar.setting.p2_per_p;
    let psi_scale = 2.0 * inp.k * big_l / (PI * PI);
    let q_scale = inp.e_star * inp.k * big_l / (PI * PI);
    let mut points = Vec::with_capacity(xh.len());
    let xs: Vec<f64> = xh.iter().map(|h| c + l * f64_of(h)).collect();
    let chis: Vec<f64> = xs.iter().map(|x| x / l_over_pi).collect();
    let integrals = mar.psi_hat_integrals(&chis)?;
    for (((h, &x), &chi), integral) in xh.iter().zip(&xs).zip(&chis).zip(integrals) {
        let sigma = mar.sigma_hat(chi)? * q_scale;
        points.push(LawPointF64 {
            xh: h.clone(),
            x,
            psi: -psi_scale * mar.psi_hat(chi)?,
            phi: -psi_scale * l_over_pi * integral,
            q1: sigma.im,
            q2: sigma.re,
        });
    }
    let state = |lam: f64| {
        let (g, p2) = (mar.gamma(lam), mar.load(lam) * mar.setting.p2_per_p);
        LawPathPoint { lambda: lam, a: l_over_pi * (lam - g), b: l_over_pi * (lam + g), p2, p1: law_at(&inp.law, p2) }
    };
    let mut path: Vec<LawPathPoint> = mar.blocks.iter().map(|b| b.end()).filter(|e| *e < lambda).map(state).collect();
    path.push(state(lambda));
    Ok(LawValuesF64 {
        lambda,
        a: l - c,
        b: l + c,
        c,
        l,
        p2,
        p1: law_at(&inp.law, p2),
        points,
        path,
        blocks: mar.blocks.len(),
        nodes: mar.options.nodes,
    })
}

/// Above this eps (nu below about 0.15) a given size is solved as one block (module doc).
pub const SMALL_NU_EPS: f64 = 0.139;

/// Smallest lambda = pi l/L the f64 loading-law method answers for (a periodic contact).
pub const MIN_LAMBDA: f64 = 1e-6;

/// The march's round-off on small contacts: its error relative to each quantity's scale grows
/// like eps/lambda^2 (two digits per decade of lambda below about 3e-3), and its check run, in
/// the same arithmetic, sees it only by chance. The claims carry SMALL_CONTACT_ROUNDOFF
/// eps/lambda^2 of each scale (twice that of P2, which goes like l^2). Measured (issue 34, fuzz
/// seed 2026 case 8848 and `examples`-style sweeps of its scene, given loads 2.1e-10 .. 1.9e-5 at
/// nu = 0, 9/50, 2/5, 1/2: lambda = 9.4e-6 .. 3e-3) against the MPFR collocation at 16 digits:
/// l, a and the stresses off by 0.6e-4 .. 5.2e-4 eps/lambda^2 (held 9.2 digits at lambda = 1e-5,
/// 11.1-12.5 at 1.2e-4, 13.0-13.9 at 1e-3) while the check run claimed up to 12.1 at 1.26e-4 (the
/// two runs' difference crossing zero). A measured bound with a factor 4 over the largest error
/// seen, not a proved one.
pub const SMALL_CONTACT_ROUNDOFF: f64 = 2e-3;

/// Solves `problem` by the f64 marching method with the nominal discretisation, digits from the
/// finer run (module doc). `xh` are points of the final contact in (-1, 1).
/// At small nu (eps > [`SMALL_NU_EPS`]) and a given size, the loading is one block (a global
/// collocation with the points of [`crate::growing_contact::march::points_for`], the check run
/// 8 more): the march's blocks of 0.05 amplify their own error there until an end recedes, while
/// one block stays stable wherever the problem fixes its solution (nu = 0, n = 1/5: l/L = 1/16
/// and 1/8 agree with the MPFR collocation, tests/all/loading_law_agreement.rs); a given load keeps
/// the blocks (and is refused there as before).
pub fn solve_law_f64(problem: &LoadingLawProblem, xh: &[Exact]) -> Result<LawSolutionF64, AdhesionError> {
    solve_law_f64_beside(problem, xh, || ()).map(|(sol, ())| sol)
}

/// [`solve_law_f64`], and `beside()` after the check run on its CPU while the nominal run (the
/// longer: the check run is about 0.7 of it) has the other to itself
/// ([`crate::numerics::parallel::join`]; `solve` runs the mode check there). `beside` is not run
/// where the solve fails before the runs; its result is dropped where a run fails.
pub fn solve_law_f64_beside<T: Send>(
    problem: &LoadingLawProblem,
    xh: &[Exact],
    beside: impl FnOnce() -> T + Send,
) -> Result<(LawSolutionF64, T), AdhesionError> {
    let eps = AdhesionParamsF64::new(problem.material()).eps;
    if let (true, LawSize::HalfLength(l)) = (eps > SMALL_NU_EPS, problem.size()) {
        let lambda = match problem.period() {
            crate::model::Period::Finite(big_l) => PI * f64_of(l) / f64_of(big_l),
            crate::model::Period::Infinite => 1.0,
        };
        if let Some(m) = crate::growing_contact::march::points_for(lambda) {
            let nominal = MarchOptions { nodes: m, block: lambda, gauss: 40, bits: 60 };
            let check = MarchOptions { nodes: m + 8, block: lambda, gauss: 52, bits: 76 };
            return solve_law_f64_runs(problem, xh, &nominal, &check, beside);
        }
    }
    let options = MarchOptions::NOMINAL;
    solve_law_f64_runs(problem, xh, &options, &options.check(), beside)
}

/// The nominal run with `options` and the check run with `check`, and `beside` after the
/// check run ([`solve_law_f64_beside`]).
fn solve_law_f64_runs<T: Send>(
    problem: &LoadingLawProblem,
    xh: &[Exact],
    options: &MarchOptions,
    check: &MarchOptions,
    beside: impl FnOnce() -> T + Send,
) -> Result<(LawSolutionF64, T), AdhesionError> {
    for h in xh {
        if h.abs() >= Exact::from_integer(1.into()) {
            return Err(AdhesionError::InvalidArgument {
                parameter: "points",
                value: readable(h),
                expected: "xh = (x - c)/l in (-1, 1)".into(),
            });
        }
    }
    // The nominal and check runs are independent: on two CPUs ([`crate::numerics::parallel::join`];
    // in turn inside another map's worker). Each run's result is its serial one; the nominal
    // run's error comes first, as when the check ran after it.
    let (u, (v, extra)) = crate::numerics::parallel::join(
        || run(problem, xh, options),
        || {
            let v = run(problem, xh, check);
            (v, beside())
        },
    );
    let u = u?;
    // Below lambda = 1e-6 the marching's P2 and a lose every digit while its check run agrees with
    // it (issue 34, fuzzing: P2 off by a factor 2 at lambda = 4e-9 and 1e-8, claiming 13 digits):
    // beyond this method's reach.
    if matches!(problem.period(), crate::model::Period::Finite(_)) && u.lambda < MIN_LAMBDA {
        return Err(AdhesionError::IllConditioned {
            method: "f64 loading law",
            parameter: "lambda",
            value: crate::numerics::accuracy::readable_f64(u.lambda),
            valid: format!("lambda >= {MIN_LAMBDA:e}"),
            reason: "the marching loses its digits on contacts this small while its check run agrees with it; \
                     the verified MPFR method (--method mpfr) solves them"
                .into(),
        });
    }
    let v = v?;
    let cap = F64_DIGITS_CAP;
    // With the f64 round-off floor (issue 34): the check run does not see it.
    // The round-off floor grows with the march: 16 eps per node of every block (fuzzing saw 2400 eps
    // of P2 at lambda = 2.6e-4).
    let steps = 8 * u.blocks * u.nodes;
    let dig = |x: f64, y: f64, scale: f64| f64_digits_nodes(x - y, x, scale, steps);
    // The round-off of small contacts (SMALL_CONTACT_ROUNDOFF), relative to each scale.
    let small = SMALL_CONTACT_ROUNDOFF * f64::EPSILON / (u.lambda * u.lambda);
    let small_digits = |k: f64| verified_digits(k * small, 1.0, cap);
    let ends = dig(u.a, v.a, u.l).min(dig(u.b, v.b, u.l)).min(dig(u.c, v.c, u.l)).min(small_digits(1.0));
    let mut loads = dig(u.p2, v.p2, u.p2).min(dig(u.p1, v.p1, u.p2)).min(small_digits(2.0));
    let inp = Inputs::new(problem);
    // A given load is known exactly: the printed P2 (the march's load at its end) and P1 = N(P2)
    // also carry their distance from it, which the check run (solving for the same load) does not
    // see (issue 34, fuzz seed 2026 cases 1692, 1868, 2462 and 2670: P2 3.4e-13 to 2.1e-12 of itself
    // from the given load at lambda = 2e-4 .. 4e-4, 13.0 digits claimed).
    if let LawSize::NormalLoad(p2) = problem.size() {
        let given = f64_of(p2);
        loads = loads.min(dig(u.p2, given, u.p2)).min(dig(u.p1, law_at(&inp.law, given), u.p2));
    }
    let (kl, ekl) = (inp.k * u.l, inp.k * u.l * inp.e_star);
    let mut fields = if u.points.is_empty() { cap } else { small_digits(1.0) };
    for (p, q) in u.points.iter().zip(&v.points) {
        fields = fields
            .min(dig(p.psi, q.psi, kl))
            .min(dig(p.phi, q.phi, kl * u.l))
            .min(dig(p.q1, q.q1, ekl))
            .min(dig(p.q2, q.q2, ekl));
    }
    let headline = ends.min(loads).min(fields);
    // Fewer than one digit is no answer (issue 34, fuzzing: at lambda = 2.5e-9 the marching gave
    // a = 0 for a = 1.0e-10 while estimating 0 digits).
    if !(headline >= 1.0) {
        return Err(AdhesionError::NotConverged {
            what: "the f64 loading-law method",
            reason: format!(
                "its check run leaves {} digits (< 1) at these parameters; the verified MPFR method (--method mpfr) reaches them",
                crate::numerics::accuracy::readable_f64((headline * 10.0).floor() / 10.0)
            ),
        });
    }
    // No path at l_j = j l/16, profile stresses or end stresses from this method: their digit
    // groups are the cap and describe nothing (the JSON prints them null).
    let digits = LawDigits { ends, loads, fields, path: cap, stresses: cap, headline, friction: cap, end_phases: cap };
    Ok((LawSolutionF64 { values: u, digits }, extra))
}
