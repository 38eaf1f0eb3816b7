//! The integration tests of this crate as one test binary (one link instead of one per file;
//! issue 33): a module per file. Run one file's tests: `cargo test --test all NAME::`.

// fuzz.rs and regression.rs each load examples/fuzz/{check,generate}.rs, as their two binaries did.
#![allow(clippy::duplicate_mod)]

mod adhesion_analytic;
mod concurrency;
mod convergence_orders;
mod convergence_orders_loading_law;
mod convergence_orders_periodic;
mod convergence_orders_polynomial;
mod friction_scene;
mod front_page;
mod fuzz;
mod loading_law_agreement;
mod physicality_agreement;
mod profiles;
mod regression;
mod reliability;
mod report_scenes;
mod scene;
mod series_objects;
mod snapshots_polynomial;
mod snapshots_series;
mod typed_answers;
