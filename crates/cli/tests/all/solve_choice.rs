//! `solve` honours `[output] target_digits` with the report's method choice (issue 15): the JSON's
//! `choice` names the method and why; the method meets the target; `--method`, `--digits` and
//! `[output] digits` still force theirs.

use super::common;
use common::{json, scene_file};
use periodic_contact::scene::parse::parse_scene;
use periodic_contact::solve::choice::{choose, Knob, Table};

fn scene_path(name: &str) -> String {
    format!("{}/{name}", concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
}

/// Digits the answer claims: verified, else estimated.
fn claimed(v: &serde_json::Value) -> f64 {
    let d = if v["digits_verified"].is_string() { &v["digits_verified"] } else { &v["digits_estimated"] };
    d.as_str().and_then(|s| s.parse().ok()).unwrap_or_else(|| panic!("no digits in {v}"))
}

#[test]
fn target_digits_runs_the_reports_choice_and_meets_it() {
    let table = Table::committed().unwrap();
    let mut methods = std::collections::BTreeSet::new();
    for scene in [
        "scenes/kuznetsov_parabola.toml",
        "scenes/sliding_wear.toml",
        "scenes/westergaard_sinusoid.toml",
        "scenes/adhesion_nu0.toml",
        "tests/data/report_scenes/parabola_friction.toml",
    ] {
        let path = scene_path(scene);
        let parsed = parse_scene(&std::fs::read_to_string(&path).unwrap()).unwrap();
        let target = parsed.output.target_digits.expect("the scene states target_digits");
        let expected = choose(&table, &parsed.problem, target);
        let v = json(&["solve", &path, "--json"]);
        let name = match expected.knob() {
            Knob::Series(_) => "series",
            Knob::F64(_) => "f64",
            Knob::Mpfr(_) | Knob::MpfrVerified(_) => "mpfr",
        };
        // The report's choice runs first; when its own digits fall short of the target, a dearer
        // candidate runs, and the reason says so.
        let reason = v["choice"]["reason"].as_str().unwrap();
        assert!(reason.starts_with(&expected.why()), "{scene}: {reason}");
        if reason == expected.why() {
            assert_eq!(v["choice"]["method"], name, "{scene}: {}", v["choice"]);
        } else {
            assert!(reason.contains(" claimed ") && reason.contains(" ran"), "{scene}: {reason}");
        }
        let ran = v["choice"]["method"].as_str().unwrap();
        assert_eq!(v["provenance"]["method"].as_str().map(|m| m.starts_with(ran)), Some(true), "{scene}");
        assert_eq!(v["choice"]["target_digits"], target.to_string(), "{scene}");
        assert!(claimed(&v) >= target as f64, "{scene}: claims {} < target {target}", claimed(&v));
        methods.insert(ran.to_string());
    }
    // The shipped scenes exercise more than one method: the choice is not a constant.
    assert!(methods.len() >= 2, "{methods:?}");
}

#[test]
fn method_and_digits_still_force() {
    let path = scene_path("scenes/kuznetsov_parabola.toml");
    let v = json(&["solve", &path, "--method", "f64", "--json"]);
    assert_eq!(v["choice"]["method"], "f64");
    assert_eq!(v["choice"]["reason"], "forced by --method");
    assert!(v["choice"]["target_digits"].is_null());
    let v = json(&["solve", &path, "--digits", "12", "--json"]);
    assert_eq!(v["choice"]["method"], "mpfr");
    assert_eq!(v["digits_requested"], "12");
    let text = "[problem]\nkind = \"sliding\"\n[material]\npoisson_ratio = \"0.3\"\ncontact_modulus = \"1\"\n\
                [punch]\nshape = \"parabolic\"\nk = \"1\"\nperiod = \"1\"\n[sliding]\nnormal_load = \"0.01\"\n";
    let v = json(&["solve", &scene_file("choice_default.toml", text), "--json"]);
    assert_eq!(v["choice"]["method"], "mpfr");
    assert_eq!(v["digits_requested"], "30");
    let forced = format!("{text}[output]\ndigits = 15\ntarget_digits = 8\n");
    let v = json(&["solve", &scene_file("choice_digits.toml", &forced), "--json"]);
    assert_eq!(v["choice"]["method"], "mpfr");
    assert_eq!(v["digits_requested"], "15");
}
