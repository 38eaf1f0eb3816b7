//! Physical admissibility of a solution: p >= 0 inside the contact and gap >= 0 outside it.
//!
//! Pressure: sign(p) = sign(D(u)) (see [`super::pressure`]); D is analytic on [-1, 1], sampled at
//! 68 Chebyshev points, both ends and 1 -+ 10^-j (j = 2..10).
//!
//! Gap: h(x) = int h' over the free interval. Two conventions of the model shape this check
//! (derivations in the module [`super`]): (i) the adhesive shear q1 = tau0 stops abruptly at the
//! contact ends, so v' jumps there and h' carries a constant -2 beta tau0/E* outside the contact;
//! it gives an overlap growing linearly from the leading edge b for any tau0 > 0, a property of
//! the step model itself, so it is left out of the check (h' from [`super::pressure::Pressure::gap_slope`]);
//! (ii) with the paper's symmetric summation [1.6]-[1.8] (mean of (E*/2) v' over a period is
//! -beta P1/L) and the wear law v' = g' - cW p (no mean wear slope), the surface is not periodic:
//! h' integrated over one period leaves the mismatch M = -(2/E*)(kappa P2 - 2 beta l tau0) (with
//! the tau0 step term kept). So h is integrated from each contact end toward the middle of the
//! free interval (x - c = +-L/2), not across it; the two halves need not meet. Removing M as a
//! uniform slope instead was tried and rejected: any uniform slope makes h < 0 next to one end,
//! where h ~ (x - b)^{3/2 - theta}. A self-consistent periodic model would add
//! K = (kappa P2 - 2 beta l tau0)/L to the right side of [2.8] (it shifts c by an odd power of
//! lambda); available as the opt-in [`crate::model::Convention::PeriodicSurface`], under which the
//! two halves meet (THEORY.md keeps the paper's convention, the default).
//! Points x = b + Delta s^4 (and L - a - Delta s^4) cluster at the ends; cumulative Simpson in s
//! with 16 panels.

use super::contact::Contact;
use super::error::SlidingError;
use super::pressure::Pressure;
use crate::numerics::accuracy::{readable_f64, readable_mpfr};
use crate::params::sliding::SlidingParamsMpfr;
use rug::ops::Pow;
use rug::Float;

/// Panels per side of the gap integration.
const GAP_PANELS: u32 = 16;

/// Checks p >= 0 on the contact; returns max p over the samples (in the tangent variable u).
pub fn check_pressure(params: &SlidingParamsMpfr, pressure: &Pressure<'_>) -> Result<Float, SlidingError> {
    let p = params.prec;
    // -cos(pi k/67): 67 is prime, so these points miss the Gauss–Chebyshev-like nodes
    // cos((2i+1) pi/(2n)) of theta = 0 for every n not a multiple of 67 (a coincidence is handled
    // by `Pressure::d`, only more slowly).
    let mut us: Vec<Float> =
        (0..=67u32).map(|k| -Float::with_val(p, Float::with_val(p, &params.pi * k) / 67u32).cos()).collect();
    for j in 2..=10u32 {
        let e = Float::with_val(p, 10u32).pow(-(j as i32));
        us.push(Float::with_val(p, 1u32 - Float::with_val(p, &e)));
        us.push(Float::with_val(p, &e - 1u32));
    }
    let vals: Vec<Float> = us.iter().map(|u| pressure.p_over_omega(u)).collect();
    let scale = vals.iter().map(|v| v.to_f64().abs()).fold(0.0, f64::max);
    let tol = scale * 2f64.powi(-((p as i32) / 2).min(60));
    let mut pmax = Float::with_val(p, 0);
    for (u, v) in us.iter().zip(&vals) {
        if v.to_f64() < -tol {
            return Err(SlidingError::NotPhysical {
                why: format!(
                    "negative pressure: p/omega = {} at u = {} (tangent variable; the contact would need to be smaller or the load is out of range)",
                    readable_mpfr(&Float::with_val(p, v * &params.unit)),
                    readable_mpfr(u)
                ),
            });
        }
        let pv = Float::with_val(p, pressure.omega(u) * v);
        if pv > pmax {
            pmax = pv;
        }
    }
    Ok(pmax)
}

/// Checks h >= 0 outside the contact (see the module doc for what h contains).
pub fn check_gap(params: &SlidingParamsMpfr, contact: &Contact, pressure: &Pressure<'_>) -> Result<(), SlidingError> {
    let p = params.prec;
    let l = &contact.size.l;
    // Distance from each contact end to where the integration stops.
    let delta = match &params.period {
        Some(big_l) => Float::with_val(p, big_l - Float::with_val(p, l * 2u32)) / 2u32,
        None => Float::with_val(p, l * 3u32),
    };
    let k = &params.k;
    let scale = Float::with_val(p, k * Float::with_val(p, l * l)).to_f64();
    let tol = scale * 1e-9;
    for side in [1i32, -1] {
        // Right side: x - c = l + delta s^4; left side (periodic: the next punch's trailing end
        // seen from punch 0 is x - c = -l, i.e. L - a): x - c = -l - delta s^4.
        let f = |s: &Float| -> Float {
            let s3 = Float::with_val(p, s.pow(3u32));
            let s4 = Float::with_val(p, &s3 * s);
            let mut xc = Float::with_val(p, &delta * &s4) + l;
            if side < 0 {
                xc = -xc;
            }
            // dh/ds = h'(x) dx/ds, dx/ds = 4 delta s^3 (right), and h = -int on the left.
            pressure.gap_slope(&xc) * s3 * &delta * 4u32
        };
        let n = GAP_PANELS;
        let ds = Float::with_val(p, 1u32) / n;
        let mut h = Float::with_val(p, 0);
        let mut f0 = f(&Float::with_val(p, 0));
        for i in 0..n {
            let s1 = Float::with_val(p, &ds * (i + 1));
            let sm = Float::with_val(p, &ds * i) + Float::with_val(p, &ds / 2u32);
            let fm = f(&sm);
            let f1 = f(&s1);
            let inc = (Float::with_val(p, &f0 + &f1) + Float::with_val(p, &fm * 4u32)) * &ds / 6u32;
            h += inc;
            let hv = if side > 0 { h.to_f64() } else { -h.to_f64() };
            if hv < -tol {
                let xc = Float::with_val(p, &delta * Float::with_val(p, (&s1).pow(4u32))) + l;
                return Err(SlidingError::NotPhysical {
                    why: format!(
                        "negative gap h = {} at x = c {} {} (the punch overlaps the surface outside the contact, gap integrated from the {} end){}",
                        readable_f64(hv),
                        if side > 0 { "+" } else { "-" },
                        readable_mpfr(&xc),
                        if side > 0 { "leading" } else { "trailing" },
                        if params.period.is_some() && params.convention == crate::model::Convention::Paper && i >= n / 2 {
                            "; far from the contact this depends on the paper's convention, whose surface does not close over a period (mismatch 2 beta P1/E* - cW P2), see sliding::reduction_mpfr::physical"
                        } else {
                            ""
                        }
                    ),
                });
            }
            f0 = f1;
        }
    }
    Ok(())
}
