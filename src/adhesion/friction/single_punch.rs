//! The single punch (period "inf"), parabola g = k x^2, normal loading, finite friction: the stick
//! ratio gamma = c/a and the load coefficient C_P = P/(E* k a^2) of the self-similar solution
//! (docs/theory.md section 17) by two methods, each on two meshes (n and 2 n stick elements) for
//! its error estimate:
//! - [`Method::Increment`]: the unit increment bounded at the stick edge (`increment_f64.rs`);
//! - [`Method::State`]: the current state with (v0, C) fixed by boundedness and gamma by the
//!   sign change of |q1| - mu q2 next to the stick edge (`state_f64.rs`).
//!
//! The state method enforces boundedness at the contact edge by q2 = 0 on the last element, which
//! separates the bounded (1 - x)^(1/2 + theta0) from the unbounded (1 - x)^(-1/2 + theta0) ever
//! less well as theta0 -> 1/2 (mu -> infinity): measured at beta = 1/2, it agrees with the increment
//! to its estimate up to mu = 5, differs by 1e-3 in gamma and 4e-3 in C_P at mu = 64, and finds no
//! stick edge at mu = 256 (refused); the increment holds 1e-4 to mu = 1024.
//!
//! gamma is searched in the logit y = ln(gamma/(1 - gamma)) by bisection, over
//! [`GAMMA_MIN`] = 1e-6 <= gamma <= [`GAMMA_MAX`] = 1 - 1e-4; a root outside (a stick zone narrower than
//! 1e-6 a, a slip zone narrower than 1e-4 a, which the f64 mesh does not resolve) is refused. beta = 0 (nu = 1/2) is
//! exact: nothing drives a slip, the whole contact sticks (gamma = 1) and C_P = pi/2 (Hertz).

use super::increment_f64::{increment, load_coefficient, stick_edge_defect};
use super::state_f64::state;
use crate::growing_contact::error::AdhesionError;

/// What a refusal of the single punch's stick ratio names.
const SINGLE: &str = "single-punch stick zone (f64)";

/// Smallest stick ratio the f64 meshes resolve.
pub const GAMMA_MIN: f64 = 1e-6;
/// Largest stick ratio the f64 meshes resolve (slip zones of 1e-4 a: the smallest slip element is
/// then about 1e-4 (1/2)(1/2n)^4 a, a few hundred ulp of 1 at n = 80).
pub const GAMMA_MAX: f64 = 1.0 - 1e-4;

/// Which discretisation of the self-similar problem.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// The unit increment, bounded at the stick edge; C_P from the edge slope (17.9).
    Increment,
    /// The current state, bounded at 1 and gamma; gamma from |q1| = mu q2, C_P = 2 int q2.
    State,
}

/// gamma = c/a and C_P = P/(E* k a^2) with their error estimates (the difference of the two
/// meshes; the finer mesh's values are returned).
#[derive(Debug, Clone, PartialEq)]
pub struct SinglePunchF64 {
    /// The stick ratio c/a.
    pub gamma: f64,
    /// |gamma(n) - gamma(2 n)|.
    pub gamma_error: f64,
    /// The load coefficient P/(E* k a^2).
    pub load_coefficient: f64,
    /// |C_P(n) - C_P(2 n)|.
    pub load_coefficient_error: f64,
}

/// The checked inputs: beta in [0, 1/2], mu > 0 finite, n >= 4 stick elements.
fn check(beta: f64, mu: f64, n: usize) -> Result<(), AdhesionError> {
    let bad = |parameter, value: String, expected: &str| AdhesionError::InvalidArgument {
        parameter,
        value,
        expected: expected.into(),
    };
    if !(0.0..=0.5).contains(&beta) {
        return Err(bad("beta", beta.to_string(), "0 <= beta <= 1/2 (nu in [0, 1/2])"));
    }
    if !(mu.is_finite() && mu > 0.0) {
        return Err(bad("friction", mu.to_string(), "a friction coefficient mu > 0 (finite)"));
    }
    if n < 4 {
        return Err(bad("elements", n.to_string(), "at least 4 stick elements"));
    }
    Ok(())
}

/// The stick ratio (`what` names it in a refusal): `defect` is positive above it and negative
/// below it (down to [`GAMMA_MIN`]; on meshes with a stick zone much narrower than that the discrete defect turns
/// positive again, an artefact). Scanned downward in the logit y = ln(gamma/(1 - gamma)) from
/// [`GAMMA_MAX`] in steps of 2 to the first negative value, then the Illinois method to a bracket
/// of 1e-10 in y; refused when there is no sign change in [GAMMA_MIN, GAMMA_MAX].
pub(crate) fn stick_ratio(
    what: &'static str,
    mut defect: impl FnMut(f64) -> Result<f64, AdhesionError>,
) -> Result<f64, AdhesionError> {
    let gamma = |y: f64| 1.0 / (1.0 + (-y).exp());
    let logit = |g: f64| (g / (1.0 - g)).ln();
    let (y_min, y_max) = (logit(GAMMA_MIN), logit(GAMMA_MAX));
    let refuse = |value: String| AdhesionError::IllConditioned {
        method: what,
        parameter: "c/a",
        value,
        valid: format!("{GAMMA_MIN:e} <= c/a <= 1 - {:e}", 1.0 - GAMMA_MAX),
        reason: "the stick-edge condition has no sign change in the range the mesh resolves".into(),
    };
    let (mut hi, mut d_hi) = (y_max, defect(gamma(y_max))?);
    if d_hi <= 0.0 {
        return Err(refuse(format!("> 1 - {:e}", 1.0 - GAMMA_MAX)));
    }
    let (lo, d_lo) = loop {
        let y = hi - 2.0;
        if y < y_min {
            return Err(refuse(format!("< {GAMMA_MIN:e}")));
        }
        let d = defect(gamma(y))?;
        if d < 0.0 {
            break (y, d);
        }
        (hi, d_hi) = (y, d);
    };
    let y = illinois((lo, d_lo), (hi, d_hi), 1e-10, |y| defect(gamma(y)))?;
    Ok(gamma(y))
}

/// The Illinois method (regula falsi with halving of the retained end's value) on a bracket
/// with f(lo) < 0 <= f(hi), to a bracket narrower than `tol` (at most 100 steps); its middle.
pub fn illinois<E>(
    (mut lo, mut f_lo): (f64, f64),
    (mut hi, mut f_hi): (f64, f64),
    tol: f64,
    mut f: impl FnMut(f64) -> Result<f64, E>,
) -> Result<f64, E> {
    let mut side = 0;
    for _ in 0..100 {
        if (hi - lo).abs() < tol {
            break;
        }
        let y = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
        let d = f(y)?;
        if d < 0.0 {
            (lo, f_lo) = (y, d);
            if side == -1 {
                f_hi *= 0.5;
            }
            side = -1;
        } else {
            (hi, f_hi) = (y, d);
            if side == 1 {
                f_lo *= 0.5;
            }
            side = 1;
        }
    }
    Ok(0.5 * (lo + hi))
}

/// (gamma, C_P) of one method on one mesh of `n` stick elements.
pub fn solve_once(beta: f64, mu: f64, n: usize, method: Method, coupled: bool) -> Result<(f64, f64), AdhesionError> {
    check(beta, mu, n)?;
    if beta == 0.0 {
        return Ok((1.0, std::f64::consts::FRAC_PI_2));
    }
    match method {
        Method::Increment => {
            let g = stick_ratio(SINGLE, |g| Ok(stick_edge_defect(&increment(beta, mu, g, n, coupled)?, beta, mu)))?;
            Ok((g, load_coefficient(&increment(beta, mu, g, n, coupled)?)))
        }
        Method::State => {
            let g = stick_ratio(SINGLE, |g| {
                let s = state(beta, mu, g, n)?;
                Ok(s.stick_margin())
            })?;
            Ok((g, state(beta, mu, g, n)?.load_coefficient()))
        }
    }
}

/// (gamma, C_P) of the coupled problem by `method` on n and on 2 n stick elements.
pub fn solve_pair(beta: f64, mu: f64, n: usize, method: Method) -> Result<[(f64, f64); 2], AdhesionError> {
    Ok([solve_once(beta, mu, n, method, true)?, solve_once(beta, mu, 2 * n, method, true)?])
}

/// gamma and C_P of the coupled problem by `method` on n and 2 n stick elements.
pub fn solve(beta: f64, mu: f64, n: usize, method: Method) -> Result<SinglePunchF64, AdhesionError> {
    Ok(from_pair(solve_pair(beta, mu, n, method)?))
}

/// The finer mesh's (gamma, C_P) with the differences from the coarser one as their estimates.
pub fn from_pair([(g1, p1), (g2, p2)]: [(f64, f64); 2]) -> SinglePunchF64 {
    SinglePunchF64 {
        gamma: g2,
        gamma_error: (g2 - g1).abs(),
        load_coefficient: p2,
        load_coefficient_error: (p2 - p1).abs(),
    }
}
