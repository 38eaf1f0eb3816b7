//! The command line as a user meets it: exit codes and messages (0 ok, 2 invalid input).

use std::process::Command;

fn run(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_periodic-contact")).args(args).output().expect("binary runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn series_json_has_the_documented_layout() {
    let (code, out, _) =
        run(&["series", "weight", "--order", "4", "--theta", "1/10", "--xh", "-1/2", "--format", "json"]);
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
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
        let (code, out, err) = run(&args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(out.is_empty(), "{args:?} printed {out}");
        assert!(err.contains(needle), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
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
    let bin = env!("CARGO_BIN_EXE_periodic-contact");
    let out = std::process::Command::new(bin)
        .args(["series", "sliding", "--order", "3", "--convention", "periodic"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("[Lambda^1] 2*kappa*theta^2 + 2*T*invpi - 1/2*kappa"), "{text}");
    let bad = std::process::Command::new(bin).args(["series", "kernel", "--order", "3", "--convention", "periodic"]).output().unwrap();
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("--convention"));
}
