//! The integration tests of this crate as one test binary (one link instead of one per file;
//! issue 33): a module per file. Run one file's tests: `cargo test --test all NAME::`.

mod common;
mod report_choice;
mod report_friction_map;
mod report_html_browser;
mod report_parallel;
mod report_shapes;
