//! The periodic row's unit increment and stick ratio c/a(lambda) by the spectral method
//! (docs/theory.md section 17.8, (17.10)), in `f64` and in MPFR with verified digits, both
//! surface conventions.
//!
//! Units L = pi (x = chi, a = lambda), E* = 1. In the tangent variable T = tan(chi)/tan(lambda)
//! the row's kernel is the Cauchy kernel plus a constant: cot(chi - xi) d xi = dt'/(t - t') +
//! t' dt'/(1 + t'^2), t = tan chi. So the increment S(T) = tan(lambda) sigma(chi(T)) solves the
//! single punch's equations (17.7) in T on (-1, 1) with two changes ([`Spectral::row`]): the
//! stick condition gains the constant (1/pi) int S1 tau^2 T/(1 + tau^2 T^2) dT and the right side
//! b beta tau/pi (b = 1 in `periodic`), and the unit load is int S2/(1 + tau^2 T^2) dT = 1,
//! tau = tan(lambda). The zone edges and all their periodic images sit at T = +-1, +-gamma_T, so
//! the single punch's basis and quadrature serve unchanged. c/a is local in lambda (17.2): the
//! gamma_T where the increment is bounded at the stick edge, c/a = atan(gamma_T tau)/lambda.
//! beta = 0 is exact: nothing drives a slip, c = a.
//!
//! The outside slope W(chi, eta) = H\[sigma2^eta\](chi) (chi > eta) of the unit increment at
//! contact eta, which the load's Volterra equation integrates, is [`Spectral::outside_slope`] at
//! T = tan(chi)/tan(eta), divided by tan(eta) ([`outside_slope`]).
//!
//! [`verified`]: two runs, (n, B) and (n + 6, B + 32) with n = digits + 6 polynomials per family
//! and B = 3.33 (digits + 4 + 1.2 n) + 16 bits, each a secant search for the stick edge from the
//! `f64` root; the digits of c/a are where they agree (scale 1). The bits grow with n because the
//! least squares amplify rounding by about 10^(1.2 n) (measured at lambda = 1.2, `paper`: the
//! defect's noise floor is 1e-27 at n = 20, 160 bits and 1e-28 at n = 26, 192 bits), and n is
//! larger than the single punch's: the row converges by about 5.5 digits per 6 polynomials
//! (section 17.8).

use rug::Float;

use super::real::{Mp, Real};
use super::spectral::{Spectral, SpectralIncrement};
use super::spectral_punch::{root_f64, root_mpfr, root_mpfr_stationary};
use crate::growing_contact::error::AdhesionError;
use crate::numerics::accuracy::{agreement_mpfr, digits_cap_for_bits};

/// c/a of the row with verified digits, and the `f64` run of the same method.
#[derive(Debug, Clone)]
pub struct VerifiedRowStick {
    /// c/a (the finer run).
    pub stick_ratio: Float,
    /// Digits where the two runs agree (scale 1).
    pub digits: f64,
    /// The `f64` method's c/a.
    pub stick_ratio_f64: f64,
    /// Working precision of the finer run (bits).
    pub bits: u32,
}

/// Refuses lambda outside (0, pi/2).
fn check_lambda(lambda: f64) -> Result<(), AdhesionError> {
    if lambda > 0.0 && lambda < 0.5 * std::f64::consts::PI {
        Ok(())
    } else {
        Err(AdhesionError::InvalidArgument {
            parameter: "lambda",
            value: lambda.to_string(),
            expected: "0 < lambda = pi a/L < pi/2".into(),
        })
    }
}

/// c/a = atan(gamma_T tan(lambda))/lambda of a stick half-width gamma_T in T.
pub fn physical_ratio<T: Real>(gamma_t: &T, lambda: &T) -> T {
    let tau = lambda.sin() / lambda.cos();
    (gamma_t.clone() * tau).atan() / lambda.clone()
}

/// The row's increment at its stick ratio in `f64` with `n` polynomials per family, and the
/// method (for [`outside_slope`]).
pub fn increment_f64(
    beta: f64,
    mu: f64,
    lambda: f64,
    n: usize,
    periodic: bool,
) -> Result<(Spectral<f64>, SpectralIncrement<f64>), AdhesionError> {
    check_lambda(lambda)?;
    let sp = Spectral::row(beta, mu, n, lambda.tan(), periodic);
    let inc = if beta == 0.0 {
        sp.solve(&0.5).ok_or_else(|| singular(lambda))?
    } else {
        root_f64(&sp, "periodic-row stick zone (spectral, f64)")?
    };
    Ok((sp, inc))
}

fn singular(lambda: f64) -> AdhesionError {
    AdhesionError::NotConverged {
        what: "periodic-row increment (spectral method)",
        reason: format!("the collocation system is singular at lambda = {lambda}"),
    }
}

/// c/a of the row at `lambda` in `f64` (1 at beta = 0).
pub fn stick_ratio_f64(beta: f64, mu: f64, lambda: f64, n: usize, periodic: bool) -> Result<f64, AdhesionError> {
    if beta == 0.0 {
        check_lambda(lambda)?;
        return Ok(1.0);
    }
    let (_, inc) = increment_f64(beta, mu, lambda, n, periodic)?;
    Ok(physical_ratio(&inc.gamma, &lambda))
}

/// The row's increment at its stick ratio in MPFR (`prec` bits, `n` polynomials per family), by
/// the secant method from the stick half-width `start` in T to a step below 10^-`digits`.
pub fn increment_mpfr(
    args: (&Float, &Float, &Float),
    periodic: bool,
    knobs: (usize, u32, u32),
    start: f64,
) -> Result<(Spectral<Mp>, SpectralIncrement<Mp>), AdhesionError> {
    increment_mpfr_root(args, periodic, knobs, start, false)
}

/// As [`increment_mpfr`]; with `stationary` the stick edge only to about 10^-`digits`
/// ([`root_mpfr_stationary`]: enough for the outside slope, stationary in it, to 10^-2 `digits`).
pub fn increment_mpfr_root(
    (beta, mu, lambda): (&Float, &Float, &Float),
    periodic: bool,
    (n, prec, digits): (usize, u32, u32),
    start: f64,
    stationary: bool,
) -> Result<(Spectral<Mp>, SpectralIncrement<Mp>), AdhesionError> {
    check_lambda(lambda.to_f64())?;
    let at = |x: &Float| Mp(Float::with_val(prec, x));
    let tau = Mp(Float::with_val(prec, lambda.tan_ref()));
    let sp = Spectral::row(at(beta), at(mu), n, tau, periodic);
    let inc = if beta.is_zero() {
        sp.solve(&Mp::new(prec, 0.5)).ok_or_else(|| singular(lambda.to_f64()))?
    } else if stationary {
        root_mpfr_stationary(&sp, start, digits)?
    } else {
        root_mpfr(&sp, start, digits)?
    };
    Ok((sp, inc))
}

/// W(chi, eta) = H\[sigma2^eta\](chi) for chi > eta of the increment `inc` solved by `sp` at
/// contact eta (units L = pi): the outside slope of the unit increment.
pub fn outside_slope<T: Real>(sp: &Spectral<T>, inc: &SpectralIncrement<T>, chi: &T, eta: &T) -> T {
    // T - 1 = tan(chi)/tan(eta) - 1 = sin(chi - eta)/(cos(chi) sin(eta)), without cancellation
    let beyond = (chi.clone() - eta.clone()).sin() / (chi.cos() * eta.sin());
    sp.outside_slope(inc, &beyond) * eta.cos() / eta.sin()
}

/// c/a of the row with verified digits (module doc); `beta`, `mu`, `lambda` at a precision of at
/// least 3.33 digits + 72 bits.
pub fn verified(
    beta: &Float,
    mu: &Float,
    lambda: &Float,
    periodic: bool,
    digits: u32,
) -> Result<VerifiedRowStick, AdhesionError> {
    let n = digits as usize + 6;
    let prec = (3.33 * (digits as f64 + 4.0 + 1.2 * n as f64) + 16.0).ceil() as u32;
    let lam = lambda.to_f64();
    if beta.is_zero() {
        check_lambda(lam)?;
        return Ok(VerifiedRowStick {
            stick_ratio: Float::with_val(prec + 32, 1),
            digits: digits_cap_for_bits(prec + 32),
            stick_ratio_f64: 1.0,
            bits: prec + 32,
        });
    }
    let (_, start) = increment_f64(beta.to_f64(), mu.to_f64(), lam, 10, periodic)?;
    let stick_ratio_f64 = physical_ratio(&start.gamma, &lam);
    let args = (beta, mu, lambda);
    let (_, i1) = increment_mpfr(args, periodic, (n, prec, digits + 4), start.gamma)?;
    let (_, i2) = increment_mpfr(args, periodic, (n + 6, prec + 32, digits + 4), i1.gamma.to_f64())?;
    let lam1 = Mp(Float::with_val(prec, lambda));
    let lam2 = Mp(Float::with_val(prec + 32, lambda));
    let (g1, g2) = (physical_ratio(&i1.gamma, &lam1).0, physical_ratio(&i2.gamma, &lam2).0);
    Ok(VerifiedRowStick {
        digits: agreement_mpfr(&g1, &g2, &Float::with_val(64, 1), digits_cap_for_bits(prec)),
        stick_ratio: g2,
        stick_ratio_f64,
        bits: prec + 32,
    })
}
