//! # periodic-contact
//!
//! Exact asymptotic series, high-precision (MPFR) and fast (f64) solutions of the periodic contact
//! problem of a row of rigid punches on an elastic half-plane (Soldatenkov 2013), with friction,
//! wear and adhesion, and the verification that they agree term by term.
//!
//! Architecture (one module per derived object or method):
//! - [`model`]: the statement of the problems, exact inputs only.
//! - `series` crate (`exact_series`): the exact power-series engine (no physics, no floats).
//! - [`asymptotics`]: the objects of THEORY.md section 5 as exact truncated series.
//! - [`numerics`]: evaluation of exact objects at `f64` and MPFR precision, quadrature.
//! - [`sliding`]: Problem 1 solvers (high-precision exact reduction; fast f64 collocation).
//! - [`report`]: data -> Markdown / LaTeX (pure), and the report writer.
//! - [`cli`]: raw arguments -> validated configuration.

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
