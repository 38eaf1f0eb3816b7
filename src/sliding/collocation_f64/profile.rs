//! The f64 method's own evaluation of the punch profile: g'(x) of the periodic extension, and for
//! a polynomial or circular punch (docs/theory.md section 9) the analytic g', g'' and the
//! cancellation-free divided difference of g' used by the Nyström interpolant.

use crate::params::sliding::{ShapeF64, SlidingParamsF64};
use std::f64::consts::PI;

/// g'(x) of the punch row (docs/theory.md sections 1, 9): the profile on the cell (-L/2, L/2)
/// repeated with period L. 2 k x reduced to the cell for the parabola, (2 pi D/L) sin(2 pi x/L)
/// for the sinusoid, sum_j slope_j x^j (x reduced to the cell) for a polynomial,
/// x/sqrt(R^2 - x^2) for the circle, which is +infinity for x >= R and -infinity for x <= -R
/// (its wall is vertical at |x| = R and no punch lies beyond: a gap integrated outward from the
/// contact becomes +infinity there).
pub(super) fn slope(prm: &SlidingParamsF64, x: f64) -> f64 {
    match (&prm.shape, prm.period) {
        (ShapeF64::Parabolic { k }, None) => 2.0 * k * x,
        (ShapeF64::Parabolic { k }, Some(l)) => 2.0 * k * (x - l * (x / l).round()),
        (ShapeF64::Sinusoidal { d }, Some(l)) => d * 2.0 * PI / l * (2.0 * PI * x / l).sin(),
        (ShapeF64::Sinusoidal { .. }, None) => f64::NAN, // refused by the model: a sinusoid has a period
        (ShapeF64::Polynomial { .. } | ShapeF64::Circular { .. }, period) => {
            let x = period.map_or(x, |l| x - l * (x / l).round());
            if let ShapeF64::Circular { r } = prm.shape
                && x.abs() >= r
            {
                return f64::INFINITY.copysign(x);
            }
            analytic_slope(&prm.shape, x)
        }
    }
}

fn horner(c: &[f64], x: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, v| acc * x + v)
}

/// g'(x) of a polynomial or circular profile, not reduced to the cell (the analytic function
/// whose continuation the collocation uses); NaN for the circle at |x| >= R and for the other
/// shapes.
pub(super) fn analytic_slope(shape: &ShapeF64, x: f64) -> f64 {
    match shape {
        ShapeF64::Polynomial { slope, .. } => horner(slope, x),
        ShapeF64::Circular { r } => x / ((r - x) * (r + x)).sqrt(),
        _ => f64::NAN,
    }
}

/// g''(x) of a polynomial or circular profile: sum_j curvature_j x^j, or R^2/(R^2 - x^2)^(3/2).
pub(super) fn analytic_curvature(shape: &ShapeF64, x: f64) -> f64 {
    match shape {
        ShapeF64::Polynomial { curvature, .. } => horner(curvature, x),
        ShapeF64::Circular { r } => r * r / ((r - x) * (r + x)).powf(1.5),
        _ => f64::NAN,
    }
}

/// (g'(x1) - g'(x2))/(x1 - x2) without cancellation:
/// - polynomial: sum_j slope_j (x1^j - x2^j)/(x1 - x2) = sum_j slope_j sum_{i<j} x1^i x2^(j-1-i)
///   (Horner in both variables);
/// - circle, x1 x2 >= 0: R^2 (x1 + x2)/((x1 s2 + x2 s1) s1 s2), s = sqrt(R^2 - x^2) (from
///   x1 s2 - x2 s1 = R^2 (x1^2 - x2^2)/(x1 s2 + x2 s1)); opposite signs: the plain quotient,
///   whose numerator and denominator then have no cancellation;
/// - x1 = x2: g''(x1).
pub(super) fn slope_divided_difference(shape: &ShapeF64, x1: f64, x2: f64) -> f64 {
    if x1 == x2 {
        return analytic_curvature(shape, x1);
    }
    match shape {
        ShapeF64::Polynomial { slope, .. } => {
            // q_j = sum_{i<j} x1^i x2^(j-1-i) satisfies q_(j+1) = x1^j + x2 q_j.
            let (mut q, mut p1, mut acc) = (0.0, 1.0, 0.0);
            for s in slope.iter().skip(1) {
                q = p1 + x2 * q;
                p1 *= x1;
                acc += s * q;
            }
            acc
        }
        ShapeF64::Circular { r } => {
            let s1 = ((r - x1) * (r + x1)).sqrt();
            let s2 = ((r - x2) * (r + x2)).sqrt();
            if x1 * x2 >= 0.0 {
                r * r * (x1 + x2) / ((x1 * s2 + x2 * s1) * s1 * s2)
            } else {
                (x1 / s1 - x2 / s2) / (x1 - x2)
            }
        }
        _ => f64::NAN,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn divided_differences_match_the_plain_quotient_and_the_derivative() {
        let poly = ShapeF64::Polynomial { slope: vec![0.1, 2.0, -0.3, 0.4], curvature: vec![2.0, -0.6, 1.2] };
        let circle = ShapeF64::Circular { r: 0.5 };
        for shape in [&poly, &circle] {
            for (x1, x2) in [(0.1, 0.3), (-0.2, 0.25), (0.2, -0.05), (-0.3, -0.1)] {
                let plain = (analytic_slope(shape, x1) - analytic_slope(shape, x2)) / (x1 - x2);
                let dd = slope_divided_difference(shape, x1, x2);
                assert!((dd - plain).abs() <= 1e-14 * plain.abs().max(1.0), "{shape:?} {x1} {x2}: {dd} vs {plain}");
            }
            // Near coincidence: the closed forms tend to g'' (the plain quotient would lose ~8 digits).
            let x = 0.2;
            let dd = slope_divided_difference(shape, x, x + 1e-9);
            let g2 = analytic_curvature(shape, x + 0.5e-9);
            assert!((dd - g2).abs() <= 1e-13 * g2.abs(), "{shape:?}: {dd} vs {g2}");
        }
        // g'' of the circle by a central difference of g' (independent of the closed form).
        let h = 1e-5;
        let fd = (analytic_slope(&circle, 0.3 + h) - analytic_slope(&circle, 0.3 - h)) / (2.0 * h);
        assert!((fd - analytic_curvature(&circle, 0.3)).abs() < 1e-8);
    }
}
