//! f_0 and g_0 of the self-similar single punch for the symbol ([`super::Symbol::new`]): the
//! order-0 system of [`crate::asymptotics::loading_law`] ("Expansion", order 0) solved on the
//! symbol's own rule, first in `f64`, then corrected by Newton in MPFR to the same tolerance as
//! [`crate::asymptotics::loading_law::law_coefficients`] (a step below 2^-(prec - 8) of f_0).
//!
//! At order 0 every series of that module is its constant term (sinc and cos of a zero argument
//! are 1), so per node and side (sigma = +-1, a1 = -1/2 - sigma i eps, a2 = -1/2 + sigma i eps,
//! N_0 = 1 + sigma g_0, D_0 = (1 + s) + sigma (1 - s) g_0):
//!   k = sigma exp(a1 (ln(1 - s) + ln N_0) + a2 ln D_0),
//!   R_sigma = Re (1 + i n) f_0 sum w s k - pi (sigma + g_0),
//!   dR/df_0 = Re (1 + i n) sum w s k,
//!   dR/dg_0 = Re (1 + i n) f_0 sum w s k sigma (a1/N_0 + a2 (1 - s)/D_0) - pi,
//! one real logarithm and one complex exponential per node and side, where the general series
//! code spends a complex logarithm, exponential and composition of series on each. Started from
//! the `f64` solution (about 1e-16 from the MPFR one), the MPFR Newton takes two steps (the
//! second confirming) instead of about six from g_0 = -2 eps n/(1 - 4 eps^2), f_0 = 2 C_P.
//! Where either stage does not converge, the caller solves by `law_coefficients` (with its
//! continuation in n).

use crate::numerics::mp_rounded;
use crate::numerics::tanh_sinh::TanhSinh;
use crate::params::adhesion::AdhesionParamsMpfr;
use nalgebra::Complex;
use rug::float::Constant;
use rug::{Complex as MComplex, Float};

type C64 = Complex<f64>;

/// (f_0, g_0) at `prec` bits on `rule` for n = `ratio`, or `None` where Newton does not converge
/// (module doc).
pub(super) fn self_similar(
    params: &AdhesionParamsMpfr,
    ratio: &Float,
    rule: &TanhSinh,
    prec: u32,
) -> Option<(Float, Float)> {
    let (f, g) = newton_f64(params, ratio.to_f64(), rule)?;
    newton_mpfr(params, ratio, rule, prec, f, g)
}

/// Nodes (s, 1 - s, w) with s, 1 - s > 0 (as the series code filters them).
fn nodes(rule: &TanhSinh) -> impl Iterator<Item = usize> + '_ {
    (0..rule.len()).filter(|&q| rule.c[q] > 0 && rule.s[q] > 0)
}

/// The order-0 system in f64 from the first-order start; steps halved while |g_0| would reach 1.
fn newton_f64(params: &AdhesionParamsMpfr, n: f64, rule: &TanhSinh) -> Option<(f64, f64)> {
    let pts: Vec<(f64, f64, f64, f64)> = nodes(rule)
        .map(|q| {
            let (s, c) = (rule.s[q].to_f64(), rule.c[q].to_f64());
            (s, c, rule.w[q].to_f64() * s, c.ln())
        })
        .collect();
    newton_f64_on(params.eps.to_f64(), params.load_constant.to_f64(), n, &pts)
}

/// [`newton_f64`] on the nodes `pts` = (s, 1 - s, w s, ln(1 - s)), with eps, C_P and n in f64.
pub(super) fn newton_f64_on(eps: f64, load_constant: f64, n: f64, pts: &[(f64, f64, f64, f64)]) -> Option<(f64, f64)> {
    let one_in = C64::new(1.0, n);
    let pi = std::f64::consts::PI;
    let (mut f, mut g) = (2.0 * load_constant, -2.0 * eps * n / (1.0 - 4.0 * eps * eps));
    for _ in 0..60 {
        let mut r = [0.0; 2];
        let mut m = [[0.0; 2]; 2];
        for (row, sigma) in [1.0f64, -1.0].into_iter().enumerate() {
            let (a1, a2) = (C64::new(-0.5, -sigma * eps), C64::new(-0.5, sigma * eps));
            let n0 = 1.0 + sigma * g;
            let ln_n0 = n0.ln();
            let (mut acc, mut mg) = (C64::new(0.0, 0.0), C64::new(0.0, 0.0));
            for &(s, c, ws, ln_c) in pts {
                let d0 = c * sigma * g + s + 1.0;
                let k0 = (a1 * (ln_c + ln_n0) + a2 * d0.ln()).exp() * (sigma * ws);
                acc += k0;
                mg += (a1 / n0 + a2 * c / d0) * k0 * sigma;
            }
            r[row] = (one_in * acc).re * f - pi * (sigma + g);
            m[row] = [(one_in * acc).re, (one_in * mg).re * f - pi];
        }
        let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
        let mut dx = [(r[0] * m[1][1] - m[0][1] * r[1]) / det, (m[0][0] * r[1] - r[0] * m[1][0]) / det];
        let mut halvings = 0;
        while (g - dx[1]).is_nan() || (g - dx[1]).abs() >= 1.0 {
            halvings += 1;
            if halvings > 40 {
                return None;
            }
            dx = [dx[0] / 2.0, dx[1] / 2.0];
        }
        f -= dx[0];
        g -= dx[1];
        if !(f.is_finite() && g.is_finite()) {
            return None;
        }
        if dx[0].abs().max(dx[1].abs()) <= 1e-14 * f.abs() {
            return Some((f, g));
        }
    }
    None
}

/// The order-0 system in MPFR from (`f`, `g`), to a step below 2^-(prec - 8) of f_0.
fn newton_mpfr(
    params: &AdhesionParamsMpfr,
    n: &Float,
    rule: &TanhSinh,
    prec: u32,
    f: f64,
    g: f64,
) -> Option<(Float, Float)> {
    let eps = Float::with_val(prec, &params.eps);
    let pts: Vec<(Float, Float, Float, Float)> = nodes(rule)
        .map(|q| {
            let (s, c) = (Float::with_val(prec, &rule.s[q]), Float::with_val(prec, &rule.c[q]));
            let ws = Float::with_val(prec, &rule.w[q] * &s);
            let ln_c = mp_rounded::ln(&c, prec);
            (s, c, ws, ln_c)
        })
        .collect();
    let one_in = MComplex::with_val(prec, (1, n));
    let pi = Float::with_val(prec, Constant::Pi);
    let goal = Float::with_val(prec, Float::i_exp(1, -(prec as i32) + 8));
    let (mut f, mut g) = (Float::with_val(prec, f), Float::with_val(prec, g));
    for _ in 0..8 {
        let mut r: [Float; 2] = [Float::new(prec), Float::new(prec)];
        let mut m: [[Float; 2]; 2] = [[Float::new(prec), Float::new(prec)], [Float::new(prec), Float::new(prec)]];
        for (row, sigma) in [(0usize, 1i32), (1, -1)] {
            let a1 = MComplex::with_val(prec, (-0.5, Float::with_val(prec, &eps * -sigma)));
            let a2 = MComplex::with_val(prec, (-0.5, Float::with_val(prec, &eps * sigma)));
            let sg0 = Float::with_val(prec, &g * sigma);
            let n0 = Float::with_val(prec, &sg0 + 1u32);
            if n0 <= 0 {
                return None;
            }
            let ln_n0 = mp_rounded::ln(&n0, prec);
            let (mut acc, mut mg) = (MComplex::new(prec), MComplex::new(prec));
            for (s, c, ws, ln_c) in &pts {
                let d0 = Float::with_val(prec, c * &sg0) + s + 1u32;
                let ln_d0 = mp_rounded::ln(&d0, prec);
                let expo = MComplex::with_val(prec, &a1 * Float::with_val(prec, ln_c + &ln_n0))
                    + MComplex::with_val(prec, &a2 * &ln_d0);
                let k0 = MComplex::with_val(prec, expo.exp_ref()) * ws * sigma;
                let term = MComplex::with_val(prec, &a1 / &n0) + MComplex::with_val(prec, &a2 * c) / &d0;
                mg += MComplex::with_val(prec, &term * &k0) * sigma;
                acc += k0;
            }
            let df = MComplex::with_val(prec, &acc * &one_in).real().clone();
            let dg = Float::with_val(prec, MComplex::with_val(prec, &mg * &one_in).real() * &f) - &pi;
            let rhs = Float::with_val(prec, &g + sigma) * &pi;
            r[row] = Float::with_val(prec, &df * &f) - rhs;
            m[row] = [df, dg];
        }
        let det = Float::with_val(prec, &m[0][0] * &m[1][1]) - Float::with_val(prec, &m[0][1] * &m[1][0]);
        if det.is_zero() || !det.is_finite() {
            return None;
        }
        let dx = (Float::with_val(prec, &r[0] * &m[1][1]) - Float::with_val(prec, &m[0][1] * &r[1])) / &det;
        let dy = (Float::with_val(prec, &m[0][0] * &r[1]) - Float::with_val(prec, &r[0] * &m[1][0])) / &det;
        f -= &dx;
        g -= &dy;
        let size_g = Float::with_val(prec, g.abs_ref());
        if size_g.is_nan() || size_g >= 1 {
            return None;
        }
        let size = Float::with_val(prec, dx.abs_ref()).max(&Float::with_val(prec, dy.abs_ref()));
        if size <= Float::with_val(prec, &goal * Float::with_val(prec, f.abs_ref())) {
            return Some((f, g));
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::asymptotics::loading_law::law_coefficients;
    use crate::model::Material;
    type Q = num_rational::BigRational;

    /// Against the general solve (`law_coefficients`, one term) on the mode check's rule and
    /// precision (76 bits, and the second run's 108 bits on its finer rule) at nu = 0.3, n = 1/5
    /// (the shipped scene), nu = 0, n = 1/2 and 1, nu = 1/10, n = 0: the same f_0, g_0 to
    /// 2^-(prec - 12) (both stop at a Newton step below 2^-(prec - 8)).
    #[test]
    fn self_similar_equals_the_series_solve() {
        for (nu, n) in [((3, 10), 0.2), ((0, 1), 0.5), ((0, 1), 1.0), ((1, 10), 0.0)] {
            let material =
                Material::from_contact_modulus(Q::new(nu.0.into(), nu.1.into()), Q::from_integer(1.into())).unwrap();
            for (prec, refine) in [(76, 1.0), (108, 1.25)] {
                let params = AdhesionParamsMpfr::new(&material, prec);
                let rule = TanhSinh::new(prec, refine, prec);
                let ratio = Float::with_val(prec, n);
                let (f, g) = self_similar(&params, &ratio, &rule, prec).expect("converges");
                let e = law_coefficients(&params, &ratio, 1, &rule, prec).unwrap();
                let tol = Float::with_val(prec, Float::i_exp(1, -(prec as i32) + 12));
                let df = Float::with_val(prec, &f - &e.f[0]).abs() / Float::with_val(prec, e.f[0].abs_ref());
                let dg = Float::with_val(prec, &g - &e.g[0]).abs();
                assert!(df <= tol && dg <= tol, "nu = {nu:?}, n = {n}, {prec} bits: {df} {dg}");
            }
        }
    }
}
