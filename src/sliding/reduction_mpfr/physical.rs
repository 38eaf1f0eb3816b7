//! The MPFR method's side of the shared physicality criterion ([`crate::sliding::physicality`]):
//! p/omega = cos^2(pi theta) D(u)/pi from [2.13] ([`super::pressure::Pressure::p_over_omega`]) and
//! the gap slope off the contact from the continuation of the same Psi
//! ([`super::pressure::Pressure::gap_slope`], which leaves the adhesive shear's edge step out and
//! contains K of the `periodic` convention by construction). Both are evaluated at working
//! precision at the criterion's points and handed over rounded to f64 (the criterion's decisions
//! and its gap quadrature are in f64; the gap is a check, not an output).
//!
//! Conventions (derivations in docs/theory.md section 8 and the module [`super`]): with the paper's
//! symmetric summation [1.6]-[1.8] and the wear law v' = g' - cW p the surface is not periodic:
//! the full gap slope integrated over the free arc leaves M = (2/E*) beta P1 - cW P2; adding
//! K = (kappa P2 - 2 beta l tau0)/L to [2.8] (`periodic`) closes it. Removing M as a uniform slope
//! instead was tried and rejected: any uniform slope makes h < 0 next to one end, where
//! h ~ (x - b)^{3/2 - theta}.

use super::contact::Contact;
use super::pressure::Pressure;
use super::profile::row_slope;
use crate::model::Convention;
use crate::params::sliding::{row_height_f64, row_rise_f64, ShapeF64, ShapeMpfr, SlidingParamsMpfr};
use crate::sliding::physicality::{
    assess, pressure_points, Assessment, Cell, ContactFunctions, Refusal, Setting, CLOSURE_TOL,
};
use rug::Float;

/// The MPFR solution seen by the criterion (in units of E*; lengths unchanged).
struct Functions<'a, 'b> {
    params: &'a SlidingParamsMpfr,
    contact: &'a Contact,
    pressure: &'a Pressure<'b>,
    shape: ShapeF64,
    period: Option<f64>,
}

impl ContactFunctions for Functions<'_, '_> {
    fn pressure_factor(&self, u: f64) -> f64 {
        self.pressure.p_over_omega(&Float::with_val(self.params.prec, u)).to_f64()
    }
    fn surface_slope(&self, xi: f64) -> f64 {
        let p = self.params.prec;
        let xi = Float::with_val(p, xi);
        let x = Float::with_val(p, &xi + &self.contact.c);
        // w = g'_row - h', formed at working precision (both are large next to a circle's wall).
        Float::with_val(p, row_slope(self.params, &x, p) - self.pressure.gap_slope(&xi)).to_f64()
    }
    fn profile_height(&self, x: f64) -> f64 {
        row_height_f64(&self.shape, self.period, x)
    }
    fn profile_rise(&self, end: f64, dx: f64) -> f64 {
        row_rise_f64(&self.shape, self.period, end, dx)
    }
}

/// Relative accuracy of p/omega the pressure test allows for: half the working precision, at
/// most 60 bits (the locating stage works at 64).
fn pressure_tol(prec: u32) -> f64 {
    2f64.powi(-((prec as i32) / 2).min(60))
}

/// The criterion's data for a contact with loads `p1`, `p2` (units of E*).
fn setting(params: &SlidingParamsMpfr, contact: &Contact, p1: &Float, p2: &Float, closure_tol: f64) -> Setting {
    let p = params.prec;
    let l = &contact.size.l;
    let a = Float::with_val(p, l - &contact.c).to_f64();
    let b = Float::with_val(p, l + &contact.c).to_f64();
    let cell = match (&params.shape, &params.period) {
        (_, None) => Cell::Unbounded,
        (ShapeMpfr::Sinusoidal { .. }, Some(big_l)) => Cell::Periodic { period: big_l.to_f64() },
        (_, Some(big_l)) => Cell::Fixed { half_period: big_l.to_f64() / 2.0 },
    };
    // M = (2/E*) beta P1 - cW P2 with E* = 1.
    let closure_formula = match (&params.period, params.convention) {
        (Some(_), Convention::Paper) => {
            (Float::with_val(p, &params.beta * p1) * 2u32 - Float::with_val(p, &params.wear * p2)).to_f64()
        }
        _ => 0.0,
    };
    Setting {
        convention: params.convention,
        cell,
        a,
        b,
        edge_step: Float::with_val(p, &params.beta * &params.tau0).to_f64() * 2.0,
        closure_formula,
        pressure_tol: pressure_tol(p),
        extent: match &params.shape {
            ShapeMpfr::Circular { r }
                if params.period.as_ref().is_none_or(|big_l| r.to_f64() < 0.5 * big_l.to_f64()) =>
            {
                Some(r.to_f64())
            }
            _ => None,
        },
        closure_tol,
    }
}

/// The shared criterion applied to a solution of the equations with loads `p1`, `p2` (units of E*).
pub fn physicality(
    params: &SlidingParamsMpfr,
    contact: &Contact,
    pressure: &Pressure<'_>,
    p1: &Float,
    p2: &Float,
) -> Result<Assessment, Refusal> {
    physicality_with(params, contact, pressure, p1, p2, CLOSURE_TOL)
}

/// [`physicality`] with the closure check's relative tolerance `closure_tol` (for a contact that
/// solves the equations only to an estimated accuracy).
pub(crate) fn physicality_with(
    params: &SlidingParamsMpfr,
    contact: &Contact,
    pressure: &Pressure<'_>,
    p1: &Float,
    p2: &Float,
    closure_tol: f64,
) -> Result<Assessment, Refusal> {
    let f = Functions {
        params,
        contact,
        pressure,
        shape: params.shape.to_f64(),
        period: params.period.as_ref().map(Float::to_f64),
    };
    assess(&f, &setting(params, contact, p1, p2, closure_tol))
}

/// The largest pressure over the criterion's pressure samples, at working precision (the scale of
/// p(x) in the answer).
pub fn max_pressure(params: &SlidingParamsMpfr, pressure: &Pressure<'_>) -> Float {
    let p = params.prec;
    let mut pmax = Float::with_val(p, 0);
    for u in pressure_points() {
        let uf = Float::with_val(p, u);
        let pv = Float::with_val(p, pressure.omega(&uf) * pressure.p_over_omega(&uf));
        if pv > pmax {
            pmax = pv;
        }
    }
    pmax
}
