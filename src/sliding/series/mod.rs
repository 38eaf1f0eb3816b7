//! Problem 1 by its truncated exact series (docs/theory.md section 5, [3.7]-[3.12]): the third method
//! beside the MPFR reduction and the f64 collocation, and the cheap one for small contacts.
//!
//! The exact expansions in Lambda = pi l_s/L (`crate::asymptotics::sliding`, symbolic in theta
//! and T) are evaluated in MPFR at a problem's parameters: [`point`] (theta, T, Lambda, l_s, k
//! from `crate::params::sliding`), [`partial`] (l, c, F_def, p through Lambda^N), [`estimate`]
//! (the error of the truncation, estimated from the terms kept: never called verified),
//! [`solve`] (the solution with its estimated digits per quantity).

pub mod estimate;
pub mod pade;
pub mod partial;
pub mod point;
pub mod solve;

pub use point::{series_point, SeriesPoint};
pub use solve::{expansion_shape, solve_series, solve_series_with, SeriesAccuracy, SeriesSolution};

#[cfg(test)]
mod tests;
