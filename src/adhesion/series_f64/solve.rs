//! Method 2 at one lambda (module doc of [`super`]): the truncation of the universal series
//! at lambda, and the dimensionless load, psi, phi and stresses from it.

use super::kernel;
use super::series::{radius_estimate, SeriesParams, UniversalSeries, C64};
use crate::adhesion::error::AdhesionError;
use crate::model::Material;
use crate::numerics::accuracy::readable_f64;
use crate::params::adhesion::AdhesionParamsF64;

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

/// Solves at lambda (0 = single punch) from the universal coefficients.
pub fn solve(universal: &UniversalSeries, lambda: f64) -> Result<SeriesSolution, AdhesionError> {
    if !(0.0..=SERIES_LAMBDA_MAX).contains(&lambda) {
        return Err(AdhesionError::IllConditioned {
            method: "f64-series",
            parameter: "lambda",
            value: readable_f64(lambda),
            valid: format!("0 <= lambda <= {SERIES_LAMBDA_MAX}"),
            reason: "the lambda^2 series converges too slowly near its radius".into(),
        });
    }
    let (mut f, mu) = (universal.f.clone(), &universal.mu);
    let cutoff = universal.params.cutoff;
    let terms = f.len();
    // Truncate where the terms f_n lambda^{2n} fall below cutoff f_0 (1e-18 nominal), or fail.
    let r = radius_estimate(&f);
    let l2 = lambda * lambda;
    let mut keep = 2usize;
    let mut p = 1.0;
    for n in 0..terms {
        keep = n + 1;
        if n >= 2 && (f[n] * p).abs() < cutoff * f[0].abs() && l2 < r {
            break;
        }
        p *= l2;
    }
    let tail = (f[keep - 1] * p).abs() / (1.0 - (l2 / r).min(0.999)) / f[0].abs();
    if !(l2 < 0.8 * r) || keep == terms && tail > 1e-16 {
        return Err(AdhesionError::IllConditioned {
            method: "f64-series",
            parameter: "lambda",
            value: readable_f64(lambda),
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
    Ok(SeriesSolution {
        lambda,
        eps: universal.constants.eps,
        cosh_pi_eps: universal.constants.cosh_pi_eps,
        f,
        c,
        rule: universal.rule.clone(),
    })
}

/// [`solve`] with the nominal discretisation, the constants of `material` computed here: for
/// tests and examples that need one lambda (a solver computes the universal part once).
pub fn solve_nominal(material: &Material, lambda: f64) -> Result<SeriesSolution, AdhesionError> {
    let universal = UniversalSeries::new(&AdhesionParamsF64::new(material), SeriesParams::NOMINAL)?;
    solve(&universal, lambda)
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
                let (re, im, r2) = kernel::stress_integrand_v(sigma, big_v * s, self.lambda, self.eps);
                let fw = self.f_at(r2) * w;
                sr += re * fw;
                si += im * fw;
            }
            let scale = big_v * self.cosh_pi_eps / std::f64::consts::PI;
            return (sr * scale, si * scale);
        }
        for &(y, _, w) in &self.rule {
            let (re, im, r2) = kernel::stress_integrand(sigma, omss, y, self.lambda, self.eps);
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
        let s = solve_nominal(&m, 0.5).unwrap();
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
mod ratio_tests {
    use super::super::series::SERIES_TERMS;
    use super::*;
    use crate::model::Exact;

    #[test]
    fn series_ratios_quoted_in_the_module_doc() {
        // Module doc of `series_f64`: f_k/f_{k+1} at k = 20, 40, 60 and the last (k = 88),
        // rounded as quoted; all f_n positive.
        for (nu, want) in [((0, 1), [1.20, 0.99, 0.85, 0.69]), ((3, 10), [2.12, 2.08, 2.05, 2.01])] {
            let m = Material::from_contact_modulus(Exact::new(nu.0.into(), nu.1.into()), Exact::from_integer(1.into()))
                .unwrap();
            let u = UniversalSeries::new(&AdhesionParamsF64::new(&m), SeriesParams::NOMINAL).unwrap();
            assert!(u.f.iter().all(|x| *x > 0.0));
            for (k, w) in [20usize, 40, 60, SERIES_TERMS - 2].into_iter().zip(want) {
                let r = u.f[k] / u.f[k + 1];
                assert!((r - w).abs() <= 0.005 + 1e-12, "nu {nu:?} k {k}: {r:.4} vs {w}");
            }
        }
    }
}
