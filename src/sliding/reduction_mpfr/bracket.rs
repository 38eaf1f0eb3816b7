//! The locating stage's shared pieces (docs/theory.md section 3): its digits and node cap, the noise
//! level of its load residual, and Brent's method on a bracketed size (`root_in`); used by
//! [`super::solve`] (parabola, sinusoid) and [`super::locate_profile`] (polynomial, circle).

use super::error::SlidingError;
use crate::numerics::accuracy::readable_f64;
use crate::numerics::roots::{brent, Bracket, RootError};

/// Digits the locating stage aims at.
pub(super) const LOCATE_DIGITS: f64 = 16.0;
/// Most nodes of the locating stage.
pub(super) const LOCATE_NODES: usize = 512;

/// The relative load residual of the locating stage is evaluated to ~16 digits: below this it is
/// noise, and the size counts as a root.
pub(super) const RESIDUAL_NOISE: f64 = 1e-15;

/// A root of the relative load residual `f` (None: no centre on the branch, an error) in the
/// bracket (lo, flo), (hi, fhi) with a sign change, by Brent's method to ~4 eps relative.
pub(super) fn root_in(
    mut f: impl FnMut(f64) -> Result<Option<f64>, SlidingError>,
    (lo, flo): (f64, f64),
    (hi, fhi): (f64, f64),
) -> Result<f64, SlidingError> {
    let denoise = |v: f64| if v.abs() <= RESIDUAL_NOISE { 0.0 } else { v };
    let g = |x: f64| -> Result<f64, SlidingError> {
        match f(x)? {
            Some(v) => Ok(denoise(v)),
            None => Err(SlidingError::NoConvergence(format!("the load curve has a gap at size {}", readable_f64(x)))),
        }
    };
    let bracket = Bracket { a: lo, b: hi, fa: denoise(flo), fb: denoise(fhi) };
    brent(g, bracket, 4.0 * f64::EPSILON * lo.abs().max(hi.abs())).map_err(|e| match e {
        RootError::Function(e) => e,
        other => SlidingError::NoConvergence(format!("locating the contact size: {other}")),
    })
}

/// Low-precision estimate of a contact size (lambda, or l for a single punch) and its centre branch.
pub type Located = (f64, usize);
