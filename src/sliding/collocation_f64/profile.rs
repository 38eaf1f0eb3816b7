//! The f64 method's own evaluation of the punch profile: g'(x) of the periodic extension.

use crate::params::sliding::{ShapeF64, SlidingParamsF64};
use std::f64::consts::PI;

/// g'(x) of the periodic extension (THEORY.md section 1, [2.16]): 2 k x reduced to the cell
/// (-L/2, L/2) for the parabola, (2 pi D/L) sin(2 pi x/L) for the sinusoid.
pub(super) fn slope(prm: &SlidingParamsF64, x: f64) -> f64 {
    match (prm.shape, prm.period) {
        (ShapeF64::Parabolic { k }, None) => 2.0 * k * x,
        (ShapeF64::Parabolic { k }, Some(l)) => 2.0 * k * (x - l * (x / l).round()),
        (ShapeF64::Sinusoidal { d }, Some(l)) => d * 2.0 * PI / l * (2.0 * PI * x / l).sin(),
        (ShapeF64::Sinusoidal { .. }, None) => f64::NAN, // refused by the model: a sinusoid has a period
    }
}
