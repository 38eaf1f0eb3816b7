//! The single punch's stick ratio gamma = c/a and load coefficient C_P = P/(E* k a^2) by the
//! spectral method (`spectral.rs`, docs/theory.md section 17.7) in `f64` and in MPFR with
//! verified digits.
//!
//! gamma is the zero of the stick-edge defect D(gamma) (negative below, positive above):
//! - `f64` ([`stick_ratio_f64`], [`root_f64`]): a coarse run (n = 6, no oversampling) scanned
//!   upward in the logit y = ln(gamma/(1 - gamma)) from gamma = 0.0025 in steps of 1/2 to the first
//!   sign change from - to + (up to gamma = 1 - 1.2e-4), its root by the Illinois method to 1e-6
//!   in y; then the run asked for bracketed there (+-1e-3 in y, widened by 8 up to 0.5; the full
//!   scan where that or the coarse run fails) and the Illinois method to a bracket of 1e-13 in y
//!   (about 10 solves instead of 20-30);
//! - MPFR ([`stick_ratio_mpfr`]): the secant method from a start (the `f64` root) to a step below
//!   2^-(bits - 16). C_P is stationary in gamma at the root (measured: dC_P/dgamma changes sign
//!   there), so the last iterate's C_P carries the root's error squared;
//! - MPFR where the slip zone is narrow ([`slip_width_mpfr`], large mu, docs/theory.md section
//!   17.3 "Large mu"): the root in ln(1 - gamma), bracketed by factors of 1.5 in the width and
//!   refined by the Illinois method, gamma formed in MPFR as 1 - width.
//!
//! [`verified`]: two discretisations at two precisions, (n, B) and (n + 6, B + 32) with
//! n = max(8, digits - 2) polynomials per family and B = 3.33 (digits + 14) + 16 bits (the
//! collocation loses about 10 digits to rounding, section 17.7); the verified digits are
//! those where the two agree, for gamma and for C_P (docs/theory.md section 17.7 for the measured
//! convergence). beta = 0 is exact (gamma = 1, C_P = pi/2). The two runs' increments are kept
//! ([`VerifiedPunch::runs`]) for the fields of `spectral_punch_fields.rs`.

use rug::ops::Pow;
use rug::Float;

use super::real::{Mp, Real};
use super::single_punch::illinois;
use super::spectral::{Spectral, SpectralIncrement};
use crate::growing_contact::error::AdhesionError;
use crate::numerics::accuracy::{agreement_mpfr, digits_cap_for_bits};

/// gamma and C_P in MPFR with their verified digits, and the `f64` run of the same method.
#[derive(Debug, Clone)]
pub struct VerifiedPunch {
    /// gamma = c/a (the finer run).
    pub gamma: Float,
    /// C_P = P/(E* k a^2) (the finer run).
    pub load_coefficient: Float,
    /// Digits where the two runs agree on gamma (scale 1).
    pub gamma_digits: f64,
    /// Digits where the two runs agree on C_P (relative).
    pub load_digits: f64,
    /// The `f64` method's gamma.
    pub gamma_f64: f64,
    /// The `f64` method's C_P.
    pub load_f64: f64,
    /// Working precision of the finer run (bits).
    pub bits: u32,
    /// The two runs (coarser, finer) for the fields (`spectral_punch_fields.rs`); none at
    /// beta = 0 (exact).
    pub runs: Option<[PunchRun; 2]>,
}

/// One MPFR run of [`verified`]: the method, its increment at the root and C_P.
pub type PunchRun = (Spectral<Mp>, SpectralIncrement<Mp>, Mp);

/// The scan's range in the logit y = ln(gamma/(1 - gamma)): gamma from 0.0025 to 1 - 1.2e-4.
const Y_MIN: f64 = -6.0;
/// See [`Y_MIN`].
const Y_MAX: f64 = 9.0;

fn not_converged(reason: String) -> AdhesionError {
    AdhesionError::NotConverged { what: "stick ratio (spectral method)", reason }
}

fn singular(gamma: f64) -> AdhesionError {
    not_converged(format!("the collocation system is singular at c/a = {gamma}"))
}

/// (gamma, C_P) in `f64` with `n` polynomials per family.
pub fn stick_ratio_f64(beta: f64, mu: f64, n: usize, coupled: bool) -> Result<(f64, f64), AdhesionError> {
    let sp = Spectral::new(beta, mu, n, coupled);
    let inc = root_f64(&sp, "single-punch stick zone (spectral, f64)")?;
    Ok((inc.gamma, sp.load_coefficient(&inc)))
}

/// The increment at the zero of the stick-edge defect of `sp` in `f64` (module doc); `what`
/// names the method in a refusal.
pub fn root_f64(sp: &Spectral<f64>, what: &'static str) -> Result<SpectralIncrement<f64>, AdhesionError> {
    let gamma = |y: f64| 1.0 / (1.0 + (-y).exp());
    let defect_of = |s: &Spectral<f64>, y: f64| -> Result<f64, AdhesionError> {
        let g = gamma(y);
        Ok(s.solve(&g).ok_or_else(|| singular(g))?.stick_edge_defect())
    };
    let defect = |y: f64| defect_of(sp, y);
    // the coarse run's root, then a bracket of it for `sp` widened until the sign changes
    let coarse = sp.coarse(COARSE_N);
    let coarse_root =
        scan(|y| defect_of(&coarse, y), what).and_then(|(lo, hi)| illinois(lo, hi, 1e-6, |y| defect_of(&coarse, y)));
    let Ok(y0) = coarse_root else {
        let (lo, hi) = scan(defect, what)?;
        let g = gamma(illinois(lo, hi, 1e-13, defect)?);
        return sp.solve(&g).ok_or_else(|| singular(g));
    };
    let mut h = 1e-3;
    let (lo, hi) = loop {
        let (a, b) = (y0 - h, y0 + h);
        let (da, db) = (defect(a)?, defect(b)?);
        if da < 0.0 && db >= 0.0 {
            break ((a, da), (b, db));
        }
        if h > 0.1 {
            break scan(defect, what)?;
        }
        h *= 8.0;
    };
    let g = gamma(illinois(lo, hi, 1e-13, defect)?);
    sp.solve(&g).ok_or_else(|| singular(g))
}

/// A bracket in the logit: (y, defect) below and above the sign change.
type Bracket = ((f64, f64), (f64, f64));

/// Polynomials per family of the coarse run that brackets the `f64` root.
const COARSE_N: usize = 6;

/// The first sign change of `defect` from - to + upward in the logit y from [`Y_MIN`] in steps
/// of 1/2 to [`Y_MAX`].
fn scan(
    mut defect: impl FnMut(f64) -> Result<f64, AdhesionError>,
    what: &'static str,
) -> Result<Bracket, AdhesionError> {
    let (mut lo, mut d_lo) = (Y_MIN, defect(Y_MIN)?);
    loop {
        let y = lo + 0.5;
        if y > Y_MAX {
            return Err(AdhesionError::IllConditioned {
                method: what,
                parameter: "c/a",
                value: "outside [0.0025, 1 - 1.2e-4]".into(),
                valid: "0.0025 <= c/a <= 1 - 1.2e-4".into(),
                reason: "the stick-edge defect has no sign change from - to + in this range".into(),
            });
        }
        let d = defect(y)?;
        if d_lo < 0.0 && d >= 0.0 {
            return Ok(((lo, d_lo), (y, d)));
        }
        (lo, d_lo) = (y, d);
    }
}

/// (gamma, C_P) in MPFR at `prec` bits with `n` polynomials per family, by the secant method
/// from `start` (within about 1e-6 of the root) to a step below 10^-`digits`.
pub fn stick_ratio_mpfr(
    beta: &Float,
    mu: &Float,
    knobs: (usize, u32, u32),
    start: f64,
    coupled: bool,
) -> Result<(Float, Float), AdhesionError> {
    let (_, inc, load) = run_mpfr(beta, mu, knobs, start, coupled)?;
    Ok((inc.gamma.0, load.0))
}

/// [`stick_ratio_mpfr`] with the method and its increment kept ([`PunchRun`]).
pub fn run_mpfr(
    beta: &Float,
    mu: &Float,
    (n, prec, digits): (usize, u32, u32),
    start: f64,
    coupled: bool,
) -> Result<PunchRun, AdhesionError> {
    let at = |x: &Float| Mp(Float::with_val(prec, x));
    let sp = Spectral::new(at(beta), at(mu), n, coupled);
    let inc = root_mpfr(&sp, start, digits)?;
    let load = sp.load_coefficient(&inc);
    Ok((sp, inc, load))
}

/// The increment at the zero of the stick-edge defect of `sp` in MPFR, by the secant method from
/// `start` (within about 1e-6 of the root) to a step below 10^-`digits`.
pub fn root_mpfr(sp: &Spectral<Mp>, start: f64, digits: u32) -> Result<SpectralIncrement<Mp>, AdhesionError> {
    secant(sp, start, digits, false)
}

/// As [`root_mpfr`], but returns the last solved iterate once the next secant step (its error) is
/// below 10^-`digits`, one solve earlier: for a quantity stationary in gamma at the root (C_P,
/// the row's outside slope: docs/theory.md section 17.8), whose error is then that step squared.
pub fn root_mpfr_stationary(
    sp: &Spectral<Mp>,
    start: f64,
    digits: u32,
) -> Result<SpectralIncrement<Mp>, AdhesionError> {
    secant(sp, start, digits, true)
}

fn secant(
    sp: &Spectral<Mp>,
    start: f64,
    digits: u32,
    stationary: bool,
) -> Result<SpectralIncrement<Mp>, AdhesionError> {
    let prec = sp.bits();
    let solve = |g: &Mp| sp.solve(g).ok_or_else(|| singular(g.to_f64()));
    let mut g0 = Mp::new(prec, start);
    let mut g1 = Mp::new(prec, start * (1.0 - 1e-8));
    let (mut d0, mut inc1) = (solve(&g0)?.stick_edge_defect(), solve(&g1)?);
    let tol = Mp(Float::with_val(prec, 10u32).pow(-(digits as i32)));
    for _ in 0..30 {
        let d1 = inc1.stick_edge_defect();
        let denom = d1.clone() - d0.clone();
        if denom == g0.lit(0.0) {
            break;
        }
        let g2 = g1.clone() - d1.clone() * (g1.clone() - g0.clone()) / denom;
        let one = g2.lit(1.0);
        if !(g2 > g2.lit(0.0) && g2 < one) {
            return Err(not_converged(format!("the secant step left 0 < c/a < 1 ({})", g2.to_f64())));
        }
        let step = (g2.clone() - g1.clone()).abs();
        if stationary && step < tol {
            return Ok(inc1);
        }
        (g0, d0) = (g1, d1);
        g1 = g2;
        inc1 = solve(&g1)?;
        if step < tol {
            return Ok(inc1);
        }
    }
    Err(not_converged(format!("the secant iteration did not settle (c/a = {})", g1.to_f64())))
}

/// The slip zone's width 1 - gamma and C_P in MPFR where it is narrow (large mu, docs/theory.md
/// section 17.3 "Large mu"): [`slip_width`] at `sp`'s precision.
pub fn slip_width_mpfr(sp: &Spectral<Mp>, start: f64, tol: f64) -> Result<(Float, Float), AdhesionError> {
    let (w, p) = slip_width(sp, start, tol)?;
    Ok((w.0, p.0))
}

/// The slip zone's width 1 - gamma and C_P where it is narrow, in `f64` or MPFR: the zero of the
/// stick-edge defect in y = ln(1 - gamma), gamma formed as 1 - e^y (in MPFR a width of 1e-8 keeps
/// its relative digits; in `f64` gamma carries the width to 1e-16 absolute), bracketed from
/// `start` (a width) by steps of a factor 1.5 (at most 40), then the Illinois method to a bracket
/// of `tol` in y. The defect is taken to `f64` for the search: its sign and size, not its digits.
pub fn slip_width<T: Real>(sp: &Spectral<T>, start: f64, tol: f64) -> Result<(T, T), AdhesionError> {
    let inc = slip_width_root(sp, start, tol)?;
    Ok((inc.gamma.lit(1.0) - inc.gamma.clone(), sp.load_coefficient(&inc)))
}

/// The increment at the root of [`slip_width`] (the search there; the row's narrow slip zones,
/// docs/theory.md section 17.8).
pub fn slip_width_root<T: Real>(sp: &Spectral<T>, start: f64, tol: f64) -> Result<SpectralIncrement<T>, AdhesionError> {
    let one = sp.tau().lit(1.0);
    let gamma = |y: f64| one.clone() - one.lit(y).exp();
    let defect = |y: f64| -> Result<f64, AdhesionError> {
        let g = gamma(y);
        Ok(sp.solve(&g).ok_or_else(|| singular(g.to_f64()))?.stick_edge_defect().to_f64())
    };
    if !(start > 0.0 && start < 1.0) {
        return Err(AdhesionError::InvalidArgument {
            parameter: "start",
            value: start.to_string(),
            expected: "a slip-zone width 0 < 1 - c/a < 1".into(),
        });
    }
    // the defect is negative below the root in gamma, i.e. above it in y; illinois wants it
    // increasing, so it runs in z = -y
    let (mut y, mut d) = (start.ln(), defect(start.ln())?);
    let step = if d < 0.0 { -(1.5f64.ln()) } else { 1.5f64.ln() };
    let mut bracket = None;
    for _ in 0..40 {
        let y2 = y + step;
        if y2 >= 0.0 {
            break;
        }
        let d2 = defect(y2)?;
        if (d2 < 0.0) != (d < 0.0) {
            bracket = Some(if d < 0.0 { ((-y, d), (-y2, d2)) } else { ((-y2, d2), (-y, d)) });
            break;
        }
        (y, d) = (y2, d2);
    }
    let Some((lo, hi)) = bracket else {
        return Err(not_converged(format!("no sign change of the stick-edge defect near 1 - c/a = {start}")));
    };
    let y = -illinois(lo, hi, tol, |z| defect(-z))?;
    sp.solve(&gamma(y)).ok_or_else(|| singular(1.0 - y.exp()))
}

/// gamma and C_P with verified digits (module doc); `beta`, `mu` at a precision of at least
/// 3.33 digits + 72 bits (exact values of the problem).
pub fn verified(beta: &Float, mu: &Float, digits: u32) -> Result<VerifiedPunch, AdhesionError> {
    let prec = (3.33 * (digits + 14) as f64 + 16.0).ceil() as u32;
    if beta.is_zero() {
        let pi = Float::with_val(prec + 32, rug::float::Constant::Pi) / 2u32;
        return Ok(VerifiedPunch {
            gamma: Float::with_val(prec + 32, 1),
            load_coefficient: pi,
            gamma_digits: digits_cap_for_bits(prec + 32),
            load_digits: digits_cap_for_bits(prec + 32),
            gamma_f64: 1.0,
            load_f64: std::f64::consts::FRAC_PI_2,
            bits: prec + 32,
            runs: None,
        });
    }
    let n = (digits as usize).saturating_sub(2).max(8);
    let (gamma_f64, load_f64) = stick_ratio_f64(beta.to_f64(), mu.to_f64(), 10, true)?;
    let coarse = run_mpfr(beta, mu, (n, prec, digits + 4), gamma_f64, true)?;
    let fine = run_mpfr(beta, mu, (n + 6, prec + 32, digits + 4), coarse.1.gamma.to_f64(), true)?;
    let (g1, p1) = (&coarse.1.gamma.0, &coarse.2 .0);
    let (g2, p2) = (fine.1.gamma.0.clone(), fine.2 .0.clone());
    let cap = digits_cap_for_bits(prec);
    Ok(VerifiedPunch {
        gamma_digits: agreement_mpfr(g1, &g2, &Float::with_val(64, 1), cap),
        load_digits: agreement_mpfr(p1, &p2, &p2, cap),
        gamma: g2,
        load_coefficient: p2,
        gamma_f64,
        load_f64,
        bits: prec + 32,
        runs: Some([coarse, fine]),
    })
}
