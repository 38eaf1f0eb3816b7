//! The truncated exact series of Problem 1 ([`crate::sliding::series`]) as a [`SlidingAnswer`]:
//! estimated (never verified) digits per quantity on the scales of
//! [`crate::params::sliding::SlidingScale`]; the load P2 and the wear outputs are exact inputs
//! (or exact multiples of P2) rounded once, shown to the digits requested.

use super::render::{DigitsKind, Measured, Num, PressureRow, Provenance, SlidingAnswer};
use crate::model::Convention;
use crate::params::sliding::SlidingScale;
use crate::sliding::series::{estimate, SeriesSolution};
use serde_json::json;

/// The answer of one series evaluation at `requested` digits (in the surface convention
/// `convention`, for the provenance).
pub fn sliding_answer(s: &SeriesSolution, requested: u32, convention: Convention) -> SlidingAnswer {
    let acc = &s.accuracy;
    let (g, fd) = (acc.contact, acc.f_def);
    // Exact inputs (and exact multiples of them) rounded once at the working precision: more than
    // the digits requested; one above them so that the printed text holds the request.
    let exact = requested as f64 + 1.0;
    let scale = |q: SlidingScale| q.mpfr(&s.k, &s.l, &s.p2, &s.max_pressure);
    let length = scale(SlidingScale::Length);
    let on = |x: &rug::Float, sc: &rug::Float, d: f64| Measured::mpfr(x.clone(), sc, d);
    let mut accuracy: Vec<(String, f64)> =
        [("a", g), ("b", g), ("c", g), ("F_def", fd)].into_iter().map(|(k, d)| (k.to_string(), d)).collect();
    if let Some(pd) = acc.pressure {
        accuracy.push(("p".into(), pd));
    }
    let pd = acc.pressure.unwrap_or(0.0);
    SlidingAnswer {
        provenance: Provenance {
            method: "series",
            bits: Some(s.prec),
            nodes: None,
            order: Some(s.order),
            convention: Some(convention.name()),
        },
        kind: DigitsKind::Estimated,
        parameter_digits: usize::MAX,
        theta: Num::Mpfr(s.theta.clone()),
        kappa: Num::Mpfr(s.kappa.clone()),
        lambda: Some(on(&s.lambda, &s.lambda, g)),
        l: on(&s.l, &length, g),
        a: on(&s.a, &length, g),
        b: on(&s.b, &length, g),
        c: on(&s.c, &length, g),
        // P1 = mu P2 + 2 l tau0 carries l's relative error in its tau0 part (l's own digits, not
        // the contact's, which c's error lowers): at most 10^-length |P1|, which on the scale P2
        // is length - log10(|P1|/P2) digits when |P1| > P2 (issue 34, fuzzing).
        p1: on(&s.p1, &s.p2, acc.length - p1_excess(&s.p1, &s.p2)),
        p2: on(&s.p2, &s.p2, exact),
        f_def: on(&s.f_def, &scale(SlidingScale::DeformationForce), fd),
        wear_per_distance: Some(on(&s.wear_per_distance, &s.wear_per_distance, exact)),
        wear_rate: s.wear_rate.as_ref().map(|w| on(w, w, exact)),
        worn_area_per_distance: Some(on(&s.worn_area_per_distance, &s.worn_area_per_distance, exact)),
        accuracy,
        extra: vec![("Lambda".into(), json!(Num::Mpfr(s.big_lambda.clone()).fmt(10)))],
        note: Some(format!(
            "estimated from the terms kept through order {} (geometric tail of their rate {:.2} per Lambda^2, \
             safety factor {}); not verified",
            s.order,
            acc.rate,
            estimate::SAFETY
        )),
        pressure: s
            .pressure
            .iter()
            .map(|pt| PressureRow {
                xh: Num::Mpfr(pt.xh.clone()),
                x: on(&pt.x, &length, g),
                p: on(&pt.p, &scale(SlidingScale::Pressure), pd),
            })
            .collect(),
        physicality: Some(s.physicality.clone()),
    }
}

/// log10(|P1|/P2) when |P1| > P2, else 0: the digits P1's error, relative to |P1|, loses on the
/// scale P2.
fn p1_excess(p1: &rug::Float, p2: &rug::Float) -> f64 {
    let ratio = rug::Float::with_val(64, p1.abs_ref()) / rug::Float::with_val(64, p2.abs_ref());
    if ratio.is_finite() && ratio > 1u32 {
        ratio.log10().to_f64()
    } else {
        0.0
    }
}
