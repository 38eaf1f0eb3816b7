//! The surface convention in the collocated equation (docs/theory.md section 8). With `periodic`
//! ([`Convention::PeriodicSurface`]) the right side of [2.8] gains the constant
//!
//! ```text
//! K = (kappa P2 - 2 beta l tau0)/L,   i.e.  beta tau0 -> beta tau0 + K,
//! ```
//!
//! which closes the surface over a period. K is a constant on the contact, so it changes only the
//! solvability condition C0[p] - K_coll = beta tau0 (+ K) of the module doc of `collocation_f64`.
//! Since P2 = sum of the unit bases' loads times their amplitudes, K is moved to the left at fixed
//! contact size: each unit basis' solvability functional gains -kappa P2_unit/L and the tau0 term
//! becomes beta tau0 (1 - 2 l/L) (the same split as the MPFR method's
//! [`crate::sliding::reduction_mpfr::equation::shift_solutions`]). At a given load this is the
//! same as adding the known K to the right side; at a given size it keeps the side conditions
//! linear in the amplitudes. `paper` or a single punch (K = 0 as L -> infinity): unchanged.
//!
//! Off the contact the same K enters the slope of the gap: with the rotation of the Flamant sum
//! removed ((E*/2) v' gains beta P1/L) and the steady wear slope cW P2/L of the worn surface,
//! h' = g' - (2/E*) (H[p] - K) (the MPFR method's continuation of [2.8] contains it by
//! construction). The f64 method's slope off the contact, the continued collocated equation
//! (`physical.rs`), holds it through the solvability condition, and its plain rule where the
//! profile has no continuation (beyond a circle's wall) takes it from [`k_constant`]; the two
//! halves of the gap then meet over the free arc.

use super::interpolant::Basis;
use super::tangent_map::Map;
use crate::model::Convention;
use crate::params::sliding::SlidingParamsF64;

/// The period when the problem's convention adds K at this map (periodic convention, finite L).
fn closing_period(prm: &SlidingParamsF64, map: &Map) -> Option<f64> {
    match (prm.convention, *map) {
        (Convention::PeriodicSurface, Map::Periodic { big_l, .. }) => Some(big_l),
        _ => None,
    }
}

/// A unit basis with the load part of K moved into its solvability functional:
/// cond -> cond - kappa P2_unit/L (periodic convention); unchanged otherwise.
pub(super) fn closed(prm: &SlidingParamsF64, map: &Map, mut b: Basis) -> Basis {
    if let Some(big_l) = closing_period(prm, map) {
        b.cond -= prm.kappa * b.p2 / big_l;
    }
    b
}

/// The constant of the solvability condition that does not scale with the load: beta tau0
/// (`paper`), beta tau0 (1 - 2 l/L) (`periodic`, the tau0 part of K).
pub(super) fn tau0_side(prm: &SlidingParamsF64, map: &Map) -> f64 {
    let bt = prm.beta * prm.tau0;
    match closing_period(prm, map) {
        Some(big_l) => bt * (1.0 - 2.0 * map.half_length() / big_l),
        None => bt,
    }
}

/// K = (kappa P2 - 2 beta l tau0)/L of a solution with load `p2` and half-length `l` in the
/// `periodic` convention (docs/theory.md section 8); 0 in `paper` and for a single punch.
pub(super) fn k_constant(prm: &SlidingParamsF64, p2: f64, l: f64) -> f64 {
    match (prm.convention, prm.period) {
        (Convention::PeriodicSurface, Some(big_l)) => (prm.kappa * p2 - 2.0 * prm.beta * l * prm.tau0) / big_l,
        _ => 0.0,
    }
}
