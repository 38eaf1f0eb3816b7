//! `periodic-contact solve`: the three routes of Problem 1 agree, the two methods of Problem 2
//! agree, bad input is exit code 2, no solution is exit code 1, output is deterministic.

use super::common;
use common::{json, run, scene_file};

fn num(v: &serde_json::Value, key: &str) -> f64 {
    v[key].as_str().unwrap_or_else(|| panic!("{key} is a string")).parse().unwrap()
}

const SCENE: &str = concat!(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."), "/scenes/sliding_friction.toml");
const ADHESION: &str = concat!(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."), "/scenes/adhesion_nu03.toml");

#[test]
fn three_routes_of_problem_1_agree() {
    let m = json(&["solve", SCENE, "--json"]);
    let f = json(&["solve", SCENE, "--method", "f64", "--json"]);
    let s = json(&["solve", SCENE, "--method", "series", "--json"]);
    assert!(num(&m, "digits_verified") >= 30.0);
    let l = num(&m, "l");
    for key in ["a", "b", "c"] {
        let (x, y, z) = (num(&m, key), num(&f, key), num(&s, key));
        assert!((x - y).abs() / l < 1e-12, "{key}: mpfr {x} vs f64 {y}");
        // The series (order 12, Lambda ~ 0.25) states ~13 estimated digits.
        assert!((x - z).abs() / l < 1e-11, "{key}: mpfr {x} vs series {z}");
    }
    let pm = m["pressure"][1]["p"].as_str().unwrap().parse::<f64>().unwrap();
    let pf = f["pressure"][1]["p"].as_str().unwrap().parse::<f64>().unwrap();
    assert!((pm - pf).abs() / pm < 1e-12);
    // The series method does not call its digits verified.
    assert!(s["digits_verified"].is_null());
    assert_eq!(m["provenance"]["method"], "mpfr");
}

#[test]
fn two_methods_of_problem_2_agree() {
    let m = json(&["solve", ADHESION, "--json"]);
    let f = json(&["solve", ADHESION, "--method", "f64", "--json"]);
    assert!(num(&m, "digits_verified") >= 20.0);
    let (pm, pf) = (num(&m, "P2"), num(&f, "P2"));
    assert!(approx::relative_eq!(pm, pf, epsilon = 0.0, max_relative = 1e-12), "P2 {pm} vs {pf}");
    for field in ["psi", "q1", "q2"] {
        for i in 0..4 {
            let a: f64 = m[field][i][field].as_str().unwrap().parse().unwrap();
            let b: f64 = f[field][i][field].as_str().unwrap().parse().unwrap();
            assert!((a - b).abs() <= 1e-11 * (1.0 + a.abs()), "{field}[{i}]: {a} vs {b}");
        }
    }
}

#[test]
fn same_scene_same_bytes() {
    let a = run(&["solve", SCENE, "--json"]);
    let b = run(&["solve", SCENE, "--json"]);
    assert_eq!(a, b);
}

#[test]
fn exit_codes() {
    // Invalid input: 2, naming the parameter.
    let (code, out, err) = run(&["solve", "/nonexistent/scene.toml"]);
    assert_eq!(code, 2, "{err}");
    assert!(out.is_empty() && err.contains("cannot be read"));
    let bad = scene_file(
        "bad.toml",
        &std::fs::read_to_string(SCENE).unwrap().replace("\"0.3\"\ncontact", "\"0.7\"\ncontact"),
    );
    let (code, _, err) = run(&["solve", &bad]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("poisson_ratio = 7/10: must lie in [0, 1/2]"), "{err}");
    for digits in ["0", "1000000000", "-5", "many"] {
        let (code, _, err) = run(&["solve", SCENE, "--digits", digits]);
        assert_eq!(code, 2, "{digits}: {err}");
        assert!(err.contains("--digits"), "{err}");
    }
    // lambda -> pi/2 (a sinusoid's contact all but closing the period): an answer with verified
    // digits, or a clear refusal; never a panic or a silent NaN.
    let near_full = scene_file(
        "near_full.toml",
        &std::fs::read_to_string(SCENE)
            .unwrap()
            .replace("shape = \"parabolic\"\nk = \"1\"", "shape = \"sinusoidal\"\namplitude = \"0.01\"")
            .replace("normal_load = \"0.01\"", "half_length = \"0.4999\""),
    );
    let (code, out, err) = run(&["solve", &near_full, "--digits", "20", "--json"]);
    // The size is valid input; the quadrature cannot reach 20 digits this close to pi/2: a
    // no-convergence refusal (exit 1) naming lambda, never a panic or a silent NaN.
    assert_eq!(code, 1, "{out}{err}");
    assert!(err.contains("no convergence: lambda = pi l/L = 1.570482 is too close to pi/2"), "{err}");
    assert!(!err.contains("panicked") && !out.contains("NaN"), "{out}{err}");
    // No solution: 1, with the reason. A sinusoid with wear cannot carry an arbitrary load.
    let heavy = scene_file(
        "heavy.toml",
        r#"
[problem]
kind = "sliding"
[material]
poisson_ratio = "0.3"
contact_modulus = "1"
[punch]
shape = "sinusoidal"
amplitude = "0.01"
period = "1"
[sliding]
normal_load = "10"
wear = "0.5"
"#,
    );
    let (code, out, err) = run(&["solve", &heavy, "--digits", "20"]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(err.contains("no solution"), "{err}");
    assert!(!err.contains("panicked"));
}

/// Issue 9: a value below its scale x 10^-digits is noise and prints as 0 (with its accuracy), in
/// both number types: the frictionless F_def and centre of the Kuznetsov scene.
#[test]
fn noise_prints_as_zero() {
    for method in ["mpfr", "f64"] {
        let v = json(&["solve", "scenes/kuznetsov_parabola.toml", "--method", method, "--json"]);
        assert_eq!(v["F_def"], "0", "{method}: {v}");
        assert_eq!(v["c"], "0", "{method}: {v}");
        assert!(num(&v["accuracy"], "F_def") >= 12.0, "{method}: {v}");
    }
}
