//! `periodic-contact solve SCENE`: runs a scene with a method and renders the result as JSON with
//! string values. Every number carries its accuracy: `digits_requested`, `digits_verified` (by a
//! second run with more bits and 1.5x the nodes for MPFR, more nodes for f64) or `digits_estimated`
//! (the series method; Problem 2's f64 method), and `accuracy` per quantity. Each method's solution
//! becomes one answer struct (`answer_*`), printed by the one renderer of its problem ([`render`])
//! under the accuracy rule of [`crate::numerics::accuracy`].

pub mod answer_adhesion;
pub mod answer_f64;
pub mod answer_law;
pub mod answer_mpfr;
pub mod answer_pade;
pub mod answer_series;
pub mod choice;
pub mod format;
pub mod render;

use crate::adhesion;
use crate::error::Error;
use crate::model::{AdhesionProblem, Convention, LoadingLawProblem, Period, SlidingProblem};
use crate::scene::{Method, Scene, SceneProblem};
use crate::sliding::{self, collocation_f64};
use serde_json::{json, Map, Value};

/// How to run a scene.
#[derive(Debug, Clone, Copy)]
pub struct SolveRequest {
    /// Method.
    pub method: Method,
    /// Digits requested.
    pub digits: u32,
    /// Order of the truncated series (series method).
    pub series_order: usize,
}

/// Default digits when neither the scene nor the command line gives them.
pub const DEFAULT_DIGITS: u32 = 30;

/// Runs the scene and renders the JSON result. A non-finite number anywhere in the result is
/// refused ([`Error::NoConvergence`]) rather than printed.
pub fn solve_scene(scene: &Scene, req: SolveRequest) -> Result<Value, Error> {
    let v = match &scene.problem {
        SceneProblem::Sliding(p) => match req.method {
            Method::Mpfr => sliding_mpfr(p, scene, req),
            Method::F64 => sliding_f64(p, scene, req),
            Method::Series => sliding_series(p, scene, req),
            Method::Pade => sliding_pade(p, scene, req),
        }
        .map_err(|e| with_periodic_hint(e, p)),
        SceneProblem::Adhesion(p) => match req.method {
            Method::Mpfr => adhesion_mpfr(p, scene, req),
            Method::F64 => adhesion_f64(p, scene, req),
            Method::Series | Method::Pade => Err(Error::input(
                "--method",
                req.method.name(),
                "the adhesion problem is solved by \"mpfr\" or \"f64\" (its series and their Pade approximants: \
                 `periodic-contact series adhesion --nu R --pade`)",
            )),
        },
        SceneProblem::LoadingLaw(p) => match req.method {
            Method::Mpfr => law_mpfr(p, scene, req),
            Method::F64 => law_f64(p, scene, req),
            Method::Series | Method::Pade => Err(Error::input(
                "--method",
                req.method.name(),
                "the loading-law problem is solved by \"mpfr\" or \"f64\" (no series method yet)",
            )),
        },
    }?;
    if let Some(path) = first_non_finite("", &v) {
        return Err(Error::NoConvergence {
            what: format!("the {} method produced a non-finite value at {path}", req.method.name()),
        });
    }
    Ok(v)
}

/// A refusal in the `paper` convention (not physical, or no solution) that the `periodic`
/// convention would solve says so (docs/theory.md section 8): the fast f64 method is run on the same
/// problem in `periodic` and, when it finds a physical contact, the message names the way forward.
fn with_periodic_hint(e: Error, p: &SlidingProblem) -> Error {
    if p.convention() != Convention::Paper || p.kappa_and_tau0_vanish() || matches!(p.period(), Period::Infinite) {
        return e;
    }
    let Ok(periodic) = p.to_builder().convention(Convention::PeriodicSurface).build() else { return e };
    let solved = collocation_f64::solve_sliding_f64(&periodic, &[], &collocation_f64::SolverOptions::default()).is_ok();
    let hint =
        "; in the `periodic` convention (--convention periodic, docs/theory.md section 8: the surface closes over \
                the period) the f64 method finds a physical contact at this load";
    match e {
        Error::NotPhysical { why } if solved => Error::NotPhysical { why: format!("{why}{hint}") },
        Error::NoSolution { why } if solved => Error::NoSolution { why: format!("{why}{hint}") },
        other => other,
    }
}

/// The path of the first string value that is not a finite number's text (NaN, inf).
fn first_non_finite(path: &str, v: &Value) -> Option<String> {
    match v {
        Value::String(s) => {
            let t = s.trim().trim_start_matches(['-', '+']).to_ascii_lowercase();
            matches!(t.as_str(), "nan" | "inf" | "infinity" | "@nan@" | "@inf@").then(|| path.to_string())
        }
        Value::Object(m) => m.iter().find_map(|(k, x)| first_non_finite(&format!("{path}.{k}"), x)),
        Value::Array(a) => a.iter().enumerate().find_map(|(i, x)| first_non_finite(&format!("{path}[{i}]"), x)),
        _ => None,
    }
}

/// `{"shape": "polynomial", "coefficients": ["0", "0", "1"]}`: the punch as the scene gives it
/// (exact parameters as text), for the provenance of every Problem 1 answer.
pub fn punch_json(shape: &crate::model::PunchShape) -> Value {
    let mut m = Map::new();
    m.insert("shape".into(), json!(shape.name()));
    match shape {
        crate::model::PunchShape::Polynomial { coefficients } => {
            m.insert("coefficients".into(), json!(coefficients.iter().map(|c| c.to_string()).collect::<Vec<_>>()));
        }
        other => {
            for (name, value) in other.parameters() {
                m.insert(name.into(), json!(value));
            }
        }
    }
    Value::Object(m)
}

/// `{"problem": "sliding", ...first answer, "solutions": [...]}` (the list only when several
/// contacts are physical); each answer's provenance names the punch ([`punch_json`]).
fn sliding_top(mut answers: Vec<Map<String, Value>>, p: &SlidingProblem) -> Value {
    for a in answers.iter_mut() {
        if let Some(Value::Object(prov)) = a.get_mut("provenance") {
            prov.insert("punch".into(), punch_json(p.shape()));
        }
    }
    let mut top = Map::new();
    top.insert("problem".into(), json!("sliding"));
    if let Some(first) = answers.first() {
        top.extend(first.clone());
    }
    if answers.len() > 1 {
        top.insert("solutions".into(), Value::Array(answers.into_iter().map(Value::Object).collect()));
    }
    Value::Object(top)
}

fn sliding_mpfr(p: &SlidingProblem, scene: &Scene, req: SolveRequest) -> Result<Value, Error> {
    let sols = sliding::solve_verified(p, &scene.output.points, req.digits)?;
    if sols.is_empty() {
        return Err(Error::NotPhysical { why: "no physical contact was found".into() });
    }
    Ok(sliding_top(
        sols.iter()
            .map(|v| render::sliding_json(&answer_mpfr::sliding_answer(v, p.convention()), req.digits))
            .collect(),
        p,
    ))
}

fn sliding_f64(p: &SlidingProblem, scene: &Scene, req: SolveRequest) -> Result<Value, Error> {
    let points: Vec<f64> =
        scene.output.points.iter().map(|x| crate::numerics::exact::to_f64(x).unwrap_or(f64::NAN)).collect();
    let sols = collocation_f64::solve_sliding_f64(p, &points, &collocation_f64::SolverOptions::default())?;
    let periodic = matches!(p.period(), Period::Finite(_));
    let shown = req.digits.min(crate::numerics::accuracy::F64_PRINT_DIGITS);
    let answers = sols
        .solutions
        .iter()
        .map(|s| {
            let mut m = render::sliding_json(&answer_f64::sliding_answer(s, periodic, p.convention()), shown);
            // digits_requested states what the user asked, not the f64 cap.
            m.insert("digits_requested".into(), json!(req.digits.to_string()));
            m
        })
        .collect();
    Ok(sliding_top(answers, p))
}

fn sliding_series(p: &SlidingProblem, scene: &Scene, req: SolveRequest) -> Result<Value, Error> {
    let s = sliding::series::solve_series(p, &scene.output.points, req.series_order, req.digits)?;
    Ok(sliding_top(
        vec![render::sliding_json(&answer_series::sliding_answer(&s, req.digits, p.convention()), req.digits)],
        p,
    ))
}

fn sliding_pade(p: &SlidingProblem, scene: &Scene, req: SolveRequest) -> Result<Value, Error> {
    let s = sliding::series::pade::solve_pade(p, &scene.output.points, req.series_order, req.digits)?;
    Ok(sliding_top(vec![answer_pade::sliding_json(&s, req.digits, p.convention())], p))
}

fn adhesion_mpfr(p: &AdhesionProblem, scene: &Scene, req: SolveRequest) -> Result<Value, Error> {
    let v = adhesion::solve_verified(p, &scene.output.points, req.digits)?;
    Ok(Value::Object(render::adhesion_json(&answer_adhesion::mpfr_answer(p, &v), req.digits)))
}

fn adhesion_f64(p: &AdhesionProblem, scene: &Scene, req: SolveRequest) -> Result<Value, Error> {
    let s = adhesion::solve_f64(p, &scene.output.points)?;
    let shown = req.digits.min(crate::numerics::accuracy::F64_PRINT_DIGITS);
    let mut m = render::adhesion_json(&answer_adhesion::f64_answer(p, &s, &scene.output.points), shown);
    m.insert("digits_requested".into(), json!(req.digits.to_string()));
    // Which f64 method answered: the lambda^2 series, or the collocation in eta beyond its radius.
    m.insert("route".into(), json!(s.route.name()));
    Ok(Value::Object(m))
}

fn law_mpfr(p: &LoadingLawProblem, scene: &Scene, req: SolveRequest) -> Result<Value, Error> {
    let sol = adhesion::loading_law::verified::solve_law(p, &scene.output.points, req.digits)?;
    Ok(Value::Object(answer_law::law_answer_json(p, &sol, req.digits)))
}

fn law_f64(p: &LoadingLawProblem, scene: &Scene, req: SolveRequest) -> Result<Value, Error> {
    let sol = adhesion::loading_law::verified_f64::solve_law_f64(p, &scene.output.points)?;
    let shown = req.digits.min(crate::numerics::accuracy::F64_PRINT_DIGITS);
    let mut m = answer_law::law_answer_json_f64(p, &sol, shown);
    // digits_requested states what the user asked, not the f64 cap.
    m.insert("digits_requested".into(), json!(req.digits.to_string()));
    Ok(Value::Object(m))
}
