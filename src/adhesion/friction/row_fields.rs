//! The periodic row's fields q1, q2, psi at points and the checks of its inequalities
//! (docs/theory.md section 17.8, "The row's fields", (17.12)-(17.14)), `f64`, superposed from the
//! increments of the spectral load ([`super::spectral_row_load::load_rate`]).
//!
//! Units L = pi (x = chi, a = lambda), E* = k = 1. The unit increment at contact eta is
//! sigma^eta(chi) = S^eta(T)/tan(eta), T = tan(chi)/tan(eta) (17.10), and P' = tan(eta) F(eta)
//! (17.11), so the state at contact lambda is (17.12)
//!     q(chi) = q2 + i q1 = int_|chi|^lambda S^eta(tan chi/tan eta) F(eta) d eta,
//! and the tangential strain psi = u' (17.13)
//!     psi(chi) = 2 int_0^eta_s(chi) D^eta(tan chi/tan eta) F(eta) d eta,
//! D = tau (E*/2) du'/dP = -(H\[S1\] + beta S2 + the row's constant) + b beta tau/pi, zero on the
//! stick zone of the increment ([`Spectral::slip_zone_strain`], [`Spectral::outside_strain`]), and
//! eta_s(chi) the contact at which chi was overtaken by the stick edge, c(eta_s) = |chi| (lambda
//! where the point still slips): a stuck point keeps its strain. The b beta tau/pi term is the
//! `periodic` convention's lateral strain (zero in `paper`).
//!
//! The increment at an eta between the load's Chebyshev nodes: its stick edge gamma_T and its
//! 6 n coefficients times cos(eta) (the unit increment's pole at full contact, as the load's G
//! cos(eta)) interpolated in eta through the nodes' (the load's barycentric weights): the basis
//! in T follows gamma_T, and the coefficients of the solution vary smoothly with eta
//! (checked in `row_fields_tests.rs` against an increment solved at that eta,
//! `interpolated_increment_is_the_solved_one`). The eta integrals are tanh-sinh, split where the
//! point changes zone (eta = |chi|: the contact edge, (eta - |chi|)^(-1/2 + theta0); eta_s: the
//! stick edge).
//!
//! Checks, from each discretisation (their error: the difference of the two):
//! - `stick_ratio`: max of |q1|/(mu q2) at x/c = j/10 (j = 1 .. 9) and 1 - 10^-k (k = 2 .. 6)
//!   (Coulomb: <= 1, tight at c, approached like 1 - A (c - x)^(1/2 - theta0), 17.2);
//! - `pressure_min`: min q2 / max q2 at x = (j/16) a, j = 0 .. 15 and the points above (>= 0);
//! - `outward_slip`: at every load node eta_j, the slip rate du/dP of the points of the slip zone,
//!   (2/E*) int_c^x (E*/2) du'/dP (the stuck points do not move), over its largest magnitude, and
//!   the maximum over the nodes and the slip zone (<= 0: every point slips inward, against
//!   q1 = mu q2 sign x, at every stage of the loading: no slip reversal).

use super::fields::{Check, Checks, PointFields};
use super::quadrature::{graded, DoubleExp};
use super::spectral::{Spectral, SpectralIncrement};
use super::spectral_row_load::LoadRate;

/// Distance to a zone's edge (in T) below which the strain's nodes are left out (`fields`).
const EDGE_CUT: f64 = 1e-15;

/// The increments of one solved load as functions of eta (module doc).
pub struct History<'a> {
    rate: &'a LoadRate<f64>,
    lambda: f64,
    beta: f64,
    mu: f64,
    n: usize,
    periodic: bool,
    rule: DoubleExp<f64>,
}

/// The fields at the points and the three checks of one discretisation.
#[derive(Debug, Clone, PartialEq)]
pub struct RowState {
    /// q1, q2 (scale E* k L/pi) and psi (scale k L/pi) at the points.
    pub points: Vec<PointFields>,
    /// [stick ratio, pressure minimum, outward slip] (module doc).
    pub checks: [f64; 3],
}

/// The fields and checks of the finer discretisation with their differences from the coarser.
#[derive(Debug, Clone, PartialEq)]
pub struct RowFieldsF64 {
    /// The fields at the points (the finer discretisation).
    pub points: Vec<PointFields>,
    /// The largest difference of the two over the points.
    pub errors: PointFields,
    /// The checks, each with its difference.
    pub checks: Checks,
}

impl<'a> History<'a> {
    /// The history of the load `rate` solved at contact `lambda` with `n` polynomials per family.
    pub fn new(rate: &'a LoadRate<f64>, lambda: f64, (beta, mu): (f64, f64), n: usize, periodic: bool) -> History<'a> {
        let theta0 = (beta * mu).atan() / std::f64::consts::PI;
        History { rate, lambda, beta, mu, n, periodic, rule: DoubleExp::new(&1.0, 0.5 + theta0) }
    }

    /// The increment at contact `eta` (module doc) and its method.
    pub fn increment_at(&self, eta: f64) -> (Spectral<f64>, SpectralIncrement<f64>) {
        let r = self.rate;
        let incs = &r.increments;
        let gammas: Vec<f64> = incs.iter().map(|(_, i)| i.gamma).collect();
        let gamma = r.interpolate(&gammas, &eta);
        // the coefficients times cos(eta): the unit increment's 1/cos(eta) pole at full contact
        // (beta = 0: S2 = 1/(pi cos(eta) sqrt(1 - T^2))) removed, as the load does for G
        let coeffs = (0..6 * self.n)
            .map(|k| {
                let values: Vec<f64> = incs.iter().zip(&r.nodes).map(|((_, i), e)| i.coeffs[k] * e.cos()).collect();
                r.interpolate(&values, &eta) / eta.cos()
            })
            .collect();
        let sp = Spectral::row(self.beta, self.mu, self.n, eta.tan(), self.periodic);
        let inc = sp.increment(&gamma, coeffs);
        (sp, inc)
    }

    /// The stick half-width c(eta) in chi = atan(gamma_T tan eta).
    fn stick_edge(&self, eta: f64) -> f64 {
        let gammas: Vec<f64> = self.rate.increments.iter().map(|(_, i)| i.gamma).collect();
        (self.rate.interpolate(&gammas, &eta) * eta.tan()).atan()
    }

    /// eta_s(chi): c(eta_s) = chi (bisection; c grows with eta), lambda where chi >= c(lambda).
    fn stuck_at(&self, chi: f64) -> f64 {
        if chi <= 0.0 {
            return 0.0;
        }
        if self.stick_edge(self.lambda) <= chi {
            return self.lambda;
        }
        let (mut lo, mut hi) = (chi, self.lambda);
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if self.stick_edge(mid) < chi {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }

    /// q1, q2 and (with `strain`) psi at chi in [0, lambda] ((17.12), (17.13)).
    pub fn fields(&self, chi: f64, strain: bool) -> PointFields {
        let (lambda, rate) = (self.lambda, self.rate);
        let eta_s = self.stuck_at(chi);
        let (mut q1, mut q2, mut psi) = (0.0, 0.0, 0.0);
        let f = |eta: f64| rate.interpolate(&rate.values, &eta);
        // slip: (chi, eta_s), d_a = eta - chi
        let len = eta_s - chi;
        if len > 0.0 {
            self.rule.sweep(&len, &graded(&0.0, &len, None, None), |d_a, _, w| {
                let eta = chi + d_a;
                let (sp, inc) = self.increment_at(eta);
                // 1 - T = sin(eta - chi)/(cos chi sin eta), without cancellation
                let to_one = d_a.sin() / (chi.cos() * eta.sin());
                let from_gamma = 1.0 - to_one - inc.gamma;
                if !(to_one > 0.0 && from_gamma > 0.0) {
                    return;
                }
                let fe = f(eta);
                let (s2, s1) = sp.densities(&inc, true, &from_gamma, &to_one);
                q2 += w * s2 * fe;
                q1 += w * s1 * fe;
                // the strain ~ (1 - T)^(-1/2 + theta0) at the contact edge: below 1e-15 the
                // nodes add at most 1e-15^(1/2) of it, and the Cauchy integrals would be graded
                // over a thousand pieces (the same cut at the edge's outside below)
                if strain && to_one > EDGE_CUT && from_gamma > EDGE_CUT {
                    let constant = sp.strain_constant(&inc);
                    psi += w * sp.slip_zone_strain(&inc, &constant, &from_gamma, &to_one) * fe;
                }
            });
        }
        // stick: (eta_s, lambda)
        let len = lambda - eta_s;
        if len > 0.0 {
            self.rule.sweep(&len, &graded(&0.0, &len, None, None), |d_a, _, w| {
                let eta = eta_s + d_a;
                let (sp, inc) = self.increment_at(eta);
                let t = chi.tan() / eta.tan();
                if inc.gamma - t <= 0.0 {
                    return; // at the stick edge (eta_s to rounding): the density is bounded there
                }
                let (s2, s1) = sp.densities(&inc, false, &(t + inc.gamma), &(inc.gamma - t));
                let fe = f(eta);
                q2 += w * s2 * fe;
                q1 += w * s1 * fe;
            });
        }
        // outside the contact: (0, chi), d_b = chi - eta
        if strain && chi > 0.0 {
            self.rule.sweep(&chi, &graded(&0.0, &chi, None, None), |d_a, d_b, w| {
                let eta = *d_a;
                let beyond = d_b.sin() / (chi.cos() * eta.sin());
                if !(beyond > EDGE_CUT && beyond < 1e300) {
                    return; // eta underflowing to 0 (tail nodes): the strain vanishes there
                }
                let (sp, inc) = self.increment_at(eta);
                let constant = sp.strain_constant(&inc);
                psi += w * sp.outside_strain(&inc, &constant, &beyond) * f(eta);
            });
        }
        PointFields { q1: q1 + 0.0, q2: q2 + 0.0, psi: 2.0 * psi + 0.0 }
    }

    /// The fields at the points x/a (`x_over_a` in [0, 1]) and the checks (module doc).
    pub fn state(&self, x_over_a: &[f64]) -> RowState {
        let lambda = self.lambda;
        let points: Vec<PointFields> = x_over_a.iter().map(|x| self.fields(x * lambda, true)).collect();
        let c = self.stick_edge(lambda);
        let near_edge = (2..7).map(|k| 1.0 - 10f64.powi(-k));
        let stick: Vec<PointFields> =
            (1..10).map(|j| j as f64 / 10.0).chain(near_edge).map(|r| self.fields(c * r, false)).collect();
        let stick_ratio = stick.iter().map(|p| p.q1.abs() / (self.mu * p.q2)).fold(0.0, f64::max);
        let contact: Vec<f64> = (0..16).map(|j| self.fields(lambda * j as f64 / 16.0, false).q2).collect();
        let all_q2 = contact.iter().chain(stick.iter().map(|p| &p.q2)).chain(points.iter().map(|p| &p.q2));
        let (low, top) = all_q2.fold((f64::INFINITY, 0.0f64), |(l, t), &q| (l.min(q), t.max(q)));
        let outward = self
            .rate
            .increments
            .iter()
            .map(|(sp, inc)| sp.outward_slip(inc, &EDGE_CUT))
            .fold(f64::NEG_INFINITY, f64::max);
        RowState { points, checks: [stick_ratio, low / top, outward] }
    }
}

/// The fields at `x_over_a` and the checks of the two discretisations (coarse, fine), each
/// [`History`] at its own lambda: the finer's values, the differences as errors.
pub fn row_fields(coarse: &History, fine: &History, x_over_a: &[f64]) -> RowFieldsF64 {
    let (c, f) = (coarse.state(x_over_a), fine.state(x_over_a));
    let mut errors: PointFields = PointFields { q1: 0.0, q2: 0.0, psi: 0.0 };
    for (a, b) in c.points.iter().zip(&f.points) {
        errors.q1 = errors.q1.max((a.q1 - b.q1).abs());
        errors.q2 = errors.q2.max((a.q2 - b.q2).abs());
        errors.psi = errors.psi.max((a.psi - b.psi).abs());
    }
    let check = |k: usize| Check { value: f.checks[k], error: (f.checks[k] - c.checks[k]).abs() };
    RowFieldsF64 {
        points: f.points,
        errors,
        checks: Checks { stick_ratio: check(0), pressure_min: check(1), outward_slip: check(2) },
    }
}
