//! Issue 14: the report's sections and cells run in parallel, and its text does not depend on the
//! threads: the fast scene set on one thread (`--jobs 1`) and on three gives the same `report.md`,
//! `coefficients.tex` and charts (except the speed charts, whose x axis is the measured run time).

use super::common;

#[test]
#[ignore = "long tier: 23 s alone in the test profile (opt-level 2) on a loaded 2-core machine (scripts/test --long)"]
fn serial_and_parallel_reports_are_identical() {
    let (serial_dir, serial) = common::fast_report_with("report-serial", Some(1));
    let (parallel_dir, parallel) = common::fast_report_with("report-parallel", Some(3));
    assert_eq!(serial.markdown, parallel.markdown);
    let names = |files: &[std::path::PathBuf]| -> Vec<String> {
        files.iter().filter_map(|p| p.file_name().map(|n| n.to_string_lossy().into_owned())).collect()
    };
    assert_eq!(names(&serial.files), names(&parallel.files));
    let mut compared = 0;
    for name in names(&serial.files) {
        if name.starts_with("speed_") || name == "timings.md" || name == "report.html" {
            continue;
        }
        let a = std::fs::read(serial_dir.join(&name)).unwrap();
        let b = std::fs::read(parallel_dir.join(&name)).unwrap();
        assert!(a == b, "{name} differs between --jobs 1 and --jobs 3");
        compared += 1;
    }
    assert!(compared >= 10, "{compared} files compared");
    let _ = std::fs::remove_dir_all(&serial_dir);
    let _ = std::fs::remove_dir_all(&parallel_dir);
}
