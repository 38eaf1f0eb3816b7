//! Outputs that survive interruption (issue 34): Ctrl-C (SIGINT) during `report` leaves the
//! previous report intact and no partial file, and the process ends by the signal (exit status
//! 130 in a shell). The report computes every section first and writes each file whole
//! (`periodic_contact_report::write_whole`: a temporary name in the same directory, renamed).

use std::process::Command;

#[test]
fn sigint_during_report_leaves_the_previous_report_intact() {
    let out = std::env::temp_dir().join(format!("periodic-contact-interrupt-{}", std::process::id()));
    std::fs::create_dir_all(&out).unwrap();
    // "The previous report": its files with known contents.
    let previous = [("report.md", "# the previous report\n"), ("timings.md", "previous timings\n")];
    for (name, text) in previous {
        std::fs::write(out.join(name), text).unwrap();
    }
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");
    let mut child = Command::new(env!("CARGO_BIN_EXE_periodic-contact"))
        .args(["report", "--fast", "--scenes", &format!("{root}/scenes"), "--out"])
        .arg(&out)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    // Mid-run: the fast report takes tens of seconds; interrupt it after one.
    std::thread::sleep(std::time::Duration::from_secs(1));
    let killed = Command::new("kill").args(["-INT", &child.id().to_string()]).status().unwrap();
    assert!(killed.success());
    let status = child.wait().unwrap();
    use std::os::unix::process::ExitStatusExt;
    // Ended by SIGINT (a shell reports 128 + 2 = 130), or exit code 130.
    assert!(status.signal() == Some(2) || status.code() == Some(130), "{status:?}");
    for (name, text) in previous {
        assert_eq!(std::fs::read_to_string(out.join(name)).unwrap(), text, "{name} changed");
    }
    let partial: Vec<_> = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.contains(".partial-"))
        .collect();
    assert!(partial.is_empty(), "partial files left: {partial:?}");
    let _ = std::fs::remove_dir_all(&out);
}
