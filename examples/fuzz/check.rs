//! The differential checks of one generated case (issue 34): every method that takes the scene is
//! run through the library (`solve::solve_scene`), the truth is the verified MPFR method at more
//! digits (through the library's solvers directly, for the scales of the accuracy rule), and:
//! 1. the methods reach the same verdict (an answer, or a refusal of the same kind; "no
//!    convergence" is a method's reach and may stand beside any verdict);
//! 2. every printed value holds its claimed digits against the truth on its scale (which also
//!    makes the methods agree to the smaller claim);
//! 3. refusals agree with the closed forms where they exist (the frictionless parabola carries
//!    every load, the frictionless sinusoid every load below pi E* D and none above);
//! 4. the exactly scaled twin (lengths x s, stresses x t) gives the same verdict and values scaled
//!    by s, t, s t (or 1) within both claims.

use super::generate::{Case, Given, Problem, Shape, Statement, Q};
use periodic_contact::error::{Error, ErrorKind};
use periodic_contact::model::Exact;
use periodic_contact::model::OnPunchRow;
use periodic_contact::scene::parse::parse_scene;
use periodic_contact::scene::{Method, Scene, SceneProblem};
use periodic_contact::solve::{answer_adhesion, answer_law, answer_mpfr, render, solve_scene, SolveRequest};
use rug::Float;
use serde_json::Value;
use std::collections::BTreeMap;

/// Digits asked of each method.
#[derive(Debug, Clone, Copy)]
pub struct Budget {
    /// The MPFR method under test.
    pub digits: u32,
    /// The truth (verified MPFR): more digits than any claim it checks (the f64 methods claim at
    /// most 15.x, the MPFR method `digits`); a value is held when within its claim plus the
    /// truth's own 10^-truth_digits of its scale, so 3 digits beyond the largest claim change
    /// that bound by 0.1 % at most.
    pub truth_digits: u32,
    /// The loading law's truth (its MPFR method is dear: it is the truth and the method at once).
    pub law_digits: u32,
    /// Solve the scaled twin.
    pub twin: bool,
    /// Run the series and Pade methods on every this-many-th case that takes them (they derive
    /// the exact expansions at the case's parameters, about 1 s per case).
    pub series_every: u64,
}

impl Budget {
    /// The budget of the 10,000-case runs.
    pub const FULL: Budget = Budget { digits: 20, truth_digits: 32, law_digits: 18, twin: true, series_every: 1 };
    /// The CI test's budget (and the long runs'): fewer digits (the truth at 18, 3 beyond the f64
    /// claims: at 24 it took 60 % of a case's time, twice its cost at 18 on the adhesion cases),
    /// the series methods on every third case that takes them.
    pub const CI: Budget = Budget { digits: 12, truth_digits: 18, law_digits: 10, twin: true, series_every: 3 };
}

/// What a method said.
#[derive(Debug, Clone, PartialEq)]
pub enum Verdict {
    /// Solutions (count).
    Answer(usize),
    /// A refusal: its kind and the class of its reason (the message with numbers removed, cut).
    Refused(ErrorKind, String),
}

impl Verdict {
    fn of(r: &Result<Value, Error>) -> Verdict {
        match r {
            Ok(v) => Verdict::Answer(v.get("solutions").and_then(Value::as_array).map_or(1, Vec::len)),
            Err(e) => Verdict::Refused(e.kind(), reason_class(e)),
        }
    }
    /// A short label for the tally.
    pub fn label(&self) -> String {
        match self {
            Verdict::Answer(_) => "answer".into(),
            Verdict::Refused(k, why) => format!("{k:?}: {why}"),
        }
    }
}

/// The reason of a refusal without its numbers: the message up to its first ';' or '(' with
/// digits replaced by '#', at most 9 words.
fn reason_class(e: &Error) -> String {
    let text = match e {
        Error::Input(m) => format!("{} {}", m.parameter, m.expected),
        other => other.to_string(),
    };
    let head = text.split([';', '(']).next().unwrap_or("");
    let words: Vec<String> = head
        .split_whitespace()
        .take(9)
        .map(|w| if w.chars().any(|c| c.is_ascii_digit()) { "#".to_string() } else { w.to_string() })
        .collect();
    words.join(" ")
}

/// One method's run.
#[derive(Debug, Clone)]
pub struct Run {
    pub method: String,
    pub verdict: Verdict,
    pub seconds: f64,
}

/// The result of one case.
#[derive(Debug, Clone, Default)]
pub struct Outcome {
    pub runs: Vec<Run>,
    pub disagreements: Vec<String>,
    /// Printed values compared with the truth (and with the twin).
    pub values_checked: usize,
    /// The scene could not be built (the generator's or the parser's fault): its message.
    pub invalid: Option<String>,
    /// Seconds spent on the scaled twin (check 4).
    pub twin_seconds: f64,
}

/// A printed value, the digits claimed for it and the path of its scale.
struct Claim {
    text: String,
    digits: f64,
}

/// The truth of a case: its values and claims by path (as printed at the truth's digits), the
/// scale of each path, the count of solutions.
struct Truth {
    claims: BTreeMap<String, Claim>,
    scales: BTreeMap<String, Float>,
}

const PREC: u32 = 512;

fn float(text: &str) -> Option<Float> {
    Float::parse(text.trim()).ok().map(|p| Float::with_val(PREC, p))
}

fn num(v: &Value, key: &str) -> Option<f64> {
    v.get(key)?.as_str()?.parse().ok()
}

/// Every printed value of an answer with the digits claimed for it (by its key in the accuracy
/// table, else the headline), keyed by path.
fn claims(v: &Value, problem: Problem) -> BTreeMap<String, Claim> {
    let mut out = BTreeMap::new();
    let head = num(v, "digits_verified").or_else(|| num(v, "digits_estimated")).unwrap_or(0.0);
    let acc = |k: &str| num(&v["accuracy"], k);
    let mut put = |path: String, x: &Value, digits: f64| {
        if let Some(t) = x.as_str() {
            out.insert(path, Claim { text: t.to_string(), digits });
        }
    };
    match problem {
        Problem::Sliding => {
            for k in [
                "lambda",
                "l",
                "a",
                "b",
                "c",
                "P1",
                "P2",
                "F_def",
                "wear_per_distance",
                "wear_rate",
                "worn_area_per_distance",
            ] {
                put(k.into(), &v[k], acc(k).unwrap_or(head));
            }
            for (i, row) in v["pressure"].as_array().into_iter().flatten().enumerate() {
                put(format!("pressure[{i}].x"), &row["x"], head);
                let d = acc(&format!("p[{i}]")).or_else(|| acc("p")).unwrap_or(head);
                put(format!("pressure[{i}].p"), &row["p"], d);
            }
        }
        Problem::Adhesion => {
            let size = acc("size").unwrap_or(head);
            for k in ["lambda", "P2", "half_width"] {
                put(k.into(), &v[k], size);
            }
            for f in ["psi", "phi", "q1", "q2"] {
                for (i, row) in v[f].as_array().into_iter().flatten().enumerate() {
                    put(format!("{f}[{i}]"), &row[f], acc(f).unwrap_or(head));
                }
            }
        }
        Problem::Law => {
            let (ends, loads, fields) =
                (acc("ends").unwrap_or(head), acc("loads").unwrap_or(head), acc("fields").unwrap_or(head));
            for k in ["lambda", "a", "b", "c", "l"] {
                put(k.into(), &v[k], ends);
            }
            for k in ["P1", "P2"] {
                put(k.into(), &v[k], loads);
            }
            for (i, row) in v["points"].as_array().into_iter().flatten().enumerate() {
                put(format!("points[{i}].x"), &row["x"], ends);
                for f in ["psi", "phi", "q1", "q2"] {
                    put(format!("points[{i}].{f}"), &row[f], fields);
                }
            }
        }
    }
    out
}

/// The factor a path's value takes under the similarity (lengths x s, stresses x t).
fn factor(path: &str, problem: Problem, s: &Q, t: &Q) -> Q {
    let leaf = path.rsplit('.').next().unwrap_or(path);
    let leaf = leaf.split('[').next().unwrap_or(leaf);
    let one = Q::from_integer(1.into());
    match (problem, leaf) {
        (_, "lambda" | "wear_per_distance" | "wear_rate" | "psi") => one,
        (_, "l" | "a" | "b" | "c" | "x" | "half_width" | "worn_area_per_distance" | "phi") => s.clone(),
        (_, "P1" | "P2" | "F_def") => s * t,
        (_, "p" | "q1" | "q2") => t.clone(),
        _ => one,
    }
}

fn to_f(q: &Q) -> Float {
    periodic_contact::numerics::exact::to_float(q, PREC)
}

/// The truth: verified MPFR at `digits` through the library's solvers (their raw solutions give
/// the scales of the accuracy rule), rendered as `solve` renders it.
fn truth(scene: &Scene, digits: u32) -> Result<(Value, Truth), Error> {
    let pts = &scene.output.points;
    let mut scales = BTreeMap::new();
    let (v, problem) = match &scene.problem {
        SceneProblem::Sliding(p) => {
            let sols = periodic_contact::sliding::solve_verified(p, pts, digits).map_err(Error::from)?;
            let first =
                sols.first().ok_or_else(|| Error::NotPhysical { why: "no physical contact was found".into() })?;
            let s = &first.solution;
            use periodic_contact::params::sliding::SlidingScale;
            let sc = |q: SlidingScale| q.mpfr(&s.k, &s.l, &s.p2, &s.max_pressure);
            for k in ["l", "a", "b", "c"] {
                scales.insert(k.to_string(), sc(SlidingScale::Length));
            }
            if let Some(lam) = &s.lambda {
                scales.insert("lambda".into(), lam.clone());
            }
            scales.insert("P1".into(), sc(SlidingScale::Load));
            scales.insert("P2".into(), sc(SlidingScale::Load));
            scales.insert("F_def".into(), sc(SlidingScale::DeformationForce));
            for (k, w) in [("wear_per_distance", &s.wear_per_distance), ("wear_rate", &s.wear_rate)] {
                if let Some(w) = w {
                    scales.insert(k.into(), w.clone());
                }
            }
            scales.insert("worn_area_per_distance".into(), s.worn_area_per_distance.clone());
            for i in 0..s.pressure.len() {
                scales.insert(format!("pressure[{i}].x"), sc(SlidingScale::Length));
                scales.insert(format!("pressure[{i}].p"), sc(SlidingScale::Pressure));
            }
            let mut answers: Vec<Value> = sols
                .iter()
                .map(|v| Value::Object(render::sliding_json(&answer_mpfr::sliding_answer(v, p.convention()), digits)))
                .collect();
            let mut top = answers[0].clone();
            if answers.len() > 1 {
                top["solutions"] = Value::Array(std::mem::take(&mut answers));
            }
            (top, Problem::Sliding)
        }
        SceneProblem::Adhesion(p) => {
            let v = periodic_contact::adhesion::solve_verified(p, pts, digits).map_err(Error::from)?;
            let s = &v.solution;
            let sc = periodic_contact::adhesion::ScalesMpfr::new(p, &s.half_width, &s.normal_load, s.prec);
            scales.insert("lambda".into(), s.lambda.clone());
            scales.insert("P2".into(), s.normal_load.clone());
            scales.insert("half_width".into(), s.half_width.clone());
            for i in 0..s.points.len() {
                scales.insert(format!("psi[{i}]"), sc.psi.clone());
                scales.insert(format!("phi[{i}]"), sc.phi.clone());
                scales.insert(format!("q1[{i}]"), sc.stress.clone());
                scales.insert(format!("q2[{i}]"), sc.stress.clone());
            }
            (Value::Object(render::adhesion_json(&answer_adhesion::mpfr_answer(p, &v), digits)), Problem::Adhesion)
        }
        SceneProblem::LoadingLaw(p) => {
            let sol = periodic_contact::loading_law::verified::solve_law(p, pts, digits).map_err(Error::from)?;
            let v = &sol.values;
            let prec = v.l.prec();
            let k = periodic_contact::numerics::exact::to_float(p.k(), prec);
            let e = periodic_contact::numerics::exact::to_float(p.material().contact_modulus(), prec);
            let kl = Float::with_val(prec, &k * &v.l);
            scales.insert("lambda".into(), v.lambda.clone());
            for key in ["a", "b", "c", "l"] {
                scales.insert(key.into(), v.l.clone());
            }
            scales.insert("P1".into(), v.p2.clone());
            scales.insert("P2".into(), v.p2.clone());
            for i in 0..v.points.len() {
                scales.insert(format!("points[{i}].x"), v.l.clone());
                scales.insert(format!("points[{i}].psi"), kl.clone());
                scales.insert(format!("points[{i}].phi"), Float::with_val(prec, &kl * &v.l));
                scales.insert(format!("points[{i}].q1"), Float::with_val(prec, &kl * &e));
                scales.insert(format!("points[{i}].q2"), Float::with_val(prec, &kl * &e));
            }
            (Value::Object(answer_law::law_answer_json(p, &sol, digits).0), Problem::Law)
        }
    };
    let claims = claims(&v, problem);
    Ok((v, Truth { claims, scales }))
}

/// The methods that take a scene (the truth aside) of case `index`.
fn methods(st: &Statement, index: u64, budget: &Budget) -> Vec<Method> {
    match st.problem {
        Problem::Sliding => {
            let mut m = vec![Method::Mpfr, Method::F64];
            let series = index.is_multiple_of(budget.series_every.max(1));
            if series && st.period.is_some() && matches!(st.given, Given::NormalLoad(_)) {
                m.extend([Method::Series, Method::Pade]);
            }
            m
        }
        Problem::Adhesion => vec![Method::Mpfr, Method::F64],
        Problem::Law => vec![Method::F64],
    }
}

fn timed<T>(f: impl FnOnce() -> T) -> (T, f64) {
    let t = std::time::Instant::now();
    let v = f();
    (v, t.elapsed().as_secs_f64())
}

/// Whether two verdicts contradict each other (module doc, check 1); `method_specific`: a method
/// that may refuse a scene as input it does not take (series, pade).
fn contradict(a: &Verdict, b: &Verdict, method_specific: bool) -> bool {
    use ErrorKind::*;
    match (a, b) {
        (Verdict::Refused(NoConvergence, _), _) | (_, Verdict::Refused(NoConvergence, _)) => false,
        // The same parameter refused (the wording may differ: lambda or a for the same size).
        (Verdict::Refused(Input, x), Verdict::Refused(Input, y)) => {
            x.split(' ').next() != y.split(' ').next() && !method_specific
        }
        (Verdict::Refused(Input, _), _) | (_, Verdict::Refused(Input, _)) => !method_specific,
        (Verdict::Answer(n), Verdict::Answer(m)) => n != m && !method_specific,
        (Verdict::Answer(_), Verdict::Refused(..)) | (Verdict::Refused(..), Verdict::Answer(_)) => true,
        (Verdict::Refused(k, _), Verdict::Refused(j, _)) => k != j,
    }
}

/// |printed - truth| <= 10^-claim S + 10^-truth_claim S (S the path's scale): the digits held.
fn held(printed: &Claim, truth: &Claim, scale: &Float) -> Option<(bool, f64)> {
    let (x, t) = (float(&printed.text)?, float(&truth.text)?);
    let diff = Float::with_val(PREC, &x - &t).abs();
    let s = Float::with_val(PREC, scale.abs_ref());
    if s.is_zero() {
        return Some((diff.is_zero(), if diff.is_zero() { f64::INFINITY } else { 0.0 }));
    }
    let bound = |d: f64| Float::with_val(PREC, &s * Float::with_val(64, -d).exp10());
    let allowed = Float::with_val(PREC, bound(printed.digits) + bound(truth.digits));
    let got = if diff.is_zero() {
        f64::INFINITY
    } else {
        Float::with_val(64, s.log10_ref()).to_f64() - Float::with_val(64, diff.log10_ref()).to_f64()
    };
    Some((diff <= allowed, got))
}

/// The closed-form statement of existence (check 3), for the frictionless periodic parabola and
/// sinusoid under a given load: Some(true) when a contact exists, Some(false) when none does.
fn closed_form_exists(st: &Statement) -> Option<bool> {
    use num_traits::Zero;
    let frictionless = st.friction.is_zero() && st.wear.is_zero() && st.tau0.is_zero();
    let (Problem::Sliding, Some(_), true, Given::NormalLoad(p)) = (st.problem, &st.period, frictionless, &st.given)
    else {
        return None;
    };
    match &st.shape {
        Shape::Parabolic { .. } => Some(true),
        Shape::Sinusoidal { d } => {
            let e_d: Exact = &st.e_star * d;
            Some(periodic_contact::numerics::exact::cmp_pi_times(p, &e_d) == std::cmp::Ordering::Less)
        }
        _ => None,
    }
}

/// Solves `scene` by every method that takes the case, records each run, and notes a verdict that
/// contradicts the truth's `tv`; returns every method's result.
fn solve_by_every_method(
    out: &mut Outcome,
    case: &Case,
    budget: &Budget,
    scene: &periodic_contact::scene::Scene,
    tv: &Verdict,
    tag: &dyn Fn(&str) -> String,
) -> Vec<(Method, Result<Value, Error>)> {
    let mut answers = vec![];
    for m in methods(&case.statement, case.index, budget) {
        let (r, secs) = timed(|| solve_scene(scene, request(m, budget)));
        let v = Verdict::of(&r);
        let specific = matches!(m, Method::Series | Method::Pade);
        if contradict(tv, &v, specific) {
            out.disagreements.push(tag(&format!(
                "verdicts differ: truth {} vs {} {}{}",
                tv.label(),
                m.name(),
                v.label(),
                r.as_ref().err().map_or(String::new(), |e| format!(" ({e})"))
            )));
        }
        out.runs.push(Run { method: m.name().into(), verdict: v, seconds: secs });
        answers.push((m, r));
    }
    answers
}

/// Runs every check of `case` under `budget`.
pub fn run(case: &Case, budget: &Budget) -> Outcome {
    let mut out = Outcome::default();
    let st = &case.statement;
    let toml = st.toml();
    let scene = match parse_scene(&toml) {
        Ok(s) => s,
        Err(e) => {
            out.invalid = Some(format!("{e}"));
            return out;
        }
    };
    let tag = |what: &str| format!("case {} ({}): {what}", case.index, st.note);
    let truth_digits = if st.problem == Problem::Law { budget.law_digits } else { budget.truth_digits };
    let ((truth_json, truth), secs) = match timed(|| truth(&scene, truth_digits)) {
        (Ok(t), secs) => (t, secs),
        (Err(e), secs) => {
            // The truth refused: every method must refuse alike (or not reach).
            let tv = Verdict::of(&Err(e.clone()));
            out.runs.push(Run { method: format!("mpfr@{truth_digits} (truth)"), verdict: tv.clone(), seconds: secs });
            let results = solve_by_every_method(&mut out, case, budget, &scene, &tv, &tag);
            check_closed_form(&mut out, st, &tag);
            let ((), secs) = timed(|| check_twin(&mut out, case, budget, &results, None, &tag));
            out.twin_seconds = secs;
            return out;
        }
    };
    let tv = Verdict::of(&Ok(truth_json.clone()));
    out.runs.push(Run { method: format!("mpfr@{truth_digits} (truth)"), verdict: tv.clone(), seconds: secs });
    let results = solve_by_every_method(&mut out, case, budget, &scene, &tv, &tag);
    // Check 2: every printed value holds its claim against the truth.
    for (m, v) in results.iter().filter_map(|(m, r)| Some((m, r.as_ref().ok()?))) {
        if v.get("solutions").is_some() != truth_json.get("solutions").is_some() {
            continue; // counted as a verdict difference above for the full methods
        }
        for (path, c) in claims(v, st.problem) {
            let (Some(t), Some(s)) = (truth.claims.get(&path), truth.scales.get(&path)) else { continue };
            out.values_checked += 1;
            match held(&c, t, s) {
                Some((true, _)) => {}
                Some((false, got)) => out.disagreements.push(tag(&format!(
                    "{} {path} = {} claims {:.1} digits of its scale {}, holds {got:.2} against the truth {} ({:.1} digits)",
                    m.name(),
                    c.text,
                    c.digits,
                    s.to_string_radix(10, Some(4)),
                    t.text,
                    t.digits
                ))),
                None => out.disagreements.push(tag(&format!("{} {path}: unreadable {:?}", m.name(), c.text))),
            }
        }
    }
    check_closed_form(&mut out, st, &tag);
    let ((), secs) = timed(|| check_twin(&mut out, case, budget, &results, Some((&truth_json, &truth)), &tag));
    out.twin_seconds = secs;
    out
}

/// The problem of a parsed scene.
pub fn problem_of(scene: &Scene) -> Problem {
    match scene.problem {
        SceneProblem::Sliding(_) => Problem::Sliding,
        SceneProblem::Adhesion(_) => Problem::Adhesion,
        SceneProblem::LoadingLaw(_) => Problem::Law,
    }
}

/// Check 2 alone for a given scene: every value `method` prints (at `digits`) holds its claimed
/// digits against verified MPFR at `truth_digits`; the disagreements, and the count of values
/// compared. Both must answer.
pub fn printed_values_hold(
    scene: &Scene,
    method: Method,
    digits: u32,
    truth_digits: u32,
) -> Result<(Vec<String>, usize), Error> {
    let margins = printed_margins(scene, method, digits, truth_digits)?;
    let bad = margins.iter().filter(|m| !m.holds).map(|m| m.text.clone()).collect();
    Ok((bad, margins.len()))
}

/// One printed value against the truth ([`printed_margins`]).
#[derive(Debug, Clone)]
pub struct Margin {
    /// Its path, e.g. `P2`.
    pub path: String,
    /// The digits claimed for it.
    pub claimed: f64,
    /// The digits it holds of its scale against the truth.
    pub held: f64,
    /// Whether it holds its claim (within the claim plus the truth's own).
    pub holds: bool,
    /// The comparison in words.
    pub text: String,
}

/// Every value `method` prints (at `digits`) against verified MPFR at `truth_digits`: the digits
/// claimed and held (check 2 with its margins). Both must answer.
pub fn printed_margins(scene: &Scene, method: Method, digits: u32, truth_digits: u32) -> Result<Vec<Margin>, Error> {
    let (_, truth) = truth(scene, truth_digits)?;
    let v = solve_scene(scene, SolveRequest { method, digits, series_order: 12 })?;
    let mut out = vec![];
    for (path, c) in claims(&v, problem_of(scene)) {
        let (Some(t), Some(s)) = (truth.claims.get(&path), truth.scales.get(&path)) else { continue };
        let (holds, held) = held(&c, t, s).unwrap_or((false, 0.0));
        let text = format!(
            "{} {path} = {} claims {:.1} digits, holds {held:.2} against {} ({:.1} digits)",
            method.name(),
            c.text,
            c.digits,
            t.text,
            t.digits
        );
        out.push(Margin { path, claimed: c.digits, held, holds, text });
    }
    Ok(out)
}

fn request(m: Method, budget: &Budget) -> SolveRequest {
    SolveRequest { method: m, digits: if m == Method::F64 { 30 } else { budget.digits }, series_order: 12 }
}

/// Check 3 on every run of the case.
fn check_closed_form(out: &mut Outcome, st: &Statement, tag: &dyn Fn(&str) -> String) {
    let Some(exists) = closed_form_exists(st) else { return };
    for run in out.runs.clone() {
        if run.method == "series" || run.method == "pade" {
            continue;
        }
        let bad = matches!(
            (&run.verdict, exists),
            (Verdict::Refused(ErrorKind::NoSolution | ErrorKind::NotPhysical, _), true)
                | (Verdict::Answer(_), false)
                | (Verdict::Refused(ErrorKind::NotPhysical, _), false)
        );
        if bad {
            out.disagreements.push(tag(&format!(
                "{} says {} where the closed form says a contact {}",
                run.method,
                run.verdict.label(),
                if exists { "exists" } else { "does not exist" }
            )));
        }
    }
}

/// Check 4: the scaled twin, by the f64 method (and the MPFR method for Problem 1 and 2), against
/// the `results` of the case's own scene by the same methods.
fn check_twin(
    out: &mut Outcome,
    case: &Case,
    budget: &Budget,
    results: &[(Method, Result<Value, Error>)],
    truth: Option<(&Value, &Truth)>,
    tag: &dyn Fn(&str) -> String,
) {
    if !budget.twin {
        return;
    }
    let st = &case.statement;
    let twin = st.scaled(&case.scaling);
    let Ok(twin_scene) = parse_scene(&twin.toml()) else {
        out.disagreements.push(tag("the scaled twin does not parse"));
        return;
    };
    let mut ms = vec![Method::F64];
    if st.problem != Problem::Law {
        ms.push(Method::Mpfr);
    }
    for m in ms {
        let Some(a) = results.iter().find(|(k, _)| *k == m).map(|(_, r)| r.clone()) else { continue };
        let b = solve_scene(&twin_scene, request(m, budget));
        let (va, vb) = (Verdict::of(&a), Verdict::of(&b));
        // A method's reach may differ between the twins (its f64 stages see other roundings):
        // "no convergence" on one side is not a contradiction.
        let same_kind = match (&va, &vb) {
            (Verdict::Answer(n), Verdict::Answer(k)) => n == k,
            (Verdict::Refused(ErrorKind::NoConvergence, _), _) | (_, Verdict::Refused(ErrorKind::NoConvergence, _)) => {
                true
            }
            (Verdict::Refused(x, _), Verdict::Refused(y, _)) => x == y,
            _ => false,
        };
        if !same_kind {
            out.disagreements.push(tag(&format!(
                "scaling: {} gives {} but {} for the twin{}",
                m.name(),
                va.label(),
                vb.label(),
                b.as_ref().err().or(a.as_ref().err()).map_or(String::new(), |e| format!(" ({e})"))
            )));
            continue;
        }
        let (Ok(a), Ok(b), Some((_, truth))) = (a, b, truth) else { continue };
        let (ca, cb) = (claims(&a, st.problem), claims(&b, st.problem));
        for (path, x) in &ca {
            let (Some(y), Some(scale)) = (cb.get(path), truth.scales.get(path)) else { continue };
            let f = to_f(&factor(path, st.problem, &case.scaling.s, &case.scaling.t));
            let (Some(xv), Some(yv)) = (float(&x.text), float(&y.text)) else { continue };
            out.values_checked += 1;
            let diff = Float::with_val(PREC, &yv - Float::with_val(PREC, &xv * &f)).abs();
            let s = Float::with_val(PREC, scale * &f).abs();
            let bound = |d: f64| Float::with_val(PREC, &s * Float::with_val(64, -d).exp10());
            if diff > Float::with_val(PREC, bound(x.digits) + bound(y.digits)) {
                out.disagreements.push(tag(&format!(
                    "scaling: {} {path}: {} x {} != {} (claims {:.1}, {:.1} digits of {})",
                    m.name(),
                    x.text,
                    f.to_string_radix(10, Some(6)),
                    y.text,
                    x.digits,
                    y.digits,
                    s.to_string_radix(10, Some(4))
                )));
            }
        }
    }
}
