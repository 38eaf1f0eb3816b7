//! Problem 2 under a loading law P1 = N(P2) (docs/theory.md section 10; issue 12) as JSON: the
//! verified MPFR solution ([`crate::loading_law::verified`]), or the f64 marching
//! method's ([`crate::loading_law::verified_f64`], the same keys, its digits from its own
//! two runs, `provenance.method` = `f64`), printed under the accuracy
//! rule of [`crate::numerics::accuracy`], each number with the digits its group verified:
//! - `ends` for lambda, a, b, c, l and the points' x (scale l);
//! - `loads` for P1, P2 (scale P2);
//! - `fields` for psi (scale k l), phi (k l^2), q1 and q2 (E* k l), the minimum over the points;
//! - `path` for the loading path (`"path"`: l_j = j l/16, j = 1..=16, with lambda_j, a_j, b_j, c_j
//!   on the scale l_j and P1_j, P2_j on P2_j;
//!   [`crate::loading_law::verified::PATH_STEPS`]), the minimum over the path.
//!
//! Derived here: `friction_needed`, the friction coefficient complete adhesion needs at the
//! printed points, max |q1|/q2 over the points where q2 > 0 (sampled at the points only, not a
//! maximum over the contact). Its digits are the fields' on the scale of its first-order error
//! bound: |d(q1/q2)| <= 10^-fields E* k l (q2 + |q1|)/q2^2. A point where q2 < 0 beyond the
//! fields' accuracy is a tension warning (complete adhesion then needs the interface to carry
//! tension there).
//!
//! `end_stress` ([`crate::loading_law::ends`]): at each end the phase phi of
//! sigma = q2 + i q1 ~ C (d/l)^(1/2 -+ i eps), the zone d/l < tension_within where q2 < 0 (the
//! oscillating singularity; a warning when it is not empty) and |q1|/q2 at d/l = 0.1 ... 1e-4
//! (null inside the tension zone): the friction complete adhesion needs grows without bound
//! toward the ends, so it is given against the distance.

use super::render::{digits_text, DigitsKind, Measured, Provenance};
use super::values::Values;
use crate::asymptotics::loading_law_modes::{problem_mode, ModeExponent};
use crate::loading_law::verified::{LawPathPoint, LawPoint, LawSolution, LawValues};
use crate::loading_law::verified_f64::LawSolutionF64;
use crate::model::OnPunchRow;
use crate::model::{Exact, LoadingLaw, LoadingLawProblem};
use crate::numerics::exact::to_float;
use rug::Float;
use serde_json::{json, Map, Value};

/// The law as the scene gives it: `{"tangential_ratio": "1/5"}` or
/// `{"loading_law": ["0", "1/5", "1/100"]}` (exact text).
pub(crate) fn law_json(law: &LoadingLaw) -> Value {
    match law {
        LoadingLaw::Linear(n) => json!({"tangential_ratio": exact_series::q_text(n)}),
        LoadingLaw::Polynomial(c) => {
            json!({"loading_law": c.iter().map(exact_series::q_text).collect::<Vec<_>>()})
        }
    }
}

/// The output scales of the loading-law problem at the solution (module doc).
struct LawScales {
    length: Float,
    load: Float,
    psi: Float,
    phi: Float,
    stress: Float,
}

impl LawScales {
    fn new(p: &LoadingLawProblem, sol: &LawSolution) -> Self {
        let v = &sol.values;
        let prec = v.l.prec();
        let kl = Float::with_val(prec, to_float(p.k(), prec) * &v.l);
        LawScales {
            length: v.l.clone(),
            load: v.p2.clone(),
            phi: Float::with_val(prec, &kl * &v.l),
            stress: Float::with_val(prec, to_float(p.material().contact_modulus(), prec) * &kl),
            psi: kl,
        }
    }
}

/// The friction the solution needs at the points: (max |q1|/q2 over the points with q2 > 0 beyond
/// the accuracy, the error scale of that ratio, the point's xh text), or None when no point has
/// q2 > 0.
pub fn friction_needed(points: &[LawPoint], stress: &Float, fields: f64) -> Option<(Float, Float, String)> {
    friction_needed_of(points.iter().map(|p| (&p.xh, &p.q1, &p.q2)), stress, fields)
}

/// [`friction_needed`] over (xh, q1, q2) triples (the report's profiles,
/// [`crate::loading_law::verified::LawStress`]).
pub fn friction_needed_of<'a>(
    points: impl IntoIterator<Item = (&'a Exact, &'a Float, &'a Float)>,
    stress: &Float,
    fields: f64,
) -> Option<(Float, Float, String)> {
    let noise = Float::with_val(stress.prec(), stress * Float::with_val(64, 10f64.powf(-fields)));
    let mut best: Option<(Float, Float, String)> = None;
    for (xh, q1, q2) in points.into_iter().filter(|(_, _, q2)| **q2 > noise) {
        let q1 = Float::with_val(q1.prec(), q1.abs_ref());
        let ratio = Float::with_val(q2.prec(), &q1 / q2);
        if best.as_ref().is_none_or(|b| ratio > b.0) {
            let q2sq = Float::with_val(q2.prec(), q2.square_ref());
            let scale = Float::with_val(q2.prec(), stress * Float::with_val(q2.prec(), q2 + &q1)) / q2sq;
            best = Some((ratio, scale, exact_series::q_text(xh)));
        }
    }
    best
}

/// The xh of the points (xh, q2) where q2 < 0 beyond the accuracy (a tension warning each).
pub fn tension_points_of<'a>(
    points: impl IntoIterator<Item = (&'a Exact, &'a Float)>,
    stress: &Float,
    fields: f64,
) -> Vec<&'a Exact> {
    let noise = Float::with_val(stress.prec(), stress * Float::with_val(64, 10f64.powf(-fields)));
    points.into_iter().filter(|(_, q2)| Float::with_val(q2.prec(), -*q2) > noise).map(|(xh, _)| xh).collect()
}

/// The loading path as JSON: one object per contact l_j (values on the scales l_j and P2_j of
/// that contact, `path` digits).
pub fn path_json(path: &[LawPathPoint], digits: f64, requested: u32) -> Value {
    path_json_held(path, digits, requested).0
}

/// [`path_json`] and the digits its printed values hold ([`Measured::held`], their minimum).
fn path_json_held(path: &[LawPathPoint], digits: f64, requested: u32) -> (Value, f64) {
    let held = std::cell::Cell::new(digits);
    let print = |x: &Float, scale: &Float| {
        let m = Measured::mpfr(x.clone(), scale, digits);
        held.set(held.get().min(m.held(requested)));
        m.print(requested)
    };
    let v = Value::Array(
        path.iter()
            .map(|p| {
                json!({
                    "lambda": print(&p.lambda, &p.lambda),
                    "l": print(&p.l, &p.l),
                    "a": print(&p.a, &p.l),
                    "b": print(&p.b, &p.l),
                    "c": print(&p.c, &p.l),
                    "P1": print(&p.p1, &p.p2),
                    "P2": print(&p.p2, &p.p2),
                })
            })
            .collect(),
    );
    (v, held.get())
}

/// The JSON object of a verified loading-law solution at `requested` digits, and its typed values
/// (the scalars `lambda`, `a`, `b`, `c`, `l`, `P1`, `P2`, `friction_needed`; the fields `x`, `psi`,
/// `phi`, `q1`, `q2` at `xh`).
pub fn law_answer_json(p: &LoadingLawProblem, sol: &LawSolution, requested: u32) -> (Map<String, Value>, Values) {
    law_answer_json_with_mode(p, sol, requested, problem_mode(p).ok())
}

/// [`law_answer_json`] with the problem's mode computed by the caller (`problem_mode`, None where
/// it cannot be computed), e.g. on another thread while the solution is solved for.
pub(crate) fn law_answer_json_with_mode(
    p: &LoadingLawProblem,
    sol: &LawSolution,
    requested: u32,
    mode: Option<ModeExponent>,
) -> (Map<String, Value>, Values) {
    let prov = Provenance {
        method: "mpfr",
        bits: Some(sol.values.l.prec()),
        nodes: Some(sol.values.nodes),
        order: None,
        convention: Some(p.convention().name()),
    };
    answer_json(p, sol, requested, prov, mode)
}

/// The JSON object of the f64 marching solution: the same keys as [`law_answer_json`], the values
/// carried exactly into 53-bit numbers and printed under the same rule with the f64 method's
/// digits; `provenance.nodes` is blocks x points per block.
pub(crate) fn law_answer_json_f64(
    p: &LoadingLawProblem,
    sol: &LawSolutionF64,
    requested: u32,
    mode: Option<ModeExponent>,
) -> (Map<String, Value>, Values) {
    let v = &sol.values;
    let f = |x: f64| Float::with_val(53, x);
    let values = LawValues {
        lambda: f(v.lambda),
        a: f(v.a),
        b: f(v.b),
        c: f(v.c),
        l: f(v.l),
        p2: f(v.p2),
        p1: f(v.p1),
        points: v
            .points
            .iter()
            .map(|q| LawPoint { xh: q.xh.clone(), x: f(q.x), psi: f(q.psi), phi: f(q.phi), q1: f(q.q1), q2: f(q.q2) })
            .collect(),
        path: Vec::new(),
        stresses: Vec::new(),
        nodes: v.nodes,
        ends: Vec::new(),
        eps: f(crate::params::adhesion::AdhesionParamsF64::new(p.material()).eps),
    };
    let prov = Provenance {
        method: "f64",
        bits: Some(53),
        nodes: Some(v.blocks * v.nodes),
        order: None,
        convention: Some(p.convention().name()),
    };
    answer_json(p, &LawSolution { values, digits: sol.digits }, requested, prov, mode)
}

fn answer_json(
    p: &LoadingLawProblem,
    sol: &LawSolution,
    requested: u32,
    prov: Provenance,
    mode: Option<ModeExponent>,
) -> (Map<String, Value>, Values) {
    let v = &sol.values;
    let d = &sol.digits;
    let sc = LawScales::new(p, sol);
    // What the printed values of each accuracy group hold (issue 34: a printed value holds the
    // digits claimed for it): ends (lambda, a, b, c, l, x), loads, fields (with the friction needed).
    let held = [d.ends, d.loads, d.fields].map(std::cell::Cell::new);
    let (ends_g, loads_g, fields_g) = (&held[0], &held[1], &held[2]);
    // Every printed number is also recorded, typed, under its key (and point).
    let values = std::cell::RefCell::new(Values::default());
    let print_at =
        |group: &std::cell::Cell<f64>, key: &str, at: Option<&Exact>, x: &Float, scale: &Float, digits: f64| {
            let m = Measured::mpfr(x.clone(), scale, digits);
            group.set(group.get().min(m.held(requested)));
            let q = m.quantity(requested, DigitsKind::Verified);
            let text = q.text.clone();
            match at {
                None => values.borrow_mut().push(key, q),
                Some(xh) => values.borrow_mut().push_point(key, "xh", exact_series::q_text(xh), q),
            }
            text
        };
    let print_in = |group: &std::cell::Cell<f64>, key: &str, x: &Float, scale: &Float, digits: f64| {
        print_at(group, key, None, x, scale, digits)
    };
    let mut m = Map::new();
    m.insert("problem".into(), json!("adhesion"));
    m.insert("law".into(), law_json(p.law()));
    // lambda = pi l/L: none for the single punch.
    let lambda = match p.period() {
        crate::model::Period::Finite(_) => json!(print_in(ends_g, "lambda", &v.lambda, &v.lambda, d.ends)),
        crate::model::Period::Infinite => Value::Null,
    };
    m.insert("lambda".into(), lambda);
    for (key, x) in [("a", &v.a), ("b", &v.b), ("c", &v.c), ("l", &v.l)] {
        m.insert(key.into(), json!(print_in(ends_g, key, x, &sc.length, d.ends)));
    }
    m.insert("P1".into(), json!(print_in(loads_g, "P1", &v.p1, &sc.load, d.loads)));
    m.insert("P2".into(), json!(print_in(loads_g, "P2", &v.p2, &sc.load, d.loads)));
    let friction = friction_needed(&v.points, &sc.stress, d.fields);
    m.insert(
        "friction_needed".into(),
        friction
            .as_ref()
            .map_or(Value::Null, |(r, scale, _)| json!(print_in(fields_g, "friction_needed", r, scale, d.fields))),
    );
    m.insert("friction_needed_at_xh".into(), friction.as_ref().map_or(Value::Null, |(_, _, xh)| json!(xh)));
    let ends = if v.ends.is_empty() { Value::Null } else { end_stress_json(sol, requested) };
    m.insert("end_stress".into(), ends);
    m.insert("digits_requested".into(), json!(requested.to_string()));
    let points: Vec<Value> = v
        .points
        .iter()
        .map(|pt| {
            json!({
                "xh": exact_series::q_text(&pt.xh),
                "x": print_at(ends_g, "x", Some(&pt.xh), &pt.x, &sc.length, d.ends),
                "psi": print_at(fields_g, "psi", Some(&pt.xh), &pt.psi, &sc.psi, d.fields),
                "phi": print_at(fields_g, "phi", Some(&pt.xh), &pt.phi, &sc.phi, d.fields),
                "q1": print_at(fields_g, "q1", Some(&pt.xh), &pt.q1, &sc.stress, d.fields),
                "q2": print_at(fields_g, "q2", Some(&pt.xh), &pt.q2, &sc.stress, d.fields),
            })
        })
        .collect();
    // The f64 method gives neither the path at l_j = j l/16 nor the end stresses: null.
    let (path, path_held) = match v.path.is_empty() {
        true => (Value::Null, f64::INFINITY),
        false => path_json_held(&v.path, d.path, requested),
    };
    // The headline: the solution's own, at most what every printed group holds.
    let headline = held.iter().map(std::cell::Cell::get).fold(d.headline.min(path_held), f64::min);
    m.insert("digits_verified".into(), json!(digits_text(headline)));
    m.insert(
        "accuracy".into(),
        json!({
            "ends": digits_text(ends_g.get()),
            "loads": digits_text(loads_g.get()),
            "fields": digits_text(fields_g.get()),
            "path": if v.path.is_empty() { Value::Null } else { json!(digits_text(path_held)) },
        }),
    );
    m.insert("points".into(), Value::Array(points));
    m.insert("path".into(), path);
    let mut warnings = tension_warnings(&v.points, &sc.stress, d.fields, requested);
    for (end, name) in v.ends.iter().zip(["leading", "trailing"]) {
        if end.tension_within > 0 {
            let zone = Measured::mpfr(end.tension_within.clone(), &end.tension_within, sol.tension_zone_digits())
                .print(requested);
            warnings.push(json!(format!(
                "tension: q2 < 0 within d/l < {zone} of the {name} end (the oscillating singularity, eps = {:.4}): complete adhesion there needs tension and unbounded friction",
                v.eps.to_f64()
            )));
        }
    }
    // The homogeneous mode eta^mu* of the self-similar start (n = N'(0)): where it exists the
    // problem fixes its history only up to C eta^mu* (asymptotics::loading_law_modes).
    // None when it cannot be computed: the self-similar start has no solution with both ends
    // advancing, a case the solvers refuse on their own. `mode` is `problem_mode(p).ok()`.
    m.insert("mode".into(), mode.as_ref().map_or(Value::Null, |m| m.json(0)));
    let mode_text = mode.as_ref().and_then(|m| m.value_text());
    // Fewer digits than asked (the f64 method's cap is 15): say so and why when it is known.
    let attainable = if prov.method == "f64" { (requested as f64).min(15.0) } else { requested as f64 };
    if d.headline + 0.5 < attainable {
        let why = match &mode_text {
            Some(mu) => format!(
                "the law and both edge conditions fix the history only up to C eta^mu* with mu* = {mu} \
                 (homogeneous mode of the self-similar start, n = N'(0), eps = {:.4}; asymptotics::loading_law_modes): \
                 a discretisation sets C by its own error at small sizes, which grows like (Lambda/eta)^mu*",
                v.eps.to_f64()
            ),
            None => format!(
                "at small nu (eps = {:.4}) the loading-law problem is ill-conditioned (its homogeneous modes: asymptotics::loading_law_modes)",
                v.eps.to_f64()
            ),
        };
        warnings.push(json!(format!(
            "accuracy: only {} of the {} digits requested were verified (two runs agree no further); {why}",
            digits_text(d.headline),
            requested,
        )));
    }
    m.insert("warnings".into(), Value::Array(warnings));
    m.insert("provenance".into(), prov.json());
    (m, values.into_inner())
}

/// The ends' phases, tension zones and needed friction against the distance (module doc).
fn end_stress_json(sol: &LawSolution, requested: u32) -> Value {
    let v = &sol.values;
    let d = &sol.digits;
    let mut m = Map::new();
    // What the printed values hold (issue 34), for the digits stated below.
    let (held_friction, held_phases) = (std::cell::Cell::new(d.friction), std::cell::Cell::new(d.end_phases));
    let print_in = |held: &std::cell::Cell<f64>, m: Measured| {
        held.set(held.get().min(m.held(requested)));
        m.print(requested)
    };
    for (end, name) in v.ends.iter().zip(["leading", "trailing"]) {
        let one = Float::with_val(end.phase.prec(), 1);
        let mut friction = Map::new();
        for (k, mu) in crate::loading_law::ends::DISTANCES.iter().zip(&end.friction_needed) {
            let value = mu
                .as_ref()
                .map_or(Value::Null, |mu| json!(print_in(&held_friction, Measured::mpfr(mu.clone(), mu, d.friction))));
            friction.insert(format!("1e{k}"), value);
        }
        m.insert(
            name.into(),
            json!({
                "phase": print_in(&held_phases, Measured::mpfr(end.phase.clone(), &one, d.end_phases)),
                "tension_within": Measured::mpfr(end.tension_within.clone(), &end.tension_within, sol.tension_zone_digits()).print(requested),
                "friction_needed_at_distance": Value::Object(friction),
            }),
        );
    }
    m.insert(
        "digits".into(),
        json!({"friction": digits_text(held_friction.get()), "phases": digits_text(held_phases.get())}),
    );
    Value::Object(m)
}

/// One warning per point where q2 < 0 beyond the fields' accuracy.
fn tension_warnings(points: &[LawPoint], stress: &Float, fields: f64, requested: u32) -> Vec<Value> {
    let tension = tension_points_of(points.iter().map(|p| (&p.xh, &p.q2)), stress, fields);
    points
        .iter()
        .filter(|pt| tension.contains(&&pt.xh))
        .map(|pt| {
            json!(format!(
                "tension: q2 = {} < 0 at xh = {}; complete adhesion needs the interface to carry tension there",
                Measured::mpfr(pt.q2.clone(), stress, fields).print(requested),
                exact_series::q_text(&pt.xh)
            ))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Exact;

    fn point(xh: i64, q1: f64, q2: f64) -> LawPoint {
        let f = |x: f64| Float::with_val(128, x);
        LawPoint { xh: Exact::from_integer(xh.into()), x: f(0.0), psi: f(0.0), phi: f(0.0), q1: f(q1), q2: f(q2) }
    }

    /// max |q1|/q2 over q2 > 0 (a point in tension and a point at the noise level are skipped);
    /// the error scale is E* k l (q2 + |q1|)/q2^2 at the maximising point.
    #[test]
    fn friction_needed_is_the_largest_ratio_where_q2_is_positive() {
        let stress = Float::with_val(128, 2.0);
        let pts = [point(0, 0.1, 1.0), point(1, -0.3, 0.5), point(2, 5.0, -1.0), point(3, 1.0, 1e-30)];
        let (r, scale, xh) = friction_needed(&pts, &stress, 20.0).unwrap();
        assert!((r.to_f64() - 0.6).abs() < 1e-15, "{r}");
        assert!((scale.to_f64() - 2.0 * 0.8 / 0.25).abs() < 1e-13, "{scale}");
        assert_eq!(xh, "1");
        assert!(friction_needed(&pts[2..], &stress, 20.0).is_none());
        let w = tension_warnings(&pts, &stress, 20.0, 10);
        assert_eq!(w.len(), 1);
        assert!(w[0].as_str().unwrap().contains("xh = 2"), "{w:?}");
    }
}
