//! Helpers shared by the report's integration tests: the report of the fixed fast scene set.

#![allow(dead_code)] // each test file uses its own subset

/// Writes the report of the fixed fast scene set (`tests/data/report_scenes`, fast profile, order
/// 4) into a per-process temporary folder named by `tag`: (the folder, what was written).
pub fn fast_report(tag: &str) -> (std::path::PathBuf, periodic_contact_report::ReportFiles) {
    fast_report_with(tag, None)
}

/// [`fast_report`] on `jobs` threads (`None`: one per logical CPU).
#[allow(dead_code)]
pub fn fast_report_with(tag: &str, jobs: Option<usize>) -> (std::path::PathBuf, periodic_contact_report::ReportFiles) {
    use periodic_contact_report::{section::Profile, write_report, ReportOptions};
    let out = std::env::temp_dir().join(format!("periodic-contact-{tag}-{}", std::process::id()));
    let opts = ReportOptions {
        out: out.clone(),
        scenes: concat!(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."), "/tests/data/report_scenes").into(),
        order: 4,
        profile: Profile::Fast,
        progress: false,
        jobs,
    };
    let files = write_report(&opts).unwrap();
    (out, files)
}
