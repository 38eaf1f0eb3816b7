//! The f64 collocation's Problem 1 solution as a [`SlidingAnswer`]: its verified digits per
//! quantity ([`SlidingSolutionF64::digits`], a check run with more nodes) on the scales of
//! [`crate::params::sliding::SlidingScale`].

use super::render::{DigitsKind, Measured, Num, PressureRow, Provenance, SlidingAnswer};
use crate::model::Convention;
use crate::numerics::accuracy::F64_DIGITS_CAP;
use crate::sliding::collocation_f64::{Quantity, SlidingSolutionF64};

/// The answer of one f64 solution (`periodic`: whether the problem has a period, else lambda is
/// not reported; `convention`: the surface convention, for the provenance).
pub fn sliding_answer(s: &SlidingSolutionF64, periodic: bool, convention: Convention) -> SlidingAnswer {
    let d = s.digits();
    let sc = &s.accuracy.scales;
    let m = |v: f64, q: Quantity| Measured::f64(v, q.scale(sc), d[q]);
    // lambda = pi l/L carries the relative accuracy of l.
    let lambda = periodic.then(|| Measured::f64(s.lambda, s.lambda, d[Quantity::Size]));
    let load = |v: Option<f64>| v.map(|w| Measured::f64(w, w, d[Quantity::P2]));
    SlidingAnswer {
        provenance: Provenance {
            method: "f64",
            bits: Some(53),
            nodes: Some(s.nodes),
            order: None,
            convention: Some(convention.name()),
        },
        kind: DigitsKind::Verified,
        parameter_digits: F64_DIGITS_CAP as usize + 1,
        theta: Num::F64(s.theta),
        kappa: Num::F64(s.kappa),
        lambda,
        l: m(s.l, Quantity::Size),
        a: m(s.a, Quantity::A),
        b: m(s.b, Quantity::B),
        c: m(s.c, Quantity::C),
        p1: m(s.p1, Quantity::P1),
        p2: m(s.p2, Quantity::P2),
        f_def: m(s.f_def, Quantity::FDef),
        wear_per_distance: load(s.wear_per_distance),
        wear_rate: load(s.wear_rate),
        worn_area_per_distance: Some(Measured::f64(
            s.worn_area_per_distance,
            s.worn_area_per_distance,
            d[Quantity::P2],
        )),
        accuracy: [
            ("a", Quantity::A),
            ("b", Quantity::B),
            ("c", Quantity::C),
            ("P1", Quantity::P1),
            ("P2", Quantity::P2),
            ("F_def", Quantity::FDef),
            ("p", Quantity::Pressure),
        ]
        .into_iter()
        .map(|(k, q)| (k.to_string(), d[q]))
        .collect(),
        extra: vec![],
        note: None,
        pressure: s
            .pressure
            .iter()
            .map(|q| PressureRow { xh: Num::F64(q.xh), x: m(q.x, Quantity::Size), p: m(q.p, Quantity::Pressure) })
            .collect(),
        physicality: Some(s.physicality.clone()),
    }
}
