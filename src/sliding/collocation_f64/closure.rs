//! The surface convention in the collocated equation (THEORY.md section 8). With `periodic`
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
