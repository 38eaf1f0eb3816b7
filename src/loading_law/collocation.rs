//! The MPFR method for Problem 2 under a linear loading law P1 = n P2 (docs/theory.md section 10,
//! `paper` convention): the two moving-edge conditions as a nonlinear system of Volterra
//! equations in the contact size, solved by Chebyshev collocation and a chord-Newton iteration.
//!
//! Variables: lambda = pi l/L (l = (a + b)/2, the loading parameter), gamma = pi c/L
//! (c = (b - a)/2), P2 = E* k (L/pi)^2 P(lambda), dP = (1 + i n) dP2. Every earlier contact
//! (eta < lambda, centre gamma(eta)) carried the increment dP(eta) and left on the surface outside
//! it (E*/2)(dv' - i du') = dP K/L ([`crate::growing_contact::kernel::outside_kernel`]). A point enters contact
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
//! Newton: from the single punch, a 64-bit Newton on a coarse rule with the closed-form Jacobian
//! (`super::jacobian`, one pass over nodes and rule; the finite-difference Jacobian it replaced
//! took 2N + 1 residuals and was 4x slower overall: the shipped scene's 20-digit solve 74 s -> 19 s
//! CPU, same output), then chord steps at the working precision with the closed form in `f64` on
//! the working rule (each step's correction J^-1 R in `f64`: only its own leading digits matter),
//! until the correction falls below 2^-(target bits): two residuals a run on the shipped scene,
//! the second correction below the goal (under 2.4e-6 of the first; the 64-bit Jacobian of the
//! coarse rule used before contracted by only 0.06 and took a third residual). Where that chord
//! iteration fails or a correction is not below half the one before, the run is redone with the
//! 64-bit MPFR Jacobian of the coarse rule, in the Newton and the chord steps (nu = 0 near the
//! homogeneous mode needs it).

use super::increment::{advance_factor, divided_difference_series, size_terms, times_t, SizeTerms};
pub use super::increment::{Increment, LawSetting};
use super::jacobian::jacobian_f64;
use crate::growing_contact::error::AdhesionError;
use crate::growing_contact::kernel::Side;
use crate::numerics::chebyshev;
use crate::numerics::tanh_sinh::TanhSinh;
use crate::params::adhesion::AdhesionParamsF64;
use rug::float::Constant;
use rug::{Assign, Complex, Float};

/// Working data of one precision.
struct Ctx {
    prec: u32,
    inc: Increment,
    lambda_max: Float,
    nodes: Vec<Float>,
    rule: TanhSinh,
    /// [`size_terms`] of the nodes and the rule.
    sizes: Vec<Vec<SizeTerms>>,
}

impl Ctx {
    fn new(setting: &LawSetting, nodes: usize, rule_bits: u32, prec: u32) -> Self {
        let inc = Increment::new(setting, prec);
        let lambda_max = setting.lambda_max(prec);
        let nodes = chebyshev::nodes(nodes, prec);
        let rule = TanhSinh::new(rule_bits, 1.0, prec);
        let sizes = size_terms(&inc, &lambda_max, &nodes, &rule, prec);
        Ctx { prec, inc, lambda_max, nodes, rule, sizes }
    }
}

/// int_0^lambda P'(eta) (1 + i n) [L K(chi_e - gamma(eta), eta) + i beta R(chi_e; eta)] d eta at
/// lambda = Lambda t for the leading (chi_e = gamma + lambda) and the trailing
/// (chi_e = gamma - lambda) end, from the Chebyshev coefficients of Phi and Gam (module doc), on
/// `rule`; R = Z(t)(A + B t)/cosh(pi eps) is the tilted punch's slope outside
/// ([`crate::growing_contact::kernel::TiltedPunch::outside`], `periodic` only: the increment's
/// i beta dP/L of docs/theory.md section 8, Problem 2, which keeps v and u periodic; its constant
/// f = 1 cancels against that term of the edge condition).
///
/// Both ends when `only` is `None`; with `Some(side)` the kernels of that end only (the other
/// end's integral is then zero; its advance factor is still checked, so the errors are the same):
/// the fields need one end per point ([`super::fields`]' psi_hat), and the kernels are the cost.
/// `sizes`: the [`SizeTerms`] of this t at the rule's points when the caller has them
/// ([`size_terms`]; computed here otherwise, the same values).
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
    sizes: Option<&[SizeTerms]>,
) -> Result<(Complex, Complex), AdhesionError> {
    let lambda = Float::with_val(prec, lambda_max * t);
    let xt = Float::with_val(prec, t * 2u32) - 1u32;
    let gam_t = chebyshev::evaluate(gam_c, &xt, prec);
    // The divided differences of Gam at this t for every rule point: one series in the other
    // argument ([`divided_difference_series`]), summed per point.
    let dd_c = divided_difference_series(gam_c, &xt, prec);
    let (mut acc_b, mut acc_a) = (Complex::new(prec), Complex::new(prec));
    let tphi = (!inc.constant_ratio()).then(|| times_t(phi_c, prec));
    let l2max = Float::with_val(prec, lambda_max.square_ref());
    // n = N'(P2(eta)) and its factors, once when the law is linear.
    let factors = |n: &Float| (Complex::with_val(prec, (1, n)), super::increment::periodic_factor(&inc.beta, n, prec));
    let constant = factors(&inc.ratio_at(&Float::with_val(prec, 0)));
    let mut clenshaw = chebyshev::Clenshaw::new(prec);
    // Phi's and the divided difference's sums at every rule point ([`chebyshev::Series`]: the
    // same bits as the MPFR loop).
    let (phi_s, dd_s) = (chebyshev::Series::new(phi_c, prec), chebyshev::Series::new(&dd_c, prec));
    // Scratch values of the loop, assigned in place (each operation rounded once, as before).
    let [mut phi, mut dd, mut ts, mut xs, mut e, mut base, mut weight, mut d, mut eta] =
        std::array::from_fn(|_| Float::new(prec));
    for q in 0..rule.len() {
        let (s, c, w) = (&rule.s[q], &rule.c[q], &rule.w[q]);
        ts.assign(t * s);
        xs.assign(&ts * 2u32);
        xs -= 1u32;
        phi_s.evaluate_into(&xs, &mut phi, &mut clenshaw);
        // E = Gam(t) + s t DGam(t, s t); DGam in t is twice the divided difference in x.
        dd_s.evaluate_into(&xs, &mut dd, &mut clenshaw);
        e.assign(&ts * &dd);
        e *= 2u32;
        e += &gam_t;
        base.assign(&lambda * c);
        weight.assign(w * s);
        weight *= &phi;
        // n = N'(P2(eta)) (constant for the linear law).
        let varying = tphi.as_ref().map(|tp| factors(&inc.ratio_at(&(chebyshev::integral(tp, &ts, prec) * &l2max))));
        let (one_in, tilt_factor) = varying.as_ref().unwrap_or(&constant);
        // The factors of eta alone and the tilted punch: once for both ends.
        let own = sizes.is_none().then(|| {
            eta.assign(&lambda * s);
            SizeTerms::new(inc, &eta, prec)
        });
        let SizeTerms { size, tilt } = own.as_ref().or(sizes.map(|v| &v[q])).expect("one of the two is set");
        for (side, sign, acc) in [(Side::Right, 1i32, &mut acc_b), (Side::Left, -1, &mut acc_a)] {
            let factor = advance_factor(&e, sign, &lambda)?;
            if only.is_some_and(|o| o != side) {
                continue;
            }
            d.assign(&base * &factor);
            let point = size.point(side, &d);
            let mut k = size.kernel(&point) * one_in;
            if let Some(tilt) = tilt {
                k += tilt.outside_at(size, &point, &inc.cosh_pi_eps) * tilt_factor;
            }
            *acc += k * &weight;
        }
    }
    // int_0^lambda P' K d eta = lambda^2 int_0^1 s Phi(t s) K ds.
    let l2 = Float::with_val(prec, lambda.square_ref());
    Ok((acc_b * &l2, acc_a * &l2))
}

/// The residuals (2 per node: leading, trailing) of the state (Phi values, then Gam values),
/// each divided by lambda.
fn residual(ctx: &Ctx, state: &[Float]) -> Result<Vec<Float>, AdhesionError> {
    let prec = ctx.prec;
    let n_nodes = ctx.nodes.len();
    let phi_c = chebyshev::coefficients(&state[..n_nodes], prec);
    let gam_c = chebyshev::coefficients(&state[n_nodes..], prec);
    let pi = Float::with_val(prec, Constant::Pi);
    // The nodes' integrals are independent: on every CPU ([`crate::numerics::parallel`]).
    let rows = crate::numerics::parallel::map(&ctx.nodes, |i, t| -> Result<[Float; 2], AdhesionError> {
        let lambda = Float::with_val(prec, &ctx.lambda_max * t);
        let gam_t = chebyshev::evaluate(&gam_c, &(Float::with_val(prec, t * 2u32) - 1u32), prec);
        let (acc_b, acc_a) =
            edge_integrals(&ctx.rule, &ctx.inc, &ctx.lambda_max, &phi_c, &gam_c, t, prec, None, Some(&ctx.sizes[i]))?;
        // G(chi_e)/lambda = pi (Gam(t) +- 1) for the parabola.
        let row = |acc: Complex, sign: i32| {
            let v = acc.real().clone() / &lambda;
            v - Float::with_val(prec, &gam_t + sign) * &pi
        };
        Ok([row(acc_b, 1), row(acc_a, -1)])
    });
    let mut out = Vec::with_capacity(2 * n_nodes);
    for pair in rows {
        out.extend(pair?);
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
    let warm: Option<Vec<Float>> = start.map(|s| {
        let taus = chebyshev::nodes(nodes, prec);
        let at = |c: &[Float], tau: &Float| chebyshev::evaluate(c, &(Float::with_val(prec, tau * 2u32) - 1u32), prec);
        let phi: Vec<Float> = taus.iter().map(|t| at(&s.phi, t)).collect();
        phi.into_iter().chain(taus.iter().map(|t| at(&s.gam, t))).collect()
    });
    let warm_start = warm.is_some();
    match solve_with(setting, warm, nodes, target_bits, prec) {
        Err(_) if warm_start => solve_from(setting, nodes, target_bits, prec, None),
        r => r,
    }
}

/// The chord Jacobian of a run of [`solve_by`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum ChordJacobian {
    /// The `f64` closed form on the working rule ([`jacobian_f64`]), once at the start; the
    /// 64-bit Newton from the single punch takes it too. The run fails where a correction
    /// exceeds [`CONTRACTION`] times the one before.
    Fine,
    /// The 64-bit MPFR closed form on a coarse rule (`super::jacobian::mpfr`): the 64-bit
    /// Newton's last one, or at `warm`; no contraction bound (the solver before the `f64` one).
    Coarse,
}

/// The iteration of [`solve_from`] from `warm` (at `prec`) or the single punch: first with the
/// `f64` chord Jacobian on the working rule ([`ChordJacobian::Fine`]); where that chord iteration
/// fails or does not contract, again with the 64-bit MPFR Jacobian of a coarse rule
/// ([`ChordJacobian::Coarse`]). The second is the solver as it was before the first (nu = 0,
/// n = 1/2, l/L = 1/8 at 12 digits, near its homogeneous mode mu* = 31.84: the `f64` one's
/// iteration lets the leading end recede at lambda = 0.3924; test
/// `small_nu_shortfall_is_a_warning` of the CLI).
fn solve_with(
    setting: &LawSetting,
    warm: Option<Vec<Float>>,
    nodes: usize,
    target_bits: u32,
    prec: u32,
) -> Result<LawCollocation, AdhesionError> {
    solve_by(setting, warm.clone(), nodes, target_bits, prec, ChordJacobian::Fine)
        .or_else(|_| solve_by(setting, warm, nodes, target_bits, prec, ChordJacobian::Coarse))
}

/// The 64-bit Newton of [`solve_from`] on a coarse rule from the single punch, the closed-form
/// Jacobian refreshed at every step while the correction exceeds 1e-8; the Jacobian by `closed_form`
/// at (the coarse discretisation, the state). Returns the state and the last Jacobian.
fn newton_64(
    setting: &LawSetting,
    nodes: usize,
    closed_form: impl Fn(&Ctx, &[Float]) -> Result<Vec<Vec<f64>>, AdhesionError>,
) -> Result<(Vec<Float>, Vec<Vec<f64>>), AdhesionError> {
    let low = Ctx::new(setting, nodes, 50, 64);
    let load_constant = AdhesionParamsF64::new(&setting.material).load_constant;
    let mut state64: Vec<Float> =
        (0..2 * nodes).map(|i| Float::with_val(64, if i < nodes { 2.0 * load_constant } else { 0.0 })).collect();
    let mut jac = closed_form(&low, &state64)?;
    let mut previous = f64::INFINITY;
    for _ in 0..30 {
        let r = residual(&low, &state64)?;
        let delta = solve_f64(&jac, &r.iter().map(|v| v.to_f64()).collect::<Vec<_>>())?;
        let size = delta.iter().fold(0f64, |m, v| m.max(v.abs()));
        for (x, d) in state64.iter_mut().zip(&delta) {
            *x -= *d;
        }
        if size < 1e-13 {
            break;
        }
        if size > 1e-8 || size > 1e-3 * previous {
            jac = closed_form(&low, &state64)?;
        }
        previous = size;
    }
    Ok((state64, jac))
}

/// A chord step's correction must be below this fraction of the one before it with
/// [`ChordJacobian::Fine`]; beyond, the iteration does not contract and
/// [`ChordJacobian::Coarse`] takes over. On the
/// shipped scenes the second correction is under 2.4e-6 of the first.
const CONTRACTION: f64 = 0.5;

/// The chord iteration of [`solve_from`] at `prec` from `warm`, or from the 64-bit Newton's
/// solution ([`newton_64`]) when there is none, with the chord Jacobian `kind`. With
/// [`ChordJacobian::Fine`] on the shipped scene the second residual's correction is already below
/// the goal and ends the iteration (the 64-bit one of the coarse rule contracted by 0.06 and
/// needed a third; docs/performance.md, "The loading law", round three).
fn solve_by(
    setting: &LawSetting,
    warm: Option<Vec<Float>>,
    nodes: usize,
    target_bits: u32,
    prec: u32,
    kind: ChordJacobian,
) -> Result<LawCollocation, AdhesionError> {
    let closed_form = |ctx: &Ctx, state: &[Float]| match kind {
        ChordJacobian::Fine => jacobian_f64(&ctx.rule, &ctx.inc, &ctx.lambda_max, &ctx.nodes, state),
        ChordJacobian::Coarse => super::jacobian::mpfr::jacobian(
            &ctx.rule,
            &ctx.inc,
            &ctx.lambda_max,
            &ctx.nodes,
            &ctx.sizes,
            state,
            ctx.prec,
        ),
    };
    let ctx = |rule_bits: u32, prec: u32| Ctx::new(setting, nodes, rule_bits, prec);
    let at = |state: &[Float], prec: u32| state.iter().map(|v| Float::with_val(prec, v)).collect::<Vec<_>>();
    let (state, jac) = match (warm, kind) {
        // The Jacobian on the working rule, at the start.
        (Some(w), ChordJacobian::Fine) => (w, None),
        (None, ChordJacobian::Fine) => (at(&newton_64(setting, nodes, closed_form)?.0, prec), None),
        // The coarse rule's at 64 bits.
        (Some(w), ChordJacobian::Coarse) => {
            let jac = closed_form(&ctx(50, 64), &at(&w, 64))?;
            (w, Some(jac))
        }
        (None, ChordJacobian::Coarse) => {
            let (state64, jac) = newton_64(setting, nodes, closed_form)?;
            (at(&state64, prec), Some(jac))
        }
    };
    let work = ctx(target_bits + 8, prec);
    let jac = match jac {
        Some(j) => j,
        None => closed_form(&work, &state)?,
    };
    let bound = (kind == ChordJacobian::Fine).then_some(CONTRACTION);
    chord(&work, state, &jac, target_bits, bound)
}

/// Chord steps on `ctx` from `state` with the fixed `jac` until the correction falls below
/// 2^-`target_bits`; an error after 40 steps, or where a correction exceeds `contraction` times the
/// one before.
fn chord(
    ctx: &Ctx,
    mut state: Vec<Float>,
    jac: &[Vec<f64>],
    target_bits: u32,
    contraction: Option<f64>,
) -> Result<LawCollocation, AdhesionError> {
    let (prec, nodes) = (ctx.prec, ctx.nodes.len());
    let goal = 2f64.powi(-(target_bits as i32));
    let mut last = f64::INFINITY;
    let mut previous = f64::INFINITY;
    for steps in 1..=40 {
        let r = residual(ctx, &state)?;
        last = r.iter().fold(0f64, |m, v| m.max(v.to_f64().abs()));
        let delta = solve_f64(jac, &r.iter().map(|v| v.to_f64()).collect::<Vec<_>>())?;
        let size = delta.iter().fold(0f64, |m, v| m.max(v.abs()));
        if let Some(bound) = contraction.filter(|b| size.is_nan() || size > b * previous) {
            return Err(AdhesionError::NotConverged {
                what: "loading-law chord iteration",
                reason: format!("correction {size:.1e} after {previous:.1e}: not below {bound} of it"),
            });
        }
        previous = size;
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
    use crate::growing_contact::kernel::Row;
    use crate::model::{Convention, Exact, LoadingLaw, Material};

    fn material(nu: (i64, i64)) -> Material {
        Material::from_contact_modulus(Exact::new(nu.0.into(), nu.1.into()), Exact::from_integer(1.into())).unwrap()
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
    #[ignore = "long tier: 6 s alone in the test profile (opt-level 2) on a loaded 2-core machine (scripts/test --long)"]
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

    /// The Jacobian tests' settings: nu = 0.3, n = 1/5, l/L = 1/5 in both conventions; the
    /// polynomial law N = P2/5 + P2^2/100 at nu = 0 (`periodic`); the single punch (l/U = 1).
    fn jacobian_cases() -> Vec<LawSetting> {
        let n = Exact::new(1.into(), 5.into());
        let size = Exact::new(1.into(), 5.into());
        let mut cases: Vec<LawSetting> = [Convention::Paper, Convention::PeriodicSurface]
            .into_iter()
            .map(|convention| LawSetting::linear(material((3, 10)), n.clone(), size.clone(), convention))
            .collect();
        let mut law = LawSetting::linear(material((0, 1)), n.clone(), size, Convention::PeriodicSurface);
        law.law =
            LoadingLaw::Polynomial(vec![Exact::from_integer(0.into()), n.clone(), Exact::new(1.into(), 100.into())]);
        cases.push(law);
        let mut single = LawSetting::linear(material((3, 10)), n, Exact::from_integer(1.into()), Convention::Paper);
        single.row = Row::Single;
        cases.push(single);
        cases
    }

    /// 8 nodes, a 50-bit rule at 128 bits, an asymmetric state (Phi, Gam not constant) and the
    /// MPFR closed-form Jacobian there.
    fn reference_jacobian(setting: &LawSetting) -> (Ctx, Vec<Float>, Vec<Vec<f64>>) {
        let (prec, nodes) = (128, 8);
        let ctx = Ctx::new(setting, nodes, 50, prec);
        let state: Vec<Float> = (0..2 * nodes)
            .map(|i| {
                let t = ctx.nodes[i % nodes].to_f64();
                Float::with_val(prec, if i < nodes { 2.3 + 0.4 * t * t } else { -0.04 + 0.02 * t })
            })
            .collect();
        let exact = super::super::jacobian::mpfr::jacobian(
            &ctx.rule,
            &ctx.inc,
            &ctx.lambda_max,
            &ctx.nodes,
            &ctx.sizes,
            &state,
            prec,
        )
        .unwrap();
        (ctx, state, exact)
    }

    /// The chord iteration's `f64` Jacobian ([`jacobian_f64`]) equals the MPFR closed form at 128
    /// bits (itself checked against central differences below) to 1e-7 of the largest entry at an
    /// asymmetric state, in both conventions (the `periodic` one with the tilted punch's central
    /// difference), for the single punch and for a polynomial law (n varying along the loading);
    /// measured: 2.1e-8 to 2.7e-8 of it, far below what the chord iteration needs (a contraction
    /// under 1e-5 makes its second correction fall below the goal).
    #[test]
    fn f64_jacobian_equals_the_mpfr_closed_form() {
        for setting in jacobian_cases() {
            let (ctx, state, exact) = reference_jacobian(&setting);
            let fast = jacobian_f64(&ctx.rule, &ctx.inc, &ctx.lambda_max, &ctx.nodes, &state).unwrap();
            let scale = exact.iter().flatten().fold(0f64, |m, v| m.max(v.abs()));
            let worst = exact.iter().flatten().zip(fast.iter().flatten()).fold(0f64, |m, (a, b)| m.max((a - b).abs()));
            eprintln!(
                "{:?} {:?}: largest |J| {scale:.3}, f64 off by {:.1e} of it",
                setting.row,
                setting.convention,
                worst / scale
            );
            assert!(worst < 1e-7 * scale, "{worst} of {scale}");
        }
    }

    /// The closed-form Jacobian ((`super::super::jacobian::mpfr`)) equals central differences of the
    /// residual at 128 bits (step 1e-12: truncation ~1e-24) to 1e-12 relative at an asymmetric
    /// state (Phi, Gam not constant), in both conventions and for the single punch; for a
    /// polynomial law, whose n(P2) dependence the closed form leaves out, the difference is that
    /// term: 6.5e-5 against the largest entry 10.5 at N = P2/5 + P2^2/100, nu = 0, l/L = 1/5
    /// (`cargo test --release --lib closed_form_jacobian -- --nocapture`).
    #[test]
    #[ignore = "long tier: 9 s alone in the test profile (opt-level 2) on a loaded 2-core machine (scripts/test --long)"]
    fn closed_form_jacobian_equals_finite_differences() {
        let prec = 128;
        for (k, setting) in jacobian_cases().into_iter().enumerate() {
            let tolerance = if k == 2 { 1e-5 } else { 1e-12 };
            let nodes = 8;
            let (ctx, state, exact) = reference_jacobian(&setting);
            let h = 1e-12;
            let mut worst = 0f64;
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
