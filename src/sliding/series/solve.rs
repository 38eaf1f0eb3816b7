//! The series method's solution of Problem 1: the truncated exact series (docs/theory.md section 5,
//! [3.7]-[3.12]) evaluated in MPFR at a problem's parameters, with an estimated (not verified)
//! accuracy per quantity ([`super::estimate`]).

use super::estimate::{rate, tail, terms};
use super::partial::{partial, Partial};
use super::point::SeriesPoint;
use crate::asymptotics::sliding::{sliding_expansion_with, SlidingExpansion, SlidingShape};
use crate::error::Error;
use crate::model::OnPunchRow;
use crate::model::{Exact, PunchShape, SlidingProblem};
use crate::numerics::accuracy::{readable_f64, readable_mpfr, verified_digits_mpfr};
use crate::numerics::exact::to_float;
use crate::numerics::precision::precision_for;
use crate::params::sliding::SlidingParamsMpfr;
use crate::sliding::physicality::Assessment;
use crate::sliding::reduction_mpfr::{physicality_at_contact, refusal_for};
use crate::sliding::PressurePoint;
use rug::Float;

/// Estimated digits per quantity (relative to each quantity's scale, module doc of
/// [`super::estimate`]).
#[derive(Debug, Clone, PartialEq)]
pub struct SeriesAccuracy {
    /// lambda, l, a, b, c and the points x (scale l): from E_l + E_c.
    pub contact: f64,
    /// l alone (scale l): from E_l. P1 = mu P2 + 2 l tau0 carries l's relative error only, not
    /// c's (issue 34, fuzz case 5496: c = rbar l with |rbar| = 1.4e9 left 3.8 digits of l in c
    /// while l itself held 13).
    pub length: f64,
    /// F_def (scale k l P2).
    pub f_def: f64,
    /// p at the requested points (scale: the largest of them); `None` without points.
    pub pressure: Option<f64>,
    /// The smallest of the above: the method's `digits_estimated`.
    pub headline: f64,
    /// The rate rho of the terms per power of Lambda^2 read from l.
    pub rate: f64,
}

/// The series method's solution of Problem 1 (the quantities of the MPFR method's
/// [`crate::sliding::SlidingSolution`], in the units of the problem).
#[derive(Debug, Clone)]
pub struct SeriesSolution {
    /// theta = arctan(kappa)/pi.
    pub theta: Float,
    /// kappa = E* cW/2 - beta mu [2.8].
    pub kappa: Float,
    /// Lambda = pi l_s/L, the expansion variable [3.10].
    pub big_lambda: Float,
    /// lambda = pi l/L [2.1].
    pub lambda: Float,
    /// Half-length l.
    pub l: Float,
    /// Trailing end a = l - c: the contact is [-a, b].
    pub a: Float,
    /// Leading end b = l + c.
    pub b: Float,
    /// Centre c.
    pub c: Float,
    /// P1 = mu P2 + 2 l tau0.
    pub p1: Float,
    /// P2 (given).
    pub p2: Float,
    /// Curvature k (osculating k = 2 pi^2 D/L^2 for the sinusoid [2.16]).
    pub k: Float,
    /// F_def = int p g' dx.
    pub f_def: Float,
    /// Mean wear depth per sliding distance cW P2/L.
    pub wear_per_distance: Float,
    /// Mean wear rate cW V P2/L when the speed V is given.
    pub wear_rate: Option<Float>,
    /// Worn area (volume per unit width) per unit sliding distance, cW P2, for each punch.
    pub worn_area_per_distance: Float,
    /// p at the requested points.
    pub pressure: Vec<PressurePoint>,
    /// The largest p at the requested points (0 without points): the scale of p.
    pub max_pressure: Float,
    /// Truncation order N (every term through Lambda^N).
    pub order: usize,
    /// Working precision in bits.
    pub prec: u32,
    /// Estimated digits per quantity.
    pub accuracy: SeriesAccuracy,
    /// The shared physicality criterion at the series' contact ([`crate::sliding::physicality`]).
    pub physicality: Assessment,
}

/// The expansion shape of a punch. The series method knows the parabola and the sinusoid; a
/// polynomial or circular punch is refused (input error naming `punch.shape`): its exact series
/// belongs to `asymptotics` (issue 11), and the MPFR and f64 methods solve it.
pub fn expansion_shape(problem: &SlidingProblem) -> Result<SlidingShape, Error> {
    match problem.shape() {
        PunchShape::Parabolic { .. } => Ok(SlidingShape::Parabolic),
        PunchShape::Sinusoidal { .. } => Ok(SlidingShape::Sinusoidal),
        other => Err(Error::input(
            "punch.shape",
            other.name(),
            "the series method solves \"parabolic\" and \"sinusoidal\" punches; use --method mpfr or f64",
        )),
    }
}

/// Solves `problem` by its series through Lambda^order at the points xh = `points`, at the
/// precision for `digits` digits (derives the expansion; see [`solve_series_with`]).
pub fn solve_series(
    problem: &SlidingProblem,
    points: &[Exact],
    order: usize,
    digits: u32,
) -> Result<SeriesSolution, Error> {
    check_order(order, SERIES_ORDER)?;
    solve_series_with(&derive_expansion(problem, order)?, problem, points, order, digits)
}

/// What the series method says of an order below 2.
const SERIES_ORDER: &str = "the series method needs an order >= 2 (it estimates its error from the terms it keeps)";

/// Refuses an order below 2 (`--order`), saying `expected` (the series and pade methods).
pub(super) fn check_order(order: usize, expected: &str) -> Result<(), Error> {
    if order < 2 {
        return Err(Error::input("--order", order, expected));
    }
    Ok(())
}

/// The preconditions of a solve from a derived expansion `e` (the series and the pade method):
/// an order >= 2 (else an input error saying `expected`), and `e` of the problem's shape and
/// convention through at least Lambda^order.
///
/// # Panics
/// When `e` has another shape or convention than the problem or is shorter than `order`.
pub(super) fn check_expansion(
    e: &SlidingExpansion,
    problem: &SlidingProblem,
    order: usize,
    expected: &str,
) -> Result<(), Error> {
    check_order(order, expected)?;
    assert_eq!(e.shape, expansion_shape(problem)?, "the expansion is of another shape");
    assert_eq!(e.convention, problem.convention(), "the expansion is of another convention");
    assert!(e.l_over_ls.prec() > order, "the expansion is shorter than Lambda^{order}");
    Ok(())
}

/// The problem's expansion through Lambda^order (its shape and convention); an engine failure is
/// no convergence.
pub(super) fn derive_expansion(problem: &SlidingProblem, order: usize) -> Result<SlidingExpansion, Error> {
    sliding_expansion_with(expansion_shape(problem)?, order, problem.convention())
        .map_err(|err| Error::NoConvergence { what: format!("the series through Lambda^{order}: {err}") })
}

/// [`solve_series`] with an expansion already derived (of the problem's shape and convention,
/// through at least Lambda^order;
/// a longer one is truncated). Errors: input (a single punch, a given half-length,
/// order < 2); no convergence when the terms of l/l_s do not decrease or the estimate leaves
/// less than one digit (module doc of [`super::estimate`]).
///
/// # Panics
/// When `e` has another shape or convention than the problem or is shorter than `order`.
pub fn solve_series_with(
    e: &SlidingExpansion,
    problem: &SlidingProblem,
    points: &[Exact],
    order: usize,
    digits: u32,
) -> Result<SeriesSolution, Error> {
    check_expansion(e, problem, order, SERIES_ORDER)?;
    let prec = precision_for(digits);
    let params = SlidingParamsMpfr::new(problem, prec)?;
    let sp = SeriesPoint::new(&params)?;
    let xh: Vec<Float> = points.iter().map(|x| to_float(x, prec)).collect();
    // Values through Lambda^(N - 2K), ..., Lambda^(N - 2), Lambda^N, K = N/2 (units of E*): in steps
    // of Lambda^2 in both conventions. In `periodic` each step adds the pair of terms Lambda^(n-1),
    // Lambda^n (module doc of [`super::estimate`]): the parabola's l/l_s has no odd terms there,
    // so single steps would read a rate from zero terms.
    let parts: Vec<Partial> = (0..=order / 2).map(|m| partial(e, order - 2 * (order / 2 - m), &sp, &xh)).collect();
    let hi = parts.last().expect("order >= 2");
    let of = |f: &dyn Fn(&Partial) -> Float| terms(&parts.iter().map(f).collect::<Vec<_>>());
    let t_l = of(&|v| v.l.clone());
    let rho = rate(&t_l);
    if rho >= 1.0 || rho.is_nan() {
        return Err(Error::NoConvergence {
            what: format!(
                "the terms of the series of l/l_s do not decrease at Lambda = pi l_s/L = {} (ratio of the last terms {}): \
                 the contact is too large for the series through Lambda^{order}; use --method mpfr",
                readable_mpfr(&sp.big_lambda),
                readable_f64(rho)
            ),
        });
    }
    // One digit above the request: the evaluation at precision_for(digits) bits sees more, and a
    // cap of exactly the request would leave the printed text (its rounding) below it (issue 34).
    let cap = digits as f64 + 1.0;
    let err_l = tail(&t_l, rho);
    let length = verified_digits_mpfr(&err_l, &hi.l, cap);
    let contact = verified_digits_mpfr(&(err_l + tail(&of(&|v| v.c.clone()), rho)), &hi.l, cap);
    let kl_p2 = Float::with_val(prec, &sp.k * &hi.l) * &sp.p2;
    let f_def = verified_digits_mpfr(&tail(&of(&|v| v.f_def.clone()), rho), &kl_p2, cap);
    let max_p = hi.pressure.iter().fold(Float::with_val(prec, 0), |m, x| if *x > m { x.clone() } else { m });
    let pressure = (!xh.is_empty()).then(|| {
        (0..xh.len())
            .map(|i| verified_digits_mpfr(&tail(&of(&|v| v.pressure[i].clone()), rho), &max_p, cap))
            .fold(f64::INFINITY, f64::min)
    });
    let headline = contact.min(f_def).min(pressure.unwrap_or(f64::INFINITY));
    if headline < 1.0 {
        return Err(Error::NoConvergence {
            what: format!(
                "the series through Lambda^{order} at Lambda = pi l_s/L = {} leaves {} estimated digits (< 1): \
                 the contact is too large for the series at this order; raise --order or use --method mpfr",
                readable_mpfr(&sp.big_lambda),
                readable_f64((headline * 10.0).floor() / 10.0)
            ),
        });
    }
    let accuracy = SeriesAccuracy { contact, length, f_def, pressure, headline, rate: rho };
    let mut s = solution(&params, &sp, hi, &xh, max_p, order, accuracy);
    assess_physicality(problem, &mut s, prec, "the series' contact")?;
    Ok(s)
}

/// The shared physicality criterion at the contact of `s` (pressure [2.13] and gap there, with
/// the contact's estimated relative error), stored in `s`; a contact that is not physical is
/// refused as `whose` contact (the series' or the Pade one) at its lambda.
pub(super) fn assess_physicality(
    problem: &SlidingProblem,
    s: &mut SeriesSolution,
    prec: u32,
    whose: &str,
) -> Result<(), Error> {
    let rel_error = 10f64.powf(-s.accuracy.contact);
    match physicality_at_contact(problem, (&s.l, &s.c), &s.p2, rel_error, prec)? {
        Ok(a) => s.physicality = a,
        Err(r) if r.is_physical() => {
            let reason = format!("{whose} at lambda = {}: {}", readable_mpfr(&s.lambda), r.why());
            return Err(refusal_for(problem, &[reason]));
        }
        Err(r) => return Err(Error::NoConvergence { what: r.why() }),
    }
    Ok(())
}

/// The solution in the units of the problem from the values through Lambda^order (or their Pade
/// values, [`super::pade`]).
pub(super) fn solution(
    params: &SlidingParamsMpfr,
    sp: &SeriesPoint,
    hi: &Partial,
    xh: &[Float],
    max_p: Float,
    order: usize,
    accuracy: SeriesAccuracy,
) -> SeriesSolution {
    let prec = sp.prec;
    let unit = &params.unit;
    let p2 = Float::with_val(prec, &sp.p2 * unit);
    let lambda = Float::with_val(prec, &params.pi * &hi.l) / &sp.period;
    let a = Float::with_val(prec, &hi.l - &hi.c);
    let b = Float::with_val(prec, &hi.l + &hi.c);
    // P1 = mu P2 + 2 l tau0 (tau0 in units of E*: times E*).
    let p1 = Float::with_val(prec, &params.mu * &p2)
        + Float::with_val(prec, 2 * hi.l.clone()) * Float::with_val(prec, &params.tau0 * unit);
    // cW P2/L = (cW E*)(P2/E*)/L.
    let worn = Float::with_val(prec, &params.wear * &sp.p2);
    let wear = Float::with_val(prec, &worn / &sp.period);
    let wear_rate = params.speed.as_ref().map(|v| Float::with_val(prec, &wear * v));
    let pressure = xh
        .iter()
        .zip(&hi.pressure)
        .map(|(x, p)| PressurePoint {
            xh: x.clone(),
            x: Float::with_val(prec, &hi.c + Float::with_val(prec, &hi.l * x)),
            p: Float::with_val(prec, p * unit),
        })
        .collect();
    SeriesSolution {
        theta: sp.theta.clone(),
        kappa: params.kappa.clone(),
        big_lambda: sp.big_lambda.clone(),
        lambda,
        l: hi.l.clone(),
        a,
        b,
        c: hi.c.clone(),
        p1,
        p2,
        k: sp.k.clone(),
        f_def: Float::with_val(prec, &hi.f_def * unit),
        wear_per_distance: wear,
        wear_rate,
        worn_area_per_distance: worn,
        pressure,
        max_pressure: Float::with_val(prec, &max_p * unit),
        order,
        prec,
        accuracy,
        physicality: Assessment::default(),
    }
}
