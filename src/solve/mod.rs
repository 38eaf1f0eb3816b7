//! `periodic-contact solve SCENE`: runs a scene with a method and renders the result as JSON with
//! string values. Every number carries its accuracy: `digits_requested`, `digits_verified` (by a
//! second run with more bits and 1.5x the nodes for MPFR, more nodes for f64) or `digits_estimated`
//! (the series method; Problem 2's f64 method), and `accuracy` per quantity. Each method's solution
//! becomes one answer struct (`answer_*`), printed by the one renderer of its problem ([`render`])
//! under the accuracy rule of [`crate::numerics::accuracy`].

pub mod answer_adhesion;
pub mod answer_analytic;
pub(crate) mod answer_f64;
pub mod answer_friction;
pub mod answer_friction_row;
pub mod answer_law;
pub mod answer_mpfr;
pub(crate) mod answer_pade;
pub(crate) mod answer_series;
pub mod batch;
pub mod choice;
pub mod format;
pub mod render;
pub(crate) mod values;

use crate::adhesion;
use crate::error::Error;
use crate::model::OnPunchRow;
use crate::model::{AdhesionProblem, Convention, LoadingLawProblem, Period, SlidingProblem};
use crate::scene::{Method, Scene, SceneProblem};
use crate::sliding::{self, collocation_f64};
use render::DigitsKind;
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

/// The accuracy an answer claims, as a number: the minimum over its accuracy table (what
/// `digits_verified` or `digits_estimated` prints, to one decimal), and whether it was verified.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Claim {
    /// Digits of the least accurate quantity, on its scale.
    pub digits: f64,
    /// Verified by a second run, or estimated.
    pub kind: DigitsKind,
}

/// One solved scene: the typed claim of its accuracy, which the method choice reads to decide
/// whether a dearer method must run ([`choice::solve_chosen`]), the typed values of each solution
/// ([`values::Values`]: every printed number with its digits and scale) and the rendered JSON of
/// `periodic-contact solve --json` (string values; docs/theory.md section 14), one rendering of
/// the same numbers.
#[derive(Debug, Clone, PartialEq)]
pub struct Answer {
    /// The accuracy claimed.
    pub claim: Claim,
    /// The values of each solution (Problem 1 may have several physical contacts; the first is the
    /// one the JSON's top level prints).
    pub solutions: Vec<values::Values>,
    /// The JSON.
    pub json: Value,
}

impl Answer {
    /// The first solution's quantity printed under `key` (`"P2"`, `"l"`, `"half_width"`, ...).
    pub fn get(&self, key: &str) -> Option<&values::Quantity> {
        self.solutions.first().and_then(|v| v.get(key))
    }

    /// The first solution's field `name` at the requested points (`"p"`, `"q2"`, ...).
    pub fn field(&self, name: &str) -> Option<&values::Field> {
        self.solutions.first().and_then(|v| v.field(name))
    }
}

/// Runs the scene and renders the JSON result ([`solve_answer`] without its claim).
pub fn solve_scene(scene: &Scene, req: SolveRequest) -> Result<Value, Error> {
    solve_answer(scene, req).map(|a| a.json)
}

/// Runs the scene: the answer with its claimed accuracy. A non-finite number anywhere in the
/// result is refused ([`Error::NoConvergence`]) rather than printed.
pub fn solve_answer(scene: &Scene, req: SolveRequest) -> Result<Answer, Error> {
    let (v, claim, solutions) = match &scene.problem {
        SceneProblem::Sliding(p) => match req.method {
            Method::Mpfr => sliding_mpfr(p, scene, req),
            Method::F64 => sliding_f64(p, scene, req),
            Method::Series => sliding_series(p, scene, req),
            Method::Pade => sliding_pade(p, scene, req),
            Method::Analytic => Err(Error::input(
                "--method",
                "analytic",
                "the analytic method takes Problem 2 (complete adhesion); Problem 1 is solved by \"mpfr\", \"f64\", \
                 \"series\" or \"pade\"",
            )),
        }
        .map_err(|e| with_periodic_hint(e, p)),
        SceneProblem::Adhesion(p) => match (p.friction(), req.method) {
            (Some(mu), _) => adhesion_friction(p, scene, mu, req),
            (None, Method::Mpfr) => adhesion_mpfr(p, scene, req),
            (None, Method::F64) => adhesion_f64(p, scene, req),
            (None, Method::Analytic) => adhesion_analytic(p, req),
            (None, Method::Series | Method::Pade) => Err(Error::input(
                "--method",
                req.method.name(),
                "the adhesion problem is solved by \"mpfr\", \"f64\" or \"analytic\" (its series and their Pade \
                 approximants: `periodic-contact series adhesion --nu R --pade`)",
            )),
        },
        SceneProblem::LoadingLaw(p) => match req.method {
            Method::Mpfr => law_mpfr(p, scene, req),
            Method::F64 => law_f64(p, scene, req),
            Method::Series | Method::Pade | Method::Analytic => Err(Error::input(
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
    Ok(Answer { claim, solutions, json: v })
}

/// What a method returns here: the JSON, the claim of its (first) answer and the typed values of
/// each solution.
type Rendered = (Value, Claim, Vec<values::Values>);

/// The claim of a Problem 1 answer.
fn sliding_claim(a: &render::SlidingAnswer) -> Claim {
    Claim { digits: a.headline(), kind: a.kind }
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

/// The value of the quantity printed under `key` (NaN when absent: no warning is then made).
fn number(v: &values::Values, key: &str) -> f64 {
    v.get(key).map_or(f64::NAN, |q| q.value)
}

/// Appends the small-slope warning of the contact [`left`, `right`] to the answer's `warnings`
/// (docs/theory.md section 9: one rule for every shape in both problems; never a refusal).
fn slope_warning(m: &mut Map<String, Value>, shape: &crate::model::PunchShape, period: &Period, left: f64, right: f64) {
    let l = match period {
        Period::Finite(l) => crate::numerics::exact::to_f64(l),
        Period::Infinite => None,
    };
    if let Some(w) = crate::params::profile::slope_warning(shape, l, left, right) {
        match m.entry("warnings").or_insert_with(|| Value::Array(Vec::new())) {
            Value::Array(list) => list.push(json!(w)),
            other => *other = json!([w]),
        }
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

/// The `convention_note` of an answer in the `paper` convention whose constant K of
/// docs/theory.md section 8 is not zero by construction (friction or wear, adhesive friction, or a
/// tangential load): the surface does not close over the period, and `periodic` would close it.
pub const PAPER_CONVENTION_NOTE: &str =
    "solved in the paper convention: [2.8] as the paper states it. With friction, wear, \
     adhesive friction or a tangential load the surface does not close over the period (the closure defect M, \
     docs/theory.md section 8); the periodic convention adds K = (kappa P2 - 2 beta l tau0)/L and closes it: \
     solve --convention periodic, or [problem] convention = \"periodic\" in the scene";

/// `{"problem": "sliding", ["convention_note"], ...first answer, "solutions": [...]}` (the list
/// only when several contacts are physical); each answer's provenance names the punch
/// ([`punch_json`]); `convention_note` ([`PAPER_CONVENTION_NOTE`]) where `paper` is solved with
/// kappa != 0 or tau0 != 0 over a finite period.
fn sliding_top(mut answers: Vec<Map<String, Value>>, values: &[values::Values], p: &SlidingProblem) -> Value {
    for a in answers.iter_mut() {
        if let Some(Value::Object(prov)) = a.get_mut("provenance") {
            prov.insert("punch".into(), punch_json(p.shape()));
        }
    }
    for (a, v) in answers.iter_mut().zip(values) {
        let (left, right) = (-number(v, "a"), number(v, "b"));
        slope_warning(a, p.shape(), p.period(), left, right);
    }
    let mut top = Map::new();
    top.insert("problem".into(), json!("sliding"));
    if p.convention() == Convention::Paper && !p.kappa_and_tau0_vanish() && matches!(p.period(), Period::Finite(_)) {
        top.insert("convention_note".into(), json!(PAPER_CONVENTION_NOTE));
    }
    if let Some(first) = answers.first() {
        top.extend(first.clone());
    }
    if answers.len() > 1 {
        top.insert("solutions".into(), Value::Array(answers.into_iter().map(Value::Object).collect()));
    }
    Value::Object(top)
}

fn sliding_mpfr(p: &SlidingProblem, scene: &Scene, req: SolveRequest) -> Result<Rendered, Error> {
    let sols = sliding::solve_verified(p, &scene.output.points, req.digits)?;
    let answers: Vec<_> = sols.iter().map(|v| answer_mpfr::sliding_answer(v, p.convention())).collect();
    let Some(first) = answers.first() else {
        return Err(Error::NotPhysical { why: "no physical contact was found".into() });
    };
    let claim = sliding_claim(first);
    let values: Vec<_> = answers.iter().map(|a| render::sliding_values(a, req.digits)).collect();
    Ok((sliding_top(answers.iter().map(|a| render::sliding_json(a, req.digits)).collect(), &values, p), claim, values))
}

fn sliding_f64(p: &SlidingProblem, scene: &Scene, req: SolveRequest) -> Result<Rendered, Error> {
    let points: Vec<f64> =
        scene.output.points.iter().map(|x| crate::numerics::exact::to_f64(x).unwrap_or(f64::NAN)).collect();
    let sols = collocation_f64::solve_sliding_f64(p, &points, &collocation_f64::SolverOptions::default())?;
    let periodic = matches!(p.period(), Period::Finite(_));
    let shown = req.digits.min(crate::numerics::accuracy::F64_PRINT_DIGITS - 1);
    let typed: Vec<_> =
        sols.solutions.iter().map(|s| answer_f64::sliding_answer(s, periodic, p.convention())).collect();
    let Some(first) = typed.first() else {
        return Err(Error::NotPhysical { why: "no physical contact was found".into() });
    };
    let claim = sliding_claim(first);
    let answers = typed
        .iter()
        .map(|a| {
            let mut m = render::sliding_json(a, shown);
            f64_digits(&mut m, req.digits);
            m
        })
        .collect();
    let values: Vec<_> = typed.iter().map(|a| render::sliding_values(a, shown)).collect();
    Ok((sliding_top(answers, &values, p), claim, values))
}

fn sliding_series(p: &SlidingProblem, scene: &Scene, req: SolveRequest) -> Result<Rendered, Error> {
    let s = sliding::series::solve_series(p, &scene.output.points, req.series_order, req.digits)?;
    let answer = answer_series::sliding_answer(&s, req.digits, p.convention());
    let values = vec![render::sliding_values(&answer, req.digits)];
    Ok((sliding_top(vec![render::sliding_json(&answer, req.digits)], &values, p), sliding_claim(&answer), values))
}

fn sliding_pade(p: &SlidingProblem, scene: &Scene, req: SolveRequest) -> Result<Rendered, Error> {
    let s = sliding::series::pade::solve_pade(p, &scene.output.points, req.series_order, req.digits)?;
    let (m, answer) = answer_pade::sliding_json(&s, req.digits, p.convention());
    let values = vec![render::sliding_values(&answer, req.digits)];
    Ok((sliding_top(vec![m], &values, p), sliding_claim(&answer), values))
}

fn adhesion_mpfr(p: &AdhesionProblem, scene: &Scene, req: SolveRequest) -> Result<Rendered, Error> {
    let v = adhesion::solve_verified(p, &scene.output.points, req.digits)?;
    let answer = answer_adhesion::mpfr_answer(p, &v);
    let claim = Claim { digits: answer.headline(), kind: answer.kind };
    let mut m = render::adhesion_json(&answer, req.digits);
    let values = render::adhesion_values(&answer, req.digits);
    m.insert("lambda_h".into(), lambda_h(p, req.digits));
    let a = number(&values, "half_width");
    slope_warning(&mut m, p.shape(), p.period(), -a, a);
    Ok((Value::Object(m), claim, vec![values]))
}

/// `lambda_h`: the largest lambda at which complete adhesion keeps `digits` (the homogeneous mode's
/// horizon, docs/theory.md section 11), 3 decimals rounded down; null for the single punch and in
/// the `periodic` convention, where the mode is not excited (section 8, Problem 2).
fn lambda_h(p: &AdhesionProblem, digits: u32) -> Value {
    match p.period() {
        Period::Finite(_) if !p.periodic_surface() => json!(crate::asymptotics::adhesion_mode::horizon_text(
            crate::asymptotics::adhesion_mode::horizon_of(p.material(), digits as f64)
        )),
        _ => Value::Null,
    }
}

fn adhesion_analytic(p: &AdhesionProblem, req: SolveRequest) -> Result<Rendered, Error> {
    let (answer, _) = answer_analytic::analytic_answer(p, req.digits)?;
    let claim = Claim { digits: answer.headline(), kind: answer.kind };
    let mut m = render::adhesion_json(&answer, req.digits);
    let values = render::adhesion_values(&answer, req.digits);
    m.insert("lambda_h".into(), lambda_h(p, req.digits));
    Ok((Value::Object(m), claim, vec![values]))
}

fn adhesion_f64(p: &AdhesionProblem, scene: &Scene, req: SolveRequest) -> Result<Rendered, Error> {
    let s = adhesion::solve_f64(p, &scene.output.points)?;
    let shown = req.digits.min(crate::numerics::accuracy::F64_PRINT_DIGITS - 1);
    let answer = answer_adhesion::f64_answer(p, &s, &scene.output.points);
    let claim = Claim { digits: answer.headline(), kind: answer.kind };
    let mut m = render::adhesion_json(&answer, shown);
    let values = render::adhesion_values(&answer, shown);
    f64_digits(&mut m, req.digits);
    m.insert("lambda_h".into(), lambda_h(p, req.digits.min(crate::numerics::accuracy::F64_DIGITS_CAP as u32)));
    let a = number(&values, "half_width");
    slope_warning(&mut m, p.shape(), p.period(), -a, a);
    // Which f64 method answered: the lambda^2 series, or the collocation in eta beyond its radius.
    m.insert("route".into(), json!(s.route.name()));
    Ok((Value::Object(m), claim, vec![values]))
}

/// Finite friction (`[adhesion] friction`): the single parabolic punch by the f64 or the mpfr
/// method ([`answer_friction`]), the periodic row by f64 or mpfr ([`answer_friction_row`]); nu = 1/2 by the
/// verified frictionless path.
fn adhesion_friction(
    p: &AdhesionProblem,
    scene: &Scene,
    mu: &crate::model::Exact,
    req: SolveRequest,
) -> Result<Rendered, Error> {
    if num_traits::Zero::is_zero(&p.material().beta()) {
        return adhesion_friction_incompressible(p, scene, mu, req);
    }
    let answer = match p.period() {
        Period::Finite(l) => answer_friction_row::row_answer(p, mu, l, (req.method, req.digits), &scene.output.points)?,
        Period::Infinite => answer_friction::friction_answer(p, mu, req.method, req.digits, &scene.output.points)?,
    };
    let mpfr = answer.provenance.method == "mpfr";
    let shown = if mpfr { req.digits } else { req.digits.min(crate::numerics::accuracy::F64_PRINT_DIGITS - 1) };
    Ok(friction_rendered(p, &answer, shown, (!mpfr).then_some(req.digits)))
}

/// A finite-friction answer printed with `shown` digits (`f64_asked`: the digits an f64 answer was
/// asked, for its `digits_note`); no horizon (`lambda_h` null: the mode is complete adhesion's).
fn friction_rendered(
    p: &AdhesionProblem,
    answer: &render::AdhesionAnswer,
    shown: u32,
    f64_asked: Option<u32>,
) -> Rendered {
    let claim = Claim { digits: answer.headline(), kind: answer.kind };
    let mut m = render::adhesion_json(answer, shown);
    let values = render::adhesion_values(answer, shown);
    if let Some(asked) = f64_asked {
        f64_digits(&mut m, asked);
    }
    m.insert("lambda_h".into(), Value::Null);
    let a = number(&values, "half_width");
    slope_warning(&mut m, p.shape(), p.period(), -a, a);
    (Value::Object(m), claim, vec![values])
}

/// Finite friction at nu = 1/2 (beta = 0): nothing drives a slip, the whole contact sticks (c = a)
/// and the problem is the frictionless one (docs/theory.md section 17.3), solved by the verified
/// MPFR method of complete adhesion (which is frictionless there) at the digits requested, whatever
/// the method asked (Kuznetsov's closed form for the periodic row, docs/theory.md section 4).
fn adhesion_friction_incompressible(
    p: &AdhesionProblem,
    scene: &Scene,
    mu: &crate::model::Exact,
    req: SolveRequest,
) -> Result<Rendered, Error> {
    answer_friction::solvable_parabola(p)?;
    let v = adhesion::solve_verified(p, &scene.output.points, req.digits)?;
    let mut answer = answer_adhesion::mpfr_answer(p, &v);
    answer.stick = Some(render::StickSlip {
        friction: exact_series::q_text(mu),
        stick_half_width: answer.half_width.clone(),
        note: answer_friction::FRICTION_NOTE_INCOMPRESSIBLE,
        checks: Vec::new(),
    });
    answer.accuracy.push(("stick".into(), answer.headline()));
    Ok(friction_rendered(p, &answer, req.digits, None))
}

/// `solve` and the problem's mode (`problem_mode`, printed with every loading-law answer) side by
/// side: the mode check is serial work of 40-90 ms that need not wait for the solve.
fn with_law_mode<S>(
    p: &LoadingLawProblem,
    solve: impl FnOnce() -> S,
) -> (S, Option<crate::asymptotics::loading_law_modes::ModeExponent>) {
    std::thread::scope(|scope| {
        let mode = scope.spawn(|| crate::asymptotics::loading_law_modes::problem_mode(p).ok());
        let solved = solve();
        (solved, mode.join().unwrap_or_else(|e| std::panic::resume_unwind(e)))
    })
}

fn law_mpfr(p: &LoadingLawProblem, scene: &Scene, req: SolveRequest) -> Result<Rendered, Error> {
    let (sol, mode) = with_law_mode(p, || crate::loading_law::verified::solve_law(p, &scene.output.points, req.digits));
    let sol = sol?;
    let claim = Claim { digits: sol.digits.headline, kind: DigitsKind::Verified };
    let (mut m, values) = answer_law::law_answer_json_with_mode(p, &sol, req.digits, mode);
    law_note(&mut m, &values, p);
    Ok((Value::Object(m), claim, vec![values]))
}

/// The loading law's notes: the small-slope warning of its parabola, and in the `paper`
/// convention with a tangential load (P1 != 0, so K != 0) `convention_note`, as for Problem 1.
fn law_note(m: &mut Map<String, Value>, values: &values::Values, p: &LoadingLawProblem) {
    let parabola = crate::model::PunchShape::Parabolic { k: p.k().clone() };
    let (left, right) = (-number(values, "a"), number(values, "b"));
    slope_warning(m, &parabola, p.period(), left, right);
    let tangential = match p.law() {
        crate::model::LoadingLaw::Linear(n) => !num_traits::Zero::is_zero(n),
        crate::model::LoadingLaw::Polynomial(c) => c.iter().any(|x| !num_traits::Zero::is_zero(x)),
    };
    if p.convention() == Convention::Paper && tangential && matches!(p.period(), Period::Finite(_)) {
        m.insert("convention_note".into(), json!(PAPER_CONVENTION_NOTE));
    }
}

/// The digits keys of an f64 answer: `digits_requested` states what the user asked (not the f64
/// cap), and where that exceeds what f64 can carry, `digits_note` says so (issue 30).
fn f64_digits(m: &mut Map<String, Value>, requested: u32) {
    let cap = crate::numerics::accuracy::F64_DIGITS_CAP as u32;
    m.insert("digits_requested".into(), json!(requested.to_string()));
    if requested > cap {
        m.insert(
            "digits_note".into(),
            json!(format!(
                "{requested} digits were asked; the f64 method carries at most {cap} significant digits, and \
                 digits_verified (or digits_estimated) states what this answer holds; for more use --method mpfr \
                 or --digits {requested}"
            )),
        );
    }
}

fn law_f64(p: &LoadingLawProblem, scene: &Scene, req: SolveRequest) -> Result<Rendered, Error> {
    // The mode check after the check run, on its CPU (the nominal run holds the other).
    let (sol, mode) = crate::loading_law::verified_f64::solve_law_f64_beside(p, &scene.output.points, || {
        crate::asymptotics::loading_law_modes::problem_mode(p).ok()
    })?;
    let shown = req.digits.min(crate::numerics::accuracy::F64_PRINT_DIGITS - 1);
    let (mut m, values) = answer_law::law_answer_json_f64(p, &sol, shown, mode);
    f64_digits(&mut m, req.digits);
    law_note(&mut m, &values, p);
    Ok((Value::Object(m), Claim { digits: sol.digits.headline, kind: DigitsKind::Verified }, vec![values]))
}
