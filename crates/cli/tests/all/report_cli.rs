//! `periodic-contact report` on the command line: invalid input exits with code 2 and names the
//! parameter (a missing scene folder, an invalid scene in it).

use std::process::Command;

fn run(args: &[&str]) -> (i32, String) {
    let o = Command::new(env!("CARGO_BIN_EXE_periodic-contact"))
        .args(args)
        .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
        .output()
        .unwrap();
    (o.status.code().unwrap_or(-1), String::from_utf8_lossy(&o.stderr).into_owned())
}

#[test]
fn missing_scene_folder_is_invalid_input() {
    let (code, err) = run(&["report", "--scenes", "/nonexistent/scenes", "--out", "/tmp/unused-report"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("--scenes"), "{err}");
}

#[test]
fn invalid_scene_in_the_folder_is_invalid_input() {
    let dir = std::env::temp_dir().join(format!("pc-report-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("bad.toml"), "[problem]\nkind = \"sliding\"\n[sweep]\nwhat = 1\n").unwrap();
    let out = dir.join("out");
    let (code, err) = run(&["report", "--scenes", dir.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("bad.toml"), "{err}");
}

#[test]
fn jobs_out_of_range_is_invalid_input() {
    for bad in ["0", "-1", "two", "257"] {
        let (code, err) = run(&["report", &format!("--jobs={bad}"), "--out", "/tmp/unused-report"]);
        assert_eq!(code, 2, "--jobs {bad}: {err}");
        assert!(err.contains("--jobs") && err.contains(bad) && err.contains("[1, 256]"), "{err}");
    }
}
