//! The typed answer of `api::solve` (issue 29): every number the JSON prints is a typed
//! `Quantity` with the same text, and its claimed digits hold. Per problem (sliding, adhesion, the
//! loading law) the f64 method's quantities are checked against the verified MPFR answer at more
//! digits: |value - truth| <= 10^-digits scale, the claim of each quantity on its own.

use periodic_contact::api::{self, Answer, DigitsKind, Quantity, SolveOptions};
use serde_json::Value;

fn solve(scene: &str, method: &str, digits: u32) -> Answer {
    let path = format!("{}/scenes/{scene}", env!("CARGO_MANIFEST_DIR"));
    let opts = SolveOptions { method: Some(method.into()), digits: Some(digits), ..Default::default() };
    api::solve_file(path.as_ref(), &opts).unwrap_or_else(|e| panic!("{scene} {method}: {e}"))
}

/// The JSON text of a field `name` at point `i`: Problem 1 `pressure[i]`, the loading law
/// `points[i]`, Problem 2 `name[i]`.
fn field_text<'a>(json: &'a Value, name: &str, i: usize) -> &'a str {
    let row = match (json.get("pressure"), json.get("points")) {
        (Some(p), _) if !p.is_null() => &p[i],
        (_, Some(p)) if !p.is_null() => &p[i],
        _ => &json[name][i],
    };
    row[name].as_str().unwrap_or_else(|| panic!("no {name} at {i} in {row}"))
}

/// Every typed number is the JSON's, and the answer has the scalars `keys`.
fn same_as_json(a: &Answer, keys: &[&str]) -> usize {
    let mut n = 0;
    for k in keys {
        let q = a.get(k).unwrap_or_else(|| panic!("no quantity {k}"));
        assert_eq!(q.text, a.json[*k].as_str().unwrap(), "{k}");
        n += 1;
    }
    let v = &a.solutions[0];
    for (k, q) in &v.scalars {
        assert_eq!(q.text, a.json[k].as_str().unwrap(), "{k}");
        assert!(q.digits.is_finite() && q.scale >= 0.0 && q.value.is_finite(), "{k}: {q:?}");
        // A zero scale is an exact zero (no wear): the value is that zero.
        assert!(q.scale > 0.0 || q.value == 0.0, "{k}: {q:?}");
    }
    for f in &v.fields {
        for (i, (_, q)) in f.points.iter().enumerate() {
            assert_eq!(q.text, field_text(&a.json, &f.name, i), "{}[{i}]", f.name);
            n += 1;
        }
    }
    n + v.scalars.len()
}

/// Each quantity of `approx` holds its digits against `truth`'s value (whose own error is
/// 10^-truth.digits of the same scale).
fn holds(approx: &Quantity, truth: &Quantity, what: &str) {
    let err = (approx.value - truth.value).abs();
    let bound = 10f64.powf(-approx.digits) * approx.scale + 10f64.powf(-truth.digits) * truth.scale;
    assert!(err <= bound * 1.0001, "{what}: {approx:?} vs {truth:?}: error {err:e} > {bound:e}");
}

/// A coordinate as printed: a decimal, or an exact fraction "p/q".
fn coordinate(t: &str) -> f64 {
    match t.split_once('/') {
        Some((p, q)) => p.parse::<f64>().unwrap() / q.parse::<f64>().unwrap(),
        None => t.parse().unwrap(),
    }
}

fn all_hold(approx: &Answer, truth: &Answer) -> usize {
    let (a, t) = (&approx.solutions[0], &truth.solutions[0]);
    let mut n = 0;
    for (k, q) in &a.scalars {
        holds(q, t.get(k).unwrap_or_else(|| panic!("truth lacks {k}")), k);
        n += 1;
    }
    for f in &a.fields {
        let tf = t.field(&f.name).unwrap();
        for ((x, q), (tx, tq)) in f.points.iter().zip(&tf.points) {
            let (x, tx) = (coordinate(x), coordinate(tx));
            assert!((x - tx).abs() <= 1e-15 * x.abs(), "{x} {tx}");
            holds(q, tq, &format!("{} at {x}", f.name));
            n += 1;
        }
    }
    n
}

#[test]
fn sliding_quantities_are_the_json_and_hold_their_digits() {
    let truth = solve("sliding_friction.toml", "mpfr", 25);
    let f64 = solve("sliding_friction.toml", "f64", 30);
    assert!(same_as_json(&truth, &["l", "a", "b", "c", "P1", "P2", "F_def"]) > 7);
    assert!(same_as_json(&f64, &["l", "a", "b", "c", "P1", "P2"]) > 6);
    assert_eq!(truth.get("P2").unwrap().kind, DigitsKind::Verified);
    assert!(f64.field("p").is_some_and(|f| f.at == "xh" && !f.points.is_empty()));
    assert!(all_hold(&f64, &truth) > 8);
    // A claim is the text's: the printed digits never exceed what the typed value holds.
    let c = f64.get("c").unwrap();
    assert!(c.digits <= 16.0 && c.digits > 12.0, "{c:?}");
}

#[test]
fn adhesion_quantities_are_the_json_and_hold_their_digits() {
    let truth = solve("adhesion_nu03.toml", "mpfr", 25);
    let f64 = solve("adhesion_nu03.toml", "f64", 30);
    assert!(same_as_json(&truth, &["P2", "half_width"]) > 2);
    same_as_json(&f64, &["P2", "half_width"]);
    assert!(truth.field("q2").is_some_and(|f| f.at == "x_over_a"));
    assert!(all_hold(&f64, &truth) > 2);
}

#[test]
#[ignore = "long tier: 9 s alone in the test profile (opt-level 2) on a loaded 2-core machine (scripts/test --long)"]
fn loading_law_quantities_are_the_json_and_hold_their_digits() {
    let truth = solve("adhesion_loading_law.toml", "mpfr", 16);
    let f64 = solve("adhesion_loading_law.toml", "f64", 30);
    same_as_json(&truth, &["a", "b", "c", "l", "P1", "P2"]);
    same_as_json(&f64, &["a", "b", "c", "l", "P1", "P2"]);
    assert!(truth.field("q1").is_some_and(|f| f.at == "xh"));
    assert!(all_hold(&f64, &truth) > 6);
}
