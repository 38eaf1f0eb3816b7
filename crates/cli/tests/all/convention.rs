//! The surface convention of Problem 1 (THEORY.md section 8) end to end: THEORY's check value in
//! both conventions with both full solvers, MPFR and f64 agreeing in the `periodic` convention
//! (friction, wear, tau0; parabola and sinusoid), K = 0 giving identical answers, and the scene
//! key / command-line flag (input errors are exit code 2 naming them).

use super::common;
use common::{json, run, scene_file};
use periodic_contact::model::{Convention, Exact, Material, Period, PunchShape, SlidingLoad, SlidingProblem};
use periodic_contact::sliding::collocation_f64::{solve_sliding_f64, SlidingSolutionF64, SolverOptions};
use periodic_contact::sliding::{solve_verified, SlidingSolution};
use rug::Float;

fn q(s: &str) -> Exact {
    exact_series::parse_rational(s).unwrap()
}

/// Inputs of one Problem 1 case (exact text), E* = 1, L = 1.
#[derive(Clone, Copy)]
struct Case {
    nu: &'static str,
    sinusoid: bool,
    /// k (parabola) or amplitude D (sinusoid).
    size: &'static str,
    mu: &'static str,
    tau0: &'static str,
    wear: &'static str,
    p2: &'static str,
}

impl Case {
    fn problem(&self, convention: Convention) -> SlidingProblem {
        let shape = if self.sinusoid {
            PunchShape::sinusoidal(q(self.size)).unwrap()
        } else {
            PunchShape::parabolic(q(self.size)).unwrap()
        };
        SlidingProblem::builder()
            .material(Material::from_contact_modulus(q(self.nu), q("1")).unwrap())
            .period(Period::finite(q("1")).unwrap())
            .shape(shape)
            .friction(q(self.mu))
            .adhesive_friction(q(self.tau0))
            .wear(q(self.wear))
            .load(SlidingLoad::NormalLoad(q(self.p2)))
            .convention(convention)
            .build()
            .unwrap()
    }
}

/// THEORY.md section 8: E* = k = L = 1, beta = 1/4 (nu = 1/3), mu = 2/5, tau0 = cW = 0, P2 = 1/20.
const CHECK: Case = Case { nu: "1/3", sinusoid: false, size: "1", mu: "2/5", tau0: "0", wear: "0", p2: "1/20" };

fn mpfr(case: &Case, convention: Convention, digits: u32) -> SlidingSolution {
    let sols = solve_verified(&case.problem(convention), &[], digits).expect("mpfr solves");
    assert_eq!(sols.len(), 1, "one physical contact");
    assert!(sols[0].accuracy.digits_verified >= digits as f64 - 1.0, "{:?}", sols[0].accuracy);
    sols[0].solution.clone()
}

fn f64_of(case: &Case, convention: Convention) -> SlidingSolutionF64 {
    let sols = solve_sliding_f64(&case.problem(convention), &[], &SolverOptions::default()).expect("f64 solves");
    assert_eq!(sols.solutions.len(), 1, "one physical contact");
    sols.solutions[0].clone()
}

fn rel(x: &Float, y: &Float, scale: &Float) -> f64 {
    Float::with_val(x.prec(), x - y).to_f64().abs() / scale.to_f64().abs()
}

#[test]
fn theory_check_value_in_both_conventions() {
    let paper = mpfr(&CHECK, Convention::Paper, 40);
    let periodic = mpfr(&CHECK, Convention::PeriodicSurface, 40);
    let (lp, lq) = (paper.lambda.clone().unwrap(), periodic.lambda.clone().unwrap());
    // lambda is the same in both conventions (>= 25 digits) and equals THEORY's value.
    assert!(rel(&lp, &lq, &lp) < 1e-25, "lambda paper {lp} vs periodic {lq}");
    assert!((lp.to_f64() - 0.547045990639).abs() < 1e-12, "lambda {lp}");
    // c to THEORY's digits.
    assert!((paper.c.to_f64() - -0.0118478575).abs() < 1e-10, "c paper {}", paper.c);
    assert!((periodic.c.to_f64() - -0.0068478575).abs() < 1e-10, "c periodic {}", periodic.c);
    // c_periodic - c_paper = -K/(E* k), K = (kappa P2 - 2 beta l tau0)/L = -beta mu P2 = -1/200.
    let shift = Float::with_val(paper.prec, &periodic.c - &paper.c);
    let expect = Float::with_val(paper.prec, 1) / 200u32;
    assert!(rel(&shift, &expect, &paper.l) < 1e-30, "shift {shift} vs 1/200");
    // P2, P1, a + b do not change; F_def does (the contact moved).
    assert!(rel(&paper.l, &periodic.l, &paper.l) < 1e-30);
    assert!(rel(&paper.p1, &periodic.p1, &paper.p2) < 1e-30);
    // f64: >= 12 digits against MPFR in each convention.
    for (conv, m) in [(Convention::Paper, &paper), (Convention::PeriodicSurface, &periodic)] {
        let f = f64_of(&CHECK, conv);
        let l = m.l.to_f64();
        let lambda_m = m.lambda.as_ref().unwrap().to_f64();
        assert!(approx::relative_eq!(f.lambda, lambda_m, epsilon = 0.0, max_relative = 1e-12), "{conv:?}: lambda");
        assert!((f.c - m.c.to_f64()).abs() < 1e-12 * l, "{conv:?}: c f64 {} vs mpfr {}", f.c, m.c);
        // The closure defect, measured by the shared criterion from the two halves of the gap:
        // M = (2/E*) beta P1 - cW P2 in `paper` (here E* = 1, beta = 1/4, cW = 0: P1/2), round-off
        // in `periodic`; the same in both methods.
        let measured = f.physicality.closure_defect.expect("a period");
        let mpfr = m.physicality.as_ref().expect("checked run").closure_defect.expect("a period");
        let expect = if conv == Convention::PeriodicSurface { 0.0 } else { 0.5 * f.p1 };
        assert!((measured - expect).abs() < 1e-9 * f.p1, "{conv:?}: closure {measured} vs {expect}");
        assert!((mpfr - expect).abs() < 1e-9 * f.p1, "{conv:?}: MPFR closure {mpfr} vs {expect}");
    }
}

/// MPFR (30 digits) and f64 agree to >= 12 digits on a, b, c (scale l), P2 and P1 (scale P2)
/// and F_def (scale k l P2).
fn agree(case: &Case, convention: Convention) {
    let m = mpfr(case, convention, 30);
    let f = f64_of(case, convention);
    let (l, p2, k) = (m.l.to_f64(), m.p2.to_f64(), m.k.to_f64());
    let checks = [
        ("a", m.a.to_f64(), f.a, l),
        ("b", m.b.to_f64(), f.b, l),
        ("c", m.c.to_f64(), f.c, l),
        ("P2", p2, f.p2, p2),
        ("P1", m.p1.to_f64(), f.p1, p2),
        ("F_def", m.f_def.to_f64(), f.f_def, k * l * p2),
    ];
    for (name, x, y, scale) in checks {
        let d = (x - y).abs() / scale;
        assert!(d < 1e-12, "{convention:?} {}: {name} mpfr {x} vs f64 {y} (relative {d:e})", case_name(case));
    }
}

fn case_name(c: &Case) -> String {
    format!(
        "{} mu={} tau0={} cW={} P2={}",
        if c.sinusoid { "sinusoid" } else { "parabola" },
        c.mu,
        c.tau0,
        c.wear,
        c.p2
    )
}

const BASE: Case = Case { nu: "0.3", sinusoid: false, size: "1", mu: "0", tau0: "0", wear: "0", p2: "0.05" };
const SINE: Case = Case { sinusoid: true, size: "0.05", p2: "0.02", ..BASE };

#[test]
fn mpfr_and_f64_agree_in_the_periodic_convention_parabola() {
    for case in [
        Case { mu: "0.5", ..BASE },
        Case { wear: "0.2", ..BASE },
        Case { mu: "0.3", tau0: "0.005", ..BASE },
        Case { mu: "0.5", p2: "0.2", ..BASE },
        Case { wear: "0.2", p2: "0.2", ..BASE },
    ] {
        agree(&case, Convention::PeriodicSurface);
    }
}

#[test]
fn mpfr_and_f64_agree_in_the_periodic_convention_sinusoid() {
    for case in [
        Case { mu: "0.5", ..SINE },
        Case { wear: "0.2", ..SINE },
        Case { mu: "0.3", tau0: "0.005", ..SINE },
        Case { mu: "0.5", p2: "0.08", ..SINE },
        Case { wear: "0.2", p2: "0.08", ..SINE },
    ] {
        agree(&case, Convention::PeriodicSurface);
    }
}

/// K = 0 (frictionless, no wear, no tau0): the two conventions are one problem, bit for bit.
#[test]
fn frictionless_conventions_coincide() {
    for case in [BASE, SINE] {
        let (mp, mq) = (mpfr(&case, Convention::Paper, 30), mpfr(&case, Convention::PeriodicSurface, 30));
        assert_eq!((&mp.l, &mp.c, &mp.f_def), (&mq.l, &mq.c, &mq.f_def), "{}", case_name(&case));
        let (fp, fq) = (f64_of(&case, Convention::Paper), f64_of(&case, Convention::PeriodicSurface));
        assert_eq!((fp.l, fp.c, fp.f_def), (fq.l, fq.c, fq.f_def), "{}", case_name(&case));
    }
}

// ---- scene key and command line ----

/// THEORY's check value as a scene, with `convention` as the [problem] line (may be empty).
fn check_scene(convention_line: &str) -> String {
    format!(
        "[problem]\nkind = \"sliding\"\n{convention_line}\n[material]\npoisson_ratio = \"1/3\"\ncontact_modulus = \"1\"\n\
         [punch]\nshape = \"parabolic\"\nk = \"1\"\nperiod = \"1\"\n[sliding]\nnormal_load = \"1/20\"\nfriction = \"2/5\"\n"
    )
}

fn num(v: &serde_json::Value, key: &str) -> f64 {
    v[key].as_str().unwrap_or_else(|| panic!("{key} is a string")).parse().unwrap()
}

#[test]
fn scene_key_and_flag_select_the_convention_and_the_provenance_states_it() {
    let default = scene_file("default.toml", &check_scene(""));
    let periodic = scene_file("periodic.toml", &check_scene("convention = \"periodic\""));
    let d = json(&["solve", &default, "--digits", "20", "--json"]);
    assert_eq!(d["provenance"]["convention"], "paper");
    assert!((num(&d, "c") - -0.0118478575).abs() < 1e-10);
    let p = json(&["solve", &periodic, "--digits", "20", "--json"]);
    assert_eq!(p["provenance"]["convention"], "periodic");
    assert!((num(&p, "c") - -0.0068478575).abs() < 1e-10);
    // The flag overrides the scene, both ways, for each full method.
    for method in ["mpfr", "f64"] {
        let o = json(&["solve", &default, "--method", method, "--convention", "periodic", "--json"]);
        assert_eq!(o["provenance"]["convention"], "periodic", "{method}");
        assert_eq!(o["provenance"]["method"], method);
        assert!((num(&o, "c") - -0.0068478575).abs() < 1e-10, "{method}");
        let o = json(&["solve", &periodic, "--method", method, "--convention", "paper", "--json"]);
        assert_eq!(o["provenance"]["convention"], "paper", "{method}");
        assert!((num(&o, "c") - -0.0118478575).abs() < 1e-10, "{method}");
    }
    // The series method states its convention and solves both (the periodic expansions with odd
    // powers of Lambda): c within its estimated digits of the check value.
    let s = json(&["solve", &default, "--method", "series", "--json"]);
    assert_eq!(s["provenance"]["convention"], "paper");
    let s = json(&["solve", &periodic, "--method", "series", "--json"]);
    assert_eq!(s["provenance"]["convention"], "periodic");
    eprintln!("series periodic c = {}", num(&s, "c"));
    assert!((num(&s, "c") - -0.0068478575).abs() < 1e-6, "{}", num(&s, "c"));
}

#[test]
fn frictionless_series_accepts_the_periodic_convention() {
    let text = check_scene("convention = \"periodic\"").replace("friction = \"2/5\"\n", "");
    let f = scene_file("frictionless.toml", &text);
    let s = json(&["solve", &f, "--method", "series", "--json"]);
    assert_eq!(s["provenance"]["convention"], "periodic");
}

#[test]
fn bad_convention_is_an_input_error_naming_the_key_or_flag() {
    let bad = scene_file("bad.toml", &check_scene("convention = \"closed\""));
    let (code, _, err) = run(&["solve", &bad]);
    assert_eq!(code, 2, "{err}");
    for word in ["problem.convention", "closed", "paper", "periodic"] {
        assert!(err.contains(word), "{word} missing from: {err}");
    }
    let not_string = scene_file("bad2.toml", &check_scene("convention = 1"));
    let (code, _, err) = run(&["solve", &not_string]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("problem.convention"), "{err}");
    let ok = scene_file("ok.toml", &check_scene(""));
    let (code, _, err) = run(&["solve", &ok, "--convention", "closed"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("--convention") && err.contains("closed"), "{err}");
}

/// Issue 32: Problem 2 is not the same in both conventions (docs/theory.md section 8, Problem 2):
/// `[problem] convention = "periodic"` and `solve --convention periodic` both make u periodic,
/// which changes the load (nu = 0.3 scene, f64), and the provenance names the convention; `paper`
/// (the default) is the earlier answer, without the key.
#[test]
fn adhesion_scenes_follow_the_convention() {
    let base_path = concat!(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."), "/scenes/adhesion_nu03.toml");
    let base = std::fs::read_to_string(base_path).unwrap();
    let with = base.replacen("kind = \"adhesion\"", "kind = \"adhesion\"\nconvention = \"periodic\"", 1);
    assert_ne!(base, with, "the scene has kind = \"adhesion\"");
    let path = scene_file("adhesion_periodic.toml", &with);
    let a = json(&["solve", &path, "--method", "f64", "--json"]);
    let flag = json(&["solve", base_path, "--method", "f64", "--json", "--convention", "periodic"]);
    let b = json(&["solve", base_path, "--method", "f64", "--json"]);
    assert_eq!(a, flag);
    assert_eq!(a["provenance"]["convention"], "periodic");
    assert!(b["provenance"].get("convention").is_none());
    let p2 = |v: &serde_json::Value| v["P2"].as_str().unwrap().parse::<f64>().unwrap();
    assert!((p2(&a) - p2(&b)).abs() > 1e-3 * p2(&b), "{} vs {}", a["P2"], b["P2"]);
}

/// Issue 10: a refusal in `paper` that `periodic` solves says so, and `periodic` then answers.
#[test]
fn paper_refusal_points_to_the_periodic_convention() {
    let scene = scene_file(
        "sinusoid_mu06.toml",
        "[problem]\nkind = \"sliding\"\n[material]\npoisson_ratio = \"0\"\ncontact_modulus = \"1\"\n[punch]\n\
         shape = \"sinusoidal\"\namplitude = \"0.01\"\nperiod = \"1\"\n[sliding]\nnormal_load = \"0.02\"\nfriction = \"0.6\"\n",
    );
    for method in ["mpfr", "f64"] {
        let (code, _, err) = run(&["solve", &scene, "--method", method, "--digits", "20"]);
        assert_eq!(code, 1, "{method}: {err}");
        assert!(err.contains("--convention periodic"), "{method}: {err}");
        let (code, _, err) = run(&["solve", &scene, "--method", method, "--digits", "20", "--convention", "periodic"]);
        assert_eq!(code, 0, "{method}: {err}");
    }
}
