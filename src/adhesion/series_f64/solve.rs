//! Method 2 at one lambda (module doc of [`super`]): the truncation of the universal series
//! at lambda, and the dimensionless load, psi, phi and stresses from it.

use super::kernel;
use super::series::{radius_estimate, SeriesParams, UniversalSeries, C64};
use crate::growing_contact::error::AdhesionError;
use crate::model::Material;
use crate::numerics::accuracy::readable_f64;
use crate::params::adhesion::AdhesionParamsF64;

/// Largest lambda accepted by the series method.
pub const SERIES_LAMBDA_MAX: f64 = 1.2;

/// The series solution at one lambda, in the contact's own variable tau = sigma^2 = (x/a)^2:
/// F(tau) = f(lambda^2 tau) = sum_n F_n tau^n with F_n = f_n lambda^(2n) (so that the single punch,
/// lambda = 0, with a profile other than the parabola, whose F is not constant, has a series too).
#[derive(Debug, Clone)]
pub struct SeriesSolution {
    /// lambda = pi a/L.
    pub lambda: f64,
    /// eps.
    pub eps: f64,
    /// cosh(pi eps).
    pub cosh_pi_eps: f64,
    /// F_n = f_n lambda^(2n): F(tau) = sum F_n tau^n (P'(eta) = eta f(eta^2)).
    pub f: Vec<f64>,
    /// C_n = c_n lambda^(2n), c_n = sum_{j+m=n} f_j mu_{j,m}: I(lambda sigma) = sum C_n sigma^(2n).
    pub c: Vec<C64>,
    rule: Vec<(f64, f64, f64)>,
}

/// Solves at lambda (0 = single punch) for the parabola (right side pi).
pub fn solve(universal: &UniversalSeries, lambda: f64) -> Result<SeriesSolution, AdhesionError> {
    solve_rhs(universal, lambda, &[1.0])
}

/// Solves at lambda (0 = single punch) with the right side pi r(tau), r = sum_n `rhs[n]` tau^n
/// ([`super::right_side`]; the parabola: \[1\]). The triangular recursion of the module doc of
/// [`super`] in the contact's variable:
///   F_n = (pi r_n - sum_{j<n} F_j lambda^(2(n-j)) Re mu_{j,n-j}) / Re M_(2n+1),
/// truncated where |F_n| falls below the cutoff times the largest |F_j| (not before the last
/// non-zero r_n).
pub fn solve_rhs(universal: &UniversalSeries, lambda: f64, rhs: &[f64]) -> Result<SeriesSolution, AdhesionError> {
    if !(0.0..=SERIES_LAMBDA_MAX).contains(&lambda) {
        return Err(AdhesionError::IllConditioned {
            method: "f64-series",
            parameter: "lambda",
            value: readable_f64(lambda),
            valid: format!("0 <= lambda <= {SERIES_LAMBDA_MAX}"),
            reason: "the lambda^2 series converges too slowly near its radius".into(),
        });
    }
    let mu = &universal.mu;
    let cutoff = universal.params.cutoff;
    let terms = universal.f.len();
    let l2 = lambda * lambda;
    let mut l2pow = vec![1.0; terms];
    for m in 1..terms {
        l2pow[m] = l2pow[m - 1] * l2;
    }
    let pi = std::f64::consts::PI;
    let mut f: Vec<f64> = Vec::with_capacity(terms);
    for n in 0..terms {
        let mut acc = pi * rhs.get(n).copied().unwrap_or(0.0);
        for (j, fj) in f.iter().enumerate() {
            acc -= fj * l2pow[n - j] * mu[j][n - j].re;
        }
        let d = mu[n][0].re;
        if !(d.abs() > 0.0) {
            return Err(AdhesionError::NotConverged {
                what: "f64-series recursion",
                reason: format!("Re M_{} vanished", 2 * n + 1),
            });
        }
        f.push(acc / d);
    }
    // Radius of the series in tau from its last two computed terms (module doc of [`super`]:
    // the ratios decrease with n, so the last is the most cautious), before truncation.
    let r = radius_estimate(&f);
    let last_rhs = rhs.iter().rposition(|r| *r != 0.0).unwrap_or(0);
    let mut scale = 0f64;
    let mut keep = terms;
    for (n, fn_) in f.iter().enumerate() {
        scale = scale.max(fn_.abs());
        if n >= 2 && n >= last_rhs && fn_.abs() < cutoff * scale {
            keep = n + 1;
            break;
        }
    }
    f.truncate(keep);
    // The tail bound assumes geometric decay at the ratio r.
    let tail = f[keep - 1].abs() / (1.0 - (1.0 / r).min(0.999)) / scale.max(f64::MIN_POSITIVE);
    if !(r > 1.25) || keep == terms && tail > 1e-16 {
        return Err(AdhesionError::IllConditioned {
            method: "f64-series",
            parameter: "lambda",
            value: readable_f64(lambda),
            valid: format!(
                "the contact well inside the radius of convergence of the series (ratio of its last terms {r:.4} in tau = (x/a)^2, at least 1.25 needed)"
            ),
            reason: format!(
                "truncation error estimate {tail:.1e}; the solution f = P'(eta)/eta is singular at the radius (lambda^2 series at this nu, or the profile's own singularity)"
            ),
        });
    }
    let c = (0..keep).map(|n| (0..=n).map(|j| mu[j][n - j] * (f[j] * l2pow[n - j])).sum()).collect();
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
        self.f.iter().rev().fold(0.0, |acc, fn_| acc * tau + fn_)
    }
    /// P2/(E* k a^2) = (1/2) int_0^1 F = (1/2) sum F_n/(n+1).
    pub fn load_ratio(&self) -> f64 {
        0.5 * self.f.iter().enumerate().map(|(n, fn_)| fn_ / (n + 1) as f64).sum::<f64>()
    }
    /// I(lambda sigma).
    pub fn integral_i(&self, sigma: f64) -> C64 {
        let x = sigma * sigma;
        self.c.iter().rev().fold(C64::new(0.0, 0.0), |acc, cn| acc * x + cn)
    }
    /// psi/(k a).
    pub fn psi_ratio(&self, sigma: f64) -> f64 {
        -2.0 * sigma / std::f64::consts::PI * self.integral_i(sigma).im
    }
    /// phi/(k a^2) = -(1/pi) sum Im C_n sigma^(2n+2)/(n+1).
    pub(crate) fn phi_ratio(&self, sigma: f64) -> f64 {
        let s2 = sigma * sigma;
        let mut p = s2;
        let mut acc = 0.0;
        for (n, cn) in self.c.iter().enumerate() {
            acc += cn.im * p / (n + 1) as f64;
            p *= s2;
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
            let f_n = s.f[n] / 0.25f64.powi(n as i32);
            assert!((f_n / pi - w).abs() < 1e-13, "f_{n} = {}", f_n / pi);
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
