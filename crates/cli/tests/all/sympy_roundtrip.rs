//! The SymPy format read back by SymPy (issue 15): `periodic-contact series ... --format sympy` is
//! parsed by plain `sympy.sympify` and compared coefficient by coefficient with the exact text of
//! `--format json` (`tests/data/sympy_roundtrip.py`). Needs Python with SymPy: ignored in
//! `cargo test`; `scripts/test` makes the venv (`scripts/sympy-venv`) and runs it with
//! `SYMPY_PYTHON=... cargo test --test all sympy_roundtrip:: -- --ignored`.

use super::common;
use common::{run, scene_file};
use std::process::Command;

/// The Python with SymPy: `SYMPY_PYTHON`, else the venv `scripts/sympy-venv` makes.
fn python() -> String {
    if let Ok(p) = std::env::var("SYMPY_PYTHON") {
        return p;
    }
    let out = Command::new(format!("{}/scripts/sympy-venv", concat!(env!("CARGO_MANIFEST_DIR"), "/../..")))
        .output()
        .expect("venv script runs");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8(out.stdout).unwrap().trim().to_string()
}

const OBJECTS: &[&[&str]] = &[
    &["kernel", "--order", "12"],
    &["weight", "--order", "8"],
    &["jacobi", "--order", "10"],
    &["sliding", "--order", "6"],
    &["sliding", "--order", "4", "--shape", "sinusoidal"],
    &["sliding", "--order", "5", "--convention", "periodic"],
    &["sliding", "--order", "2", "--shape", "polynomial", "--coefficients", "0,?,1,?,?"],
    &["adhesion", "--order", "6"],
    &["adhesion", "--order", "4", "--degree", "4"],
];

#[test]
#[ignore = "needs Python with SymPy (scripts/test runs it)"]
fn sympy_reads_back_every_object() {
    let py = python();
    let script = format!("{}/tests/data/sympy_roundtrip.py", concat!(env!("CARGO_MANIFEST_DIR"), "/../.."));
    for (i, args) in OBJECTS.iter().enumerate() {
        let mut a = vec!["series"];
        a.extend_from_slice(args);
        let output = |format: &str| {
            let mut b = a.clone();
            b.extend(["--format", format]);
            let (code, out, err) = run(&b);
            assert_eq!(code, 0, "{b:?}: {err}");
            out
        };
        let sympy_file = scene_file(&format!("roundtrip_{i}.sympy"), &output("sympy"));
        let json_file = scene_file(&format!("roundtrip_{i}.json"), &output("json"));
        let r = Command::new(&py).args([&script, &sympy_file, &json_file]).output().expect("python runs");
        assert!(
            r.status.success(),
            "{args:?}: {}{}",
            String::from_utf8_lossy(&r.stdout),
            String::from_utf8_lossy(&r.stderr)
        );
        eprint!("{}", String::from_utf8_lossy(&r.stdout));
    }
}
