//! The dimensionless solution of the Volterra equation at one lambda (module doc of [`super`]):
//! F and J as Chebyshev series, and from them the load, psi, phi, the stresses and the edge
//! stress factor; restriction to a smaller lambda and rounding to fewer bits.
//!
//! The variable of the interpolants: in the `paper` convention P'(eta)/eta is even in eta, so F
//! and J are interpolated in tau = sigma^2 (sigma = eta/lambda); in the `periodic` convention
//! (a [`kernel::LateralShift`]) the kernel carries odd powers and they are interpolated in sigma:
//! P'(eta) = eta F(eta/lambda), P2/(E* k a^2) = int_0^1 sigma F(sigma) d sigma,
//! phi/(k a^2) = -(2/pi) int_0^sigma s J(s) ds with J(s) = Im I(s).

use super::kernel;
use crate::model::Exact;
use crate::numerics::chebyshev;
use crate::numerics::exact::to_float;
use crate::numerics::tanh_sinh::TanhSinh;
use rug::float::Constant;
use rug::ops::Pow;
use rug::{Complex, Float};
use std::sync::Arc;
use std::sync::OnceLock;

/// How the coefficients of J(tau) = Im I(sqrt tau) are computed when first asked: J costs as much
/// as the collocation matrix (a Clenshaw sum of n terms per pair (i, q)) and only phi uses it, so
/// a solve keeps what J needs and computes it once, on demand, with the same operations (the same
/// bits) as when it was computed in the solve.
#[derive(Debug, Clone)]
pub(super) enum JSource {
    /// From the collocation rows: per Chebyshev node tau_i, the pairs (w_q Im z_iq, x_iq)
    /// ([`super::solve`]); J(tau_i) = sum_q w_q Im z_iq F(x_iq).
    Rows(Arc<Vec<Vec<(Float, Float)>>>),
    /// J of a solution at a larger lambda, re-interpolated at tau (lambda'/lambda)^2 (the ratio).
    Restricted(Box<VolterraSolution>, Float),
    /// J of a solution rounded to this one's precision.
    Reduced(Box<VolterraSolution>),
}

/// The Chebyshev coefficients (in x = 2 t - 1) of t F(t) from those of F.
fn times_t(c: &[Float], prec: u32) -> Vec<Float> {
    // t = (1 + x)/2, x T_0 = T_1, x T_k = (T_(k+1) + T_(k-1))/2.
    let n = c.len();
    let mut out: Vec<Float> = c.iter().map(|x| Float::with_val(prec, x / 2u32)).collect();
    out.push(Float::with_val(prec, 0));
    for (k, ck) in c.iter().enumerate() {
        let q = Float::with_val(prec, ck / 4u32);
        if k == 0 {
            out[1] += Float::with_val(prec, ck / 2u32);
        } else {
            out[k + 1] += &q;
            out[k - 1] += &q;
        }
    }
    debug_assert_eq!(out.len(), n + 1);
    out
}

/// The Chebyshev coefficients of c(tau ratio) at the n Chebyshev nodes of tau in [0, 1].
fn resample(c: &[Float], ratio: &Float, n: usize, prec: u32) -> Vec<Float> {
    let tau = chebyshev::nodes(n, prec);
    let vals: Vec<Float> = tau
        .iter()
        .map(|t| {
            let x = Float::with_val(prec, t * ratio) * 2u32 - 1u32;
            chebyshev::evaluate(c, &x, prec)
        })
        .collect();
    chebyshev::coefficients(&vals, prec)
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
    /// Chebyshev coefficients of F(tau) = f(lambda^2 tau) (`paper`), or of F(sigma) (`periodic`,
    /// module doc).
    pub f_coeffs: Vec<Float>,
    /// The `periodic` convention's kernel change (None: `paper`, and the single punch).
    pub shift: Option<kernel::LateralShift>,
    /// Where the Chebyshev coefficients of J(tau) = Im I(sqrt tau) come from ([`Self::j_coeffs`]).
    pub(super) j_source: JSource,
    /// Those coefficients, computed when first asked (only phi needs them).
    pub(super) j_coeffs: OnceLock<Vec<Float>>,
    /// Largest |Re I(sigma) - pi| found at off-collocation check points (a residual).
    pub residual: f64,
    /// Ratio of largest to smallest pivot of the collocation matrix (conditioning indicator).
    pub pivot_ratio: f64,
    pub(super) rule: TanhSinh,
    pub(super) pre: kernel::VolterraNodes,
}

impl VolterraSolution {
    /// The solution at a smaller lambda' <= lambda without re-solving: f(t) does not depend on
    /// lambda, so F'(tau) = F(tau lambda'^2/lambda^2) and J'(tau) = J(tau lambda'^2/lambda^2)
    /// (I depends on chi only); both re-interpolated at the same number of Chebyshev nodes.
    pub(crate) fn restrict(&self, lambda_new: &Float) -> VolterraSolution {
        let prec = self.prec;
        let n = self.f_coeffs.len();
        let ratio = if self.lambda.is_zero() {
            Float::with_val(prec, 0)
        } else if self.shift.is_some() {
            Float::with_val(prec, lambda_new / &self.lambda)
        } else {
            Float::with_val(prec, lambda_new / &self.lambda).square()
        };
        VolterraSolution {
            prec,
            lambda: Float::with_val(prec, lambda_new),
            eps: self.eps.clone(),
            cosh_pi_eps: self.cosh_pi_eps.clone(),
            f_coeffs: resample(&self.f_coeffs, &ratio, n, prec),
            shift: self.shift.clone(),
            j_source: JSource::Restricted(Box::new(self.clone()), ratio),
            j_coeffs: OnceLock::new(),
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
            shift: self.shift.as_ref().map(|_| kernel::LateralShift::new(&Float::with_val(prec, &self.eps), prec)),
            j_source: JSource::Reduced(Box::new(self.clone())),
            j_coeffs: OnceLock::new(),
            residual: self.residual,
            pivot_ratio: self.pivot_ratio,
            rule,
            pre,
        }
    }

    /// Chebyshev coefficients of J(tau) = Im I(sqrt tau), computed on the first call (J is
    /// needed by phi only; the solve keeps what it takes, see `JSource`).
    pub fn j_coeffs(&self) -> &[Float] {
        self.j_coeffs.get_or_init(|| match &self.j_source {
            JSource::Rows(rows) => {
                let prec = self.prec;
                let mut clenshaw = chebyshev::Clenshaw::new(prec);
                let mut t = Float::new(prec);
                let j_values: Vec<Float> = rows
                    .iter()
                    .map(|row| {
                        let mut acc = Float::with_val(prec, 0);
                        for (im, x) in row {
                            clenshaw.evaluate_into(&self.f_coeffs, x, &mut t);
                            t *= im;
                            acc += &t;
                        }
                        acc
                    })
                    .collect();
                chebyshev::coefficients(&j_values, prec)
            }
            JSource::Restricted(parent, ratio) => resample(parent.j_coeffs(), ratio, parent.f_coeffs.len(), self.prec),
            JSource::Reduced(parent) => parent.j_coeffs().iter().map(|x| Float::with_val(self.prec, x)).collect(),
        })
    }

    /// Whether this is the `periodic` convention's solution (F in sigma, module doc).
    pub fn periodic(&self) -> bool {
        self.shift.is_some()
    }

    /// The interpolation variable at sigma = eta/lambda given sigma^2: sigma^2 (`paper`) or
    /// sigma (`periodic`).
    pub(crate) fn variable_of_square(&self, sigma_sq: &Float) -> Float {
        if self.periodic() {
            Float::with_val(self.prec, sigma_sq.sqrt_ref())
        } else {
            sigma_sq.clone()
        }
    }

    /// I(sigma) = int_0^1 s w(s) G(lambda sigma, s) F(sigma^2 s^2) ds as (re, im); Re I = pi
    /// (`periodic`: F(sigma s) and its kernel).
    pub fn integral_i(&self, sigma: &Float) -> (Float, Float) {
        let prec = self.prec;
        let chi = Float::with_val(prec, &self.lambda * sigma);
        let sc_chi = chi.clone().sin_cos(Float::new(prec));
        let sig2 = Float::with_val(prec, sigma * sigma);
        let (mut sr, mut si) = (Float::with_val(prec, 0), Float::with_val(prec, 0));
        for q in 0..self.rule.len() {
            let (re, im) = self.pre.integrand(
                q,
                &self.rule.s[q],
                &self.rule.c[q],
                &chi,
                &sc_chi,
                &self.eps,
                self.shift.as_ref(),
                prec,
            );
            let x = if self.periodic() {
                Float::with_val(prec, sigma * &self.rule.s[q]) * 2u32 - 1u32
            } else {
                Float::with_val(prec, &sig2 * &self.pre.s2[q]) * 2u32 - 1u32
            };
            let fw = chebyshev::evaluate(&self.f_coeffs, &x, prec) * &self.rule.w[q];
            sr += Float::with_val(prec, &re * &fw);
            si += Float::with_val(prec, &im * &fw);
        }
        (sr, si)
    }

    /// P2/(E* k a^2) = (1/2) int_0^1 F (`periodic`: int_0^1 sigma F(sigma) d sigma).
    pub fn load_ratio(&self) -> Float {
        let one = Float::with_val(self.prec, 1u32);
        self.load_ratio_to(&one)
    }

    /// The load at the contact sigma lambda in units of E* k a^2 (a of this solution):
    /// (1/2) int_0^(sigma^2) F(tau) d tau (`paper`), int_0^sigma s F(s) ds (`periodic`).
    pub(crate) fn load_ratio_to(&self, sigma: &Float) -> Float {
        if self.periodic() {
            chebyshev::integral(&times_t(&self.f_coeffs, self.prec), sigma, self.prec)
        } else {
            let tau = Float::with_val(self.prec, sigma * sigma);
            chebyshev::integral(&self.f_coeffs, &tau, self.prec) / 2u32
        }
    }

    /// F at its variable: F(tau) = f(lambda^2 tau), i.e. P'(eta) = eta F(eta^2/lambda^2)
    /// (`periodic`: P'(eta) = eta F(eta/lambda), the argument is sigma).
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

    /// phi/(k a^2) at sigma: -(1/pi) int_0^{sigma^2} J (`periodic`: -(2/pi) int_0^sigma s J(s) ds).
    pub(crate) fn phi_ratio(&self, sigma: &Float) -> Float {
        let pi = Float::with_val(self.prec, Constant::Pi);
        if self.periodic() {
            let sj = times_t(self.j_coeffs(), self.prec);
            return -(chebyshev::integral(&sj, sigma, self.prec) * 2u32) / pi;
        }
        let t = Float::with_val(self.prec, sigma * sigma);
        -chebyshev::integral(self.j_coeffs(), &t, self.prec) / pi
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
    pub(crate) fn stress_ratio_near_edge(&self, delta: &Float) -> (Float, Float) {
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
                let (re, im, r2) =
                    kernel::stress_integrand_v(sigma, &v, &self.lambda, &self.eps, self.shift.as_ref(), prec);
                let fw = self.f_at(&self.variable_of_square(&r2)) * &self.rule.w[q];
                sr += Float::with_val(prec, &re * &fw);
                si += Float::with_val(prec, &im * &fw);
            }
            let scale = Float::with_val(prec, &big_v * self.flat_punch_factor()) / pi;
            return (sr * &scale, si * &scale);
        }
        for q in 0..self.rule.len() {
            let (re, im, r2) = kernel::stress_integrand(
                sigma,
                omss,
                &self.rule.s[q],
                &self.lambda,
                &self.eps,
                self.shift.as_ref(),
                prec,
            );
            let fw = self.f_at(&self.variable_of_square(&r2)) * &self.rule.w[q];
            sr += Float::with_val(prec, &re * &fw);
            si += Float::with_val(prec, &im * &fw);
        }
        let scale = Float::with_val(prec, omss.sqrt_ref()) * self.flat_punch_factor() / pi;
        (sr * &scale, si * &scale)
    }

    /// The flat punch's constant factor: cosh(pi eps) (`paper`), 1 (`periodic`, where the kernel's
    /// 1/cosh(pi eps) cancels it; [`kernel`]).
    fn flat_punch_factor(&self) -> Float {
        if self.periodic() {
            Float::with_val(self.prec, 1u32)
        } else {
            self.cosh_pi_eps.clone()
        }
    }

    /// Edge stress factor C: (q2 + i q1)/(E* k a) = C delta^{1/2 - i eps} (1 + O(delta)),
    /// delta = 1 - x/a -> 0, with
    /// C = (cosh(pi eps)/pi) 2^{1/2 + i eps}/(1 - 2 i eps) cos(lambda (1 - 2 i eps))
    ///     sinc(2 lambda)^{i eps - 1/2} F(1)
    /// (leading term of the stress integral at the edge, derived from [`super::kernel`];
    /// `periodic`: cosh(pi eps) cos(lambda (1 - 2 i eps)) -> cos(lambda - i eps (2 lambda - pi))).
    pub(crate) fn edge_stress_factor(&self) -> Complex {
        let prec = self.prec;
        let one = Float::with_val(prec, 1u32);
        let f1 = self.f_at(&one);
        let pi = Float::with_val(prec, Constant::Pi);
        let i_eps = Complex::with_val(prec, (0, &self.eps));
        let two = Complex::with_val(prec, 2u32);
        let p = two.pow(Complex::with_val(prec, (0.5f64, &self.eps)));
        let den = Complex::with_val(prec, 1u32) - Complex::with_val(prec, &i_eps * 2u32);
        let mut im_arg = Float::with_val(prec, &self.lambda * &self.eps) * -2i32;
        if let Some(shift) = &self.shift {
            im_arg += &shift.pi_eps;
        }
        let arg = Complex::with_val(prec, (&self.lambda, im_arg));
        let cosv = arg.cos();
        let sn = kernel::sinc(&Float::with_val(prec, &self.lambda * 2u32), prec);
        let snp = Complex::with_val(prec, sn).pow(Complex::with_val(prec, (-0.5f64, &self.eps)));
        p / den * cosv * snp * f1 * self.flat_punch_factor() / pi
    }
}

/// lambda = pi a / L from exact a, L.
pub fn lambda_of(a: &Exact, l: &Exact, prec: u32) -> Float {
    let r = to_float(&(a / l), prec + 8);
    Float::with_val(prec, r * Float::with_val(prec + 8, Constant::Pi))
}
