//! The homogeneous modes of Problem 2 under the linear loading law P1 = n P2 (issue 12, small
//! nu): where the incremental complete-adhesion problem stops fixing its solution.
//!
//! # The symbol \[derived here\]
//! Near lambda = 0 the loading-law problem is the self-similar single punch ([`super::loading_law`],
//! order 0: F = P'/eta = f_0, Gam = gamma/eta = g_0). Perturb it by F = f_0 + u eta^mu,
//! Gam = g_0 + v eta^mu (mu > -1). In the edge conditions
//! R_sigma = Re (1 + i n) int_0^1 s F(lambda s) (lambda K_sigma) ds - pi (sigma + Gam(lambda)), the
//! perturbation enters, to first order and at lambda -> 0, as lambda^mu M(mu) (u, v)^T with
//!   M_sigma,f(mu) = Re (1 + i n) int_0^1 s^(mu+1) k_sigma(s) ds,
//!   M_sigma,g(mu) = Re (1 + i n) f_0 int_0^1 s k_sigma(s) sigma e_mu(s) (a1/N_0 + a2 (1 - s)/D_0) ds - pi,
//! k_sigma = sigma (1 - s)^(a1) N_0^(a1) D_0^(a2), N_0 = 1 + sigma g_0, D_0 = (1 + s) + sigma (1 - s) g_0,
//! a1 = -1/2 - sigma i eps, a2 = -1/2 + sigma i eps, e_mu(s) = (1 - s^(mu+1))/(1 - s)
//! (the edge point's shift chi_e - chi_e(eta) gains sigma v lambda^(mu+1) (1 - s^(mu+1))). At
//! mu = 2j this is the matrix of order j of the series ([`super::loading_law`], "Expansion"):
//! each coefficient (f_j, g_j) is divided by det M(2j).
//!
//! # What a zero means
//! If det M(mu*) = 0 for a real mu* > 0, then F = f_0 + C u eta^(mu*), Gam = g_0 + C v eta^(mu*)
//! solves the linearised problem for every C, and (the kernel being of Mellin type at lambda ->
//! 0) the nonlinear problem has a one-parameter family of solutions through the self-similar one:
//! the loading law and both moving-edge conditions fix the history only up to C eta^(mu*)
//! (times a series in eta^2 for the periodic row). The solution analytic in lambda^2 (the series,
//! C = 0) is one member; where mu* is close to an even integer 2j its coefficient of lambda^(2j)
//! is large (near-resonance: divided by det M(2j)), and at mu* = 2j exactly it does not exist.
//! A numerical method fixes C by its own discretisation error at small sizes, and that error
//! reaches Lambda multiplied by up to (Lambda/eta)^(mu*): the smaller mu*, the sooner a method
//! loses its digits. Measured with the MPFR collocation (`verified::solve_law`, paper
//! convention; `cargo test --release --test all loading_law_agreement:: -- --ignored --nocapture
//! nu_zero_reach` and `cargo run --release --example loading_law_small_nu`): nu = 0, n = 1/5
//! (mu* = 178.3) verifies 25.9 digits at l/L = 1/16, 16.1 at 1/8, 2.6 at 1/4; n = 1/2 (mu* =
//! 31.8) 2.1 at 1/8; nu = 1/10, n = 1/5 (mu* = 580) 18.2 at 1/8. (The f64 march with blocks of
//! 0.05 refused nu <= 0.1 by its own instability; one block at small nu agrees with the
//! collocation at nu = 0, n = 1/5, l/L = 1/16 and 1/8: `verified_f64::solve_law_f64`.)
//!
//! # Measured
//! `cargo run --release --example loading_law_modes` (12 digits asked; verified digits in
//! brackets; "none": no zero found on (0, 2000]):
//!
//! | nu \\ n | 1/5 | 1/2 | 1 |
//! |---|---|---|---|
//! | 0 | 178.311153 (10.5) | 31.8395100566 (17.2) | 1.08745322144 (19.9) |
//! | 1/10 | 579.9425 (8.2) | 87.6154721909 (12.4) | 5.92270667737 (21.1) |
//! | 3/20 | 1323.756 (7.4) | 174.480669 (10.9) | 11.6866733089 (18.5) |
//! | 1/5 | none | 427.254973 (9.2) | 25.0932246271 (18.2) |
//! | 3/10 | none | none | 251.992321 (9.6) |
//!
//! At n = 0 (the symmetric problem) det M = 2 M_f M_g and both factors vanish close together:
//! nu = 0: mu* = 603.731091 (9.2), a pair of zeros that the plain sign scan steps over (found by
//! the finer rescan at the minimum of |det M|): the smaller one is M_g's (the centre moving);
//! M_f(mu) = Re M_(mu+1) vanishes at 604.73, the symmetric problem's own mode
//! ([`super::adhesion_mode`], test `the_loading_law_symbol_has_this_zero_in_its_f_column`), which
//! is the pole of the exact symmetric coefficients where Re M_(2N+1) = 0 near N = 302 (issue 13).
//! No zero found below 2000 at
//! n = 0 for nu >= 1/10. Checks (tests below): nu = 0, n = 1/2 and 1/5 against an
//! independent mpmath computation of the same determinant (`mp.findroot` on the 2x2
//! determinant with `mp.quad`, run once: 31.8395100566, 178.311153189); the series' coefficients
//! change sign between lambda^30 and lambda^32 with |g_16| = 6.6e9 against |g_15| = 1.8e7 (the
//! near-resonance at mu* = 31.84); and toward the end of the self-similar branch (the fold n* of
//! [`super::loading_law`], bracketed there as 1 < n* < 1.125 at nu = 0) mu* falls to 0 with
//! det M(0): nu = 0, n = 1: mu* = 1.0875, det M(0) = -3.21; n = 26/25: mu* = 0.19998,
//! det M(0) = -1.00: the fold is where the mode's exponent reaches the self-similar solution's.
//!
//! [`Symbol::first_zero`] searches real zeros (a scan in mu with a sign change, then regula
//! falsi); complex zeros (pairs mu, conj mu) are counted by the argument principle
//! ([`Symbol::zeros_in`]): none in [-0.9, 31] x [-40, 40] at nu = 0, n = 1/2 (the real zero
//! 31.84 found alone in [31, 33] x [-1, 1]), none in [-0.9, 300] x [-40, 40] at nu = 3/10,
//! n = 1/2 (test `no_complex_zero_below_the_mode`).

use super::loading_law::law_coefficients;
use crate::error::Error;
use crate::model::OnPunchRow;
use crate::model::{Material, ModelError};
use crate::numerics::accuracy::{digits_cap_for_bits, verified_digits_mpfr};
use crate::numerics::exact::to_float;
use crate::numerics::mp_rounded;
use crate::numerics::precision::{bits_for_digits, SOLVER_GUARD_BITS, VERIFY_EXTRA_BITS};
use crate::numerics::tanh_sinh::TanhSinh;
use crate::params::adhesion::AdhesionParamsMpfr;
use num_traits::Signed;
use rug::float::Constant;
use rug::{Complex, Float};
use screen::Screen;

mod quick;
mod scan;
mod screen;
mod self_similar;

type Q = num_rational::BigRational;

/// Largest mu scanned for a zero of det M(mu).
pub const MU_MAX: u32 = 2000;

/// The scan's grid on [0, `mu_max`]: steps of 1 to 100, then 2 % per step ([`Symbol::first_zero`]).
fn scan_grid(mu_max: u32) -> Vec<f64> {
    let mut grid = Vec::new();
    let mut m = 0.0f64;
    while m <= mu_max as f64 {
        grid.push(m);
        m = if m < 100.0 { m + 1.0 } else { (m * 1.02).round() };
    }
    grid
}

/// The symbol's mu-independent part at one precision: per quadrature node, ln s, 1 - s and the
/// two real weights of each side.
#[derive(Debug, Clone)]
pub struct Symbol {
    prec: u32,
    /// f_0 and g_0 of the self-similar solution.
    pub f0: Float,
    /// g_0 = c/l of the single punch.
    pub g0: Float,
    pi: Float,
    nodes: Vec<Node>,
    /// det M in f64 with an error bound, to decide the scan's signs without MPFR where it can
    /// (`None` below [`screen::MIN_PREC`] bits).
    screen: Option<Screen>,
}

/// One quadrature node of the symbol.
#[derive(Debug, Clone)]
struct Node {
    /// ln s (from the complement near s = 1).
    ln_s: Float,
    /// exp(ln s) rounded once (s^mu = exp((mu + 1) ln s)/exp(ln s) in [`Symbol::matrix`]).
    exp_ln_s: Float,
    /// 1 - s.
    c: Float,
    /// [wf_+, wg_+], [wf_-, wg_-]: wf = Re (1 + i n) w s k_sigma,
    /// wg = Re (1 + i n) f_0 w s k_sigma sigma (a1/N_0 + a2 (1 - s)/D_0).
    sides: [[Float; 2]; 2],
}

impl Symbol {
    /// From the material constants and n = `ratio` at `prec` bits on `rule` (the self-similar
    /// solution by [`law_coefficients`] with one term).
    pub fn new(params: &AdhesionParamsMpfr, ratio: &Float, rule: &TanhSinh, prec: u32) -> Result<Self, Error> {
        let e = law_coefficients(params, ratio, 1, rule, prec)?;
        Self::with_start(params, ratio, rule, prec, e.f[0].clone(), e.g[0].clone())
    }

    /// [`Self::new`] with the self-similar solution's f_0, g_0 from `self_similar` (the order-0
    /// system alone, f64 then MPFR Newton: the same f_0, g_0 to 2^-(prec - 12), several times
    /// faster), or by [`law_coefficients`] where that does not converge.
    fn new_fast(params: &AdhesionParamsMpfr, ratio: &Float, rule: &TanhSinh, prec: u32) -> Result<Self, Error> {
        match self_similar::self_similar(params, ratio, rule, prec) {
            Some((f0, g0)) => Self::with_start(params, ratio, rule, prec, f0, g0),
            None => Self::new(params, ratio, rule, prec),
        }
    }

    fn with_start(
        params: &AdhesionParamsMpfr,
        ratio: &Float,
        rule: &TanhSinh,
        prec: u32,
        f0: Float,
        g0: Float,
    ) -> Result<Self, Error> {
        let one_in = Complex::with_val(prec, (1, ratio));
        let eps = Float::with_val(prec, &params.eps);
        let mut nodes = Vec::with_capacity(rule.len());
        for q in 0..rule.len() {
            if !(rule.c[q] > 0 && rule.s[q] > 0) {
                continue;
            }
            let (s, c) = (Float::with_val(prec, &rule.s[q]), Float::with_val(prec, &rule.c[q]));
            let ws = Float::with_val(prec, &rule.w[q] * &s);
            let ln_c = mp_rounded::ln(&c, prec);
            let zero = || Float::new(prec);
            let mut sides: [[Float; 2]; 2] = [[zero(), zero()], [zero(), zero()]];
            for (side, sigma) in [(0usize, 1i32), (1, -1)] {
                let a1 = Complex::with_val(prec, (-0.5, Float::with_val(prec, &eps * -sigma)));
                let a2 = Complex::with_val(prec, (-0.5, Float::with_val(prec, &eps * sigma)));
                let sg0 = Float::with_val(prec, &g0 * sigma);
                let n0 = Float::with_val(prec, &sg0 + 1u32);
                let d0 = Float::with_val(prec, &c * &sg0) + &s + 1u32;
                let ln_n0 = mp_rounded::ln(&n0, prec);
                let ln_d0 = mp_rounded::ln(&d0, prec);
                let expo = Complex::with_val(prec, &a1 * Float::with_val(prec, &ln_c + &ln_n0))
                    + Complex::with_val(prec, &a2 * &ln_d0);
                let k = Complex::with_val(prec, expo.exp_ref()) * sigma;
                let wk = Complex::with_val(prec, &k * &ws) * &one_in;
                let term = Complex::with_val(prec, &a1 / &n0) + Complex::with_val(prec, &a2 * &c) / &d0;
                let wg = Complex::with_val(prec, &wk * &term) * &f0 * sigma;
                sides[side] = [wk.real().clone(), wg.real().clone()];
            }
            // ln s from the complement near s = 1 (s itself has lost the digits of 1 - s there).
            let ln_s = if s > 0.5 { Float::with_val(prec, (-c.clone()).ln_1p_ref()) } else { mp_rounded::ln(&s, prec) };
            let exp_ln_s = Float::with_val(prec, ln_s.exp_ref());
            nodes.push(Node { ln_s, exp_ln_s, c, sides });
        }
        let screen = (prec >= screen::MIN_PREC).then(|| Screen::new(&nodes));
        Ok(Symbol { prec, f0, g0, pi: Float::with_val(prec, Constant::Pi), nodes, screen })
    }

    /// M(mu) (rows leading, trailing; columns f, g; module doc).
    pub fn matrix(&self, mu: &Float) -> [[Float; 2]; 2] {
        let p = self.prec;
        let mut m: [[Float; 2]; 2] = [[Float::new(p), Float::new(p)], [Float::new(p), Float::new(p)]];
        let mu1 = Float::with_val(p, mu + 1u32);
        for Node { ln_s, exp_ln_s, c, sides } in &self.nodes {
            // s^mu and e_mu = (1 - s^(mu+1))/(1 - s), the latter from expm1 (accurate as s -> 1).
            let x = Float::with_val(p, ln_s * &mu1);
            let s_mu1 = Float::with_val(p, x.exp_ref());
            let s_mu = Float::with_val(p, &s_mu1 / exp_ln_s);
            let e = -Float::with_val(p, x.exp_m1_ref()) / c;
            for k in 0..2 {
                m[k][0] += Float::with_val(p, &sides[k][0] * &s_mu);
                m[k][1] += Float::with_val(p, &sides[k][1] * &e);
            }
        }
        for row in m.iter_mut() {
            row[1] -= &self.pi;
        }
        m
    }

    /// det M(mu) at a complex mu (the weights are real: the real part is taken before s^mu).
    pub(crate) fn det_complex(&self, mu: &Complex) -> Complex {
        let p = self.prec;
        let zero = || Complex::new(p);
        let mut m = [[zero(), zero()], [zero(), zero()]];
        let mu1 = Complex::with_val(p, mu + 1u32);
        let small = Float::with_val(p, Float::i_exp(1, -8));
        for Node { ln_s, c, sides, .. } in &self.nodes {
            let x = Complex::with_val(p, &mu1 * ln_s);
            let s_mu = Complex::with_val(p, Complex::with_val(p, mu * ln_s).exp_ref());
            // expm1(x): its Taylor series where |x| is small (exp(x) - 1 cancels there).
            let expm1 = if Float::with_val(p, x.abs_ref()) < small {
                let (mut term, mut sum) = (x.clone(), x.clone());
                for k in 2..=(p / 6 + 4) {
                    term = Complex::with_val(p, &term * &x) / k;
                    sum += &term;
                }
                sum
            } else {
                Complex::with_val(p, x.exp_ref()) - 1u32
            };
            let e = -expm1 / c;
            for k in 0..2 {
                m[k][0] += Complex::with_val(p, &s_mu * &sides[k][0]);
                m[k][1] += Complex::with_val(p, &e * &sides[k][1]);
            }
        }
        for row in m.iter_mut() {
            row[1] -= &self.pi;
        }
        Complex::with_val(p, &m[0][0] * &m[1][1]) - Complex::with_val(p, &m[0][1] * &m[1][0])
    }

    /// The number of zeros of det M inside the rectangle [re_lo, re_hi] x [im_lo, im_hi] (none on
    /// its edges), by the argument principle: the change of arg det along the boundary, sampled
    /// with steps halved until each changes the argument by less than pi/4.
    pub fn zeros_in(&self, re: (f64, f64), im: (f64, f64)) -> i64 {
        let p = self.prec;
        let corners = [(re.0, im.0), (re.1, im.0), (re.1, im.1), (re.0, im.1), (re.0, im.0)];
        let at = |x: f64, y: f64| {
            let d = self.det_complex(&Complex::with_val(p, (x, y)));
            d.imag().to_f64().atan2(d.real().to_f64())
        };
        let mut total = 0.0f64;
        for w in corners.windows(2) {
            let ((x0, y0), (x1, y1)) = (w[0], w[1]);
            let mut stack = vec![(0.0f64, 1.0f64, at(x0, y0), at(x1, y1))];
            while let Some((t0, t1, a0, a1)) = stack.pop() {
                let mut d = a1 - a0;
                d -= (d / std::f64::consts::TAU).round() * std::f64::consts::TAU;
                if d.abs() < std::f64::consts::FRAC_PI_4 || t1 - t0 < 1e-9 {
                    total += d;
                } else {
                    let tm = 0.5 * (t0 + t1);
                    let am = at(x0 + tm * (x1 - x0), y0 + tm * (y1 - y0));
                    stack.push((tm, t1, am, a1));
                    stack.push((t0, tm, a0, am));
                }
            }
        }
        (total / std::f64::consts::TAU).round() as i64
    }

    /// det M(mu).
    pub fn det(&self, mu: &Float) -> Float {
        let m = self.matrix(mu);
        Float::with_val(self.prec, &m[0][0] * &m[1][1]) - Float::with_val(self.prec, &m[0][1] * &m[1][0])
    }

    /// The smallest real zero of det M on (0, `mu_max`] to about `prec` bits: a scan (steps of 1
    /// to 100, then 2 % per step), then regula falsi (Illinois) on the first sign change. Where
    /// |det M| has a local minimum on the scan without a sign change (two zeros close together,
    /// as at n = 0, where det M = 2 M_f M_g and both factors vanish near mu = 604 at nu = 0), the
    /// two steps around it are rescanned 64 times finer, twice.
    pub fn first_zero(&self, mu_max: u32) -> Option<Float> {
        let grid = scan_grid(mu_max);
        // With the symbol every question has an answer.
        let (lo, hi) = scan::first_change(Some(self), self.screen.as_ref(), &grid, 2).flatten()?;
        let p = self.prec;
        let (lo, hi) = (Float::with_val(p, lo), Float::with_val(p, hi));
        let (f_lo, f_hi) = (self.det(&lo), self.det(&hi));
        Some(self.refine(lo, f_lo, hi, f_hi))
    }

    fn refine(&self, mut a: Float, mut fa: Float, mut b: Float, mut fb: Float) -> Float {
        let p = self.prec;
        let tol = Float::with_val(p, Float::i_exp(1, -(p as i32) + 12));
        let mut side = 0i32;
        for _ in 0..4 * p {
            let den = Float::with_val(p, &fb - &fa);
            let mut c = Float::with_val(p, &b - &a) * &fb / den;
            c = Float::with_val(p, &b - &c);
            if !(c > a && c < b) {
                c = Float::with_val(p, &a + &b) / 2u32;
            }
            let fc = self.det(&c);
            if fc.is_zero() {
                return c;
            }
            if fc.is_sign_negative() == fb.is_sign_negative() {
                (b, fb) = (c, fc);
                if side == 1 {
                    fa /= 2u32;
                }
                side = 1;
            } else {
                (a, fa) = (c, fc);
                if side == -1 {
                    fb /= 2u32;
                }
                side = -1;
            }
            if Float::with_val(p, &b - &a) <= Float::with_val(p, &tol * &b) {
                break;
            }
        }
        Float::with_val(p, &a + &b) / 2u32
    }
}

/// The mode exponent at one nu and n, verified by a second run.
#[derive(Debug, Clone)]
pub struct ModeExponent {
    /// nu.
    pub nu: Q,
    /// n.
    pub ratio: Q,
    /// The smallest real zero mu* of det M on (0, [`MU_MAX`]], or `None` (det M has one sign there).
    pub mu: Option<Float>,
    /// Digits of mu* on which the two runs agree (the cap when `mu` is `None`).
    pub digits: f64,
    /// c/l of the self-similar single punch (g_0).
    pub g0: Float,
    /// det M(0) (the Jacobian of the self-similar system; nonzero).
    pub det_at_zero: Float,
}

/// Digits of mu* printed wherever a loading-law problem reports its mode.
pub const MODE_DIGITS: u32 = 12;

/// The mode of a loading-law problem: at its nu and n = N'(0) (the self-similar start's ratio),
/// to [`MODE_DIGITS`] digits: [`mode_exponent`]'s answer, from the f64 screens where they prove
/// that its runs find no zero (module `quick`; then `g0` and `det_at_zero` are f64 values).
pub(crate) fn problem_mode(problem: &crate::model::LoadingLawProblem) -> Result<ModeExponent, Error> {
    let (nu, ratio) = (problem.material().poisson_ratio(), problem.law().initial_ratio());
    match quick::no_zero(nu, &ratio, MODE_DIGITS) {
        Some(mode) => Ok(mode),
        None => mode_exponent(nu, &ratio, MODE_DIGITS),
    }
}

/// The material (E* = 1) of the mode check at `nu`, and `ratio` checked: the refusals of
/// [`mode_exponent`] (module `quick` takes its f64 path only where there is none).
fn mode_material(nu: &Q, ratio: &Q) -> Result<Material, Error> {
    let half = Q::new(1.into(), 2.into());
    if nu.is_negative() || *nu > half {
        return Err(Error::input("nu", nu, "must lie in [0, 1/2]"));
    }
    if ratio.is_negative() {
        return Err(Error::input("ratio", ratio, "n = P1/P2 >= 0 (the mirror image x -> -x gives n < 0)"));
    }
    Material::from_contact_modulus(nu.clone(), Q::from_integer(1.into()))
        .map_err(|e| Error::Input(ModelError { parameter: "nu".into(), ..e }))
}

/// The mode exponent at Poisson's ratio `nu` and n = `ratio` to `digits` digits (two runs, the
/// second with more bits and a finer rule).
pub fn mode_exponent(nu: &Q, ratio: &Q, digits: u32) -> Result<ModeExponent, Error> {
    let material = mode_material(nu, ratio)?;
    let bits = bits_for_digits(digits) + SOLVER_GUARD_BITS;
    let run = |extra: u32, refine: f64| -> Result<(Symbol, Option<Float>), Error> {
        let prec = bits + extra;
        let params = AdhesionParamsMpfr::new(&material, prec);
        let rule = TanhSinh::new(bits + extra, refine, prec);
        let ratio = to_float(ratio, prec);
        // The fast symbol decides where there is no zero: only the scan's signs matter then, and
        // its f_0, g_0 differ from the series solve's by 2^-(prec - 12) (test
        // `self_similar_equals_the_series_solve`), which moves det M by about that fraction of
        // its terms, against a screen bound near 1e-16 of them (2^-(prec - 12) = 5e-20 at the
        // 76 bits of 12 digits). A zero's value and digits come from the series solve's symbol,
        // as before (so they are unchanged).
        let sym = Symbol::new_fast(&params, &ratio, &rule, prec)?;
        let mu = sym.first_zero(MU_MAX);
        if mu.is_none() {
            return Ok((sym, mu));
        }
        let sym = Symbol::new(&params, &ratio, &rule, prec)?;
        let mu = sym.first_zero(MU_MAX);
        Ok((sym, mu))
    };
    // The two runs are independent: on two CPUs ([`crate::numerics::parallel`]; serially inside
    // another map's worker), the results as the serial runs'.
    let [first, second]: [Result<(Symbol, Option<Float>), Error>; 2] =
        crate::numerics::parallel::map(&[(0, 1.0), (VERIFY_EXTRA_BITS, 1.25)], |_, &(extra, refine)| {
            run(extra, refine)
        })
        .try_into()
        .unwrap_or_else(|_| unreachable!("parallel::map returns one result per item"));
    let (sym, mu) = first?;
    let (_, check) = second?;
    let cap = digits_cap_for_bits(bits);
    let digits = match (&mu, &check) {
        (Some(a), Some(b)) => verified_digits_mpfr(&Float::with_val(b.prec(), a - b), a, cap),
        (None, None) => cap,
        _ => 0.0,
    };
    let det_at_zero = sym.det(&Float::with_val(sym.prec, 0));
    Ok(ModeExponent { nu: nu.clone(), ratio: ratio.clone(), mu, digits, g0: sym.g0, det_at_zero })
}

impl ModeExponent {
    /// Even powers 2j <= `order` of lambda within 1 of mu* (near-resonant series coefficients).
    pub fn resonances(&self, order: usize) -> Vec<usize> {
        let Some(mu) = &self.mu else { return Vec::new() };
        let mu = mu.to_f64();
        (1..=order / 2).map(|j| 2 * j).filter(|&p| (mu - p as f64).abs() < 1.0).collect()
    }

    /// mu* printed to its verified digits (at most 12), or `None`.
    pub fn value_text(&self) -> Option<String> {
        self.mu.as_ref().map(|mu| {
            let scale = Float::with_val(mu.prec(), mu.abs_ref());
            crate::numerics::accuracy::print_mpfr(mu, &scale, self.digits, 12)
        })
    }

    /// The lines `series loading-law` prints after the coefficients (`order` the printed order).
    pub fn text(&self, order: usize) -> String {
        let what = format!("smallest real zero of det M(mu) on (0, {MU_MAX}], asymptotics::loading_law_modes");
        match self.value_text() {
            None => format!("\nhomogeneous mode: none found with a real exponent mu* <= {MU_MAX} ({what})\n"),
            Some(v) => {
                let res = self.resonances(order);
                let res = if res.is_empty() {
                    String::new()
                } else {
                    format!(
                        "; near-resonant (|mu* - 2j| < 1, coefficient divided by det M(2j)): {}",
                        res.iter().map(|p| format!("lambda^{p}")).collect::<Vec<_>>().join(", ")
                    )
                };
                format!(
                    "\nhomogeneous mode: mu* = {v} ({} digits verified; {what}): the loading law and both edge conditions fix the history only up to C eta^mu*; these coefficients are the member analytic in lambda^2 (C = 0){res}\n",
                    crate::numerics::accuracy::digits_text(self.digits)
                )
            }
        }
    }

    /// JSON: `{"exponent": string or null, "digits", "searched_to", "resonances": [powers]}`.
    pub fn json(&self, order: usize) -> serde_json::Value {
        serde_json::json!({
            "exponent": self.value_text(),
            "digits": self.mu.as_ref().map(|_| (self.digits * 10.0).round() / 10.0),
            "searched_to": MU_MAX,
            "resonances": self.resonances(order),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> Q {
        Q::new(n.into(), d.into())
    }

    /// nu = 0, n = 1/2 and 1/5: mu* = 31.8395100566 and 178.311153189 (the independent mpmath
    /// computation of the module doc), verified to >= 15 and >= 10 digits by the second run;
    /// nu = 3/10: no zero below MU_MAX at n = 1/5, 1/2.
    #[test]
    fn mode_exponent_against_mpmath() {
        let m = mode_exponent(&q(0, 1), &q(1, 2), 20).unwrap();
        let mu = m.mu.clone().expect("a zero at nu = 0, n = 1/2").to_f64();
        assert!((mu - 31.8395100566).abs() < 2e-10, "{mu}");
        assert!(m.digits >= 15.0, "{}", m.digits);
        assert!((m.g0.to_f64() + 0.208_502_536_975_995_35).abs() < 1e-15, "{}", m.g0);
        let m = mode_exponent(&q(0, 1), &q(1, 5), 12).unwrap();
        let mu = m.mu.clone().expect("a zero at nu = 0, n = 1/5").to_f64();
        assert!((mu - 178.311153189).abs() < 1e-7 && m.digits >= 10.0, "{mu} {}", m.digits);
        // n = 0: the close pair near mu = 604 (module doc), found by the finer rescan.
        let m = mode_exponent(&q(0, 1), &q(0, 1), 12).unwrap();
        let mu = m.mu.clone().expect("a zero at nu = 0, n = 0").to_f64();
        assert!((mu - 603.731091).abs() < 1e-5 && m.digits >= 9.0, "{mu} {}", m.digits);
        for n in [q(1, 5), q(1, 2)] {
            let m = mode_exponent(&q(3, 10), &n, 12).unwrap();
            assert!(m.mu.is_none(), "nu = 3/10, n = {n}: {:?}", m.mu);
        }
    }

    /// Toward the fold of the self-similar branch (nu = 0) mu* and det M(0) fall to 0 together:
    /// n = 1: mu* = 1.0875, det M(0) = -3.21; n = 26/25: mu* = 0.19998, det M(0) = -1.00.
    #[test]
    fn mode_reaches_zero_at_the_fold() {
        let a = mode_exponent(&q(0, 1), &q(1, 1), 12).unwrap();
        let b = mode_exponent(&q(0, 1), &q(26, 25), 12).unwrap();
        let (ma, mb) = (a.mu.unwrap().to_f64(), b.mu.unwrap().to_f64());
        assert!((ma - 1.08745322144).abs() < 1e-9 && (mb - 0.199975078035).abs() < 1e-9, "{ma} {mb}");
        let (da, db) = (a.det_at_zero.to_f64(), b.det_at_zero.to_f64());
        assert!((da + 3.2127).abs() < 1e-3 && (db + 1.0006).abs() < 1e-3, "{da} {db}");
    }

    /// No complex zeros below the real one: at nu = 0, n = 1/2 the argument principle counts no
    /// zero of det M in [-0.9, 31] x [-40, 40] and exactly one (mu* = 31.84) in [31, 33] x [-1, 1];
    /// at nu = 3/10, n = 1/2 none in [-0.9, 300] x [-40, 40].
    #[test]
    fn no_complex_zero_below_the_mode() {
        // 160 bits: at 96 (rule of 80 bits) the rule misses s^(mu+1) near s = 0 at Re mu -> -1,
        // |Im mu| ~ 40 and the count is 4 spurious zeros in [-0.9, -0.5] x [-40, 40].
        let prec = 160;
        let material = Material::from_contact_modulus(q(0, 1), q(1, 1)).unwrap();
        let params = AdhesionParamsMpfr::new(&material, prec);
        let rule = TanhSinh::new(prec - 16, 1.0, prec);
        let sym = Symbol::new(&params, &Float::with_val(prec, 0.5), &rule, prec).unwrap();
        let real = sym.det(&Float::with_val(prec, 20)).to_f64();
        let complex = sym.det_complex(&Complex::with_val(prec, (20, 0))).real().to_f64();
        assert!((real - complex).abs() < 1e-20 * real.abs(), "{real} {complex}");
        assert_eq!(sym.zeros_in((-0.9, 31.0), (-40.0, 40.0)), 0);
        assert_eq!(sym.zeros_in((31.0, 33.0), (-1.0, 1.0)), 1);
        let material = Material::from_contact_modulus(q(3, 10), q(1, 1)).unwrap();
        let params = AdhesionParamsMpfr::new(&material, prec);
        let sym = Symbol::new(&params, &Float::with_val(prec, 0.5), &rule, prec).unwrap();
        assert_eq!(sym.zeros_in((-0.9, 300.0), (-40.0, 40.0)), 0);
    }

    /// The f64 screen (module `screen`): its bound holds against the MPFR determinant at every
    /// point of the scan grid and decides the sign at almost all of them; the scan with the screen
    /// finds bit for bit the zero the all-MPFR scan finds (the screen switched off), including the
    /// close pair at n = 0 that only the finer rescan finds, and none where there is none.
    #[test]
    fn the_screen_decides_as_mpfr_does() {
        let prec = bits_for_digits(12) + SOLVER_GUARD_BITS;
        for (nu, n) in [(q(0, 1), 0.5), (q(0, 1), 0.0), (q(0, 1), 0.2), (q(3, 10), 0.2), (q(1, 10), 1.0)] {
            let material = Material::from_contact_modulus(nu.clone(), q(1, 1)).unwrap();
            let params = AdhesionParamsMpfr::new(&material, prec);
            let rule = TanhSinh::new(prec - SOLVER_GUARD_BITS, 1.0, prec);
            let sym = Symbol::new(&params, &Float::with_val(prec, n), &rule, prec).unwrap();
            let screen = sym.screen.clone().expect("screened at this precision");
            let (mut decided, mut total) = (0, 0);
            for mu in [0.0, 0.5, 1.0, 2.5, 7.0, 31.0, 99.0, 178.0, 250.0, 603.5, 1000.0, 1999.0] {
                let a = screen.det(mu);
                let exact = sym.det(&Float::with_val(prec, mu)).to_f64();
                assert!((a.value - exact).abs() <= a.bound, "nu = {nu}, n = {n}, mu = {mu}: {a:?} vs {exact}");
                assert!(a.bound < 1e-9 * (1.0 + exact.abs()), "{a:?}");
                total += 1;
                if let Some(neg) = a.negative() {
                    assert_eq!(neg, exact < 0.0);
                    decided += 1;
                }
            }
            assert!(decided + 1 >= total, "nu = {nu}, n = {n}: {decided} of {total} decided");
            let mut plain = sym.clone();
            plain.screen = None;
            let (with, without) = (sym.first_zero(MU_MAX), plain.first_zero(MU_MAX));
            match (&with, &without) {
                (Some(a), Some(b)) => assert!(a == b && a.prec() == b.prec(), "nu = {nu}, n = {n}: {a} vs {b}"),
                (None, None) => {}
                _ => panic!("nu = {nu}, n = {n}: {with:?} vs {without:?}"),
            }
        }
        let low = Symbol::new(
            &AdhesionParamsMpfr::new(&Material::from_contact_modulus(q(0, 1), q(1, 1)).unwrap(), 60),
            &Float::with_val(60, 0.5),
            &TanhSinh::new(40, 1.0, 60),
            60,
        )
        .unwrap();
        assert!(low.screen.is_none(), "below MIN_PREC the scan is all MPFR");
    }

    /// Bad input names the parameter.
    #[test]
    fn refuses_bad_input() {
        let e = mode_exponent(&q(3, 5), &q(1, 5), 12).unwrap_err().to_string();
        assert!(e.contains("nu") && e.contains("3/5") && e.contains("[0, 1/2]"), "{e}");
        let e = mode_exponent(&q(0, 1), &q(-1, 5), 12).unwrap_err().to_string();
        assert!(e.contains("ratio") && e.contains("-1/5"), "{e}");
    }

    /// At mu = 2j the symbol is the series' matrix of order j: the coefficient g_j of c/l is
    /// divided by det M(2j), so the series' coefficients jump where mu* passes 2j (nu = 0, n =
    /// 1/2: mu* in (30, 32), g_15 < 0 < g_16, |g_16/g_15| > 300).
    #[test]
    #[ignore = "long tier: 11 s alone in the test profile (opt-level 2) on a loaded 2-core machine (scripts/test --long)"]
    fn series_resonates_at_the_mode() {
        let prec = 160;
        let material = Material::from_contact_modulus(q(0, 1), q(1, 1)).unwrap();
        let params = AdhesionParamsMpfr::new(&material, prec);
        let rule = TanhSinh::new(prec - 20, 1.0, prec);
        let n = Float::with_val(prec, 0.5);
        let sym = Symbol::new(&params, &n, &rule, prec).unwrap();
        let d30 = sym.det(&Float::with_val(prec, 30)).to_f64();
        let d32 = sym.det(&Float::with_val(prec, 32)).to_f64();
        assert!(d30 < 0.0 && d32 > 0.0 && d32 < 0.1, "det M(30) = {d30}, det M(32) = {d32}");
        let e = law_coefficients(&params, &n, 17, &rule, prec).unwrap();
        let (g15, g16) = (e.g[15].to_f64(), e.g[16].to_f64());
        assert!(g15 < 0.0 && g16 > 0.0 && g16 / -g15 > 300.0, "g_15 = {g15}, g_16 = {g16}");
    }
}
