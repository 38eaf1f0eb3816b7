//! Outputs that survive interruption (issue 34): Ctrl-C (SIGINT) during `report` or a long `solve`
//! stops the run with exit code 130 (the CLI's handler, `exit_on_interrupt` in `src/main.rs`),
//! leaves the previous report intact and no temporary file of the process. The report computes
//! every section first and writes each file whole (`periodic_contact_report::write_whole`: a
//! temporary name `.NAME.partial-PID` in the same directory, renamed); the handler removes the
//! process's temporary files before it exits.

use std::os::unix::process::ExitStatusExt;
use std::process::{Child, Command, Stdio};

const ROOT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");

fn start(args: &[&str]) -> Child {
    Command::new(env!("CARGO_BIN_EXE_periodic-contact"))
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap()
}

/// Sends SIGINT to `child` after `secs` seconds (the runs below take tens of seconds) and returns
/// its exit status, stdout and stderr; the child must still have been running.
fn interrupt(child: Child, secs: u64) -> (std::process::ExitStatus, String, String) {
    std::thread::sleep(std::time::Duration::from_secs(secs));
    let killed = Command::new("kill").args(["-INT", &child.id().to_string()]).status().unwrap();
    assert!(killed.success());
    let out = child.wait_with_output().unwrap();
    let text = |b: &[u8]| String::from_utf8_lossy(b).into_owned();
    (out.status, text(&out.stdout), text(&out.stderr))
}

#[test]
fn sigint_during_report_exits_130_and_leaves_the_previous_report_intact() {
    let out = std::env::temp_dir().join(format!("periodic-contact-interrupt-{}", std::process::id()));
    std::fs::create_dir_all(&out).unwrap();
    // "The previous report": its files with known contents.
    let previous = [("report.md", "# the previous report\n"), ("timings.md", "previous timings\n")];
    for (name, text) in previous {
        std::fs::write(out.join(name), text).unwrap();
    }
    let child = start(&["report", "--fast", "--scenes", &format!("{ROOT}/scenes"), "--out", out.to_str().unwrap()]);
    // A temporary file of the child's as an interrupted `write_whole` leaves it (the child writes
    // its own only in its last moments), and another process's, which must stay.
    let own = out.join(format!(".report.html.partial-{}", child.id()));
    let other = out.join(".report.html.partial-1");
    std::fs::write(&own, "half a file").unwrap();
    std::fs::write(&other, "another run's").unwrap();
    let (status, _, stderr) = interrupt(child, 1);
    assert_eq!(status.code(), Some(130), "{status:?} (signal {:?}); stderr: {stderr}", status.signal());
    assert!(stderr.contains("interrupted"), "{stderr}");
    for (name, text) in previous {
        assert_eq!(std::fs::read_to_string(out.join(name)).unwrap(), text, "{name} changed");
    }
    assert!(!own.exists(), "the interrupted run's temporary file was left");
    assert!(other.exists(), "another process's temporary file was removed");
    std::fs::remove_file(&other).unwrap();
    let partial: Vec<_> = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.contains(".partial-"))
        .collect();
    assert!(partial.is_empty(), "partial files left: {partial:?}");
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn sigint_during_a_long_solve_exits_130_and_prints_nothing() {
    // The loading law at 40 verified digits: tens of seconds in this (debug) build.
    let child = start(&["solve", &format!("{ROOT}/scenes/adhesion_loading_law.toml"), "--digits", "40"]);
    let (status, stdout, stderr) = interrupt(child, 1);
    assert_eq!(status.code(), Some(130), "{status:?} (signal {:?}); stderr: {stderr}", status.signal());
    assert!(stdout.is_empty(), "partial output: {stdout}");
    assert!(stderr.contains("interrupted"), "{stderr}");
}
