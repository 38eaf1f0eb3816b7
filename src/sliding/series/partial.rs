//! The series quantities at one truncation order (docs/theory.md section 5, [3.7]-[3.12]), in units of
//! E* (loads and pressures divided by E*; lengths as they are).

use super::point::SeriesPoint;
use crate::asymptotics::sliding::SlidingExpansion;
use crate::numerics::evaluate;
use rug::ops::Pow;
use rug::Float;

/// l, c, F_def and p(xh) from the series truncated after Lambda^order.
#[derive(Debug, Clone)]
pub struct Partial {
    /// Half-length l.
    pub l: Float,
    /// Centre c.
    pub c: Float,
    /// F_def / E*.
    pub f_def: Float,
    /// p / E* at the requested xh.
    pub pressure: Vec<Float>,
}

/// The quantities from the series truncated after Lambda^order, at the points `xh`:
/// - l, c by [`SeriesPoint::contact`];
/// - F_def = pi E* k^2 l_s^3 (F_def/(pi E* k^2 l_s^3)) (the expansion's scaled series);
/// - p = E* k l cos(pi theta) omega(xh) (1 + sum_j Lambda^(s j) pi_j(xh)), j <= order/s, s = the
///   expansion's step (2 in `paper`, 1 in `periodic`),
///   omega = (1 + xh)^(1/2 + theta) (1 - xh)^(1/2 - theta).
pub fn partial(e: &SlidingExpansion, order: usize, sp: &SeriesPoint, xh: &[Float]) -> Partial {
    let prec = sp.prec;
    let (l, c) = sp.contact(e, order);
    let fds = sp.eval(&e.f_def_scaled, order);
    let pi = Float::with_val(prec, rug::float::Constant::Pi);
    let ls3 = Float::with_val(prec, sp.l_s.clone().square() * &sp.l_s);
    let f_def = Float::with_val(prec, &pi * &sp.k) * &sp.k * ls3 * fds;
    let cos = Float::with_val(prec, Float::with_val(prec, &pi * &sp.theta).cos());
    let half = Float::with_val(prec, 0.5);
    let l_step = Float::with_val(prec, sp.big_lambda.clone().pow(e.step as u32));
    let xh_s = exact_series::Symbol::new("xh").expect("valid");
    let [th, t, kappa, invpi] = sp.bindings();
    let mut pressure = Vec::with_capacity(xh.len());
    for x in xh {
        let mut b = Float::with_val(prec, 1);
        let mut lam_pow = Float::with_val(prec, 1);
        let binds = [th.clone(), t.clone(), kappa.clone(), invpi.clone(), (xh_s, x.clone())];
        for pj in e.pressure.iter().take(order / e.step) {
            lam_pow *= &l_step;
            let v = evaluate::poly_mpfr(pj, &binds, prec)
                .expect("the pressure terms hold only theta, T, kappa, invpi and xh");
            b += Float::with_val(prec, &lam_pow * v);
        }
        let ep = Float::with_val(prec, &half + &sp.theta);
        let em = Float::with_val(prec, &half - &sp.theta);
        let omega = Float::with_val(
            prec,
            Float::with_val(prec, 1 + x).pow(&ep) * Float::with_val(prec, 1 - x.clone()).pow(&em),
        );
        pressure.push(Float::with_val(prec, &sp.k * &l) * &cos * omega * b);
    }
    Partial { l, c, f_def, pressure }
}
