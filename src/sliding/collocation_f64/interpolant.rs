//! Discrete solutions at fixed contact: the unit bases (one solve of the LU-factored system per
//! right-hand side shape), the discrete state (map, centre, G at the nodes) and the Nyström
//! interpolant G(u) between the nodes and off the contact.

use super::error::Result;
use super::operator::{nearest_collocation_point, Collocation, GridPoint};
use super::profile::slope_divided_difference;
use super::tangent_map::Map;
use crate::params::sliding::ShapeF64;
use std::f64::consts::PI;

/// Discrete solution for one right-hand side shape F(u) (unit amplitude): G, K and the two
/// functionals C0[p] - K and P2[p].
pub(super) struct Basis {
    pub(super) g: Vec<f64>,
    pub(super) cond: f64,
    pub(super) p2: f64,
}

/// Solves the collocation system for the right-hand side `f` and evaluates the two side
/// functionals (module doc of `collocation_f64`).
pub(super) fn basis(col: &Collocation, map: &Map, f: impl Fn(f64) -> f64) -> Result<Basis> {
    let rhs: Vec<f64> = col.colloc.iter().map(|&u| f(u)).collect();
    let (g, k) = col.solve(&rhs)?;
    let c0 = col.sum(&g, |t| map.c0_weight(t));
    let p2 = col.sum(&g, |t| map.jac(t));
    Ok(Basis { g, cond: c0 - k, p2 })
}

/// A discrete state: the map, the centre c, G in physical units at the nodes
/// (p(u) = omega(u) G(u)) and the shape part of the right-hand side (for the Nyström interpolant).
#[derive(Clone)]
pub(super) struct State {
    pub(super) map: Map,
    pub(super) c: f64,
    pub(super) g: Vec<f64>,
    pub(super) p2: f64,
    pub(super) rhs: Rhs,
}

/// The shape part F(u) of the right-hand side in physical units (constants are absorbed in K).
#[derive(Debug, Clone)]
pub(super) enum Rhs {
    /// F = s (x(u) - c): parabola, s = E* k.
    Offset { s: f64 },
    /// F = s (X sin 2phi + Y cos 2phi), phi = atan(m u): sinusoid, s = pi E* D/L.
    Sinusoid { s: f64, x: f64, y: f64 },
    /// F = (E*/2) g'(c + x(u) - c): a polynomial or circular profile at the centre c.
    Profile { half_e: f64, c: f64, shape: ShapeF64 },
}

impl Rhs {
    /// (F(u) - F(v))/(u - v), in cancellation-free closed forms:
    /// atan(mu) - atan(mv) = atan(m (u - v)/(1 + m^2 u v)) when 1 + m^2 u v > 0;
    /// sin 2phi: 2m (u - v)(1 - m^2 u v)/((1 + m^2 u^2)(1 + m^2 v^2));
    /// cos 2phi: -2 m^2 (u - v)(u + v)/((1 + m^2 u^2)(1 + m^2 v^2)).
    fn divided_difference(&self, map: &Map, u: f64, v: f64) -> f64 {
        let d = u - v;
        match (self, *map) {
            (&Rhs::Offset { s }, Map::Single { l }) => s * l,
            (&Rhs::Offset { s }, Map::Periodic { big_l, m, .. }) => {
                let q = 1.0 + m * m * u * v;
                let dd = if d == 0.0 {
                    m / (1.0 + m * m * u * u)
                } else if q > 0.0 {
                    (m * d / q).atan() / d
                } else {
                    ((m * u).atan() - (m * v).atan()) / d
                };
                s * big_l / PI * dd
            }
            (&Rhs::Sinusoid { s, x, y }, Map::Periodic { m, .. }) => {
                let den = (1.0 + m * m * u * u) * (1.0 + m * m * v * v);
                s * (x * 2.0 * m * (1.0 - m * m * u * v) - y * 2.0 * m * m * (u + v)) / den
            }
            (Rhs::Sinusoid { .. }, Map::Single { .. }) => unreachable!("sinusoid needs a period"),
            // (E*/2) g'[x(u), x(v)] x[u, v]: both divided differences free of cancellation
            // (`profile::slope_divided_difference` and the arctan form above).
            (Rhs::Profile { half_e, c, shape }, map) => {
                let (xu, xv) = (c + map.offset(u), c + map.offset(v));
                let dx = match map {
                    Map::Single { l } => l,
                    Map::Periodic { big_l, m, .. } => {
                        let q = 1.0 + m * m * u * v;
                        let dd = if d == 0.0 {
                            m / (1.0 + m * m * u * u)
                        } else if q > 0.0 {
                            (m * d / q).atan() / d
                        } else {
                            ((m * u).atan() - (m * v).atan()) / d
                        };
                        big_l / PI * dd
                    }
                };
                half_e * slope_divided_difference(shape, xu, xv) * dx
            }
        }
    }
}

/// G(u) by the Nyström interpolant of the collocation equation [reconstructed]: from
/// G(u) D(u) = F(u) - K - (1/pi) sum_k W_k G_k/(u - t_k), D(u) = (u + 2 theta)/cos(pi theta)
/// - (1/pi) sum_k W_k/(u - t_k) (the kappa-term plus the exact PV Cauchy transform of omega, see
/// `gauss_jacobi_f64::omega_cauchy_exterior`, minus its quadrature), and D(x_r) = 0 = the
/// residual at the collocation point x_r nearest to u, subtracting both at x_r gives
///
/// ```text
/// G(u) = [ (F(u) - F(x_r))/(u - x_r) + (1/pi) sum_k W_k G_k / ((u - t_k)(x_r - t_k)) ]
///      / [ 1/cos(pi theta)           + (1/pi) sum_k W_k     / ((u - t_k)(x_r - t_k)) ],
/// ```
///
/// free of 0/0 at x_r and of K. Its error follows the quadrature, tan(lambda/2)^{2n}, instead of
/// the interpolant's tan(lambda/2)^n; it is also the analytic continuation used off the contact.
pub(super) fn g_at(col: &Collocation, st: &State, u: f64) -> f64 {
    let xs = &col.colloc;
    let n = col.rule.nodes.len();
    let r = nearest_collocation_point(xs, u);
    let nodes = &col.rule.nodes[..n];
    // W_k/(pi (x_r - t_k)) from the collocation matrix, so the loop has one division per node.
    let row = &col.kernel[r * n..(r + 1) * n];
    let g = &st.g[..n];
    let mut num = st.rhs.divided_difference(&st.map, u, xs[r]);
    let mut den = col.sec_pi_theta;
    for k in 0..n {
        let q = row[k] / (u - nodes[k]);
        num += q * g[k];
        den += q;
    }
    let v = num / den;
    if v.is_finite() {
        return v;
    }
    // u on a node: a division by zero above (inf/inf); the node's value.
    match nodes.iter().position(|t| *t == u) {
        Some(k) => st.g[k],
        None => v,
    }
}

/// G at the points of the operator's [`super::operator::SampleGrid`] (in its order): the same
/// values as [`g_at`] there, to the bit, from the precomputed weights (n multiply-adds and one
/// divided difference of F per point, no division per node).
pub(super) fn g_on_grid(col: &Collocation, st: &State) -> Vec<f64> {
    let grid = &col.grid;
    let n = col.rule.nodes.len();
    let g = &st.g[..n];
    grid.at
        .iter()
        .enumerate()
        .map(|(i, at)| match *at {
            GridPoint::Node(k) => g[k],
            GridPoint::Row(r) => {
                let mut num = st.rhs.divided_difference(&st.map, grid.u[i], col.colloc[r]);
                for (q, gk) in grid.q[i * n..(i + 1) * n].iter().zip(g) {
                    num += q * gk;
                }
                num / grid.den[i]
            }
        })
        .collect()
}

/// Nodes per chunk of the reciprocals in [`g_and_cauchy_sum`].
const CHUNK: usize = 32;

/// G(u) of [`g_at`] for u off the contact (|u| >= 1, never a node) together with the node sum
/// of the Cauchy transform there, S(u) = sum_k W_k (G(u) - G_k)/(u - t_k), from one reciprocal
/// 1/(u - t_k) per node (the gap's slope, `physical::hilbert_outside`): S = G(u) sum_k W_k/(u -
/// t_k) - sum_k W_k G_k/(u - t_k), all terms of one sign off the contact.
pub(super) fn g_and_cauchy_sum(col: &Collocation, st: &State, u: f64) -> (f64, f64) {
    let xs = &col.colloc;
    let n = col.rule.nodes.len();
    let r = if u < 0.0 { 0 } else { xs.len() - 1 };
    let row = &col.kernel[r * n..(r + 1) * n];
    let (mut num, mut den) = (st.rhs.divided_difference(&st.map, u, xs[r]), col.sec_pi_theta);
    let (mut sw, mut swg) = (0.0, 0.0);
    // The reciprocals a chunk at a time (a loop the compiler vectorises), then the sums in node
    // order: the same operations as one loop, so the same bits.
    let mut inv = [0.0; CHUNK];
    for start in (0..n).step_by(CHUNK) {
        let m = CHUNK.min(n - start);
        for (v, t) in inv[..m].iter_mut().zip(&col.rule.nodes[start..start + m]) {
            *v = 1.0 / (u - t);
        }
        let nodes = col.rule.weights[start..start + m].iter().zip(&st.g[start..start + m]).zip(&row[start..start + m]);
        for (((w, g), k), inv) in nodes.zip(&inv[..m]) {
            let q = k * inv;
            num += q * g;
            den += q;
            sw += w * inv;
            swg += w * g * inv;
        }
    }
    let gu = num / den;
    (gu, gu * sw - swg)
}
