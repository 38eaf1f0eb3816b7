//! The periodic row's fields q1, q2, psi at points and the checks of its inequalities
//! (docs/theory.md section 17.8, "The row's fields", (17.12)-(17.14)), superposed from the
//! increments of the spectral load ([`super::spectral_row_load::load_rate`]), generic over `f64`
//! and MPFR ([`History`]); [`row_fields`]: two `f64` discretisations, their difference the
//! error; [`verified_row_fields`]: two MPFR runs (those of
//! [`super::spectral_row_load::verified_mpfr_runs`], node roots in full), their agreement the
//! verified digits.
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
//! cos(eta)) interpolated in the load's node variable through the nodes' (the load's
//! barycentric weights): the basis in T follows gamma_T, and the coefficients of the solution
//! vary smoothly with eta (checked in `row_fields_tests.rs` against an increment solved at that
//! eta, `interpolated_increment_is_the_solved_one`). In `f64` the coefficients carry the frame's
//! rounding noise (a floor of 1e-6 .. 1e-4 in the interpolated densities); in MPFR at the bits
//! of the verified load they do not, and the fields converge with the nodes (docs/theory.md
//! section 17.8, "The row's fields in MPFR"). The eta integrals are tanh-sinh, split where the
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

use rug::Float;

use super::fields::{Check, Checks, PointFields};
use super::quadrature::{graded, DoubleExp};
use super::real::{Mp, Real};
use super::spectral::{Spectral, SpectralIncrement};
use super::spectral_punch_fields::VerifiedFields;
use super::spectral_row_load::LoadRate;
use crate::numerics::accuracy::{agreement_mpfr, digits_cap_for_bits};

/// Distance to a zone's edge (in T) below which the strain's nodes are left out (`fields`), in
/// `f64`; MPFR takes [`History::with_edge_cut`].
const EDGE_CUT: f64 = 1e-15;

/// The increments of one solved load as functions of eta (module doc), in `f64` or MPFR.
pub struct History<'a, T = f64> {
    rate: &'a LoadRate<T>,
    lambda: T,
    beta: T,
    mu: T,
    n: usize,
    periodic: bool,
    rule: DoubleExp<T>,
    /// The nodes' stick edges gamma_T.
    gammas: Vec<T>,
    /// Per coefficient k, its values times cos(eta_j) at the nodes.
    scaled: Vec<Vec<T>>,
    edge_cut: T,
}

/// The fields at the points and the three checks of one discretisation.
#[derive(Debug, Clone, PartialEq)]
pub struct RowState<T = f64> {
    /// q1, q2 (scale E* k L/pi) and psi (scale k L/pi) at the points.
    pub points: Vec<PointFields<T>>,
    /// [stick ratio, pressure minimum, outward slip] (module doc).
    pub checks: [T; 3],
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

impl<'a, T: Real> History<'a, T> {
    /// The history of the load `rate` solved at contact `lambda` with `n` polynomials per family.
    pub fn new(rate: &'a LoadRate<T>, lambda: T, (beta, mu): (T, T), n: usize, periodic: bool) -> History<'a, T> {
        let theta0 = (beta.to_f64() * mu.to_f64()).atan() / std::f64::consts::PI;
        let incs = &rate.increments;
        let gammas = incs.iter().map(|(_, i)| i.gamma.clone()).collect();
        // the coefficients times cos(eta): the unit increment's 1/cos(eta) pole at full contact
        // (beta = 0: S2 = 1/(pi cos(eta) sqrt(1 - T^2))) removed, as the load does for G
        let cosines: Vec<T> = rate.nodes.iter().map(|e| e.cos()).collect();
        let scaled = (0..6 * n)
            .map(|k| incs.iter().zip(&cosines).map(|((_, i), c)| i.coeffs[k].clone() * c.clone()).collect())
            .collect();
        let rule = DoubleExp::new(&lambda.lit(1.0), 0.5 + theta0);
        let edge_cut = lambda.lit(EDGE_CUT);
        History { rate, lambda, beta, mu, n, periodic, rule, gammas, scaled, edge_cut }
    }

    /// The same history with the strain's nodes within `cut` of a zone's edge left out (module
    /// doc; the default 1e-15 suits `f64`: the strain ~ distance^(-1/2 + theta0), so the nodes
    /// left out add at most about `cut`^(1/2 + theta0)).
    pub fn with_edge_cut(mut self, cut: f64) -> History<'a, T> {
        self.edge_cut = self.lambda.lit(cut);
        self
    }

    /// The increment at contact `eta` (module doc) and its method.
    pub fn increment_at(&self, eta: &T) -> (Spectral<T>, SpectralIncrement<T>) {
        let terms = self.rate.terms(eta);
        let gamma = LoadRate::interpolate_at(&terms, &self.gammas);
        let cos = eta.cos();
        let coeffs = self.scaled.iter().map(|values| LoadRate::interpolate_at(&terms, values) / cos.clone()).collect();
        let sp = Spectral::row(self.beta.clone(), self.mu.clone(), self.n, eta.tan(), self.periodic);
        let inc = sp.increment(&gamma, coeffs);
        (sp, inc)
    }

    /// The stick half-width c(eta) in chi = atan(gamma_T tan eta).
    fn stick_edge(&self, eta: &T) -> T {
        (self.rate.interpolate(&self.gammas, eta) * eta.tan()).atan()
    }

    /// eta_s(chi): c(eta_s) = chi (bisection to the working precision; c grows with eta), lambda
    /// where chi >= c(lambda).
    fn stuck_at(&self, chi: &T) -> T {
        let (zero, half) = (chi.lit(0.0), chi.lit(0.5));
        if *chi <= zero {
            return zero;
        }
        if self.stick_edge(&self.lambda) <= *chi {
            return self.lambda.clone();
        }
        let (mut lo, mut hi) = (chi.clone(), self.lambda.clone());
        for _ in 0..(chi.bits() + 7).max(60) {
            let mid = half.clone() * (lo.clone() + hi.clone());
            if self.stick_edge(&mid) < *chi {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        half * (lo + hi)
    }

    /// q1, q2 and (with `strain`) psi at chi in [0, lambda] ((17.12), (17.13)).
    pub fn fields(&self, chi: &T, strain: bool) -> PointFields<T> {
        let (lambda, rate, cut) = (&self.lambda, self.rate, &self.edge_cut);
        let (zero, one) = (chi.lit(0.0), chi.lit(1.0));
        let eta_s = self.stuck_at(chi);
        let (mut q1, mut q2, mut psi) = (zero.clone(), zero.clone(), zero.clone());
        let f = |eta: &T| rate.interpolate(&rate.values, eta);
        // slip: (chi, eta_s), d_a = eta - chi
        let len = eta_s.clone() - chi.clone();
        if len > zero {
            self.rule.sweep(&len, &graded(&zero, &len, None, None), |d_a, _, w| {
                let eta = chi.clone() + d_a.clone();
                let (sp, inc) = self.increment_at(&eta);
                // 1 - T = sin(eta - chi)/(cos chi sin eta), without cancellation
                let to_one = d_a.sin() / (chi.cos() * eta.sin());
                let from_gamma = one.clone() - to_one.clone() - inc.gamma.clone();
                if !(to_one > zero && from_gamma > zero) {
                    return;
                }
                let fe = f(&eta);
                let (s2, s1) = sp.densities(&inc, true, &from_gamma, &to_one);
                q2 += &(w.clone() * s2 * fe.clone());
                q1 += &(w.clone() * s1 * fe.clone());
                // the strain ~ (1 - T)^(-1/2 + theta0) at the contact edge: below the cut the
                // nodes add at most cut^(1/2) of it, and the Cauchy integrals would be graded
                // over a thousand pieces (the same cut at the edge's outside below)
                if strain && to_one > *cut && from_gamma > *cut {
                    let constant = sp.strain_constant(&inc);
                    psi += &(w.clone() * sp.slip_zone_strain(&inc, &constant, &from_gamma, &to_one) * fe);
                }
            });
        }
        // stick: (eta_s, lambda)
        let len = lambda.clone() - eta_s.clone();
        if len > zero {
            self.rule.sweep(&len, &graded(&zero, &len, None, None), |d_a, _, w| {
                let eta = eta_s.clone() + d_a.clone();
                let (sp, inc) = self.increment_at(&eta);
                let t = chi.tan() / eta.tan();
                if inc.gamma.clone() - t.clone() <= zero {
                    return; // at the stick edge (eta_s to rounding): the density is bounded there
                }
                let (s2, s1) = sp.densities(&inc, false, &(t.clone() + inc.gamma.clone()), &(inc.gamma.clone() - t));
                let fe = f(&eta);
                q2 += &(w.clone() * s2 * fe.clone());
                q1 += &(w.clone() * s1 * fe);
            });
        }
        // outside the contact: (0, chi), d_b = chi - eta
        if strain && *chi > zero {
            let huge = chi.lit(1e300);
            self.rule.sweep(chi, &graded(&zero, chi, None, None), |d_a, d_b, w| {
                let eta = d_a;
                let beyond = d_b.sin() / (chi.cos() * eta.sin());
                if !(beyond > *cut && beyond < huge) {
                    return; // eta underflowing to 0 (tail nodes): the strain vanishes there
                }
                let (sp, inc) = self.increment_at(eta);
                let constant = sp.strain_constant(&inc);
                psi += &(w.clone() * sp.outside_strain(&inc, &constant, &beyond) * f(eta));
            });
        }
        PointFields { q1: q1 + zero.clone(), q2: q2 + zero.clone(), psi: chi.lit(2.0) * psi + zero }
    }

    /// The fields at the points x/a (`x_over_a` in [0, 1]) and the checks (module doc).
    pub fn state(&self, x_over_a: &[T]) -> RowState<T> {
        let lambda = &self.lambda;
        let lit = |v: f64| lambda.lit(v);
        let points: Vec<PointFields<T>> =
            x_over_a.iter().map(|x| self.fields(&(x.clone() * lambda.clone()), true)).collect();
        let c = self.stick_edge(lambda);
        let near_edge = (2..7).map(|k| 1.0 - 10f64.powi(-k));
        let stick: Vec<PointFields<T>> = (1..10)
            .map(|j| j as f64 / 10.0)
            .chain(near_edge)
            .map(|r| self.fields(&(c.clone() * lit(r)), false))
            .collect();
        let stick_ratio = stick.iter().map(|p| p.q1.abs() / (self.mu.clone() * p.q2.clone())).fold(lit(0.0), max);
        let contact: Vec<T> =
            (0..16).map(|j| self.fields(&(lambda.clone() * lit(j as f64 / 16.0)), false).q2).collect();
        let all_q2 = contact.iter().chain(stick.iter().map(|p| &p.q2)).chain(points.iter().map(|p| &p.q2));
        let (low, top) = all_q2
            .fold((lit(f64::INFINITY), lit(0.0)), |(l, t), q| (if *q < l { q.clone() } else { l }, max(t, q.clone())));
        let outward = self
            .rate
            .increments
            .iter()
            .map(|(sp, inc)| sp.outward_slip(inc, &self.edge_cut))
            .fold(lit(f64::NEG_INFINITY), max);
        RowState { points, checks: [stick_ratio, low / top, outward] }
    }
}

/// The larger of two numbers (the first where they are equal or unordered).
fn max<T: Real>(a: T, b: T) -> T {
    if b > a {
        b
    } else {
        a
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

/// The fields at `x_over_a` (x/a, rounded to each run's precision) and the checks of two MPFR
/// runs (coarse, fine) at the same lambda: the finer's values, per field the least number of
/// digits where the two agree over the points on the scale 1 (E* k L/pi, k L/pi), each check
/// with its difference from the coarser's.
pub fn verified_row_fields(coarse: &History<Mp>, fine: &History<Mp>, x_over_a: &[Float]) -> VerifiedFields {
    let each = |h: &History<Mp>| {
        let xs: Vec<Mp> = x_over_a.iter().map(|x| Mp(Float::with_val(h.lambda.bits(), x))).collect();
        h.state(&xs)
    };
    let (c, f) = (each(coarse), each(fine));
    let cap = digits_cap_for_bits(coarse.lambda.bits());
    let one = Float::with_val(64, 1);
    let agree = |get: fn(&PointFields<Mp>) -> &Mp| {
        c.points.iter().zip(&f.points).map(|(a, b)| agreement_mpfr(&get(a).0, &get(b).0, &one, cap)).fold(cap, f64::min)
    };
    let digits = PointFields { q1: agree(|p| &p.q1), q2: agree(|p| &p.q2), psi: agree(|p| &p.psi) };
    let check =
        |k: usize| Check { value: f.checks[k].to_f64(), error: (f.checks[k].to_f64() - c.checks[k].to_f64()).abs() };
    VerifiedFields {
        points: f.points.into_iter().map(|p| PointFields { q1: p.q1.0, q2: p.q2.0, psi: p.psi.0 }).collect(),
        digits,
        checks: Checks { stick_ratio: check(0), pressure_min: check(1), outward_slip: check(2) },
    }
}
