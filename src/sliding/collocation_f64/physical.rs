//! The f64 method's side of the shared physicality criterion ([`crate::sliding::physicality`]):
//! p/omega = G(u) from the Nyström interpolant, and the surface slope off the contact from H[p]
//! (docs/theory.md section 2): w = g' - h' = (2/E*) (H[p] - K) - 2 beta tau0/E* (the last term removes
//! the adhesive shear's edge step, which the criterion leaves out; K of the `periodic` convention,
//! `closure.rs`); the profile's height from [`row_height_f64`].

use super::closure::k_constant;
use super::interpolant::{g_and_cauchy_sum, g_at, State};
use super::operator::Collocation;
use super::outputs::Outputs;
use super::tangent_map::Map;
use crate::model::Convention;
use crate::numerics::gauss_jacobi_f64::omega_cauchy_exterior_sec;
use crate::params::sliding::SlidingParamsF64;
use crate::params::sliding::{row_height_f64, ShapeF64};
use crate::sliding::physicality::{assess, Assessment, Cell, ContactFunctions, Refusal, Setting, CLOSURE_TOL};
use std::f64::consts::PI;

/// H[p](x) for x outside the contact (docs/theory.md section 2). Near the contact (|u| <= 3) the
/// Cauchy part is G(u) (1/pi) int omega/(u - t) - (1/pi) sum W_k (G(u) - G_k)/(u - t_k)
/// (exact for the polynomial G; both sums from one reciprocal per node, [`g_and_cauchy_sum`]),
/// with the closed form of [`omega_cauchy_exterior_sec`]; farther out
/// the plain rule in the cot (or 1/(x - xi)) form, through the node terms of [`FarField`].
/// `c0` is C0[p] of the state ([`c0_of`]).
fn hilbert_outside(col: &Collocation, st: &State, far: &FarField, theta: f64, c0: f64, x: f64) -> f64 {
    let u = st.map.u_of_x(x, st.c);
    if u.is_finite() && u.abs() <= 3.0 {
        // Off the contact |u| >= 1; rounding at the very edge could give |u| slightly below 1.
        let u = u.signum() * u.abs().max(1.0);
        let (gu, s) = g_and_cauchy_sum(col, st, u);
        gu * omega_cauchy_exterior_sec(u, theta, col.sec_pi_theta) - s / PI + c0
    } else {
        far.at(st, x)
    }
}

/// The plain rule for H[p] far from the contact, its node factors computed once per state:
/// periodic, with phi_x = pi (x - c)/L and phi_k = atan(m t_k) = pi (xi_k - c)/L (the tangent
/// map), the node term W_k G_k x'(t_k)/(L tan(phi_x - phi_k)) is
///
/// ```text
/// a_k (cos phi_x + b_k sin phi_x)/(sin phi_x - b_k cos phi_x),
/// a_k = W_k G_k m/(pi (1 + m^2 t_k^2)),   b_k = m t_k = tan phi_k
/// ```
///
/// (cot(phi_x - phi_k) with cos phi_k, sin phi_k = (1, b_k)/sqrt(1 + b_k^2)): one sine and cosine
/// per point instead of a tangent per node; single punch: W_k G_k l/(pi (x - xi_k)),
/// xi_k = c + l t_k.
struct FarField {
    /// (a_k, b_k) periodic, or (W_k G_k l/pi, xi_k) single.
    nodes: Vec<(f64, f64)>,
}

impl FarField {
    fn new(col: &Collocation, st: &State) -> Self {
        let nodes = col
            .rule
            .nodes
            .iter()
            .zip(&col.rule.weights)
            .zip(&st.g)
            .map(|((t, w), g)| match st.map {
                Map::Periodic { m, .. } => (w * g * m / (PI * (1.0 + m * m * t * t)), m * t),
                Map::Single { l } => (w * g * l / PI, st.c + l * t),
            })
            .collect();
        FarField { nodes }
    }
    fn at(&self, st: &State, x: f64) -> f64 {
        match st.map {
            Map::Periodic { big_l, .. } => {
                let (s, c) = (PI * (x - st.c) / big_l).sin_cos();
                // The terms a chunk at a time (a loop with a division per node that the compiler
                // vectorises), then summed in node order from the same start as `sum`: the
                // same bits as one `map(..).sum()`.
                let mut terms = [0.0; 32];
                let mut total = -0.0;
                for chunk in self.nodes.chunks(32) {
                    for (v, (a, b)) in terms.iter_mut().zip(chunk) {
                        *v = a * (c + b * s) / (s - b * c);
                    }
                    for v in &terms[..chunk.len()] {
                        total += v;
                    }
                }
                total
            }
            Map::Single { .. } => self.nodes.iter().map(|(a, xi)| a / (x - xi)).sum(),
        }
    }
}

/// C0[p] = sum_k W_k G_k (1/pi) m^2 t_k/(1 + m^2 t_k^2) (docs/theory.md section 2); 0 for a single punch.
fn c0_of(col: &Collocation, st: &State) -> f64 {
    col.sum(&st.g, |t| st.map.c0_weight(t))
}

/// The f64 solution seen by the criterion.
struct Functions<'a> {
    col: &'a Collocation,
    prm: &'a SlidingParamsF64,
    st: &'a State,
    far: FarField,
    c0: f64,
    k_const: f64,
    /// G at the operator's samples ([`Outputs::grid_g`]).
    grid_g: &'a [f64],
}

impl ContactFunctions for Functions<'_> {
    fn pressure_factor(&self, u: f64) -> f64 {
        g_at(self.col, self.st, u)
    }
    /// At the operator's fixed samples (the criterion's pressure points) the outputs already hold
    /// G, the same values as [`g_at`] ([`super::interpolant::g_on_grid`]).
    fn pressure_factors(&self, us: &[f64]) -> Vec<f64> {
        if us == self.col.grid.u.as_slice() {
            self.grid_g.to_vec()
        } else {
            us.iter().map(|&u| self.pressure_factor(u)).collect()
        }
    }
    fn surface_slope(&self, xi: f64) -> f64 {
        let (prm, x) = (self.prm, self.st.c + xi);
        2.0 / prm.e_star * (hilbert_outside(self.col, self.st, &self.far, prm.theta, self.c0, x) - self.k_const)
            - 2.0 * prm.beta * prm.tau0 / prm.e_star
    }
    fn profile_height(&self, x: f64) -> f64 {
        row_height_f64(&self.prm.shape, self.prm.period, x)
    }
}

/// Relative accuracy of G(u) that the pressure test allows for.
const PRESSURE_TOL: f64 = 1e-9;

/// The criterion's data for an f64 solution with outputs `out`.
pub(super) fn setting(prm: &SlidingParamsF64, out: &Outputs) -> Setting {
    let cell = match (&prm.shape, prm.period) {
        (_, None) => Cell::Unbounded,
        (ShapeF64::Sinusoidal { .. }, Some(big_l)) => Cell::Periodic { period: big_l },
        (_, Some(big_l)) => Cell::Fixed { half_period: 0.5 * big_l },
    };
    let closure_formula = match (prm.period, prm.convention) {
        (Some(_), Convention::Paper) => 2.0 * prm.beta * out.p1 / prm.e_star - prm.wear * out.p2,
        _ => 0.0,
    };
    Setting {
        convention: prm.convention,
        cell,
        a: out.a,
        b: out.b,
        edge_step: 2.0 * prm.beta * prm.tau0 / prm.e_star,
        closure_formula,
        pressure_tol: PRESSURE_TOL,
        extent: match &prm.shape {
            ShapeF64::Circular { r } if prm.period.is_none_or(|big_l| *r < 0.5 * big_l) => Some(*r),
            _ => None,
        },
        closure_tol: CLOSURE_TOL,
    }
}

/// The shared criterion ([`crate::sliding::physicality::assess`]) applied to a discrete state.
pub(super) fn physicality(
    col: &Collocation,
    prm: &SlidingParamsF64,
    st: &State,
    out: &Outputs,
) -> Result<Assessment, Refusal> {
    let f = Functions {
        col,
        prm,
        st,
        far: FarField::new(col, st),
        c0: c0_of(col, st),
        k_const: k_constant(prm, out.p2, out.l),
        grid_g: &out.grid_g,
    };
    assess(&f, &setting(prm, out))
}
