//! The sizes the analytic method reaches (issue 31): whether the series history fixes C, and the
//! largest lambda at which the method holds the digits asked, at any nu (docs/theory.md section 11).
//!
//! The history (the series up to eta0) fixes the member only while the homogeneous mode's growth
//! from eta0 to lambda, G = (1/ln 10) int_eta0^lambda (d ln H/d ln eta) d eta/eta by the frozen
//! symbol ([`frozen_growth`]), stays representable: up to a cap (the method's `GROWTH_CAP`, 150
//! decades; nu = 0: G = 103 from 0.45 to 1.2, measured A = 10^104, 34.9 digits). Beyond it
//! (nu = 3/10: G = 2.3e5 from 0.45 to 1.35, and still about 4e4 from eta = pi/4, where the
//! series in t = tan eta stops converging) the history does not fix C, and two runs agree to no
//! more than the digits the mode leaves until full contact, R(lambda) (docs/theory.md section 11),
//! as with the verified MPFR method. Measured at nu = 3/10 (runs of 75-240 nodes, 200-500 bits,
//! eta0 = 0.42, 0.45, 0.6): 37-44 digits at lambda = 1.3 (R = 50.5; there the 100-node runs'
//! Chebyshev tail, 1e-43, limits), 12.7-15 at 1.35 (R = 14.1), 2.6-3.3 at 1.4 (R = 3.3), none at
//! 1.5 (R = 0), whatever the nodes, bits and eta0. So the method holds d digits up to
//! max(lambda_p, lambda_h(nu, d)), lambda_p the size where G from the method's eta0 reaches the
//! cap ([`reach`]; lambda_h(nu, d) claims R - 2 = d). Tests (tests/all/adhesion_analytic.rs):
//! `the_reach_at_three_ratios`, `at_nu_0_3_its_reach_holds_twenty_digits`,
//! `at_nu_0_3_lambda_1_5_the_refusal_names_its_reach`.

use crate::asymptotics::adhesion_mode::{frozen_growth, horizon, horizon_text, GROWTH_STEP};
use crate::model::Material;
use crate::params::adhesion::AdhesionParamsF64;

/// Where the method holds a number of digits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reach {
    /// lambda_p: the size up to which the history fixes C (G from `eta0` <= `cap`); pi/2 where G
    /// stays below the cap up to full contact (nu = 0: G = 103 at most).
    pub pinned_to: f64,
    /// lambda_h(nu, digits) ([`horizon`]): the size up to which the mode leaves the digits anyway.
    pub lambda_h: f64,
    /// The end of the series history.
    pub eta0: f64,
    /// The largest growth (decades) the history still fixes C through.
    pub cap: f64,
}

impl Reach {
    /// The largest lambda at which the method holds the digits: max(lambda_p, lambda_h).
    pub fn lambda(&self) -> f64 {
        self.pinned_to.max(self.lambda_h)
    }

    /// "up to lambda = 1.333 (lambda_h ...)" as the refusals print it, rounded down.
    pub fn text(&self) -> String {
        let top = std::f64::consts::FRAC_PI_2;
        if self.pinned_to >= top {
            format!(
                "up to lambda -> pi/2 as far as the mode goes (its growth from eta0 = {} stays below \
                 10^{:.0}; measured up to lambda = 1.2 at nu = 0)",
                self.eta0, self.cap
            )
        } else if self.pinned_to > self.lambda_h {
            format!(
                "up to lambda = {} (where the mode's growth from eta0 = {} reaches 10^{:.0})",
                horizon_text(self.pinned_to),
                self.eta0,
                self.cap
            )
        } else {
            format!(
                "up to lambda = {} (lambda_h; the series history fixes C only up to lambda = {}, where the mode's \
                 growth from eta0 = {} reaches 10^{:.0})",
                horizon_text(self.lambda_h),
                horizon_text(self.pinned_to),
                self.eta0,
                self.cap
            )
        }
    }
}

/// Decades of the mode's frozen-symbol growth from `from` to `to` (trapezoid in eta, step
/// [`GROWTH_STEP`]), stopping once they exceed `stop`; 0 at eps = 0 (nu = 1/2).
pub fn history_growth(eps: f64, b: f64, s: f64, from: f64, to: f64, stop: f64) -> f64 {
    if eps <= 0.0 || to <= from {
        return 0.0;
    }
    let (mut r, mut lo, mut g_lo) = (0.0, from, frozen_growth(eps, b, s, from) / from);
    while lo < to && r / std::f64::consts::LN_10 <= stop {
        let hi = (lo + GROWTH_STEP).min(to);
        let g_hi = frozen_growth(eps, b, s, hi) / hi;
        r += 0.5 * (hi - lo) * (g_lo + g_hi);
        (lo, g_lo) = (hi, g_hi);
    }
    r / std::f64::consts::LN_10
}

/// lambda_p: the grid size (step [`GROWTH_STEP`] from `eta0`) before the growth from eta0 first
/// exceeds `cap` decades; pi/2 if it never does.
fn pinned_to(eps: f64, b: f64, s: f64, eta0: f64, cap: f64) -> f64 {
    let top = std::f64::consts::FRAC_PI_2;
    if eps <= 0.0 {
        return top;
    }
    let cap = cap * std::f64::consts::LN_10;
    let (mut r, mut lo, mut g_lo) = (0.0, eta0, frozen_growth(eps, b, s, eta0) / eta0);
    while lo < top {
        let hi = (lo + GROWTH_STEP).min(top);
        let g_hi = frozen_growth(eps, b, s, hi) / hi;
        r += 0.5 * (hi - lo) * (g_lo + g_hi);
        if r > cap {
            return lo;
        }
        (lo, g_lo) = (hi, g_hi);
    }
    top
}

/// Where the analytic method, its history ending at `eta0` and fixing C through at most `cap`
/// decades of growth, holds `digits` for `material` (module doc).
pub fn reach(material: &Material, digits: f64, eta0: f64, cap: f64) -> Reach {
    let c = AdhesionParamsF64::new(material);
    Reach { pinned_to: pinned_to(c.eps, c.b, c.s, eta0, cap), lambda_h: horizon(c.eps, c.b, c.s, digits), eta0, cap }
}
