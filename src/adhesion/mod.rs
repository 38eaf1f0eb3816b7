//! Problem 2: indentation of periodic convex punches with complete adhesion
//! (docs/theory.md section 4; Soldatenkov 2013, (1.4), (2.18)-(2.26)).
//!
//! Two independent methods, side by side with the same file names:
//! - [`volterra_mpfr`] (method 1): MPFR Chebyshev collocation of the Volterra equation of the
//!   incremental method; `kernel`, `solve` (one lambda), `volterra` (the dimensionless solution),
//!   `solution` (dimensional), `verify` (two runs, verified digits);
//! - [`series_f64`] (method 2): power series in lambda^2, `f64`; `kernel`, `series` (the
//!   universal coefficients), `solve` (one lambda), `solution` (dimensional), `verify` (two runs,
//!   estimated digits);
//! - [`collocation_f64`] (method 2b): collocation in eta, `f64`, one block of the loading law's
//!   march with N = 0, where the series stops (issue 13); [`method_f64`] picks between 2 and 2b.
//!
//! - [`friction`]: finite friction (docs/theory.md section 17), so far the single punch's
//!   self-similar stick/slip solution by two `f64` methods (not yet reachable from scenes).
//!
//! Both surface conventions (docs/theory.md section 8, Problem 2; [`crate::model::AdhesionProblem::convention`]):
//! `paper` (the Flamant far field) and `periodic` (u periodic; the MPFR kernel's factor
//! [`volterra_mpfr::kernel::LateralShift`], the f64 collocation's tilted punch; the lambda^2 series
//! is `paper` only). Checked in `convention_tests.rs` (boundary-element values, the two methods, the
//! loading law with N = 0, the mode).
//!
//! Punches: the parabola, even polynomials and the circle (both methods), with the refusals of
//! [`profile`] (convexity, |x| < R, the load search's bounds). Shared: [`points`] (the requested points), [`scales`] (the scale of each output and the digits
//! relative to it), [`tension`] (the tension zones at the oscillating edge), [`error`]. The
//! derived material constants (eps, cosh(pi eps), B, S, C_P) are computed once per solve in
//! [`crate::params::adhesion`] and passed as data; the quadrature and interpolation are
//! [`crate::numerics::tanh_sinh`] and [`crate::numerics::chebyshev`].
//!
//! Entry points:
//! - [`solve_verified`]`(problem, points, digits)`: MPFR, two runs, verified digits per quantity;
//! - [`solve_mpfr`]`(problem, points, params)`: one MPFR run;
//! - [`solve_f64`]`(problem, points)`: the independent f64 method (series, else collocation in
//!   eta), with estimated digits.
//!
//! docs/theory.md section 4 was checked numerically, not only used: the unit-load flat-punch stress
//! satisfies (H + i beta) sigma_flat = 0 inside and H\[sigma_flat\] = K/L outside (to 1e-13), and the
//! full solution satisfies v' = g', u' = psi inside (to 1e-12) by an evaluation of the surface
//! relations [1.6]-[1.8] independent of the incremental construction (`tests.rs`). No correction
//! to docs/theory.md was needed. Additions: the conditioning limits of the incremental method at small
//! nu ([`volterra_mpfr`], Conditioning) and the behaviour of the lambda^2 series ([`series_f64`]).

pub mod analytic;
pub mod collocation_f64;
pub mod friction;
pub mod method_f64;
pub mod points;
pub mod profile;
pub mod scales;
pub mod series_f64;
pub mod tension;
pub mod volterra_mpfr;

pub use crate::growing_contact::error::{self, AdhesionError};
pub use method_f64::solve_f64;
pub use scales::{Digits, ScalesF64, ScalesMpfr};
pub use series_f64::solution::{AdhesionSolutionF64, F64Route, PointValuesF64};
pub use volterra_mpfr::solution::{solve_mpfr, solve_mpfr_with, AdhesionSolution, PointValues, TensionZones};
pub use volterra_mpfr::verify::{solve_verified, VerifiedSolution};

#[cfg(test)]
mod against_series;
#[cfg(test)]
mod convention_tests;
#[cfg(test)]
mod tests;
