//! Problem 2's solutions (the MPFR Volterra method and the f64 lambda^2-series method) as
//! [`AdhesionAnswer`]s: digits per quantity on the scales of [`crate::adhesion::scales`]
//! (verified by a second run for MPFR; estimated by a second, finer run for f64).

use super::render::{AdhesionAnswer, DigitsKind, FieldRow, Measured, Num, Provenance, ZoneRow};
use crate::adhesion::{AdhesionSolutionF64, Digits, ScalesF64, ScalesMpfr, VerifiedSolution};
use crate::model::OnPunchRow;
use crate::model::{AdhesionProblem, Exact, Period};

fn accuracy(d: &Digits) -> Vec<(String, f64)> {
    [("size", d.size), ("psi", d.psi), ("phi", d.phi), ("q1", d.q1), ("q2", d.q2)]
        .into_iter()
        .map(|(k, v)| (k.to_string(), v))
        .collect()
}

/// The answer of a verified MPFR solution.
pub fn mpfr_answer(p: &AdhesionProblem, v: &VerifiedSolution) -> AdhesionAnswer {
    let s = &v.solution;
    let d = &v.digits_verified;
    let sc = ScalesMpfr::new(p, &s.half_width, &s.normal_load, s.prec);
    let own = |x: &rug::Float| Measured::mpfr(x.clone(), x, d.size);
    let field = |name: &str, get: &dyn Fn(&crate::adhesion::PointValues) -> rug::Float, scale: &rug::Float, dg: f64| {
        let rows = s
            .points
            .iter()
            .map(|pt| FieldRow {
                x_over_a: exact_series::q_text(&pt.x_over_a),
                value: Measured::mpfr(get(pt), scale, dg),
            })
            .collect();
        (name.to_string(), rows)
    };
    AdhesionAnswer {
        provenance: Provenance {
            method: "mpfr",
            bits: Some(s.prec),
            nodes: Some(s.nodes),
            order: None,
            convention: convention_key(p),
        },
        kind: DigitsKind::Verified,
        lambda: matches!(p.period(), Period::Finite(_)).then(|| own(&s.lambda)),
        p2: own(&s.normal_load),
        half_width: own(&s.half_width),
        accuracy: accuracy(d),
        fields: vec![
            field("psi", &|pt| pt.psi.clone(), &sc.psi, d.psi),
            field("phi", &|pt| pt.phi.clone(), &sc.phi, d.phi),
            field("q1", &|pt| pt.q1.clone(), &sc.stress, d.q1),
            field("q2", &|pt| pt.q2.clone(), &sc.stress, d.q2),
        ],
        tension_zones: Some(
            s.tension
                .zones
                .iter()
                .map(|z| ZoneRow {
                    from: Num::Mpfr(z.from_x_over_a.clone()),
                    to: Num::Mpfr(z.to_x_over_a.clone()),
                    // from_x_over_a = 1 - delta_outer (the end farther from the edge).
                    from_one_minus: Num::Mpfr(z.delta_outer.clone()),
                    to_one_minus: Num::Mpfr(z.delta_inner.clone()),
                    refined: z.refined,
                })
                .collect(),
        ),
        warnings: v.warnings.clone(),
        stick: None,
    }
}

/// `provenance.convention` of Problem 2: `periodic` when that convention applies (a finite
/// period; docs/theory.md section 8), else absent as before (the `paper` problem, and the single
/// punch, which is the same in both).
fn convention_key(p: &AdhesionProblem) -> Option<&'static str> {
    p.periodic_surface().then_some("periodic")
}

/// The answer of the f64 method at the scene's points `points` (x/a, exact).
pub(crate) fn f64_answer(p: &AdhesionProblem, s: &AdhesionSolutionF64, points: &[Exact]) -> AdhesionAnswer {
    let d = &s.digits_estimated;
    let sc = ScalesF64::new(p, s.half_width, s.normal_load);
    let own = |x: f64| Measured::f64(x, x, d.size);
    let field = |name: &str, get: &dyn Fn(&crate::adhesion::PointValuesF64) -> f64, scale: f64, dg: f64| {
        let rows = s
            .points
            .iter()
            .zip(points)
            .map(|(pt, x)| FieldRow { x_over_a: exact_series::q_text(x), value: Measured::f64(get(pt), scale, dg) })
            .collect();
        (name.to_string(), rows)
    };
    AdhesionAnswer {
        provenance: Provenance {
            method: "f64",
            bits: Some(53),
            nodes: Some(s.terms),
            order: None,
            convention: convention_key(p),
        },
        kind: DigitsKind::Estimated,
        lambda: matches!(p.period(), Period::Finite(_)).then(|| own(s.lambda)),
        p2: own(s.normal_load),
        half_width: own(s.half_width),
        accuracy: accuracy(d),
        fields: vec![
            field("psi", &|pt| pt.psi, sc.psi, d.psi),
            field("phi", &|pt| pt.phi, sc.phi, d.phi),
            field("q1", &|pt| pt.q1, sc.stress, d.q1),
            field("q2", &|pt| pt.q2, sc.stress, d.q2),
        ],
        tension_zones: None,
        warnings: s.warnings.clone(),
        stick: None,
    }
}
