//! The MPFR reduction's Problem 1 solution as a [`SlidingAnswer`]: digits per quantity verified by
//! a second run ([`crate::sliding::VerifiedSolution`]) on the scales of
//! [`crate::params::sliding::SlidingScale`].

use super::render::{DigitsKind, Measured, Num, PressureRow, Provenance, SlidingAnswer};
use crate::model::Convention;
use crate::params::sliding::SlidingScale;
use crate::sliding::VerifiedSolution;

/// The answer of one verified MPFR solution (`convention`: the surface convention, for the
/// provenance).
pub fn sliding_answer(v: &VerifiedSolution, convention: Convention) -> SlidingAnswer {
    let s = &v.solution;
    let d = |name: &str| v.accuracy.digits.iter().find(|(n, _)| n == name).map_or(v.accuracy.digits_verified, |x| x.1);
    let scale = |q: SlidingScale| q.mpfr(&s.k, &s.l, &s.p2, &s.max_pressure);
    let (length, load) = (scale(SlidingScale::Length), scale(SlidingScale::Load));
    // l, lambda and x have no comparison of their own: the weakest of a, b, c.
    let geometry = ["a", "b", "c"].iter().map(|n| d(n)).fold(f64::INFINITY, f64::min);
    let on = |x: &rug::Float, sc: &rug::Float, digits: f64| Measured::mpfr(x.clone(), sc, digits);
    // Wear outputs are multiples of P2: P2's relative digits.
    let own = |x: &rug::Float| Measured::mpfr(x.clone(), x, d("P2"));
    SlidingAnswer {
        provenance: Provenance {
            method: "mpfr",
            bits: Some(s.prec),
            nodes: Some(s.nodes),
            order: None,
            convention: Some(convention.name()),
        },
        kind: DigitsKind::Verified,
        parameter_digits: usize::MAX,
        theta: Num::Mpfr(s.theta.clone()),
        kappa: Num::Mpfr(s.kappa.clone()),
        lambda: s.lambda.as_ref().map(|l| on(l, l, geometry)),
        l: on(&s.l, &length, geometry),
        a: on(&s.a, &length, d("a")),
        b: on(&s.b, &length, d("b")),
        c: on(&s.c, &length, d("c")),
        p1: on(&s.p1, &load, d("P1")),
        p2: on(&s.p2, &load, d("P2")),
        f_def: on(&s.f_def, &scale(SlidingScale::DeformationForce), d("F_def")),
        wear_per_distance: s.wear_per_distance.as_ref().map(own),
        wear_rate: s.wear_rate.as_ref().map(own),
        worn_area_per_distance: Some(own(&s.worn_area_per_distance)),
        accuracy: v.accuracy.digits.clone(),
        extra: vec![],
        note: None,
        pressure: s
            .pressure
            .iter()
            .enumerate()
            .map(|(i, p)| PressureRow {
                xh: Num::Mpfr(p.xh.clone()),
                x: on(&p.x, &length, geometry),
                p: on(&p.p, &scale(SlidingScale::Pressure), d(&format!("p[{i}]"))),
            })
            .collect(),
        physicality: s.physicality.clone(),
    }
}
