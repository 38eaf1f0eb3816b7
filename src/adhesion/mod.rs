//! Problem 2: indentation of periodic parabolic punches with complete adhesion
//! (THEORY.md section 4; Soldatenkov 2013, (1.4), (2.18)-(2.26)).
//!
//! Objects: [`crate::params::adhesion`] (eps, B, S, M_m), [`tanh_sinh`] (double-exponential quadrature on (0,1)),
//! [`kernel`] (the regularised kernels of the incremental method), [`chebyshev`],
//! [`volterra_mpfr`] (method 1: MPFR Chebyshev collocation of the Volterra equation),
//! [`series_f64`] (method 2: power series in lambda^2, f64), [`solution`] (dimensional results,
//! tension zones), [`verified`] (two runs, verified digits).
//!
//! Entry points:
//! - [`verified::solve_verified`]`(problem, points, digits)`: MPFR, two runs, digits per quantity;
//! - [`solution::solve_mpfr`]`(problem, points, params)`: one MPFR run;
//! - [`solution::solve_f64`]`(problem, points)`: the independent f64 method.
//!
//! THEORY.md section 4 was checked numerically, not only used: the unit-load flat-punch stress
//! satisfies (H + i beta) sigma_flat = 0 inside and H[sigma_flat] = K/L outside (to 1e-13), and the
//! full solution satisfies v' = g', u' = psi inside (to 1e-12) by an evaluation of the surface
//! relations [1.6]-[1.8] independent of the incremental construction (`tests.rs`). No correction
//! to THEORY.md was needed. Additions: the conditioning limits of the incremental method at small
//! nu ([`volterra_mpfr`], Conditioning) and the behaviour of the lambda^2 series ([`series_f64`]).

pub mod chebyshev;
pub mod error;
pub mod kernel;
pub mod series_f64;
pub mod solution;
pub mod tanh_sinh;
pub mod verified;
pub mod volterra_mpfr;

pub use error::AdhesionError;

#[cfg(test)]
mod tests;
