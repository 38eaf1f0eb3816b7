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
//! - [`asymptotics`]: the objects of THEORY.md section 5 as exact truncated series (engine: the
//!   `exact_series` crate in `series/`, no physics, no floats).
//! - [`sliding`] (Problem 1: `reduction_mpfr`, `collocation_f64`, `series`) and [`adhesion`]
//!   (Problem 2: `volterra_mpfr`, `series_f64`): two independent methods per problem side by side,
//!   with parallel verbs (`solve`, `verify`, `physical`, `solution`).
//! - [`verification`]: term-by-term convergence orders of the series against the full solutions;
//!   the closed-form frictionless load of a general even profile (THEORY.md section 9).
//! - [`solve`]: a scene -> one method -> one answer struct -> the one JSON renderer per problem.
//! - [`report`]: the main job (tables, charts, stability maps); [`cli`]: raw arguments ->
//!   validated configuration; `main.rs` parses, runs and maps error kinds to exit codes.

pub mod adhesion;
pub mod asymptotics;
pub mod cli;
pub mod error;
pub mod model;
pub mod numerics;
pub mod params;
pub mod report;
pub mod scene;
pub mod sliding;
pub mod solve;
pub mod verification;
