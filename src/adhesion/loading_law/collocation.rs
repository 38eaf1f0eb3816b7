//! The MPFR method for Problem 2 under a linear loading law P1 = n P2 (docs/theory.md section 10,
//! `paper` convention): the two moving-edge conditions as a nonlinear system of Volterra
//! equations in the contact size, solved by Chebyshev collocation and a chord-Newton iteration.
//!
//! Variables: lambda = pi l/L (l = (a + b)/2, the loading parameter), gamma = pi c/L
//! (c = (b - a)/2), P2 = E* k (L/pi)^2 P(lambda), dP = (1 + i n) dP2. Every earlier contact
//! (eta < lambda, centre gamma(eta)) carried the increment dP(eta) and left on the surface outside
//! it (E*/2)(dv' - i du') = dP K/L ([`super::kernel::outside_kernel`]). A point enters contact
//! with the punch's slope, at the leading end chi_b = gamma(lambda) + lambda and at the trailing
//! end chi_a = gamma(lambda) - lambda:
//!   Re int_0^lambda (1 + i n) P'(eta) K(chi_e - gamma(eta), eta) d eta = G(chi_e),
//!   G(chi) = pi^2 g'(L chi/pi)/(2 k L)   (the parabola: G = pi chi; section 4's equation when
//!   n = 0 and gamma = 0).
//! Unknowns on [0, Lambda] (Lambda the final size), t = eta/Lambda: P'(eta) = eta Phi(t) and
//! gamma(eta) = eta Gam(t), both interpolated at N Chebyshev nodes of t (values as unknowns).
//! With eta = lambda s the distance to the nearer end is
//!   d = lambda (1 - s) (1 +- E),  E = Gam(t) + s t [Gam(t) - Gam(s t)]/(t - s t),
//! (+ leading, - trailing), formed from the divided difference so that it keeps its accuracy as
//! s -> 1 (tanh-sinh in s with the complement 1 - s). Both ends must advance: 1 +- E > 0.
//! Each equation is divided by lambda (both sides are O(lambda)).
//! Newton: the closed-form Jacobian (`super::jacobian`) at 64 bits with a coarse rule (one pass
//! over nodes and rule; the finite-difference Jacobian it replaced took 2N + 1 residuals and was
//! 4x slower overall: the shipped scene's 20-digit solve 74 s -> 19 s CPU, same output), then
//! chord steps at the working precision (each step's correction J^-1 R in `f64`: only its own leading digits
//! matter), until the correction falls below 2^-(target bits).

use super::kernel::{outside_kernel, Row, Side, TiltedPunch};
use crate::adhesion::error::AdhesionError;
use crate::model::{Convention, Exact, LoadingLaw, Material};
use crate::numerics::chebyshev;
use crate::numerics::exact::to_float;
use crate::numerics::tanh_sinh::TanhSinh;
use crate::params::adhesion::{AdhesionParamsF64, AdhesionParamsMpfr};
use rug::float::Constant;
use rug::{Complex, Float};

/// What the collocation needs besides the unknowns: exact inputs, rounded once per precision.
#[derive(Debug, Clone)]
pub struct LawSetting {
    /// The half-plane's material (eps and C_P are derived at each precision).
    pub material: Material,
    /// The law P1 = N(P2).
    pub law: LoadingLaw,
    /// E* k L^2: P2 = (E* k L^2/pi^2) P (periodic); E* k U^2 for the single punch in the length
    /// unit U (P2 = E* k U^2 P, [`Row::Single`]).
    pub load_scale: Exact,
    /// l/L at the final size, exact (Lambda = pi l/L); l/U for the single punch (Lambda = l/U).
    pub size_over_period: Exact,
    /// Periodic row or single punch ([`Row`]).
    pub row: Row,
    /// The surface convention (docs/theory.md section 8): `periodic` adds the tilted punch's increment
    /// ([`super::kernel::TiltedPunch`]).
    pub convention: Convention,
}

impl LawSetting {
    /// The linear law n with E* k L^2 = 1 (tests and the dimensionless problem).
    pub fn linear(material: Material, n: Exact, size_over_period: Exact, convention: Convention) -> Self {
        LawSetting {
            material,
            law: LoadingLaw::Linear(n),
            load_scale: Exact::from_integer(1.into()),
            size_over_period,
            row: Row::Periodic,
            convention,
        }
    }

    /// Lambda at `prec` bits: pi l/L, or l/U for the single punch.
    pub fn lambda_max(&self, prec: u32) -> Float {
        match self.row {
            Row::Periodic => to_float(&self.size_over_period, prec) * Float::with_val(prec, Constant::Pi),
            Row::Single => to_float(&self.size_over_period, prec),
        }
    }
}

/// The material and law constants every increment needs, at one precision.
#[derive(Debug, Clone)]
pub struct Increment {
    /// eps.
    pub eps: Float,
    /// cosh(pi eps).
    pub cosh_pi_eps: Float,
    /// beta.
    pub beta: Float,
    /// N'(P2) coefficients (numpy order, in powers of P2).
    pub slope: Vec<Float>,
    /// N(P2) coefficients.
    pub law: Vec<Float>,
    /// E* k L^2/pi^2 (P2 per unit P).
    pub p2_per_p: Float,
    /// Whether the `periodic` convention's rotation increment is added (never for the single
    /// punch: the rotation -beta P1/L vanishes as L -> infinity).
    pub periodic: bool,
    /// Periodic row or single punch.
    pub row: Row,
}

impl Increment {
    /// From the setting at `prec` bits.
    pub fn new(setting: &LawSetting, prec: u32) -> Self {
        let constants = AdhesionParamsMpfr::new(&setting.material, prec);
        let pi2 = match setting.row {
            Row::Periodic => Float::with_val(prec, Constant::Pi).square(),
            Row::Single => Float::with_val(prec, 1),
        };
        let law = match &setting.law {
            LoadingLaw::Linear(n) => vec![Exact::from_integer(0.into()), n.clone()],
            LoadingLaw::Polynomial(c) => c.clone(),
        };
        Increment {
            eps: constants.eps,
            cosh_pi_eps: constants.cosh_pi_eps,
            beta: constants.beta,
            slope: setting.law.derivative().iter().map(|c| to_float(c, prec)).collect(),
            law: law.iter().map(|c| to_float(c, prec)).collect(),
            p2_per_p: to_float(&setting.load_scale, prec) / pi2,
            periodic: setting.convention == Convention::PeriodicSurface && setting.row == Row::Periodic,
            row: setting.row,
        }
    }
    /// Whether n = N' is constant along the loading (linear law).
    pub fn constant_ratio(&self) -> bool {
        self.slope.len() <= 1
    }
    /// n = N'(P2) at P2 = p2_per_p `p`.
    pub fn ratio_at(&self, p: &Float) -> Float {
        let prec = p.prec();
        let p2 = Float::with_val(prec, p * &self.p2_per_p);
        self.slope.iter().rev().fold(Float::with_val(prec, 0), |acc, c| acc * &p2 + c)
    }
    /// N(P2) at P2 = p2_per_p `p`, in units of p2_per_p (i.e. P1/p2_per_p).
    pub fn law_at(&self, p: &Float) -> Float {
        let prec = p.prec();
        let p2 = Float::with_val(prec, p * &self.p2_per_p);
        self.law.iter().rev().fold(Float::with_val(prec, 0), |acc, c| acc * &p2 + c) / &self.p2_per_p
    }
}

/// Chebyshev coefficients of t Phi(t) (t = (x + 1)/2, x T_j = (T_(j+1) + T_|j-1|)/2) from those
/// of Phi: P(Lambda t) = Lambda^2 int_0^t t' Phi(t') dt'.
pub(super) fn times_t(phi: &[Float], prec: u32) -> Vec<Float> {
    let n = phi.len();
    let mut x_phi = vec![Float::with_val(prec, 0); n + 1];
    for (j, c) in phi.iter().enumerate() {
        if j == 0 {
            x_phi[1] += c;
        } else {
            let h = Float::with_val(prec, c / 2u32);
            x_phi[j + 1] += &h;
            x_phi[j - 1] += &h;
        }
    }
    for (j, c) in phi.iter().enumerate() {
        x_phi[j] += c;
    }
    x_phi.into_iter().map(|v| v / 2u32).collect()
}

/// Working data of one precision.
struct Ctx {
    prec: u32,
    inc: Increment,
    lambda_max: Float,
    nodes: Vec<Float>,
    rule: TanhSinh,
}

impl Ctx {
    fn new(setting: &LawSetting, nodes: usize, rule_bits: u32, prec: u32) -> Self {
        Ctx {
            prec,
            inc: Increment::new(setting, prec),
            lambda_max: setting.lambda_max(prec),
            nodes: chebyshev::nodes(nodes, prec),
            rule: TanhSinh::new(rule_bits, 1.0, prec),
        }
    }
}

/// sum_j c_j [T_j(x) - T_j(y)]/(x - y) by the recurrence d_(j+1) = 2 x d_j + 2 T_j(y) - d_(j-1)
/// (d_0 = 0, d_1 = 1): accurate as y -> x.
pub(super) fn divided_difference(c: &[Float], x: &Float, y: &Float, prec: u32) -> Float {
    let mut acc = Float::with_val(prec, 0);
    let (mut d_prev, mut d) = (Float::with_val(prec, 0), Float::with_val(prec, 1));
    let (mut t_prev, mut t) = (Float::with_val(prec, 1), y.clone());
    for cj in c.iter().skip(1) {
        acc += Float::with_val(prec, cj * &d);
        // d_(j+1) and T_(j+1)(y).
        let d_next = Float::with_val(prec, x * &d) * 2u32 + Float::with_val(prec, &t * 2u32) - &d_prev;
        let t_next = Float::with_val(prec, y * &t) * 2u32 - &t_prev;
        d_prev = std::mem::replace(&mut d, d_next);
        t_prev = std::mem::replace(&mut t, t_next);
    }
    acc
}

/// int_0^lambda P'(eta) [(1 + i n) L K(chi_e - gamma(eta), eta) - beta n R(chi_e; eta)] d eta at
/// lambda = Lambda t for the leading (chi_e = gamma + lambda) and the trailing
/// (chi_e = gamma - lambda) end, from the Chebyshev coefficients of Phi and Gam (module doc), on
/// `rule`; R = Z(t)(A + B t)/cosh(pi eps) is the tilted punch's slope outside
/// ([`super::kernel::TiltedPunch::outside`], `periodic` only; its constant f = 1 cancels against
/// the -beta P1/L of the edge condition).
///
/// Both ends when `only` is `None`; with `Some(side)` the kernels of that end only (the other
/// end's integral is then zero; its advance factor is still checked, so the errors are the same):
/// the fields need one end per point ([`super::fields`]' psi_hat), and the kernels are the cost.
#[allow(clippy::too_many_arguments)]
pub(super) fn edge_integrals(
    rule: &TanhSinh,
    inc: &Increment,
    lambda_max: &Float,
    phi_c: &[Float],
    gam_c: &[Float],
    t: &Float,
    prec: u32,
    only: Option<Side>,
) -> Result<(Complex, Complex), AdhesionError> {
    let at = |c: &[Float], t: &Float| chebyshev::evaluate(c, &(Float::with_val(prec, t * 2u32) - 1u32), prec);
    let lambda = Float::with_val(prec, lambda_max * t);
    let gam_t = at(gam_c, t);
    let (mut acc_b, mut acc_a) = (Complex::new(prec), Complex::new(prec));
    let xt = Float::with_val(prec, t * 2u32) - 1u32;
    let tphi = (!inc.constant_ratio()).then(|| times_t(phi_c, prec));
    let l2max = Float::with_val(prec, lambda_max.square_ref());
    let n_const = inc.ratio_at(&Float::with_val(prec, 0));
    for q in 0..rule.len() {
        let (s, c, w) = (&rule.s[q], &rule.c[q], &rule.w[q]);
        let ts = Float::with_val(prec, t * s);
        let eta = Float::with_val(prec, &lambda * s);
        let phi = at(phi_c, &ts);
        // E = Gam(t) + s t DGam(t, s t); DGam in t is twice the divided difference in x.
        let xs = Float::with_val(prec, &ts * 2u32) - 1u32;
        let dd = divided_difference(gam_c, &xt, &xs, prec) * 2u32;
        let e = Float::with_val(prec, &gam_t + Float::with_val(prec, &ts * &dd));
        let base = Float::with_val(prec, &lambda * c);
        let weight = Float::with_val(prec, w * s) * &phi;
        // n = N'(P2(eta)) (constant for the linear law).
        let n = match &tphi {
            Some(tp) => inc.ratio_at(&(chebyshev::integral(tp, &ts, prec) * &l2max)),
            None => n_const.clone(),
        };
        let one_in = Complex::with_val(prec, (1, &n));
        let beta_n = Float::with_val(prec, &inc.beta * &n);
        // The tilted punch depends on eta only: once for both ends.
        let tilt = inc.periodic.then(|| TiltedPunch::rotation(&eta, &inc.eps, &inc.cosh_pi_eps, prec));
        for (side, sign, acc) in [(Side::Right, 1i32, &mut acc_b), (Side::Left, -1, &mut acc_a)] {
            let factor = advance_factor(&e, sign, &lambda)?;
            if only.is_some_and(|o| o != side) {
                continue;
            }
            let d = Float::with_val(prec, &base * &factor);
            let mut k = outside_kernel(inc.row, side, &d, &eta, &inc.eps, prec) * &one_in;
            if let Some(tilt) = &tilt {
                k -= tilt.outside(side, &d, &eta, &inc.eps, &inc.cosh_pi_eps, prec) * &beta_n;
            }
            *acc += k * &weight;
        }
    }
    // int_0^lambda P' K d eta = lambda^2 int_0^1 s Phi(t s) K ds.
    let l2 = Float::with_val(prec, lambda.square_ref());
    Ok((acc_b * &l2, acc_a * &l2))
}

/// 1 +- E, the rate at which the leading (`sign` = 1) or trailing (-1) end advances relative to
/// the half-length; an error when it does not (the contact must grow at both ends).
pub(super) fn advance_factor(e: &Float, sign: i32, lambda: &Float) -> Result<Float, AdhesionError> {
    let factor = Float::with_val(e.prec(), e * sign) + 1u32;
    if factor > 0 {
        return Ok(factor);
    }
    Err(AdhesionError::NotConverged {
        what: "loading-law collocation",
        reason: format!(
            "the {} end recedes at lambda = {:.4} (the contact must grow at both ends)",
            if sign > 0 { "leading" } else { "trailing" },
            lambda.to_f64()
        ),
    })
}

/// The residuals (2 per node: leading, trailing) of the state (Phi values, then Gam values),
/// each divided by lambda.
fn residual(ctx: &Ctx, state: &[Float]) -> Result<Vec<Float>, AdhesionError> {
    let prec = ctx.prec;
    let n_nodes = ctx.nodes.len();
    let phi_c = chebyshev::coefficients(&state[..n_nodes], prec);
    let gam_c = chebyshev::coefficients(&state[n_nodes..], prec);
    let pi = Float::with_val(prec, Constant::Pi);
    let mut out = Vec::with_capacity(2 * n_nodes);
    for t in &ctx.nodes {
        let lambda = Float::with_val(prec, &ctx.lambda_max * t);
        let gam_t = chebyshev::evaluate(&gam_c, &(Float::with_val(prec, t * 2u32) - 1u32), prec);
        let (acc_b, acc_a) = edge_integrals(&ctx.rule, &ctx.inc, &ctx.lambda_max, &phi_c, &gam_c, t, prec, None)?;
        for (acc, sign) in [(acc_b, 1i32), (acc_a, -1)] {
            let v = acc.real().clone() / &lambda;
            // G(chi_e)/lambda = pi (Gam(t) +- 1) for the parabola.
            let g = Float::with_val(prec, &gam_t + sign) * &pi;
            out.push(v - g);
        }
    }
    Ok(out)
}

/// The solution of the collocation: Phi and Gam values at the nodes and their Chebyshev
/// coefficients.
#[derive(Debug, Clone)]
pub struct LawCollocation {
    /// Working precision.
    pub prec: u32,
    /// Lambda.
    pub lambda_max: Float,
    /// Chebyshev coefficients of Phi(t), P'(eta) = eta Phi(eta/Lambda).
    pub phi: Vec<Float>,
    /// Chebyshev coefficients of Gam(t), gamma(eta) = eta Gam(eta/Lambda).
    pub gam: Vec<Float>,
    /// Chebyshev coefficients of t Phi(t) ([`times_t`]), for the load along the loading.
    t_phi: Vec<Float>,
    /// The material and law constants at `prec`.
    pub inc: Increment,
    /// Largest |residual| at the last step.
    pub residual: f64,
    /// Chord steps taken.
    pub steps: usize,
}

impl LawCollocation {
    /// P(Lambda t) = int_0^(Lambda t) eta Phi(eta/Lambda) d eta = Lambda^2 int_0^t t' Phi(t') dt'
    /// (P2 = E* k (L/pi)^2 P), by the Chebyshev integral of t Phi (`times_t`).
    pub fn load_at(&self, t: &Float) -> Float {
        let prec = self.prec;
        chebyshev::integral(&self.t_phi, t, prec) * Float::with_val(prec, self.lambda_max.square_ref())
    }
    /// P(Lambda), the final load in units of E* k (L/pi)^2.
    pub fn load(&self) -> Float {
        self.load_at(&Float::with_val(self.prec, 1))
    }
    /// gamma(Lambda)/Lambda = c/l.
    pub fn centre_ratio(&self) -> Float {
        chebyshev::evaluate(&self.gam, &Float::with_val(self.prec, 1), self.prec)
    }
}

/// Solves with `nodes` Chebyshev nodes at `prec` bits for 2^-`target_bits`.
pub fn solve(setting: &LawSetting, nodes: usize, target_bits: u32, prec: u32) -> Result<LawCollocation, AdhesionError> {
    solve_from(setting, nodes, target_bits, prec, None)
}

/// [`solve`], its Newton iteration started from `start` (Phi and Gam of another collocation of
/// the same problem, e.g. a coarser run, interpolated to these nodes) instead of the symmetric
/// single punch. The iteration still runs to 2^-`target_bits` on its own discretisation: the
/// start changes the path, not the point it converges to. If it fails from `start`, it is run
/// again from the single punch.
pub fn solve_from(
    setting: &LawSetting,
    nodes: usize,
    target_bits: u32,
    prec: u32,
    start: Option<&LawCollocation>,
) -> Result<LawCollocation, AdhesionError> {
    // From the single punch (Phi = 2 C_P, Gam = 0): Newton at 64 bits on a coarse rule to a first
    // solution, with the closed-form Jacobian ([`super::jacobian`]) refreshed at every step while
    // the correction exceeds 1e-8, then kept (chord) at `prec`. From `start`: its Phi and Gam at
    // these nodes at `prec` bits, the Jacobian there, and the chord iteration at once (the 64-bit
    // Newton would move a start closer than its coarse rule's accuracy away from the solution).
    let low = Ctx::new(setting, nodes, 50, 64);
    let warm: Option<Vec<Float>> = start.map(|s| {
        let taus = chebyshev::nodes(nodes, prec);
        let at = |c: &[Float], tau: &Float| chebyshev::evaluate(c, &(Float::with_val(prec, tau * 2u32) - 1u32), prec);
        let phi: Vec<Float> = taus.iter().map(|t| at(&s.phi, t)).collect();
        phi.into_iter().chain(taus.iter().map(|t| at(&s.gam, t))).collect()
    });
    let state64: Vec<Float> = match &warm {
        Some(w) => w.iter().map(|v| Float::with_val(64, v)).collect(),
        None => {
            let load_constant = AdhesionParamsF64::new(&setting.material).load_constant;
            (0..2 * nodes).map(|i| Float::with_val(64, if i < nodes { 2.0 * load_constant } else { 0.0 })).collect()
        }
    };
    let warm_start = warm.is_some();
    match solve_with(setting, &low, state64, warm, nodes, target_bits, prec) {
        Err(_) if warm_start => solve_from(setting, nodes, target_bits, prec, None),
        r => r,
    }
}

/// The iteration of [`solve_from`] from `state64` (and `warm` at `prec`, if given: no 64-bit
/// Newton then).
fn solve_with(
    setting: &LawSetting,
    low: &Ctx,
    mut state64: Vec<Float>,
    warm: Option<Vec<Float>>,
    nodes: usize,
    target_bits: u32,
    prec: u32,
) -> Result<LawCollocation, AdhesionError> {
    let closed_form = |ctx: &Ctx, state: &[Float]| {
        super::jacobian::jacobian(&ctx.rule, &ctx.inc, &ctx.lambda_max, &ctx.nodes, state, ctx.prec)
    };
    let mut jac = closed_form(low, &state64)?;
    if warm.is_none() {
        let mut previous = f64::INFINITY;
        for _ in 0..30 {
            let r = residual(low, &state64)?;
            let delta = solve_f64(&jac, &r.iter().map(|v| v.to_f64()).collect::<Vec<_>>())?;
            let size = delta.iter().fold(0f64, |m, v| m.max(v.abs()));
            for (x, d) in state64.iter_mut().zip(&delta) {
                *x -= *d;
            }
            if size < 1e-13 {
                break;
            }
            if size > 1e-8 || size > 1e-3 * previous {
                jac = closed_form(low, &state64)?;
            }
            previous = size;
        }
    }
    let ctx = Ctx::new(setting, nodes, target_bits + 8, prec);
    let mut state: Vec<Float> = warm.unwrap_or_else(|| state64.iter().map(|v| Float::with_val(prec, v)).collect());
    let goal = 2f64.powi(-(target_bits as i32));
    let mut steps = 0;
    let mut last = f64::INFINITY;
    for _ in 0..40 {
        steps += 1;
        let r = residual(&ctx, &state)?;
        last = r.iter().fold(0f64, |m, v| m.max(v.to_f64().abs()));
        let delta = solve_f64(&jac, &r.iter().map(|v| v.to_f64()).collect::<Vec<_>>())?;
        let size = delta.iter().fold(0f64, |m, v| m.max(v.abs()));
        for (x, d) in state.iter_mut().zip(&delta) {
            *x -= *d;
        }
        if size < goal {
            let lambda_max = Float::with_val(prec, &ctx.lambda_max);
            let phi = chebyshev::coefficients(&state[..nodes], prec);
            return Ok(LawCollocation {
                prec,
                lambda_max,
                inc: ctx.inc.clone(),
                t_phi: times_t(&phi, prec),
                phi,
                gam: chebyshev::coefficients(&state[nodes..], prec),
                residual: last,
                steps,
            });
        }
    }
    Err(AdhesionError::NotConverged {
        what: "loading-law chord iteration",
        reason: format!("40 steps, residual {last:.1e}"),
    })
}

/// J x = r in `f64` (LU with partial pivoting, nalgebra).
fn solve_f64(jac: &[Vec<f64>], r: &[f64]) -> Result<Vec<f64>, AdhesionError> {
    let m = r.len();
    let a = nalgebra::DMatrix::from_fn(m, m, |i, j| jac[i][j]);
    let b = nalgebra::DVector::from_column_slice(r);
    a.lu()
        .solve(&b)
        .map(|x| x.iter().copied().collect())
        .ok_or(AdhesionError::NotConverged { what: "loading-law Newton", reason: "singular Jacobian".into() })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::adhesion::volterra_mpfr::{solve as volterra_solve, VolterraParams};
    use crate::model::{Convention, Exact, LoadingLaw, Material};
    use crate::params::adhesion::AdhesionParamsMpfr;

    fn material(nu: (i64, i64)) -> Material {
        Material::from_contact_modulus(Exact::new(nu.0.into(), nu.1.into()), Exact::from_integer(1.into())).unwrap()
    }

    /// n = 0: the symmetric problem of section 4 (gamma = 0, the same load as the Volterra
    /// method's at 30 digits). The error is the collocation's: 16 nodes 1.3e-18, 24 nodes 1.2e-26,
    /// 32 nodes 1.3e-34 at Lambda = 0.5, nu = 0.3 (`LAW_NODES=24 cargo test --release --lib
    /// loading_law::collocation::tests::zero -- --nocapture`).
    #[test]
    fn zero_ratio_is_the_symmetric_solution() {
        let m = material((3, 10));
        // l/L = 100000/628318, Lambda = pi l/L = 0.49999...
        let size = Exact::new(100000.into(), 628318.into());
        let setting = LawSetting::linear(m.clone(), Exact::from_integer(0.into()), size, Convention::Paper);
        let t = std::time::Instant::now();
        let nodes: usize = std::env::var("LAW_NODES").ok().and_then(|v| v.parse().ok()).unwrap_or(16);
        let sol = solve(&setting, nodes, 100, 140).unwrap();
        eprintln!("{:.2}s, {} steps, residual {:.1e}", t.elapsed().as_secs_f64(), sol.steps, sol.residual);
        let params = VolterraParams::for_digits(30);
        let constants = AdhesionParamsMpfr::new(&m, params.prec);
        let lam = Float::with_val(params.prec, &sol.lambda_max);
        let sym = volterra_solve(&constants, &lam, params).unwrap();
        let p_sym = sym.load_ratio() * Float::with_val(params.prec, lam.square_ref());
        let p = sol.load();
        let rel = Float::with_val(140, &p - &p_sym).to_f64() / p_sym.to_f64();
        eprintln!("P = {} vs {}: rel {rel:.1e}; c/l = {:.1e}", p.to_f64(), p_sym.to_f64(), sol.centre_ratio().to_f64());
        let tol = [(16, 1e-17), (24, 1e-25), (32, 1e-33)].iter().find(|(n, _)| *n == nodes).map_or(1e-17, |v| v.1);
        assert!(rel.abs() < tol, "{rel:e}");
        assert!(sol.centre_ratio().abs().to_f64() < 1e-25);
    }

    /// nu = 1/2 (eps = 0, beta = 0): normal and tangential problems decouple, so for any n the
    /// contact stays centred and P is Kuznetsov's 2 C_P ln sec(Lambda) = pi ln sec(Lambda).
    #[test]
    fn nu_half_decouples() {
        let setting = LawSetting::linear(
            material((1, 2)),
            Exact::new(1.into(), 2.into()),
            Exact::new(1.into(), 5.into()),
            Convention::Paper,
        );
        let sol = solve(&setting, 16, 100, 140).unwrap();
        let lam = Float::with_val(140, &sol.lambda_max);
        let want = Float::with_val(140, lam.cos_ref()).recip().ln() * Float::with_val(140, Constant::Pi);
        let rel = Float::with_val(140, sol.load() - &want).to_f64() / want.to_f64();
        eprintln!("nu = 1/2, n = 1/2: P rel {rel:.1e}, c/l {:.1e}", sol.centre_ratio().to_f64());
        assert!(rel.abs() < 1e-17, "{rel:e}");
        assert!(sol.centre_ratio().abs().to_f64() < 1e-25);
    }

    /// n = 1/5, nu = 0.3, l/L = 1/6, the paper's convention: a loading law that shifts the contact.
    fn shifted_setting() -> LawSetting {
        LawSetting::linear(
            material((3, 10)),
            Exact::new(1.into(), 5.into()),
            Exact::new(1.into(), 6.into()),
            Convention::Paper,
        )
    }

    /// n = 1/5 at nu = 0.3: the contact shifts (c != 0) and the load differs from the symmetric
    /// one; printed for inspection.
    #[test]
    fn tangential_ratio_shifts_the_contact() {
        let setting = shifted_setting();
        let t = std::time::Instant::now();
        let sol = solve(&setting, 16, 100, 140).unwrap();
        eprintln!(
            "{:.2}s, {} steps, residual {:.1e}: P = {}, c/l = {}",
            t.elapsed().as_secs_f64(),
            sol.steps,
            sol.residual,
            sol.load().to_f64(),
            sol.centre_ratio().to_f64()
        );
        assert!(sol.centre_ratio().abs().to_f64() > 1e-4);
    }

    /// A warm start ([`solve_from`] from a coarser run, as the verified solve's second run starts
    /// from its first) converges to the cold start's solution: n = 1/5, nu = 0.3, l/L = 1/6, 24
    /// nodes from the 16-node solution; load, c/l and every Chebyshev coefficient of Phi and Gam
    /// within 2^-80 of the cold start's (the iterations stop below 2^-90).
    #[test]
    fn a_warm_start_reaches_the_cold_start_solution() {
        let setting = shifted_setting();
        let coarse = solve(&setting, 16, 90, 130).unwrap();
        let t = std::time::Instant::now();
        let cold = solve(&setting, 24, 90, 130).unwrap();
        let t_cold = t.elapsed().as_secs_f64();
        let t = std::time::Instant::now();
        let warm = solve_from(&setting, 24, 90, 130, Some(&coarse)).unwrap();
        eprintln!("cold {t_cold:.2}s, warm {:.2}s", t.elapsed().as_secs_f64());
        let tol = 2f64.powi(-80);
        let close = |a: &Float, b: &Float| Float::with_val(130, a - b).to_f64().abs() <= tol * (1.0 + b.to_f64().abs());
        assert!(close(&warm.load(), &cold.load()), "{} vs {}", warm.load(), cold.load());
        assert!(close(&warm.centre_ratio(), &cold.centre_ratio()));
        assert_eq!((warm.phi.len(), warm.gam.len()), (24, 24));
        for (a, b) in warm.phi.iter().zip(&cold.phi).chain(warm.gam.iter().zip(&cold.gam)) {
            assert!(close(a, b), "{a} vs {b}");
        }
    }

    /// The closed-form Jacobian ([`super::super::jacobian`]) equals central differences of the
    /// residual at 128 bits (step 1e-12: truncation ~1e-24) to 1e-12 relative at an asymmetric
    /// state (Phi, Gam not constant), in both conventions and for the single punch; for a
    /// polynomial law, whose n(P2) dependence the closed form leaves out, the difference is that
    /// term: 6.5e-5 against the largest entry 10.5 at N = P2/5 + P2^2/100, nu = 0, l/L = 1/5
    /// (`cargo test --release --lib closed_form_jacobian -- --nocapture`).
    #[test]
    fn closed_form_jacobian_equals_finite_differences() {
        let n = Exact::new(1.into(), 5.into());
        let poly =
            LoadingLaw::Polynomial(vec![Exact::from_integer(0.into()), n.clone(), Exact::new(1.into(), 100.into())]);
        let size = Exact::new(1.into(), 5.into());
        let mut cases = Vec::new();
        for convention in [Convention::Paper, Convention::PeriodicSurface] {
            cases.push((LawSetting::linear(material((3, 10)), n.clone(), size.clone(), convention), 1e-12));
        }
        let mut law = LawSetting::linear(material((0, 1)), n.clone(), size.clone(), Convention::PeriodicSurface);
        law.law = poly;
        cases.push((law, 1e-5));
        let mut single = LawSetting::linear(material((3, 10)), n, Exact::from_integer(1.into()), Convention::Paper);
        single.row = Row::Single;
        cases.push((single, 1e-12));
        let prec = 128;
        for (setting, tolerance) in cases {
            let nodes = 8;
            let ctx = Ctx::new(&setting, nodes, 50, prec);
            let state: Vec<Float> = (0..2 * nodes)
                .map(|i| {
                    let t = ctx.nodes[i % nodes].to_f64();
                    Float::with_val(prec, if i < nodes { 2.3 + 0.4 * t * t } else { -0.04 + 0.02 * t })
                })
                .collect();
            let h = 1e-12;
            let mut worst = 0f64;
            let exact =
                super::super::jacobian::jacobian(&ctx.rule, &ctx.inc, &ctx.lambda_max, &ctx.nodes, &state, prec)
                    .unwrap();
            let scale = exact.iter().flatten().fold(0f64, |m, v| m.max(v.abs()));
            for j in 0..2 * nodes {
                let (mut plus, mut minus) = (state.clone(), state.clone());
                plus[j] += h;
                minus[j] -= h;
                let (rp, rm) = (residual(&ctx, &plus).unwrap(), residual(&ctx, &minus).unwrap());
                for i in 0..2 * nodes {
                    let fd = Float::with_val(prec, &rp[i] - &rm[i]).to_f64() / (2.0 * h);
                    worst = worst.max((fd - exact[i][j]).abs());
                }
            }
            eprintln!(
                "{:?} {:?}: largest |J| {scale:.3}, largest difference {worst:.1e}",
                setting.row, setting.convention
            );
            assert!(worst < tolerance * scale, "{worst} of {scale}");
        }
    }
}
