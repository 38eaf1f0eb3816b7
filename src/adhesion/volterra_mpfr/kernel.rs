//! The regularised kernels of the incremental (Mossakovskii) method, docs/theory.md section 4.
//!
//! With chi = pi x/L, eta = chi s (s in (0, 1)) and sinc z = sin z/z, the kernel of the Volterra
//! equation factors as
//!   K(chi, chi s) chi = w(s) G(chi, s),  w(s) = (1+s)^{-1/2+i eps} (1-s)^{-1/2-i eps},
//!   G(chi, s) = cos(chi (1 - 2 i eps s)) (sinc(chi(1+s))/sinc(chi(1-s)))^{i eps}
//!               / sqrt(sinc(chi(1+s)) sinc(chi(1-s))),
//! where w is the half-range weight of the moments M_m (docs/theory.md section 5) and G is analytic,
//! even in chi, G(0, s) = 1. Likewise the flat-punch stress sigma_flat(x; a') of docs/theory.md
//! section 4, integrated against dP2(a') over a' = a r, r in (sigma, 1), sigma = x/a, becomes after
//! r = sqrt(sigma^2 + (1 - sigma^2) y^2) (which removes the inverse square root)
//!   (q2 + i q1)/(E* k a) = (cosh(pi eps)/pi) sqrt(1 - sigma^2)
//!      int_0^1 cos(lambda(sigma - 2 i eps r)) (r + sigma)^{2 i eps} ((1 - sigma^2) y^2)^{-i eps}
//!      (sinc(lambda(r+sigma))/sinc(lambda(r-sigma)))^{i eps}
//!      / sqrt(sinc(lambda(r+sigma)) sinc(lambda(r-sigma))) F(r^2) dy,
//! with P'(eta) = eta f(eta^2), F(tau) = f(lambda^2 tau). At lambda = 0 (single punch) and eps = 0
//! this is Hertz: F = pi, q2 = E* k a sqrt(1 - sigma^2).
//!
//! The same integrands in `f64` (method 2): [`crate::adhesion::series_f64::kernel`].
//!
//! The `periodic` convention (u periodic; docs/theory.md section 8, Problem 2) changes one factor
//! of both kernels: cos(chi - 2 i eps eta) -> cos(chi - i eps (2 eta - pi))/cosh(pi eps)
//! ([`LateralShift`]); G is then no longer even in chi, and F is interpolated in sigma instead of
//! sigma^2 ([`super::volterra`]).

use rug::float::Constant;
use rug::{Assign, Float};

/// The `periodic` convention's change of the kernels (module doc): the shift pi eps of the
/// imaginary part of the cosine's argument and the factor 1/cosh(pi eps).
#[derive(Debug, Clone)]
pub struct LateralShift {
    /// pi eps.
    pub pi_eps: Float,
    /// 1/cosh(pi eps).
    pub inv_cosh_pi_eps: Float,
}

impl LateralShift {
    /// The shift for `eps` at `prec` bits.
    pub fn new(eps: &Float, prec: u32) -> Self {
        let pi_eps = Float::with_val(prec, Constant::Pi) * eps;
        let inv_cosh_pi_eps = Float::with_val(prec, pi_eps.cosh_ref()).recip();
        LateralShift { pi_eps, inv_cosh_pi_eps }
    }
}

/// sinc z = sin z / z (1 at z = 0).
pub fn sinc(z: &Float, prec: u32) -> Float {
    if z.is_zero() {
        return Float::with_val(prec, 1u32);
    }
    Float::with_val(prec, z.sin_ref()) / z
}

/// s w(s) G(chi, s) as (re, im) for s with complement c = 1 - s (both accurate).
pub fn volterra_integrand(s: &Float, c: &Float, chi: &Float, eps: &Float, prec: u32) -> (Float, Float) {
    let one_p = Float::with_val(prec, s + 1u32);
    let a = sinc(&Float::with_val(prec, chi * &one_p), prec);
    let b = sinc(&Float::with_val(prec, chi * c), prec);
    let mag = Float::with_val(prec, &one_p * c) * &a * &b;
    let mag = Float::with_val(prec, s / mag.sqrt());
    let theta = Float::with_val(prec, one_p.ln_ref()) - Float::with_val(prec, c.ln_ref())
        + Float::with_val(prec, a.ln_ref())
        - Float::with_val(prec, b.ln_ref());
    let theta = theta * eps;
    let y = Float::with_val(prec, chi * s) * eps * 2u32;
    let (cr, ci) = cos_minus_i(chi, &y, prec);
    rotate(&mag, &theta, &cr, &ci, prec)
}

/// cos(x - i y) = cos x cosh y + i sin x sinh y.
fn cos_minus_i(x: &Float, y: &Float, prec: u32) -> (Float, Float) {
    let (sx, cx) = x.clone().sin_cos(Float::new(prec));
    let (shy, chy) = y.clone().sinh_cosh(Float::new(prec));
    (cx * chy, sx * shy)
}

/// mag e^{i theta} (cr + i ci).
fn rotate(mag: &Float, theta: &Float, cr: &Float, ci: &Float, prec: u32) -> (Float, Float) {
    let (st, ct) = theta.clone().sin_cos(Float::new(prec));
    let re = Float::with_val(prec, &ct * cr) - Float::with_val(prec, &st * ci);
    let im = Float::with_val(prec, &ct * ci) + Float::with_val(prec, &st * cr);
    (re * mag, im * mag)
}

/// The stress integrand without F(r^2), at node y (complement of y not needed), as
/// (re, im, r^2). `one_minus_sigma_sq` = 1 - sigma^2 > 0 (rounded once from the exact point).
pub fn stress_integrand(
    sigma: &Float,
    one_minus_sigma_sq: &Float,
    y: &Float,
    lambda: &Float,
    eps: &Float,
    shift: Option<&LateralShift>,
    prec: u32,
) -> (Float, Float, Float) {
    let y2d = Float::with_val(prec, y * y) * one_minus_sigma_sq; // r^2 - sigma^2
    let r2 = Float::with_val(prec, sigma * sigma) + &y2d;
    let r = Float::with_val(prec, r2.sqrt_ref());
    let rps = Float::with_val(prec, &r + sigma);
    let rms = Float::with_val(prec, &y2d / &rps);
    let a = sinc(&Float::with_val(prec, lambda * &rps), prec);
    let b = sinc(&Float::with_val(prec, lambda * &rms), prec);
    let mag = Float::with_val(prec, &a * &b).sqrt().recip();
    let theta = Float::with_val(prec, rps.ln_ref()) * 2u32 - Float::with_val(prec, y2d.ln_ref())
        + Float::with_val(prec, a.ln_ref())
        - Float::with_val(prec, b.ln_ref());
    let theta = theta * eps;
    let x = Float::with_val(prec, lambda * sigma);
    let mut yy = Float::with_val(prec, lambda * &r) * eps * 2u32;
    if let Some(shift) = shift {
        yy -= &shift.pi_eps;
    }
    let (cr, ci) = cos_minus_i(&x, &yy, prec);
    let (re, im) = rotate(&mag, &theta, &cr, &ci, prec);
    (re, im, r2)
}

/// The stress integrand in the variable v, r = sigma cosh v (0 < sigma < 1, v in (0, acosh(1/sigma))),
/// used for small sigma where the y-form of [`stress_integrand`] has branch points at
/// y = +-i sigma/sqrt(1 - sigma^2) close to its end y = 0 (slow tanh-sinh convergence). Here
/// r dr/sqrt(r^2 - sigma^2) = r dv and ((r+sigma)/(r-sigma))^{i eps} = coth(v/2)^{2 i eps}, so
///   (q2 + i q1)/(E* k a) = (cosh(pi eps)/pi) int_0^{acosh(1/sigma)} cos(lambda(sigma - 2 i eps r))
///       coth(v/2)^{2 i eps} (sinc(lambda(r+sigma))/sinc(lambda(r-sigma)))^{i eps}
///       / sqrt(sinc(lambda(r+sigma)) sinc(lambda(r-sigma))) r F(r^2) dv,
/// whose singularities in v lie at distance pi from the real axis. Returns (re, im, r^2) without
/// F(r^2) and without the prefactor, times r.
pub fn stress_integrand_v(
    sigma: &Float,
    v: &Float,
    lambda: &Float,
    eps: &Float,
    shift: Option<&LateralShift>,
    prec: u32,
) -> (Float, Float, Float) {
    let half = Float::with_val(prec, v / 2u32);
    let (sh, ch) = half.sinh_cosh(Float::new(prec));
    let r = Float::with_val(prec, &ch * &ch) * sigma * 2u32 - sigma; // sigma cosh v
    let rps = Float::with_val(prec, &ch * &ch) * sigma * 2u32;
    let rms = Float::with_val(prec, &sh * &sh) * sigma * 2u32;
    let a = sinc(&Float::with_val(prec, lambda * &rps), prec);
    let b = sinc(&Float::with_val(prec, lambda * &rms), prec);
    let mag = Float::with_val(prec, &a * &b).sqrt().recip() * &r;
    let theta = (Float::with_val(prec, &ch / &sh).ln() * 2u32 + Float::with_val(prec, &a / &b).ln()) * eps;
    let x = Float::with_val(prec, lambda * sigma);
    let mut yy = Float::with_val(prec, lambda * &r) * eps * 2u32;
    if let Some(shift) = shift {
        yy -= &shift.pi_eps;
    }
    let (cr, ci) = cos_minus_i(&x, &yy, prec);
    let (re, im) = rotate(&mag, &theta, &cr, &ci, prec);
    let r2 = Float::with_val(prec, &r * &r);
    (re, im, r2)
}

/// Per-node constants of the Volterra integrand (independent of chi): s^2,
/// ln((1+s)/(1-s)) and s/sqrt((1+s)(1-s)), to evaluate [`volterra_integrand`] with fewer
/// transcendental calls.
#[derive(Debug, Clone)]
pub struct VolterraNodes {
    /// s^2.
    pub s2: Vec<Float>,
    /// ln((1+s)/(1-s)).
    pub log_ratio: Vec<Float>,
    /// s/sqrt((1+s)(1-s)).
    pub amp: Vec<Float>,
    /// 1 + s.
    pub one_p: Vec<Float>,
}

impl VolterraNodes {
    /// From the nodes s and complements c.
    pub fn new(s: &[Float], c: &[Float], prec: u32) -> Self {
        let mut out = VolterraNodes { s2: vec![], log_ratio: vec![], amp: vec![], one_p: vec![] };
        for (sj, cj) in s.iter().zip(c) {
            let one_p = Float::with_val(prec, sj + 1u32);
            out.s2.push(Float::with_val(prec, sj * sj));
            out.log_ratio.push(Float::with_val(prec, &one_p / cj).ln());
            out.amp.push(Float::with_val(prec, sj / Float::with_val(prec, &one_p * cj).sqrt()));
            out.one_p.push(one_p);
        }
        out
    }

    /// Same value as [`volterra_integrand`] at node j; `sc_chi` = (sin chi, cos chi); with a
    /// `shift`, the `periodic` convention's kernel (module doc). [`Self::factors`] and then
    /// [`integrand_from_factors`].
    #[allow(clippy::too_many_arguments)]
    pub fn integrand(
        &self,
        j: usize,
        s: &Float,
        c: &Float,
        chi: &Float,
        sc_chi: &(Float, Float),
        eps: &Float,
        shift: Option<&LateralShift>,
        prec: u32,
    ) -> (Float, Float) {
        let (mag, log_sum) = self.factors(j, c, chi, prec);
        integrand_from_factors(&mut FactorScratch::new(prec), &mag, &log_sum, s, chi, sc_chi, eps, shift)
    }

    /// The factors of [`Self::integrand`] at node j (complement `c`) that depend on chi and the
    /// node only, not on the material or the convention: (mag, L) with
    /// mag = s/sqrt((1+s)(1-s) sinc(chi(1+s)) sinc(chi(1-s))) and
    /// L = ln(sinc(chi(1+s))/sinc(chi(1-s))) + ln((1+s)/(1-s)), the phase being theta = eps L.
    pub fn factors(&self, j: usize, c: &Float, chi: &Float, prec: u32) -> (Float, Float) {
        let a = sinc(&Float::with_val(prec, chi * &self.one_p[j]), prec);
        let b = sinc(&Float::with_val(prec, chi * c), prec);
        let ab = Float::with_val(prec, &a * &b);
        let mag = Float::with_val(prec, &self.amp[j] / ab.sqrt());
        let log_sum = Float::with_val(prec, &a / &b).ln() + &self.log_ratio[j];
        (mag, log_sum)
    }
}

/// The intermediate numbers of [`integrand_from_factors`] at one precision, reused from node to
/// node: an operation into a scratch number rounds as into a fresh one of the same precision, so
/// the bits are those of the one-piece evaluation, with nine allocations fewer per node.
#[derive(Debug)]
pub struct FactorScratch {
    prec: u32,
    theta: Float,
    y: Float,
    shy: Float,
    chy: Float,
    cr: Float,
    ci: Float,
    st: Float,
    ct: Float,
    t: Float,
}

impl FactorScratch {
    /// Scratch at `prec` bits.
    pub fn new(prec: u32) -> Self {
        let z = Float::new(prec);
        FactorScratch {
            prec,
            theta: z.clone(),
            y: z.clone(),
            shy: z.clone(),
            chy: z.clone(),
            cr: z.clone(),
            ci: z.clone(),
            st: z.clone(),
            ct: z.clone(),
            t: z,
        }
    }
}

/// The integrand of [`VolterraNodes::integrand`] from its [`VolterraNodes::factors`] (mag, L) at
/// node s, at the scratch's precision: mag e^(i eps L) cos(chi - i y), y = 2 eps chi s (minus
/// pi eps with a `shift`, the product divided by cosh(pi eps)); every operation rounded as in the
/// one-piece evaluation (test `factored_integrand_keeps_the_one_piece_bits`).
#[allow(clippy::too_many_arguments)]
pub fn integrand_from_factors(
    w: &mut FactorScratch,
    mag: &Float,
    log_sum: &Float,
    s: &Float,
    chi: &Float,
    sc_chi: &(Float, Float),
    eps: &Float,
    shift: Option<&LateralShift>,
) -> (Float, Float) {
    w.theta.assign(log_sum * eps);
    w.y.assign(chi * s);
    w.y *= eps;
    w.y *= 2u32;
    if let Some(shift) = shift {
        w.y -= &shift.pi_eps;
    }
    (&mut w.shy, &mut w.chy).assign(w.y.sinh_cosh_ref());
    w.cr.assign(&sc_chi.1 * &w.chy);
    w.ci.assign(&sc_chi.0 * &w.shy);
    // mag e^(i theta) (cr + i ci), as `rotate`.
    (&mut w.st, &mut w.ct).assign(w.theta.sin_cos_ref());
    let mut re = Float::with_val(w.prec, &w.ct * &w.cr);
    w.t.assign(&w.st * &w.ci);
    re -= &w.t;
    let mut im = Float::with_val(w.prec, &w.ct * &w.ci);
    w.t.assign(&w.st * &w.cr);
    im += &w.t;
    re *= mag;
    im *= mag;
    if let Some(shift) = shift {
        re *= &shift.inv_cosh_pi_eps;
        im *= &shift.inv_cosh_pi_eps;
    }
    (re, im)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn adhesion_precomputed_integrand_matches_direct() {
        let prec = 128;
        let s = Float::with_val(prec, 0.7);
        let c = Float::with_val(prec, 1u32) - &s;
        let chi = Float::with_val(prec, 0.9);
        let eps = Float::with_val(prec, 0.17);
        let pre = VolterraNodes::new(std::slice::from_ref(&s), std::slice::from_ref(&c), prec);
        let sc = chi.clone().sin_cos(Float::new(prec));
        let (r1, i1) = pre.integrand(0, &s, &c, &chi, &sc, &eps, None, prec);
        let (r2, i2) = volterra_integrand(&s, &c, &chi, &eps, prec);
        assert!(Float::with_val(prec, r1 - r2).abs().to_f64() < 1e-35);
        assert!(Float::with_val(prec, i1 - i2).abs().to_f64() < 1e-35);
    }

    #[test]
    fn factored_integrand_keeps_the_one_piece_bits() {
        // The integrand as it was computed in one piece, fresh numbers for every operation,
        // against the factors and the reused scratch: every bit, both conventions, eps = 0 and
        // eps > 0, at one and two limbs.
        for prec in [64u32, 107, 131] {
            let mut scratch = FactorScratch::new(prec);
            for (s, eps, chi, shifted) in [
                (0.7, 0.17, 0.9, false),
                (0.013, 0.0566, 1.41, true),
                (0.999, 0.0, 0.3, false),
                (0.4, 0.2206, 1.2, true),
            ] {
                let (s, eps, chi) = (Float::with_val(prec, s), Float::with_val(prec, eps), Float::with_val(prec, chi));
                let c = Float::with_val(prec, 1u32) - &s;
                let pre = VolterraNodes::new(std::slice::from_ref(&s), std::slice::from_ref(&c), prec);
                let sc = chi.clone().sin_cos(Float::new(prec));
                let shift = shifted.then(|| LateralShift::new(&eps, prec));
                let one_piece = {
                    let a = sinc(&Float::with_val(prec, &chi * &pre.one_p[0]), prec);
                    let b = sinc(&Float::with_val(prec, &chi * &c), prec);
                    let ab = Float::with_val(prec, &a * &b);
                    let mag = Float::with_val(prec, &pre.amp[0] / ab.sqrt());
                    let theta = (Float::with_val(prec, &a / &b).ln() + &pre.log_ratio[0]) * &eps;
                    let mut y = Float::with_val(prec, &chi * &s) * &eps * 2u32;
                    if let Some(shift) = &shift {
                        y -= &shift.pi_eps;
                    }
                    let (shy, chy) = y.sinh_cosh(Float::new(prec));
                    let cr = Float::with_val(prec, &sc.1 * &chy);
                    let ci = Float::with_val(prec, &sc.0 * &shy);
                    let (re, im) = rotate(&mag, &theta, &cr, &ci, prec);
                    match &shift {
                        Some(shift) => (re * &shift.inv_cosh_pi_eps, im * &shift.inv_cosh_pi_eps),
                        None => (re, im),
                    }
                };
                let (mag, l) = pre.factors(0, &c, &chi, prec);
                let factored = integrand_from_factors(&mut scratch, &mag, &l, &s, &chi, &sc, &eps, shift.as_ref());
                assert_eq!(factored, one_piece, "prec {prec}, s {s}");
                assert_eq!(pre.integrand(0, &s, &c, &chi, &sc, &eps, shift.as_ref(), prec), one_piece);
            }
        }
    }
}
