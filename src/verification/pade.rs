//! Padé resummation against the full solutions (docs/theory.md section 11): per object and contact
//! size lambda, the digits of the plain partial sum and of the best Padé approximant built from
//! the same coefficients, each against a reference computed without the series (a closed form, or
//! the verified MPFR solver), with the Padé method's own estimate and its refusals.
//!
//! Objects:
//! - `Kuznetsov l`: the frictionless periodic parabola, l/l_s in w = Lambda^2, exact coefficients
//!   (theta = T = 0 substituted), against cos(lambda) = exp(-Lambda^2/2) [2.15]: l/l_s =
//!   lambda/Lambda, Lambda^2 = -2 ln cos lambda;
//! - `sinusoid a`: the frictionless sinusoid, exact coefficients, against sin(lambda) = Lambda
//!   [2.17] (P2 = pi E* D sin^2 lambda, Lambda = pi a0/L with the osculating k): a/a0 =
//!   lambda/sin(lambda);
//! - `friction l`, `friction c`: the parabola with Coulomb friction (E* = k = L = 1, nu = 3/10,
//!   mu = 2/5: theta = arctan(-4/35)/pi), MPFR coefficients at theta, against the verified MPFR
//!   reduction at the half-length l = lambda L/pi (the series evaluated at that solution's load);
//! - `P2 nu=0`, `P2 nu=3/10`: Problem 2's load P2 = C_P E* k a^2 (1 + c_2 lambda^2 + ...) [3.18],
//!   MPFR coefficients at nu, w = lambda^2, against the verified MPFR Volterra solver at a =
//!   lambda L/pi.
//!
//! The two closed-form objects have known singularities, and their rows also resum after the
//! conformal map of the cut plane onto the unit disc ([`crate::numerics::pade::Conformal`]):
//! Kuznetsov's at w = +-2 pi i (exp(-w/2) = -1), cuts along the imaginary axis; the sinusoid's
//! at w = 1 (sin lambda = 1), cut [1, infinity).
//!
//! Scales: l for l, c (Problem 1), P2 for the load; the digits of a comparison are capped by the
//! reference's own digits.

use crate::adhesion;
use crate::asymptotics::adhesion::{adhesion_expansion_with, adhesion_values, AdhesionExpansion};
use crate::asymptotics::sliding::{sliding_expansion_with, SlidingExpansion, SlidingShape};
use crate::model::{AdhesionProblem, AdhesionSize, Convention, Exact, Material, Period, PunchShape, SlidingProblem};
use crate::numerics::accuracy::verified_digits_mpfr;
use crate::numerics::evaluate::series_q_mpfr;
use crate::numerics::exact::to_float;
use crate::numerics::pade::{float_to_q, resum, resum_conformal, resum_mpfr, Conformal, Cut};
use crate::sliding::series::pade::solve_pade_with;
use crate::sliding::series::partial::partial;
use crate::sliding::series::point::series_point;
use exact_series::{Poly, Ring, Series, Symbol, Q};
use rug::Float;

/// One object at one lambda.
#[derive(Debug, Clone, PartialEq)]
pub struct PadeRow {
    /// The object (`Kuznetsov l`, `sinusoid a`, `friction l`, `friction c`, `P2 nu=0`, ...).
    pub object: String,
    /// The contact size lambda = pi l/L (pi a/L).
    pub lambda: f64,
    /// The series variable w at that size (Lambda^2 or lambda^2).
    pub w: f64,
    /// The order N of the series (every term through Lambda^N or lambda^N).
    pub order: usize,
    /// `exact` (rationals) or `MPFR` (coefficients at transcendental parameters).
    pub coefficients: &'static str,
    /// The reference: `closed form [2.15]` etc., or the MPFR solver.
    pub reference: String,
    /// Digits of the plain partial sum against the reference.
    pub plain: Option<f64>,
    /// The best Padé approximant: (L, M, estimated digits, digits against the reference).
    pub pade: Option<(usize, usize, f64, f64)>,
    /// The conformal map of the known singularity (closed-form objects only), as text.
    pub map: Option<String>,
    /// The best Padé approximant in z after that map: (L, M, estimated, against the reference).
    pub conformal: Option<(usize, usize, f64, f64)>,
    /// Why there is no Padé value (every candidate refused) or no reference.
    pub refusal: Option<String>,
}

/// The chart's contact sizes.
pub const LAMBDAS: [f64; 5] = [0.4, 0.8, 1.0, 1.2, 1.4];

/// The verified MPFR solution of a Problem 2 problem at the given digits
/// ([`adhesion::solve_verified`], or a caller's memo of it: the report shares these runs with its
/// stability map).
pub type AdhesionReference<'a> = &'a (dyn Fn(&AdhesionProblem, u32) -> Result<std::sync::Arc<adhesion::VerifiedSolution>, adhesion::AdhesionError>
         + Sync);

/// [`adhesion::solve_verified`] as an [`AdhesionReference`] without a memo.
pub(crate) fn solve_adhesion_reference(
    p: &AdhesionProblem,
    digits: u32,
) -> Result<std::sync::Arc<adhesion::VerifiedSolution>, adhesion::AdhesionError> {
    adhesion::solve_verified(p, &[], digits).map(std::sync::Arc::new)
}

/// a/L = lambda/pi rounded to 6 decimals for the Problem 2 rows: the rounding of the report's
/// stability map (`report::calibration::rational`), so that the two compute one problem once.
fn near6(x: f64) -> Exact {
    Q::new(((x * 1e6).round() as i64).into(), 1_000_000i64.into())
}

fn q(n: i64, d: i64) -> Q {
    Q::new(n.into(), d.into())
}

/// An exact rational within 1e-12 of `x`.
fn near(x: f64) -> Exact {
    Q::new(((x * 1e12).round() as i64).into(), 1_000_000_000_000i64.into())
}

/// l/l_s of a Problem 1 expansion at theta = T = 0, exactly, as a series in w = Lambda^2.
pub fn frictionless_l_over_ls(e: &SlidingExpansion) -> Series<Q> {
    let zero = Q::from_integer(0.into());
    let (th, t) = (Symbol::new("theta").expect("valid"), Symbol::new("T").expect("valid"));
    let c: Vec<Q> = e
        .l_over_ls
        .coeffs()
        .iter()
        .step_by(2)
        .map(|p: &Poly| {
            p.subs(th, &zero).subs(t, &zero).as_q().expect("theta and T are the only symbols of the paper expansion")
        })
        .collect();
    Series::from_coeffs(c)
}

/// The conformal map of the known singularity of the frictionless l/l_s (module doc).
pub fn singularity_map(shape: SlidingShape, prec: u32) -> Conformal {
    match shape {
        SlidingShape::Parabolic => {
            Conformal { cut: Cut::Imaginary, radius: Float::with_val(prec, rug::float::Constant::Pi) * 2u32 }
        }
        SlidingShape::Sinusoidal => Conformal { cut: Cut::Real, radius: Float::with_val(prec, 1) },
    }
}

/// The closed-form rows (`Kuznetsov l`, `sinusoid a`) at `digits` digits.
fn closed_form_rows(e: &SlidingExpansion, order: usize, lambdas: &[f64], digits: u32) -> Vec<PadeRow> {
    let prec = crate::numerics::precision::precision_for(digits);
    let cap = digits as f64;
    let shape = e.shape;
    let f = frictionless_l_over_ls(e).truncate(order / 2 + 1);
    let (name, reference) = match shape {
        SlidingShape::Parabolic => ("Kuznetsov l", "closed form cos(lambda) = exp(-Lambda^2/2) [2.15]"),
        SlidingShape::Sinusoidal => ("sinusoid a", "closed form sin(lambda) = Lambda [2.17]"),
    };
    let map = singularity_map(shape, prec);
    let map_text = match shape {
        SlidingShape::Parabolic => "cuts from w = +-2 pi i along the imaginary axis",
        SlidingShape::Sinusoidal => "cut [1, inf) from w = 1",
    };
    lambdas
        .iter()
        .map(|&lam| {
            let lambda = Float::with_val(prec, lam);
            let w = match shape {
                SlidingShape::Parabolic => Float::with_val(prec, lambda.clone().cos().ln()) * -2,
                SlidingShape::Sinusoidal => Float::with_val(prec, lambda.clone().sin().square()),
            };
            let truth = Float::with_val(prec, &lambda / w.clone().sqrt());
            let plain = series_q_mpfr(&f, &w, prec);
            let d = |x: &Float| verified_digits_mpfr(&Float::with_val(prec, x - &truth), &truth, cap);
            let r = resum(&f, &w, &truth, cap, prec);
            let pade = r.best().map(|b| (b.l, b.m, b.digits, d(&b.value)));
            let cw: Vec<Float> = f.coeffs().iter().map(|c| to_float(c, prec)).collect();
            let conformal = resum_conformal(&cw, &map, &w, &truth, cap, prec)
                .and_then(|r| r.best().map(|b| (b.l, b.m, b.digits, d(&b.value))));
            PadeRow {
                object: name.into(),
                lambda: lam,
                w: w.to_f64(),
                order,
                coefficients: "exact",
                reference: reference.into(),
                plain: Some(d(&plain)),
                pade,
                map: Some(map_text.into()),
                conformal,
                refusal: pade.is_none().then(|| r.refusals().join("; ")),
            }
        })
        .collect()
}

/// The friction rows (`friction l`, `friction c`).
fn friction_rows(e: &SlidingExpansion, order: usize, lambdas: &[f64], digits: u32) -> Vec<PadeRow> {
    let prec = crate::numerics::precision::precision_for(digits);
    let cap = digits as f64;
    let base = |b: crate::model::SlidingProblemBuilder| {
        b.material(Material::from_contact_modulus(q(3, 10), q(1, 1)).expect("valid material"))
            .period(Period::Finite(q(1, 1)))
            .shape(PunchShape::Parabolic { k: q(1, 1) })
            .friction(q(2, 5))
    };
    let mut rows = vec![];
    for &lam in lambdas {
        let row = |object: &str| PadeRow {
            object: object.into(),
            lambda: lam,
            w: f64::NAN,
            order,
            coefficients: "MPFR",
            reference: "MPFR reduction (verified)".into(),
            plain: None,
            pade: None,
            map: None,
            conformal: None,
            refusal: None,
        };
        let (mut rl, mut rc) = (row("friction l"), row("friction c"));
        let by_size = base(SlidingProblem::builder()).half_length(near(lam / std::f64::consts::PI)).build();
        let reference = by_size
            .map_err(|e| e.to_string())
            .and_then(|p| crate::sliding::solve_verified(&p, &[], digits).map_err(|e| e.to_string()));
        let v = match reference {
            Ok(v) if !v.is_empty() => v[0].clone(),
            Ok(_) => {
                rl.refusal = Some("reference: no physical contact".into());
                rc.refusal = rl.refusal.clone();
                rows.extend([rl, rc]);
                continue;
            }
            Err(why) => {
                rl.refusal = Some(format!("reference: {why}"));
                rc.refusal = rl.refusal.clone();
                rows.extend([rl, rc]);
                continue;
            }
        };
        let m = &v.solution;
        let ref_digits = v.accuracy.digits_verified.min(cap);
        rl.reference = format!("MPFR reduction ({ref_digits:.0} digits verified)");
        rc.reference = rl.reference.clone();
        let p2 = float_to_q(&m.p2).expect("finite load");
        let problem = base(SlidingProblem::builder()).normal_load(p2).build().expect("the load of a solution is valid");
        let sp = series_point(&problem, prec).expect("a periodic problem at a given load");
        let w = Float::with_val(prec, sp.big_lambda.clone().square()).to_f64();
        rl.w = w;
        rc.w = w;
        let plain = partial(e, order, &sp, &[]);
        let d = |x: &Float, y: &Float| verified_digits_mpfr(&Float::with_val(prec, x - y), &m.l, ref_digits);
        rl.plain = Some(d(&plain.l, &m.l));
        rc.plain = Some(d(&plain.c, &m.c));
        match solve_pade_with(e, &problem, &[], order, digits) {
            Ok(s) => {
                let of = |name: &str| s.chosen.iter().find(|c| c.quantity == name).expect("chosen per quantity");
                let (cl, cr) = (of("l/l_s"), of("rbar - rbar_s"));
                rl.pade = Some((cl.l, cl.m, s.solution.accuracy.contact, d(&s.solution.l, &m.l)));
                rc.pade = Some((cr.l, cr.m, s.solution.accuracy.contact, d(&s.solution.c, &m.c)));
            }
            Err(why) => {
                rl.refusal = Some(why.to_string());
                rc.refusal = rl.refusal.clone();
            }
        }
        rows.extend([rl, rc]);
    }
    rows
}

/// The Problem 2 rows (`P2 nu=...`) from the load expansion `e` through order `order`.
fn adhesion_rows(
    e: &AdhesionExpansion,
    nu: &Q,
    order: usize,
    lambdas: &[f64],
    digits: u32,
    reference: AdhesionReference,
) -> Vec<PadeRow> {
    let prec = crate::numerics::precision::precision_for(digits);
    let cap = digits as f64;
    let name = format!("P2 nu={}", exact_series::q_text(nu));
    let values = adhesion_values(e, nu, prec).expect("nu in [0, 1/2]");
    let cw: Vec<Float> = values.load.iter().take(order + 1).step_by(2).cloned().collect();
    let material = Material::from_contact_modulus(nu.clone(), q(1, 1)).expect("valid material");
    let pi = Float::with_val(prec, rug::float::Constant::Pi);
    lambdas
        .iter()
        .map(|&lam| {
            let a = near6(lam / std::f64::consts::PI);
            let a_f = to_float(&a, prec);
            let lambda = Float::with_val(prec, &pi * &a_f);
            let w = Float::with_val(prec, lambda.clone().square());
            let mut row = PadeRow {
                object: name.clone(),
                lambda: lam,
                w: w.to_f64(),
                order,
                coefficients: "MPFR",
                reference: "MPFR Volterra (verified)".into(),
                plain: None,
                pade: None,
                map: None,
                conformal: None,
                refusal: None,
            };
            let problem = AdhesionProblem::new(
                material.clone(),
                Period::Finite(q(1, 1)),
                PunchShape::Parabolic { k: q(1, 1) },
                AdhesionSize::HalfWidth(a.clone()),
            )
            .expect("a valid problem");
            let v = match reference(&problem, digits) {
                Ok(v) => v,
                Err(why) => {
                    row.refusal = Some(format!("reference: {why}"));
                    return row;
                }
            };
            let ref_digits = v.digits_verified.size.min(cap);
            row.reference = format!("MPFR Volterra ({ref_digits:.0} digits verified)");
            // P2 = C_P E* k a^2 B(w): the bracket's truth and scale.
            let unit = Float::with_val(prec, &values.load_constant * &a_f) * &a_f;
            let truth = Float::with_val(prec, &v.solution.normal_load / &unit);
            let d = |x: &Float| verified_digits_mpfr(&Float::with_val(prec, x - &truth), &truth, ref_digits);
            let plain = cw.iter().rev().fold(Float::with_val(prec, 0), |acc, c| acc * &w + c);
            row.plain = Some(d(&plain));
            match resum_mpfr(&cw, &w, &truth, cap, prec) {
                Some(r) => match r.best() {
                    Some(b) => row.pade = Some((b.l, b.m, b.digits, d(&b.value))),
                    None => row.refusal = Some(r.refusals().join("; ")),
                },
                None => row.refusal = Some("a coefficient is not finite".into()),
            }
            row
        })
        .collect()
}

/// The orders, sizes and reference digits of a chart.
#[derive(Debug, Clone)]
pub struct PadePlan {
    /// Order of the parabola's series (Kuznetsov, friction).
    pub parabola: usize,
    /// Order of the sinusoid's series (its symbolic derivation is the dearest: 0.34 s at 12,
    /// 2.3 s at 16 in release, `time periodic-contact series sliding --shape sinusoidal --order N`).
    pub sinusoid: usize,
    /// Order of Problem 2's load series.
    pub adhesion: usize,
    /// The sizes lambda.
    pub lambdas: Vec<f64>,
    /// Digits of the references (and the cap of every comparison).
    pub digits: u32,
}

impl PadePlan {
    /// The default report's plan (its Pade section): orders 16, 12, 12 at [`LAMBDAS`], references
    /// at 20 digits.
    pub fn report() -> Self {
        PadePlan { parabola: 16, sinusoid: 12, adhesion: 12, lambdas: LAMBDAS.to_vec(), digits: 20 }
    }
}

/// The objects of the chart, in its order (each gives one row, or two for friction, per lambda).
#[derive(Debug, Clone, PartialEq)]
pub enum PadeObject {
    /// `Kuznetsov l` (closed form).
    Kuznetsov,
    /// `sinusoid a` (closed form).
    Sinusoid,
    /// `friction l` and `friction c` (the verified MPFR reduction).
    Friction,
    /// `P2 nu=...` at this nu (the verified MPFR Volterra solver).
    Adhesion(Q),
}

/// Every object of the chart, in the chart's order.
pub fn pade_objects() -> Vec<PadeObject> {
    vec![
        PadeObject::Kuznetsov,
        PadeObject::Sinusoid,
        PadeObject::Friction,
        PadeObject::Adhesion(q(0, 1)),
        PadeObject::Adhesion(q(3, 10)),
    ]
}

/// The exact expansions the rows are built from: the `paper` parabola through (at least)
/// `plan.parabola`, the sinusoid through `plan.sinusoid`, Problem 2's load through `plan.adhesion`
/// (an expansion derived through a higher order gives the same rows: each row takes the terms
/// through its own order).
pub struct PadeSeries<'a> {
    /// The parabola's (Kuznetsov, friction).
    pub parabola: &'a SlidingExpansion,
    /// The sinusoid's.
    pub sinusoid: &'a SlidingExpansion,
    /// Problem 2's.
    pub adhesion: &'a AdhesionExpansion,
    /// The verified MPFR references of Problem 2's rows.
    pub adhesion_reference: AdhesionReference<'a>,
}

/// The rows of `object` at the one size `lambda` (independent of the other rows, so that a caller
/// may compute them in any order or in parallel; [`pade_rows`] in the chart's order).
pub fn pade_rows_at(plan: &PadePlan, series: &PadeSeries, object: &PadeObject, lambda: f64) -> Vec<PadeRow> {
    let l = [lambda];
    match object {
        PadeObject::Kuznetsov => closed_form_rows(series.parabola, plan.parabola, &l, plan.digits),
        PadeObject::Sinusoid => closed_form_rows(series.sinusoid, plan.sinusoid, &l, plan.digits),
        PadeObject::Friction => friction_rows(series.parabola, plan.parabola, &l, plan.digits),
        PadeObject::Adhesion(nu) => {
            adhesion_rows(series.adhesion, nu, plan.adhesion, &l, plan.digits, series.adhesion_reference)
        }
    }
}

/// Every row of the chart at `plan`: Kuznetsov, sinusoid, friction l and c, P2 at nu = 0, 3/10
/// (per object, by lambda).
pub fn pade_rows(plan: &PadePlan) -> Vec<PadeRow> {
    let paper =
        |shape, order| sliding_expansion_with(shape, order, Convention::Paper).expect("the paper expansion derives");
    let parabola = paper(SlidingShape::Parabolic, plan.parabola);
    let sinusoid = paper(SlidingShape::Sinusoidal, plan.sinusoid);
    let adhesion = adhesion_expansion_with(plan.adhesion, false).expect("the adhesion expansion derives");
    let series = PadeSeries {
        parabola: &parabola,
        sinusoid: &sinusoid,
        adhesion: &adhesion,
        adhesion_reference: &solve_adhesion_reference,
    };
    let mut rows = vec![];
    for object in pade_objects() {
        for &lambda in &plan.lambdas {
            rows.extend(pade_rows_at(plan, &series, &object, lambda));
        }
    }
    rows
}
