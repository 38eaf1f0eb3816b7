//! # periodic-contact
//!
//! Exact asymptotic series, high-precision (MPFR) and fast (f64) solutions of the periodic contact
//! problem of a row of rigid punches on an elastic half-plane (Soldatenkov 2013), with friction,
//! wear and adhesion, and the verification that they agree term by term.
//!
//! Architecture: layers, lowest first; a module uses only modules of lower layers
//! (`tests/architecture.rs` checks it and draws the graph in `docs/module-graph.md`):
//! - [`model`]: the statement of the problems, exact inputs only, validated once when built;
//!   [`error`]: the one error type (input / no solution / not physical / no convergence);
//!   [`scene`]: scene files (strict TOML) -> model.
//! - [`numerics`]: exact -> MPFR / `f64` (rounded once), the one accuracy rule
//!   ([`numerics::accuracy`]), precision and guard bits, root finding, quadrature rules.
//! - [`params`]: derived parameters computed once per problem and precision (Problem 1: kappa,
//!   theta, beta, k, a0, l_s, T, units; Problem 2: eps, cosh(pi eps), B, S).
//! - [`asymptotics`]: the objects of docs/theory.md section 5 as exact truncated series (engine: the
//!   `exact_series` crate in `series/`, no physics, no floats).
//! - [`sliding`] (Problem 1: `reduction_mpfr`, `collocation_f64`, `series`) and [`adhesion`]
//!   (Problem 2: `volterra_mpfr`, `series_f64`): two independent methods per problem side by side,
//!   with parallel verbs (`solve`, `verify`, `physical`, `solution`).
//! - [`verification`]: term-by-term convergence orders of the series against the full solutions;
//!   the closed-form frictionless load of a general even profile (docs/theory.md section 9).
//! - [`solve`]: a scene -> one method -> one answer struct -> the one JSON renderer per problem;
//!   [`series_request`]: what `derive` is asked, validated once (the one table of options).
//! - [`api`]: the front door for users of the crate (below).
//!
//! Clients, in crates of their own (so that their dependencies stay out of this one): the report
//! (`crates/report`, the main job: tables, charts, stability maps) and the command line
//! (`crates/cli`, the `periodic-contact` binary: raw arguments -> the library's requests -> one
//! rendering); the Python module (`python/`).
//!
//! ## Using the crate
//!
//! Add it as a dependency (`periodic-contact = { path = "..." }`; the example crate
//! `examples/user-crate` does, with an insta snapshot test of a derived series) and use [`api`]:
//! derive an object ([`api::derive`]), solve a scene ([`api::solve_toml`], [`api::solve_file`]),
//! check the series' orders ([`api::check_orders`]). Every call validates its input with the
//! command line's messages and returns JSON-ready values, e.g. (a doctest; the README's Rust
//! example is compiled and run as one too, through `ReadmeDoctests` under `cfg(doctest)`):
//!
//! ```
//! use periodic_contact::api::{self, SolveOptions};
//! // 1. The exact Problem 1 expansions at theta = 1/10, through Lambda^4.
//! let sliding = api::derive(&api::SeriesRequest::new("sliding", 4).option("theta", "1/10"))?.json();
//! let l_over_ls = &sliding["parts"][0]; // l/l_s = 1 - 2/25 Lambda^2 + ...
//! assert_eq!(l_over_ls["coefficients"][1]["text"], "-2/25");
//! // 2. A scene file solved as `periodic-contact solve FILE --json --method f64` does.
//! let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/sliding_friction.toml");
//! let opts = SolveOptions { method: Some("f64".into()), ..Default::default() };
//! let answer = api::solve_file(scene.as_ref(), &opts)?;
//! let l = answer.get("l").unwrap(); // typed: text, value, digits held, scale
//! println!("l = {} ({:.1} digits of {:e})", l.text, l.digits, l.scale);
//! # Ok::<(), api::ApiError>(())
//! ```
//!
//! Formulas in these pages are TeX between `$` signs, rendered by KaTeX when the documentation is
//! built with the header of the repository (`RUSTDOCFLAGS="--html-in-header katex-header.html"
//! cargo doc`, as docs.rs does from `[package.metadata.docs.rs]`), e.g. the kernel
//! $Z(z) = z \cot z = 1 - z^2/3 - z^4/45 - \dots$ of [`asymptotics::kernel`].

/// The README's code blocks as doctests (its Rust example is compiled and run; its `console`,
/// `toml`, `python` and `sh` blocks are not Rust: `crates/cli/tests/all/doc_commands.rs` runs the
/// commands).
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

pub mod adhesion;
pub mod api;
pub mod asymptotics;
pub mod error;
pub mod growing_contact;
pub mod loading_law;
pub mod model;
pub mod numerics;
pub mod params;
pub mod scene;
pub mod series_request;
pub mod sliding;
pub mod solve;
pub mod verification;

pub use api::{derive, solve_file, solve_toml, ApiError, Derivation, SeriesRequest, SolveOptions};
