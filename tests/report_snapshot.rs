//! The report text for a fixed, fast scene set (`tests/data/report_scenes`, fast profile,
//! coefficient tables through order 4): snapshot-tested. Timings stay out of it (they go to
//! `timings.md`, checked here to state the machine).

use periodic_contact::report::{section::Profile, write_report, ReportOptions};

#[test]
fn report_text_fast_scene_set() {
    let out = std::env::temp_dir().join(format!("periodic-contact-report-test-{}", std::process::id()));
    let opts = ReportOptions {
        out: out.clone(),
        scenes: concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/report_scenes").into(),
        order: 4,
        profile: Profile::Fast,
        progress: false,
    };
    let files = write_report(&opts).unwrap();
    let md = std::fs::read_to_string(out.join("report.md")).unwrap();
    assert_eq!(md, files.markdown);
    // Every chart has its SVG and CSV; the SVG names its axes and curves.
    let svgs: Vec<_> = files.files.iter().filter(|p| p.extension().is_some_and(|x| x == "svg")).collect();
    assert!(svgs.len() >= 8, "{svgs:?}");
    for svg in &svgs {
        assert!(svg.with_extension("csv").exists(), "{}", svg.display());
        let text = std::fs::read_to_string(svg).unwrap();
        assert!(
            text.contains("[-]") || text.contains("[s]") || text.contains("units"),
            "{}: axis units",
            svg.display()
        );
    }
    let timings = std::fs::read_to_string(out.join("timings.md")).unwrap();
    assert!(timings.contains("Machine:") && timings.contains("logical CPUs"));
    assert!(!md.contains("seconds") && !md.contains("wall time:"), "timings leaked into report.md");
    let _ = std::fs::remove_dir_all(&out);
    let mut settings = insta::Settings::clone_current();
    settings.set_snapshot_path("../snapshots");
    settings.set_prepend_module_to_snapshot(false);
    settings.bind(|| insta::assert_snapshot!("report_fast_scene_set", md));
}
