//! Locating the contact of a polynomial or circular punch (docs/theory.md section 9) at low
//! precision, and the node count such a profile needs; the stages of [`super::solve`] for the
//! parabola and the sinusoid stay there.

use super::bracket::{root_in, Located, LOCATE_DIGITS, LOCATE_NODES, RESIDUAL_NOISE};
use super::error::SlidingError;
use super::setup::Setup;
use crate::numerics::accuracy::readable_f64;
use crate::params::sliding::{ShapeMpfr, SlidingParamsMpfr, CIRCLE_SIZE_CAP};
use rug::Float;

/// A node count beyond every cap (the contact reaches the circle's singularity).
const HOPELESS: usize = 1 << 20;

/// Nodes a polynomial or circular profile needs beyond `super::solve::nodes_for` at size `s` (lambda, or l
/// for a single punch); 0 for the parabola and the sinusoid. A polynomial of degree N makes the
/// single punch's integrands polynomials of degree about N + 1: N + 8 nodes. The circle's g' is
/// singular at x = +-R, i.e. (for a contact centred near 0) at the real u* = R/l (single) or
/// tan(pi R/L)/m (periodic, when R < L/2), so the error behaves like rho^(-2n),
/// rho = u* + sqrt(u*^2 - 1) (Bernstein ellipse): n = (digits + 4) ln 10/(2 ln rho) [heuristic:
/// the centre c != 0 moves the singularity; the second run of `solve_verified` measures the
/// digits actually obtained].
pub(super) fn profile_nodes(params: &SlidingParamsMpfr, s: f64, digits: f64) -> usize {
    match &params.shape {
        ShapeMpfr::Polynomial { slope, .. } => slope.len() + 8,
        ShapeMpfr::Circular { r } => {
            let r = r.to_f64();
            let u_star = match &params.period {
                None => r / s,
                Some(big_l) => {
                    let angle = std::f64::consts::PI * r / big_l.to_f64();
                    if angle >= std::f64::consts::FRAC_PI_2 {
                        return 8;
                    }
                    angle.tan() / s.tan()
                }
            };
            if !(u_star > 1.0) {
                return HOPELESS;
            }
            let rho = u_star + (u_star * u_star - 1.0).sqrt();
            let n = ((digits + 4.0) * std::f64::consts::LN_10 / (2.0 * rho.ln())).ceil();
            if n > HOPELESS as f64 {
                HOPELESS
            } else {
                (n as usize).max(8)
            }
        }
        _ => 0,
    }
}

/// The locating stage for a polynomial or circular punch (docs/theory.md section 9): P2 grows with the
/// contact size for a convex profile, so the size is bracketed geometrically from the
/// single-punch estimate l_s of the curvature scale k ([`SlidingParamsMpfr::k`]) and refined by
/// Brent's method, as for the parabola. The sizes are capped by the lambda of the node cap, by
/// the cell (2 l < L) and, for the circle, by l < R. A size where no centre exists (the circle's
/// contact reaching |x| = R) counts as too large.
pub(super) fn locate_profile(
    setup: &Setup,
    params: &SlidingParamsMpfr,
    p2: &Float,
    cap: f64,
    f: impl Fn(f64, usize) -> Result<Option<f64>, SlidingError>,
) -> Result<Vec<Located>, SlidingError> {
    let ls = params.l_s(p2).to_f64();
    let radius = match &params.shape {
        ShapeMpfr::Circular { r } => Some(r.to_f64() * CIRCLE_SIZE_CAP),
        _ => None,
    };
    let smax = match (&params.period, radius) {
        (Some(big_l), r) => {
            let big_l = big_l.to_f64();
            let by_r = r.map_or(f64::INFINITY, |r| std::f64::consts::PI * r / big_l);
            cap.min(by_r)
        }
        (None, Some(r)) => r,
        (None, None) => f64::INFINITY,
    };
    let s_of_l = |l: f64| match &params.period {
        Some(big_l) => std::f64::consts::PI * l / big_l.to_f64(),
        None => l,
    };
    let too_large = || {
        SlidingError::NoSolution {
        load: setup.load_text.clone().unwrap_or_default(),
        why: format!(
            "the contact would exceed {} (lambda = pi l/L of about {LOCATE_NODES} nodes for {LOCATE_DIGITS} digits, the cell 2 l < L{})",
            if params.period.is_some() { format!("lambda = {}", readable_f64(smax)) } else { format!("l = {}", readable_f64(smax)) },
            if radius.is_some() { ", or the circle's |x| < R (l <= 0.9 R searched)" } else { "" }
        ),
    }
    };
    let eval = |s: f64| -> Result<Option<f64>, SlidingError> { Ok(f(s, 0)?.filter(|v| v.is_finite())) };
    let mut s0 = s_of_l(ls).min(0.5 * smax).max(1e-300);
    let mut f0 = eval(s0)?;
    let mut tries = 0;
    while f0.is_none() {
        s0 *= 0.5;
        f0 = eval(s0)?;
        tries += 1;
        if tries > 60 {
            return Err(SlidingError::NoConvergence(format!(
                "no centre of the contact found below size {}",
                readable_f64(s0)
            )));
        }
    }
    let f0 = f0.expect("loop exits with a value");
    if f0.abs() <= RESIDUAL_NOISE {
        return Ok(vec![(s0, 0)]);
    }
    let (mut lo, mut flo, mut hi, mut fhi) = (s0, f0, s0, f0);
    let mut tries = 0;
    while fhi < 0.0 {
        lo = hi;
        flo = fhi;
        let next = if smax.is_finite() { (hi * 2.0).min(hi + 0.5 * (smax - hi)) } else { hi * 2.0 };
        tries += 1;
        if tries > 200 || (smax.is_finite() && smax - next < 1e-12 * smax) {
            return Err(too_large());
        }
        hi = next;
        fhi = match eval(hi)? {
            Some(v) => v,
            None => return Err(too_large()),
        };
    }
    let mut tries = 0;
    while flo > 0.0 {
        hi = lo;
        fhi = flo;
        lo *= 0.5;
        flo = eval(lo)?.ok_or_else(|| SlidingError::NoConvergence("no centre at a smaller contact".into()))?;
        tries += 1;
        if tries > 2000 {
            return Err(SlidingError::NoConvergence("no lower bracket for the contact size".into()));
        }
    }
    Ok(vec![(root_in(|x| f(x, 0), (lo, flo), (hi, fhi))?, 0)])
}
