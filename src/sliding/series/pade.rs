//! The Padé method of Problem 1 (docs/theory.md section 11): the same exact expansions as the
//! series method ([3.7]-[3.12], through Lambda^N), their coefficients evaluated at the problem's
//! parameters, resummed by near-diagonal Padé approximants in w = Lambda^2 (`paper`: even series)
//! or w = Lambda (`periodic`), [`crate::numerics::pade`]. Each quantity is resummed on its own:
//! l/l_s, rbar - rbar_s, F_def/(pi E* k^2 l_s^3) and the pressure bracket 1 + sum_j Lambda^(s j)
//! pi_j(xh) at each point.
//!
//! Digits (estimated, never verified): per quantity the best candidate's agreement with its
//! neighbours, propagated as the series method propagates its tails (c = rbar l: E_c = l E_rbar +
//! |rbar| E_l; p: the bracket's error times E* k l cos(pi theta) omega plus p E_l/l), and capped by
//! the agreement of a second run with [`VERIFY_EXTRA_BITS`] more bits (the coefficients are MPFR
//! numbers, rounded once; the approximant is the exact one of the rounded values); each error
//! is then taken [`ESTIMATE_SAFETY`] times larger, and P1 carries l's digits alone. The method is
//! refused (no convergence) when every candidate of a quantity is refused, naming each reason, or
//! when fewer than one digit remains.

use super::partial::Partial;
use super::point::SeriesPoint;
use super::solve::{
    assess_physicality, check_expansion, check_order, derive_expansion, solution, SeriesAccuracy, SeriesSolution,
};
use crate::asymptotics::sliding::{SlidingExpansion, SlidingShape};
use crate::error::Error;
use crate::model::{Exact, SlidingProblem};
use crate::numerics::accuracy::{readable_f64, readable_mpfr, verified_digits_mpfr};
use crate::numerics::evaluate;
use crate::numerics::exact::to_float;
use crate::numerics::pade::{complex_text, resum_conformal, resum_mpfr, Conformal, Cut, Resummation};
use crate::numerics::precision::{precision_for, VERIFY_EXTRA_BITS};
use crate::params::sliding::SlidingParamsMpfr;
use exact_series::{Poly, Series};
use rug::ops::Pow;
use rug::Float;

/// The approximant chosen for one quantity.
#[derive(Debug, Clone, PartialEq)]
pub struct Chosen {
    /// The quantity (`l_over_ls`, `rbar_minus_rbar_s`, `F_def_scaled`, `pressure_bracket(xh)`).
    pub quantity: String,
    /// [L/M].
    pub l: usize,
    /// [L/M].
    pub m: usize,
    /// Its estimated digits on the quantity's scale.
    pub digits: f64,
    /// Its poles in w (6 digits), nearest first; in z when `map` is set.
    pub poles: Vec<String>,
    /// The conformal map applied before the approximant ([`known_singularity`]), as text; `None`:
    /// Pade in w itself.
    pub map: Option<&'static str>,
}

/// The conformal map of a singularity the project knows in closed form, for the frictionless
/// (theta = 0, T = 0) expansions in w = Lambda^2 (docs/theory.md section 11): Kuznetsov's parabola,
/// l/l_s = arccos(exp(-w/2))/sqrt(w), singular where exp(-w/2) = +-1 off 0 (cuts from
/// w = +-2 pi i along the imaginary axis), and every quantity with it (each is analytic in
/// lambda(w)); the sinusoid, a/a0 = arcsin(sqrt w)/sqrt w (cut [1, inf)). `None` otherwise.
pub fn known_singularity(e: &SlidingExpansion, sp: &SeriesPoint) -> Option<(Conformal, &'static str)> {
    if e.step != 2 || !sp.theta.is_zero() || !sp.t.is_zero() {
        return None;
    }
    let prec = sp.prec;
    Some(match e.shape {
        SlidingShape::Parabolic => (
            Conformal { cut: Cut::Imaginary, radius: Float::with_val(prec, rug::float::Constant::Pi) * 2u32 },
            "z: the plane cut from w = +-2 pi i along the imaginary axis onto |z| < 1, w = 4 pi z/(1 - z^2)",
        ),
        SlidingShape::Sinusoidal => (
            Conformal { cut: Cut::Real, radius: Float::with_val(prec, 1) },
            "z: the plane cut along [1, inf) onto |z| < 1, w = 4 z/(1 + z)^2",
        ),
    })
}

/// The Padé method's solution: the quantities of the series method's solution (its `accuracy`
/// holding the Padé digits; `rate` is the ratio of the last two terms of l/l_s, for comparison)
/// and the approximants chosen.
#[derive(Debug, Clone)]
pub struct PadeSolution {
    /// The solution (as the series method's).
    pub solution: SeriesSolution,
    /// Whether the variable is w = Lambda^2 (`paper`) or Lambda (`periodic`).
    pub w_is_square: bool,
    /// The approximant chosen per quantity.
    pub chosen: Vec<Chosen>,
}

/// The coefficients of an exact expansion at the point, through Lambda^order.
fn coefficients(s: &Series<Poly>, order: usize, sp: &SeriesPoint, prec: u32) -> Vec<Float> {
    let b = sp.bindings();
    s.truncate(order + 1)
        .coeffs()
        .iter()
        .map(|c| evaluate::poly_mpfr(c, &b, prec).expect("the expansions hold only theta, T, kappa and invpi"))
        .collect()
}

/// Fewest estimated digits the Padé method answers with: the agreement of neighbouring approximants
/// estimates the error only once they converge (a heuristic; the differential fuzzer's cases,
/// docs/fuzzing.md, are its evidence).
pub const MIN_ESTIMATED_DIGITS: f64 = 3.0;

/// The factor on each approximant's neighbour difference before it is claimed as its error: the
/// difference estimates the error, it does not bound it; where the approximants converge slowly
/// (a rate near 1/2 per coefficient) the error exceeds it. Seen by the differential fuzzer (issue
/// 34, docs/fuzzing.md): F_def estimated to 3.69 digits held 3.60 (case 5436 of seed 2026, lambda =
/// 1.32, order 12: error 1.25 times the estimate); 1.8 estimated held 1.4 at lambda = 1.48 (2.5
/// times, now below [`MIN_ESTIMATED_DIGITS`]). Three, as the series method's
/// [`super::estimate::SAFETY`]: the claims are the agreement less log10 3 = 0.48 digits.
pub const ESTIMATE_SAFETY: f64 = 3.0;

/// One quantity resummed at w: its best value and digits, or the refusal naming every reason.
/// With a known singularity (`map`) the Pade approximants in z after the conformal map compete with
/// those in w, chosen by their own estimates (the larger wins; a tie keeps w).
fn resummed(
    name: &str,
    c: &[Float],
    w_is_square: bool,
    sp: &SeriesPoint,
    scale: &Float,
    cap: f64,
    map: Option<&(Conformal, &'static str)>,
) -> Result<(Float, f64, Chosen), Error> {
    let prec = sp.prec;
    let (cw, w): (Vec<Float>, Float) = if w_is_square {
        (c.iter().step_by(2).cloned().collect(), Float::with_val(prec, sp.big_lambda.clone().square()))
    } else {
        (c.to_vec(), sp.big_lambda.clone())
    };
    let r: Resummation = resum_mpfr(&cw, &w, scale, cap, prec).ok_or_else(|| Error::NoConvergence {
        what: format!("a coefficient of {name} is not finite at these parameters"),
    })?;
    let conformal = map.and_then(|(m, text)| Some((resum_conformal(&cw, m, &w, scale, cap, prec)?, *text)));
    let mapped = conformal.as_ref().and_then(|(rc, text)| Some((rc.best()?, *text)));
    // The conformal map's best approximant where it beats the plain one, else the plain one.
    let (b, map) = match mapped {
        Some((b, text)) if r.best().is_none_or(|p| b.digits > p.digits) => (b, Some(text)),
        _ => {
            let Some(b) = r.best() else {
                return Err(Error::NoConvergence {
                    what: format!(
                        "every Pade approximant of {name} at Lambda = pi l_s/L = {} is refused: {}",
                        readable_mpfr(&sp.big_lambda),
                        r.refusals().join("; ")
                    ),
                });
            };
            (b, None)
        }
    };
    let chosen = Chosen {
        quantity: name.to_string(),
        l: b.l,
        m: b.m,
        digits: b.digits,
        poles: b.poles.iter().map(complex_text).collect(),
        map,
    };
    Ok((b.value.clone(), b.digits, chosen))
}

/// The values at one precision: (partial with the Padé values, digits of l/l_s, rbar, F_def,
/// pressure brackets, chosen).
struct Run {
    partial: Partial,
    digits: SeriesAccuracy,
    chosen: Vec<Chosen>,
    w_is_square: bool,
}

fn run(
    e: &SlidingExpansion,
    problem: &SlidingProblem,
    points: &[Exact],
    order: usize,
    digits: u32,
    prec: u32,
) -> Result<(Run, SlidingParamsMpfr, SeriesPoint, Vec<Float>), Error> {
    // One digit above the request: the evaluation at precision_for(digits) bits sees more, and a
    // cap of exactly the request would leave the printed text (its rounding) below it (issue 34).
    let cap = digits as f64 + 1.0;
    let params = SlidingParamsMpfr::new(problem, prec)?;
    let sp = SeriesPoint::new(&params)?;
    let xh: Vec<Float> = points.iter().map(|x| to_float(x, prec)).collect();
    let one = Float::with_val(prec, 1);
    let l_coeffs = coefficients(&e.l_over_ls, order, &sp, prec);
    let w_is_square = e.step == 2;
    let known = known_singularity(e, &sp);
    let map = known.as_ref();
    let (l_ratio, d_l, ch_l) = resummed("l/l_s", &l_coeffs, w_is_square, &sp, &one, cap, map)?;
    let r_coeffs = coefficients(&e.rbar_minus_rbar_s, order, &sp, prec);
    let (dr, d_r, ch_r) = resummed("rbar - rbar_s", &r_coeffs, w_is_square, &sp, &one, cap, map)?;
    let l = Float::with_val(prec, &sp.l_s * &l_ratio);
    let rbar = Float::with_val(prec, 2 * sp.theta.clone() - &sp.t) + &dr;
    let c = Float::with_val(prec, &rbar * &l);
    // F_def = pi E* k^2 l_s^3 fds; its scale k l P2 in units of fds.
    let pi = Float::with_val(prec, rug::float::Constant::Pi);
    let ls3 = Float::with_val(prec, sp.l_s.clone().square() * &sp.l_s);
    let unit_fd = Float::with_val(prec, &pi * &sp.k) * &sp.k * &ls3;
    let kl_p2 = Float::with_val(prec, &sp.k * &l) * &sp.p2;
    let f_coeffs = coefficients(&e.f_def_scaled, order, &sp, prec);
    let (fds, d_f, ch_f) = resummed(
        "F_def/(pi E* k^2 l_s^3)",
        &f_coeffs,
        w_is_square,
        &sp,
        &Float::with_val(prec, &kl_p2 / &unit_fd),
        cap,
        map,
    )?;
    let f_def = Float::with_val(prec, &unit_fd * &fds);
    // Pressure brackets at the points.
    let cos = Float::with_val(prec, Float::with_val(prec, &pi * &sp.theta).cos());
    let half = Float::with_val(prec, 0.5);
    let [th, t, kappa, invpi] = sp.bindings();
    let xh_s = exact_series::Symbol::new("xh").expect("valid");
    let mut pressure = vec![];
    let mut chosen = vec![ch_l, ch_r, ch_f];
    for x in &xh {
        let binds = [th.clone(), t.clone(), kappa.clone(), invpi.clone(), (xh_s, x.clone())];
        let mut b = vec![Float::with_val(prec, 0); order + 1];
        b[0] = one.clone();
        for (j, pj) in e.pressure.iter().take(order / e.step).enumerate() {
            b[e.step * (j + 1)] = evaluate::poly_mpfr(pj, &binds, prec)
                .expect("the pressure terms hold only theta, T, kappa, invpi and xh");
        }
        let ep = Float::with_val(prec, &half + &sp.theta);
        let em = Float::with_val(prec, &half - &sp.theta);
        let omega = Float::with_val(
            prec,
            Float::with_val(prec, 1 + x).pow(&ep) * Float::with_val(prec, 1 - x.clone()).pow(&em),
        );
        let factor = Float::with_val(prec, &sp.k * &l) * &cos * omega;
        pressure.push((b, factor));
    }
    // The bracket's scale: max p over the points in units of its factor (a first pass with the
    // plain brackets gives max p to a few digits, enough for a scale).
    let plain_max = pressure
        .iter()
        .map(|(b, f)| Float::with_val(prec, f * b.iter().fold(Float::with_val(prec, 0), |acc, x| acc + x)).abs())
        .fold(Float::with_val(prec, 0), |m, x| if x > m { x } else { m });
    let mut p_values = vec![];
    let mut d_p: Option<f64> = None;
    for (i, (b, factor)) in pressure.iter().enumerate() {
        let scale = Float::with_val(prec, &plain_max / factor);
        let name = format!("pressure bracket at xh = {}", readable_mpfr(&xh[i]));
        let (v, d, ch) = resummed(&name, b, w_is_square, &sp, &scale, cap, map)?;
        p_values.push(Float::with_val(prec, factor * &v));
        d_p = Some(d_p.map_or(d, |a| a.min(d)));
        chosen.push(ch);
    }
    // Propagation to the outputs (module doc).
    let err = |d: f64, scale: &Float| Float::with_val(prec, scale * Float::with_val(prec, 10).pow(-d));
    let e_l = err(d_l, &sp.l_s);
    let e_c = Float::with_val(prec, &l * err(d_r, &one)) + Float::with_val(prec, rbar.clone().abs() * &e_l);
    let contact = verified_digits_mpfr(&Float::with_val(prec, &e_l + &e_c), &l, cap);
    let length = verified_digits_mpfr(&e_l, &l, cap);
    let max_p = p_values.iter().fold(Float::with_val(prec, 0), |m, x| if *x > m { x.clone() } else { m });
    let pressure_digits = d_p.map(|d| {
        let e_b = err(d, &plain_max);
        let rel_l = Float::with_val(prec, &e_l / &l);
        verified_digits_mpfr(&(e_b + Float::with_val(prec, &max_p * &rel_l)), &max_p, cap)
    });
    let headline = contact.min(d_f).min(pressure_digits.unwrap_or(f64::INFINITY));
    let rate = {
        let cw: Vec<&Float> =
            if w_is_square { l_coeffs.iter().step_by(2).collect() } else { l_coeffs.iter().collect() };
        let n = cw.len();
        if n >= 2 && !cw[n - 2].is_zero() {
            let w =
                if w_is_square { Float::with_val(prec, sp.big_lambda.clone().square()) } else { sp.big_lambda.clone() };
            Float::with_val(64, Float::with_val(prec, cw[n - 1] / cw[n - 2]) * &w).abs().to_f64()
        } else {
            f64::NAN
        }
    };
    let digits = SeriesAccuracy { contact, length, f_def: d_f, pressure: pressure_digits, headline, rate };
    let partial =
        Partial { l, c, f_def: Float::with_val(prec, &f_def), pressure: p_values.iter().map(|p| p.clone()).collect() };
    Ok((Run { partial, digits, chosen, w_is_square }, params, sp, xh))
}

/// What the pade method says of an order below 2: it needs two coefficients in Lambda^2 at least.
const PADE_ORDER: &str = "the pade method needs an order >= 2 (two coefficients in Lambda^2 at least)";

/// Solves `problem` by the Padé approximants of its series through Lambda^order (see
/// [`solve_pade_with`]).
pub fn solve_pade(
    problem: &SlidingProblem,
    points: &[Exact],
    order: usize,
    digits: u32,
) -> Result<PadeSolution, Error> {
    check_order(order, PADE_ORDER)?;
    solve_pade_with(&derive_expansion(problem, order)?, problem, points, order, digits)
}

/// [`solve_pade`] with the expansion already derived (of the problem's shape and convention,
/// through at least Lambda^order). Errors: input (as the series method: a single punch, a given
/// half-length, order < 2); no convergence when every approximant of a quantity is refused
/// (module doc) or fewer than one digit is estimated; not physical at the Padé contact.
///
/// # Panics
/// When `e` has another shape or convention than the problem or is shorter than `order`.
pub fn solve_pade_with(
    e: &SlidingExpansion,
    problem: &SlidingProblem,
    points: &[Exact],
    order: usize,
    digits: u32,
) -> Result<PadeSolution, Error> {
    check_expansion(e, problem, order, PADE_ORDER)?;
    let prec = precision_for(digits);
    let (first, params, sp, xh) = run(e, problem, points, order, digits, prec)?;
    let (second, ..) = run(e, problem, points, order, digits, prec + VERIFY_EXTRA_BITS)?;
    // One digit above the request: the evaluation at precision_for(digits) bits sees more, and a
    // cap of exactly the request would leave the printed text (its rounding) below it (issue 34).
    let cap = digits as f64 + 1.0;
    let agree = |x: &Float, y: &Float, scale: &Float| verified_digits_mpfr(&Float::with_val(prec, x - y), scale, cap);
    let (a, b) = (&first.partial, &second.partial);
    let mut acc = first.digits.clone();
    acc.length = acc.length.min(agree(&a.l, &b.l, &a.l));
    acc.contact = acc.contact.min(agree(&a.l, &b.l, &a.l)).min(agree(&a.c, &b.c, &a.l));
    let kl_p2 = Float::with_val(prec, &sp.k * &a.l) * &sp.p2;
    acc.f_def = acc.f_def.min(agree(&a.f_def, &b.f_def, &kl_p2));
    let max_p = a.pressure.iter().fold(Float::with_val(prec, 0), |m, x| if *x > m { x.clone() } else { m });
    if let Some(pd) = acc.pressure.as_mut() {
        for (x, y) in a.pressure.iter().zip(&b.pressure) {
            *pd = pd.min(agree(x, y, &max_p));
        }
    }
    acc.headline = acc.contact.min(acc.f_def).min(acc.pressure.unwrap_or(f64::INFINITY));
    // Below MIN_ESTIMATED_DIGITS the neighbours' agreement does not estimate the error (issue 34:
    // the fuzzer found 1.8 digits claimed, 1.4 held, at lambda = 1.48).
    if acc.headline < MIN_ESTIMATED_DIGITS {
        return Err(Error::NoConvergence {
            what: format!(
                "the Pade approximants of the series through Lambda^{order} at Lambda = pi l_s/L = {} leave {} estimated \
                 digits (< {MIN_ESTIMATED_DIGITS}: neighbours agreeing this little do not estimate the error)",
                readable_mpfr(&sp.big_lambda),
                readable_f64((acc.headline * 10.0).floor() / 10.0)
            ),
        });
    }
    // The claims: each error estimate times ESTIMATE_SAFETY (the propagation above is linear in
    // the errors, so every digit count loses log10 of it).
    let lost = ESTIMATE_SAFETY.log10();
    let less = |d: f64| (d - lost).max(0.0);
    for d in [&mut acc.contact, &mut acc.length, &mut acc.f_def] {
        *d = less(*d);
    }
    acc.pressure = acc.pressure.map(less);
    acc.headline = acc.contact.min(acc.f_def).min(acc.pressure.unwrap_or(f64::INFINITY));
    let chosen = first.chosen.into_iter().map(|c| Chosen { digits: less(c.digits), ..c }).collect();
    let mut s = solution(&params, &sp, a, &xh, max_p, order, acc);
    assess_physicality(problem, &mut s, prec, "the Pade contact")?;
    Ok(PadeSolution { solution: s, w_is_square: first.w_is_square, chosen })
}
