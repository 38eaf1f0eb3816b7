//! Issue 13's points for Problem 2 through the command line: where the problem fixes its solution
//! both methods deliver (MPFR >= 20 verified digits, f64 within 1e-12), and beyond, both refuse
//! naming the homogeneous solution and its exponent m* (asymptotics::adhesion_mode).

use super::common;
use common::{json, run, scene_file};

/// A Problem 2 scene: parabola k = 1, L = 1, E* = 1, half-width `a` = lambda/pi to 20 digits.
fn scene(nu: &str, a: &str) -> String {
    format!(
        "[problem]\nkind = \"adhesion\"\n[material]\npoisson_ratio = \"{nu}\"\ncontact_modulus = \"1\"\n\
         [punch]\nshape = \"parabolic\"\nk = \"1\"\nperiod = \"1\"\n[adhesion]\nhalf_width = \"{a}\"\n\
         [output]\ndigits = 20\npoints = [\"0\", \"0.5\", \"0.9\"]\n"
    )
}

fn num(v: &serde_json::Value) -> f64 {
    v.as_str().unwrap().parse().unwrap()
}

/// nu = 0, lambda = 0.7 (the series answers) and nu = 0.3, lambda = 1.2 (beyond the series: the
/// collocation in eta answers): MPFR verifies >= 20 digits, f64 agrees with it to 1e-12 in the
/// load and the fields and says which route it took.
#[test]
fn both_methods_deliver_where_the_problem_fixes_the_solution() {
    for (nu, a, route) in
        [("0", "0.22281692032865347008", "lambda^2 series"), ("0.3", "0.38197186342054880584", "collocation in eta")]
    {
        let path = scene_file(&format!("reach_{nu}.toml"), &scene(nu, a));
        let m = json(&["solve", &path, "--method", "mpfr", "--json"]);
        assert!(num(&m["digits_verified"]) >= 20.0, "nu {nu}: {m}");
        let f = json(&["solve", &path, "--method", "f64", "--json"]);
        assert_eq!(f["route"], route, "nu {nu}");
        assert!(num(&f["digits_estimated"]) >= 12.0, "nu {nu}: {f}");
        let rel = (num(&m["P2"]) - num(&f["P2"])).abs() / num(&m["P2"]);
        assert!(rel < 1e-12, "nu {nu}: P2 {} vs {}", m["P2"], f["P2"]);
        let scale: f64 = 0.3; // k a ~ 0.2-0.4: fields compared against 1e-12 of it
        for key in ["psi", "phi", "q1", "q2"] {
            for (u, v) in m[key].as_array().unwrap().iter().zip(f[key].as_array().unwrap()) {
                let (x, y) = (num(&u[key]), num(&v[key]));
                assert!((x - y).abs() < 1e-12 * scale.max(x.abs()), "nu {nu} {key}: {x} vs {y}");
            }
        }
    }
}

/// nu = 0, lambda = 1.2 and nu = 0.3, lambda = 1.5: both methods refuse (exit code 2), naming
/// the homogeneous solution and m* (605.7 at nu = 0, 1409212.5 at nu = 0.3).
#[test]
fn beyond_it_both_refuse_naming_the_mode() {
    for (nu, a, m_star) in
        [("0", "0.38197186342054880584", "m* = 605.7"), ("0.3", "0.47746482927568600730", "m* = 1409212.5")]
    {
        let path = scene_file(&format!("beyond_{nu}.toml"), &scene(nu, a));
        for method in ["mpfr", "f64"] {
            let (code, _, err) = run(&["solve", &path, "--method", method, "--json"]);
            assert_ne!(code, 0, "nu {nu} {method}");
            assert!(err.contains("homogeneous solution") && err.contains(m_star), "nu {nu} {method}: {err}");
        }
    }
}
