//! The loading-law problem in dimensional form with verified digits (docs/theory.md section 10): a
//! periodic row of parabolic punches g = k x^2, or a single one, indented with complete adhesion
//! under P1 = N(P2), given the final half-length l = (a + b)/2 or the load. The single punch runs
//! the same collocation with L = pi U in a length unit U ([`crate::growing_contact::kernel::Row::Single`]: U = l
//! for a given l; for a given load U = 1.3 times the symmetric single punch's half-length, so the
//! final size is a root inside [0, U]). Two collocation runs ([`super::collocation`]), the
//! second with 8 more nodes, 24 more bits (fewer where that saves an MPFR limb) and a finer rule; digits = -log10 of their difference
//! over the quantity's scale (l for a, b, c; P2 for the loads; k l for psi; k l^2 for phi;
//! E* k l for the stresses), as everywhere ([`crate::numerics::accuracy`]). Under a given load the
//! ends, loads, fields and stresses also carry the distance of the printed P2 from that load.
//! The loading path comes from the same runs: one collocation on [0, Lambda] holds every smaller
//! contact (the Volterra structure), so at l_j = j l/[`PATH_STEPS`] the ends and loads are
//!   c_j = (L/pi) gamma(lambda_j) = (L/pi) lambda_j Gam(j/PATH_STEPS), a_j = l_j - c_j,
//!   b_j = l_j + c_j, P2_j = E* k (L/pi)^2 P(lambda_j) ([`LawCollocation::load_at`]), P1_j = N(P2_j),
//! their digits on the scales l_j and P2_j of each point.
//! Scalings (chi = pi x/L, fields of [`super::fields`]):
//!   P2 = E* k (L/pi)^2 P(Lambda), P1 = n P2, l = L Lambda/pi, c = (L/pi) gamma(Lambda),
//!   psi = -(2 k L/pi^2) psi_hat, q2 + i q1 = E* k (L/pi^2) sigma_hat,
//!   phi(x) = int_0^x psi = -(2 k L^2/pi^3) int_0^chi psi_hat (Gauss–Legendre in the entry size
//!   eta, where the integrand is analytic: [`LawCollocation::psi_hat_integral`]; the point x = 0
//!   entered first, where the fields are not smooth in x, is an end of the interval).

use super::collocation::{solve, solve_from, LawCollocation, LawSetting};
use super::ends::EndStress;
use crate::growing_contact::error::AdhesionError;
use crate::growing_contact::kernel::{Row, Side};
use crate::model::OnPunchRow;
use crate::model::{readable, Exact, LawSize, LoadingLawProblem, ModelError, Period};
use crate::numerics::accuracy::{readable_mpfr, verified_digits_mpfr};
use crate::numerics::exact::{to_f64, to_float};
use crate::numerics::precision::{below_limb_boundary, bits_for_digits, SOLVER_GUARD_BITS};
use crate::numerics::tanh_sinh::TanhSinh;
use num_traits::Signed;
use rug::float::Constant;
use rug::{Complex, Float};

/// Values at one point x = c + l xh of the final contact.
#[derive(Debug, Clone)]
pub struct LawPoint {
    /// xh in (-1, 1).
    pub xh: Exact,
    /// x.
    pub x: Float,
    /// psi = u' frozen at entry.
    pub psi: Float,
    /// phi = int_0^x psi.
    pub phi: Float,
    /// Shear traction q1.
    pub q1: Float,
    /// Pressure q2.
    pub q2: Float,
}

/// The number of steps of the loading path: l_j = j l/PATH_STEPS, j = 1..=PATH_STEPS.
pub const PATH_STEPS: u32 = 16;

/// One contact of the loading path (module doc): the state when the half-length was l_j.
#[derive(Debug, Clone)]
pub struct LawPathPoint {
    /// lambda_j = pi l_j/L.
    pub lambda: Float,
    /// l_j = (a_j + b_j)/2.
    pub l: Float,
    /// Trailing end a_j.
    pub a: Float,
    /// Leading end b_j.
    pub b: Float,
    /// Centre c_j = (b_j - a_j)/2.
    pub c: Float,
    /// Normal load P2_j.
    pub p2: Float,
    /// Tangential load P1_j = N(P2_j).
    pub p1: Float,
}

/// The stresses alone at one point x = c + l xh of the final contact (a profile: no psi, no phi,
/// whose nested quadrature costs ~100 times more).
#[derive(Debug, Clone)]
pub struct LawStress {
    /// xh in (-1, 1).
    pub xh: Exact,
    /// x.
    pub x: Float,
    /// Shear traction q1.
    pub q1: Float,
    /// Pressure q2.
    pub q2: Float,
}

/// One run's dimensional values.
#[derive(Debug, Clone)]
pub struct LawValues {
    /// lambda = pi l/L (periodic row); l/U for the single punch (U the collocation's unit).
    pub lambda: Float,
    /// a, b, c, l.
    pub a: Float,
    /// Leading end.
    pub b: Float,
    /// Centre (b - a)/2.
    pub c: Float,
    /// Half-length.
    pub l: Float,
    /// Normal load per punch.
    pub p2: Float,
    /// Tangential load per punch.
    pub p1: Float,
    /// Points.
    pub points: Vec<LawPoint>,
    /// The loading path, j = 1..=[`PATH_STEPS`] (the last is the final contact).
    pub path: Vec<LawPathPoint>,
    /// q1, q2 at the profile points ([`solve_law_sampled`]; empty from [`solve_law`]).
    pub stresses: Vec<LawStress>,
    /// Collocation nodes.
    pub nodes: usize,
    /// The leading end b, then the trailing end -a ([`super::ends`]).
    pub ends: Vec<EndStress>,
    /// eps of the material.
    pub eps: Float,
}

/// The verified solution: the first run's values and the digits confirmed by the second.
#[derive(Debug, Clone)]
pub struct LawSolution {
    /// Values (first run).
    pub values: LawValues,
    /// Digits of a, b, c (scale l), of P1, P2 (scale P2), and the minimum over the points of
    /// psi (k l), phi (k l^2), q1, q2 (E* k l).
    pub digits: LawDigits,
}

impl LawSolution {
    /// Digits of the tension zones' d/l = exp(-gap/eps) ([`EndStress::tension_within`]): the
    /// phases' less log10(1/eps).
    pub fn tension_zone_digits(&self) -> f64 {
        let eps = self.values.eps.to_f64();
        if eps > 0.0 {
            self.digits.end_phases + eps.log10()
        } else {
            self.digits.end_phases
        }
    }
}

/// Verified digits per group of outputs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LawDigits {
    /// a, b, c.
    pub ends: f64,
    /// P1, P2.
    pub loads: f64,
    /// psi, phi, q1, q2 at the points.
    pub fields: f64,
    /// The loading path: a_j, b_j, c_j on the scale l_j, P1_j, P2_j on P2_j, the minimum over j.
    pub path: f64,
    /// q1, q2 at the profile points (scale E* k l); the cap when there are none.
    pub stresses: f64,
    /// Minimum of the above.
    pub headline: f64,
    /// The friction needed near the ends ([`super::ends`]) by the two runs.
    pub friction: f64,
    /// The end phases: the two runs and the asymptote's error ([`EndStress::phase_error`]); the
    /// tension zones' d/l carry these digits less log10(1/eps).
    pub end_phases: f64,
}

/// Collocation nodes for 2^-bits at Lambda: Phi(t) = f(Lambda^2 t^2) is singular at
/// t = (pi/2)/Lambda (full contact), so the Chebyshev coefficients on t in [0, 1] decay like
/// rho^-j, rho = z + sqrt(z^2 - 1), z = 2 t_s - 1 (measured: 16, 24, 32 nodes give 1e-18, 1e-26,
/// 1e-34 at Lambda = 0.5, rho = 10.5; [`super::collocation`] tests).
fn nodes_for(bits: u32, lambda: f64) -> usize {
    let z = 2.0 * std::f64::consts::FRAC_PI_2 / lambda - 1.0;
    let rho = z + (z * z - 1.0).max(0.0).sqrt();
    ((bits as f64 * std::f64::consts::LN_2 / rho.ln()).ceil() as usize + 4).max(8)
}

/// The length unit of the collocation's variables: L/pi for a periodic row (chi = pi x/L), U
/// for the single punch (chi = x/U, [`Row::Single`]).
#[derive(Debug, Clone)]
enum Unit {
    /// Period L.
    Period(Exact),
    /// The single punch's unit U.
    Single(Exact),
}

impl Unit {
    /// L/pi or U at `prec` bits.
    fn length(&self, prec: u32) -> Float {
        match self {
            Unit::Period(l) => to_float(l, prec) / Float::with_val(prec, Constant::Pi),
            Unit::Single(u) => to_float(u, prec),
        }
    }
}

/// The setting of `problem` at the final size `size` = l/L (periodic) or l/U (single punch).
fn setting(problem: &LoadingLawProblem, unit: &Unit, size: Exact) -> LawSetting {
    let (l, row) = match unit {
        Unit::Period(l) => (l, Row::Periodic),
        Unit::Single(u) => (u, Row::Single),
    };
    LawSetting {
        material: problem.material().clone(),
        law: problem.law().clone(),
        load_scale: problem.material().contact_modulus() * problem.k() * l * l,
        size_over_period: size,
        row,
        convention: problem.convention(),
    }
}

/// Nodes at the final size: the periodic row's Phi(t) is singular at full contact
/// ([`nodes_for`]); the single punch's is entire (constant for the linear law: the problem is
/// self-similar), counted as a small periodic contact.
fn nodes_at(unit: &Unit, bits: u32, lambda: f64) -> usize {
    match unit {
        Unit::Period(_) => nodes_for(bits, lambda),
        Unit::Single(_) => nodes_for(bits, 0.3),
    }
}

/// An exact rational within 2^-bits of `v` (its binary expansion cut).
fn exact_of(v: &Float, bits: u32) -> Exact {
    let scale = rug::Integer::from(1) << bits;
    let n = Float::with_val(v.prec(), v * &scale).round().to_integer().unwrap_or_default();
    let num = num_bigint::BigInt::parse_bytes(n.to_string().as_bytes(), 10).unwrap_or_default();
    let den = num_bigint::BigInt::parse_bytes(scale.to_string().as_bytes(), 10).unwrap_or_default();
    Exact::new(num, den)
}

/// The final size of the given load: the collocation on [0, Lambda_1] gives P(lambda) for every
/// lambda <= Lambda_1 (the Volterra structure: a smaller contact is a restriction), so one solve
/// at a Lambda_1 beyond the answer and a root of P(lambda) = P2/(E* k unit^2) on its Chebyshev
/// interpolant (bisection) find it. Periodic: Lambda_1 from the symmetric Kuznetsov-like guess
/// P ~ 2 C_P ln sec(lambda), enlarged while P(Lambda_1) is short of the target; returns l/L.
/// Single punch: Lambda_1 = 1 in the unit U = 1.3 sqrt(P2/(C_P E* k)) (the symmetric single
/// punch's half-length, P2 = C_P E* k l^2, enlarged), U doubled while short; returns (l/U, U).
fn size_for_load(
    problem: &LoadingLawProblem,
    p2: &Exact,
    bits: u32,
    prec: u32,
) -> Result<(Unit, Exact), AdhesionError> {
    let pi = Float::with_val(prec, Constant::Pi);
    let cp = crate::params::adhesion::AdhesionParamsF64::new(problem.material()).load_constant;
    let half_pi = std::f64::consts::FRAC_PI_2;
    let stiffness = problem.material().contact_modulus() * problem.k();
    // (unit, Lambda_1) of attempt j.
    let attempt = |j: i32, big: f64| -> (Unit, f64) {
        match problem.period() {
            Period::Finite(l) => (Unit::Period(l.clone()), big),
            Period::Infinite => {
                let hertz = (to_f64(&(p2 / &stiffness)).unwrap_or(f64::NAN) / cp).sqrt();
                let u = exact_of(&Float::with_val(prec, 1.3 * hertz * 2f64.powi(j)), 40);
                (Unit::Single(u), 1.0)
            }
        }
    };
    let mut big = 0.0;
    if let Period::Finite(l) = problem.period() {
        let target = to_f64(&(p2 / &(&stiffness * l * l))).unwrap_or(f64::NAN) * std::f64::consts::PI.powi(2);
        let guess = crate::numerics::elementary::acos_exp_neg(target / (2.0 * cp));
        big = (guess * 1.15 + 0.05).min(0.5 * (guess + half_pi));
    }
    for j in 0..6 {
        let (unit, lambda_1) = attempt(j, big);
        let over = match &unit {
            Unit::Period(_) => exact_of(&Float::with_val(prec, Float::with_val(prec, lambda_1) / &pi), 40),
            Unit::Single(_) => Exact::from_integer(1.into()),
        };
        let sol = solve(&setting(problem, &unit, over.clone()), nodes_at(&unit, bits, lambda_1), bits, prec)?;
        // P = P2/(P2 per unit P) of this setting (E* k L^2/pi^2 or E* k U^2).
        let target = to_float(p2, prec) / &sol.inc.p2_per_p;
        if sol.load() < target {
            big = 0.5 * (big + half_pi);
            continue;
        }
        let (mut lo, mut hi) = (Float::with_val(prec, 0), Float::with_val(prec, 1));
        for _ in 0..(prec + 8) {
            let mid = Float::with_val(prec, &lo + &hi) / 2u32;
            if sol.load_at(&mid) < target {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        // lambda = Lambda_1 t scales the size linearly in both rows: l/L or l/U = over t.
        let size = exact_of(&(to_float(&over, prec) * lo), prec);
        return Ok((unit, size));
    }
    Err(AdhesionError::IllConditioned {
        method: "mpfr-loading-law",
        parameter: "normal_load",
        value: readable(p2),
        valid: "a load whose contact stays well below full contact (lambda < pi/2)".into(),
        reason: "the contact is too close to full contact".into(),
    })
}

/// One collocation run with `extra_nodes` over the nominal count, its Newton iteration started
/// from `start` where given ([`solve_from`]; the second run starts from the first run's solution).
fn run(
    problem: &LoadingLawProblem,
    xh: &[Exact],
    stress_xh: &[Exact],
    extra_nodes: usize,
    target_bits: u32,
    prec: u32,
    start: Option<&LawCollocation>,
) -> Result<(LawValues, LawCollocation), AdhesionError> {
    let (unit, over) = match (problem.size(), problem.period()) {
        (LawSize::HalfLength(l), Period::Finite(big_l)) => (Unit::Period(big_l.clone()), l / big_l),
        (LawSize::HalfLength(l), Period::Infinite) => (Unit::Single(l.clone()), Exact::from_integer(1.into())),
        (LawSize::NormalLoad(p2), _) => size_for_load(problem, p2, target_bits, prec)?,
    };
    let lambda = to_f64(&over).unwrap_or(f64::NAN) * std::f64::consts::PI;
    let s = setting(problem, &unit, over);
    let sol = solve_from(&s, nodes_at(&unit, target_bits, lambda) + extra_nodes, target_bits, prec, start)?;
    // N' >= 0 along the loading (the requirement: P1 must not decrease as P2 grows).
    for i in 0..=32u32 {
        let p = sol.load_at(&(Float::with_val(prec, i) / 32u32));
        let n = sol.inc.ratio_at(&p);
        if n < 0 {
            let p2 = Float::with_val(prec, &p * &sol.inc.p2_per_p);
            return Err(ModelError::new(
                problem.law().key(),
                problem.law().text(),
                format!(
                    "N'(P2) >= 0 along the loading (P1 must not decrease as P2 grows), but N'({}) = {}",
                    readable_mpfr(&p2),
                    readable_mpfr(&n)
                ),
            )
            .into());
        }
    }
    Ok((values(problem, &unit, &sol, xh, stress_xh, target_bits)?, sol))
}

fn values(
    problem: &LoadingLawProblem,
    unit: &Unit,
    sol: &LawCollocation,
    xh: &[Exact],
    stress_xh: &[Exact],
    target_bits: u32,
) -> Result<LawValues, AdhesionError> {
    let prec = sol.prec;
    let pi = Float::with_val(prec, Constant::Pi);
    let k = to_float(problem.k(), prec);
    let e_star = to_float(problem.material().contact_modulus(), prec);
    let l_over_pi = unit.length(prec);
    let lambda = sol.lambda_max.clone();
    let gamma = sol.centre_at(&lambda);
    let l = Float::with_val(prec, &l_over_pi * &lambda);
    let c = Float::with_val(prec, &l_over_pi * &gamma);
    let p = sol.load();
    let p2 = Float::with_val(prec, &p * &sol.inc.p2_per_p);
    let p1 = sol.inc.law_at(&p) * &sol.inc.p2_per_p;
    let rule = TanhSinh::new(target_bits + 8, 1.0, prec);
    // Gauss–Legendre in the entry size for phi ([`LawCollocation::psi_hat_integral`]): the
    // collocation's n nodes for these bits give rho^-(n - 4) = 2^-bits; Gauss–Legendre's error
    // rho^(-2 m) with m = (n - 4)/2 + 4 is that times rho^-8.
    let phi_nodes = (nodes_at(unit, target_bits, lambda.to_f64()) - 4).div_ceil(2) + 4;
    // 2 k L/pi^2 and E* k L/pi^2 with L = pi unit.
    let psi_scale = Float::with_val(prec, &k * &l_over_pi) * 2u32 / &pi;
    let q_scale = Float::with_val(prec, &e_star * &k) * &l_over_pi / &pi;
    let phi_scale = Float::with_val(prec, &psi_scale * &l_over_pi);
    // psi and sigma at the points, the profile's stresses and the two ends: one map on every CPU
    // (ends first, the largest items, so that the CPUs finish together); phi after, point by
    // point, its Gauss–Legendre nodes on every CPU.
    enum Job<'a> {
        End(Side),
        Point(&'a Exact),
        Stress(&'a Exact),
    }
    enum Done {
        End(Box<EndStress>),
        Point(Float, Float, Float, Complex),
        Stress(Float, Complex),
    }
    let jobs: Vec<Job> = [Job::End(Side::Right), Job::End(Side::Left)]
        .into_iter()
        .chain(xh.iter().map(Job::Point))
        .chain(stress_xh.iter().map(Job::Stress))
        .collect();
    let at = |h: &Exact| {
        let x = Float::with_val(prec, &c + Float::with_val(prec, &l * to_float(h, prec)));
        let chi = Float::with_val(prec, &x / &l_over_pi);
        (x, chi)
    };
    let done = crate::numerics::parallel::map(&jobs, |_, job| match job {
        Job::End(side) => Done::End(Box::new(sol.end_stress(*side, &rule))),
        Job::Point(h) => {
            let (x, chi) = at(h);
            let psi = -sol.psi_hat(&chi, &rule) * &psi_scale;
            let sigma: Complex = sol.sigma_hat(&chi, &rule) * &q_scale;
            Done::Point(x, chi, psi, sigma)
        }
        Job::Stress(h) => {
            let (x, chi) = at(h);
            Done::Stress(x, sol.sigma_hat(&chi, &rule) * &q_scale)
        }
    });
    let (mut ends, mut located, mut profile) = (Vec::new(), Vec::new(), Vec::new());
    for d in done {
        match d {
            Done::End(e) => ends.push(*e),
            Done::Point(x, chi, psi, sigma) => located.push((x, chi, psi, sigma)),
            Done::Stress(x, sigma) => profile.push((x, sigma)),
        }
    }
    let mut points = Vec::with_capacity(xh.len());
    for (h, (x, chi, psi, sigma)) in xh.iter().zip(located) {
        let phi = -sol.psi_hat_integral(&chi, &rule, phi_nodes)? * &phi_scale;
        points.push(LawPoint { xh: h.clone(), x, psi, phi, q1: sigma.imag().clone(), q2: sigma.real().clone() });
    }
    let stresses = stress_xh
        .iter()
        .zip(profile)
        .map(|(h, (x, sigma))| LawStress { xh: h.clone(), x, q1: sigma.imag().clone(), q2: sigma.real().clone() })
        .collect();
    let path = (1..=PATH_STEPS)
        .map(|j| {
            let t = Float::with_val(prec, j) / PATH_STEPS;
            let lambda_j = Float::with_val(prec, &lambda * &t);
            let l_j = Float::with_val(prec, &l_over_pi * &lambda_j);
            let c_j = Float::with_val(prec, &l_over_pi * sol.centre_at(&lambda_j));
            let p_j = sol.load_at(&t);
            LawPathPoint {
                a: Float::with_val(prec, &l_j - &c_j),
                b: Float::with_val(prec, &l_j + &c_j),
                c: c_j,
                l: l_j,
                lambda: lambda_j,
                p2: Float::with_val(prec, &p_j * &sol.inc.p2_per_p),
                p1: sol.inc.law_at(&p_j) * &sol.inc.p2_per_p,
            }
        })
        .collect();
    Ok(LawValues {
        lambda,
        a: Float::with_val(prec, &l - &c),
        b: Float::with_val(prec, &l + &c),
        c,
        l,
        p2,
        p1,
        points,
        path,
        stresses,
        nodes: sol.phi.len(),
        ends,
        eps: sol.inc.eps.clone(),
    })
}

/// Solves `problem` for `digits` digits, verified by a second, finer run (module doc). `xh` are
/// points of the final contact in (-1, 1).
pub fn solve_law(problem: &LoadingLawProblem, xh: &[Exact], digits: u32) -> Result<LawSolution, AdhesionError> {
    solve_law_sampled(problem, xh, &[], digits)
}

/// [`solve_law`] with, besides the points `xh` (all fields), the stresses q1, q2 alone at the
/// profile points `stress_xh` in (-1, 1) ([`LawValues::stresses`], digits
/// [`LawDigits::stresses`]), from the same two runs.
pub fn solve_law_sampled(
    problem: &LoadingLawProblem,
    xh: &[Exact],
    stress_xh: &[Exact],
    digits: u32,
) -> Result<LawSolution, AdhesionError> {
    solve_law_collocation(problem, xh, stress_xh, digits).map(|(solution, _)| solution)
}

/// A collocation that did not converge, with the problem's homogeneous mode named when it has
/// one ([`crate::asymptotics::loading_law_modes`]: the history is fixed only up to C eta^mu*, and
/// the discretisation's error at small sizes grows like (Lambda/eta)^mu*; nu = 0, n = 1/2, l/L =
/// 1/8 at 20 digits ends so: `nu_zero_reach` in `tests/all/loading_law_agreement.rs`; the message:
/// test `refusal_names_the_mode`).
fn with_mode(problem: &LoadingLawProblem, e: AdhesionError) -> AdhesionError {
    let AdhesionError::NotConverged { what, reason } = e else { return e };
    let n0 = problem.law().initial_ratio();
    let mode = crate::asymptotics::loading_law_modes::problem_mode(problem);
    let reason = match mode.ok().and_then(|m| m.value_text()) {
        Some(mu) => format!(
            "{reason}; the problem has the homogeneous mode eta^mu* with mu* = {mu} (nu = {}, n = N'(0) = {}; \
             asymptotics::loading_law_modes): the law and both edge conditions fix the history only up to C eta^mu*, \
             and the discretisation's error at small sizes grows like (Lambda/eta)^mu*",
            readable(problem.material().poisson_ratio()),
            readable(&n0)
        ),
        None => reason,
    };
    AdhesionError::NotConverged { what, reason }
}

/// [`solve_law_sampled`] and the first run's collocation (whose values it returns): for checks
/// that need the solution as a function, such as the residual of [1.8] in [`super::fields`]'
/// tests.
pub(crate) fn solve_law_collocation(
    problem: &LoadingLawProblem,
    xh: &[Exact],
    stress_xh: &[Exact],
    digits: u32,
) -> Result<(LawSolution, LawCollocation), AdhesionError> {
    for h in xh.iter().chain(stress_xh) {
        if !(h.abs() < Exact::from_integer(1.into())) {
            return Err(AdhesionError::InvalidArgument {
                parameter: "points",
                value: readable(h),
                expected: "xh = (x - c)/l in (-1, 1)".into(),
            });
        }
    }
    let bits = bits_for_digits(digits) + 8;
    let (first, collocation) =
        run(problem, xh, stress_xh, 0, bits, bits + 32, None).map_err(|e| with_mode(problem, e))?;
    // The second run's 24 more bits, or fewer where that saves an MPFR limb and keeps 32 guard
    // bits over its target (131 -> 127 bits at 20 digits; the runs' difference is their
    // discretisations', some 2^-75, far above either rounding).
    let second_prec = below_limb_boundary(bits + 16 + SOLVER_GUARD_BITS, bits + 56);
    let (second, _) = run(problem, xh, stress_xh, 8, bits + 16, second_prec, Some(&collocation))
        .map_err(|e| with_mode(problem, e))?;
    let cap = digits as f64 + 8.0;
    let dig = |u: &Float, v: &Float, scale: &Float| {
        let d = Float::with_val(u.prec().max(v.prec()), u - v);
        verified_digits_mpfr(&d, scale, cap)
    };
    let (u, v) = (&first, &second);
    let mut ends = dig(&u.a, &v.a, &u.l).min(dig(&u.b, &v.b, &u.l)).min(dig(&u.c, &v.c, &u.l));
    let mut loads = dig(&u.p2, &v.p2, &u.p2).min(dig(&u.p1, &v.p1, &u.p2));
    let prec = u.l.prec();
    // A given load is exact: the printed P2 (and P1 = N(P2)) also carries its distance from it,
    // which the second run, solving for the same load, does not see; the size solved for that
    // load, and so the ends and the fields, carry the same discretisation error (issue 34, fuzz
    // seed 2026 case 7302: at lambda = 0.955, 10 digits, the runs agreed to 6.73 digits of P2, which
    // lay 6.69 digits from the given load, and the stresses 6.81 digits where they held 6.77
    // against the f64 method, to which the MPFR runs at 11, 16 and 24 digits converge).
    let given_load = match problem.size() {
        LawSize::NormalLoad(p2) => Some(dig(&u.p2, &to_float(p2, prec), &u.p2)),
        LawSize::HalfLength(_) => None,
    };
    if let Some(d) = given_load {
        loads = loads.min(d);
        ends = ends.min(d);
    }
    let k = to_float(problem.k(), prec);
    let e_star = to_float(problem.material().contact_modulus(), prec);
    let kl = Float::with_val(prec, &k * &u.l);
    let kl2 = Float::with_val(prec, &kl * &u.l);
    let ekl = Float::with_val(prec, &kl * &e_star);
    let mut fields = cap;
    for (p, q) in u.points.iter().zip(&v.points) {
        fields = fields
            .min(dig(&p.psi, &q.psi, &kl))
            .min(dig(&p.phi, &q.phi, &kl2))
            .min(dig(&p.q1, &q.q1, &ekl))
            .min(dig(&p.q2, &q.q2, &ekl));
    }
    if let (Some(d), false) = (given_load, u.points.is_empty()) {
        fields = fields.min(d);
    }
    let mut stresses = cap;
    for (p, q) in u.stresses.iter().zip(&v.stresses) {
        stresses = stresses.min(dig(&p.q1, &q.q1, &ekl)).min(dig(&p.q2, &q.q2, &ekl));
    }
    if let (Some(d), false) = (given_load, u.stresses.is_empty()) {
        stresses = stresses.min(d);
    }
    let mut path = cap;
    for (p, q) in u.path.iter().zip(&v.path) {
        path = path
            .min(dig(&p.a, &q.a, &p.l))
            .min(dig(&p.b, &q.b, &p.l))
            .min(dig(&p.c, &q.c, &p.l))
            .min(dig(&p.p2, &q.p2, &p.p2))
            .min(dig(&p.p1, &q.p1, &p.p2));
    }
    let headline = ends.min(loads).min(fields).min(path).min(stresses);
    let (mut friction, mut end_phases) = (cap, cap);
    for (p, q) in u.ends.iter().zip(&v.ends) {
        let model = -p.phase_error.to_f64().max(1e-300).log10();
        end_phases = end_phases.min(dig(&p.phase, &q.phase, &Float::with_val(prec, 1))).min(model);
        for (f, g) in p.friction_needed.iter().zip(&q.friction_needed) {
            if let (Some(f), Some(g)) = (f, g) {
                friction = friction.min(dig(f, g, f));
            }
        }
    }
    let digits = LawDigits { ends, loads, fields, path, stresses, headline, friction, end_phases };
    Ok((LawSolution { values: first, digits }, collocation))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Convention, LoadingLaw, Material, Period, PunchShape};

    fn q(n: i64, d: i64) -> Exact {
        Exact::new(n.into(), d.into())
    }

    /// A collocation that does not converge names the homogeneous mode when the problem has one
    /// (nu = 0, n = 1/2: mu* = 31.8395100566) and passes the error on unchanged when it has none
    /// (nu = 3/10, n = 1/5).
    #[test]
    fn refusal_names_the_mode() {
        let stuck = || AdhesionError::NotConverged {
            what: "loading-law collocation",
            reason: "the trailing end recedes".into(),
        };
        let nu0 = law_problem_at(q(0, 1), LoadingLaw::Linear(q(1, 2)), LawSize::HalfLength(q(1, 8)), Convention::Paper);
        let e = with_mode(&nu0, stuck()).to_string();
        assert!(
            e.contains("trailing end recedes") && e.contains("mu* = 31.8395100566") && e.contains("n = N'(0) = 1/2"),
            "{e}"
        );
        let nu03 = law_problem(LoadingLaw::Linear(q(1, 5)), LawSize::HalfLength(q(1, 8)), Convention::Paper);
        assert_eq!(with_mode(&nu03, stuck()).to_string(), stuck().to_string());
    }

    fn law_problem(law: LoadingLaw, size: LawSize, convention: Convention) -> LoadingLawProblem {
        law_problem_at(q(3, 10), law, size, convention)
    }

    fn law_problem_at(nu: Exact, law: LoadingLaw, size: LawSize, convention: Convention) -> LoadingLawProblem {
        let material = Material::from_contact_modulus(nu, q(1, 1)).unwrap();
        LoadingLawProblem::new(
            material,
            Period::Finite(q(1, 1)),
            PunchShape::Parabolic { k: q(1, 1) },
            law,
            size,
            convention,
        )
        .unwrap()
    }

    /// The polynomial-law path (n = N'(P2(eta)) evaluated along the loading) with N = n P2 + 0 P2^2
    /// equals the linear law; the given load is found back (normal_load = the P2 of a given
    /// half-length returns that half-length); N' < 0 is refused naming the law's key.
    #[test]
    #[ignore = "long tier: 15 s alone in the test profile (opt-level 2) on a loaded 2-core machine (scripts/test --long)"]
    fn polynomial_path_given_load_and_refusals() {
        let xh = [q(1, 3)];
        let lin = solve_law(
            &law_problem(LoadingLaw::Linear(q(1, 5)), LawSize::HalfLength(q(1, 6)), Convention::PeriodicSurface),
            &xh,
            8,
        )
        .unwrap();
        let poly = solve_law(
            &law_problem(
                LoadingLaw::Polynomial(vec![q(0, 1), q(1, 5), q(0, 1)]),
                LawSize::HalfLength(q(1, 6)),
                Convention::PeriodicSurface,
            ),
            &xh,
            8,
        )
        .unwrap();
        let rel = |a: &Float, b: &Float| Float::with_val(200, a - b).to_f64().abs() / b.to_f64().abs();
        assert!(rel(&poly.values.p2, &lin.values.p2) < 1e-10, "{} vs {}", poly.values.p2, lin.values.p2);
        assert!(rel(&poly.values.c, &lin.values.c) < 1e-10);
        assert!(rel(&lin.values.p1, &Float::with_val(200, &lin.values.p2 / 5u32)) < 1e-10);
        // Given load: the P2 of l = 1/6 (as an exact decimal of 30 digits) returns l and c.
        let p2 = exact_of(&lin.values.p2, 120);
        let back = solve_law(
            &law_problem(LoadingLaw::Linear(q(1, 5)), LawSize::NormalLoad(p2), Convention::PeriodicSurface),
            &xh,
            8,
        )
        .unwrap();
        eprintln!(
            "given load: l = {} (1/6), c = {} vs {}, digits {:?}",
            back.values.l, back.values.c, lin.values.c, back.digits
        );
        assert!((back.values.l.to_f64() - 1.0 / 6.0).abs() < 1e-9);
        assert!(rel(&back.values.c, &lin.values.c) < 1e-7);
        assert!(back.digits.headline >= 8.0, "{:?}", back.digits);
        // N' < 0.
        let e = solve_law(
            &law_problem(LoadingLaw::Linear(q(-1, 5)), LawSize::HalfLength(q(1, 6)), Convention::Paper),
            &xh,
            10,
        )
        .unwrap_err();
        let AdhesionError::Model(m) = &e else { panic!("{e}") };
        assert_eq!((m.parameter.as_str(), m.value.as_str()), ("tangential_ratio", "-1/5"), "{e}");
    }

    fn single(nu: Exact, n: Exact, size: LawSize) -> LoadingLawProblem {
        let material = Material::from_contact_modulus(nu, q(3, 2)).unwrap();
        let shape = PunchShape::Parabolic { k: q(1, 2) };
        LoadingLawProblem::new(material, Period::Infinite, shape, LoadingLaw::Linear(n), size, Convention::Paper)
            .unwrap()
    }

    /// The single punch (period `inf`, [`Row::Single`]): n = 0 is the symmetric single punch
    /// (c = 0, P2 = C_P E* k l^2, C_P = pi/(2 (1 - 2 eps S)), docs/theory.md 5); at nu = 1/2 Hertz
    /// (P2 = pi E* k l^2/2, c = 0) with q1 = n q2; n = 1/5 at nu = 0.3 is self-similar (c/l,
    /// P2/l^2, psi/(k l), q/(E* k l) the same at l = 1/2 and l = 3), its given load is found back,
    /// and the periodic row tends to it like Lambda^2 (c/l at L = 40 and 80, l = 1: the
    /// differences' ratio is 4 within 1%).
    #[test]
    #[ignore = "long tier: 15 s alone in the test profile (opt-level 2) on a loaded 2-core machine (scripts/test --long)"]
    fn single_punch_limits_and_self_similarity() {
        let xh = [q(-3, 5), q(1, 4)];
        let digits = 16;
        let rel = |a: &Float, b: &Float, scale: f64| Float::with_val(200, a - b).to_f64().abs() / scale;
        // n = 0.
        let sym = solve_law(&single(q(3, 10), q(0, 1), LawSize::HalfLength(q(2, 3))), &xh, digits).unwrap();
        let material = Material::from_contact_modulus(q(3, 10), q(3, 2)).unwrap();
        let cp = crate::params::adhesion::AdhesionParamsMpfr::new(&material, 200).load_constant;
        let hertz_like = Float::with_val(200, &cp * 3u32) / 4u32 * 4u32 / 9u32; // C_P (3/2)(1/2)(2/3)^2
        assert!(sym.digits.headline >= digits as f64, "{:?}", sym.digits);
        assert!(rel(&sym.values.p2, &hertz_like, hertz_like.to_f64()) < 1e-16, "{} vs {}", sym.values.p2, hertz_like);
        assert!(sym.values.c.to_f64().abs() < 1e-16);
        // nu = 1/2.
        let half = solve_law(&single(q(1, 2), q(1, 5), LawSize::HalfLength(q(2, 3))), &xh, digits).unwrap();
        let hertz = Float::with_val(200, Constant::Pi) * 3u32 / 4u32 * 4u32 / 9u32 / 2u32;
        assert!(rel(&half.values.p2, &hertz, hertz.to_f64()) < 1e-16, "{} vs {}", half.values.p2, hertz);
        assert!(half.values.c.to_f64().abs() < 1e-16);
        for p in &half.values.points {
            assert!(rel(&p.q1, &Float::with_val(200, &p.q2 / 5u32), 1.0) < 1e-16);
        }
        // Self-similar at n = 1/5.
        let small = solve_law(&single(q(3, 10), q(1, 5), LawSize::HalfLength(q(1, 2))), &xh, digits).unwrap();
        let big = solve_law(&single(q(3, 10), q(1, 5), LawSize::HalfLength(q(3, 1))), &xh, digits).unwrap();
        let ratio = |v: &LawValues| Float::with_val(200, &v.c / &v.l);
        let (us, ub) = (&small.values, &big.values);
        eprintln!(
            "single punch n = 1/5: c/l = {}, P2/l^2 = {}, digits {:?}",
            ratio(us),
            Float::with_val(200, &us.p2 / Float::with_val(200, us.l.square_ref())),
            small.digits
        );
        assert!(small.digits.headline >= digits as f64 && big.digits.headline >= digits as f64);
        assert!(rel(&ratio(us), &ratio(ub), 1.0) < 1e-16);
        let load = |v: &LawValues| Float::with_val(200, &v.p2 / Float::with_val(200, v.l.square_ref()));
        assert!(rel(&load(us), &load(ub), load(ub).to_f64()) < 1e-16);
        for (p, r) in us.points.iter().zip(&ub.points) {
            // psi ~ k l, q ~ E* k l: the big punch's values are 6 times the small one's.
            assert!(rel(&Float::with_val(200, &p.psi * 6u32), &r.psi, r.psi.to_f64().abs()) < 1e-15);
            assert!(rel(&Float::with_val(200, &p.q2 * 6u32), &r.q2, r.q2.to_f64().abs()) < 1e-15);
            assert!(rel(&Float::with_val(200, &p.q1 * 6u32), &r.q1, r.q1.to_f64().abs()) < 1e-15);
        }
        // Given load.
        let p2 = exact_of(&ub.p2, 120);
        let back = solve_law(&single(q(3, 10), q(1, 5), LawSize::NormalLoad(p2)), &xh, digits).unwrap();
        assert!(rel(&back.values.l, &ub.l, 3.0) < 1e-16, "{}", back.values.l);
        // The periodic row tends to the single punch like Lambda^2.
        let row = |big_l: i64| {
            let material = Material::from_contact_modulus(q(3, 10), q(3, 2)).unwrap();
            let p = LoadingLawProblem::new(
                material,
                Period::Finite(q(big_l, 1)),
                PunchShape::Parabolic { k: q(1, 2) },
                LoadingLaw::Linear(q(1, 5)),
                LawSize::HalfLength(q(1, 1)),
                Convention::Paper,
            )
            .unwrap();
            let v = solve_law(&p, &[], digits).unwrap().values;
            Float::with_val(200, &v.c / &v.l)
        };
        let (d40, d80) = (Float::with_val(200, row(40) - ratio(us)), Float::with_val(200, row(80) - ratio(us)));
        let r = d40.to_f64() / d80.to_f64();
        eprintln!("c/l - single: L = 40 {d40:.3e}, L = 80 {d80:.3e}, ratio {r}");
        assert!((r - 4.0).abs() < 0.04, "{r}");
    }

    /// The loading path is the restriction of the solution to smaller contacts (the Volterra
    /// structure): the path point l_8 = l/2 of the solve at l = 1/6 (paper, n = 1/5, nu = 0.3)
    /// equals an independent solve at l = 1/12 (its own collocation on [0, Lambda/2]) to the
    /// digits both claim; the profile stresses equal the points' q1, q2 at the same xh.
    #[test]
    fn loading_path_is_the_solution_at_smaller_contacts() {
        let problem = |l: Exact| law_problem(LoadingLaw::Linear(q(1, 5)), LawSize::HalfLength(l), Convention::Paper);
        let t = std::time::Instant::now();
        let full = solve_law_sampled(&problem(q(1, 6)), &[q(1, 2)], &[q(-9, 10), q(1, 2)], 8).unwrap();
        let half = solve_law(&problem(q(1, 12)), &[], 8).unwrap();
        eprintln!("{:.1}s, digits {:?} and {:?}", t.elapsed().as_secs_f64(), full.digits, half.digits);
        assert!(full.digits.path >= 8.0 && full.digits.stresses >= 8.0, "{:?}", full.digits);
        let p = &full.values.path[7];
        let h = &half.values;
        let d = full.digits.path.min(half.digits.ends).min(half.digits.loads) - 0.5;
        let close = |x: &Float, y: &Float, scale: &Float, what: &str| {
            let e = Float::with_val(200, x - y).to_f64().abs() / scale.to_f64().abs();
            eprintln!("{what}: {x} vs {y}: {e:.1e}");
            assert!(e < 10f64.powf(-d), "{what}: {x} vs {y}: {e:e}");
        };
        close(&p.l, &h.l, &h.l, "l");
        close(&p.a, &h.a, &h.l, "a");
        close(&p.b, &h.b, &h.l, "b");
        close(&p.c, &h.c, &h.l, "c");
        close(&p.p2, &h.p2, &h.p2, "P2");
        close(&p.p1, &h.p1, &h.p2, "P1");
        // The path is not trivially proportional: c_j/l_j varies along the loading.
        let ratio = |p: &LawPathPoint| Float::with_val(200, &p.c / &p.l).to_f64();
        assert!((ratio(&full.values.path[0]) - ratio(p)).abs() > 1e-4);
        let (s, pt) = (&full.values.stresses[1], &full.values.points[0]);
        assert_eq!((&s.xh, &s.q1, &s.q2, &s.x), (&pt.xh, &pt.q1, &pt.q2, &pt.x));
    }
}
