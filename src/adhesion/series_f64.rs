//! Method 2 (`f64`): the Volterra equation of THEORY.md section 4 solved as a power series in
//! lambda^2 ("collocation in lambda^2"), independent of the Chebyshev collocation of method 1.
//!
//! With P'(eta) = eta f(eta^2), f(t) = sum_n f_n t^n, and the Taylor expansion in chi^2 of the
//! regular kernel factor G(chi, s) = sum_m g_m(s) chi^{2m} ([`super::kernel`]; g_0 = 1), the
//! equation Re int_0^1 s w(s) G(chi, s) f(chi^2 s^2) ds = pi is triangular:
//!   sum_{j+m=n} f_j Re mu_{j,m} = pi delta_{n0},   mu_{j,m} = int_0^1 s^{2j+1} w(s) g_m(s) ds,
//! (mu_{j,0} = M_{2j+1}, the half-range moments of THEORY.md section 5, so f_0 = pi/Re M_1 and
//! C_P = f_0/2). The g_m(s) are computed at each quadrature node as Taylor coefficients of
//! G(., s) (series log/exp/cos in f64 at that node, no expansion in powers of s, which would
//! cancel catastrophically), the mu by tanh-sinh. Then, with c_n = sum_{j+m=n} f_j mu_{j,m},
//!   P2/(E* k a^2) = (1/2) sum_n f_n lambda^{2n}/(n+1),
//!   psi/(k a) = -(2 sigma/pi) sum_n (lambda sigma)^{2n} Im c_n,
//!   phi/(k a^2) = -(1/pi) sum_n lambda^{2n} Im c_n sigma^{2n+2}/(n+1),
//! and the stresses by f64 tanh-sinh of the integral of [`super::kernel`] with this f.
//! At eps = 0 the series in lambda^2 converges for lambda < pi/2 (f = pi tan(sqrt t)/sqrt t).
//! For eps > 0 it does not have that radius: all f_n are positive but the ratios f_{n-1}/f_n keep
//! decreasing (nu = 0: 1.20 at n = 20, 0.99 at 40, 0.85 at 60, 0.69 at 89; nu = 0.3: 2.12, 2.08,
//! 2.05, 2.01; nu = 0.45: 2.4365 -> 2.4344), and the recursion divides by Re M_{2n+1}, which
//! changes sign at n ~ 302 for nu = 0: the series is at best slowly convergent, possibly only
//! asymptotic, at small nu. The method computes [`SERIES_TERMS`] coefficients, truncates where
//! the terms fall below 1e-18, and returns `IllConditioned` when lambda^2 is not well inside the
//! observed ratio (lambda <= ~0.74 at nu = 0, ~1.2 at nu >= 0.3).

use crate::params::adhesion as constants;
use super::error::AdhesionError;
use super::kernel::f64k;
use super::tanh_sinh::tanh_sinh_f64;
use crate::model::Material;
use nalgebra::Complex;

type C64 = Complex<f64>;

/// Largest lambda accepted by the series method.
pub const SERIES_LAMBDA_MAX: f64 = 1.2;

/// The series solution at one lambda.
#[derive(Debug, Clone)]
pub struct SeriesSolution {
    /// lambda = pi a/L.
    pub lambda: f64,
    /// eps.
    pub eps: f64,
    /// cosh(pi eps).
    pub cosh_pi_eps: f64,
    /// Taylor coefficients f_n of f(t) (P'(eta) = eta f(eta^2)).
    pub f: Vec<f64>,
    /// c_n = sum_{j+m=n} f_j mu_{j,m}: I(chi) = sum c_n chi^{2n}.
    pub c: Vec<C64>,
    rule: Vec<(f64, f64, f64)>,
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

/// Radius estimate R (in t = eta^2) from the last coefficient ratio f_{n-1}/f_n (all f_n observed
/// positive for nu in [0, 1/2]). The ratios decrease with n, so this is an over-estimate, used
/// with a safety factor (lambda^2 < 0.8 R) and a truncation-error estimate.
fn radius_estimate(f: &[f64]) -> f64 {
    let n = f.len();
    if n < 3 || f[n - 1] == 0.0 {
        return f64::INFINITY;
    }
    (f[n - 2] / f[n - 1]).abs()
}

/// The universal Taylor coefficients f_n (n < [`SERIES_TERMS`]) and the moments mu_{j,m}.
pub fn universal_coefficients(
    material: &Material,
    rule: &[(f64, f64, f64)],
) -> Result<(Vec<f64>, Vec<Vec<C64>>), AdhesionError> {
    let terms = SERIES_TERMS;
    let eps = constants::eps(material, 64).to_f64();
    let lsinc = ln_sinc_coeffs(terms);
    // mu[j][m], j + m < terms.
    let mut mu = vec![vec![C64::new(0.0, 0.0); terms]; terms];
    for &(s, c, w) in rule {
        let (wr, wi) = f64k::weight_s(s, c, eps);
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

/// Solves at lambda (0 = single punch).
pub fn solve(material: &Material, lambda: f64) -> Result<SeriesSolution, AdhesionError> {
    if !(0.0..=SERIES_LAMBDA_MAX).contains(&lambda) {
        return Err(AdhesionError::IllConditioned {
            method: "f64-series",
            parameter: "lambda",
            value: format!("{lambda}"),
            valid: format!("0 <= lambda <= {SERIES_LAMBDA_MAX}"),
            reason: "the lambda^2 series converges too slowly near its radius".into(),
        });
    }
    let eps = constants::eps(material, 64).to_f64();
    let cosh_pi_eps = constants::cosh_pi_eps(material, 64).to_f64();
    let rule = tanh_sinh_f64(60, 1.2);
    let (mut f, mu) = universal_coefficients(material, &rule)?;
    let terms = f.len();
    // Truncate where the terms f_n lambda^{2n} fall below 1e-18 f_0, or fail.
    let r = radius_estimate(&f);
    let l2 = lambda * lambda;
    let mut keep = 2usize;
    let mut p = 1.0;
    for n in 0..terms {
        keep = n + 1;
        if n >= 2 && (f[n] * p).abs() < 1e-18 * f[0].abs() && l2 < r {
            break;
        }
        p *= l2;
    }
    let tail = (f[keep - 1] * p).abs() / (1.0 - (l2 / r).min(0.999)) / f[0].abs();
    if !(l2 < 0.8 * r) || keep == terms && tail > 1e-16 {
        return Err(AdhesionError::IllConditioned {
            method: "f64-series",
            parameter: "lambda",
            value: format!("{lambda}"),
            valid: format!(
                "lambda^2 well inside the radius of convergence R ~ {r:.4} of the lambda^2 series at this nu"
            ),
            reason: format!(
                "truncation error estimate {tail:.1e}; the solution f = P'(eta)/eta is singular at eta^2 = R"
            ),
        });
    }
    f.truncate(keep);
    let terms = keep;
    let c = (0..terms).map(|n| (0..=n).map(|j| mu[j][n - j] * f[j]).sum()).collect();
    Ok(SeriesSolution { lambda, eps, cosh_pi_eps, f, c, rule })
}

impl SeriesSolution {
    /// F(tau) = f(lambda^2 tau).
    pub fn f_at(&self, tau: f64) -> f64 {
        let x = self.lambda * self.lambda * tau;
        self.f.iter().rev().fold(0.0, |acc, fn_| acc * x + fn_)
    }
    /// P2/(E* k a^2).
    pub fn load_ratio(&self) -> f64 {
        let l2 = self.lambda * self.lambda;
        let mut p = 1.0;
        let mut s = 0.0;
        for (n, fn_) in self.f.iter().enumerate() {
            s += fn_ * p / (n + 1) as f64;
            p *= l2;
        }
        0.5 * s
    }
    /// I(lambda sigma).
    pub fn integral_i(&self, sigma: f64) -> C64 {
        let x = (self.lambda * sigma).powi(2);
        self.c.iter().rev().fold(C64::new(0.0, 0.0), |acc, cn| acc * x + cn)
    }
    /// psi/(k a).
    pub fn psi_ratio(&self, sigma: f64) -> f64 {
        -2.0 * sigma / std::f64::consts::PI * self.integral_i(sigma).im
    }
    /// phi/(k a^2).
    pub fn phi_ratio(&self, sigma: f64) -> f64 {
        let l2 = self.lambda * self.lambda;
        let s2 = sigma * sigma;
        let mut p = s2;
        let mut acc = 0.0;
        for (n, cn) in self.c.iter().enumerate() {
            acc += cn.im * p / (n + 1) as f64;
            p *= l2 * s2;
        }
        -acc / std::f64::consts::PI
    }
    /// (q2, q1)/(E* k a) at sigma in [0, 1].
    pub fn stress_ratio(&self, sigma: f64) -> (f64, f64) {
        let omss = (1.0 - sigma) * (1.0 + sigma);
        if omss <= 0.0 {
            return (0.0, 0.0);
        }
        let (mut sr, mut si) = (0.0, 0.0);
        if sigma > 0.0 && sigma < 0.5 {
            // v-form, r = sigma cosh v (see kernel::stress_integrand_v).
            let big_v = (1.0 / sigma).acosh();
            for &(s, _, w) in &self.rule {
                let (re, im, r2) = f64k::stress_integrand_v(sigma, big_v * s, self.lambda, self.eps);
                let fw = self.f_at(r2) * w;
                sr += re * fw;
                si += im * fw;
            }
            let scale = big_v * self.cosh_pi_eps / std::f64::consts::PI;
            return (sr * scale, si * scale);
        }
        for &(y, _, w) in &self.rule {
            let (re, im, r2) = f64k::stress_integrand(sigma, omss, y, self.lambda, self.eps);
            let fw = self.f_at(r2) * w;
            sr += re * fw;
            si += im * fw;
        }
        let scale = omss.sqrt() * self.cosh_pi_eps / std::f64::consts::PI;
        (sr * scale, si * scale)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Exact;

    #[test]
    fn adhesion_series_kuznetsov_coefficients() {
        // eps = 0: f(t) = pi tan(sqrt t)/sqrt t = pi (1 + t/3 + 2 t^2/15 + 17 t^3/315 + ...).
        let m = Material::from_contact_modulus(Exact::new(1.into(), 2.into()), Exact::from_integer(1.into())).unwrap();
        let s = solve(&m, 0.5).unwrap();
        let pi = std::f64::consts::PI;
        let want = [1.0, 1.0 / 3.0, 2.0 / 15.0, 17.0 / 315.0];
        for (n, w) in want.iter().enumerate() {
            assert!((s.f[n] / pi - w).abs() < 1e-13, "f_{n} = {}", s.f[n] / pi);
        }
        // Kuznetsov: P2/(E* k a^2) = ln sec(lambda)/lambda^2.
        let want = pi * (1.0 / 0.5f64.cos()).ln() / 0.25;
        assert!((s.load_ratio() - want).abs() < 1e-14);
    }
}
#[cfg(test)]
mod chart_tests {
    use super::*;
    use crate::model::Exact;
    /// Chart (not a check): ratios f_{n-1}/f_n of the universal coefficients. They decrease
    /// with n for eps > 0 (nu = 0: 1.20 at n = 20, 0.99 at 40, 0.85 at 60, 0.69 at 89), so the
    /// lambda^2 series has at best a radius well below (pi/2)^2 at small nu. Run with `--ignored`.
    #[test]
    #[ignore]
    fn adhesion_chart_series_ratios() {
        for nu in [(0i64, 1i64), (1, 10), (3, 10), (9, 20), (49, 100)] {
            let m = Material::from_contact_modulus(Exact::new(nu.0.into(), nu.1.into()), Exact::from_integer(1.into()))
                .unwrap();
            let (f, _) = universal_coefficients(&m, &tanh_sinh_f64(60, 1.2)).unwrap();
            let s = SeriesSolution { f, ..solve(&m, 0.0).unwrap() };
            let n = s.f.len();
            let r: Vec<String> =
                (n - 8..n - 1).chain([20usize, 40, 60]).map(|k| format!("{:.4}", s.f[k] / s.f[k + 1])).collect();
            println!("nu {:?} eps {:.4} ratios {:?}", nu, s.eps, r);
            let signs: String = s.f.iter().map(|x| if *x > 0.0 { '+' } else { '-' }).collect();
            println!("   signs {signs}");
        }
    }
}
