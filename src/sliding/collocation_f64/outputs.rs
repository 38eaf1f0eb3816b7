//! The outputs of a discrete state: lambda, l, a, b, c, P1 = mu P2 + 2 l tau0, P2,
//! F_def = int p g' dx, p at the requested points and on a grid (for max p and the checks).

use super::interpolant::{g_at, State};
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
    /// p at the GRID midpoints xh = -1 + (2i + 1)/GRID.
    pub(super) grid_p: Vec<f64>,
}

/// Points of the interior grid of p.
const GRID: usize = 201;

/// Evaluates the outputs of the state `st` at the requested points xh = (x - c)/l.
pub(super) fn outputs(col: &Collocation, prm: &SlidingParamsF64, st: &State, points: &[f64]) -> Outputs {
    let l = st.map.half_length();
    let c = st.c;
    let p_at = |xh: f64| {
        let u = st.map.u_of_xh(xh);
        omega(u, prm.theta) * g_at(col, st, u)
    };
    let grid_p: Vec<f64> = (0..GRID).map(|i| p_at(-1.0 + 2.0 * (i as f64 + 0.5) / GRID as f64)).collect();
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
        grid_p,
    }
}
