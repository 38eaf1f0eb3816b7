//! Problem 2: indentation of periodic parabolic punches with complete adhesion
//! (THEORY.md section 4; Soldatenkov 2013, (1.4), (2.18)-(2.26)).
//!
//! Objects: [`constants`] (eps, B, S, M_m), [`tanh_sinh`] (double-exponential quadrature on (0,1)),
//! [`kernel`] (the regularised kernels of the incremental method), [`chebyshev`],
//! [`volterra_mpfr`] (method 1: MPFR Chebyshev collocation of the Volterra equation),
//! [`series_f64`] (method 2: power series in lambda^2, f64), [`verified`] (two runs, digits).

pub mod chebyshev;
pub mod constants;
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
