//! The integrands of docs/theory.md section 4 in `f64` (method 2): the same formulas as the MPFR
//! kernels of [`crate::adhesion::volterra_mpfr::kernel`] (which documents them), evaluated in `f64`;
//! and the unit-load flat-punch stress, used by the tests of the surface relations.

fn sinc(z: f64) -> f64 {
    if z == 0.0 {
        1.0
    } else {
        z.sin() / z
    }
}

fn rotate(mag: f64, theta: f64, cr: f64, ci: f64) -> (f64, f64) {
    let (st, ct) = theta.sin_cos();
    (mag * (ct * cr - st * ci), mag * (ct * ci + st * cr))
}

/// s w(s) (no G): the lambda -> 0 factor, with complement c.
pub(crate) fn weight_s(s: f64, c: f64, eps: f64) -> (f64, f64) {
    let one_p = 1.0 + s;
    let mag = s / (one_p * c).sqrt();
    let theta = eps * (one_p.ln() - c.ln());
    rotate(mag, theta, 1.0, 0.0)
}

/// v-form of the stress integrand (see [`crate::adhesion::volterra_mpfr::kernel::stress_integrand_v`]): (re, im, r^2).
pub fn stress_integrand_v(sigma: f64, v: f64, lambda: f64, eps: f64) -> (f64, f64, f64) {
    let (sh, ch) = ((0.5 * v).sinh(), (0.5 * v).cosh());
    let r = sigma * v.cosh();
    let (rps, rms) = (2.0 * sigma * ch * ch, 2.0 * sigma * sh * sh);
    let a = sinc(lambda * rps);
    let b = sinc(lambda * rms);
    let mag = r / (a * b).sqrt();
    let theta = eps * (2.0 * (ch / sh).ln() + (a / b).ln());
    let x = lambda * sigma;
    let yy = 2.0 * eps * lambda * r;
    let (cr, ci) = (x.cos() * yy.cosh(), x.sin() * yy.sinh());
    let (re, im) = rotate(mag, theta, cr, ci);
    (re, im, r * r)
}

/// Stress integrand without F(r^2): (re, im, r^2).
pub fn stress_integrand(sigma: f64, omss: f64, y: f64, lambda: f64, eps: f64) -> (f64, f64, f64) {
    let y2d = y * y * omss;
    let r2 = sigma * sigma + y2d;
    let r = r2.sqrt();
    let rps = r + sigma;
    let rms = y2d / rps;
    let a = sinc(lambda * rps);
    let b = sinc(lambda * rms);
    let mag = 1.0 / (a * b).sqrt();
    let theta = eps * (2.0 * rps.ln() - y2d.ln() + a.ln() - b.ln());
    let x = lambda * sigma;
    let yy = 2.0 * eps * lambda * r;
    let (cr, ci) = (x.cos() * yy.cosh(), x.sin() * yy.sinh());
    let (re, im) = rotate(mag, theta, cr, ci);
    (re, im, r2)
}

/// L sigma_flat(x; a) for the unit-load adhesive flat punch on [-a, a] (docs/theory.md section 4):
/// cosh(pi eps) cos(chi - 2 i eps lambda) (sin(lambda+chi)/sin(lambda-chi))^{i eps}
/// / sqrt(sin^2 lambda - sin^2 chi), |chi| < lambda, in f64 as (re, im) = (q2, q1) part;
/// `lp` = lambda + chi and `lm` = lambda - chi are passed separately (accurate near the ends).
/// At eps = 0 it is Sadowsky's cos(chi)/sqrt(sin^2 lambda - sin^2 chi).
pub fn flat_punch_stress(chi: f64, lp: f64, lm: f64, lambda: f64, eps: f64, cosh_pi_eps: f64) -> (f64, f64) {
    let (sp, sm) = (lp.sin(), lm.sin());
    let mag = cosh_pi_eps / (sp * sm).sqrt();
    let theta = eps * (sp.ln() - sm.ln());
    let (cr, ci) = (chi.cos() * (2.0 * eps * lambda).cosh(), chi.sin() * (2.0 * eps * lambda).sinh());
    let (st, ct) = theta.sin_cos();
    (mag * (ct * cr - st * ci), mag * (ct * ci + st * cr))
}
