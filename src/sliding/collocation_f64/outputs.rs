//! The outputs of a discrete state: lambda, l, a, b, c, P1 = mu P2 + 2 l tau0, P2,
//! F_def = int p g' dx, p at the requested points and at the operator's fixed samples in u (for
//! max p, the check run's pressure difference and the physicality criterion's p >= 0).

use super::interpolant::{g_at, g_on_grid, State};
use super::operator::Collocation;
use super::profile::slope;
use super::solution::PressurePoint;
use crate::numerics::gauss_jacobi_f64::omega;
use crate::params::sliding::SlidingParamsF64;

/// The outputs of one run (main or check).
pub(super) struct Outputs {
    pub(super) lambda: f64,
    pub(super) l: f64,
    pub(super) a: f64,
    pub(super) b: f64,
    pub(super) c: f64,
    pub(super) p1: f64,
    pub(super) p2: f64,
    pub(super) f_def: f64,
    pub(super) max_p: f64,
    pub(super) pressure: Vec<PressurePoint>,
    /// G = p/omega at the samples of the operator's [`super::operator::SampleGrid`] (the
    /// physicality criterion's pressure points, fixed in u).
    pub(super) grid_g: Vec<f64>,
    /// p = omega G there.
    pub(super) grid_p: Vec<f64>,
}

/// Evaluates the outputs of the state `st` at the requested points xh = (x - c)/l. max p is the
/// largest p over the fixed samples in u and the requested points: the samples are the ones
/// the MPFR method takes its max p over
/// ([`crate::sliding::reduction_mpfr::physical::max_pressure`]), 68 Chebyshev–Lobatto points
/// (spacing at most pi/67 in the angle) and 18 next to the ends, so it is the sampled maximum
/// (the scale of p's accuracy), not the interpolant's maximum to full accuracy.
pub(super) fn outputs(col: &Collocation, prm: &SlidingParamsF64, st: &State, points: &[f64]) -> Outputs {
    let l = st.map.half_length();
    let c = st.c;
    let p_at = |xh: f64| {
        let u = st.map.u_of_xh(xh);
        omega(u, prm.theta) * g_at(col, st, u)
    };
    let grid_g = g_on_grid(col, st);
    let grid_p: Vec<f64> = col.grid.omega.iter().zip(&grid_g).map(|(w, g)| w * g).collect();
    let pressure: Vec<PressurePoint> =
        points.iter().map(|&xh| PressurePoint { xh, x: c + l * xh, p: p_at(xh) }).collect();
    let max_p = grid_p.iter().chain(pressure.iter().map(|p| &p.p)).fold(0.0f64, |m, v| m.max(*v));
    let mut f_def = 0.0;
    for ((t, w), gk) in col.rule.nodes.iter().zip(&col.rule.weights).zip(&st.g) {
        f_def += w * gk * slope(prm, c + st.map.offset(*t)) * st.map.jac(*t);
    }
    Outputs {
        lambda: st.map.lambda(),
        l,
        a: l - c,
        b: l + c,
        c,
        p1: prm.mu * st.p2 + 2.0 * l * prm.tau0,
        p2: st.p2,
        f_def,
        max_p,
        pressure,
        grid_g,
        grid_p,
    }
}
