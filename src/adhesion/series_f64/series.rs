//! The universal part of method 2 (module doc of [`super`]): the Taylor coefficients g_m(s) of the
//! kernel factor at each quadrature node, the moments mu_{j,m}, and the coefficients f_n of
//! f(t), which do not depend on lambda: computed once per material and discretisation.

use super::kernel;
use crate::growing_contact::error::AdhesionError;
use crate::numerics::tanh_sinh::tanh_sinh_f64;
use crate::params::adhesion::AdhesionParamsF64;
use nalgebra::Complex;

/// Complex `f64`.
pub type C64 = Complex<f64>;

/// Discretisation of one run of method 2.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SeriesParams {
    /// Accuracy in bits the tanh-sinh rule of the moments and stresses is built for.
    pub bits: u32,
    /// Refinement of the rule's step (1 = nominal step for `bits`).
    pub refine: f64,
    /// The series in lambda^2 is truncated where its terms fall below `cutoff` f_0.
    pub cutoff: f64,
}

impl SeriesParams {
    /// The discretisation of the values returned.
    pub const NOMINAL: SeriesParams = SeriesParams { bits: 60, refine: 1.2, cutoff: 1e-18 };

    /// The second run of the accuracy estimate: a 1.5 times finer rule and a truncation 1000 times
    /// further out.
    pub fn refined(&self) -> Self {
        SeriesParams { bits: self.bits, refine: self.refine * 1.5, cutoff: self.cutoff * 1e-3 }
    }
}

/// The universal coefficients of one material at one discretisation.
#[derive(Debug, Clone)]
pub struct UniversalSeries {
    /// The material's constants.
    pub constants: AdhesionParamsF64,
    /// The discretisation.
    pub params: SeriesParams,
    /// Taylor coefficients f_n of f(t), n < [`SERIES_TERMS`].
    pub f: Vec<f64>,
    /// mu_{j,m}, j + m < [`SERIES_TERMS`].
    pub mu: Vec<Vec<C64>>,
    /// The tanh-sinh rule (s, 1 - s, weight) on (0, 1).
    pub rule: Vec<(f64, f64, f64)>,
}

impl UniversalSeries {
    /// f_n and mu_{j,m} of the material with `constants`, on the rule of `params`.
    pub fn new(constants: &AdhesionParamsF64, params: SeriesParams) -> Result<Self, AdhesionError> {
        let rule = tanh_sinh_f64(params.bits, params.refine);
        let (f, mu) = universal_coefficients(constants.eps, &rule)?;
        Ok(UniversalSeries { constants: *constants, params, f, mu, rule })
    }
}

/// Taylor coefficients l_k (k >= 0, l_0 = 0) of ln(sin z/z) in powers of z^2.
fn ln_sinc_coeffs(m: usize) -> Vec<f64> {
    // sinc = sum (-1)^n z^{2n}/(2n+1)!; log by L' = S'/S.
    let mut s = vec![0.0; m];
    let mut fact = 1.0;
    for n in 0..m {
        if n > 0 {
            fact *= ((2 * n) * (2 * n + 1)) as f64;
        }
        s[n] = if n % 2 == 0 { 1.0 } else { -1.0 } / fact;
    }
    let mut l = vec![0.0; m];
    for n in 1..m {
        let mut acc = n as f64 * s[n];
        for k in 1..n {
            acc -= k as f64 * l[k] * s[n - k];
        }
        l[n] = acc / n as f64;
    }
    l
}

/// Taylor coefficients g_m(s), m < terms, of G(chi, s) in chi^2 at one node.
fn g_coeffs(s: f64, c: f64, eps: f64, lsinc: &[f64], terms: usize) -> Vec<C64> {
    let i_eps = C64::new(0.0, eps);
    let (p, q) = ((1.0 + s) * (1.0 + s), c * c);
    let mut a = vec![C64::new(0.0, 0.0); terms];
    let (mut pk, mut qk) = (1.0, 1.0);
    for k in 1..terms {
        pk *= p;
        qk *= q;
        a[k] = (i_eps * (pk - qk) - 0.5 * (pk + qk)) * lsinc[k];
    }
    let mut e = vec![C64::new(0.0, 0.0); terms];
    e[0] = C64::new(1.0, 0.0);
    for n in 1..terms {
        let mut acc = C64::new(0.0, 0.0);
        for k in 1..=n {
            acc += a[k] * e[n - k] * k as f64;
        }
        e[n] = acc / n as f64;
    }
    // cos(chi w), w = 1 - 2 i eps s: sum (-1)^n w^{2n} chi^{2n}/(2n)!.
    let w2 = {
        let w = C64::new(1.0, -2.0 * eps * s);
        w * w
    };
    let mut cs = vec![C64::new(0.0, 0.0); terms];
    let mut t = C64::new(1.0, 0.0);
    for n in 0..terms {
        if n > 0 {
            t = -t * w2 / (((2 * n - 1) * (2 * n)) as f64);
        }
        cs[n] = t;
    }
    (0..terms).map(|n| (0..=n).map(|k| cs[k] * e[n - k]).sum()).collect()
}

/// Number of Taylor coefficients computed (f_n are universal: they do not depend on lambda).
pub const SERIES_TERMS: usize = 90;

/// Radius estimate R from the last coefficient ratio |f_{n-1}/f_n| (in the variable of the series
/// given: t = eta^2 for the universal f_n, tau = t/lambda^2 for a solution's F_n; all f_n observed
/// positive for nu in [0, 1/2]). The ratios decrease with n, so this is an over-estimate, used
/// with a safety factor (lambda^2 < 0.8 R, i.e. 1.25 in tau) and a truncation-error estimate.
pub(super) fn radius_estimate(f: &[f64]) -> f64 {
    let n = f.len();
    if n < 3 || f[n - 1] == 0.0 {
        return f64::INFINITY;
    }
    (f[n - 2] / f[n - 1]).abs()
}

/// The universal Taylor coefficients f_n (n < [`SERIES_TERMS`]) and the moments mu_{j,m}.
/// `eps` of the material, `rule` the tanh-sinh rule of the moments.
pub fn universal_coefficients(eps: f64, rule: &[(f64, f64, f64)]) -> Result<(Vec<f64>, Vec<Vec<C64>>), AdhesionError> {
    let terms = SERIES_TERMS;
    let lsinc = ln_sinc_coeffs(terms);
    // mu[j][m], j + m < terms.
    let mut mu = vec![vec![C64::new(0.0, 0.0); terms]; terms];
    for &(s, c, w) in rule {
        let (wr, wi) = kernel::weight_s(s, c, eps);
        let base = C64::new(wr, wi) * w;
        let g = g_coeffs(s, c, eps, &lsinc, terms);
        let s2 = s * s;
        let mut sp = 1.0;
        for j in 0..terms {
            for m in 0..terms - j {
                mu[j][m] += base * g[m] * sp;
            }
            sp *= s2;
        }
    }
    let pi = std::f64::consts::PI;
    let mut f = vec![0.0; terms];
    for n in 0..terms {
        let mut acc = if n == 0 { pi } else { 0.0 };
        for j in 0..n {
            acc -= f[j] * mu[j][n - j].re;
        }
        let d = mu[n][0].re;
        if !(d.abs() > 0.0) {
            return Err(AdhesionError::NotConverged {
                what: "f64-series recursion",
                reason: format!("Re M_{} vanished", 2 * n + 1),
            });
        }
        f[n] = acc / d;
    }
    Ok((f, mu))
}
