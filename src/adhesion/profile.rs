//! Refusals of an even polynomial or circular punch on the contact [-a, a] of Problem 2
//! (docs/theory.md section 9), the same criteria as Problem 1's
//! [`crate::params::sliding::check_profile_on_contact`]: (i) the circle's contact stays inside
//! |x| < R; (ii) g'' >= 0 on [0, a] (g even; sampled at 257 Chebyshev points in `f64` from the
//! exact coefficients, relative tolerance 1e-12: a heuristic, a dip narrower than the sampling
//! is missed); (iii) g'(a) <= [`MAX_CONTACT_SLOPE`] (g' is increasing once g is convex), the
//! small-slope assumption [1.9]. The parabola is not checked (no slope limit, as before).
//! Also [`largest_admissible_half_width`]: the a with g'(a) = [`MAX_CONTACT_SLOPE`], which bounds
//! the search for the half-width of a given load.

use super::error::AdhesionError;
use crate::model::{readable, AdhesionProblem, AdhesionSize, ModelError, PunchShape};
use crate::numerics::accuracy::readable_f64;
use crate::numerics::exact::to_f64;
use crate::params::sliding::{polynomial_derivative, MAX_CONTACT_SLOPE};

/// g' and g'' of the problem's profile in `f64` (None for the parabola).
#[allow(clippy::type_complexity)]
fn slope_and_curvature(problem: &AdhesionProblem) -> Option<(Box<dyn Fn(f64) -> f64>, Box<dyn Fn(f64) -> f64>)> {
    match problem.shape() {
        PunchShape::Polynomial { coefficients } => {
            let to =
                |v: Vec<crate::model::Exact>| v.iter().map(|c| to_f64(c).unwrap_or(f64::NAN)).collect::<Vec<f64>>();
            let horner = |c: Vec<f64>| move |x: f64| c.iter().rev().fold(0.0, |acc, v| acc * x + v);
            Some((
                Box::new(horner(to(polynomial_derivative(coefficients, 1)))),
                Box::new(horner(to(polynomial_derivative(coefficients, 2)))),
            ))
        }
        PunchShape::Circular { radius } => {
            let r = to_f64(radius).unwrap_or(f64::NAN);
            Some((
                Box::new(move |x: f64| x / ((r - x) * (r + x)).sqrt()),
                Box::new(move |x: f64| r * r / ((r - x) * (r + x)).powf(1.5)),
            ))
        }
        _ => None,
    }
}

fn size_of(problem: &AdhesionProblem) -> (&'static str, String) {
    match problem.size() {
        AdhesionSize::HalfWidth(a) => ("half_width", readable(a)),
        AdhesionSize::NormalLoad(p) => ("normal_load", readable(p)),
    }
}

/// Checks (i)-(iii) of the module doc on the contact [-a, a].
pub fn check_profile_on_contact(problem: &AdhesionProblem, a: f64) -> Result<(), AdhesionError> {
    let Some((slope, curvature)) = slope_and_curvature(problem) else {
        return Ok(());
    };
    let (size_name, size_value) = size_of(problem);
    let contact = format!("[-a, a] = [-{0}, {0}]", readable_f64(a));
    if let PunchShape::Circular { radius } = problem.shape() {
        let r = to_f64(radius).unwrap_or(f64::NAN);
        if !(a < r) {
            return Err(ModelError::new(
                size_name,
                size_value,
                format!(
                    "the contact {contact} of the circular punch reaches |x| = R = {} (radius): reduce {size_name} or enlarge the radius",
                    readable(radius)
                ),
            )
            .into());
        }
    }
    let n = 256;
    for i in 0..=n {
        let x = 0.5 * a * (1.0 - (std::f64::consts::PI * i as f64 / n as f64).cos());
        let v = curvature(x);
        let scale = curvature(0.0).abs().max(curvature(a).abs());
        if !(v >= -1e-12 * scale) {
            let (name, value) = problem.shape().parameters().remove(0);
            return Err(ModelError::new(
                name,
                value,
                format!(
                    "the profile must be convex on the contact {contact} (g'' >= 0; docs/theory.md section 9), but g''({}) = {}",
                    readable_f64(x),
                    readable_f64(v)
                ),
            )
            .into());
        }
    }
    let worst = slope(a).abs();
    if !(worst <= MAX_CONTACT_SLOPE) {
        return Err(ModelError::new(
            size_name,
            size_value,
            format!(
                "g'(a) on the contact {contact} is {} > {MAX_CONTACT_SLOPE}: the theory assumes a small slope |g'| << 1 [1.9] (neglected terms O(g'^2)); reduce {size_name}",
                readable_f64(worst)
            ),
        )
        .into());
    }
    Ok(())
}

/// The half-width a with g'(a) = [`MAX_CONTACT_SLOPE`] (bisection in `f64` on the increasing
/// g'; None for the parabola, which has no slope limit). The circle: R/sqrt(1 + 1/s^2), s the limit.
pub fn largest_admissible_half_width(problem: &AdhesionProblem) -> Option<f64> {
    let (slope, _) = slope_and_curvature(problem)?;
    let mut hi = 1.0f64;
    if let PunchShape::Circular { radius } = problem.shape() {
        let s = MAX_CONTACT_SLOPE;
        return Some(to_f64(radius).unwrap_or(f64::NAN) / (1.0 + 1.0 / (s * s)).sqrt());
    }
    while slope(hi) < MAX_CONTACT_SLOPE && hi < 1e300 {
        hi *= 2.0;
    }
    let mut lo = 0.0f64;
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if slope(mid) < MAX_CONTACT_SLOPE {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(lo)
}
