//! Helpers shared by the command-line integration tests: run the binary, read its JSON, write a
//! scene file into a per-test temporary folder.

#![allow(dead_code)] // each test file uses its own subset

use std::io::Write;
use std::process::Command;

/// The workspace's root folder (scene paths in the tests are relative to it).
pub const ROOT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");

/// Runs `periodic-contact ARGS` in the workspace's root: (exit code, stdout, stderr).
pub fn run(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_periodic-contact"))
        .args(args)
        .current_dir(ROOT)
        .output()
        .expect("binary runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Runs `periodic-contact ARGS`, asserts exit code 0 and parses stdout as JSON.
pub fn json(args: &[&str]) -> serde_json::Value {
    let (code, out, err) = run(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    serde_json::from_str(&out).unwrap()
}

/// Writes `text` to `name` in this test's temporary folder (process and test name: the files of
/// all the command-line tests run in one process, `tests/all`); returns the path.
pub fn scene_file(name: &str, text: &str) -> String {
    let test = std::thread::current().name().unwrap_or("main").replace("::", "-");
    let dir = std::env::temp_dir().join(format!("periodic-contact-test-{}-{test}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::File::create(&p).unwrap().write_all(text.as_bytes()).unwrap();
    p.display().to_string()
}

/// Runs `periodic-contact ARGS` and asserts a usage error: exit code 2, nothing on stdout, a
/// message containing `needle`, no panic.
pub fn assert_usage_error(args: &[&str], needle: &str) {
    let (code, out, err) = run(args);
    assert_eq!(code, 2, "{args:?}: {err}");
    assert!(out.is_empty(), "{args:?} printed {out}");
    assert!(err.contains(needle), "{args:?}: {err}");
    assert!(!err.contains("panicked"), "{args:?}: {err}");
}
