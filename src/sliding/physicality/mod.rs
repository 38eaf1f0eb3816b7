//! One physicality criterion for every Problem 1 method (docs/theory.md section 8).
//!
//! A method (MPFR reduction, f64 collocation, or the series method through one of them) hands its
//! solution over as two functions, [`ContactFunctions`]: the bounded factor p(u)/omega(u) of the
//! pressure [2.13] on the contact (tangent variable u in [-1, 1]) and the slope of the gap off the
//! contact. This module chooses the points, integrates, applies the tolerances and words the
//! verdict, so two methods given the same contact reach the same verdict for the same reason.
//!
//! The criterion, in both conventions:
//! 1. the contact lies inside the cell: for a profile repeated from the cell (-L/2, L/2) (the
//!    parabola) -a > -L/2 and b < L/2; for a periodic profile (the sinusoid) 2 l < L;
//! 2. p >= 0 on [-a, b]: p/omega sampled at 68 Chebyshev–Lobatto points -cos(pi k/67) and at
//!    1 - 10^-j, -1 + 10^-j (j = 2..10), refused below -`pressure_tol` times the largest |p/omega|;
//! 3. the gap h between the punch and the (worn) surface, integrated from the leading end b and
//!    from the trailing end -a, each to the middle of the free arc x - c = +-L/2 (single punch:
//!    4 l beyond each end), must be >= 0. The slope used is the gap slope without the step
//!    2 beta tau0/E* that the adhesive shear q1 = tau0 puts into v' at the contact ends (just past
//!    the leading edge it would make h < 0 for every tau0 > 0: a property of the tau0 model, not
//!    of the contact); that step is reported as `edge_step`. Near an end h ~ d^(3/2 -+ theta), so
//!    the samples are graded as x = end +- R s^4, s = j/32 (j = 1..32), and the slope is
//!    integrated in s by 16-point Gauss–Legendre on 4 dyadic panels (64 slopes per side).
//!
//! Where the surface closes over a period (the `periodic` convention; or `paper` with K = 0, i.e.
//! M = 0, where the two conventions are the same problem) the two halves of the gap meet: with the
//! full slope, h_lead(mid) - h_trail(mid) = 0, checked (its value is reported as `closure_defect`,
//! round-off), and a negative gap is a refusal. In `paper` with M != 0 the two halves differ by
//! the closure defect M = (2/E*) beta P1 - cW P2 (checked against the formula): the gap is defined
//! only up to M, so a negative gap is a warning reported beside `closure_defect`, not a refusal.
//! A single punch has no closure (K = 0 as L -> infinity): a negative gap is a refusal.
//!
//! The admissible range of the load (or size) that a refusal quotes is computed by
//! [`admissible`] from the method's own direct problem.

pub mod admissible;

use crate::error::Error;
use crate::model::OnPunchRow;
use crate::model::{readable, Convention, Period, PunchShape, SlidingLoad, SlidingProblem};
use crate::numerics::accuracy::readable_f64;
use crate::numerics::gauss_jacobi_f64::{gauss_jacobi, GaussRule};

/// A method's solution as the criterion sees it (lengths and loads in any one consistent unit).
pub trait ContactFunctions {
    /// p(u)/omega(u) at the tangent variable u in [-1, 1] (its sign is the sign of p).
    fn pressure_factor(&self, u: f64) -> f64;
    /// p/omega at each of `us` (the criterion passes its samples, [`pressure_points`]): by
    /// default [`Self::pressure_factor`] at each; a method that already has the values at these
    /// points (the f64 method evaluates its outputs there) returns them, the same numbers.
    fn pressure_factors(&self, us: &[f64]) -> Vec<f64> {
        us.iter().map(|&u| self.pressure_factor(u)).collect()
    }
    /// The slope of the (worn) surface that the gap is measured to, w = g'_row(x) - h'(x), at
    /// x - c = `xi` off the contact (|xi| > l, up to the middle of the free arc): smooth there
    /// (it is the elastic response plus constants), with the surface convention's constant K
    /// included and the adhesive shear's edge step 2 beta tau0/E* left out (module doc).
    fn surface_slope(&self, xi: f64) -> f64;
    /// [`Self::surface_slope`] at each of `xis` into `out` (the criterion passes a panel's
    /// points at once): by default one at a time; a method may evaluate them together, with the
    /// same numbers as one at a time.
    fn surface_slopes(&self, xis: &[f64], out: &mut [f64]) {
        for (o, xi) in out.iter_mut().zip(xis) {
            *o = self.surface_slope(*xi);
        }
    }
    /// g of the punch row at x (the profile repeated from its cell, steps and all; +infinity
    /// where there is no punch), e.g. [`crate::params::sliding::row_height_f64`].
    fn profile_height(&self, x: f64) -> f64;
    /// g_row(end + dx) - g_row(end): by default the two heights differenced; a method gives the
    /// form without their cancellation, e.g. [`crate::params::sliding::row_rise_f64`] (next to a
    /// contact far off the origin the heights are far larger than the gap).
    fn profile_rise(&self, end: f64, dx: f64) -> f64 {
        self.profile_height(end + dx) - self.profile_height(end)
    }
}

/// Where the contact must lie.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Cell {
    /// The profile is repeated from the cell (-L/2, L/2) (kinks at +-L/2): -a > -L/2, b < L/2.
    Fixed {
        /// L/2.
        half_period: f64,
    },
    /// The profile is periodic by itself: only 2 l < L.
    Periodic {
        /// L.
        period: f64,
    },
    /// A single punch: anywhere.
    Unbounded,
}

/// The contact and the data of the criterion that do not come from [`ContactFunctions`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Setting {
    /// Surface convention.
    pub convention: Convention,
    /// Where the contact must lie (also gives the period).
    pub cell: Cell,
    /// Trailing end -a is at x = -`a`.
    pub a: f64,
    /// Leading end.
    pub b: f64,
    /// 2 beta tau0/E*: the slope step the adhesive shear puts just past the contact ends.
    pub edge_step: f64,
    /// The closure defect by its formula, M = (2/E*) beta P1 - cW P2, in `paper` with a period;
    /// 0 otherwise (docs/theory.md section 8).
    pub closure_formula: f64,
    /// Relative tolerance of the pressure test (the method's accuracy of p/omega).
    pub pressure_tol: f64,
    /// Where the profile ends (|x| < R for a circle narrower than the cell): beyond it there is
    /// no punch, so the gap is integrated only up to it and the closure is not checked.
    pub extent: Option<f64>,
    /// Relative tolerance of the closure check ([`CLOSURE_TOL`] for a solution of the equations;
    /// larger for a contact known only to an estimated accuracy, e.g. the series method's).
    pub closure_tol: f64,
}

impl Setting {
    fn l(&self) -> f64 {
        0.5 * (self.a + self.b)
    }
    fn c(&self) -> f64 {
        0.5 * (self.b - self.a)
    }
    fn period(&self) -> Option<f64> {
        match self.cell {
            Cell::Fixed { half_period } => Some(2.0 * half_period),
            Cell::Periodic { period } => Some(period),
            Cell::Unbounded => None,
        }
    }
    /// Whether the surface closes over a period (a negative gap is then a refusal).
    fn closes(&self) -> bool {
        self.convention == Convention::PeriodicSurface || self.closure_formula == 0.0 || self.period().is_none()
    }
}

/// Relative tolerance of the gap test: the f64 quadrature of the gap (`gap_side`) is accurate
/// to ~1e-11 of max |h| (test `the_gap_quadrature_matches_a_fine_reference`); 1e-8 leaves a margin.
pub const GAP_TOL: f64 = 1e-8;
/// The rounding bound of a gap sample h = rise - int w, relative to |rise| + |int w|: the rise
/// ([`ContactFunctions::profile_rise`]) a few operations, the integral a sum of at most 16 terms
/// per panel and 4 panels of slopes each a few operations from their own data (a sum of n terms
/// rounds within n eps of the sum of their magnitudes; w keeps one sign where it is large, next
/// to a contact far off the origin, so that sum is |int w|): 32 eps. Next to a contact at c with
/// half-length l (a parabola, single punch) |rise| ~ |int w| ~ 2 k |c| 4 l at the sample farthest
/// out, against a largest gap of about 22 k l^2 there (Hertz's at 5 l from the centre), so the
/// bound is about 5e-15 |c|/l of the largest gap: below [`GAP_TOL`] of it up to |c| ~ 2e6 l
/// (fuzz seed 2026 case 3960: 6.6e4, where the plain difference of heights, not this bound, was
/// the fault), the larger term beyond (adhesive friction at tiny loads puts c at
/// -beta tau0/(E* k) whatever l is).
pub const GAP_ROUNDING: f64 = 32.0 * f64::EPSILON;

/// One sample of the gap ([`gap_side`]): where, the gap, and the bound of its rounding.
#[derive(Debug, Clone, Copy)]
struct GapSample {
    x: f64,
    h: f64,
    rounding: f64,
}

/// Relative tolerance on the closure check: |measured - expected| <= this times max |h| + |M|.
pub const CLOSURE_TOL: f64 = 1e-6;

/// Which end a gap was integrated from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum End {
    /// The leading end x = b.
    Leading,
    /// The trailing end x = -a.
    Trailing,
}

impl End {
    fn name(self) -> &'static str {
        match self {
            End::Leading => "leading",
            End::Trailing => "trailing",
        }
    }
}

/// What the criterion found for an admissible contact (the default: nothing found yet).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Assessment {
    /// Largest |p/omega| over the samples.
    pub max_pressure_factor: f64,
    /// The most negative gap of the criterion (0 when none is below round-off).
    pub min_gap: f64,
    /// Where it is (x).
    pub min_gap_x: f64,
    /// h_lead(mid) - h_trail(mid) with the full slope, measured: M = (2/E*) beta P1 - cW P2 in
    /// `paper`, round-off in `periodic`; None for a single punch or a profile that does not span
    /// the free arc (a circle narrower than the cell).
    pub closure_defect: Option<f64>,
    /// 2 beta tau0/E* (0 without adhesive friction).
    pub edge_step: f64,
    /// In `paper` (M != 0): the gap is negative somewhere; the message says how much and why it
    /// is not a refusal.
    pub warning: Option<String>,
}

/// Why a contact is refused.
#[derive(Debug, Clone, PartialEq)]
pub enum Refusal {
    /// The contact leaves its cell.
    OutsideCell {
        /// -a.
        neg_a: f64,
        /// b.
        b: f64,
        /// L/2.
        half_period: f64,
    },
    /// p < 0 somewhere on the contact.
    NegativePressure {
        /// The tangent variable where it was found.
        u: f64,
        /// p/omega there, relative to the largest |p/omega|.
        relative: f64,
    },
    /// The punch overlaps the surface outside the contact.
    NegativeGap {
        /// The gap.
        h: f64,
        /// Where (x).
        x: f64,
        /// Integrated from which end.
        from: End,
    },
    /// The gap is NaN or -infinity at x (the method's evaluation failed there).
    NonFinite {
        /// Where (x).
        x: f64,
    },
    /// The two halves of the gap disagree with the closure they must have: the method's gap
    /// slope or its integration is not accurate enough (a failure to converge, not physics).
    Inconsistent {
        /// h_lead(mid) - h_trail(mid) measured.
        measured: f64,
        /// What it must be (0 or M).
        expected: f64,
    },
}

impl Refusal {
    /// Whether this is a finding about the physics (else a numerical failure).
    pub(crate) fn is_physical(&self) -> bool {
        !matches!(self, Refusal::Inconsistent { .. } | Refusal::NonFinite { .. })
    }

    /// The reason in words (the same for every method).
    pub fn why(&self) -> String {
        match self {
            Refusal::OutsideCell { neg_a, b, half_period } => format!(
                "the contact [-a, b] = [{}, {}] leaves the cell (-L/2, L/2) = (-{h}, {h}) of the periodic profile",
                readable_f64(*neg_a),
                readable_f64(*b),
                h = readable_f64(*half_period)
            ),
            Refusal::NegativePressure { u, relative } => format!(
                "negative pressure: p/omega = {} of its maximum at u = {} (tangent variable; u = -1 is the trailing end, u = 1 the leading end)",
                readable_f64(*relative),
                readable_f64(*u)
            ),
            Refusal::NegativeGap { h, x, from } => format!(
                "negative gap h = {} at x = {} (the punch overlaps the surface outside the contact; gap integrated from the {} end)",
                readable_f64(*h),
                readable_f64(*x),
                from.name()
            ),
            Refusal::NonFinite { x } => {
                format!("the gap is not finite at x = {} (its evaluation failed)", readable_f64(*x))
            }
            Refusal::Inconsistent { measured, expected } => format!(
                "the two halves of the gap differ by {}, expected {} (the gap slope is not accurate enough)",
                readable_f64(*measured),
                readable_f64(*expected)
            ),
        }
    }
}

/// The pressure samples of criterion 2 (module doc).
pub fn pressure_points() -> Vec<f64> {
    let mut us: Vec<f64> = (0..=67).map(|k| -(std::f64::consts::PI * k as f64 / 67.0).cos()).collect();
    for j in 2..=10 {
        let e = 10f64.powi(-j);
        us.push(1.0 - e);
        us.push(e - 1.0);
    }
    us
}

/// Samples of the gap per side: x - c = start + dir R s^4 at s = j/32, j = 1..=32.
const GAP_SAMPLES: usize = 32;
/// The panels of the gap integration in s, in units of 1/[`GAP_SAMPLES`]: dyadic toward the end
/// (w ~ d^(1/2 -+ theta) next to it, and the other contact end's singularity at a distance
/// proportional to the panel's own from the end), each with [`GAP_NODES`] Gauss–Legendre points.
/// The samples inside a panel come from the interpolant of its node values, whose error falls
/// like rho^(-N) (not the rule's rho^(-2N)): 16 points keep them within 1e-11 of max |h|
/// (test `the_gap_quadrature_matches_a_fine_reference`; 12 points gave 7e-10).
const GAP_PANELS: [(usize, usize); 4] = [(0, 4), (4, 8), (8, 16), (16, 32)];
/// Gauss–Legendre points per panel of the gap integration.
const GAP_NODES: usize = 16;

/// The Gauss–Legendre rule of the gap panels and its partial integrals: for a panel of `w`
/// samples, row k - 1 of `partial[w]` holds int_{-1}^{-1 + 2k/w} l_i(z) dz (l_i the Lagrange
/// basis of the nodes, k = 1..=w; the last row is the weights), so the integral of the
/// interpolant of the node values up to each sample inside the panel is one dot product.
struct GapRule {
    rule: GaussRule,
    partial: std::collections::BTreeMap<usize, Vec<[f64; GAP_NODES]>>,
}

/// int_{-1}^{y} l_i(z) dz for the Gauss–Legendre nodes z_i and weights w_i: with l_i =
/// sum_m (2m+1)/2 w_i P_m(z_i) P_m (exact: the rule integrates degree 2N - 2) and
/// int_{-1}^y P_m = (P_{m+1}(y) - P_{m-1}(y))/(2m+1) (m >= 1), y + 1 (m = 0):
/// (w_i/2) [y + 1 + sum_{m=1}^{N-1} P_m(z_i) (P_{m+1}(y) - P_{m-1}(y))].
fn partial_integrals(rule: &GaussRule, y: f64) -> [f64; GAP_NODES] {
    let legendre = |x: f64| {
        let mut p = [0.0; GAP_NODES + 1];
        p[0] = 1.0;
        p[1] = x;
        for m in 1..GAP_NODES {
            p[m + 1] = ((2 * m + 1) as f64 * x * p[m] - m as f64 * p[m - 1]) / (m + 1) as f64;
        }
        p
    };
    let py = legendre(y);
    let mut out = [0.0; GAP_NODES];
    for (i, (z, w)) in rule.nodes.iter().zip(&rule.weights).enumerate() {
        let pz = legendre(*z);
        let mut s = y + 1.0;
        for m in 1..GAP_NODES {
            s += pz[m] * (py[m + 1] - py[m - 1]);
        }
        out[i] = 0.5 * w * s;
    }
    out
}

fn gap_rule() -> &'static GapRule {
    static RULE: std::sync::OnceLock<GapRule> = std::sync::OnceLock::new();
    RULE.get_or_init(|| {
        let rule = gauss_jacobi(GAP_NODES, 0.0, 0.0).expect("Gauss-Legendre rule of the gap panels");
        let mut partial = std::collections::BTreeMap::new();
        for &(a, b) in &GAP_PANELS {
            let w = b - a;
            partial.entry(w).or_insert_with(|| {
                (1..=w)
                    .map(|k| {
                        if k == w {
                            let mut last = [0.0; GAP_NODES];
                            last.copy_from_slice(&rule.weights);
                            last
                        } else {
                            partial_integrals(&rule, -1.0 + 2.0 * k as f64 / w as f64)
                        }
                    })
                    .collect()
            });
        }
        GapRule { rule, partial }
    })
}

/// Criterion 3 on one side: samples (x, h) of the gap from the end at x - c = `start` over
/// `reach` in direction `dir` (+1 leading, -1 trailing), at x - c = start + dir R s^4,
/// s = j/32 (j = 1..=32):
///     h(x) = g_row(x) - g_row(end) - int_end^x w,
/// w the surface slope ([`ContactFunctions::surface_slope`], smooth off the contact) integrated
/// in s (dx/ds = 4 R s^3, so w ~ d^(1/2 -+ theta) next to the end becomes s^(5 -+ 4 theta) or
/// smoother) by 16-point Gauss–Legendre on the 4 dyadic panels [`GAP_PANELS`] (64 slopes per
/// side, where 32 panels of 6 points took 192), the integral up to a sample inside a panel by
/// the node values' interpolant ([`GapRule`]); the profile's own height taken exactly (so its
/// steps at the cell edges and a slope singular at the edge of a circle need no quadrature).
///
/// Each sample carries a bound of its rounding, [`GAP_ROUNDING`] (|rise| + |int w|): next to a
/// contact far off the origin both terms are far larger than the gap they difference.
fn gap_side(f: &impl ContactFunctions, c: f64, start: f64, reach: f64, dir: f64) -> Vec<GapSample> {
    let gr = gap_rule();
    let end = c + start;
    let mut w_int = 0.0;
    let mut out = Vec::with_capacity(GAP_SAMPLES);
    let (mut xis, mut vals) = ([0.0; GAP_NODES], [0.0; GAP_NODES]);
    for &(a, b) in &GAP_PANELS {
        let (s0, s1) = (a as f64 / GAP_SAMPLES as f64, b as f64 / GAP_SAMPLES as f64);
        let half = 0.5 * (s1 - s0);
        let ss = gr.rule.nodes.iter().map(|z| 0.5 * (s0 + s1) + half * z);
        // x - c = start + dir R s^4, dx/ds = 4 R s^3 (times dir).
        for (xi, s) in xis.iter_mut().zip(ss.clone()) {
            *xi = start + dir * reach * s.powi(4);
        }
        f.surface_slopes(&xis, &mut vals);
        for (v, s) in vals.iter_mut().zip(ss) {
            *v = *v * 4.0 * reach * s.powi(3);
        }
        let rows = &gr.partial[&(b - a)];
        // Each row's dot product with the node values, summed in node order from -0.0 as
        // `Iterator::sum` does, the rows side by side (node loop outside) so that the sums do
        // not wait for each other.
        let mut incs = [-0.0; GAP_SAMPLES];
        let incs = &mut incs[..rows.len()];
        for (k, v) in vals.iter().enumerate() {
            for (inc, row) in incs.iter_mut().zip(rows) {
                *inc += row[k] * v;
            }
        }
        for (k, inc) in incs.iter().enumerate() {
            // int_end^x w = dir int |dx| w.
            let dx = dir * reach * ((a + k + 1) as f64 / GAP_SAMPLES as f64).powi(4);
            let (rise, int) = (f.profile_rise(end, dx), w_int + dir * inc * half);
            let rounding = GAP_ROUNDING * (rise.abs() + int.abs());
            out.push(GapSample { x: end + dx, h: rise - int, rounding });
        }
        w_int += dir * half * incs.last().copied().unwrap_or(0.0);
    }
    out
}

/// Applies the criterion (module doc) to a contact. `Ok` carries what is reported beside an
/// admissible contact; `Err` the first reason to refuse it.
pub fn assess(f: &impl ContactFunctions, setting: &Setting) -> Result<Assessment, Refusal> {
    let (l, c) = (setting.l(), setting.c());
    // 1. The cell.
    match setting.cell {
        Cell::Fixed { half_period } if setting.a >= half_period || setting.b >= half_period => {
            return Err(Refusal::OutsideCell { neg_a: -setting.a, b: setting.b, half_period });
        }
        Cell::Periodic { period } if 2.0 * l >= period => {
            return Err(Refusal::OutsideCell { neg_a: -setting.a, b: setting.b, half_period: 0.5 * period });
        }
        _ => {}
    }
    // 2. p >= 0.
    static US: std::sync::OnceLock<Vec<f64>> = std::sync::OnceLock::new();
    let us = US.get_or_init(pressure_points);
    let vals = f.pressure_factors(us);
    let max_pressure_factor = vals.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    if let Some((u, v)) = us.iter().zip(&vals).find(|(_, v)| **v < -setting.pressure_tol * max_pressure_factor) {
        return Err(Refusal::NegativePressure { u: *u, relative: v / max_pressure_factor });
    }
    // 3. The gap, from each end to the middle of the free arc.
    let reach = match setting.period() {
        Some(big_l) => 0.5 * big_l - l,
        None => 4.0 * l,
    };
    // Where the profile ends (a narrow circle), the gap stops: no punch beyond.
    let (reach_lead, reach_trail) = match setting.extent {
        Some(r) => (reach.min(r - setting.b), reach.min(r - setting.a)),
        None => (reach, reach),
    };
    let lead = gap_side(f, c, l, reach_lead, 1.0);
    let trail = gap_side(f, c, -l, reach_trail, -1.0);
    // +infinity is a gap where no punch is (beyond a circle's wall); NaN a failed evaluation.
    if let Some(v) = lead.iter().chain(&trail).find(|v| v.h.is_nan() || v.h == f64::NEG_INFINITY) {
        return Err(Refusal::NonFinite { x: v.x });
    }
    let hmax = lead
        .iter()
        .chain(&trail)
        .filter(|v| v.h.is_finite())
        .fold(0.0f64, |m, v| m.max(v.h.abs()))
        .max(f64::MIN_POSITIVE);
    // The closure: with the criterion's slope (step left out) the halves differ by
    // M + edge_step (L - 2 l) (the step integrates to edge_step over the arc's length).
    let spans = reach_lead == reach && reach_trail == reach;
    let closure_defect = match setting.period() {
        Some(_) if spans => {
            let measured = lead.last().map_or(0.0, |v| v.h) - trail.last().map_or(0.0, |v| v.h);
            let defect = measured - setting.edge_step * 2.0 * reach;
            let expected =
                if setting.convention == Convention::PeriodicSurface { 0.0 } else { setting.closure_formula };
            if (defect - expected).abs() > setting.closure_tol * (hmax + expected.abs()) {
                return Err(Refusal::Inconsistent { measured: defect, expected });
            }
            Some(defect)
        }
        _ => None,
    };
    // The most negative gap (where it is reported), and the most negative beyond its rounding
    // ([`GAP_ROUNDING`]) and the tolerance of the quadrature ([`GAP_TOL`] of the largest gap).
    let mut worst = (0.0f64, c + l, End::Leading);
    let mut beyond: Option<(GapSample, End)> = None;
    for (side, end) in [(&lead, End::Leading), (&trail, End::Trailing)] {
        for v in side.iter() {
            if v.h < worst.0 {
                worst = (v.h, v.x, end);
            }
            if v.h + v.rounding < -GAP_TOL * hmax && beyond.is_none_or(|(b, _)| v.h + v.rounding < b.h + b.rounding) {
                beyond = Some((*v, end));
            }
        }
    }
    let negative = beyond.is_some();
    if let Some((v, end)) = beyond {
        worst = (v.h, v.x, end);
    }
    let mut warning = None;
    if negative {
        if setting.closes() {
            return Err(Refusal::NegativeGap { h: worst.0, x: worst.1, from: worst.2 });
        }
        warning = Some(format!(
            "{}; in the paper's convention the surface does not close over a period (closure defect M = {}), so the gap is \
             defined only up to that defect: not refused (the `periodic` convention closes it)",
            Refusal::NegativeGap { h: worst.0, x: worst.1, from: worst.2 }.why(),
            readable_f64(closure_defect.unwrap_or(setting.closure_formula))
        ));
    }
    Ok(Assessment {
        max_pressure_factor,
        min_gap: if negative { worst.0 } else { 0.0 },
        min_gap_x: worst.1,
        closure_defect,
        edge_step: setting.edge_step,
        warning,
    })
}

/// The refusal of a method that returns no contact, in one wording for every method: `reasons`
/// are why each contact the equations gave was refused (empty: the equations gave none, i.e. no
/// contact carries the load: "no solution"); `ranges` is the admissible range in words
/// ([`admissible::Admissible::loads_text`] or [`admissible::Admissible::sizes_text`]).
pub fn refusal(load: &SlidingLoad, reasons: &[String], ranges: &str) -> Error {
    let (name, value) = match load {
        SlidingLoad::NormalLoad(v) => ("normal_load", readable(v)),
        SlidingLoad::HalfLength(v) => ("half_length", readable(v)),
    };
    if reasons.is_empty() {
        let what = match load {
            SlidingLoad::NormalLoad(_) => format!("no contact carries {name} = {value} at these parameters"),
            SlidingLoad::HalfLength(_) => {
                format!("no centre of a contact with {name} = {value} gives a positive load at these parameters")
            }
        };
        return Error::NoSolution { why: format!("{what}; {ranges}") };
    }
    let (subject, verb) = if reasons.len() == 1 { ("the contact", "is") } else { ("the contacts", "are") };
    Error::NotPhysical {
        why: format!("{subject} with {name} = {value} {verb} not physical ({}); {ranges}", reasons.join("; ")),
    }
}

/// What the physics allows at large loads, where a closed form knows it (kappa = tau0 = 0, the
/// frictionless equation, docs/theory.md section 6): the sinusoid carries at most the full-contact
/// load pi E* D (Westergaard [2.17], P2 = pi E* D sin^2 lambda -> pi E* D as lambda -> pi/2); the
/// parabola carries every load (Kuznetsov [2.15], cos lambda = exp(-Lambda^2/2): the centred contact
/// approaches full contact as P2 -> infinity). None elsewhere (friction, wear, adhesive shear,
/// other profiles): there the admissible range comes only from a method's scan.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LoadLimit {
    /// Full contact carries this load (in the problem's units): every load below it has a contact.
    FullContact(f64),
    /// Every load has a contact.
    Unbounded,
}

impl LoadLimit {
    /// The limit of `problem`, if a closed form gives it.
    pub fn of(problem: &SlidingProblem) -> Option<LoadLimit> {
        if !problem.kappa_and_tau0_vanish() || !matches!(problem.period(), Period::Finite(_)) {
            return None;
        }
        match problem.shape() {
            PunchShape::Sinusoidal { amplitude } => {
                let e_d = crate::numerics::exact::to_f64(&(problem.material().contact_modulus() * amplitude))?;
                Some(LoadLimit::FullContact(std::f64::consts::PI * e_d))
            }
            PunchShape::Parabolic { .. } => Some(LoadLimit::Unbounded),
            _ => None,
        }
    }

    /// The limit in words.
    pub fn text(self) -> String {
        match self {
            LoadLimit::FullContact(v) => format!(
                "physically every load below full contact has a contact: full contact (lambda -> pi/2) carries \
                 P2 = pi E* D = {} (Westergaard [2.17])",
                readable_f64(v)
            ),
            LoadLimit::Unbounded => "physically every load has a contact: it approaches full contact (lambda -> pi/2) \
                                     as P2 grows without bound (Kuznetsov [2.15])"
                .into(),
        }
    }
}

/// The refusal of a method that found no contact for a given load, knowing its admissible scan
/// `adm` (loads in units of `unit`): [`refusal`] when the scan settles the question (the load lies
/// outside every physical run, and no run reaches the scan's end), "no solution" naming the
/// closed-form limit of [`LoadLimit`] when the load is above it; otherwise the load may be carried
/// by a contact beyond this method's reach, and the refusal says so (`NoConvergence`), with the end
/// of the scan (as the contact fraction 2l/L = 2 lambda/pi) and the physical limit where one is
/// known. A search limit is never presented as physics.
pub fn refusal_in_reach(
    problem: &SlidingProblem,
    adm: &admissible::Admissible,
    unit: f64,
    reasons: &[String],
    ranges: &str,
) -> Error {
    let (SlidingLoad::NormalLoad(v), Period::Finite(_)) = (problem.load(), problem.period()) else {
        return refusal(problem.load(), reasons, ranges);
    };
    let (Some(load), Some(last)) = (crate::numerics::exact::to_f64(v), adm.runs.last()) else {
        return refusal(problem.load(), reasons, ranges);
    };
    let limit = LoadLimit::of(problem);
    // The full-contact load, when the load is at or above it: compared exactly (issue 34: a load
    // given to 20 digits just below pi E* D was refused as above it by an f64 comparison).
    let exceeded = match (limit, problem.shape()) {
        (Some(LoadLimit::FullContact(m)), PunchShape::Sinusoidal { amplitude }) => {
            let e_d = problem.material().contact_modulus() * amplitude;
            (crate::numerics::exact::cmp_pi_times(v, &e_d) != std::cmp::Ordering::Less).then_some(m)
        }
        _ => None,
    };
    if let (Some(m), true) = (exceeded, reasons.is_empty()) {
        return Error::NoSolution {
            why: format!(
                "no contact carries normal_load = {}: it exceeds the full-contact load pi E* D = {} (Westergaard \
                 [2.17]), the most the sinusoid carries; {ranges}",
                readable(v),
                readable_f64(m)
            ),
        };
    }
    if !reasons.is_empty() || !last.open_above || exceeded.is_some() || load <= last.load_hi.0 * unit {
        return refusal(problem.load(), reasons, ranges);
    }
    let physics = match limit {
        Some(l) => l.text(),
        None => "the physical limit beyond the scan is not known in closed form at these parameters".into(),
    };
    Error::NoConvergence {
        what: format!(
            "normal_load = {} needs a contact beyond this method's reach: its scan ends at contact fraction 2l/L = {} \
             carrying {} (the node count needed grows without bound as the contact fills the period); {physics}; {ranges}",
            readable(v),
            readable_f64(2.0 * last.size_hi / std::f64::consts::PI),
            readable_f64(last.load_hi.0 * unit)
        ),
    }
}

#[cfg(test)]
mod tests;
