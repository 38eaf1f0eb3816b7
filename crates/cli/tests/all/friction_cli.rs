//! `periodic-contact solve` with `[adhesion] friction` (issue 32, docs/theory.md section 17): the
//! shipped single-punch scene gives the boundary-element c/a = 0.5219(1) to its digits, and what is
//! not solved with finite friction is refused as bad input (exit code 2) naming the parameter; a
//! finite period goes to the periodic row.

use super::common;
use common::{json, run, scene_file};

const SCENE: &str = "scenes/adhesion_friction_single.toml";

fn num(v: &serde_json::Value, key: &str) -> f64 {
    v[key].as_str().unwrap_or_else(|| panic!("{key} is a string in {v}")).parse().unwrap()
}

#[test]
fn shipped_scene_gives_the_boundary_element_stick_ratio() {
    let v = json(&["solve", SCENE, "--json"]);
    let (c, a) = (num(&v, "stick_half_width"), num(&v, "half_width"));
    let digits = num(&v["accuracy"], "stick");
    assert!(digits >= 4.0, "{v}");
    // issue 32: 0.5219(1) by boundary elements; this answer's own claim on the scale a
    let claimed = 10f64.powf(-digits) * a;
    assert!((c / a - 0.5219).abs() <= 1e-4 + claimed, "c/a = {} ({digits} digits)", c / a);
    assert_eq!(v["friction"], "1/2");
    assert_eq!(v["provenance"]["method"], "f64");
    assert_eq!(v["choice"]["method"], "f64");
    // the headline is the fields' (3-4 digits), the size and the stick zone hold 4-5
    assert!(v["digits_verified"].is_null() && num(&v, "digits_estimated") >= 3.0, "{v}");
    assert!(num(&v["accuracy"], "size") >= 4.0, "{v}");
    // the fields at the scene's points x/a = 0, 0.5, 0.9: q1 = 0 at the centre, q1 = mu q2 in the
    // slip zone (0.9 > c/a), psi = 0 at the centre
    let at = |name: &str, i: usize| num(&v[name][i], name);
    assert!(at("q1", 0) == 0.0 && at("psi", 0) == 0.0 && at("q2", 0) > 0.0, "{v}");
    assert!((at("q1", 2) - 0.5 * at("q2", 2)).abs() < 1e-4, "{v}");
    // the checks, JSON numbers with their errors and meanings
    for key in
        ["stick_friction_ratio_max", "pressure_min_over_max", "outward_slip_rate_max", "methods_difference_stick_ratio"]
    {
        let c = &v["checks"][key];
        assert!(c["value"].is_number() && c["error"].is_number() && c["means"].is_string(), "{key}: {v}");
    }
    assert!(v["checks"]["stick_friction_ratio_max"]["value"].as_f64().unwrap() <= 1.0 + 1e-4, "{v}");
    // C_P = P/(E* k a^2) = 1.800927 (docs/theory.md 17.4), between Hertz's pi/2 and complete adhesion
    let p2 = num(&v, "P2");
    assert!(p2 > std::f64::consts::FRAC_PI_2 && p2 < 1.95787 && (p2 - 1.800927).abs() < 1e-4, "{v}");
    let zones = v["slip_zones"].as_array().unwrap();
    assert_eq!(zones.len(), 2);
    assert_eq!((num(&zones[0], "from"), num(&zones[0], "to")), (-a, -c));
    assert_eq!((num(&zones[1], "from"), num(&zones[1], "to")), (c, a));
    let note = v["friction_note"].as_str().unwrap();
    assert!(note.contains("Spence") && note.contains("stick") && note.contains("constant during loading"), "{note}");
    // the same answer under a given load: a = 1 back, the same c/a
    let text = std::fs::read_to_string(format!("{}/{SCENE}", common::ROOT)).unwrap();
    let loaded =
        scene_file("friction_load.toml", &text.replace("half_width = \"1\"", &format!("normal_load = \"{p2}\"")));
    let w = json(&["solve", &loaded, "--json"]);
    assert!((num(&w, "half_width") - 1.0).abs() < 1e-4 && (num(&w, "stick_half_width") - c).abs() < 1e-4, "{w}");
}

#[test]
fn what_friction_does_not_solve_is_refused_naming_it() {
    let (code, _, err) = run(&["solve", SCENE, "--method", "series"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("--method") && err.contains("--method mpfr") && err.contains("4-5 digits"), "{err}");
    let text = std::fs::read_to_string(format!("{}/{SCENE}", common::ROOT)).unwrap();
    // a finite period is the periodic row (lambda = pi a/L = 0.39 here), solved by the spectral
    // method; a contact beyond lambda <= 1.5 is refused naming half_width
    let periodic = scene_file("friction_period.toml", &text.replace("period = \"inf\"", "period = \"8\""));
    let (code, out, err) = run(&["solve", &periodic]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("stick_half_width") && out.contains("lambda: 3.92"), "{out}");
    let unswept = text.split("[sweep]").next().unwrap();
    let wide = scene_file("friction_wide.toml", &unswept.replace("period = \"inf\"", "period = \"2.05\""));
    let (code, _, err) = run(&["solve", &wide]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("half_width") && err.contains("lambda = pi a/L <= 1.5"), "{err}");
    let circle = scene_file(
        "friction_circle.toml",
        &text.replace("shape = \"parabolic\"\nk = \"1\"", "shape = \"circular\"\nradius = \"4\""),
    );
    let (code, _, err) = run(&["solve", &circle]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("shape") && err.contains("circular"), "{err}");
    // the spectral method's cost grows with the digits: more than 16 are refused naming `digits`,
    // and the periodic row's verified MPFR load at most 12 (the default 30 is refused naming digits)
    let (code, _, err) = run(&["solve", SCENE, "--method", "mpfr", "--digits", "30"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("digits") && err.contains("30") && err.contains("at most 16"), "{err}");
    let (code, _, err) = run(&["solve", &periodic, "--method", "mpfr"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("digits") && err.contains("periodic row") && err.contains("at most 12"), "{err}");
    let zero = scene_file("friction_zero.toml", &text.replace("friction = \"1/2\"", "friction = \"0\""));
    let (code, _, err) = run(&["solve", &zero]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("adhesion.friction") && err.contains("> 0"), "{err}");
}

#[test]
fn mpfr_gives_verified_digits_of_the_spectral_method() {
    // docs/theory.md section 17.7: c/a = 0.5219076749221461 (16.2 digits), C_P = 1.800911965200506302
    // without the points (their MPFR fields cost a minute in the test profile: the long tier's
    // friction_scene::mpfr_fields_are_verified_and_within_the_f64_claims) and the sweep
    let text = std::fs::read_to_string(format!("{}/{SCENE}", common::ROOT)).unwrap();
    let unswept = text.split("[sweep]").next().unwrap();
    let bare: String = unswept.lines().filter(|l| !l.starts_with("points")).map(|l| format!("{l}\n")).collect();
    let scene = scene_file("friction_mpfr.toml", &bare);
    let w = json(&["solve", &scene, "--method", "mpfr", "--digits", "10", "--json"]);
    // its checks: the difference from the f64 increment method within that method's estimate
    let check = &w["checks"]["methods_difference_stick_ratio"];
    assert!(check["value"].as_f64().unwrap() <= check["error"].as_f64().unwrap(), "{w}");
    assert!((num(&w, "stick_half_width") - 0.5219076749221461).abs() < 1e-10, "{w}");
    assert!((num(&w, "P2") - 1.800911965200506).abs() < 1e-9, "{w}");
    assert!(
        w["digits_verified"].is_object() || w["digits_verified"].is_number() || w["digits_verified"].is_string(),
        "{w}"
    );
}
