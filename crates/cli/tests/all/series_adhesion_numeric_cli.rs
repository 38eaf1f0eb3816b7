//! `periodic-contact series adhesion --order N --nu R` beyond the exact route (issue 13,
//! "coefficients to any order"): the numerical route's content at order 200 (its time is in
//! docs/performance.md), its first terms against the exact route's values at the same nu, the
//! pole at nu = 0, and the refusals.

use super::common;
use common::{assert_usage_error, run};

/// The `[v^k] value` lines of a text output as (part, power, value): every such line when
/// `marker` is empty, else only those after a line starting with `marker` within each part.
fn values(text: &str, marker: &str) -> Vec<(String, String, String)> {
    let mut part = String::new();
    let mut out = Vec::new();
    let mut on = marker.is_empty();
    for line in text.lines() {
        if !marker.is_empty() && line.starts_with(marker) {
            on = true;
            continue;
        }
        if let Some(name) = line.strip_prefix("part: ").or_else(|| line.strip_prefix("object: ")) {
            part = name.trim().to_string();
            on = marker.is_empty();
            continue;
        }
        if let (true, Some(rest)) = (on, line.strip_prefix('[')) {
            let (power, value) = rest.split_once("] ").unwrap();
            out.push((part.clone(), power.to_string(), value.to_string()));
        }
    }
    out
}

/// `--order 200 --nu 3/10`: exit 0, every term through lambda^200 and chi^201, 30 digits
/// verified, no pole; its first terms (through lambda^12 and chi^13) print exactly the 30-digit
/// values of the exact route `--order 12 --nu 3/10` (the symbolic coefficients substituted).
#[test]
fn order_200_at_three_tenths_matches_the_exact_route() {
    let (code, text, err) = run(&["series", "adhesion", "--order", "200", "--nu", "3/10"]);
    assert_eq!(code, 0, "{err}");
    assert!(text.contains("object: adhesion (numerical route)"), "{text}");
    assert!(text.contains("no pole"), "{text}");
    assert!(text.contains("[lambda^200] "), "{text}");
    assert!(text.contains("[chi^201] "), "{text}");
    let numeric = values(&text, "");
    assert_eq!(numeric.len(), 1 + 101 + 101);
    let (code, exact, err) = run(&["series", "adhesion", "--order", "12", "--nu", "3/10"]);
    assert_eq!(code, 0, "{err}");
    // The exact route prints the values after "values at nu = 3/10 (30 digits):" in each part.
    let exact = values(&exact, "values at nu = 3/10 (30 digits):");
    assert_eq!(exact.len(), 1 + 7 + 7);
    for (part, power, value) in &exact {
        let same = numeric.iter().find(|(p, k, _)| p == part && k == power);
        let Some((_, _, v)) = same else { panic!("{part} {power} missing from the numerical route") };
        assert_eq!(v, value, "{part} [{power}]");
    }
    let (code, json, err) = run(&["series", "adhesion", "--order", "200", "--nu", "3/10", "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&json).unwrap();
    assert_eq!(v["route"], "numeric");
    assert_eq!(v["printed_order"], 200);
    assert!(v["pole"].is_null());
    assert!(v["verified_digits"].as_f64().unwrap() >= 30.0, "{}", v["verified_digits"]);
    assert_eq!(v["parts"][1]["coefficients"].as_array().unwrap().len(), 101);
}

/// nu = 0 beyond N = 303: the text and the JSON name the sign change of Re M_(2N+1) and print
/// through lambda^604 only.
#[test]
#[ignore = "long tier: 6 s alone in the test profile (opt-level 2) on a loaded 2-core machine (scripts/test --long)"]
fn pole_at_nu_zero_is_named() {
    let (code, text, err) = run(&["series", "adhesion", "--order", "640", "--nu", "0", "--digits", "12"]);
    assert_eq!(code, 0, "{err}");
    assert!(text.contains("changes sign at N = 303"), "{}", &text[..2000.min(text.len())]);
    assert!(text.contains("[lambda^604] ") && !text.contains("[lambda^606] "));
    let (code, json, err) =
        run(&["series", "adhesion", "--order", "640", "--nu", "0", "--digits", "12", "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&json).unwrap();
    assert_eq!(v["pole"]["n"], 303);
    assert_eq!(v["printed_order"], 604);
}

/// `--digits` at a small order runs the numerical route; the exact route without --nu stays capped
/// at 24 and says where the numerical route is; bad values name the flag (exit code 2).
#[test]
fn routes_and_refusals() {
    let (code, text, err) = run(&["series", "adhesion", "--order", "4", "--nu", "1/4", "--digits", "50"]);
    assert_eq!(code, 0, "{err}");
    assert!(text.contains("values to 50 digits"), "{text}");
    for (args, needle) in [
        (vec!["series", "adhesion", "--order", "30"], "with --nu R the numerical route takes up to 1000"),
        (vec!["series", "adhesion", "--order", "1002", "--nu", "0.3"], "[0, 1000]"),
        (vec!["series", "adhesion", "--order", "4", "--nu", "0.3", "--digits", "0"], "--digits"),
        (vec!["series", "adhesion", "--order", "4", "--digits", "20"], "only the adhesion series with --nu"),
        (vec!["series", "kernel", "--order", "4", "--digits", "20"], "--digits"),
        (vec!["series", "adhesion", "--order", "40", "--nu", "0.3", "--format", "latex"], "text or json"),
        (vec!["series", "adhesion", "--order", "40", "--nu", "0.7"], "must lie in [0, 1/2]"),
        (vec!["series", "adhesion", "--order", "40", "--nu", "0.3", "--pade"], "built by the exact route"),
        (vec!["series", "loading-law", "--order", "4", "--nu", "0.3", "--ratio", "0", "--digits", "9"], "--digits"),
    ] {
        assert_usage_error(&args, needle);
    }
}

/// Issue 31: lambda_h(nu, digits) from a command: `series adhesion --nu R --digits D` prints the
/// horizon (text line `horizon:` and JSON key `lambda_h`, 3 decimals rounded down), rising with
/// nu: at 20 digits 0.766 (nu = 0), 0.951 (1/10: 0.9519, printed rounded down), 1.333 (3/10)
/// (docs/theory.md section 11).
#[test]
fn the_horizon_from_a_command() {
    let mut last = 0.0;
    for (nu, want) in [("0", "0.766"), ("1/10", "0.951"), ("3/10", "1.333")] {
        let (code, out, err) =
            run(&["series", "adhesion", "--order", "4", "--nu", nu, "--digits", "20", "--format", "json"]);
        assert_eq!(code, 0, "{err}");
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        let h = v["lambda_h"].as_str().unwrap_or_else(|| panic!("lambda_h in {v}"));
        assert_eq!(h, want, "nu = {nu}");
        let x: f64 = h.parse().unwrap();
        assert!(x > last, "lambda_h rises with nu: {x} after {last}");
        last = x;
        let (code, text, err) = run(&["series", "adhesion", "--order", "4", "--nu", nu, "--digits", "20"]);
        assert_eq!(code, 0, "{err}");
        assert!(text.contains(&format!("horizon: lambda_h = {want} (at nu = ")), "{text}");
    }
}
