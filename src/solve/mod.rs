//! `periodic-contact solve SCENE`: runs a scene with a method and renders the result as JSON with
//! string values. Every number carries its accuracy: `digits_requested`, `digits_verified` (by a
//! second run with more bits and 1.5x the nodes for MPFR, more nodes for f64) and `accuracy` per
//! quantity. A value is printed with only as many significant digits as were verified (and no
//! more than requested); the series method states estimated, not verified, digits.

pub mod format;
pub mod answer_f64;
pub mod answer_mpfr;
pub mod answer_series;
pub mod render;
pub mod series_method;

use crate::adhesion::{self, AdhesionError};
use crate::model::ModelError as InvalidInput;
use crate::model::{Period, SlidingProblem};
use crate::scene::{Method, Scene, SceneProblem};
use crate::sliding::{self, collocation_f64, SlidingError};
use format::{digits_in_value, fmt_f64, fmt_float};
use serde_json::{json, Map, Value};

/// Why a solve did not produce an answer.
#[derive(Debug, thiserror::Error)]
pub enum SolveError {
    /// Invalid input (exit code 2).
    #[error(transparent)]
    Invalid(#[from] InvalidInput),
    /// No solution, no convergence (exit code 1).
    #[error("{0}")]
    Failed(String),
}

impl From<SlidingError> for SolveError {
    fn from(e: SlidingError) -> Self {
        match e {
            SlidingError::Parameter { parameter, value, expected } => {
                SolveError::Invalid(InvalidInput::new(parameter, value, expected))
            }
            other => SolveError::Failed(other.to_string()),
        }
    }
}

impl From<collocation_f64::SlidingF64Error> for SolveError {
    fn from(e: collocation_f64::SlidingF64Error) -> Self {
        use collocation_f64::SlidingF64Error as E;
        match &e {
            E::Input(crate::error::Error::Input(m)) => m.clone().into(),
            E::InvalidPoint { .. } => SolveError::Invalid(InvalidInput::new("scene", "(f64 method)", e.to_string())),
            _ => SolveError::Failed(e.to_string()),
        }
    }
}

impl From<AdhesionError> for SolveError {
    fn from(e: AdhesionError) -> Self {
        match e {
            AdhesionError::Model(m) => m.into(),
            AdhesionError::InvalidArgument { parameter, value, expected } => {
                SolveError::Invalid(InvalidInput::new(parameter, value, expected))
            }
            other => SolveError::Failed(other.to_string()),
        }
    }
}

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
/// refused (exit code 1) rather than printed.
pub fn solve_scene(scene: &Scene, req: SolveRequest) -> Result<Value, SolveError> {
    let v = solve_scene_unchecked(scene, req)?;
    if let Some(path) = first_non_finite("", &v) {
        return Err(SolveError::Failed(format!(
            "the {} method produced a non-finite value at {path}",
            req.method.name()
        )));
    }
    Ok(v)
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

fn solve_scene_unchecked(scene: &Scene, req: SolveRequest) -> Result<Value, SolveError> {
    match &scene.problem {
        SceneProblem::Sliding(p) => match req.method {
            Method::Mpfr => sliding_mpfr(p, scene, req),
            Method::F64 => sliding_f64(p, scene, req),
            Method::Series => series_method::sliding_series(p, scene, req),
        },
        SceneProblem::Adhesion(p) => match req.method {
            Method::Mpfr => adhesion_mpfr(p, scene, req),
            Method::F64 => adhesion_f64(p, scene, req),
            Method::Series => Err(SolveError::Invalid(InvalidInput::new(
                "--method",
                "series",
                "the adhesion problem is solved by \"mpfr\" or \"f64\"",
            ))),
        },
    }
}

fn provenance(method: &str, bits: Option<u32>, nodes: Option<usize>) -> Value {
    json!({
        "version": env!("CARGO_PKG_VERSION"),
        "method": method,
        "bits": bits.map(|b| b.to_string()),
        "nodes": nodes.map(|n| n.to_string()),
    })
}

fn sliding_mpfr(p: &SlidingProblem, scene: &Scene, req: SolveRequest) -> Result<Value, SolveError> {
    let sols = sliding::solve_verified(p, &scene.output.points, req.digits)?;
    let first = sols.first().ok_or_else(|| SolveError::Failed("no physical solution was found".into()))?;
    let mut top = Map::new();
    top.insert("problem".into(), Value::String("sliding".into()));
    let render = |v| render::sliding_json(&answer_mpfr::sliding_answer(v), req.digits);
    top.extend(render(first));
    if sols.len() > 1 {
        let all: Vec<Value> = sols.iter().map(|s| Value::Object(render(s))).collect();
        top.insert("solutions".into(), Value::Array(all));
    }
    Ok(Value::Object(top))
}

fn sliding_f64(p: &SlidingProblem, scene: &Scene, req: SolveRequest) -> Result<Value, SolveError> {
    let points: Vec<f64> =
        scene.output.points.iter().map(|x| crate::numerics::exact::to_f64(x).unwrap_or(f64::NAN)).collect();
    let sols = collocation_f64::solve_sliding_f64(p, &points, &collocation_f64::SolverOptions::default())?;
    let periodic = matches!(p.period(), Period::Finite(_));
    let requested = req.digits.min(crate::numerics::accuracy::F64_DIGITS_CAP as u32);
    let render = |s| render::sliding_json(&answer_f64::sliding_answer(s, periodic), requested);
    let mut top = Map::new();
    top.insert("problem".into(), json!("sliding"));
    top.extend(render(sols.primary()));
    // digits_requested states what the user asked, not the f64 cap.
    top.insert("digits_requested".into(), json!(req.digits.to_string()));
    if sols.solutions.len() > 1 {
        top.insert("solutions".into(), Value::Array(sols.solutions.iter().map(|s| Value::Object(render(s))).collect()));
    }
    Ok(Value::Object(top))
}

fn adhesion_mpfr(p: &crate::model::AdhesionProblem, scene: &Scene, req: SolveRequest) -> Result<Value, SolveError> {
    let v = adhesion::verified::solve_verified(p, &scene.output.points, req.digits)?;
    let s = &v.solution;
    let dv = &v.digits_verified;
    let digits = req.digits;
    let prec = s.prec;
    let k = match p.shape() {
        crate::model::PunchShape::Parabolic { k } => crate::numerics::exact::to_float(k, prec),
        crate::model::PunchShape::Sinusoidal { .. } => unreachable!("validated: adhesion is parabolic only"),
    };
    let e_star = crate::numerics::exact::to_float(p.material().contact_modulus(), prec);
    let a = &s.half_width;
    let ka = rug::Float::with_val(prec, &k * a);
    let ka2 = rug::Float::with_val(prec, &ka * a);
    let eka = rug::Float::with_val(prec, &e_star * &ka);
    let field = |name: &str,
                 get: &dyn Fn(&adhesion::solution::PointValues) -> &rug::Float,
                 scale: &rug::Float,
                 d: f64| {
        let list: Vec<Value> = s
            .points
            .iter()
            .map(|pt| {
                let x = get(pt);
                json!({"x_over_a": exact_series::q_text(&pt.x_over_a), name: fmt_float(x, digits_in_value(x, scale, d, digits))})
            })
            .collect();
        Value::Array(list)
    };
    let mut m = Map::new();
    m.insert("problem".into(), json!("adhesion"));
    m.insert(
        "lambda".into(),
        if matches!(p.period(), Period::Infinite) {
            Value::Null
        } else {
            json!(fmt_float(&s.lambda, digits_in_value(&s.lambda, &s.lambda, dv.size, digits)))
        },
    );
    m.insert(
        "P2".into(),
        json!(fmt_float(&s.normal_load, digits_in_value(&s.normal_load, &s.normal_load, dv.size, digits))),
    );
    m.insert("half_width".into(), json!(fmt_float(a, digits_in_value(a, a, dv.size, digits))));
    m.insert("digits_requested".into(), json!(digits.to_string()));
    m.insert("digits_verified".into(), json!(format!("{:.1}", dv.headline)));
    m.insert(
        "accuracy".into(),
        json!({"size": format!("{:.1}", dv.size), "psi": format!("{:.1}", dv.psi), "phi": format!("{:.1}", dv.phi),
               "q1": format!("{:.1}", dv.q1), "q2": format!("{:.1}", dv.q2)}),
    );
    m.insert("psi".into(), field("psi", &|pt| &pt.psi, &ka, dv.psi));
    m.insert("phi".into(), field("phi", &|pt| &pt.phi, &ka2, dv.phi));
    m.insert("q1".into(), field("q1", &|pt| &pt.q1, &eka, dv.q1));
    m.insert("q2".into(), field("q2", &|pt| &pt.q2, &eka, dv.q2));
    let zones: Vec<Value> = s
        .tension
        .zones
        .iter()
        .map(|z| json!({"from_x_over_a": fmt_float(&z.from_x_over_a, 6), "to_x_over_a": fmt_float(&z.to_x_over_a, 6), "refined": z.refined}))
        .collect();
    m.insert("tension_zones".into(), Value::Array(zones));
    m.insert("warnings".into(), Value::Array(v.warnings.iter().map(|w| json!(w)).collect()));
    m.insert("provenance".into(), provenance("mpfr", Some(prec), Some(s.nodes)));
    Ok(Value::Object(m))
}

fn adhesion_f64(p: &crate::model::AdhesionProblem, scene: &Scene, req: SolveRequest) -> Result<Value, SolveError> {
    let s = adhesion::solution::solve_f64(p, &scene.output.points)?;
    // A second f64 run is the same series; its accuracy is stated against the MPFR method in the
    // test suite (agreement to 1e-12), so here the digits are estimated, not verified.
    let digits = req.digits.min(12) as usize;
    let list = |get: &dyn Fn(&adhesion::solution::PointValuesF64) -> f64, name: &str| {
        Value::Array(
            s.points
                .iter()
                .map(|pt| json!({"x_over_a": fmt_f64(pt.x_over_a, 16), name: fmt_f64(get(pt), digits)}))
                .collect(),
        )
    };
    Ok(json!({
        "problem": "adhesion",
        "lambda": if matches!(p.period(), Period::Infinite) { Value::Null } else { json!(fmt_f64(s.lambda, digits)) },
        "P2": fmt_f64(s.normal_load, digits),
        "half_width": fmt_f64(s.half_width, digits),
        "digits_requested": req.digits.to_string(),
        "digits_verified": Value::Null,
        "digits_estimated": "12",
        "accuracy": {"note": "f64 lambda^2-series method: agreement with the MPFR method to 1e-12 is tested, not re-verified per run; use --method mpfr for verified digits"},
        "psi": list(&|pt| pt.psi, "psi"),
        "phi": list(&|pt| pt.phi, "phi"),
        "q1": list(&|pt| pt.q1, "q1"),
        "q2": list(&|pt| pt.q2, "q2"),
        "provenance": provenance("f64", Some(53), Some(s.terms)),
    }))
}
