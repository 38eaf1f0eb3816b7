//! Discrete solutions at fixed contact: the unit bases (one solve of the LU-factored system per
//! right-hand side shape), the discrete state (map, centre, G at the nodes) and the Nyström
//! interpolant G(u) between the nodes and off the contact.

use super::error::Result;
use super::operator::{nearest_collocation_point, Collocation, GridPoint};
use super::profile::{analytic_slope, slope_divided_difference};
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

impl Rhs {
    /// Off the contact, at u (|u| >= 1) and x = c + `xi` (xi = x(u) - c known, so no arctangent
    /// of the tangent map is needed): the continuation of the full right side,
    /// F(x) = (E*/2) g'(x) (the parabola's E* k c, which its state keeps in K, added back; the
    /// analytic g', not reduced to the cell), and F[u, x_r] = (F(u) - F(x_r))/(u - x_r) at the
    /// collocation point x_r with `xi_r` = x(x_r) - c. Since |x_r| < 1 <= |u|, u - x_r does not
    /// vanish and the quotient of the offsets loses no more than ln(1/(1 - |x_r|)) bits of its
    /// own (F's differences as in [`Self::divided_difference`], the map's from the offsets).
    pub(super) fn off_contact(&self, map: &Map, c: f64, u: f64, xi: f64, xr: f64, xi_r: f64) -> (f64, f64) {
        // x[u, x_r]: l, or (xi - xi_r)/(u - x_r).
        let dx = || match *map {
            Map::Single { l } => l,
            Map::Periodic { .. } => (xi - xi_r) / (u - xr),
        };
        match (self, *map) {
            (&Rhs::Offset { s }, _) => (s * (c + xi), s * dx()),
            (&Rhs::Sinusoid { s, x, y }, Map::Periodic { m, .. }) => {
                // sin 2phi, cos 2phi of tan phi = m u.
                let t = m * u;
                let q = 1.0 + t * t;
                (s * (x * 2.0 * t / q + y * (1.0 - t * t) / q), self.divided_difference(map, u, xr))
            }
            (Rhs::Sinusoid { .. }, Map::Single { .. }) => unreachable!("sinusoid needs a period"),
            (Rhs::Profile { half_e, c: cp, shape }, _) => (
                half_e * analytic_slope(shape, cp + xi),
                half_e * slope_divided_difference(shape, cp + xi, cp + xi_r) * dx(),
            ),
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
/// divided difference of F per point, no division per node). Each point's sum runs over the
/// nodes in order, as in [`g_at`]; the points run side by side (the node loop outside), so the
/// sums do not wait for each other.
pub(super) fn g_on_grid(col: &Collocation, st: &State) -> Vec<f64> {
    let grid = &col.grid;
    let (n, points) = (col.rule.nodes.len(), grid.u.len());
    let mut num: Vec<f64> = grid
        .at
        .iter()
        .zip(&grid.u)
        .map(|(at, &u)| match *at {
            GridPoint::Node(_) => 0.0,
            GridPoint::Row(r) => st.rhs.divided_difference(&st.map, u, col.colloc[r]),
        })
        .collect();
    for (q, gk) in grid.q.chunks_exact(points).zip(&st.g[..n]) {
        for (nu, qk) in num.iter_mut().zip(q) {
            *nu += qk * gk;
        }
    }
    for ((nu, at), den) in num.iter_mut().zip(&grid.at).zip(&grid.den) {
        *nu = match *at {
            GridPoint::Node(k) => st.g[k],
            GridPoint::Row(_) => *nu / den,
        };
    }
    num
}

/// Points per batch of [`g_off_contact`].
const LANES: usize = 8;

/// G(u) of [`g_at`] at points `us` off the contact (|u| >= 1, never a node), all on the side of
/// the collocation point x_r nearest to them (`r` = the last for u >= 1, 0 for u <= -1), from the
/// divided differences F[u, x_r] already known (`dds`, [`Rhs::off_contact`]): the points a batch
/// of [`LANES`] at a time, each with the same operations in the same order as the others (the
/// node loop outside, a loop over the batch inside that the compiler vectorises), so a point's
/// value does not depend on the batch it is in.
pub(super) fn g_off_contact(col: &Collocation, st: &State, r: usize, us: &[f64], dds: &[f64], out: &mut [f64]) {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the processor has the `avx2` feature (checked above).
        return unsafe { g_off_contact_avx2(col, st, r, us, dds, out) };
    }
    g_off_contact_portable(col, st, r, us, dds, out)
}

/// [`g_off_contact_portable`] compiled for 256-bit vectors: four divisions per instruction instead of
/// two; the same operations on each lane (no fused multiply-adds), so the same bits.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn g_off_contact_avx2(col: &Collocation, st: &State, r: usize, us: &[f64], dds: &[f64], out: &mut [f64]) {
    g_off_contact_portable(col, st, r, us, dds, out)
}

/// [`g_off_contact`] for any processor (the vectors the target allows without run-time
/// detection).
#[inline(always)]
pub(super) fn g_off_contact_portable(
    col: &Collocation,
    st: &State,
    r: usize,
    us: &[f64],
    dds: &[f64],
    out: &mut [f64],
) {
    let n = col.n();
    let (nodes, g) = (&col.rule.nodes[..n], &st.g[..n]);
    let row = &col.kernel[r * n..(r + 1) * n];
    debug_assert!(us.iter().all(|u| u.abs() >= 1.0 && (*u > 0.0) == (r > 0)), "off the contact, on x_r's side");
    for ((u, dd), out) in us.chunks(LANES).zip(dds.chunks(LANES)).zip(out.chunks_mut(LANES)) {
        let m = u.len();
        // Unused lanes at u = 2 (off every node), their results dropped.
        let mut uu = [2.0; LANES];
        uu[..m].copy_from_slice(u);
        let mut num = [0.0; LANES];
        num[..m].copy_from_slice(dd);
        let mut den = [col.sec_pi_theta; LANES];
        for ((w, t), gk) in row.iter().zip(nodes).zip(g) {
            for ((v, nu), de) in uu.iter().zip(&mut num).zip(&mut den) {
                let q = w / (v - t);
                *nu += q * gk;
                *de += q;
            }
        }
        for ((o, nu), de) in out.iter_mut().zip(&num).zip(&den) {
            *o = nu / de;
        }
    }
}
