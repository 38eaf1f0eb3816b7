//! A polynomial or circular profile (docs/theory.md section 9) in the f64 method: the state at fixed
//! contact size with the centre found by Newton's method, and the scalar equation P2(size) = P2.
//!
//! At fixed size and centre c the right side is F(u) = (E*/2) g'(c + x(u) - c), collocated as
//! any other (one LU solve with the cached factorisation). The solvability condition
//! r(c) = (C0[p] - K) - beta tau0 (`closure.rs`: with the `periodic` convention's K) is linear in F,
//! so dr/dc is the same functional of F_c(u) = (E*/2) g''(c + x(u) - c): Newton's method in c from
//! c = 0 costs two solves per step. The load P2(size) of a convex profile increases with the size
//! (lambda = pi l/L, or l for a single punch); it is bracketed geometrically from the single-punch
//! estimate of the curvature scale k ([`SlidingParamsF64::l_s`]) and solved by Brent's method.

use super::closure::{closed, tau0_side};
use super::error::{root_error, Result, SlidingF64Error};
use super::interpolant::{basis, Basis, Rhs, State};
use super::operator::{collocation, Collocation};
use super::parabola::kuznetsov_guess;
use super::profile::{analytic_curvature, analytic_slope, slope_divided_difference};
use super::solution::SolverOptions;
use super::tangent_map::{Map, LAMBDA_MAX};
use crate::numerics::accuracy::readable_f64;
use crate::numerics::roots::{brent, Bracket};
use crate::params::sliding::{ShapeF64, SlidingParamsF64, CIRCLE_SIZE_CAP};
use std::f64::consts::PI;

/// Most Newton steps for the centre.
const CENTRE_STEPS: usize = 60;

/// The map of a size: lambda for a period, l for a single punch.
pub(super) fn map_of(prm: &SlidingParamsF64, size: f64) -> Map {
    match prm.period {
        Some(big_l) => Map::periodic(big_l, size),
        None => Map::Single { l: size },
    }
}

/// The size of a half-length: lambda = pi l/L, or l.
pub(super) fn size_of_half_length(prm: &SlidingParamsF64, l: f64) -> f64 {
    prm.period.map_or(l, |big_l| PI * l / big_l)
}

/// Largest size: lambda below [`LAMBDA_MAX`] and, for the circle, l <= [`CIRCLE_SIZE_CAP`] R.
fn size_cap(prm: &SlidingParamsF64) -> f64 {
    let by_radius = match prm.shape {
        ShapeF64::Circular { r } => size_of_half_length(prm, r * CIRCLE_SIZE_CAP),
        _ => f64::INFINITY,
    };
    match prm.period {
        Some(_) => LAMBDA_MAX.min(by_radius),
        None => by_radius,
    }
}

/// The contact [c - l, c + l] lies where the profile is defined (the circle: |x| < R).
fn defined_at(prm: &SlidingParamsF64, l: f64, c: f64) -> bool {
    match prm.shape {
        ShapeF64::Circular { r } => c.abs() + l < r,
        _ => true,
    }
}

/// The state of a polynomial or circular profile at the size of `map`: the centre c solving the
/// solvability condition (Newton's method, module doc), G and P2.
pub(super) fn profile_state(col: &Collocation, prm: &SlidingParamsF64, map: Map) -> Result<State> {
    let l = map.half_length();
    let half_e = 0.5 * prm.e_star;
    let side = tau0_side(prm, &map);
    let lost = |why: &str| SlidingF64Error::NoConvergence {
        reason: format!("the centre of the contact of half-length {}: {why}", readable_f64(l)),
    };
    let mut c = 0.0;
    if !defined_at(prm, l, c) {
        return Err(lost("the circle's contact reaches |x| = R"));
    }
    for _ in 0..CENTRE_STEPS {
        let b = slope_basis(col, prm, &map, c)?;
        let db = closed(prm, &map, basis(col, &map, |u| half_e * analytic_curvature(&prm.shape, c + map.offset(u)))?);
        let r = b.cond - side;
        if !(r.is_finite() && db.cond.is_finite()) || db.cond == 0.0 {
            return Err(lost("Newton's method met a non-finite or flat residual"));
        }
        let mut step = r / db.cond;
        let mut halvings = 0;
        while !defined_at(prm, l, c - step) {
            step *= 0.5;
            halvings += 1;
            if halvings > 60 {
                return Err(lost("the circle's contact reaches |x| = R"));
            }
        }
        c -= step;
        if step.abs() <= 4.0 * f64::EPSILON * (l + c.abs()) || r == 0.0 {
            let b = slope_basis(col, prm, &map, c)?;
            let rhs = Rhs::Profile { half_e, c, shape: prm.shape.clone() };
            return Ok(State { map, c, g: b.g, p2: b.p2, rhs });
        }
    }
    Err(lost("Newton's method did not converge"))
}

/// The unit basis of F(u) = (E*/2) g'(c + x(u) - c) at the centre c: its constant (E*/2) g'(c)
/// is solved exactly by G = 0, K = (E*/2) g'(c) (cond = C0 - K = -(E*/2) g'(c)), so only the
/// variation (E*/2) (x(u) - c) g'[c + x(u) - c, c] is collocated
/// ([`slope_divided_difference`], smooth in its arguments, times the offset as computed). Collocated
/// whole, the rounding of g' at c + x(u) - c (eps |g'(c)|, and eps |c| in the point) against a
/// variation of g'' l cost eps |c|/l of P2 and F_def, which next to a contact far off the origin
/// (adhesive friction at small loads, |c|/l up to 1e6 and more) left the f64 method 10 digits or
/// none (issue 34; the sinusoid's case in `sinusoid::sinusoid_bases`).
fn slope_basis(col: &Collocation, prm: &SlidingParamsF64, map: &Map, c: f64) -> Result<Basis> {
    let half_e = 0.5 * prm.e_star;
    let mut b = basis(col, map, |u| {
        let d = map.offset(u);
        half_e * d * slope_divided_difference(&prm.shape, c + d, c)
    })?;
    b.cond -= half_e * analytic_slope(&prm.shape, c);
    Ok(closed(prm, map, b))
}

/// Starting size: the single-punch half-length l_s of the curvature scale k [3.10], through
/// Kuznetsov's relation for a period ([`kuznetsov_guess`]).
pub(super) fn size_guess(prm: &SlidingParamsF64, p2: f64) -> f64 {
    let s = match prm.period {
        Some(big_l) => kuznetsov_guess(prm, big_l, p2),
        None => prm.l_s(p2),
    };
    s.min(0.5 * size_cap(prm))
}

/// Solves P2(size) = `p2` at `n` nodes (module doc). `near`: a size already solved at other
/// nodes (the bracket then starts at +-1e-7 relative around it).
pub(super) fn profile_size(prm: &SlidingParamsF64, p2: f64, n: usize, near: Option<f64>) -> Result<f64> {
    let col = collocation(prm.theta, n)?;
    let cap = size_cap(prm);
    let f = |s: f64| -> Result<f64> { Ok((profile_state(&col, prm, map_of(prm, s))?.p2 / p2).ln()) };
    let too_large = || SlidingF64Error::NoConvergence {
        reason: format!(
            "the load P2 = {} needs a contact larger than {} = {}{} (or more than {n} nodes)",
            readable_f64(p2),
            if prm.period.is_some() { "lambda" } else { "l" },
            readable_f64(cap),
            if matches!(prm.shape, ShapeF64::Circular { .. }) {
                ", where the circle's contact reaches |x| = R"
            } else {
                ""
            }
        ),
    };
    let (guess, width) = match near {
        Some(s) => (s, 1e-7),
        None => (size_guess(prm, p2), 0.5),
    };
    let (mut lo, mut hi) = (guess * (1.0 - width), (guess * (1.0 + width)).min(guess + 0.5 * (cap - guess)));
    let mut flo = f(lo)?;
    let mut it = 0;
    while flo > 0.0 {
        hi = lo;
        lo *= 0.5;
        flo = f(lo)?;
        it += 1;
        if it > 2000 {
            return Err(SlidingF64Error::NoConvergence {
                reason: "could not bracket the contact size from below".into(),
            });
        }
    }
    let mut fhi = match f(hi) {
        Ok(v) => v,
        Err(_) => return Err(too_large()),
    };
    while fhi < 0.0 {
        lo = hi;
        flo = fhi;
        let next = if cap.is_finite() { (hi * 2.0).min(hi + 0.5 * (cap - hi)) } else { hi * 2.0 };
        if next <= hi || (cap.is_finite() && cap - next < 1e-12 * cap) {
            return Err(too_large());
        }
        hi = next;
        fhi = f(hi).map_err(|_| too_large())?;
    }
    brent(f, Bracket { a: lo, b: hi, fa: flo, fb: fhi }, 1e-16 * hi).map_err(root_error)
}

/// Nodes for a polynomial or circular profile at `size` beyond the rule of
/// [`super::operator::collocation_nodes`]: a polynomial of degree N needs N + 8 (a single punch's
/// data are then polynomials); the circle's g' is singular at x = +-R, for a contact centred near
/// 0 at the real u* = R/l (single) or tan(pi R/L)/tan(lambda) (periodic, R < L/2), so the error
/// behaves like rho^(-2n), rho = u* + sqrt(u*^2 - 1): n = ln(1/target)/(2 ln rho) + 8 [heuristic;
/// the check run measures the error].
pub(super) fn profile_nodes(prm: &SlidingParamsF64, size: f64, options: &SolverOptions) -> usize {
    let n = match (&prm.shape, prm.period) {
        (ShapeF64::Polynomial { slope, .. }, _) => slope.len() + 8,
        (ShapeF64::Circular { r }, period) => {
            let u_star = match period {
                None => r / size,
                Some(big_l) if PI * r / big_l < 0.5 * PI => (PI * r / big_l).tan() / size.tan(),
                Some(_) => f64::INFINITY,
            };
            let rho = u_star + (u_star * u_star - 1.0).max(0.0).sqrt();
            if rho.is_finite() && rho > 1.0 {
                ((-(options.target.ln()) / (2.0 * rho.ln())).ceil() + 8.0).min(options.max_nodes as f64) as usize
            } else if rho.is_infinite() {
                8
            } else {
                options.max_nodes
            }
        }
        _ => 8,
    };
    n.clamp(8, options.max_nodes)
}
