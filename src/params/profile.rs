//! The punch profile as the checks see it (docs/theory.md sections 1, 9): the exact derivatives of a
//! polynomial, the height of the punch row, the refusals of a general profile on its contact
//! (convexity, the circle's wall) and the small-slope warning of every shape in both problems
//! ([`slope_warning`], docs/theory.md section 9). Re-exported from [`super::sliding`].

use crate::error::Error;
use crate::model::OnPunchRow;
use crate::model::{Exact, ModelError, PunchShape, SlidingLoad, SlidingProblem};
use crate::numerics::exact::to_f64;
use std::f64::consts::PI;

/// Punch shape in `f64`.
#[derive(Debug, Clone, PartialEq)]
pub enum ShapeF64 {
    /// g = k x^2.
    Parabolic {
        /// k.
        k: f64,
    },
    /// g = D (1 - cos(2 pi x/L)) [2.16].
    Sinusoidal {
        /// D.
        d: f64,
    },
    /// g = sum_j c_j x^j (docs/theory.md section 9), by the coefficients of its derivatives, each
    /// formed exactly and rounded once (trailing zeros dropped).
    Polynomial {
        /// g' = sum_j slope\[j\] x^j, slope\[j\] = (j + 1) c_(j+1).
        slope: Vec<f64>,
        /// g'' = sum_j curvature\[j\] x^j, curvature\[j\] = (j + 2)(j + 1) c_(j+2).
        curvature: Vec<f64>,
    },
    /// g = R - sqrt(R^2 - x^2) (docs/theory.md section 9).
    Circular {
        /// R.
        r: f64,
    },
}

/// g of the punch row at x (docs/theory.md sections 1, 9): the profile on the cell (-L/2, L/2)
/// repeated with period L (x reduced to the cell; the sinusoid is periodic by itself), so a
/// profile with odd terms steps at the cell edges; +infinity where a circle has no punch
/// (|x| >= R in the cell). For the physicality criterion's gap (a check, in f64).
pub fn row_height_f64(shape: &ShapeF64, period: Option<f64>, x: f64) -> f64 {
    let xr = period.map_or(x, |l| x - l * (x / l).round());
    match shape {
        ShapeF64::Parabolic { k } => k * xr * xr,
        ShapeF64::Sinusoidal { d } => {
            period.map_or(f64::NAN, |l| d * (1.0 - (2.0 * std::f64::consts::PI * x / l).cos()))
        }
        // g = sum_i slope_i x^(i+1)/(i+1).
        ShapeF64::Polynomial { slope, .. } => {
            slope.iter().enumerate().rev().fold(0.0, |acc, (i, s)| acc * xr + s / (i + 1) as f64) * xr
        }
        // Beyond the wall: no punch. At the wall (|x| = R up to the rounding of the point, e.g.
        // the middle of the free arc of a circle with R = L/2 filling its cell): the height R.
        ShapeF64::Circular { r } if xr.abs() > *r * (1.0 + 4.0 * f64::EPSILON) => f64::INFINITY,
        // R - sqrt(R^2 - x^2) in the form without cancellation, x^2/(R + sqrt(R^2 - x^2)): the
        // difference lost eps R, which near a large circle's contact exceeded the gap test's
        // tolerance (issue 34, fuzz seed 2026 cases 497 and 1192: R = 818 and x = 0.015, a gap
        // of -1.1e-13 against a tolerance of 2e-14, refused in one scaling and not in the other).
        ShapeF64::Circular { r } => {
            let d = (r - xr.abs()).max(0.0);
            xr * xr / (r + (d * (r + xr.abs())).sqrt())
        }
    }
}

/// g_row(e + dx) - g_row(e), the rise of the punch row from e over dx ([`row_height_f64`] at both
/// points, differenced) without the cancellation of the two heights: where e and e + dx lie in
/// one cell, dx times the divided difference of g (parabola k dx (2 e + dx); sinusoid
/// 2 D sin(pi (2 e + dx)/L) sin(pi dx/L); polynomial dx sum_j g_j (x^j - e^j)/(x - e) by Horner
/// in both variables; circle dx (x + e)/(s_x + s_e), s = sqrt(R^2 - x^2)); across a cell edge
/// (a step of the row) the plain difference; +infinity where x has no punch. The plain difference
/// loses eps g(e) = eps k e^2, which next to a contact far off the origin (|e| >> dx) exceeds the
/// gap itself (issue 34, fuzz seed 2026 case 3960: e = -2.3e-5, dx = 1.4e-9, a gap of 1e-19
/// against a rounding of 4e-26, refused by the gap test's tolerance 1e-8 of the largest gap).
///
/// Where the plain difference loses at most 4 bits (|g(x)| + |g(e)| <= 16 |g(x) - g(e)|, e.g.
/// far from a centred contact), it is returned as it is: the two forms then agree to a few eps,
/// and the halves of a closed surface's gap, which meet at one point from both sides, keep the
/// same heights there.
pub fn row_rise_f64(shape: &ShapeF64, period: Option<f64>, e: f64, dx: f64) -> f64 {
    let x = e + dx;
    let (gx, ge) = (row_height_f64(shape, period, x), row_height_f64(shape, period, e));
    let plain = gx - ge;
    let cell = |v: f64| period.map_or(0.0, |l| (v / l).round());
    if cell(x) != cell(e) || dx == 0.0 || !plain.is_finite() || gx.abs() + ge.abs() <= 16.0 * plain.abs() {
        return plain;
    }
    let shift = period.map_or(0.0, |l| l * cell(e));
    let (er, xr) = (e - shift, x - shift);
    match shape {
        ShapeF64::Parabolic { k } => k * dx * (2.0 * er + dx),
        ShapeF64::Sinusoidal { d } => {
            period.map_or(f64::NAN, |l| 2.0 * d * (PI * (2.0 * er + dx) / l).sin() * (PI * dx / l).sin())
        }
        // g = sum_j g_j x^j, g_j = slope_(j-1)/j (j >= 1); q_j = (x^j - e^j)/(x - e) satisfies
        // q_(j+1) = x^j + e q_j.
        ShapeF64::Polynomial { slope, .. } => {
            let (mut q, mut xp, mut acc) = (0.0, 1.0, 0.0);
            for (i, s) in slope.iter().enumerate() {
                q = xp + er * q;
                xp *= xr;
                acc += s / (i + 1) as f64 * q;
            }
            dx * acc
        }
        ShapeF64::Circular { r } => {
            if xr.abs() > *r * (1.0 + 4.0 * f64::EPSILON) || er.abs() > *r * (1.0 + 4.0 * f64::EPSILON) {
                return plain;
            }
            let s = |v: f64| ((r - v.abs()).max(0.0) * (r + v.abs())).sqrt();
            let (sx, se) = (s(xr), s(er));
            if sx + se == 0.0 {
                return plain;
            }
            dx * (xr + er) / (sx + se)
        }
    }
}

/// The exact coefficients of g^(order) for g = sum_j c_j x^j (order 1: g', 2: g''), trailing
/// zeros dropped (at least one entry).
pub fn polynomial_derivative(coefficients: &[Exact], order: usize) -> Vec<Exact> {
    let mut d: Vec<Exact> = coefficients
        .iter()
        .enumerate()
        .skip(order)
        .map(|(j, c)| {
            let mut f = Exact::from_integer(1.into());
            for i in 0..order {
                f *= Exact::from_integer(((j - i) as i64).into());
            }
            c * f
        })
        .collect();
    while d.len() > 1 && d.last().is_some_and(num_traits::Zero::is_zero) {
        d.pop();
    }
    if d.is_empty() {
        d.push(Exact::from_integer(0.into()));
    }
    d
}

/// Largest |g'| on the contact without a warning, for every shape in both problems (docs/theory.md
/// section 9, the small-slope rule). The theory linearises the boundary conditions in the slope
/// ([1.9]: |g'| << 1, the boundary of the half-plane and its normal are taken as those of the
/// undeformed surface); the neglected terms are relative O(g'^2) (e.g. the normal's direction
/// cosine 1/sqrt(1 + g'^2) = 1 - g'^2/2), i.e. up to 12% at |g'| = 1/2. Beyond it the answer is
/// still the linear problem's, to the digits printed (the problem is linear in the profile: g
/// scaled by s scales every load and stress by s at the same contact, so any slope is a small
/// one's answer scaled), and the output warns with the slope and where ([`slope_warning`]).
pub const MAX_CONTACT_SLOPE: f64 = 0.5;

/// The largest |g'| on the contact [`left`, `right`] of `shape` (`period`: L, or None for a single
/// punch), and where: (|g'|, x). At the ends for the parabola, a convex polynomial (g' increasing)
/// and the circle; the sinusoid's g' = (2 pi D/L) sin(2 pi x/L) peaks at x = +-L/4 when the contact
/// holds it. `f64` from the exact parameters (a warning's figure, not a printed result).
pub(crate) fn max_contact_slope(shape: &PunchShape, period: Option<f64>, left: f64, right: f64) -> (f64, f64) {
    let f = |q: &Exact| to_f64(q).unwrap_or(f64::NAN);
    let slope: Box<dyn Fn(f64) -> f64> = match shape {
        PunchShape::Parabolic { k } => {
            let k = f(k);
            Box::new(move |x| 2.0 * k * x)
        }
        PunchShape::Sinusoidal { amplitude } => {
            let (d, l) = (f(amplitude), period.unwrap_or(f64::NAN));
            let peak = 2.0 * PI * d / l;
            for x in [-0.25 * l, 0.25 * l] {
                if left <= x && x <= right {
                    return (peak, x);
                }
            }
            Box::new(move |x| peak * (2.0 * PI * x / l).sin())
        }
        PunchShape::Polynomial { coefficients } => {
            let d1: Vec<f64> = polynomial_derivative(coefficients, 1).iter().map(f).collect();
            Box::new(move |x| d1.iter().rev().fold(0.0, |acc, c| acc * x + c))
        }
        PunchShape::Circular { radius } => {
            let r = f(radius);
            Box::new(move |x| x / ((r - x) * (r + x)).sqrt())
        }
    };
    let (l, r) = (slope(left).abs(), slope(right).abs());
    // A tie within rounding (a symmetric contact, whose two ends' slopes differ in the last bits
    // of their evaluation) goes to the right end.
    if r >= l * (1.0 - 1e-12) {
        (r, right)
    } else {
        (l, left)
    }
}

/// The small-slope warning (docs/theory.md section 9), one rule for every shape in both problems:
/// None when max |g'| on the contact [`left`, `right`] is at most [`MAX_CONTACT_SLOPE`], else a
/// sentence naming the slope, where it is reached and what it means.
pub fn slope_warning(shape: &PunchShape, period: Option<f64>, left: f64, right: f64) -> Option<String> {
    let (s, x) = max_contact_slope(shape, period, left, right);
    (s > MAX_CONTACT_SLOPE).then(|| {
        format!(
            "small slope: |g'| = {} at x = {} on the contact [{}, {}] exceeds {MAX_CONTACT_SLOPE}; the linear theory \
             assumes |g'| << 1 [1.9] (neglected terms relative O(g'^2), about {:.0}% here): the answer is the linear \
             problem's, to the digits printed, and a coarse model of the physical contact (docs/theory.md section 9)",
            crate::numerics::accuracy::readable_f64(s),
            crate::numerics::accuracy::readable_f64(x),
            crate::numerics::accuracy::readable_f64(left),
            crate::numerics::accuracy::readable_f64(right),
            50.0 * s * s
        )
    })
}

/// Largest half-length, as a fraction of the circle's radius, that the locating stages search:
/// there |g'| = 0.9/sqrt(1 - 0.81) = 2.06, far beyond [`MAX_CONTACT_SLOPE`], so no admissible
/// contact is lost, and the quadrature near the singularity of g' at |x| = R stays affordable.
pub const CIRCLE_SIZE_CAP: f64 = 0.9;

/// Refusals of a polynomial or circular profile on a found contact [-a, b] = [`left`, `right`]
/// (docs/theory.md section 9), evaluated in `f64` from the exact profile: (i) the circle's contact
/// must stay inside |x| < R; (ii) g'' >= 0 on [-a, b] (sampled at 257 Chebyshev points and the
/// ends, relative tolerance 1e-12: a heuristic, a dip narrower than the sampling is missed);
/// The slope is not refused: [`slope_warning`] is the one rule of every shape. The parabola and
/// the sinusoid are not checked here. Each error names the parameter to change, its value and the
/// valid range.
pub fn check_profile_on_contact(problem: &SlidingProblem, left: f64, right: f64) -> Result<(), Error> {
    // The texts of the errors, formatted only when one is returned (the f64 solver calls this
    // for every solve, most of them of the unchecked shapes).
    let size_name = match problem.load() {
        SlidingLoad::NormalLoad(_) => "normal_load",
        SlidingLoad::HalfLength(_) => "half_length",
    };
    let size_value = || match problem.load() {
        SlidingLoad::NormalLoad(p) => crate::model::readable(p),
        SlidingLoad::HalfLength(l) => crate::model::readable(l),
    };
    let contact = || {
        format!(
            "[-a, b] = [{}, {}]",
            crate::numerics::accuracy::readable_f64(left),
            crate::numerics::accuracy::readable_f64(right)
        )
    };
    let curvature_at: Box<dyn Fn(f64) -> f64> = match problem.shape() {
        PunchShape::Polynomial { coefficients } => {
            let d2: Vec<f64> =
                polynomial_derivative(coefficients, 2).iter().map(|c| to_f64(c).unwrap_or(f64::NAN)).collect();
            Box::new(move |x: f64| d2.iter().rev().fold(0.0, |acc, v| acc * x + v))
        }
        PunchShape::Circular { radius } => {
            let r = to_f64(radius).unwrap_or(f64::NAN);
            if !(left.abs() < r && right.abs() < r) {
                return Err(Error::Input(ModelError::new(
                    size_name,
                    size_value(),
                    format!(
                        "the contact {} of the circular punch reaches |x| = R = {} (radius): reduce {size_name} or enlarge the radius",
                        contact(),
                        crate::model::readable(radius)
                    ),
                )));
            }
            Box::new(move |x: f64| r * r / ((r - x) * (r + x)).powf(1.5))
        }
        _ => return Ok(()),
    };
    // (ii) convexity.
    let n = 256;
    let xs: Vec<f64> = (0..=n)
        .map(|i| {
            let t = -(PI * i as f64 / n as f64).cos();
            0.5 * (left + right) + 0.5 * (right - left) * t
        })
        .collect();
    let g2: Vec<f64> = xs.iter().map(|x| curvature_at(*x)).collect();
    let scale = g2.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    if let Some((x, v)) = xs.iter().zip(&g2).find(|(_, v)| !(**v >= -1e-12 * scale)) {
        let (name, value) = problem.shape().parameters().remove(0);
        return Err(Error::Input(ModelError::new(
            name,
            value,
            format!(
                "the profile must be convex on the contact {} (g'' >= 0; docs/theory.md section 9), but g''({}) = {}",
                contact(),
                crate::numerics::accuracy::readable_f64(*x),
                crate::numerics::accuracy::readable_f64(*v)
            ),
        )));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Float;

    /// g(e + dx) - g(e) in MPFR (256 bits) from the f64 inputs, e + dx exact.
    fn rise_mpfr(shape: &ShapeF64, period: Option<f64>, e: f64, dx: f64) -> f64 {
        let f = |v: f64| Float::with_val(256, v);
        let g = |x: &Float| -> Float {
            match shape {
                ShapeF64::Parabolic { k } => Float::with_val(256, x * x) * *k,
                ShapeF64::Sinusoidal { d } => {
                    let l = period.unwrap();
                    let pi = Float::with_val(256, rug::float::Constant::Pi);
                    (1 - Float::with_val(256, x * pi * 2u32 / l).cos()) * *d
                }
                ShapeF64::Polynomial { slope, .. } => {
                    let mut acc = Float::with_val(256, 0);
                    for (i, s) in slope.iter().enumerate().rev() {
                        acc = acc * x + Float::with_val(256, f(*s) / (i as u32 + 1));
                    }
                    acc * x
                }
                ShapeF64::Circular { r } => f(*r) - (f(*r * *r) - Float::with_val(256, x * x)).sqrt(),
            }
        };
        let x = Float::with_val(256, f(e) + f(dx));
        Float::with_val(256, g(&x) - g(&f(e))).to_f64()
    }

    /// Next to a contact far off the origin (e = -2.3e-5, dx from 1e-15 to 1e-9, fuzz seed 2026
    /// case 3960) the rise of every shape is within a few eps of itself, where the plain
    /// difference of heights loses eps g(e) (up to 1e6 times the rise); across a cell edge (a
    /// step of the row) it is the plain difference.
    #[test]
    fn the_rise_of_the_row_has_no_cancellation() {
        let shapes = [
            (ShapeF64::Parabolic { k: 25.0 / 74.0 }, None),
            (ShapeF64::Sinusoidal { d: 0.01 }, Some(1e-3)),
            (ShapeF64::Polynomial { slope: vec![0.0, 2.0, 0.0, 0.4], curvature: vec![2.0, 0.0, 1.2] }, None),
            (ShapeF64::Polynomial { slope: vec![0.02, 2.0, 1.5], curvature: vec![2.0, 3.0] }, Some(1.0)),
            (ShapeF64::Circular { r: 0.5 }, None),
        ];
        for (shape, period) in &shapes {
            for e in [-2.3e-5, 7.1e-3] {
                for dx in [1e-15, -3e-12, 1.4e-9, -1e-9] {
                    let rise = row_rise_f64(shape, *period, e, dx);
                    let exact = rise_mpfr(shape, *period, e, dx);
                    assert!(
                        (rise - exact).abs() <= 8.0 * f64::EPSILON * exact.abs(),
                        "{shape:?} e {e} dx {dx}: {rise:e} vs {exact:e}"
                    );
                }
            }
        }
        // Across the cell edge x = 1/2 of a row with an odd term: the step g(-1/2) - g(1/2) is in it.
        let (shape, period) = &shapes[3];
        let (e, dx) = (0.49, 0.02);
        let plain = row_height_f64(shape, *period, e + dx) - row_height_f64(shape, *period, e);
        assert_eq!(row_rise_f64(shape, *period, e, dx), plain);
    }
}
