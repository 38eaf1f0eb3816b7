//! The integration tests of this crate as one test binary (one link instead of one per file;
//! issue 33): a module per file. Run one file's tests: `cargo test --test all NAME::`.

mod adhesion_profiles;
mod adhesion_reach;
mod cli;
mod cli_extras;
mod common;
mod convention;
mod doc_commands;
mod friction_cli;
mod interrupt;
mod loading_law_cli;
mod pade;
mod profiles_cli;
mod reliability_cli;
mod report_cli;
mod report_snapshot;
mod scene_template;
mod series_adhesion_numeric_cli;
mod series_loading_law_cli;
mod solve;
mod solve_choice;
mod sympy_roundtrip;
mod theory_doc;
