//! Method 1 (MPFR): Chebyshev collocation of the Volterra equation of the first kind of the
//! incremental method, THEORY.md section 4 (Mossakovskii; the paper's (2.19) with a growing
//! contact).
//!
//! Writing P2 = E* k (L/pi)^2 P(lambda), P'(eta) = eta f(eta^2) and, at a given lambda,
//! F(tau) = f(lambda^2 tau) on tau in [0, 1], the equation
//! int_0^chi Re K(chi, eta) P'(eta) d eta = pi chi becomes, with eta = chi s and chi = lambda sigma
//! (see [`super::kernel`]),
//!   Re I(sigma) = pi,   I(sigma) = int_0^1 s w(s) G(lambda sigma, s) F(sigma^2 s^2) ds,
//! for sigma in (0, 1]. F is analytic on [0, 1] (its nearest singularity is at
//! tau = (pi/(2 lambda))^2, full contact; at eps = 0, f(t) = pi tan(sqrt t)/sqrt t), so a Chebyshev
//! interpolant in tau with n nodes converges like rho^-n, rho = z + sqrt(z^2 - 1),
//! z = 2 (pi/(2 lambda))^2 - 1. Collocation at the Chebyshev nodes tau_i = sigma_i^2, integrals by
//! tanh-sinh ([`super::tanh_sinh`]), real n x n system by Gaussian elimination.
//! Then (THEORY.md section 4):
//!   P2/(E* k a^2) = (1/2) int_0^1 F(tau) d tau,
//!   psi/(k a) = -(2 sigma/pi) Im I(sigma),
//!   phi/(k a^2) = -(1/pi) int_0^{sigma^2} Im I(sqrt tau) d tau,
//! and the stresses by [`super::kernel::stress_integrand`].
//! lambda = 0 is the single punch (G = 1, F = pi/Re M_1 constant: self-similar).
//!
//! # Conditioning (measured; THEORY.md section 7)
//! For nu = 1/2 (eps = 0) and nu >= 0.45 the method verifies 20+ digits up to lambda ~ 1.49.
//! For small nu it breaks down at a moderate contact size: verified digits of P2 at 20 requested
//! (`adhesion_chart_conditioning`): nu = 0: 31 (lambda <= 0.47), 27 (0.63), 22 (0.79), 6 (0.94),
//! 2 (1.10), 0 beyond; nu = 0.3: >= 26 up to 1.26, 3 at 1.41, no convergence at 1.49.
//! Mechanism (a hypothesis supported by the following facts, not a proof): the kernel Re K is the
//! real part of an Abel kernel (chi - eta)^{-1/2 - i eps}, so on powers eta^{2n+1} the operator
//! acts, at lambda -> 0, by the factor Re M_{2n+1}; Re M_m changes sign at m ~ 605 for nu = 0
//! (m ~ 2285 for nu = 0.1, beyond 2e5 for nu = 0.3; computed from the recurrence for M_m), and the
//! phase of the near-diagonal coefficient cos(chi(1 - 2 i eps)) (sin 2 chi)^{i eps} grows with chi,
//! bringing the sign change down to low degrees as lambda grows: the first-kind equation then has
//! (near-)homogeneous solutions and the discrete problem loses digits without bound. The same
//! factor 1/Re M_{2n+1} enters the lambda^2 series (see [`super::series_f64`]).
//! A second chart (`adhesion_chart_singularity_location`, 200-bit runs) reads the decay rate rho
//! of the Chebyshev coefficients of F on [0, lambda^2] and the real singularity t_s it implies
//! (z = 2 t_s/lambda^2 - 1, rho = z + sqrt(z^2 - 1)): nu = 0.3 gives a stable
//! t_s = 2.05-2.10 for lambda = 0.4-0.8, i.e. f = P'(eta)/eta is singular at a real
//! eta_s ~ 1.43-1.45 < pi/2 (consistent with the breakdown between lambda = 1.26 and 1.41);
//! nu = 0 gives t_s ~ 0.75-1.07 (eta_s ~ 0.86-1.04, drifting with lambda). With the gradual loss
//! of digits beyond it (nu = 0: 6 digits at 0.94, 2 at 1.10), this points to a weak real-axis
//! singularity of the incremental solution at eta_s(nu) < pi/2 (eta_s -> pi/2 as nu -> 1/2), which
//! also bounds the radius of the lambda^2 series. Its nature (a non-analytic term of high order
//! vs a blow-up of dP2/da) is not settled here; a composite basis split at eta_s would be the
//! remedy for the method.
//! `solve_verified` reports the loss (fewer verified digits, and a typed error below 2 digits).

use super::chebyshev;
use crate::params::adhesion as constants;
use super::error::AdhesionError;
use super::kernel;
use super::tanh_sinh::TanhSinh;
use crate::model::{Exact, Material};
use crate::numerics::exact::to_float;
use rug::float::Constant;
use rug::ops::Pow;
use rug::{Complex, Float};

/// Largest collocation size accepted; beyond it lambda is too close to pi/2.
pub const MAX_NODES: usize = 320;

/// Discretisation of one run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VolterraParams {
    /// Working precision in bits.
    pub prec: u32,
    /// Target accuracy in bits (sets the node counts).
    pub target_bits: u32,
    /// Extra refinement of the quadrature step and the Chebyshev size (1 = nominal).
    pub refine: f64,
}

impl VolterraParams {
    /// Nominal parameters for `digits` decimal digits.
    pub fn for_digits(digits: u32) -> Self {
        let target_bits = (digits as f64 * std::f64::consts::LOG2_10).ceil() as u32 + 8;
        VolterraParams { prec: target_bits + 32, target_bits, refine: 1.0 }
    }
    /// The verification run: more bits, more nodes, finer quadrature.
    pub fn refined(&self) -> Self {
        VolterraParams { prec: self.prec + 24, target_bits: self.target_bits + 16, refine: self.refine * 1.15 }
    }
}

/// Chebyshev size for accuracy 2^-bits at this lambda (see module doc), or an error near pi/2.
pub fn chebyshev_size(lambda: f64, bits: u32, refine: f64) -> Result<usize, AdhesionError> {
    if lambda <= 0.0 {
        return Ok(2);
    }
    let half_pi = std::f64::consts::FRAC_PI_2;
    let tau_star = (half_pi / lambda).powi(2);
    let z = 2.0 * tau_star - 1.0;
    // Observed (nu = 0) slower decay (rho ~ 2 + 3.2/lambda^2 at lambda = pi/5): cap rho so the
    // first size is usually sufficient and the adaptive re-solve rare.
    let rho = (z + (z * z - 1.0).max(0.0).sqrt()).min(2.0 + 3.0 / (lambda * lambda));
    let n = ((bits as f64 * std::f64::consts::LN_2 / rho.ln()) * refine).ceil() as usize + 4;
    if !(n <= MAX_NODES) {
        return Err(AdhesionError::IllConditioned {
            method: "mpfr-volterra",
            parameter: "lambda",
            value: format!("{lambda}"),
            valid: format!("lambda = pi a/L well below pi/2 (here {n} > {MAX_NODES} Chebyshev nodes would be needed)"),
            reason: "the solution is singular at full contact lambda = pi/2; the interpolant converges like ((pi/2 - lambda)/pi)^(n/2)".into(),
        });
    }
    Ok(n)
}

/// The dimensionless solution at one lambda.
#[derive(Debug, Clone)]
pub struct VolterraSolution {
    /// Working precision.
    pub prec: u32,
    /// lambda = pi a/L (0 for the single punch).
    pub lambda: Float,
    /// eps.
    pub eps: Float,
    /// cosh(pi eps).
    pub cosh_pi_eps: Float,
    /// Chebyshev coefficients of F(tau) = f(lambda^2 tau).
    pub f_coeffs: Vec<Float>,
    /// Chebyshev coefficients of J(tau) = Im I(sqrt tau).
    pub j_coeffs: Vec<Float>,
    /// Largest |Re I(sigma) - pi| found at off-collocation check points (a residual).
    pub residual: f64,
    /// Ratio of largest to smallest pivot of the collocation matrix (conditioning indicator).
    pub pivot_ratio: f64,
    rule: TanhSinh,
    pre: kernel::VolterraNodes,
}

/// Solves the Volterra equation at `lambda` (0 <= lambda < pi/2), choosing the Chebyshev size
/// adaptively: a first size from [`chebyshev_size`], then, while the last three coefficients are
/// not below 2^-target_bits |c_0|, a larger size from the observed geometric decay (at most four
/// times). The a priori estimate assumes the singularity at full contact only; for eps > 0 the
/// coefficients decay more slowly (observed at nu = 0: ratio ~1/10 per coefficient at
/// lambda = pi/5 instead of the predicted 1/23; see the module doc on conditioning), hence the
/// a posteriori check.
pub fn solve(material: &Material, lambda: &Float, params: VolterraParams) -> Result<VolterraSolution, AdhesionError> {
    let mut n = chebyshev_size(lambda.to_f64(), params.target_bits, params.refine)?;
    let goal = (params.target_bits as f64) * std::f64::consts::LN_2;
    for _ in 0..5 {
        let sol = solve_with_nodes(material, lambda, params, n)?;
        let c: Vec<f64> = sol.f_coeffs.iter().map(|x| x.clone().abs().to_f64()).collect();
        let c0 = c[0].max(f64::MIN_POSITIVE);
        let m = c.len();
        if m < 8 {
            return Ok(sol);
        }
        let tail = c[m - 3..].iter().cloned().fold(0f64, f64::max) / c0;
        let tail_ln = if tail > 0.0 { tail.ln() } else { -goal - 1.0 };
        if tail_ln <= -goal {
            return Ok(sol);
        }
        // Decay rate from the second half of the coefficients.
        let h = m / 2;
        let first = c[h..h + 3].iter().cloned().fold(0f64, f64::max) / c0;
        let rate = ((first.ln() - tail_ln) / ((m - 3 - h) as f64)).max(0.05);
        let extra = ((tail_ln + goal) / rate).ceil() as usize + 4;
        n = (n + extra).max(n + 4);
        if n > MAX_NODES {
            return Err(AdhesionError::IllConditioned {
                method: "mpfr-volterra",
                parameter: "lambda",
                value: format!("{}", lambda.to_f64()),
                valid: format!("a contact for which {MAX_NODES} Chebyshev nodes suffice"),
                reason: format!("Chebyshev coefficients decay too slowly (rate {rate:.3} per node)"),
            });
        }
    }
    Err(AdhesionError::NotConverged { what: "adaptive Chebyshev size", reason: "five enlargements".into() })
}

/// Solves with exactly `n` Chebyshev nodes.
pub fn solve_with_nodes(
    material: &Material,
    lambda: &Float,
    params: VolterraParams,
    n: usize,
) -> Result<VolterraSolution, AdhesionError> {
    let prec = params.prec;
    let eps = constants::eps(material, prec);
    let cosh_pi_eps = constants::cosh_pi_eps(material, prec);
    let rule = TanhSinh::new(params.target_bits + 8, params.refine, prec);
    let pre = kernel::VolterraNodes::new(&rule.s, &rule.c, prec);
    let tau = chebyshev::nodes(n, prec);
    let pi = Float::with_val(prec, Constant::Pi);
    // Rows: A_ij = sum_q Re z_iq T_j(x_iq), x_iq = 2 tau_i s_q^2 - 1; keep Im z_iq, x_iq for J.
    let mut a = vec![vec![Float::with_val(prec, 0); n]; n];
    let mut keep: Vec<Vec<(Float, Float)>> = Vec::with_capacity(n);
    let mut tj = vec![Float::with_val(prec, 0); n];
    for i in 0..n {
        let sigma = Float::with_val(prec, tau[i].sqrt_ref());
        let chi = Float::with_val(prec, lambda * &sigma);
        let sc_chi = chi.clone().sin_cos(Float::new(prec));
        let mut row_keep = Vec::with_capacity(rule.len());
        for q in 0..rule.len() {
            let (re, im) = pre.integrand(q, &rule.s[q], &rule.c[q], &chi, &sc_chi, &eps, prec);
            let re = re * &rule.w[q];
            let im = im * &rule.w[q];
            let x = Float::with_val(prec, &tau[i] * &pre.s2[q]) * 2u32 - 1u32;
            chebyshev_values(&x, &mut tj, prec);
            for j in 0..n {
                a[i][j] += Float::with_val(prec, &re * &tj[j]);
            }
            row_keep.push((im, x));
        }
        keep.push(row_keep);
    }
    let rhs = vec![pi.clone(); n];
    let (f_coeffs, pivot_ratio) = gauss_solve(a, rhs, prec)?;
    let j_values: Vec<Float> = keep
        .iter()
        .map(|row| {
            let mut acc = Float::with_val(prec, 0);
            for (im, x) in row {
                acc += chebyshev::evaluate(&f_coeffs, x, prec) * im;
            }
            acc
        })
        .collect();
    let j_coeffs = chebyshev::coefficients(&j_values, prec);
    let mut sol = VolterraSolution {
        prec,
        lambda: Float::with_val(prec, lambda),
        eps,
        cosh_pi_eps,
        f_coeffs,
        j_coeffs,
        residual: 0.0,
        pivot_ratio,
        rule,
        pre,
    };
    // Residual of Re I = pi between collocation nodes (a posteriori check).
    let mut res = 0f64;
    for k in 0..4 {
        let sg = Float::with_val(prec, 0.13 + 0.29 * k as f64);
        let (re, _) = sol.integral_i(&sg);
        res = res.max(Float::with_val(prec, re - &pi).abs().to_f64());
    }
    sol.residual = res;
    Ok(sol)
}

/// T_0..T_{n-1} at x.
fn chebyshev_values(x: &Float, out: &mut [Float], prec: u32) {
    let n = out.len();
    if n == 0 {
        return;
    }
    out[0] = Float::with_val(prec, 1u32);
    if n > 1 {
        out[1] = x.clone();
    }
    for j in 2..n {
        let t = Float::with_val(prec, x * &out[j - 1]) * 2u32 - &out[j - 2];
        out[j] = t;
    }
}

/// Gaussian elimination with partial pivoting; returns the solution and max/min |pivot|.
fn gauss_solve(mut a: Vec<Vec<Float>>, mut b: Vec<Float>, prec: u32) -> Result<(Vec<Float>, f64), AdhesionError> {
    let n = b.len();
    let (mut pmax, mut pmin) = (0f64, f64::INFINITY);
    for k in 0..n {
        let p = (k..n)
            .max_by(|&i, &j| {
                a[i][k].clone().abs().partial_cmp(&a[j][k].clone().abs()).unwrap_or(std::cmp::Ordering::Equal)
            })
            .unwrap_or(k);
        a.swap(k, p);
        b.swap(k, p);
        let piv = a[k][k].clone();
        let pa = piv.clone().abs().to_f64();
        if !(pa > 0.0) || !pa.is_finite() {
            return Err(AdhesionError::NotConverged {
                what: "collocation solve",
                reason: format!("zero or non-finite pivot at column {k}"),
            });
        }
        pmax = pmax.max(pa);
        pmin = pmin.min(pa);
        for i in k + 1..n {
            let m = Float::with_val(prec, &a[i][k] / &piv);
            if m.is_zero() {
                continue;
            }
            for j in k..n {
                let t = Float::with_val(prec, &m * &a[k][j]);
                a[i][j] -= t;
            }
            let t = Float::with_val(prec, &m * &b[k]);
            b[i] -= t;
        }
    }
    let mut x = vec![Float::with_val(prec, 0); n];
    for k in (0..n).rev() {
        let mut acc = b[k].clone();
        for j in k + 1..n {
            acc -= Float::with_val(prec, &a[k][j] * &x[j]);
        }
        x[k] = acc / &a[k][k];
    }
    Ok((x, pmax / pmin))
}

impl VolterraSolution {
    /// The solution at a smaller lambda' <= lambda without re-solving: f(t) does not depend on
    /// lambda, so F'(tau) = F(tau lambda'^2/lambda^2) and J'(tau) = J(tau lambda'^2/lambda^2)
    /// (I depends on chi only); both re-interpolated at the same number of Chebyshev nodes.
    pub fn restrict(&self, lambda_new: &Float) -> VolterraSolution {
        let prec = self.prec;
        let n = self.f_coeffs.len();
        let ratio = if self.lambda.is_zero() {
            Float::with_val(prec, 0)
        } else {
            Float::with_val(prec, lambda_new / &self.lambda).square()
        };
        let tau = chebyshev::nodes(n, prec);
        let resample = |c: &[Float]| {
            let vals: Vec<Float> = tau
                .iter()
                .map(|t| {
                    let x = Float::with_val(prec, t * &ratio) * 2u32 - 1u32;
                    chebyshev::evaluate(c, &x, prec)
                })
                .collect();
            chebyshev::coefficients(&vals, prec)
        };
        VolterraSolution {
            prec,
            lambda: Float::with_val(prec, lambda_new),
            eps: self.eps.clone(),
            cosh_pi_eps: self.cosh_pi_eps.clone(),
            f_coeffs: resample(&self.f_coeffs),
            j_coeffs: resample(&self.j_coeffs),
            residual: self.residual,
            pivot_ratio: self.pivot_ratio,
            rule: self.rule.clone(),
            pre: self.pre.clone(),
        }
    }

    /// A copy rounded to `bits` (>= 53) with a quadrature rule for that accuracy: for cheap
    /// evaluations that need only a few digits (locating tension zones).
    pub fn reduced(&self, bits: u32) -> VolterraSolution {
        let prec = bits.max(53);
        let rule = TanhSinh::new(prec - 8, 1.0, prec);
        let pre = kernel::VolterraNodes::new(&rule.s, &rule.c, prec);
        let r = |v: &[Float]| v.iter().map(|x| Float::with_val(prec, x)).collect::<Vec<_>>();
        VolterraSolution {
            prec,
            lambda: Float::with_val(prec, &self.lambda),
            eps: Float::with_val(prec, &self.eps),
            cosh_pi_eps: Float::with_val(prec, &self.cosh_pi_eps),
            f_coeffs: r(&self.f_coeffs),
            j_coeffs: r(&self.j_coeffs),
            residual: self.residual,
            pivot_ratio: self.pivot_ratio,
            rule,
            pre,
        }
    }

    /// I(sigma) = int_0^1 s w(s) G(lambda sigma, s) F(sigma^2 s^2) ds as (re, im); Re I = pi.
    pub fn integral_i(&self, sigma: &Float) -> (Float, Float) {
        let prec = self.prec;
        let chi = Float::with_val(prec, &self.lambda * sigma);
        let sc_chi = chi.clone().sin_cos(Float::new(prec));
        let sig2 = Float::with_val(prec, sigma * sigma);
        let (mut sr, mut si) = (Float::with_val(prec, 0), Float::with_val(prec, 0));
        for q in 0..self.rule.len() {
            let (re, im) = self.pre.integrand(q, &self.rule.s[q], &self.rule.c[q], &chi, &sc_chi, &self.eps, prec);
            let x = Float::with_val(prec, &sig2 * &self.pre.s2[q]) * 2u32 - 1u32;
            let fw = chebyshev::evaluate(&self.f_coeffs, &x, prec) * &self.rule.w[q];
            sr += Float::with_val(prec, &re * &fw);
            si += Float::with_val(prec, &im * &fw);
        }
        (sr, si)
    }

    /// P2/(E* k a^2) = (1/2) int_0^1 F.
    pub fn load_ratio(&self) -> Float {
        let one = Float::with_val(self.prec, 1u32);
        chebyshev::integral(&self.f_coeffs, &one, self.prec) / 2u32
    }

    /// F(tau) = f(lambda^2 tau), i.e. P'(eta) = eta F(eta^2/lambda^2).
    pub fn f_at(&self, tau: &Float) -> Float {
        let x = Float::with_val(self.prec, tau * 2u32) - 1u32;
        chebyshev::evaluate(&self.f_coeffs, &x, self.prec)
    }

    /// psi/(k a) at sigma = x/a in [0, 1]: -(2 sigma/pi) Im I(sigma).
    pub fn psi_ratio(&self, sigma: &Float) -> Float {
        let (_, im) = self.integral_i(sigma);
        let pi = Float::with_val(self.prec, Constant::Pi);
        -(im * sigma * 2u32) / pi
    }

    /// phi/(k a^2) at sigma: -(1/pi) int_0^{sigma^2} J.
    pub fn phi_ratio(&self, sigma: &Float) -> Float {
        let t = Float::with_val(self.prec, sigma * sigma);
        let pi = Float::with_val(self.prec, Constant::Pi);
        -chebyshev::integral(&self.j_coeffs, &t, self.prec) / pi
    }

    /// (q2, q1)/(E* k a) at the exact point sigma = x/a in [0, 1] (1 - sigma^2 rounded once).
    pub fn stress_ratio(&self, sigma_exact: &Exact) -> (Float, Float) {
        let prec = self.prec;
        let one = Exact::from_integer(1.into());
        let omss_exact = &one - sigma_exact * sigma_exact;
        if omss_exact <= Exact::from_integer(0.into()) {
            return (Float::with_val(prec, 0), Float::with_val(prec, 0));
        }
        self.stress_ratio_float(&to_float(sigma_exact, prec), &to_float(&omss_exact, prec))
    }

    /// (q2, q1)/(E* k a) at distance delta = 1 - x/a from the edge, 0 < delta <= 1.
    pub fn stress_ratio_near_edge(&self, delta: &Float) -> (Float, Float) {
        let prec = self.prec;
        let sigma = Float::with_val(prec, 1u32) - delta;
        let omss = Float::with_val(prec, 2u32) - delta;
        let omss = omss * delta;
        self.stress_ratio_float(&sigma, &omss)
    }

    fn stress_ratio_float(&self, sigma: &Float, omss: &Float) -> (Float, Float) {
        let prec = self.prec;
        let (mut sr, mut si) = (Float::with_val(prec, 0), Float::with_val(prec, 0));
        let pi = Float::with_val(prec, Constant::Pi);
        if !sigma.is_zero() && *sigma < 0.5f64 {
            // v-form: r = sigma cosh v, v in (0, V), V = acosh(1/sigma).
            let big_v = Float::with_val(prec, sigma.recip_ref()).acosh();
            for q in 0..self.rule.len() {
                let v = Float::with_val(prec, &big_v * &self.rule.s[q]);
                let (re, im, r2) = kernel::stress_integrand_v(sigma, &v, &self.lambda, &self.eps, prec);
                let fw = self.f_at(&r2) * &self.rule.w[q];
                sr += Float::with_val(prec, &re * &fw);
                si += Float::with_val(prec, &im * &fw);
            }
            let scale = Float::with_val(prec, &big_v * &self.cosh_pi_eps) / pi;
            return (sr * &scale, si * &scale);
        }
        for q in 0..self.rule.len() {
            let (re, im, r2) = kernel::stress_integrand(sigma, omss, &self.rule.s[q], &self.lambda, &self.eps, prec);
            let fw = self.f_at(&r2) * &self.rule.w[q];
            sr += Float::with_val(prec, &re * &fw);
            si += Float::with_val(prec, &im * &fw);
        }
        let scale = Float::with_val(prec, omss.sqrt_ref()) * &self.cosh_pi_eps / pi;
        (sr * &scale, si * &scale)
    }

    /// Edge stress factor C: (q2 + i q1)/(E* k a) = C delta^{1/2 - i eps} (1 + O(delta)),
    /// delta = 1 - x/a -> 0, with
    /// C = (cosh(pi eps)/pi) 2^{1/2 + i eps}/(1 - 2 i eps) cos(lambda (1 - 2 i eps))
    ///     sinc(2 lambda)^{i eps - 1/2} F(1)
    /// (leading term of the stress integral at the edge, derived from [`super::kernel`]).
    pub fn edge_stress_factor(&self) -> Complex {
        let prec = self.prec;
        let one = Float::with_val(prec, 1u32);
        let f1 = self.f_at(&one);
        let pi = Float::with_val(prec, Constant::Pi);
        let i_eps = Complex::with_val(prec, (0, &self.eps));
        let two = Complex::with_val(prec, 2u32);
        let p = two.pow(Complex::with_val(prec, (0.5f64, &self.eps)));
        let den = Complex::with_val(prec, 1u32) - Complex::with_val(prec, &i_eps * 2u32);
        let arg = Complex::with_val(prec, (&self.lambda, Float::with_val(prec, &self.lambda * &self.eps) * -2i32));
        let cosv = arg.cos();
        let sn = kernel::sinc(&Float::with_val(prec, &self.lambda * 2u32), prec);
        let snp = Complex::with_val(prec, sn).pow(Complex::with_val(prec, (-0.5f64, &self.eps)));
        p / den * cosv * snp * f1 * &self.cosh_pi_eps / pi
    }
}

/// lambda = pi a / L from exact a, L.
pub fn lambda_of(a: &Exact, l: &Exact, prec: u32) -> Float {
    let r = to_float(&(a / l), prec + 8);
    Float::with_val(prec, r * Float::with_val(prec + 8, Constant::Pi))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn material(nu: (i64, i64)) -> Material {
        Material::from_contact_modulus(Exact::new(nu.0.into(), nu.1.into()), Exact::from_integer(1.into())).unwrap()
    }

    #[test]
    fn adhesion_kuznetsov_f_is_pi_tan() {
        // eps = 0: P' = pi tan eta (Kuznetsov), i.e. F(tau) = pi tan(lambda sqrt tau)/(lambda sqrt tau).
        let prec = 120;
        let lam = Float::with_val(prec, 0.5);
        let sol = solve(&material((1, 2)), &lam, VolterraParams::for_digits(25)).unwrap();
        for t in [0.0, 0.3, 0.77, 1.0] {
            let tau = Float::with_val(prec, t);
            let eta = Float::with_val(prec, tau.sqrt_ref()) * &lam;
            let want = if t == 0.0 {
                Float::with_val(prec, Constant::Pi)
            } else {
                Float::with_val(prec, eta.tan_ref()) / &eta * Float::with_val(prec, Constant::Pi)
            };
            let err = Float::with_val(prec, sol.f_at(&tau) - want).abs().to_f64();
            assert!(err < 1e-24, "tau {t}: {err:e}");
        }
    }
}
