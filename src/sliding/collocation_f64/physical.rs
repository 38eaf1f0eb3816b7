//! The f64 method's side of the shared physicality criterion ([`crate::sliding::physicality`]):
//! p/omega = G(u) from the Nyström interpolant, and the surface slope off the contact from the
//! continuation of the collocated equation; the profile's height from [`row_height_f64`].
//!
//! # The slope off the contact [derived here]
//! Off the contact (|u| > 1) the Cauchy part of H[p] (docs/theory.md section 2) for p = omega G,
//! with G continued by the Nyström interpolant G_N ([`super::interpolant::g_at`]), is
//!
//! ```text
//! C(u) = G_N(u) Omega(u) - (1/pi) sum_k W_k (G_N(u) - G_k)/(u - t_k)
//! ```
//!
//! (exact for a polynomial G; Omega = (1/pi) int omega/(u - t) = (u + 2 theta - X(u)) sec(pi theta),
//! [`crate::numerics::gauss_jacobi_f64::omega_cauchy_exterior`], X the exterior weight
//! [`omega_exterior`]). G_N solves the collocation equation continued to u,
//! G_N D = F - K_c - (1/pi) sum_k W_k G_k/(u - t_k), D(u) = (u + 2 theta) sec(pi theta) - (1/pi)
//! sum_k W_k/(u - t_k) (`interpolant.rs`; K_c the constant of the collocated equation). Since
//! Omega - (1/pi) sum_k W_k/(u - t_k) = D - sec(pi theta) X, the sums cancel:
//!
//! ```text
//! C(u) = G_N (D - sec X) + (1/pi) sum_k W_k G_k/(u - t_k) = F(u) - K_c - sec(pi theta) G_N(u) X(u).
//! ```
//!
//! With the solvability condition C0[p] - K_c = beta tau0 + K (K of the convention, `closure.rs`;
//! for the parabola K_c also holds E* k c, put back into F by [`super::interpolant::Rhs::off_contact`])
//! H[p] = C + C0[p] = (E*/2) g'(x) + beta tau0 + K - sec(pi theta) G_N X, and the criterion's slope
//! w = (2/E*) (H[p] - K) - 2 beta tau0/E* ([`ContactFunctions::surface_slope`]) is
//!
//! ```text
//! w(x) = g'(x) - (2/E*) sec(pi theta) G_N(u) X(u),   i.e.  h'(x) = (2/E*) sec(pi theta) X(u) G_N(u):
//! ```
//!
//! off the contact the gap's slope is the pressure factor continued with the exterior weight, as
//! p = omega G on it (g' the analytic profile, not reduced to the cell: the criterion takes the
//! row's height exactly). It is the statement of docs/theory.md section 3 that the MPFR method's
//! gap uses with its own G ([`crate::sliding::reduction_mpfr::pressure::Pressure::gap_slope`]). Per point: the tangent map's tangent, X (a logarithm and an
//! exponential) and the n terms of G_N, without the arctangent of F and the n-term Cauchy sum of
//! the form above, and with no separate far-field rule (it holds for every |u| >= 1). Only where
//! the profile has no continuation (beyond a circle's wall, where the row has no punch) the plain
//! rule of H[p] takes over. The n terms of G_N run for a batch of points side by side
//! ([`g_off_contact`]). The test `the_continued_slope_is_the_cauchy_transform` compares the slope
//! with the Cauchy form near the contact and with the plain rule far from it.

use super::closure::k_constant;
use super::interpolant::{g_at, g_off_contact, State};
use super::operator::Collocation;
use super::outputs::Outputs;
use crate::model::Convention;
use crate::numerics::gauss_jacobi_f64::omega_exterior;
use crate::params::sliding::SlidingParamsF64;
use crate::params::sliding::{row_height_f64, row_rise_f64, ShapeF64};
use crate::sliding::physicality::{assess, Assessment, Cell, ContactFunctions, Refusal, Setting, CLOSURE_TOL};
use std::f64::consts::PI;

/// The collocation point next to an end, x_0 or x_n (index `r`), with its offset x(x_r) - c:
/// the Nyström interpolant's point for u <= -1 and u >= 1.
#[derive(Clone, Copy)]
struct End {
    r: usize,
    xr: f64,
    xi_r: f64,
}

/// The f64 solution seen by the criterion.
struct Functions<'a> {
    col: &'a Collocation,
    prm: &'a SlidingParamsF64,
    st: &'a State,
    /// The trailing and the leading end's collocation points.
    ends: [End; 2],
    /// C0[p] - K (K of the convention, `closure.rs`), for [`Self::plain_rule`].
    c0_minus_k: f64,
    /// G at the operator's samples ([`Outputs::grid_g`]).
    grid_g: &'a [f64],
}

impl<'a> Functions<'a> {
    fn new(col: &'a Collocation, prm: &'a SlidingParamsF64, st: &'a State, out: &'a Outputs) -> Self {
        let end = |r: usize| End { r, xr: col.colloc[r], xi_r: st.map.offset(col.colloc[r]) };
        let ends = [end(0), end(col.colloc.len() - 1)];
        let c0 = col.sum(&st.g, |t| st.map.c0_weight(t));
        Functions { col, prm, st, ends, c0_minus_k: c0 - k_constant(prm, out.p2, out.l), grid_g: &out.grid_g }
    }

    /// w at u from the plain rule, H[p] = (1/pi) sum_k W_k G_k/(u - t_k) + C0[p] (docs/theory.md
    /// section 2; its error, the rule's for the Cauchy transform of omega times G_N, falls like
    /// (|u| + sqrt(u^2 - 1))^(-2n)): where the profile has no continuation to continue the
    /// equation with (beyond a circle's wall, where the row has no punch and the gap is
    /// +infinity whatever its slope).
    fn plain_rule(&self, u: f64) -> f64 {
        let (col, prm) = (self.col, self.prm);
        let cauchy: f64 =
            col.rule.nodes.iter().zip(&col.rule.weights).zip(&self.st.g).map(|((t, w), g)| w * g / (u - t)).sum();
        2.0 / prm.e_star * (cauchy / PI + self.c0_minus_k) - 2.0 * prm.beta * prm.tau0 / prm.e_star
    }

    /// u of x = c + xi off the contact (|u| >= 1: rounding at the very edge could give |u|
    /// slightly below 1).
    fn u_off_contact(&self, xi: f64) -> f64 {
        let u = self.st.map.u_of_offset(xi);
        u.signum() * u.abs().max(1.0)
    }

    /// w at points of one side of the contact (module doc; `leading`: xi > 0, u >= 1), by batches.
    fn slopes_one_side(&self, leading: bool, xis: &[f64], out: &mut [f64]) {
        const BATCH: usize = 16;
        let (prm, st) = (self.prm, self.st);
        let end = self.ends[usize::from(leading)];
        let (mut us, mut fs, mut dds, mut gs) = ([0.0; BATCH], [0.0; BATCH], [0.0; BATCH], [0.0; BATCH]);
        for (xis, out) in xis.chunks(BATCH).zip(out.chunks_mut(BATCH)) {
            let m = xis.len();
            for (i, &xi) in xis.iter().enumerate() {
                let u = self.u_off_contact(xi);
                (fs[i], dds[i]) = st.rhs.off_contact(&st.map, st.c, u, xi, end.xr, end.xi_r);
                us[i] = u;
            }
            // Beyond a circle's wall F has no value: those points by the plain rule.
            let mut continued = [true; BATCH];
            for ((c, f), dd) in continued.iter_mut().zip(&fs).zip(&mut dds[..m]) {
                if !(f.is_finite() && dd.is_finite()) {
                    (*c, *dd) = (false, 0.0);
                }
            }
            g_off_contact(self.col, st, end.r, &us[..m], &dds[..m], &mut gs[..m]);
            let h = 2.0 / prm.e_star;
            for (i, o) in out.iter_mut().enumerate() {
                *o = if continued[i] {
                    h * (fs[i] - self.col.sec_pi_theta * gs[i] * omega_exterior(us[i], prm.theta))
                } else {
                    self.plain_rule(us[i])
                };
            }
        }
    }
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
    /// w(x) = g'(x) - (2/E*) sec(pi theta) G_N(u) X(u) (module doc).
    fn surface_slope(&self, xi: f64) -> f64 {
        let mut w = [0.0];
        self.surface_slopes(&[xi], &mut w);
        w[0]
    }
    /// The same at many points, the terms of G_N for a batch of points at a time (the same
    /// numbers as one at a time).
    fn surface_slopes(&self, xis: &[f64], out: &mut [f64]) {
        // Runs of points on one side of the contact (the gap's panels are): u has the sign of xi.
        let mut start = 0;
        while start < xis.len() {
            let side = xis[start] > 0.0;
            let len = xis[start..].iter().take_while(|xi| (**xi > 0.0) == side).count();
            self.slopes_one_side(side, &xis[start..start + len], &mut out[start..start + len]);
            start += len;
        }
    }
    fn profile_height(&self, x: f64) -> f64 {
        row_height_f64(&self.prm.shape, self.prm.period, x)
    }
    fn profile_rise(&self, end: f64, dx: f64) -> f64 {
        row_rise_f64(&self.prm.shape, self.prm.period, end, dx)
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
    assess(&Functions::new(col, prm, st, out), &setting(prm, out))
}

#[cfg(test)]
mod tests {
    use super::super::candidates::{candidates, state_of};
    use super::super::operator::collocation;
    use super::super::outputs::outputs;
    use super::super::solution::SolverOptions;
    use super::super::tangent_map::Map;
    use super::*;
    use crate::model::{Exact, Material, Period, PunchShape, SlidingLoad, SlidingProblem};
    use crate::numerics::gauss_jacobi_f64::omega_cauchy_exterior;
    use num_bigint::BigInt;
    use std::f64::consts::PI;

    fn q(n: i64, d: i64) -> Exact {
        Exact::new(BigInt::from(n), BigInt::from(d))
    }

    /// The sliding scenes' problems (`scenes/`, E* = 1, L = 1): (nu, shape, mu, tau0, cW, P2).
    fn scene_problems() -> Vec<SlidingProblem> {
        let parabola = || PunchShape::parabolic(q(1, 1)).unwrap();
        let sinusoid = || PunchShape::sinusoidal(q(1, 100)).unwrap();
        let cases = [
            (q(3, 10), parabola(), q(3, 10), q(0, 1), q(0, 1), q(1, 100)),
            (q(1, 4), parabola(), q(0, 1), q(0, 1), q(2, 5), q(1, 100)),
            (q(3, 10), parabola(), q(1, 5), q(1, 100), q(0, 1), q(1, 100)),
            (q(3, 10), sinusoid(), q(1, 2), q(0, 1), q(0, 1), q(1, 200)),
            (q(3, 10), sinusoid(), q(0, 1), q(0, 1), q(0, 1), q(1, 200)),
            (
                q(1, 4),
                PunchShape::polynomial(vec![q(0, 1), q(1, 50), q(1, 1), q(1, 2)]).unwrap(),
                q(1, 5),
                q(1, 100),
                q(1, 10),
                q(1, 20),
            ),
            (
                q(3, 10),
                PunchShape::polynomial(vec![q(0, 1), q(0, 1), q(1, 4), q(0, 1), q(1, 2)]).unwrap(),
                q(3, 10),
                q(0, 1),
                q(0, 1),
                q(1, 50),
            ),
            (q(3, 10), PunchShape::circular(q(1, 2)).unwrap(), q(3, 10), q(0, 1), q(0, 1), q(1, 50)),
        ];
        cases
            .into_iter()
            .map(|(nu, shape, mu, tau0, cw, p2)| {
                SlidingProblem::builder()
                    .material(Material::from_contact_modulus(nu, q(1, 1)).unwrap())
                    .period(Period::finite(q(1, 1)).unwrap())
                    .shape(shape)
                    .friction(mu)
                    .adhesive_friction(tau0)
                    .wear(cw)
                    .load(SlidingLoad::NormalLoad(p2))
                    .build()
                    .unwrap()
            })
            .collect()
    }

    /// The criterion's slope w = (2/E*) (H[p] - K) - 2 beta tau0/E* with H[p] off the contact in
    /// the Cauchy form of the module doc near the contact (|u| <= 3: G_N(u) Omega(u) - (1/pi)
    /// sum_k W_k (G_N(u) - G_k)/(u - t_k) + C0[p], G_N from `g_at`, Omega by powers) and by the
    /// plain rule farther out (the node terms W_k G_k x'(t_k) cot(pi (x - xi_k)/L)/L, or
    /// W_k G_k l/(pi (x - xi_k)) for a single punch), K by its formula (docs/theory.md section 8).
    fn cauchy_form(col: &Collocation, prm: &SlidingParamsF64, st: &State, out: &Outputs, xi: f64) -> f64 {
        let (nodes, weights, g) = (&col.rule.nodes, &col.rule.weights, &st.g);
        let c0: f64 = (0..col.n()).map(|k| weights[k] * g[k] * st.map.c0_weight(nodes[k])).sum();
        let u = st.map.u_of_offset(xi);
        let h = if u.abs() <= 3.0 {
            let u = u.signum() * u.abs().max(1.0);
            let gu = g_at(col, st, u);
            let s: f64 = (0..col.n()).map(|k| weights[k] * (gu - g[k]) / (u - nodes[k])).sum();
            gu * omega_cauchy_exterior(u, prm.theta) - s / PI + c0
        } else {
            (0..col.n())
                .map(|k| {
                    let d = xi - st.map.offset(nodes[k]);
                    let a = weights[k] * g[k] * st.map.jac(nodes[k]);
                    match st.map {
                        Map::Periodic { big_l, .. } => a / ((PI * d / big_l).tan() * big_l),
                        Map::Single { .. } => a / (PI * d),
                    }
                })
                .sum()
        };
        let k_const = match (prm.convention, prm.period) {
            (Convention::PeriodicSurface, Some(big_l)) => {
                (prm.kappa * out.p2 - 2.0 * prm.beta * out.l * prm.tau0) / big_l
            }
            _ => 0.0,
        };
        2.0 / prm.e_star * (h - k_const) - 2.0 * prm.beta * prm.tau0 / prm.e_star
    }

    /// The continued slope (module doc) against the Cauchy form, off both ends of every root
    /// of the sliding scenes' problems, in both conventions, and of their single-punch variants: within
    /// 1e-13 of the largest |w| (observed 7.0e-14). Batches give the same bits as
    /// single points.
    #[test]
    fn the_continued_slope_is_the_cauchy_transform() {
        let (mut cases, mut worst, mut walls) = (0, 0.0f64, 0);
        for p in scene_problems() {
            let variants = [Convention::Paper, Convention::PeriodicSurface]
                .map(|c| p.to_builder().convention(c).build().ok())
                .into_iter()
                .chain([p.to_builder().period(Period::Infinite).build().ok()]);
            for p in variants.flatten() {
                let prm = SlidingParamsF64::new(&p).unwrap();
                for (cand, n) in candidates(&prm, prm.target, &SolverOptions::default()).unwrap() {
                    if n > 60 {
                        continue; // a root near lambda = pi/2 (the sinusoid's second, unphysical)
                    }
                    let col = collocation(prm.theta, n).unwrap();
                    let st = state_of(&prm, prm.target, cand, n, false).unwrap();
                    let out = outputs(&col, &prm, &st, &[]);
                    let f = Functions::new(&col, &prm, &st, &out);
                    let reach = prm.period.map_or(4.0 * out.l, |big_l| 0.5 * big_l - out.l);
                    let xis: Vec<f64> = [1.0, -1.0]
                        .iter()
                        .flat_map(|dir| (1..=200).map(move |j| dir * (out.l + reach * (j as f64 / 200.0).powi(4))))
                        .collect();
                    let mut w = vec![0.0; xis.len()];
                    f.surface_slopes(&xis, &mut w);
                    let reference: Vec<f64> = xis.iter().map(|xi| cauchy_form(&col, &prm, &st, &out, *xi)).collect();
                    let scale = reference.iter().fold(0.0f64, |m, v| m.max(v.abs()));
                    for ((xi, w), r) in xis.iter().zip(&w).zip(&reference) {
                        assert_eq!(w.to_bits(), f.surface_slope(*xi).to_bits(), "batch vs one point at {xi}");
                        assert!((w - r).abs() <= 1e-13 * scale, "n {n} xi {xi}: {w} vs {r} (scale {scale})");
                        worst = worst.max((w - r).abs() / scale);
                        if let ShapeF64::Circular { r } = prm.shape {
                            walls += usize::from((st.c + xi).abs() >= r);
                        }
                    }
                    cases += 1;
                }
            }
        }
        eprintln!("{cases} roots, worst {worst:.2e} of the largest |w|, {walls} points beyond a circle's wall");
        assert!(cases >= 20 && walls > 0, "{cases} roots, {walls} points beyond a wall");
    }
}
