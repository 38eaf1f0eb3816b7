//! Refusals of an even polynomial or circular punch on the contact [-a, a] of Problem 2
//! (docs/theory.md section 9), the same criteria as Problem 1's
//! [`crate::params::sliding::check_profile_on_contact`]: (i) the circle's contact stays inside
//! |x| < R; (ii) g'' >= 0 on [0, a] (g even; sampled at 257 Chebyshev points in `f64` from the
//! exact coefficients, relative tolerance 1e-12: a heuristic, a dip narrower than the sampling
//! is missed). The slope is not refused: every shape gets the one small-slope warning of
//! [`crate::params::profile::slope_warning`] (docs/theory.md section 9). Also
//! [`half_width_search`]: where the search for the half-width of a given load may look (the
//! circle's cap short of its wall; a polynomial's first bracket, grown as needed).

use super::error::AdhesionError;
use crate::model::OnPunchRow;
use crate::model::{readable, AdhesionProblem, AdhesionSize, ModelError, PunchShape};
use crate::numerics::accuracy::readable_f64;
use crate::numerics::exact::to_f64;
use crate::params::sliding::{polynomial_derivative, CIRCLE_SIZE_CAP, MAX_CONTACT_SLOPE};

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
    let Some((_, curvature)) = slope_and_curvature(problem) else {
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
    Ok(())
}

/// Where the search for the half-width of a given load may look, by profile.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum HalfWidthSearch {
    /// The parabola: no bound of the profile's own (its single punch is self-similar).
    Parabola,
    /// A polynomial: no bound; `start` is a first bracket (the a with g'(a) =
    /// [`MAX_CONTACT_SLOPE`]), doubled while the load there is short of the target.
    Unbounded {
        /// The first bracket's end.
        start: f64,
    },
    /// The circle: a <= [`CIRCLE_SIZE_CAP`] R, short of its wall |x| = R where g' is infinite (the
    /// quadrature near that singularity stays affordable; |g'| = 2.06 there).
    Capped {
        /// The largest half-width searched.
        a_max: f64,
    },
}

/// The [`HalfWidthSearch`] of the problem's profile.
pub fn half_width_search(problem: &AdhesionProblem) -> HalfWidthSearch {
    match problem.shape() {
        PunchShape::Circular { radius } => {
            HalfWidthSearch::Capped { a_max: CIRCLE_SIZE_CAP * to_f64(radius).unwrap_or(f64::NAN) }
        }
        PunchShape::Polynomial { .. } => HalfWidthSearch::Unbounded { start: slope_half_width(problem).unwrap_or(1.0) },
        _ => HalfWidthSearch::Parabola,
    }
}

/// The refusal of a load whose contact would pass the circle's search cap `a_max` (`load`: the
/// given P2; `largest`: the load at the cap, when known).
pub(crate) fn circle_cap_error(load: &crate::model::Exact, a_max: f64, largest: Option<String>) -> AdhesionError {
    ModelError::new(
        "normal_load",
        readable(load),
        format!(
            "the contact of the circular punch would pass a = {} = {CIRCLE_SIZE_CAP} R{}, the limit of the search short \
             of its wall |x| = R (g' -> infinity); reduce normal_load or enlarge the radius",
            readable_f64(a_max),
            largest.map_or(String::new(), |p| format!(" (largest load {p})"))
        ),
    )
    .into()
}

/// The half-width a with g'(a) = [`MAX_CONTACT_SLOPE`] (bisection in `f64` on the increasing
/// g'; None for the parabola): a polynomial's first search bracket.
fn slope_half_width(problem: &AdhesionProblem) -> Option<f64> {
    let (slope, _) = slope_and_curvature(problem)?;
    let mut hi = 1.0f64;
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
