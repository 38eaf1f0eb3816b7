//! Issue 11 on the command line: the shipped scenes of the new punches (quartic, asymmetric cubic,
//! circle) solve with both methods, agree, and their provenance names the punch; bad profiles in
//! a scene are input errors (exit code 2) naming the key.

use super::common;
use common::{json, run, scene_file};

fn num(v: &serde_json::Value, key: &str) -> f64 {
    v[key].as_str().unwrap_or_else(|| panic!("{key} is a string")).parse().unwrap()
}

fn scene(name: &str) -> String {
    format!("{}/scenes/{name}.toml", concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
}

#[test]
fn shipped_profile_scenes_solve_with_both_methods() {
    for (name, shape) in [("quartic", "polynomial"), ("cubic_asymmetric", "polynomial"), ("circle", "circular")] {
        let path = scene(name);
        let m = json(&["solve", &path, "--json"]);
        let f = json(&["solve", &path, "--method", "f64", "--json"]);
        assert!(num(&m, "digits_verified") >= 30.0, "{name}: {m}");
        assert_eq!(m["provenance"]["punch"]["shape"], shape, "{name}");
        assert_eq!(f["provenance"]["punch"]["shape"], shape, "{name}");
        let l = num(&m, "l");
        for key in ["a", "b", "c"] {
            let (x, y) = (num(&m, key), num(&f, key));
            assert!((x - y).abs() / l < 1e-12, "{name} {key}: mpfr {x} vs f64 {y}");
        }
    }
    let m = json(&["solve", &scene("quartic"), "--json"]);
    assert_eq!(m["provenance"]["punch"]["coefficients"], serde_json::json!(["0", "0", "1", "0", "1/10"]));
    let c = json(&["solve", &scene("circle"), "--json"]);
    assert_eq!(c["provenance"]["punch"]["radius"], "1/2");
    assert_eq!(c["provenance"]["convention"], "periodic");
    // The series method refuses them (input, exit code 2).
    let (code, _, err) = run(&["solve", &scene("quartic"), "--method", "series", "--json"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("punch.shape"), "{err}");
}

#[test]
fn bad_profiles_in_a_scene_are_input_errors_naming_the_key() {
    let base = |punch: &str| {
        format!(
            "[problem]\nkind = \"sliding\"\n[material]\npoisson_ratio = \"0.3\"\ncontact_modulus = \"1\"\n[punch]\n{punch}\nperiod = \"1\"\n[sliding]\nnormal_load = \"0.01\"\n"
        )
    };
    for (i, (punch, key)) in [
        ("shape = \"polynomial\"\ncoefficients = [\"1\", \"0\", \"1\"]", "coefficients"),
        ("shape = \"polynomial\"\ncoefficients = [\"0\", \"1\"]", "coefficients"),
        ("shape = \"polynomial\"\ncoefficients = [\"0\", \"0\", \"x\"]", "punch.coefficients[2]"),
        ("shape = \"polynomial\"\ncoefficients = \"1\"", "punch.coefficients"),
        ("shape = \"polynomial\"\nk = \"1\"", "punch.k"),
        ("shape = \"circular\"\nradius = \"-1\"", "radius"),
        ("shape = \"circular\"", "punch.radius"),
    ]
    .into_iter()
    .enumerate()
    {
        let path = scene_file(&format!("bad_profile_{i}.toml"), &base(punch));
        let (code, _, err) = run(&["solve", &path, "--json"]);
        assert_eq!(code, 2, "{punch}: {err}");
        assert!(err.contains(key), "{punch}: {err}");
    }
}
