//! `docs/theory.md` defines every symbol, series part and JSON key the commands print (issue 15):
//! its tables (sections 12, 13, 14) are parsed here and every printed name must be in them, so the
//! document cannot drift from the outputs.

use super::common;
use common::{json, run};
use std::collections::BTreeSet;

const DOC: &str = include_str!("../../../../docs/theory.md");

/// The first backticked names of each row of the table in section `number` (column `col`),
/// e.g. "| `c_r`, `r` | ..." gives c_r and r.
fn table_names(number: u32, col: usize) -> Vec<String> {
    let start =
        DOC.find(&format!("\n## {number}. ")).unwrap_or_else(|| panic!("docs/theory.md has no section {number}"));
    let body = &DOC[start + 1..];
    let end = body[3..].find("\n## ").map_or(body.len(), |e| e + 3);
    let mut names = Vec::new();
    for line in body[..end].lines().filter(|l| l.starts_with('|')) {
        let Some(cell) = line.split('|').nth(col + 1) else { continue };
        for piece in cell.split(',') {
            let piece = piece.trim();
            if let Some(name) = piece.strip_prefix('`').and_then(|p| p.split('`').next()) {
                names.push(name.to_string());
            }
        }
    }
    assert!(names.len() > 5, "section {number} has too few rows: {names:?}");
    names
}

/// Whether `name` is defined by one of `defined`; a row `rho_j` (or `_n`, `_m`) stands for
/// `rho_1`, `rho_2`, ...
fn is_defined(name: &str, defined: &[String]) -> bool {
    defined.iter().any(|d| {
        d == name
            || ["_j", "_n", "_m"].iter().any(|s| {
                d.strip_suffix(s).is_some_and(|stem| {
                    name.strip_prefix(stem)
                        .and_then(|r| r.strip_prefix('_'))
                        .is_some_and(|i| !i.is_empty() && i.chars().all(|c| c.is_ascii_digit()))
                })
            })
    })
}

/// Every `symbols` entry, `variable` and `object` anywhere in a JSON value.
fn collect(v: &serde_json::Value, symbols: &mut BTreeSet<String>, objects: &mut BTreeSet<String>) {
    match v {
        serde_json::Value::Object(m) => {
            for (k, x) in m {
                match (k.as_str(), x) {
                    ("symbols", serde_json::Value::Array(a)) => {
                        symbols.extend(a.iter().filter_map(|s| s.as_str().map(String::from)))
                    }
                    ("variable", serde_json::Value::String(s)) => {
                        symbols.insert(s.clone());
                    }
                    ("object", serde_json::Value::String(s)) => {
                        objects.insert(s.clone());
                    }
                    _ => collect(x, symbols, objects),
                }
            }
        }
        serde_json::Value::Array(a) => a.iter().for_each(|x| collect(x, symbols, objects)),
        _ => {}
    }
}

/// Identifiers in the coefficient lines (`[v^k] text`, `j_k text`) of the text format.
fn text_identifiers(text: &str, out: &mut BTreeSet<String>) {
    for line in text.lines() {
        let rest = if let Some(r) = line.strip_prefix('[') {
            let (label, r) = r.split_once(']').unwrap_or(("", ""));
            out.insert(label.split('^').next().unwrap_or("").to_string());
            r
        } else if line.starts_with("j_") {
            line.split_once(' ').map_or("", |(_, r)| r)
        } else {
            continue;
        };
        let mut word = String::new();
        for c in rest.chars().chain(std::iter::once(' ')) {
            if c.is_ascii_alphanumeric() || c == '_' {
                word.push(c);
            } else {
                if is_word(&word) {
                    out.insert(word.clone());
                }
                word.clear();
            }
        }
    }
}

/// A word that is a name, not a number in exponent form such as `1e-3`.
fn is_word(w: &str) -> bool {
    w.starts_with(|c: char| c.is_ascii_alphabetic())
}

const SERIES_RUNS: &[&[&str]] = &[
    &["series", "kernel", "--order", "4"],
    &["series", "weight", "--order", "4"],
    &["series", "jacobi", "--order", "4"],
    &["series", "sliding", "--order", "4"],
    &["series", "sliding", "--order", "4", "--shape", "sinusoidal"],
    &["series", "sliding", "--order", "3", "--convention", "periodic"],
    &["series", "sliding", "--order", "2", "--shape", "polynomial", "--coefficients", "0,?,1,?,?"],
    &["series", "adhesion", "--order", "4"],
    &["series", "adhesion", "--order", "2", "--degree", "4"],
];

#[test]
fn every_printed_series_symbol_and_part_is_defined() {
    let symbols_doc = table_names(12, 0);
    let parts_doc = table_names(13, 1);
    let (mut symbols, mut objects) = (BTreeSet::new(), BTreeSet::new());
    for args in SERIES_RUNS {
        let mut a = args.to_vec();
        a.extend(["--format", "json"]);
        collect(&json(&a), &mut symbols, &mut objects);
        let (code, text, err) = run(args);
        assert_eq!(code, 0, "{args:?}: {err}");
        text_identifiers(&text, &mut symbols);
    }
    let (code, text, err) = run(&["series", "loading-law", "--nu", "3/10", "--ratio", "1/5", "--order", "2"]);
    assert_eq!(code, 0, "{err}");
    text_identifiers(&text, &mut symbols);
    for line in text.lines() {
        if let Some(p) = line.strip_prefix("part: ") {
            objects.insert(p.to_string());
        }
    }
    // Sanity: the collection sees what the outputs hold.
    for s in ["theta", "xh", "T", "Lambda", "lambda", "eps", "B", "S", "chi", "kappa", "invpi", "rho_3"] {
        assert!(symbols.contains(s), "{s} not collected: {symbols:?}");
    }
    let missing: Vec<_> = symbols.iter().filter(|s| !is_defined(s, &symbols_doc)).collect();
    assert!(missing.is_empty(), "symbols printed by `series` but not in docs/theory.md section 12: {missing:?}");
    let objects_doc: Vec<String> = parts_doc.into_iter().chain(table_names(13, 0)).collect();
    let missing: Vec<_> = objects.iter().filter(|s| !objects_doc.contains(s)).collect();
    assert!(missing.is_empty(), "series parts not in docs/theory.md section 13: {missing:?}");
}

fn keys(v: &serde_json::Value, out: &mut BTreeSet<String>) {
    match v {
        serde_json::Value::Object(m) => {
            for (k, x) in m {
                out.insert(k.clone());
                keys(x, out);
            }
        }
        serde_json::Value::Array(a) => a.iter().for_each(|x| keys(x, out)),
        _ => {}
    }
}

#[test]
fn every_solve_json_key_is_defined() {
    let doc = table_names(14, 0);
    let mut found = BTreeSet::new();
    for (scene, method) in [
        ("scenes/sliding_friction.toml", "f64"),
        ("scenes/sliding_friction.toml", "series"),
        ("scenes/adhesion_nu03.toml", "f64"),
        ("scenes/adhesion_loading_law.toml", "f64"),
        ("scenes/adhesion_friction_single.toml", "f64"),
    ] {
        let path = format!("{}/{scene}", concat!(env!("CARGO_MANIFEST_DIR"), "/../.."));
        keys(&json(&["solve", &path, "--method", method, "--json"]), &mut found);
    }
    for k in ["theta", "P2", "psi", "end_stress", "digits_verified", "provenance", "stick_half_width"] {
        assert!(found.contains(k), "{k} not collected");
    }
    let missing: Vec<_> = found.iter().filter(|k| !doc.contains(k)).collect();
    assert!(missing.is_empty(), "solve --json keys not in docs/theory.md section 14: {missing:?}");
}
