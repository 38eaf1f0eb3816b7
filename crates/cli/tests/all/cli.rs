//! The command line as a user meets it: exit codes and messages (0 ok, 2 invalid input).

use super::common;
use common::{assert_usage_error, run};

#[test]
fn series_json_has_the_documented_layout() {
    let (code, out, _) =
        run(&["series", "weight", "--order", "4", "--theta", "1/10", "--xh", "-1/2", "--format", "json"]);
    assert_eq!(code, 0);
    let top: serde_json::Value = serde_json::from_str(&out).unwrap();
    // One schema for every object (issue 15): {"object", "parts": [...]}.
    assert_eq!(top["object"], "weight");
    let v = &top["parts"][0];
    assert_eq!(v["object"], "weight");
    assert_eq!(v["variable"], "lambda");
    assert_eq!(v["order"], 4);
    assert_eq!(v["symbols"], serde_json::json!([]));
    // At theta = 1/10, xh = -1/2: -1/6 (1 + xh^2 + 4 theta xh) = -1/6 (1 + 1/4 - 1/5) = -7/40.
    assert_eq!(v["coefficients"][1]["power"], 2);
    assert_eq!(v["coefficients"][1]["text"], "-7/40");
}

#[test]
fn bad_input_is_exit_code_2_with_a_message_naming_the_parameter() {
    for (args, needle) in [
        (vec!["series", "kernel", "--order", "1000000000"], "--order"),
        (vec!["series", "kernel", "--order", "-3"], "--order"),
        (vec!["series", "kernel", "--order", "x"], "--order"),
        (vec!["series", "weight", "--order", "4", "--theta", "1/2"], "|theta| < 1/2"),
        (vec!["series", "weight", "--order", "4", "--theta", "abc"], "--theta"),
        (vec!["series", "weight", "--order", "4", "--xh", "3/2"], "[-1, 1]"),
        (vec!["series", "jacobi", "--order", "4", "--xh", "0"], "--xh"),
        (vec!["series", "nothing", "--order", "4"], "possible values"),
        (vec!["series", "kernel"], "--order"),
        (vec!["series", "adhesion", "--order", "2", "--nu", "0.6"], "--nu = 3/5: must lie in [0, 1/2]"),
        (vec!["series", "kernel", "--order", "2", "--nu", "0.3"], "only the adhesion series"),
    ] {
        assert_usage_error(&args, needle);
    }
}

#[test]
fn output_is_deterministic() {
    let a = run(&["series", "jacobi", "--order", "20", "--format", "latex"]);
    let b = run(&["series", "jacobi", "--order", "20", "--format", "latex"]);
    assert_eq!(a, b);
    assert!(a.1.contains(r"j_{1} &= -2 \theta"));
}

/// Issue 10: `series sliding --convention periodic` prints the periodic expansions (odd powers of
/// Lambda; the first interaction term of rbar is O(Lambda), THEORY.md section 8); the flag is
/// refused for objects without a convention.
#[test]
fn series_sliding_periodic_convention() {
    let (code, text, err) = run(&["series", "sliding", "--order", "3", "--convention", "periodic"]);
    assert_eq!(code, 0, "{err}");
    assert!(text.contains("[Lambda^1] 2*kappa*theta^2 + 2*T*invpi - 1/2*kappa"), "{text}");
    let (code, _, err) = run(&["series", "kernel", "--order", "3", "--convention", "periodic"]);
    assert_eq!(code, 2);
    assert!(err.contains("--convention"), "{err}");
}
